// Doctests of integrators/: each fast kernel equals the generic solver on its own discrete
// Lagrangian (claim V-EX1), and has its order, measured two-sided on Kepler (nonlinear).
#include <cmath>

#include <doctest/doctest.h>
#include <fmt/format.h>

#include "vibook/core/order.hpp"
#include "vibook/figures/registry.hpp"
#include "vibook/integrators/check_v_ex1.hpp"
#include "vibook/integrators/kernels.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/mechanics/del_solver.hpp"
#include "vibook/mechanics/discrete_lagrangian.hpp"

using namespace vibook;

TEST_CASE("V-EX1: kernels equal the generic solver on their discrete Lagrangians") {
  for (const auto& agreement : checks::v_ex1_agreements()) {
    const auto& name = agreement.first;  // (not a structured binding: doctest's INFO captures it)
    const auto& a = agreement.second;
    INFO(name, ": one-step ", a.one_step, ", trajectory ", a.trajectory);
    CHECK(a.one_step <= checks::kOneStepTolerance);
    CHECK(a.trajectory <= checks::kTrajectoryTolerance);
    CHECK(a.max_iterations >= 1);
    CHECK(a.max_iterations <= 6);
  }
  // The papers' scaling L_disc ≈ L with (5) taken literally gives p/h.
  CHECK(std::abs(checks::v_ex1_literal_scaling_factor() - 1.0 / 0.05) <= 1e-12 * 20.0);
  // The ledger check records the same numbers and a measured status.
  const auto results = figures::find("check-v-ex1")->run({});
  REQUIRE(results.size() == 3);
  CHECK(results[0].id == "V-EX1");
  // (a)-(d) and (4) read from the paper agree; both maps of (5) lack the factor h: a misprint.
  CHECK(results[0].status == claims::Status::erratum);
  CHECK(results[0].cause == "misprint");
  CHECK(results[0].value("displays_agreeing") == 5);  // (a)-(d) and (4)
  CHECK(results[1].id == "V-P1");
  CHECK(results[1].status == claims::Status::reproduced);
  CHECK(results[2].id == "V-ERR-5");
  CHECK(results[2].status == claims::Status::erratum);
  REQUIRE(results[2].comparisons.size() == 2);  // p_j and p_{j+1}, each corrected by h
  for (const auto& c : results[2].comparisons)
    CHECK(c.edit.find("multiplied by \\(h\\)") != std::string::npos);
}

TEST_CASE("measured orders on Kepler e = 0.5, h = 3/64 ... 3/4096 (two-sided, |p - p0| < 0.1)") {
  for (const auto& o : checks::kernel_orders()) {
    INFO(o.method, ": fitted order ", o.slope, " over ", o.points, " step sizes");
    CHECK(o.points >= 5);
    CHECK(std::abs(o.slope - o.expected) < checks::kOrderTolerance);
  }
}

TEST_CASE("V-P1: the discrete Euler-Lagrange expression is consistent (measured order)") {
  for (const auto& o : checks::del_consistency_orders()) {
    INFO(o.method, ": fitted order ", o.slope, " over ", o.points, " step sizes");
    CHECK(o.points >= 5);
    CHECK(std::abs(o.slope - o.expected) < checks::kOrderTolerance);
  }
}
