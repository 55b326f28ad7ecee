// Doctests of the Vermeeren 2017 figures. `vibook figure vermeeren-fig1` runs the same
// function as the test case here (modified/vermeeren_fig1.cpp).
#include <cmath>
#include <string>

#include <doctest/doctest.h>

#include "vibook/claims/ledger.hpp"
#include "vibook/core/tolerance.hpp"
#include "vibook/modified/checks.hpp"

using namespace vibook;

TEST_CASE("vermeeren-fig1: claim V-EX3 measured and asserted") {
  const auto fig = checks::vermeeren_fig1();
  REQUIRE(fig.id == "vermeeren-fig1");
  const auto results = fig.run({});
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
