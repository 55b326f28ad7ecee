/// \file registry.hpp
/// \brief The check and figure registry: an index only. A *check* (claims/check.hpp) measures
/// one or more claims; a *figure* is a check that also writes CSV data and has a gnuplot
/// script `figures/ID.gp`. The checks live in their paper section's folder, beside the code
/// they test, and are declared in that folder's `checks.hpp`; the figure's doctest and
/// `vibook figure ID` call the same `run` function.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "vibook/claims/check.hpp"
#include "vibook/claims/ledger.hpp"

namespace vibook::figures {

using claims::Check;
using claims::Context;

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

/// The figures `ids` names, in that order; every figure (and, when long_studies_enabled(),
/// every long study with a figure) when it is empty. Throws ArgumentError naming `arg` for an
/// unknown ID, a check without a figure, or an ID given twice.
std::vector<const Check*> select_figures(const std::vector<std::string>& ids,
                                         const std::string& arg);

/// Regenerate `figures` into `out_root/ID/`, one thread per figure (at most one per core),
/// after checking, before any work, that `out_root` can be created and written, is not a
/// symbolic link (followed silently, it would write elsewhere) and that each `out_root/ID`,
/// where it exists, is a directory (ArgumentError naming `arg` otherwise).
std::vector<FigureOutput> make_figures(const std::vector<const Check*>& figures,
                                       const std::filesystem::path& out_root,
                                       const std::string& arg);

/// Run one check and hold it to its declaration: every claim it names must be measured (not
/// pending) in its results, and every result must be a claim it names or an erratum
/// (`*-ERR-*`). Throws std::logic_error naming the check and the claim otherwise. Every run
/// (claims, figures, the book) goes through here, so the ledger's "measured exactly when some
/// check names it" holds by construction.
std::vector<claims::ClaimResult> run_check(const Check& check, const Context& context);

/// Run checks in parallel (one task per check, at most `jobs` at a time; 0 = hardware).
std::vector<std::vector<claims::ClaimResult>> run_checks(const std::vector<const Check*>& checks,
                                                         unsigned jobs = 0);

/// Run every check (and the long studies when long_studies_enabled()) and record the results
/// in a fresh ledger, in registry order.
/// With `figures_dir`, a figure whose output DIR/ID/claims.json exists is read from there
/// instead of being run again: the book build runs `vibook figures` first, then
/// `vibook claims --figures-dir`, and each measurement is made once.
claims::Ledger measure_all(unsigned jobs = 0,
                           const std::optional<std::filesystem::path>& figures_dir = {});

/// The ledger of the checks `ids` names (ArgumentError naming `arg` for an unknown one; every
/// other claim stays pending), or of all of them (measure_all with `figures_dir`) when empty.
claims::Ledger measure(const std::vector<std::string>& ids,
                       const std::optional<std::filesystem::path>& figures_dir,
                       const std::string& arg);

/// The book's claim tables, written into `dir` (each file through core/output_file; a write
/// error names `arg`): claims.html, summary.html, provenance.html (from `provenance`, the
/// ledger's `claims::provenance`), claims-S/V/SS/A.html (one paper each), and one table per
/// check, ID.html. A chapter shows each claim once: a claim measured by several checks is
/// shown with the most specific of them (the one naming the fewest claims; the first of equals
/// in the registry's order), and the others link to its row instead of repeating it.
void write_claim_tables(const claims::Ledger& ledger, const nlohmann::json& provenance,
                        const std::filesystem::path& dir, const std::string& arg);

}  // namespace vibook::figures
