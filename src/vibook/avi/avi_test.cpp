// Doctests of avi/ and epavi/ on Kepler: first step exactly h0, energy behaviour, adaptivity.
#include <cmath>
#include <numbers>

#include <doctest/doctest.h>

#include "vibook/avi/avi.hpp"
#include "vibook/epavi/epavi.hpp"
#include "vibook/kepler/kepler.hpp"

using namespace vibook;

TEST_CASE(
    "AVI1 and AVI2 on Kepler: Δa gives a first step of h0, steps adapt, energy error bounded") {
  const double e = 0.7, h0 = 0.001;
  const State<2> s0 = kepler_perihelion_state(e);
  const double H0 = energy(Kepler{}, s0.q, s0.p);
  auto run = [&](auto monitor) {
    AdaptiveMidpoint<Kepler, decltype(monitor)> avi(Kepler{}, monitor);
    TimedState<2> s{0.0, s0.q, s0.p};
    const double da = avi.step_for_first_step(s, h0);
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
