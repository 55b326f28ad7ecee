// Doctests of the ledger's HTML: the reproduction report and the chapter excerpts.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <string>

#include "vibook/claims/ledger.hpp"

using namespace vibook::claims;

namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("every catalogued claim has the paper's statement to print beside our measurement") {
  for (const auto& c : catalogue()) {
    INFO(c.id);
    CHECK(!paper_statement(c.id).empty());
  }
  // The paper's own numbers are in it (S-F2: AVI about 1e-4, EpAVI about 1e-13).
  CHECK(std::string(paper_statement("S-F2")).find("1e-13") != std::string::npos);
  CHECK(paper_statement("S-ERR-14").empty());
}

TEST_CASE("the reproduction report: grouped by paper, one anchored row per claim, side by side") {
  Ledger ledger;
  ClaimResult r;
  r.id = "S-F2";
  r.status = Status::not_reproduced;
  r.values = {{"avi_energy_err", 2.5e-5}};
  r.note = "a <note>";
  r.source = "sharma-fig2";
  ledger.record(r);
  const std::string html = ledger.to_html();
  // One heading and one table per paper, in the book's order, then the field audit.
  CHECK(count(html, "<h2 class=\"vibook-paper\"") == 4);
  CHECK(count(html, "<table class=\"vibook-claims\">") == 4);
  CHECK(html.find("id=\"paper-S\"") < html.find("id=\"paper-V\""));
  CHECK(html.find("id=\"paper-V\"") < html.find("id=\"paper-SS\""));
  CHECK(html.find("id=\"paper-SS\"") < html.find("id=\"paper-A\""));
  // Every claim once, with its anchor and an evidence cell naming what measured it.
  CHECK(count(html, " id=\"claim-") == catalogue().size());
  const auto row = html.substr(html.find("id=\"claim-S-F2\""));
  // the row, and the note's full-width row under it
  const auto end = row.find("</tr>", row.find("</tr>") + 5);
  const std::string tr = row.substr(0, end);
  CHECK(tr.find("<tr class=\"claim-note status-not-reproduced\" data-status=\"not-reproduced\" "
                "data-note-of=\"S-F2\"><td colspan=\"4\">") != std::string::npos);
  CHECK(tr.find("data-status=\"not-reproduced\"") != std::string::npos);
  CHECK(tr.find("about 1e-13") != std::string::npos);  // the paper's side
  CHECK(tr.find("avi_<wbr>energy_<wbr>err&nbsp;=&nbsp;2.5e-05") != std::string::npos);  // ours
  CHECK(tr.find("a &lt;note&gt;") != std::string::npos);                                // escaped
  CHECK(tr.find("data-source=\"sharma-fig2\"") != std::string::npos);
  // A chapter's excerpt: the same columns without anchors or evidence, its IDs linking to
  // the report.
  const std::string excerpt = ledger.to_html({}, {"S-F2"});
  CHECK(count(excerpt, "<tr class=\"status-") == 1);
  CHECK(count(excerpt, "<tr class=\"claim-note") == 1);
  CHECK(excerpt.find(" id=\"claim-") == std::string::npos);
  CHECK(excerpt.find("report.html#claim-S-F2") != std::string::npos);
  CHECK(excerpt.find("claim-evidence") == std::string::npos);
}

TEST_CASE("long notes and long lists of values are folded, nothing is lost") {
  Ledger ledger;
  ClaimResult r;
  r.id = "SS-T12";
  r.status = Status::not_reproduced;
  for (int i = 0; i < 12; ++i) r.values.push_back({"v" + std::to_string(i), double(i)});
  std::string note;
  for (int i = 0; i < 40; ++i) note += "Sentence " + std::to_string(i) + " of the note. ";
  r.note = note + "Last <term>.";
  r.source = "check-modified";
  ledger.record(r);
  const std::string html = ledger.to_html({}, {"SS-T12"});
  CHECK(count(html, "<details>") == 2);
  CHECK(html.find("<summary>4 more values</summary>") != std::string::npos);
  CHECK(html.find("v11&nbsp;=&nbsp;11") != std::string::npos);  // folded, not dropped
  CHECK(html.find("Sentence 0 of the note.") < html.find("<summary>the rest of the note"));
  CHECK(html.find("Last &lt;term&gt;.") != std::string::npos);
}

