/// \file gnuplot.hpp
/// \brief Headless gnuplot runner: `gnuplot -c SCRIPT DATA_DIR OUTPUT_BASE`, started as
/// a child process with arguments (no shell, no pipe). The script writes `OUTPUT_BASE.svg`
/// and `OUTPUT_BASE.png`.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace vibook::plot {

/// gnuplot is not installed, or failed. The message says which, and what to do.
class PlotError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Full path of an executable found on PATH, or empty.
std::filesystem::path find_on_path(const std::string& program);

/// `PREFIX/relative` when this executable runs from an installed `PREFIX/bin/` and that path
/// exists; empty otherwise.
std::filesystem::path installed_path(const std::string& relative);

/// Directory that holds the figure scripts (`ID.gp`, `style.gp`): `$VIBOOK_FIGURES_DIR` if set,
/// else the installed copy (`PREFIX/share/vibook/figures`) for an installed `vibook`, else the
/// source tree's figures/ (compiled in).
std::filesystem::path scripts_dir();

/// How long one gnuplot run may take before it is killed: `$VIBOOK_GNUPLOT_TIMEOUT` seconds
/// if set (PlotError if it is not a positive number), else 120.
double gnuplot_timeout_seconds();

/// Render figure `id` from the CSV files in `data_dir` to `data_dir/ID.svg` and `.png`.
/// gnuplot's own messages go to data_dir/gnuplot.log. Throws PlotError, also when gnuplot
/// runs longer than gnuplot_timeout_seconds() (it is then killed).
void render(const std::string& id, const std::filesystem::path& data_dir);

}  // namespace vibook::plot
