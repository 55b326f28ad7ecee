// Doctests of integrators/: each fast kernel equals the generic solver on its own discrete
// Lagrangian (claim V-EX1), and has its order, measured two-sided on Kepler (nonlinear).
#include <cmath>

#include <doctest/doctest.h>
#include <fmt/format.h>

#include "vibook/core/order.hpp"
#include "vibook/figures/check_v_ex1.hpp"
#include "vibook/figures/registry.hpp"
#include "vibook/integrators/kernels.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/mechanics/del_solver.hpp"
#include "vibook/mechanics/discrete_lagrangian.hpp"

using namespace vibook;

TEST_CASE("V-EX1: kernels equal the generic solver on their discrete Lagrangians") {
  for (const auto& [name, a] : figures::v_ex1_agreements()) {
    INFO(name, ": one-step ", a.one_step, ", trajectory ", a.trajectory);
    CHECK(a.one_step <= figures::kOneStepTolerance);
    CHECK(a.trajectory <= figures::kTrajectoryTolerance);
    CHECK(a.max_iterations >= 1);
    CHECK(a.max_iterations <= 6);
  }
  // The papers' scaling L_disc ≈ L with (5) taken literally gives p/h.
  CHECK(std::abs(figures::v_ex1_literal_scaling_factor() - 1.0 / 0.05) <= 1e-12 * 20.0);
  // The ledger check records the same numbers and a measured status.
  const auto results = figures::find("check-v-ex1")->run({});
  REQUIRE(results.size() == 1);
  CHECK(results[0].status == claims::Status::reproduced_with_caveat);
}

namespace {

// Global error |(q, p) − exact| at T = 3 (half a period of e = 0.5 is π) after n steps.
template <class Stepper>
double kepler_error(Stepper stepper, int n) {
  const double T = 3.0, h = T / n;
  State<2> s = kepler_perihelion_state(0.5);
  for (int k = 0; k < n; ++k) stepper.step(s.q, s.p, h);
  const State<2> ex = KeplerOrbit::perihelion(0.5).at(T);
  return std::max((s.q - ex.q).lpNorm<Eigen::Infinity>(), (s.p - ex.p).lpNorm<Eigen::Infinity>());
}

template <class MakeStepper>
OrderFit measured_order(MakeStepper make) {
  std::vector<double> hs, errs;
  for (int n = 64; n <= 4096; n *= 2) {
    hs.push_back(3.0 / n);
    errs.push_back(kepler_error(make(), n));
  }
  // Round-off plateau: errors below 1e-11 are not fitted (n·ε·|state| is ~1e-12 here).
  return fit_order(hs, errs, 1e-11);
}

}  // namespace

TEST_CASE("measured orders on Kepler e = 0.5, h = 3/64 ... 3/4096 (two-sided, |p - p0| < 0.1)") {
  const auto L = mechanical_lagrangian(Kepler{});
  struct Row {
    const char* name;
    double expected;
    OrderFit fit;
  };
  const Row rows[] = {
      {"se", 1.0, measured_order([] { return SymplecticEuler<Kepler>(); })},
      {"se-adjoint", 1.0, measured_order([] { return SymplecticEulerAdjoint<Kepler>(); })},
      {"sv", 2.0, measured_order([] { return StormerVerlet<Kepler>(); })},
      {"midpoint", 2.0, measured_order([] { return ImplicitMidpoint<Kepler>(); })},
      {"del-generic(midpoint)", 2.0,
       measured_order([&] { return make_del_integrator<2>(midpoint_dl(L)); })},
  };
  for (const auto& r : rows) {
    INFO(r.name, ": fitted order ", r.fit.slope, " over ", r.fit.points, " step sizes");
    CHECK(r.fit.points >= 5);
    CHECK(std::abs(r.fit.slope - r.expected) < 0.1);
  }
}
