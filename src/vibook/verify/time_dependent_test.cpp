// Doctests of the map study on a time-dependent system (chapter "Verify your own integrator",
// section "Time-dependent systems"): the state carries the clock, z = (q, p, t). A method that
// evaluates the forcing at the right times passes at its order; the same method with the time
// advanced by the wrong coefficient fails the order on the forced system, although it is right
// on an autonomous one; a method that is not symplectic fails symplecticity of the time-t map.
#include <algorithm>
#include <cmath>
#include <memory>

#include <doctest/doctest.h>

#include "vibook/integrators/galerkin.hpp"
#include "vibook/integrators/prk.hpp"
#include "vibook/verify/expression.hpp"
#include "vibook/verify/map_study.hpp"
#include "vibook/verify/typed_potential.hpp"
#include "vibook/verify/typed_system.hpp"

using namespace vibook;
using namespace vibook::verify;

namespace {

// A typed L(q, v, t), e.g. the forced pendulum L = v²/2 + cos q + q cos(t)/2 (H = p²/2 − cos q
// − q cos(t)/2, reversible under (q, p, t) -> (q, −p, −t)).
std::unique_ptr<TypedDiscreteLagrangian> forced(const std::string& lagrangian) {
  TypedTexts t{"", "", lagrangian, "", 0};
  t.system_only = true;
  t.allow_time = true;
  return std::make_unique<TypedDiscreteLagrangian>(t);
}

// Gauss's Galerkin method with two nodes on L(q, v, t), its nodes at t + c_i h (`stale`: every
// node at the step's start time t, i.e. the time advanced with coefficient 0 inside the step).
Step gauss2(const TypedDiscreteLagrangian& sys, bool stale) {
  const TypedDiscreteLagrangian* s = &sys;
  auto clock = std::make_shared<double>(0.0);
  auto L = [s, stale, clock](const auto& q, const auto& v,
                             const auto& t) -> typename std::remove_cvref_t<decltype(q)>::Scalar {
    using T = typename std::remove_cvref_t<decltype(q)>::Scalar;
    return s->lagrangian<1, T>(Vec<T, 1>(q), Vec<T, 1>(v), stale ? constant_of<T>(*clock) : T(t));
  };
  auto integrator =
      std::make_shared<GalerkinIntegrator<1, Eigen::Dynamic, decltype(L)>>(L, gauss_rule(2));
  return [integrator, clock](Eigen::VectorXd& z, double h) {
    if (z.size() == 3) *clock = z(2);
    step_qp<1>(*integrator, z, h);
  };
}

MapMeasurement measure(const TypedDiscreteLagrangian& sys, const std::string& text, Step step,
                       double expected) {
  MapStudy s;
  set_typed_lagrangian(s, sys, text, {0.5}, {0.0});
  s.step = std::move(step);
  s.expected = expected;
  s.steps = 4096;  // the energy run (the autonomous case's only)
  // a first-order method never reaches the window: its walk stops here, and the fit takes its
  // 6 smallest step sizes
  s.max_substeps = 2e4;
  s.symmetric_claimed = true;
  MapMeasurement r;
  measure_map(s, r);
  return r;
}

bool failed(const MapMeasurement& r, const std::string& part) {
  return std::find(r.failed.begin(), r.failed.end(), part) != r.failed.end();
}

}  // namespace

TEST_CASE("time-dependent system: the clock in the state, the forcing at the nodes' times") {
  const std::string text = "v^2/2 + cos(q) + q*cos(t)/2";
  const auto sys = forced(text);
  REQUIRE(sys->time_dependent());

  SUBCASE("Gauss 2 with the nodes at t + c_i h: order 4, symplectic, symmetric, reversible") {
    const MapMeasurement r = measure(*sys, text, gauss2(*sys, false), 4);
    CHECK(r.failed.empty());
    const double p = r.js["order"]["fitted"].get<double>();
    CHECK(std::abs(p - 4) < 0.2);
    CHECK(r.js["reversibility"]["required"].get<bool>());
    CHECK_FALSE(r.js["energy"]["judged"].get<bool>());
  }
  SUBCASE("the same with every node at the step's start time: order 1 on the forced system") {
    const MapMeasurement r = measure(*sys, text, gauss2(*sys, true), 4);
    CHECK(failed(r, "order"));
    const double p = r.js["order"]["fitted"].get<double>();
    CHECK(std::abs(p - 1) < 0.2);
  }
  SUBCASE("... and right on the autonomous pendulum, where the time is never read") {
    const std::string autonomous = "v^2/2 + cos(q)";
    const auto a = forced(autonomous);
    REQUIRE_FALSE(a->time_dependent());
    const MapMeasurement r = measure(*a, autonomous, gauss2(*a, true), 4);
    CHECK(r.failed.empty());
  }
  SUBCASE("explicit Euler with the clock: not symplectic as a time-t map") {
    const Step euler = [](Eigen::VectorXd& z, double h) {
      const double q = z(0), p = z(1), t = z(2);
      z(0) = q + h * p;
      z(1) = p + h * (-std::sin(q) + std::cos(t) / 2);
      z(2) = t + h;
    };
    const MapMeasurement r = measure(*sys, text, euler, 1);
    CHECK(failed(r, "symplectic"));
    CHECK(failed(r, "symmetric"));
    CHECK_FALSE(failed(r, "order"));
  }
}

