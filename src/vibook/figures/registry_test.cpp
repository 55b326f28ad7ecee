// Doctests of the registry (the index of every section's checks) and the ledger.
#include <algorithm>
#include <cmath>
#include <set>

#include <doctest/doctest.h>

#include "vibook/claims/ledger.hpp"
#include "vibook/core/tolerance.hpp"
#include "vibook/figures/registry.hpp"
#include "vibook/verify/field_audit.hpp"

using namespace vibook;

TEST_CASE("ledger: every catalogued claim present, pending until measured") {
  claims::Ledger ledger;
  CHECK(ledger.rows().size() == claims::catalogue().size());
  CHECK(claims::catalogue().size() == 39 + verify::audit_entries().size());
  for (const auto& row : ledger.rows()) CHECK(row.result.status == claims::Status::pending);
  // Every claim a check names is in the catalogue, or an erratum (which describes itself).
  std::set<std::string> catalogued;
  for (const auto& c : claims::catalogue()) catalogued.insert(c.id);
  for (const auto* list : {&figures::registry(), &figures::long_studies()})
    for (const auto& c : *list)
      for (const auto& id : c.claims) {
        INFO(c.id, " names ", id);
        CHECK((catalogued.count(id) == 1 || id.find("-ERR-") != std::string::npos));
      }
  // One check run (the whole ledger is run by the book build, through the same run_check):
  // exactly its claims are measured, the others stay pending.
  const auto* check = figures::find("check-v-ex1");
  REQUIRE(check != nullptr);
  claims::Ledger measured;
  for (const auto& rs : figures::run_checks({check}, 1))
    for (const auto& r : rs) measured.record(r);
  for (const auto& row : measured.rows()) {
    INFO(row.info.id);
    const bool named =
        std::find(check->claims.begin(), check->claims.end(), row.info.id) != check->claims.end();
    CHECK((row.result.status != claims::Status::pending) == named);
  }
  // JSON shape of `vibook claims --json`.
  const auto js = measured.to_json();
  REQUIRE(js.contains("claims"));
  const auto& first = js["claims"][0];
  for (const char* key : {"id", "paper", "title", "status", "values", "note"})
    CHECK(first.contains(key));
}

TEST_CASE("run_check: a check is held to the claims it names") {
  using claims::ClaimResult;
  using claims::Status;
  auto fake = [](std::vector<std::string> names, std::vector<ClaimResult> results) {
    figures::Check c;
    c.id = "fake-check";
    c.claims = std::move(names);
    c.run = [results](const figures::Context&) { return results; };
    return c;
  };
  auto result = [](std::string id, Status st, std::optional<claims::ClaimInfo> info = {}) {
    ClaimResult r;
    r.id = std::move(id);
    r.status = st;
    r.source = "fake-check";
    r.info = std::move(info);
    return r;
  };
  const ClaimResult v_ex1 = result("V-EX1", Status::reproduced);
  const ClaimResult v_p1 = result("V-P1", Status::reproduced);
  const ClaimResult v_p1_pending = result("V-P1", Status::pending);
  const ClaimResult erratum =
      result("V-ERR-9", Status::erratum, claims::ClaimInfo{"V-ERR-9", "V", "(9)", "t"});
  // Names one and measures it (an erratum beside it): accepted.
  CHECK(figures::run_check(fake({"V-EX1"}, {v_ex1, erratum}), {}).size() == 2);
  // Names two, measures one: refused, naming the claim.
  CHECK_THROWS_WITH_AS(figures::run_check(fake({"V-EX1", "V-P1"}, {v_ex1}), {}),
                       doctest::Contains("V-P1"), std::logic_error);
  // Leaves a named claim pending: refused.
  CHECK_THROWS_AS(figures::run_check(fake({"V-EX1", "V-P1"}, {v_ex1, v_p1_pending}), {}),
                  std::logic_error);
  // Measures a claim it does not name: refused.
  CHECK_THROWS_WITH_AS(figures::run_check(fake({"V-P1"}, {v_p1, v_ex1}), {}),
                       doctest::Contains("V-EX1"), std::logic_error);
}

TEST_CASE("ledger: errata") {
  // Unknown IDs are refused unless they are errata with their own description.
  claims::Ledger l2;
  claims::ClaimResult unknown;
  unknown.id = "X-1";
  unknown.status = claims::Status::reproduced;
  CHECK_THROWS_AS(l2.record(unknown), std::invalid_argument);
  claims::ClaimResult e5;
  e5.id = "V-ERR-5";
  e5.status = claims::Status::erratum;
  e5.info = claims::ClaimInfo{"V-ERR-5", "V", "(5)", "t"};
  l2.record(e5);
  CHECK(l2.find("V-ERR-5") != nullptr);
}
