#include "vibook/claims/ledger.hpp"

#include <cmath>
#include <stdexcept>

#include <algorithm>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

namespace vibook::claims {

std::string_view to_string(Status s) {
  switch (s) {
    case Status::pending:
      return "pending";
    case Status::reproduced:
      return "reproduced";
    case Status::reproduced_with_caveat:
      return "reproduced-with-caveat";
    case Status::not_reproduced:
      return "not-reproduced";
    case Status::erratum:
      return "erratum";
  }
  return "pending";
}

ClaimResult erratum(ClaimInfo info, std::string source,
                    std::vector<std::pair<std::string, double>> values, bool evidence_holds,
                    std::string note) {
  ClaimResult r;
  r.id = info.id;
  r.status = evidence_holds ? Status::erratum : Status::not_reproduced;
  r.values = std::move(values);
  r.note = std::move(note);
  r.source = std::move(source);
  r.info = std::move(info);
  return r;
}

double ClaimResult::value(std::string_view name) const {
  for (const auto& [k, v] : values) {
    if (k == name) return v;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

Ledger::Ledger() {
  for (const auto& info : catalogue()) {
    ClaimResult r;
    r.id = info.id;
    rows_.push_back({info, r});
  }
}

const Ledger::Row* Ledger::find(std::string_view id) const {
  const auto it =
      std::find_if(rows_.begin(), rows_.end(), [&](const Row& r) { return r.info.id == id; });
  return it == rows_.end() ? nullptr : &*it;
}

namespace {
// Severity when two checks measure the same claim: the combined status is the worse one.
int severity(Status s) {
  switch (s) {
    case Status::pending:
      return 0;
    case Status::reproduced:
      return 1;
    case Status::reproduced_with_caveat:
      return 2;
    case Status::erratum:
      return 3;
    case Status::not_reproduced:
      return 4;
  }
  return 0;
}
}  // namespace

void Ledger::record(const ClaimResult& r) {
  for (auto& row : rows_) {
    if (row.info.id == r.id) {
      if (row.result.status == Status::pending) {
        row.result = r;
      } else {  // a second check of the same claim: keep both measurements
        auto& m = row.result;
        m.values.insert(m.values.end(), r.values.begin(), r.values.end());
        m.note += " | " + r.note;
        m.source += ", " + r.source;
        m.comparisons.insert(m.comparisons.end(), r.comparisons.begin(), r.comparisons.end());
        m.errata.insert(m.errata.end(), r.errata.begin(), r.errata.end());
        if (severity(r.status) > severity(m.status) || (m.cause.empty() && !r.cause.empty()))
          m.cause = r.cause;
        if (!r.headline.empty())
          m.headline = m.headline.empty() ? r.headline : m.headline + "; " + r.headline;
        if (severity(r.status) > severity(m.status)) m.status = r.status;
      }
      return;
    }
  }
  if (!r.info || r.id.find("-ERR-") == std::string::npos) {
    throw std::invalid_argument("claims ledger: unknown claim ID '" + r.id +
                                "' (only <paper>-ERR-<equation> IDs may be added)");
  }
  rows_.push_back({*r.info, r});
}

namespace {
// The fields of a comparison, in their JSON order (clang-format would reflow this list
// differently from run to run).
// clang-format off
#define VIBOOK_COMPARISON_FIELDS(X)                                                       \
  X(paper)                                                                                \
  X(display)                                                                              \
  X(label)                                                                                \
  X(part)                                                                                 \
  X(quote)                                                                                \
  X(against)                                                                              \
  X(ours) X(through) X(outcome) X(detail) X(corrected) X(edit) X(search) X(check) X(role) \
      X(verified)
// clang-format on
}  // namespace

nlohmann::json to_json(const FormulaComparison& c) {
  nlohmann::json j = nlohmann::json::object();
#define X(f) j[#f] = c.f;
  VIBOOK_COMPARISON_FIELDS(X)
#undef X
  return j;
}

FormulaComparison comparison_from_json(const nlohmann::json& j) {
  FormulaComparison c;
  if (!j.is_object()) throw std::runtime_error("claims.json: a comparison is not an object");
#define X(f)                                                                              \
  if (!j.contains(#f) || !j[#f].is_string())                                              \
    throw std::runtime_error("claims.json: a comparison has no string field \"" #f "\""); \
  c.f = j[#f].get<std::string>();
  VIBOOK_COMPARISON_FIELDS(X)
#undef X
  return c;
}

namespace {
nlohmann::json comparisons_json(const std::vector<FormulaComparison>& cs) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& c : cs) a.push_back(to_json(c));
  return a;
}
}  // namespace

nlohmann::json results_to_json(const std::vector<ClaimResult>& results) {
  nlohmann::json arr = nlohmann::json::array();
  for (const auto& r : results) {
    nlohmann::json values = nlohmann::json::object();
    for (const auto& [k, v] : r.values) values[k] = v;
    nlohmann::json c = {{"id", r.id},
                        {"status", to_string(r.status)},
                        {"values", values},
                        {"note", r.note},
                        {"source", r.source}};
    if (!r.comparisons.empty()) c["comparisons"] = comparisons_json(r.comparisons);
    if (!r.cause.empty()) c["cause"] = r.cause;
    if (!r.errata.empty()) c["errata"] = r.errata;
    if (!r.headline.empty()) c["headline"] = r.headline;
    arr.push_back(std::move(c));
  }
  return {{"claims", arr}};
}

std::vector<ClaimResult> results_from_json(const nlohmann::json& js) {
  std::vector<ClaimResult> out;
  if (!js.contains("claims") || !js["claims"].is_array())
    throw std::runtime_error("claims.json: no \"claims\" array");
  for (const auto& c : js["claims"]) {
    ClaimResult r;
    r.id = c.at("id").get<std::string>();
    const std::string st = c.at("status").get<std::string>();
    bool known = false;
    for (Status s : {Status::pending, Status::reproduced, Status::reproduced_with_caveat,
                     Status::not_reproduced, Status::erratum}) {
      if (to_string(s) == st) r.status = s, known = true;
    }
    if (!known) throw std::runtime_error("claims.json: unknown status '" + st + "'");
    for (const auto& [k, v] : c.at("values").items())
      r.values.push_back({k, v.is_number() ? v.get<double>() : std::nan("")});
    r.note = c.at("note").get<std::string>();
    r.source = c.at("source").get<std::string>();
    if (c.contains("comparisons"))
      for (const auto& x : c.at("comparisons")) r.comparisons.push_back(comparison_from_json(x));
    if (c.contains("cause")) r.cause = c.at("cause").get<std::string>();
    if (c.contains("errata")) r.errata = c.at("errata").get<std::vector<std::string>>();
    if (c.contains("headline")) r.headline = c.at("headline").get<std::string>();
    out.push_back(std::move(r));
  }
  return out;
}

nlohmann::json Ledger::to_json() const {
  nlohmann::json arr = nlohmann::json::array();
  for (const auto& row : rows_) {
    nlohmann::json values = nlohmann::json::object();
    for (const auto& [k, v] : row.result.values) values[k] = v;
    nlohmann::json c = {{"id", row.info.id},
                        {"paper", row.info.paper},
                        {"where", row.info.where},
                        {"title", row.info.title},
                        {"status", to_string(row.result.status)},
                        {"values", values},
                        {"note", row.result.note},
                        {"source", row.result.source}};
    if (!row.result.comparisons.empty())
      c["comparisons"] = comparisons_json(row.result.comparisons);
    if (!row.result.cause.empty()) c["cause"] = row.result.cause;
    if (!row.result.errata.empty()) c["errata"] = row.result.errata;
    if (!row.result.headline.empty()) c["headline"] = row.result.headline;
    arr.push_back(std::move(c));
  }
  return {{"claims", arr}};
}

std::string Ledger::to_table() const {
  std::size_t w = 10;  // the longest ID
  for (const auto& row : rows_) w = std::max(w, row.info.id.size());
  std::string out = fmt::format("{:<{}} {:<23} {}\n", "ID", w, "STATUS", "TITLE");
  for (const auto& row : rows_) {
    out += fmt::format("{:<{}} {:<23} {}\n", row.info.id, w, to_string(row.result.status),
                       row.info.title);
    for (const auto& [k, v] : row.result.values) out += fmt::format("{:>36} = {:.6g}\n", k, v);
  }
  return out;
}

namespace {
std::string escape(std::string_view s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '<':
        o += "&lt;";
        break;
      case '>':
        o += "&gt;";
        break;
      case '&':
        o += "&amp;";
        break;
      case '"':
        o += "&quot;";
        break;
      case '\\':
        o += "&#92;";
        break;  // keep TeX delimiters out of MathJax's reach
      case '$':
        o += "&#36;";
        break;
      default:
        o += c;
    }
  }
  return o;
}
}  // namespace

namespace {

// A long value name (kepler_two_step_residual_rel_max) may break after an underscore, not
// inside a word, when its column is narrow.
std::string break_at_underscores(const std::string& s) {
  std::string out;
  for (char c : s) {
    out += c;
    if (c == '_') out += "<wbr>";
  }
  return out;
}

// The three papers, in the book's order, then the field audit of published methods (each row's
// source is in its "where" column): key and short citation.
constexpr std::pair<const char*, const char*> kPapers[] = {{"S", "Sharma et al. 2022"},
                                                           {"V", "Vermeeren 2017"},
                                                           {"SS", "Shen &amp; Sun 2025"},
                                                           {"A", "Field audit"}};

}  // namespace

std::string Ledger::to_html(std::string_view paper_filter,
                            const std::vector<std::string>& ids) const {
  // One row per claim, the paper's side beside ours: the claim (ID, where, title), what the
  // paper states with its numbers, and what we measured (status, values, note). The whole
  // ledger (the reproduction report) is grouped by paper, gives every row an anchor,
  // #claim-ID, a filter by status and an empty evidence cell that the book build fills with
  // links to the chapter, figure, CSV data and check source (book/report_evidence.py). The
  // excerpts in the chapters link to the report's rows (an ID may appear in two excerpts of
  // one chapter, so they carry no id of their own).
  const bool whole = paper_filter.empty() && ids.empty();
  std::string out;
  if (whole) {
    out += "<p class=\"vibook-filter\">Show:";
    for (Status st : {Status::reproduced, Status::reproduced_with_caveat, Status::not_reproduced,
                      Status::erratum, Status::pending})
      out += fmt::format(
          " <label class=\"status-{0}\"><input type=\"checkbox\" value=\"{0}\" checked> "
          "{0}</label>",
          to_string(st));
    out += "</p>\n";
  }
  const auto row_html = [&](const Row& row) {
    // Long lists of values and long notes (a symbolic mismatch spelled out term by term)
    // are folded: the first values and the note's opening sentences show, the rest opens on a
    // click.
    constexpr std::size_t kShownValues = 8, kNoteShown = 400;
    std::string values;
    for (std::size_t i = 0; i < row.result.values.size(); ++i) {
      if (i == kShownValues && row.result.values.size() > kShownValues + 2)
        values += fmt::format("<details><summary>{} more values</summary>",
                              row.result.values.size() - kShownValues);
      const auto& [k, v] = row.result.values[i];
      values += fmt::format("<span class=\"value\">{}&nbsp;=&nbsp;{:.4g}</span><br/>",
                            break_at_underscores(escape(k)), v);
    }
    if (row.result.values.size() > kShownValues + 2) values += "</details>";
    std::string note = escape(row.result.note);
    if (row.result.note.size() > kNoteShown + 200) {
      // Cut after the first sentence that ends past kNoteShown characters of the raw note.
      // (never inside a formula: "\right. " ends a sentence only in the text)
      const std::string& n = row.result.note;
      const auto in_math = [&n](std::size_t at) {
        std::size_t open = 0;
        for (std::size_t i = n.find("\\(", 0); i < at; i = n.find("\\(", i + 2)) ++open;
        std::size_t close = 0;
        for (std::size_t i = n.find("\\)", 0); i < at; i = n.find("\\)", i + 2)) ++close;
        return open > close;
      };
      std::size_t cut = n.find(". ", kNoteShown);
      while (cut != std::string::npos && in_math(cut)) cut = n.find(". ", cut + 2);
      if (cut != std::string::npos && cut + 2 < row.result.note.size())
        note = escape(row.result.note.substr(0, cut + 1)) +
               "<details><summary>the rest of the note</summary>" +
               escape(row.result.note.substr(cut + 2)) + "</details>";
    }
    const std::string status{to_string(row.result.status)};
    const std::string id = escape(row.info.id);
    const std::string anchor =
        whole ? fmt::format(" id=\"claim-{}\" data-status=\"{}\"", id, status) : std::string();
    const std::string id_cell = whole
                                    ? fmt::format("<a href=\"#claim-{0}\">{0}</a>", id)
                                    : fmt::format("<a href=\"report.html#claim-{0}\">{0}</a>", id);
    const std::string_view statement = paper_statement(row.info.id);
    std::string r = fmt::format(
        "<tr class=\"status-{}\"{}><td class=\"claim-id\">{}<br/><span class=\"where\">{}</span>"
        "</td><td class=\"claim-paper\"><b>{}</b>{}</td><td class=\"claim-ours\"><b "
        "class=\"status\">{}</b><br/>{}</td>",
        status, anchor, id_cell, escape(row.info.where), escape(row.info.title),
        statement.empty() ? std::string() : "<br/>" + escape(statement), status, values);
    if (whole)
      r += fmt::format("<td class=\"claim-evidence\" data-source=\"{}\"></td>",
                       escape(row.result.source));
    r += "</tr>\n";
    // The note (how it was measured, the formulas compared) under the row, across the whole
    // table: a displayed difference or correction needs the width of the page, not of a column.
    if (!row.result.note.empty())
      r += fmt::format(
          "<tr class=\"claim-note status-{0}\"{1}><td colspan=\"{2}\"><div "
          "class=\"note\">{3}</div></td></tr>\n",
          status, whole ? fmt::format(" data-status=\"{}\" data-note-of=\"{}\"", status, id) : "",
          whole ? 4 : 3, note);
    return r;
  };
  const std::string header = fmt::format(
      "<table class=\"vibook-claims\">\n<tr><th>ID, where</th><th>The paper's claim (and what "
      "we check)</th><th>What we measured</th>{}</tr>\n",
      whole ? "<th>Evidence</th>" : "");
  if (!whole) {
    out += header;
    for (const auto& row : rows_) {
      if (!paper_filter.empty() && row.info.paper != paper_filter) continue;
      if (!ids.empty() && std::find(ids.begin(), ids.end(), row.info.id) == ids.end()) continue;
      out += row_html(row);
    }
    return out + "</table>\n";
  }
  for (const auto& [key, name] : kPapers) {
    out += fmt::format("<h2 class=\"vibook-paper\" id=\"paper-{}\">{}</h2>\n", key, name);
    out += header;
    for (const auto& row : rows_)
      if (row.info.paper == key) out += row_html(row);
    out += "</table>\n";
  }
  out +=
      "<script>\n"
      "(function () {  // vibook: show only the rows of the statuses ticked (offline, no "
      "library)\n"
      "  var boxes = document.querySelectorAll('p.vibook-filter input');\n"
      "  function apply() {\n"
      "    var show = {};\n"
      "    boxes.forEach(function (b) { show[b.value] = b.checked; });\n"
      "    document.querySelectorAll('table.vibook-claims tr[data-status]').forEach(function (r) "
      "{\n"
      "      r.style.display = show[r.getAttribute('data-status')] ? '' : 'none';\n"
      "    });\n"
      "  }\n"
      "  boxes.forEach(function (b) { b.addEventListener('change', apply); });\n"
      "})();\n"
      "</script>\n";
  return out;
}

namespace {
// HTML-escaped, TeX left for MathJax (a headline may quote the LaTeX of a correction).
std::string escape_keep_tex(std::string_view s) {
  std::string o;
  for (char c : s) {
    if (c == '<')
      o += "&lt;";
    else if (c == '>')
      o += "&gt;";
    else if (c == '&')
      o += "&amp;";
    else
      o += c;
  }
  return o;
}

// The kind of a claim on the landing page: its status and, when not reproduced, its cause.
struct Kind {
  const char* key;
  const char* column;   // the table's short heading
  const char* heading;  // the list's heading
};
constexpr Kind kKinds[] = {
    {"reproduced", "reproduced", "reproduced"},
    {"reproduced-with-caveat", "with a caveat", "reproduced with a caveat"},
    {"erratum-misprint", "misprint", "holds once the misprints are corrected (status erratum)"},
    {"not-reproduced-does-not-hold", "does not hold",
     "not reproduced: the statement does not hold"},
    {"not-reproduced-open-reading", "open reading",
     "not reproduced: depends on a reading the paper leaves open"},
    {"not-reproduced-edge-of-criterion", "at the edge",
     "not reproduced: at the edge of the criterion fixed beforehand"},
    {"not-reproduced-pre-asymptotic", "still converging",
     "not reproduced: the measured order is still converging at the smallest step sizes of the "
     "window fixed beforehand"},
    {"not-reproduced-unexplained", "no cause given", "not reproduced: cause not given"},
    {"pending", "pending", "pending"},
    // Counted apart from the claims: a deliberately wrong method of the field audit that vibook
    // failed (the audit working, not a method reproduced), and a question the paper leaves open.
    {"flagged", "flagged", "deliberately wrong methods of the audit, failed as they must be"},
    {"question", "not a claim", "questions the paper leaves open, measured"}};

// Claims whose criterion was set, or changed, after their data had first been seen, and how
// (the landing page lists them; each note or chapter gives the detail). "A": the field audit.
constexpr std::pair<const char*, const char*> kLateCriteria[] = {
    {"S-F3",
     "the tolerance on the mean steps, 0.01 h0 (twice the paper's rounding), was chosen after the "
     "values had first been seen"},
    {"S-F5",
     "the criterion (monotone decrease, residual at most 10 u|E| at tolerance 1e-17, step profile "
     "within 1e-4) was fixed after a first reading of the tolerance, as a bound on the step, had "
     "shown no effect at all (chapter 3)"},
    {"A",
     "for every row of the field audit, the variational order derived by the engine joined the "
     "criterion after the rows had first been measured (commit bf2628f); no row's status "
     "changed"},
    {"A",
     "the Galerkin rows of order 6 and 8 are measured in double-double, and every order fit keeps "
     "only the points where the local slopes have settled, both added after A-GAUSS4 and "
     "A-LOBATTO5 had been seen failing in double (pre-asymptotic on Kepler); the rows' criterion "
     "did not move, and those two rows changed to reproduced (chapter 8, the Galerkin methods)"},
    {"A",
     "the order study's rerun in double-double when double's local slopes do not settle was "
     "added after McLachlan and Atela's fifth-order splitting had been seen failing on Kepler in "
     "double (5.98, slopes unsettled); the splitting rows were added with it, under the audit's "
     "criterion, and A-SPLIT-MCLACHLAN-ATELA-5 passes with the rerun (chapter 8, Splittings)"}};

std::string kind_of(const ClaimResult& r) {
  if (r.id.find("-X-") != std::string::npos) return "question";
  if (r.id.starts_with("A-WRONG-") && r.status == Status::reproduced) return "flagged";
  switch (r.status) {
    case Status::reproduced:
      return "reproduced";
    case Status::reproduced_with_caveat:
      return "reproduced-with-caveat";
    case Status::erratum:
      return "erratum-misprint";
    case Status::pending:
      return "pending";
    case Status::not_reproduced:
      if (r.cause == "does-not-hold" || r.cause == "open-reading" ||
          r.cause == "edge-of-criterion" || r.cause == "pre-asymptotic")
        return "not-reproduced-" + r.cause;
      return "not-reproduced-unexplained";
  }
  return "pending";
}
}  // namespace

std::vector<std::string> Ledger::unexplained() const {
  std::vector<std::string> out;
  for (const auto& row : rows_) {
    const auto& r = row.result;
    if (row.info.id.find("-ERR-") != std::string::npos) continue;
    const bool failed = r.status == Status::not_reproduced || r.status == Status::erratum;
    if (failed &&
        (r.cause.empty() || r.headline.empty() || kind_of(r) == "not-reproduced-unexplained"))
      out.push_back(row.info.id);
  }
  return out;
}

std::string Ledger::to_summary_html() const {
  // Claims (the catalogue's IDs) counted once each, by status and cause; the errata (the
  // printed formulas found wrong) counted separately, never as claims.
  auto is_claim = [](const Row& r) { return r.info.id.find("-ERR-") == std::string::npos; };
  auto count = [&](std::string_view paper, std::string_view kind) {
    return std::count_if(rows_.begin(), rows_.end(), [&](const Row& r) {
      return is_claim(r) && (paper.empty() || r.info.paper == paper) && kind_of(r.result) == kind;
    });
  };
  // A cause of "not reproduced" gets a column when some claim has it ("does not hold" always),
  // so that the table fits the column of the page.
  // Rows counted apart (flagged wrong methods, questions) get a column only when there are some.
  auto apart = [](std::string_view key) { return key == "flagged" || key == "question"; };
  std::vector<const Kind*> shown;
  int causes = 0;
  std::string apart_heads;
  for (const auto& k : kKinds) {
    const std::string_view key = k.key;
    const bool cause = key.starts_with("not-reproduced-");
    if ((cause && key != "not-reproduced-does-not-hold") || apart(key))
      if (count({}, key) == 0) continue;
    shown.push_back(&k);
    causes += cause ? 1 : 0;
    if (key == "flagged") apart_heads += "<th rowspan=\"2\">wrong<br>method,<br>flagged</th>";
    if (key == "question") apart_heads += "<th rowspan=\"2\">not a<br>claim</th>";
  }
  std::string out = fmt::format(
      "<table class=\"vibook-summary\">\n<tr><th rowspan=\"2\">paper</th><th "
      "colspan=\"2\">reproduced</th><th rowspan=\"2\">erratum:<br>misprint</th><th "
      "colspan=\"{}\">not reproduced</th><th rowspan=\"2\">pending</th>{}<th "
      "rowspan=\"2\">claims</th><th rowspan=\"2\">errata<br>found</th><th "
      "rowspan=\"2\">of which<br>no small<br>correction</th></tr>\n<tr>",
      causes, apart_heads);
  for (const Kind* k : shown) {
    const std::string_view key = k->key;
    if (key == "erratum-misprint" || key == "pending" || apart(key)) continue;
    out += fmt::format("<th>{}</th>", key == "reproduced" ? "as stated" : k->column);
  }
  out += "</tr>\n";
  auto errata = [&](std::string_view paper) {
    return std::count_if(rows_.begin(), rows_.end(), [&](const Row& r) {
      return !is_claim(r) && (paper.empty() || r.info.paper == paper) &&
             r.result.status == Status::erratum;
    });
  };
  // Errata whose display no small edit corrects (cause does-not-hold): the formula vibook
  // derives, verified another way, stands in for the correction.
  auto replaced = [&](std::string_view paper) {
    return std::count_if(rows_.begin(), rows_.end(), [&](const Row& r) {
      return !is_claim(r) && (paper.empty() || r.info.paper == paper) &&
             r.result.status == Status::erratum && r.result.cause == "does-not-hold";
    });
  };
  // The claims column: what the status columns count (rows counted apart are not claims).
  auto claims_of = [&](std::string_view paper) {
    return std::count_if(rows_.begin(), rows_.end(), [&](const Row& r) {
      return is_claim(r) && (paper.empty() || r.info.paper == paper) && !apart(kind_of(r.result));
    });
  };
  for (const auto& [key, name] : kPapers) {
    out += fmt::format("<tr><td>{}</td>", name);
    for (const Kind* k : shown)
      out += fmt::format("<td class=\"kind-{}\">{}</td>", k->key, count(key, k->key));
    out += fmt::format("<td>{}</td><td>{}</td><td>{}</td></tr>\n", claims_of(key), errata(key),
                       replaced(key));
  }
  out += "<tr><td><b>all</b></td>";
  for (const Kind* k : shown)
    out += fmt::format("<td class=\"kind-{}\"><b>{}</b></td>", k->key, count({}, k->key));
  out += fmt::format("<td><b>{}</b></td><td><b>{}</b></td><td><b>{}</b></td></tr>\n</table>\n",
                     claims_of({}), errata({}), replaced({}));
  // Each claim that is not simply reproduced, headed by what failed, with a link to its row.
  for (const auto& k : kKinds) {
    if (std::string_view(k.key) == "reproduced" || std::string_view(k.key) == "pending" ||
        std::string_view(k.key) == "flagged")
      continue;
    std::string items;
    for (const auto& r : rows_) {
      if (!is_claim(r) || kind_of(r.result) != k.key) continue;
      const std::string id = escape(r.info.id);
      std::string head =
          r.result.headline.empty() ? escape(r.info.title) : escape_keep_tex(r.result.headline);
      if (r.result.status == Status::reproduced_with_caveat && r.result.headline.empty())
        head = escape(r.info.title) + " (the caveat is in the note)";
      std::string errs;
      for (const auto& e : r.result.errata)
        errs += fmt::format("{0}<a href=\"report.html#claim-{1}\">{1}</a>",
                            errs.empty() ? "" : ", ", escape(e));
      items += fmt::format(
          "<li><a href=\"report.html#claim-{0}\"><code>{0}</code></a> ({1}): {2}{3}</li>\n", id,
          escape(r.info.where), head, errs.empty() ? "" : " — errata " + errs);
    }
    if (!items.empty())
      out += fmt::format("<p><b>{}</b>:</p>\n<ul class=\"vibook-findings\">\n{}</ul>\n", k.heading,
                         items);
  }
  // Criteria that were not all fixed before the first measurement: said here, not only in
  // the notes.
  {
    std::string late;
    for (const auto& [id, why] : kLateCriteria)
      late +=
          std::string_view(id) == "A"
              ? fmt::format("<li><a href=\"report.html#paper-A\">the field audit</a>: {}</li>\n",
                            escape(why))
              : fmt::format(
                    "<li><a href=\"report.html#claim-{0}\"><code>{0}</code></a>: "
                    "{1}</li>\n",
                    escape(id), escape(why));
    out +=
        "<p><b>Criteria set after a first look at the data</b> (the statuses follow them; a "
        "reader may weigh them accordingly):</p>\n<ul class=\"vibook-findings\">\n" +
        late + "</ul>\n";
  }
  std::string items;
  for (const auto& r : rows_) {
    if (is_claim(r)) continue;
    items += fmt::format(
        "<li><a href=\"report.html#claim-{0}\"><code>{0}</code></a> ({1}, {2}): {3}{4}</li>\n",
        escape(r.info.id), escape(r.info.where), to_string(r.result.status),
        escape_keep_tex(r.info.title),
        r.result.cause == "does-not-hold"
            ? " — no small edit corrects it: the formula vibook derives, verified another way, "
              "stands in its place"
            : "");
  }
  if (!items.empty())
    out +=
        "<p><b>Errata</b> (a printed formula or statement found wrong; the report shows the "
        "print, the correction and the evidence):</p>\n<ul class=\"vibook-findings\">\n" +
        items + "</ul>\n";
  return out;
}

}  // namespace vibook::claims