TEST_CASE("a long note is never folded inside a formula") {
  // "\right. " inside \( \) looks like the end of a sentence; the fold waits for the text's.
  Ledger ledger;
  ClaimResult r;
  r.id = "SS-T12";
  r.status = Status::erratum;
  // Built by append: GCC 12's -Warray-bounds misreads a chain of operator+ on temporaries
  // (a known false positive once the string headers come precompiled).
  r.note = std::string(390, 'x');
  r.note.append(" Corrected: \\(\\left[a \\right. \\quad \\left. + b\\right]\\), ");
  r.note.append("which agrees. ").append(std::string(300, 'y')).append(".");
  ledger.record(r);
  const std::string html = ledger.to_html({}, {"SS-T12"});
  const auto fold = html.find("<details><summary>the rest of the note");
  REQUIRE(fold != std::string::npos);
  CHECK(html.rfind("which agrees.", fold) != std::string::npos);  // folded after the formula
  CHECK(html.find("&#92;right]&#92;)") < fold);  // the formula whole, before the fold
}

TEST_CASE("the landing page's counts: a flagged wrong method and a question are not claims") {
  Ledger ledger;
  auto record = [&](const char* id, Status s) {
    ClaimResult r;
    r.id = id;
    r.status = s;
    r.source = "test";
    ledger.record(r);
  };
  record("A-WRONG-DIGIT", Status::reproduced);  // vibook failed it, as it must
  record("A-YOSHIDA4", Status::reproduced);
  record("S-X-EXIST", Status::reproduced);
  const std::string html = ledger.to_summary_html();
  CHECK(html.find("wrong<br>method,<br>flagged") != std::string::npos);
  CHECK(html.find("not a<br>claim") != std::string::npos);
  // The audit's row: one reproduced, one flagged; its claims column counts the reproduced one
  // and the catalogue's other audit rows (pending here), never the flagged one.
  const auto audit = html.substr(html.find("<td>Field audit</td>"));
  const auto row = audit.substr(0, audit.find("</tr>"));
  CHECK(row.find("<td class=\"kind-reproduced\">1</td>") != std::string::npos);
  CHECK(row.find("<td class=\"kind-flagged\">1</td>") != std::string::npos);
  std::size_t audit_rows = 0;
  for (const auto& c : catalogue()) audit_rows += c.paper == "A" ? 1 : 0;
  CHECK(row.find(fmt::format("<td>{}</td>", audit_rows - 1)) != std::string::npos);
  // Sharma's row: the question counted apart.
  const auto sharma = html.substr(html.find("<td>Sharma et al. 2022</td>"));
  CHECK(sharma.substr(0, sharma.find("</tr>")).find("<td class=\"kind-question\">1</td>") !=
        std::string::npos);
  // A flagged method is not listed among the findings; the question is, under its own heading.
  CHECK(html.find("questions the paper leaves open") != std::string::npos);
  CHECK(html.find("deliberately wrong methods of the audit") == std::string::npos);
  // Criteria set after a first look are said on the landing page, not only in the notes.
  CHECK(html.find("Criteria set after a first look at the data") != std::string::npos);
  CHECK(html.find("report.html#claim-S-F3\"><code>S-F3</code></a>: the tolerance") !=
        std::string::npos);
}

TEST_CASE("the landing page's counts: an erratum without a small correction is counted apart") {
  Ledger ledger;
  auto erratum = [&](const char* id, const char* cause) {
    ClaimResult r;
    r.id = id;
    r.status = Status::erratum;
    r.cause = cause;
    r.source = "test";
    r.info = ClaimInfo{id, "SS", "(9.9)", "a display"};
    ledger.record(r);
  };
  erratum("SS-ERR-9.1", "misprint");
  erratum("SS-ERR-9.2", "does-not-hold");
  const std::string html = ledger.to_summary_html();
  CHECK(html.find("of which<br>no small<br>correction") != std::string::npos);
  const auto ss = html.substr(html.find("<td>Shen &amp; Sun 2025</td>"));
  // its last two cells: errata found 2, of which 1 without a small correction
  CHECK(ss.substr(0, ss.find("</tr>")).ends_with("<td>2</td><td>1</td>"));
  CHECK(html.find("SS-ERR-9.2</code></a> ((9.9), erratum): a display — no small edit corrects "
                  "it") != std::string::npos);
  CHECK(html.find("SS-ERR-9.1</code></a> ((9.9), erratum): a display</li>") != std::string::npos);
}
