// Doctests of adaptive.hpp: a typed discrete Lagrangian run as an EpAVI. The midpoint rule
// typed as text must be the library's EpAVI (Sharma et al. 2022, (25)) step for step; a wrong
// L_d (kinetic term doubled) keeps its own discrete energy and must fail on the intended one;
// and where EpAVI has no admissible step (Kepler, e = 0.8, as in the EpAVI chapter) the run
// stops with the fold recorded, not with a crash or a wrong step.
#include "vibook/verify/adaptive.hpp"

#include <doctest/doctest.h>

#include "vibook/epavi/epavi.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/modified/engine.hpp"
#include "vibook/problems/problems.hpp"
#include "vibook/verify/expression.hpp"

using namespace vibook;

namespace {

const char* kMidpoint = "h*((q1-q0)^2/(2*h^2) - V((q0+q1)/2))";

double pendulum_energy(const Eigen::VectorXd& z) { return 0.5 * z(1) * z(1) - std::cos(z(0)); }

}  // namespace

TEST_CASE("adaptive: the typed midpoint L_d run as EpAVI is the library's EpAVI (25)") {
  std::unique_ptr<verify::TypedDiscreteLagrangian> dl;
  {
    std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
    dl = std::make_unique<verify::TypedDiscreteLagrangian>(kMidpoint, "-cos(x)");
  }
  const auto Ld = dl->bind<1>();
  const double h0 = 0.1;
  Eigen::VectorXd z0(2);
  z0 << 1.0, 0.5;
  // Any q1 will do for the comparison: both start from the same one.
  const Vec<double, 1> q1(1.0 + 0.05 - 0.004);
  const long long steps = 400;
  const auto a = verify::epavi_study<1>(Ld, pendulum_energy, z0, q1, h0, steps);
  REQUIRE_FALSE(a.failure.happened);
  CHECK(a.steps_taken == steps);

  EpAVI<Pendulum> m{Pendulum{}};
  auto s = m.start(0.0, Vec<double, 1>(z0(0)), h0, q1);
  CHECK(std::abs(s.E - a.E1) <= 1e-15);
  double dt_min = h0, dt_max = h0;
  for (long long k = 1; k < steps; ++k) {
    const double t = s.t;
    m.step(s);
    dt_min = std::min(dt_min, s.t - t);
    dt_max = std::max(dt_max, s.t - t);
  }
  // Only the order of the operations in L_d differs. The energy equation (16) is flat in Δt
  // (it fixes the step through an O(Δt²) effect), so round-off in a step grows along the run:
  // the library's own EpAVI started from q1 moved by 4e-16 (relative) ends 1e-11 away after
  // these 400 steps. The typed run must agree with the library's as closely as that, within a
  // factor 10; a different method (another L_d, another energy) differs by O(h³) a step, 1e-3.
  EpAVI<Pendulum> m2{Pendulum{}};
  auto s2 = m2.start(0.0, Vec<double, 1>(z0(0)), h0, Vec<double, 1>(q1(0) * (1 + 4e-16)));
  for (long long k = 1; k < steps; ++k) m2.step(s2);
  const double spread_q = std::abs(s2.q(0) - s.q(0)), spread_p = std::abs(s2.p(0) - s.p(0)),
               spread_t = std::abs(s2.t - s.t);
  INFO("round-off spread: q ", spread_q, ", p ", spread_p, ", t ", spread_t);
  CHECK(spread_q > 0);
  CHECK(spread_q < 1e-9);
  CHECK(std::abs(a.t_reached - s.t) <= 10 * spread_t);
  CHECK(std::abs(a.z_end(0) - s.q(0)) <= 10 * spread_q);
  CHECK(std::abs(a.z_end(1) - s.p(0)) <= 10 * spread_p);
  CHECK(std::abs(a.dt_min - dt_min) <= 1e-12);
  CHECK(std::abs(a.dt_max - dt_max) <= 1e-12);
  // The comparison can fail: the trapezoidal L_d, another second-order method, run the same
  // way ends far outside that spread.
  {
    std::unique_ptr<verify::TypedDiscreteLagrangian> trap;
    {
      std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
      trap = std::make_unique<verify::TypedDiscreteLagrangian>(
          "h*((q1-q0)^2/(2*h^2) - (V(q0)+V(q1))/2)", "-cos(x)");
    }
    const auto b = verify::epavi_study<1>(trap->bind<1>(), pendulum_energy, z0, q1, h0, steps);
    CHECK(std::abs(b.z_end(0) - s.q(0)) > 1e4 * spread_q);
  }
  // The steps do adapt (the pendulum's speed varies along the swing).
  CHECK(a.dt_max / a.dt_min > 1.05);
  // The discrete energy is what (16) keeps; the intended energy is bounded.
  CHECK(a.discrete_energy_drift <= 1e-12);
  const auto v = verify::judge_energy(a.energy, 1.0, 2);
  CHECK(v.passed);
}

TEST_CASE("adaptive: a doubled kinetic term keeps its own energy and fails on the intended one") {
  std::unique_ptr<verify::TypedDiscreteLagrangian> dl;
  {
    std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
    dl = std::make_unique<verify::TypedDiscreteLagrangian>("h*((q1-q0)^2/h^2 - V((q0+q1)/2))",
                                                           "-cos(x)");
  }
  const auto Ld = dl->bind<1>();
  Eigen::VectorXd z0(2);
  z0 << 1.0, 0.5;
  const Vec<double, 1> q1(1.0 + 0.05 - 0.004);
  const auto a = verify::epavi_study<1>(Ld, pendulum_energy, z0, q1, 0.1, 400);
  REQUIRE_FALSE(a.failure.happened);
  CHECK(a.discrete_energy_drift <= 1e-12);  // its own energy, kept
  const auto v = verify::judge_energy(a.energy, 1.0, 2);
  CHECK_FALSE(v.passed);
  CHECK(v.verdict == "large");
}

TEST_CASE("adaptive: Kepler at e = 0.8 has no admissible step and the fold is recorded") {
  std::unique_ptr<verify::TypedDiscreteLagrangian> dl;
  {
    std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
    dl = std::make_unique<verify::TypedDiscreteLagrangian>(kMidpoint, "-1/sqrt(x^2+y^2)");
  }
  const auto Ld = dl->bind<2>();
  const double e = 0.8, h0 = 1e-3;
  const State<2> s0 = kepler_perihelion_state(e);
  const KeplerOrbit orbit = KeplerOrbit::perihelion(e);
  Eigen::VectorXd z0(4);
  z0 << s0.q, s0.p;
  const auto H = [](const Eigen::VectorXd& z) {
    return 0.5 * z.tail<2>().squaredNorm() - 1 / z.head<2>().norm();
  };
  const auto a = verify::epavi_study<2>(Ld, H, z0, orbit.at(h0).q, h0, 20000);
  REQUIRE(a.failure.happened);
  CHECK(a.failure.sign_changes == 0);
  CHECK(a.failure.far_sign_changes == 0);
  CHECK(a.failure.scan_points > 100);
  CHECK(a.failure.scan_min_abs > 0);
  CHECK(a.steps_taken == a.failure.step - 1);
  CHECK(a.energy.steps == a.steps_taken);
  CHECK(a.failure.message.find("no admissible time step") != std::string::npos);
  // The library's EpAVI stops at the same step.
  EpAVI<Kepler> m{Kepler{}};
  auto s = m.start(0.0, s0.q, h0, orbit.at(h0).q);
  long long k = 1;
  try {
    for (; k < 20000; ++k) m.step(s);
  } catch (const SolveError&) {
  }
  CHECK(k + 1 == a.failure.step);
}
