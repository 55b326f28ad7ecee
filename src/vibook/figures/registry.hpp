/// \file registry.hpp
/// \brief The check and figure registry. A *check* measures one or more claims; a *figure*
/// is a check that also writes CSV data and has a gnuplot script `figures/ID.gp`. The
/// figure's doctest and `vibook figure ID` call the same `run` function.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "vibook/claims/ledger.hpp"

namespace vibook::figures {

/// Where a check writes its data: nothing (measure only) or a directory for its CSV files.
struct Context {
  std::optional<std::filesystem::path> out_dir;
};

struct Check {
  std::string id;
  std::string title;
  bool is_figure = false;
  std::vector<std::string> claims;  ///< claim IDs this check measures
  std::function<std::vector<claims::ClaimResult>(const Context&)> run;
};

/// Every check and figure, in a fixed order (the ones CI runs).
const std::vector<Check>& registry();
/// Long studies (minutes to hours): run by `./build.sh book`, which sets VIBOOK_LONG_STUDIES=1,
/// or by name (`vibook figure ID`); never by the tests.
const std::vector<Check>& long_studies();
/// True when VIBOOK_LONG_STUDIES is set to a non-empty value other than 0.
bool long_studies_enabled();
/// The check with this ID (in either list), or nullptr.
const Check* find(std::string_view id);

/// Outcome of regenerating one figure into `out_root/ID/`.
struct FigureOutput {
  std::string id;
  std::filesystem::path dir;
  std::vector<claims::ClaimResult> results;
  bool rendered = false;
  std::string render_error;  ///< set when gnuplot was missing or failed (CSV still written)
};

/// Run the figure's computation with `out_root/ID/` as data directory, write claims.json,
/// then render with gnuplot. A rendering failure is reported in the result, not thrown.
FigureOutput make_figure(const Check& check, const std::filesystem::path& out_root);

/// Run checks in parallel (one task per check, at most `jobs` at a time; 0 = hardware).
std::vector<std::vector<claims::ClaimResult>> run_checks(const std::vector<const Check*>& checks,
                                                         unsigned jobs = 0);

/// Run every check (and the long studies when long_studies_enabled()) and record the results
/// in a fresh ledger.
/// With `figures_dir`, a long study whose figure output DIR/ID/claims.json exists is read from
/// there instead of being run again (the book build runs `vibook figures` first).
claims::Ledger measure_all(unsigned jobs = 0,
                           const std::optional<std::filesystem::path>& figures_dir = {});

// The individual checks (one translation unit each).
Check vermeeren_fig1();
Check check_v_ex1();
Check check_s_del();
Check sharma_fig1();
Check sharma_fig2();
Check sharma_fig3();
Check sharma_fig4();
Check sharma_fig5();
Check check_s_eq29();
Check check_s_eq39();
Check check_s_l1();
Check epavi_existence();
Check check_ss_t8();
Check shen_sun_fig7();
Check relativistic_precession();
Check check_ss_t2();
Check check_ss_p4();
Check check_ss_t6();
Check shen_sun_fig2();
Check shen_sun_fig345();
Check shen_sun_fig6();
Check shen_sun_work_precision();
Check sharma_eq29_long();
Check check_modified();
Check check_v_t16();
Check vermeeren_fig3();
Check shen_sun_fig1();
Check check_ss_t13();
/// The long study at a fraction `scale` of its length (the doctest runs it small).
std::vector<claims::ClaimResult> run_eq29_long(const Context& ctx, double scale);

}  // namespace vibook::figures
