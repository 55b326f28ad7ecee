/// \file check.hpp
/// \brief What a *check* is: a function that measures one or more claims of the ledger.
///
/// Each paper section keeps its checks beside the code they test (`epavi/sharma_fig12.cpp`,
/// `modified/check_v_t16.cpp`, ...) and declares them in its `checks.hpp`. The registry
/// (`figures/registry.hpp`) is only an index of them. A *figure* is a check that also writes
/// CSV data and has a gnuplot script `figures/ID.gp`; its doctest and `vibook figure ID` call
/// the same `run` function.
///
/// Chapter: \ref report.
#pragma once

#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "vibook/claims/ledger.hpp"

namespace vibook::claims {

/// Where a check writes its data: nothing (measure only) or a directory for its CSV files.
struct Context {
  std::optional<std::filesystem::path> out_dir;
};

/// The CSV file `name` in the check's directory, or nothing when the check only measures.
inline std::optional<std::ofstream> open_csv(const Context& ctx, const std::string& name) {
  std::optional<std::ofstream> f;
  if (ctx.out_dir) f.emplace(*ctx.out_dir / name);
  return f;
}

/// One check of the ledger.
struct Check {
  std::string id;
  std::string title;
  bool is_figure = false;
  std::vector<std::string> claims;  ///< claim IDs this check measures
  std::function<std::vector<ClaimResult>(const Context&)> run;
};

}  // namespace vibook::claims
