// Doctests of phases.hpp: every criterion of every route with a deliberately wrong input that
// must fail it and a correct one at the edge that must pass it (chapter "Verify your own
// integrator", section "The criteria of every route").
#include "vibook/verify/phases.hpp"

#include <cmath>
#include <limits>

#include <doctest/doctest.h>

#include "vibook/integrators/kernels.hpp"
#include "vibook/problems/problems.hpp"

using namespace vibook;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Eigen::VectorXd state(double q, double p) {
  Eigen::VectorXd z(2);
  z << q, p;
  return z;
}

double pendulum_force(double q) { return -std::sin(q); }

// Explicit Euler on the pendulum: order 1, not symplectic, not symmetric.
void explicit_euler(Eigen::VectorXd& z, double h) {
  const double q = z(0), p = z(1);
  z(0) = q + h * p;
  z(1) = p + h * pendulum_force(q);
}

// The classical Runge–Kutta method of order 4: not symplectic, not symmetric; its defects
// are C h^5, below 1e-8 at h = 0.05.
void rk4(Eigen::VectorXd& z, double h) {
  auto f = [](const Eigen::Vector2d& y) { return Eigen::Vector2d(y(1), pendulum_force(y(0))); };
  const Eigen::Vector2d y = z;
  const Eigen::Vector2d k1 = f(y), k2 = f(y + h / 2 * k1), k3 = f(y + h / 2 * k2),
                        k4 = f(y + h * k3);
  z = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
}

// Symplectic Euler (drift, then kick): order 1, symplectic, not symmetric.
void symplectic_euler(Eigen::VectorXd& z, double h) {
  z(0) += h * z(1);
  z(1) += h * pendulum_force(z(0));
}

// Störmer–Verlet composed by Yoshida's triple jump: order 4, symplectic and symmetric.
void triple_jump(Eigen::VectorXd& z, double h) {
  const double c = std::cbrt(2.0), g1 = 1 / (2 - c), g0 = -c / (2 - c);
  for (double g : {g1, g0, g1}) {
    const double k = g * h;
    z(1) += k / 2 * pendulum_force(z(0));
    z(0) += k * z(1);
    z(1) += k / 2 * pendulum_force(z(0));
  }
}

const std::vector<Eigen::VectorXd> kStates{state(1.0, 0.5), state(-0.3, 1.2)};

}  // namespace

TEST_CASE("judge_scaling: resolved and growing is NO, unresolved or flat is yes") {
  verify::ScalingJudgement j;
  j.h = {0.05, 0.1, 0.2, 0.4};
  j.resolution = {1e-13, 1e-13, 1e-13, 1e-13};
  j.error = {"", "", "", ""};
  SUBCASE("the signature of a sixth-order non-symplectic method: h^7") {
    j.defect = {5.8e-14, 5.3e-12, 6.6e-10, 7.6e-8};
    verify::judge_scaling(j);
    CHECK_FALSE(j.passed);
    CHECK(j.resolved);
    CHECK(j.growth > 4);
  }
  SUBCASE("round-off at every size: symplectic to the resolution") {
    j.defect = {8e-14, 2e-14, 9e-14, 5e-14};
    verify::judge_scaling(j);
    CHECK(j.passed);
    CHECK_FALSE(j.resolved);
  }
  SUBCASE("resolved but flat: not a defect of a consistent map") {
    j.defect = {3e-12, 3e-12, 3e-12, 3e-12};
    verify::judge_scaling(j);
    CHECK(j.passed);
    CHECK(std::abs(j.growth) < 0.1);
  }
  SUBCASE("a system without the reversing symmetry: O(h), resolved and growing") {
    j.defect = {5e-2, 1e-1, 2e-1, 4e-1};
    verify::judge_scaling(j);
    CHECK_FALSE(j.passed);
    CHECK(std::abs(j.growth - 1) < 0.05);
  }
  SUBCASE("resolved at the smallest step, the larger ones failed: NO") {
    j.defect = {1e-6, kNaN, kNaN, kNaN};
    verify::judge_scaling(j);
    CHECK_FALSE(j.passed);
  }
}

TEST_CASE("symplecticity_by_scaling: explicit Euler and RK4 fail, symplectic maps pass") {
  // Wrong inputs: order 1 (defect ~h^2) and order 4, whose defect at h = 0.05 is ~1e-8 and
  // passed a fixed tolerance of 1e-8 at that size.
  CHECK_FALSE(verify::symplecticity_by_scaling(explicit_euler, kStates, 0.05).passed);
  const auto r = verify::symplecticity_by_scaling(rk4, kStates, 0.05);
  CHECK_FALSE(r.passed);
  CHECK(r.growth > 3);  // the signature h^5
  // The edges: first order, and fourth order with negative substeps.
  CHECK(verify::symplecticity_by_scaling(symplectic_euler, kStates, 0.05).passed);
  CHECK(verify::symplecticity_by_scaling(triple_jump, kStates, 0.05).passed);
}

TEST_CASE("symmetry_by_scaling: symplectic Euler and RK4 are not symmetric, the triple jump is") {
  CHECK_FALSE(verify::symmetry_by_scaling(symplectic_euler, kStates, 0.05).passed);
  CHECK_FALSE(verify::symmetry_by_scaling(rk4, kStates, 0.05).passed);
  const auto t = verify::symmetry_by_scaling(triple_jump, kStates, 0.05);
  CHECK(t.passed);
  CHECK_FALSE(t.resolved);
  // On a reversible system, reversibility says the same.
  CHECK_FALSE(verify::reversibility_by_scaling(symplectic_euler, kStates, 0.05).passed);
  CHECK(verify::reversibility_by_scaling(triple_jump, kStates, 0.05).passed);
}

TEST_CASE("momentum_reversal: the pendulum is reversible, a charged particle is not") {
  const verify::Observable pendulum = [](const Eigen::VectorXd& z) {
    return 0.5 * z(1) * z(1) - std::cos(z(0));
  };
  // H = |p - A(q)|^2/2 + |q|^2/2 with A = (-q2, q1)/2: a magnetic field along the third axis.
  const verify::Observable magnetic = [](const Eigen::VectorXd& z) {
    const double v1 = z(2) + z(1) / 2, v2 = z(3) - z(0) / 2;
    return 0.5 * (v1 * v1 + v2 * v2) + 0.5 * (z(0) * z(0) + z(1) * z(1));
  };
  CHECK(verify::momentum_reversal(pendulum, kStates).holds);
  Eigen::VectorXd z(4);
  z << 1.0, 0.0, 0.0, 0.5;  // at rest: v = 0
  const auto m = verify::momentum_reversal(magnetic, {z});
  CHECK_FALSE(m.holds);
  CHECK(m.why.find("H(q, -p)") != std::string::npos);
}

TEST_CASE("judge_consistency: order below 1 by the conditions or measured below 1/2 never passes") {
  CHECK_FALSE(verify::judge_consistency(0, 0.0).passed);  // SV with coefficients 1, 1
  CHECK_FALSE(verify::judge_consistency(kNaN, 0.02).passed);
  CHECK(verify::judge_consistency(1, 0.98).passed);  // the edge: first order
  CHECK(verify::judge_consistency(kNaN, 12.0).passed);
  CHECK(verify::judge_consistency(kNaN, kNaN).passed);  // nothing measured: the order decides
}
