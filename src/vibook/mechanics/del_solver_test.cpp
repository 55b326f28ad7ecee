// Doctests of mechanics/: the generic variational integrator on a user's own Lagrangian.
// The blocks between //! [name] markers are quoted in the book with \snippet.
#include <cmath>

#include <doctest/doctest.h>

#include "vibook/mechanics/del_solver.hpp"
#include "vibook/mechanics/discrete_lagrangian.hpp"

TEST_CASE("generic solver: a user's own Lagrangian, two coupled degrees of freedom") {
  //! [user-lagrangian]
  // A continuous Lagrangian of your own: any callable L(q, v), generic in its scalar type.
  // Mass matrix diag(1, 2), a pendulum coupled to a quartic oscillator.
  auto L = [](const auto& q, const auto& v) -> vibook::scalar_t<decltype(q)> {
    using std::cos;
    return 0.5 * v(0) * v(0) + v(1) * v(1)                         // kinetic energy ½ vᵀMv
           - (1.0 - cos(q(0))) - 0.25 * q(1) * q(1) * q(1) * q(1)  // potential
           - 0.1 * q(0) * q(1);                                    // coupling
  };
  // Its midpoint discrete Lagrangian (Vermeeren, Example 1(a)) and the integrator: every
  // derivative, including the Newton Jacobian, comes from Eigen AutoDiff.
  auto integrator = vibook::make_del_integrator<2>(vibook::midpoint_dl(L));
  vibook::Vec<double, 2> q(0.3, -0.2), p(0.1, 0.4);
  const double h = 0.05;
  for (int k = 0; k < 200; ++k) {
    const vibook::SolveReport r = integrator.step(q, p, h);  // throws SolveError on failure
    CHECK(r.converged);
    CHECK(r.iterations <= 6);
  }
  //! [user-lagrangian]
  CHECK(q.allFinite());
}

TEST_CASE("generic solver satisfies the two-step discrete Euler-Lagrange equation (V (4))") {
  auto L = [](const auto& q, const auto& v) -> vibook::scalar_t<decltype(q)> {
    using std::cos;
    return 0.5 * v(0) * v(0) + v(1) * v(1) - (1.0 - cos(q(0))) - 0.25 * q(1) * q(1) * q(1) * q(1) -
           0.1 * q(0) * q(1);
  };
  auto del = vibook::make_del_integrator<2>(vibook::stormer_verlet_dl(L));
  vibook::Vec<double, 2> q(0.3, -0.2), p(0.1, 0.4), q_prev = q;
  const double h = 0.05;
  del.step(q, p, h);
  double worst = 0.0;
  for (int k = 0; k < 100; ++k) {
    vibook::Vec<double, 2> q_next = q, p_next = p;
    del.step(q_next, p_next, h);
    // D2 L_d(q_{k−1}, q_k) + D1 L_d(q_k, q_{k+1}) = 0, relative to the size of one term.
    const double scale = del.momentum_plus(q_prev, q, h).lpNorm<Eigen::Infinity>();
    worst =
        std::max(worst, del.del_residual(q_prev, q, q_next, h).lpNorm<Eigen::Infinity>() / scale);
    q_prev = q;
    q = q_next;
    p = p_next;
  }
  CHECK(worst <= 64 * vibook::kEps);
}

TEST_CASE("a discrete Lagrangian written directly, in the papers' scaling") {
  //! [direct-discrete-lagrangian]
  // Shen & Sun (4.16), symplectic Euler for U = ¼q⁴, written as the papers do (L_disc ≈ L) and
  // brought into vibook's scaling L_d = h·L_disc by scaled_by_step.
  auto Ldisc = [](const auto& x0, const auto& x1, const auto& h) -> vibook::scalar_t<decltype(h)> {
    const auto v = ((x1 - x0) / h).eval();
    return 0.5 * v.squaredNorm() - 0.25 * x1(0) * x1(0) * x1(0) * x1(0);
  };
  auto del = vibook::make_del_integrator<1>(vibook::scaled_by_step(Ldisc));
  //! [direct-discrete-lagrangian]
  // Explicit form: x1 = x0 + h p0, p1 = p0 − h x1³.
  vibook::Vec<double, 1> q(0.7), p(0.2);
  double x = 0.7, y = 0.2;
  for (int k = 0; k < 50; ++k) {
    del.step(q, p, 0.1);
    x += 0.1 * y;
    y -= 0.1 * x * x * x;
  }
  CHECK(std::abs(q(0) - x) <= 64 * vibook::kEps);
  CHECK(std::abs(p(0) - y) <= 64 * vibook::kEps);
}

TEST_CASE("a failing step is a typed error, not a NaN") {
  // A degenerate L_d: D1 L_d does not depend on q1, so the Newton Jacobian is singular.
  auto Ld = [](const auto& x0, const auto& x1, const auto& h) -> vibook::scalar_t<decltype(h)> {
    return h * (x0(0) * x0(0) + 0.0 * x1(0));
  };
  auto del = vibook::make_del_integrator<1>(Ld);
  vibook::Vec<double, 1> q(1.0), p(0.5);
  CHECK_THROWS_AS(del.step(q, p, 0.1), vibook::SolveError);
  CHECK(q(0) == 1.0);  // state untouched
}
