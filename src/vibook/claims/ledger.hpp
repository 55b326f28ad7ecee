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

/// One measurement of a claim, produced by a check function.
struct ClaimResult {
  std::string id;
  Status status = Status::pending;
  std::vector<std::pair<std::string, double>> values;  ///< measured numbers, in order
  std::string note;                                    ///< what was measured and how
  std::string source;                                  ///< check or figure that measured it
  std::optional<ClaimInfo> info;  ///< required for IDs not in the catalogue (errata)

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

 private:
  std::vector<Row> rows_;
};

/// JSON of a list of results (one figure's claims.json).
nlohmann::json results_to_json(const std::vector<ClaimResult>& results);
/// The inverse of results_to_json for catalogued claims (errata carry no description there):
/// reads a figure's claims.json back. Throws std::runtime_error on a malformed file.
std::vector<ClaimResult> results_from_json(const nlohmann::json& js);

}  // namespace vibook::claims
