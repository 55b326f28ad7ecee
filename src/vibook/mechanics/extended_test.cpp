// Doctests of mechanics/extended.hpp: the time-marching form reproduces the two-step
// equations (claim S-DEL), the discrete energy sign (erratum S-ERR-14), and typed failures.
#include <cmath>

#include <doctest/doctest.h>

#include "vibook/figures/registry.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/mechanics/check_s_del.hpp"
#include "vibook/mechanics/extended.hpp"

using namespace vibook;

TEST_CASE("S-DEL: marching (15)-(18) reproduces (11)-(12) on Kepler and on the pendulum") {
  for (const auto& m : {checks::s_del_kepler(4000), checks::s_del_pendulum(4000)}) {
    CHECK(m.two_step_residual <= checks::kSDelTolerance);
    CHECK(m.max_energy_residual <= 1e-12);
    CHECK(m.energy_drift <= 1e-11);  // autonomous L_d: E_{k+1} = E_k up to the solves
    CHECK(m.min_step > 0);
  }
  const auto k = checks::s_del_kepler(4000);
  CHECK(k.max_step > 3 * k.min_step);                // the steps adapt along the e = 0.5 orbit
  CHECK(std::abs(k.discrete_energy + 0.5) <= 1e-3);  // −D3 L_d is the energy H = −1/2
  CHECK(k.printed_eq14_residual > 0.1);              // (14) as printed breaks (16)
  const auto results = figures::find("check-s-del")->run({});
  REQUIRE(results.size() == 2);
  // (11)-(13), (15)-(18) read from the paper agree; (14) needs its sign reversed.
  CHECK(results[0].status == claims::Status::erratum);
  CHECK(results[0].value("displays_compared") == 8);
  CHECK(results[0].value("displays_agreeing") == 7);
  CHECK(results[1].id == "S-ERR-14");
  CHECK(results[1].status == claims::Status::erratum);
  REQUIRE(results[1].comparisons.size() == 1);
  CHECK(results[1].comparisons[0].edit.find("sign") != std::string::npos);
}

TEST_CASE("extended step: no admissible root is a typed error, not a NaN") {
  // Start on Kepler, then ask for an energy no nearby step can reach.
  auto vi = make_extended_del_integrator<2>(extended_midpoint_dl(mechanical_lagrangian(Kepler{})));
  const auto orbit = KeplerOrbit::perihelion(0.5);
  auto s = vi.start(0.0, orbit.at(0.0).q, 0.01, orbit.at(0.01).q);
  s.E += 10.0;
  const auto before = s;
  CHECK_THROWS_AS(vi.step(s), SolveError);
  CHECK(s.t == before.t);
  CHECK(s.q == before.q);
}
