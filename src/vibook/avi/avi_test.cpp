// Doctests of avi/ and epavi/ on Kepler: first step exactly h0, energy behaviour, adaptivity.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <doctest/doctest.h>

#include "vibook/avi/avi.hpp"
#include "vibook/epavi/epavi.hpp"
#include "vibook/kepler/kepler.hpp"

using namespace vibook;

namespace {
// Kepler e = 0.7 from perihelion, the start of every AVI test here.
const State<2> kPerihelion = kepler_perihelion_state(0.7);
const double kH0 = energy(Kepler{}, kPerihelion.q, kPerihelion.p);

// The state at perihelion, and an AVI with the given monitor whose first step from it has
// physical length h0, with its Δa.
TimedState<2> at_perihelion() { return {0.0, kPerihelion.q, kPerihelion.p}; }
template <class Monitor>
std::pair<AdaptiveMidpoint<Kepler, Monitor>, double> avi_with_first_step(Monitor monitor,
                                                                         double h0) {
  AdaptiveMidpoint<Kepler, Monitor> avi(Kepler{}, monitor);
  const double da = avi.step_for_first_step(at_perihelion(), h0);
  return {avi, da};
}
}  // namespace

TEST_CASE(
    "AVI1 and AVI2 on Kepler: Δa gives a first step of h0, steps adapt, energy error bounded") {
  const double h0 = 0.001, H0 = kH0;
  auto run = [&](auto monitor) {
    auto [avi, da] = avi_with_first_step(monitor, h0);
    TimedState<2> s = at_perihelion();
    CHECK(std::abs(avi.physical_step(s, da) - h0) <= 4 * kEps * h0);
    double max_dt = 0, max_dH = 0;
    int max_it = 0;
    while (s.t < 2 * std::numbers::pi) {  // one period
      const double t0 = s.t;
      const SolveReport r = avi.step(s, da);
      max_it = std::max(max_it, r.iterations);
      max_dt = std::max(max_dt, s.t - t0);
      max_dH = std::max(max_dH, std::abs(energy(Kepler{}, s.q, s.p) - H0));
    }
    CHECK(max_it <= 8);
    CHECK(max_dt > 5 * h0);  // e = 0.7: the step grows towards aphelion
    CHECK(max_dH < 1e-3);    // bounded (symplectic in the extended space)
    return max_dH;
  };
  const double e1 = run(MonitorArclength{H0}), e2 = run(MonitorQuadratic{});
  MESSAGE("AVI1 max |H − H0| = ", e1, ", AVI2 = ", e2);
}

TEST_CASE("AVI: the step solved for the midpoint is the step of the full 2N-system") {
  // Along one period (e = 0.7, h0 = 1e-3), every step is taken both ways from the same state:
  // by `step` (N equations for the midpoint, started from the extrapolated midpoints and a kept
  // Newton matrix) and by `step_full_system` (2N equations, explicit Euler start, AutoDiff
  // Jacobian). Both solve the same equations to NewtonOptions' rule (4 units of round-off), so
  // q1, p1 and t1 agree to a few units of round-off of their size; a wrong formula, a wrong
  // monitor gradient that stalled Newton, or a stale start accepted too early would not.
  const double h0 = 0.001, u = kEps / 2, H0 = kH0;
  auto compare = [&](auto monitor) {
    auto [avi, da] = avi_with_first_step(monitor, h0);
    TimedState<2> s = at_perihelion();
    double worst = 0, iterations = 0, max_residual = 0;
    long steps = 0;
    while (s.t < 2 * std::numbers::pi) {
      TimedState<2> ref = s;
      avi.step_full_system(ref, da);
      const SolveReport r = avi.step(s, da);
      CHECK(r.converged);
      iterations += r.iterations;
      max_residual = std::max(max_residual, r.residual);
      ++steps;
      const double size =
          std::max({s.q.lpNorm<Eigen::Infinity>(), s.p.lpNorm<Eigen::Infinity>(), std::abs(s.t)});
      const double d = std::max({(s.q - ref.q).lpNorm<Eigen::Infinity>(),
                                 (s.p - ref.p).lpNorm<Eigen::Infinity>(), std::abs(s.t - ref.t)});
      worst = std::max(worst, d / (u * size));
    }
    MESSAGE("largest difference of one step: ", worst, " units of round-off; ",
            iterations / double(steps), " evaluations per step; largest residual ", max_residual);
    CHECK(worst <= 32);
    // The extrapolated start leaves one correction and one confirming evaluation in most
    // steps (a cold start from explicit Euler takes three to five).
    CHECK(iterations / double(steps) <= 2.5);
  };
  compare(MonitorArclength{H0});
  compare(MonitorQuadratic{});
}

TEST_CASE("AVI: the written-out monitor gradients agree with AutoDiff") {
  const Kepler P;
  const MonitorArclength g1{kH0};
  const MonitorQuadratic g2;
  for (const Vec<double, 2>& q :
       {Vec<double, 2>(0.3, 0.0), Vec<double, 2>(-1.2, 0.8), Vec<double, 2>(0.05, -1.7)}) {
    auto check = [&](const auto& g) {
      const Vec<double, 2> exact = g.gradient(P, q);
      const Vec<double, 2> ad = g(P, ad::variables<2>(q)).derivatives();
      CHECK((exact - ad).lpNorm<Eigen::Infinity>() <= 16 * kEps * ad.lpNorm<Eigen::Infinity>());
    };
    check(g1);
    check(g2);
  }
}

TEST_CASE("AVI: a step off the trajectory starts cold, and a step without solution throws") {
  auto [avi, da] = avi_with_first_step(MonitorQuadratic{}, 0.001);
  TimedState<2> s = at_perihelion();
  for (int k = 0; k < 20; ++k) avi.step(s, da);
  // Another state (here the start again): the history of the first trajectory must not be
  // used; the step equals the full system's.
  TimedState<2> a = at_perihelion(), b = a;
  const SolveReport r = avi.step(a, da);
  avi.step_full_system(b, da);
  CHECK(r.iterations >= 3);  // the cold start: no extrapolation from the other trajectory
  CHECK((a.q - b.q).lpNorm<Eigen::Infinity>() <= 32 * kEps);
  // A fictitious step a thousand times too long: no midpoint solves (21)–(22) near the start;
  // the step throws SolveError with its report instead of returning NaN.
  TimedState<2> c = at_perihelion();
  CHECK_THROWS_AS(avi.step(c, 1e4 * da), SolveError);
}

TEST_CASE("EpAVI on Kepler: discrete energy constant, first step from the exact solution") {
  const double e = 0.7, h0 = 0.001;
  const KeplerOrbit orbit = KeplerOrbit::perihelion(e);
  EpAVI<Kepler> epavi{Kepler{}};
  auto s = epavi.start(0.0, orbit.at(0.0).q, h0, orbit.at(h0).q);
  const double E1 = s.E;
  double max_dE = 0, max_dt = 0, prev = s.t;
  while (s.t < 2 * std::numbers::pi) {
    const auto r = epavi.step(s);
    CHECK(r.energy_residual <= 1e-13);
    max_dE = std::max(max_dE, std::abs(s.E - E1));
    max_dt = std::max(max_dt, s.t - prev);
    prev = s.t;
  }
  MESSAGE("EpAVI one period: max |E_k − E_1| = ", max_dE, ", max step / h0 = ", max_dt / h0);
  CHECK(max_dE <= 1e-12);
  CHECK(max_dt > 5 * h0);
}
