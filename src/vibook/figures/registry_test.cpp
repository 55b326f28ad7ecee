// Doctests of the registry (the index of every section's checks) and the ledger.
#include <cmath>
#include <set>

#include <doctest/doctest.h>

#include "vibook/claims/ledger.hpp"
#include "vibook/core/tolerance.hpp"
#include "vibook/figures/registry.hpp"

using namespace vibook;

TEST_CASE("ledger: every catalogued claim present, pending until measured") {
  claims::Ledger ledger;
  CHECK(ledger.rows().size() == claims::catalogue().size());
  CHECK(claims::catalogue().size() == 39);
  for (const auto& row : ledger.rows()) CHECK(row.result.status == claims::Status::pending);
  // After measuring: exactly the claims some check names are measured, the rest pending, and
  // the extra rows are the errata the checks add.
  const auto measured = figures::measure_all(2);
  std::set<std::string> checked;
  for (const auto& c : figures::registry()) checked.insert(c.claims.begin(), c.claims.end());
  std::size_t errata = 0;
  for (const auto& row : measured.rows()) {
    INFO(row.info.id);
    CHECK((row.result.status != claims::Status::pending) == (checked.count(row.info.id) == 1));
    if (row.info.id.find("-ERR-") != std::string::npos) {
      ++errata;
      CHECK(row.result.status == claims::Status::erratum);
    }
  }
  REQUIRE(measured.find("V-ERR-5") != nullptr);
  CHECK(measured.rows().size() == claims::catalogue().size() + errata);
  // JSON shape of `vibook claims --json`.
  const auto js = measured.to_json();
  REQUIRE(js.contains("claims"));
  const auto& first = js["claims"][0];
  for (const char* key : {"id", "paper", "title", "status", "values", "note"})
    CHECK(first.contains(key));
  // Unknown IDs are refused unless they are errata with their own description.
  claims::Ledger l2;
  CHECK_THROWS_AS(l2.record({"X-1", claims::Status::reproduced, {}, "", "", std::nullopt}),
                  std::invalid_argument);
  l2.record({"V-ERR-5",
             claims::Status::erratum,
             {},
             "",
             "",
             claims::ClaimInfo{"V-ERR-5", "V", "(5)", "t"}});
  CHECK(l2.find("V-ERR-5") != nullptr);
}
