// Doctests of the verification helpers: each helper must pass a method that has the property
// and fail one that has not (Störmer–Verlet against explicit Euler on the pendulum).
#include "vibook/verify/verify.hpp"

#include <doctest/doctest.h>

#include "vibook/integrators/kernels.hpp"
#include "vibook/problems/problems.hpp"

using namespace vibook;

namespace {

Eigen::VectorXd state(double q, double p) {
  Eigen::VectorXd z(2);
  z << q, p;
  return z;
}

// The pendulum H = p²/2 − cos q: nonlinear, reversible.
double pendulum_energy(const Eigen::VectorXd& z) { return 0.5 * z(1) * z(1) - std::cos(z(0)); }

// Explicit Euler: first order, neither symplectic nor symmetric; its energy grows.
void explicit_euler(Eigen::VectorXd& z, double h) {
  const double q = z(0), p = z(1);
  z(0) = q + h * p;
  z(1) = p - h * std::sin(q);
}

}  // namespace

TEST_CASE("verify: Störmer–Verlet passes, explicit Euler fails, on the pendulum") {
  StormerVerlet<Pendulum> sv;
  const verify::Step sv_step = [&](Eigen::VectorXd& z, double h) { verify::step_qp<1>(sv, z, h); };
  const verify::Step euler_step = explicit_euler;
  const Eigen::VectorXd z0 = state(1.0, 0.5);
  const double T = 2.0;
  // Reference: Störmer–Verlet at h = 1e-5 (error ~1e-10, below the fit's floor of 1e-8).
  const Eigen::VectorXd ref = verify::integrate(sv_step, z0, 1e-5, T);
  const std::vector<double> hs{0.1, 0.05, 0.025, 0.0125, 0.00625};

  SUBCASE("convergence order, two-sided") {
    const auto s = verify::convergence_order(sv_step, z0, T, ref, hs, 2.0, 0.1, 1e-8);
    CHECK(s.points == 5);
    CHECK(s.passed);
    CHECK(std::abs(s.order - 2.0) < 0.1);
    const auto e = verify::convergence_order(euler_step, z0, T, ref, hs, 2.0, 0.1, 1e-8);
    CHECK_FALSE(e.passed);
    CHECK(std::abs(e.order - 1.0) < 0.1);
  }
  SUBCASE("symplecticity") {
    const std::vector<Eigen::VectorXd> zs{state(1.0, 0.5), state(-0.3, 1.2), state(2.0, -0.1)};
    const auto s = verify::symplecticity_defect(sv_step, zs, 0.1, 1e-8);
    CHECK(s.passed);
    CHECK(s.samples == 3);
    // Explicit Euler: det J = 1 + h² cos q, so the defect is about h² = 1e-2.
    const auto e = verify::symplecticity_defect(euler_step, zs, 0.1, 1e-8);
    CHECK_FALSE(e.passed);
    CHECK(e.defect > 1e-3);
  }
  SUBCASE("reversibility") {
    const std::vector<Eigen::VectorXd> zs{state(1.0, 0.5), state(-0.3, 1.2)};
    CHECK(verify::reversibility_defect(sv_step, zs, 0.1, 1e-14).passed);
    const auto e = verify::reversibility_defect(euler_step, zs, 0.1, 1e-14);
    CHECK_FALSE(e.passed);
    CHECK(e.defect > 1e-3);
  }
  SUBCASE("long-time energy") {
    const auto s = verify::energy_behaviour(sv_step, pendulum_energy, z0, 0.1, 1 << 15);
    CHECK(s.bounded);
    CHECK(s.max_error < 1e-2);
    const auto e = verify::energy_behaviour(euler_step, pendulum_energy, z0, 0.01, 1 << 15);
    CHECK_FALSE(e.bounded);
    CHECK(e.exponent > 0.5);
  }
  SUBCASE("work-precision") {
    const auto w = verify::work_precision({{"sv", sv_step}, {"euler", euler_step}}, z0, T, ref, hs);
    REQUIRE(w.error.size() == 2);
    CHECK(w.methods[1] == "euler");
    CHECK(w.steps.front() == 20);
    // At every step size Störmer–Verlet is the more accurate, by more as h shrinks.
    for (std::size_t i = 0; i < hs.size(); ++i) CHECK(w.error[0][i] < w.error[1][i]);
    CHECK(w.error[1].back() / w.error[0].back() > w.error[1].front() / w.error[0].front());
  }
  SUBCASE("bad arguments") {
    CHECK_THROWS_AS(verify::integrate(sv_step, z0, 0.0, 1.0), std::invalid_argument);
    CHECK_THROWS_AS(verify::energy_behaviour(sv_step, pendulum_energy, z0, 0.1, 10),
                    std::invalid_argument);
  }
}