TEST_CASE("time-dependent system: a forcing odd in t breaks the reversing symmetry") {
  // q sin t: H(q, −p, −t) ≠ H(q, p, t), so reversibility is reported but not required.
  const std::string text = "v^2/2 + cos(q) + q*sin(t)/2";
  const auto sys = forced(text);
  const MapMeasurement r = measure(*sys, text, gauss2(*sys, false), 4);
  CHECK(r.failed.empty());
  CHECK_FALSE(r.js["reversibility"]["system_reversible"].get<bool>());
  CHECK_FALSE(r.js["reversibility"]["required"].get<bool>());
}

namespace {

// V(q, t) typed, as the tableau route's problem type, with every stage's time replaced by the
// step's start time when `stale` (the clock the step was told): a PRK method with its stages at
// t where the extended system puts them at t + c_i h.
struct StalePotential {
  static constexpr int N = 1;
  TypedPotential<1> inner;
  std::shared_ptr<double> clock;
  template <class T, class Time>
  T potential(const Vec<T, 1>& q, const Time&) const {
    return inner.potential<T>(q, *clock);
  }
  template <class T, class Time>
  Vec<T, 1> gradient(const Vec<T, 1>& q, const Time&) const {
    return inner.gradient<T>(q, *clock);
  }
};

// Gauss's two-stage tableau (collocation: a = â), the method of examples/tableaus/gauss2.json.
PrkTableau gauss2_tableau() {
  const double r = std::sqrt(3.0) / 6;
  const std::vector<std::vector<double>> a = {{0.25, 0.25 - r}, {0.25 + r, 0.25}};
  return {a, a, {0.5, 0.5}, {0.5, 0.5}};
}

}  // namespace

TEST_CASE("time-dependent system: a tableau's stages at t + c_i h (the --tableau route)") {
  const std::string text = "v^2/2 + cos(q) + q*cos(t)/2";
  const auto sys = forced(text);
  TypedTexts vt{"", "-cos(x) - x*cos(t)/2", "", "p^2/2 + V(q)", 0};
  vt.system_only = true;
  vt.allow_time = true;
  const TypedDiscreteLagrangian v(vt);
  REQUIRE(v.time_dependent());
  SUBCASE("Gauss 2 as a PRK tableau, each stage at its time: order 4") {
    auto m = std::make_shared<PartitionedRkMethod<Eigen::Dynamic, TypedPotential<1>>>(
        TypedPotential<1>{&v}, gauss2_tableau());
    const Step step = [m](Eigen::VectorXd& z, double h) { step_qp<1>(*m, z, h); };
    const MapMeasurement r = measure(*sys, text, step, 4);
    CHECK(r.failed.empty());
    CHECK(std::abs(r.js["order"]["fitted"].get<double>() - 4) < 0.2);
  }
  SUBCASE("the same with every stage at the step's start time: order 1") {
    auto clock = std::make_shared<double>(0.0);
    auto m = std::make_shared<PartitionedRkMethod<Eigen::Dynamic, StalePotential>>(
        StalePotential{TypedPotential<1>{&v}, clock}, gauss2_tableau());
    const Step step = [m, clock](Eigen::VectorXd& z, double h) {
      *clock = z(2);
      step_qp<1>(*m, z, h);
    };
    const MapMeasurement r = measure(*sys, text, step, 4);
    CHECK(failed(r, "order"));
    CHECK(std::abs(r.js["order"]["fitted"].get<double>() - 1) < 0.2);
  }
}
