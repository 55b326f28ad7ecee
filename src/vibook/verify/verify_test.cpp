// Doctests of the verification helpers: each helper must pass a method that has the property
// and fail one that has not (Störmer–Verlet against explicit Euler on the pendulum).
#include "vibook/verify/verify.hpp"

#include <limits>

#include "vibook/core/precision.hpp"
#include "vibook/verify/reference.hpp"

#include <doctest/doctest.h>

#include "vibook/integrators/kernels.hpp"
#include "vibook/problems/problems.hpp"

using namespace vibook;

namespace {

Eigen::VectorXd pendulum_state(double q, double p) {
  Eigen::VectorXd z(2);
  z << q, p;
  return z;
}

// The pendulum H = p²/2 − cos q: nonlinear, reversible.
double pendulum_energy(const Eigen::VectorXd& z) { return 0.5 * z(1) * z(1) - std::cos(z(0)); }

// Explicit Euler: first order, neither symplectic nor symmetric; its energy grows.
void pendulum_euler(Eigen::VectorXd& z, double h) {
  const double q = z(0), p = z(1);
  z(0) = q + h * p;
  z(1) = p - h * std::sin(q);
}

}  // namespace

TEST_CASE("verify: Störmer–Verlet passes, explicit Euler fails, on the pendulum") {
  StormerVerlet<Pendulum> sv;
  const verify::Step sv_step = [&](Eigen::VectorXd& z, double h) { verify::step_qp<1>(sv, z, h); };
  const verify::Step euler_step = pendulum_euler;
  const Eigen::VectorXd z0 = pendulum_state(1.0, 0.5);
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
    const std::vector<Eigen::VectorXd> zs{pendulum_state(1.0, 0.5), pendulum_state(-0.3, 1.2),
                                          pendulum_state(2.0, -0.1)};
    const auto s = verify::symplecticity_defect(sv_step, zs, 0.1, 1e-8);
    CHECK(s.passed);
    CHECK(s.samples == 3);
    // Explicit Euler: det J = 1 + h² cos q, so the defect is about h² = 1e-2.
    const auto e = verify::symplecticity_defect(euler_step, zs, 0.1, 1e-8);
    CHECK_FALSE(e.passed);
    CHECK(e.defect > 1e-3);
  }
  SUBCASE("reversibility") {
    const std::vector<Eigen::VectorXd> zs{pendulum_state(1.0, 0.5), pendulum_state(-0.3, 1.2)};
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

// --- #24: the order fit, the energy verdict and the reference, each with an input that must
// fail it ---------------------------------------------------------------------------------

TEST_CASE("fit_order_plateau: the round-off plateau is left out, a wrong order is not hidden") {
  std::vector<double> h, e4, e1;
  for (int i = 0; i < 10; ++i) {
    h.push_back(0.2 / std::pow(2.0, i));
    // C h^4 down to a plateau of 2e-12 (round-off), with a wobble of a few per cent
    e4.push_back(std::max(4e-2 * std::pow(h.back(), 4) * (1 + 0.03 * ((i % 3) - 1)), 2e-12));
    e1.push_back(0.3 * h.back());
  }
  const auto fit = verify::fit_order_plateau(h, e4, 3.6e-15);
  CHECK(std::abs(fit.slope - 4) < 0.1);
  CHECK(fit.plateau >= 2);
  CHECK_FALSE(fit.used.back());
  // without the plateau search the same data give a slope far from 4 (what #24 saw: 1.8)
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double x = std::log(h[i]), y = std::log(e4[i]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double n = double(h.size()), naive = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  CHECK(std::abs(naive - 4) > 0.5);
  // a first-order error is fitted as first order, whatever the floor
  const auto f1 = verify::fit_order_plateau(h, e1, 3.6e-15);
  CHECK(std::abs(f1.slope - 1) < 0.01);
  CHECK(f1.plateau == 0);
}

TEST_CASE("judge_energy: conserved to round-off, bounded, drifts, large, by the numbers") {
  verify::EnergyBehaviour e;
  e.steps = 100000;
  e.h = 0.05;
  e.exponent = 0.4;  // a random walk of round-off
  e.max_error = 3.5e-14;
  auto v = verify::judge_energy(e, 1.0, 2);
  CHECK(v.verdict == "conserved to round-off");
  CHECK(v.passed);
  // the same walk at 1e-9 is not round-off: a growth
  e.max_error = 1e-9;
  v = verify::judge_energy(e, 1.0, 2);
  CHECK(v.verdict == "grows");
  CHECK_FALSE(v.passed);
  // Size is no criterion where the scaling is read: a first-order symplectic method's 5 %,
  // bounded and halving with h, passes (the edge); the same 5 % that does not shrink fails.
  e.exponent = 0.0;
  e.max_error = 0.05;
  v = verify::judge_energy(e, 1.0, 1, 0.05 / 2);
  CHECK(v.verdict == "bounded");
  CHECK(v.passed);
  v = verify::judge_energy(e, 1.0, 1, 0.05 / 1.1);
  CHECK(v.verdict == "bounded, not O(h^p)");
  CHECK_FALSE(v.passed);
  // Without a run at h/2 (an adaptive run) the size decides: 98 % is large.
  e.max_error = 0.98;
  v = verify::judge_energy(e, 1.0, 2);
  CHECK(v.verdict == "large");
  CHECK_FALSE(v.passed);
  // bounded and O(h^2): passes; bounded but O(h) when order 2 is claimed: fails
  e.max_error = 1e-4;
  CHECK(verify::judge_energy(e, 1.0, 2, 1e-4 / 4).verdict == "bounded");
  v = verify::judge_energy(e, 1.0, 2, 1e-4 / 2);
  CHECK(v.verdict == "bounded, not O(h^p)");
  CHECK_FALSE(v.passed);
  // a linear drift
  e.exponent = 1.0;
  CHECK(verify::judge_energy(e, 1.0, 2).verdict == "drifts");
  e.max_error = std::numeric_limits<double>::infinity();
  CHECK(verify::judge_energy(e, 1.0, 2).verdict == "blows up");
}

TEST_CASE("reference_solution: GBS in double-double against the exact harmonic oscillator") {
  // y = (q, p), q' = p, p' = -q; q(5) = cos 5 from q(0) = 1, p(0) = 0.
  const verify::Field<dd_real> f = [](const std::vector<dd_real>& y) {
    return std::vector<dd_real>{y[1], -y[0]};
  };
  const auto r = verify::reference_solution<dd_real>(f, {dd_real(1), dd_real(0)}, 5.0);
  const dd_real q_exact = cos(dd_real(5));
  CHECK(std::abs(to_double(r.y[0] - q_exact)) < 1e-28);
  CHECK(r.error < 1e-25);
  // a field with a singularity on the way: an error, not a number
  const verify::Field<dd_real> blow = [](const std::vector<dd_real>& y) {
    return std::vector<dd_real>{y[0] * y[0]};  // y' = y², y(0) = 1: y = 1/(1 − t)
  };
  CHECK_THROWS_AS(verify::reference_solution<dd_real>(blow, {dd_real(1)}, 2.0, 1e-26, 0, 1L << 10),
                  NumericalError);
}

TEST_CASE("step_jacobian: the map is called in one fixed order, whatever the compiler") {
  // A black box may keep state from call to call (a deliberately wrong stepper of the field
  // audit does); the order of its calls must then not depend on how a compiler evaluates the
  // operands of one expression. Per column: the increments -2, +2, -1, +1 (times delta), in
  // this order; and the Jacobian of a linear map is exact.
  std::vector<double> seen;
  const Eigen::VectorXd z = Eigen::Vector2d(0.5, -0.25);
  const verify::Step linear = [&](Eigen::VectorXd& w, double h) {
    seen.push_back(w(0) - z(0) + w(1) - z(1));
    w = Eigen::Vector2d(w(0) + h * w(1), w(1) - h * w(0));
  };
  const Eigen::MatrixXd J = verify::step_jacobian(linear, z, 0.1, 1e-3);
  REQUIRE(seen.size() == 8);
  const double d = 1e-3;  // delta * max(1, |z_j|)
  const double want[] = {-2 * d, 2 * d, -d, d, -2 * d, 2 * d, -d, d};
  for (std::size_t i = 0; i < 8; ++i)
    CHECK(std::abs(seen[i] - want[i]) <= 1e-15);  // (z + s d) - z: round-off of 0.5 at most
  CHECK(std::abs(J(0, 0) - 1.0) <= 1e-12);
  CHECK(std::abs(J(0, 1) - 0.1) <= 1e-12);
  CHECK(std::abs(J(1, 0) + 0.1) <= 1e-12);
  CHECK(std::abs(J(1, 1) - 1.0) <= 1e-12);
}
