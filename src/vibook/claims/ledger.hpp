/// \file ledger.hpp
/// \brief The claims ledger: every claim of the three papers with a stable ID, the paper's
/// statement, what vibook measured and the resulting status. Statuses are set only by check
/// functions that measure; an unmeasured claim stays `pending`.
///
/// Chapter: \ref report.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace vibook::claims {

enum class Status { pending, reproduced, reproduced_with_caveat, not_reproduced, erratum };

/// "pending", "reproduced", "reproduced-with-caveat", "not-reproduced", "erratum".
std::string_view to_string(Status s);

/// A claim as catalogued (CLAIMS.md): ID, paper key (S, V or SS), where in the paper, title.
struct ClaimInfo {
  std::string id;
  std::string paper;
  std::string where;
  std::string title;
};

/// One printed display (or one part of it) compared with what vibook computes: the LaTeX read
/// from the paper's own text, what it was compared with, and the outcome. A formula table row
/// says *agrees* only through one of these (printed/compare.hpp makes them).
struct FormulaComparison {
  std::string paper;      ///< "S", "V" or "SS"
  std::string display;    ///< "(39)", or "L288" for an unnumbered display (its first line)
  std::string label;      ///< "(39)", or "the 2nd unnumbered display after (39), §5.1 …"
  std::string part;       ///< which part: "the right-hand side", "member 2 of 3"
  std::string quote;      ///< the LaTeX compared, verbatim from the paper
  std::string against;    ///< what it was compared with (the engine's modified equation, …)
  std::string ours;       ///< our side, as LaTeX
  std::string through;    ///< "through h^2", "exactly"
  std::string outcome;    ///< "agrees", "differs", "ill-formed" or "unreadable"
  std::string detail;     ///< the first difference, or the reader's message
  std::string corrected;  ///< the corrected quote (empty when none was found)
  std::string edit;       ///< the correction in words ("the sign of the term …")
  std::string search;     ///< how the correction was searched for
  std::string check;      ///< the check that compared it
  /// "" for a comparison that decides the display's outcome; "cross-check" for one shown
  /// beside it (another reading, another route) that decides nothing.
  std::string role;
  /// How our side is verified independently (when it is the correction of a display that no
  /// small edit corrects).
  std::string verified;
};

/// One measurement of a claim, produced by a check function.
struct ClaimResult {
  std::string id;
  Status status = Status::pending;
  std::vector<std::pair<std::string, double>> values;  ///< measured numbers, in order
  std::string note;                                    ///< what was measured and how
  std::string source;                                  ///< check or figure that measured it
  std::optional<ClaimInfo> info;               ///< required for IDs not in the catalogue (errata)
  std::vector<FormulaComparison> comparisons;  ///< printed displays this claim compared
  /// Why a claim is not simply reproduced: "misprint" (the printed formula is wrong and the
  /// errata listed correct it), "does-not-hold" (the statement fails, with the evidence in the
  /// note), "open-reading" (it depends on a reading the paper leaves open; the note shows each),
  /// "edge-of-criterion" (the measurement lies at the criterion fixed beforehand; the note says
  /// by how much), "pre-asymptotic" (a measured order still converging toward the stated one at
  /// the smallest step sizes of the window fixed beforehand; the note gives the local slopes).
  /// Empty for a reproduced claim.
  std::string cause;
  std::vector<std::string> errata;  ///< the erratum IDs a "misprint" cause refers to
  /// One line naming what failed (a claim not reproduced) or what is misprinted: the claim's
  /// headline on the book's landing page. Required for every claim with a cause.
  std::string headline;

  /// The measured value of that name, or NaN if there is none (so that any comparison with
  /// a missing value fails).
  double value(std::string_view name) const;
};

/// An erratum claim `PAPER-ERR-EQUATION` measured by `source`: status `erratum` when the
/// measured evidence holds (the print is wrong and the correction right), `not-reproduced`
/// otherwise.
ClaimResult erratum(ClaimInfo info, std::string source,
                    std::vector<std::pair<std::string, double>> values, bool evidence_holds,
                    std::string note);

/// Every catalogued claim, in the order of CLAIMS.md.
const std::vector<ClaimInfo>& catalogue();

/// The full statement of a catalogued claim, with the paper's own numbers (CLAIMS.md), for the
/// report's "the paper says" column; empty for an erratum ID (its title and note say it).
std::string_view paper_statement(std::string_view id);

/// The ledger: the catalogue, each claim pending until a result is recorded.
class Ledger {
 public:
  struct Row {
    ClaimInfo info;
    ClaimResult result;
  };

  Ledger();
  /// Record a measurement. A claim measured by several checks keeps all their values and
  /// notes, and the worse status. An ID outside the catalogue must carry `info` and be an erratum
  /// claim `PAPER-ERR-EQUATION`; otherwise std::invalid_argument.
  void record(const ClaimResult& r);
  const std::vector<Row>& rows() const { return rows_; }
  const Row* find(std::string_view id) const;

  /// {"claims":[{"id","paper","title","status","values":{name:number},"note"}]}
  nlohmann::json to_json() const;
  /// Plain-text table for the terminal.
  std::string to_table() const;
  /// HTML table for the book (cells escaped): all claims, or those of one paper, or the
  /// listed IDs.
  std::string to_html(std::string_view paper_filter = {},
                      const std::vector<std::string>& ids = {}) const;
  /// HTML for the book's first page: the number of claims per paper and status, then the
  /// claims that were not reproduced and the errata found, by ID and title.
  std::string to_summary_html() const;
  /// The claims (not errata) that are not reproduced, or reproduced only with misprints
  /// corrected, without a cause or a headline saying what failed: the book refuses them.
  std::vector<std::string> unexplained() const;

 private:
  std::vector<Row> rows_;
};

/// JSON of one comparison, and back (std::runtime_error on a malformed object).
nlohmann::json to_json(const FormulaComparison& c);
FormulaComparison comparison_from_json(const nlohmann::json& j);

/// JSON of a list of results (one figure's claims.json).
nlohmann::json results_to_json(const std::vector<ClaimResult>& results);
/// The inverse of results_to_json for catalogued claims (errata carry no description there):
/// reads a figure's claims.json back. Throws std::runtime_error on a malformed file.
std::vector<ClaimResult> results_from_json(const nlohmann::json& js);

}  // namespace vibook::claims
