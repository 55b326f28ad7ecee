// Doctests of the figures and the ledger. `vibook figure vermeeren-fig1` runs the same
// function as the first test case here.
#include <cmath>
#include <set>

#include <doctest/doctest.h>

#include "vibook/claims/ledger.hpp"
#include "vibook/core/tolerance.hpp"
#include "vibook/figures/registry.hpp"

using namespace vibook;

namespace {}  // namespace

TEST_CASE("vermeeren-fig1: claim V-EX3 measured and asserted") {
  const auto* fig = figures::find("vermeeren-fig1");
  REQUIRE(fig != nullptr);
  const auto results = fig->run({});
  REQUIRE(results.size() == 1);
  const auto& r = results[0];
  INFO(r.note);
  CHECK(r.id == "V-EX3");
  CHECK(r.status == claims::Status::reproduced);
  // Period 6 at h = 1 over 1e5 periods: the floating-point recurrence is exactly periodic.
  CHECK(r.value("period6_max_dev_1e5_periods") <= 600000 * kEps);
  CHECK(std::abs(r.value("exact_modified_period_h1") - 6.0) <= 8 * kEps);
  // Exact modified frequency against the discrete solution: round-off, conditioning-aware.
  for (const char* h : {"0.1", "0.5", "1", "1.5", "1.9"}) {
    CHECK(r.value(std::string("exact_modified_max_dev_h") + h) <=
          r.value(std::string("exact_modified_bound_h") + h));
  }
  CHECK(r.value("exact_modified_max_dev_h1.9_long_double") * 100 <
        r.value("exact_modified_max_dev_h1.9"));
  // Truncations: order 4 is closer than order 2 on [80, 100], in both readings.
  CHECK(r.value("zoom_max_dev_order4_at_rest") < r.value("zoom_max_dev_order2_at_rest"));
  CHECK(r.value("zoom_max_dev_order4_matched") < r.value("zoom_max_dev_order2_matched"));
  CHECK(r.value("series_sum40_rel_err_h1") <= 8 * kEps);
}

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
