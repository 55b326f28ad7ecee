// Shared declarations of the `vibook` command's subcommands.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

#include "vibook/core/errors.hpp"

// CLI11 is a header-only library of some 10,000 lines: a translation unit that includes it
// spends about 13 s (g++ -O2, this project's 2-core machine) on it. Only the units that
// register options (main, run, modified, verify) include <CLI/CLI.hpp>; the rest see this
// declaration.
namespace CLI {
class App;
}  // namespace CLI

namespace vibook::cli {

/// Exit statuses of the command: 0 success, 1 other failure (e.g. gnuplot missing),
/// 2 bad argument, 3 numerical failure, 4 an output could not be written.
/// Exit statuses, the same for every command (README). kVerdict: `vibook verify` ran to the
/// end and a verdict failed (the report names which).
enum Exit : int { kOk = 0, kFailure = 1, kBadArgument = 2, kNumerical = 3, kIo = 4, kVerdict = 5 };

/// One message to standard error that never throws and never aborts: a closed or full stderr
/// loses the message but not the exit status (every error path of the command goes through it).
/// A message is one line: its newlines and tabs become spaces, and past kMaxMessage characters
/// it is cut, saying how long it was (an argument or a library's message echoed whole made
/// screen-wide "lines"; the JSON of --json-out keeps every reason whole).
void eprint(const std::string& text);
/// The message as eprint writes it.
std::string one_line(const std::string& text);
inline constexpr std::size_t kMaxMessage = 300;

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
