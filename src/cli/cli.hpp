// Shared declarations of the `vibook` command's subcommands.
#pragma once

#include <functional>
#include <string>

#include "vibook/core/command.hpp"
#include "vibook/core/errors.hpp"

// CLI11 is a header-only library of some 10,000 lines: a translation unit that includes it
// spends about 13 s (g++ -O2, this project's 2-core machine) on it. Only the units that
// register options (main, run, modified, verify) include <CLI/CLI.hpp>; the rest see this
// declaration.
namespace CLI {
class App;
}  // namespace CLI

namespace vibook::cli {

// The exit statuses (kOk, …), eprint and one_line: vibook/core/command.hpp.

/// The command line as the user typed it (shell-quoted where needed), for reports.
const std::string& command_line();
/// Record it (main does, before parsing).
void set_command_line(int argc, char** argv);

/// Register `vibook run` on the app; the returned function executes it after parsing.
std::function<int()> add_run_command(CLI::App& app);
/// Register `vibook modified` (the symbolic modified-equation engine).
std::function<int()> add_modified_command(CLI::App& app);
/// Register `vibook verify` (a typed discrete Lagrangian through solver, helpers and engine).
std::function<int()> add_verify_command(CLI::App& app);

}  // namespace vibook::cli
