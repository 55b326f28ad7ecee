// Doctests of relativistic/: the exact orbit against a high-accuracy numerical reference,
// and the integrators (3.19), (3.22) and the generic solver on (3.20) agreeing (claim SS-T8).
#include <cmath>

#include <doctest/doctest.h>

#include "vibook/core/order.hpp"
#include "vibook/mechanics/del_solver.hpp"
#include "vibook/relativistic/exact.hpp"
#include "vibook/relativistic/relativistic.hpp"

using namespace vibook;
using namespace vibook::relativistic;

namespace {

// Classical RK4 on (3.16) in long double: the reference for the exact solution.
struct LState {
  long double t, x0, x1, g, u0, u1;
};
LState rhs(const LState& s, long double c) {
  const long double r2 = s.x0 * s.x0 + s.x1 * s.x1, ir3 = 1.0L / (r2 * std::sqrt(r2));
  const long double gx = s.x0 * ir3, gy = s.x1 * ir3;  // ∇φ for φ = −1/r
  return {s.g, s.u0, s.u1, -(gx * s.u0 + gy * s.u1) / (c * c), -gx * s.g, -gy * s.g};
}
LState axpy(const LState& a, long double k, const LState& b) {
  return {a.t + k * b.t, a.x0 + k * b.x0, a.x1 + k * b.x1,
          a.g + k * b.g, a.u0 + k * b.u0, a.u1 + k * b.u1};
}
LState rk4(LState s, long double c, long double tau, int n) {
  const long double h = tau / n;
  for (int i = 0; i < n; ++i) {
    const LState k1 = rhs(s, c), k2 = rhs(axpy(s, h / 2, k1), c), k3 = rhs(axpy(s, h / 2, k2), c),
                 k4 = rhs(axpy(s, h, k3), c);
    s = axpy(s, h / 6, axpy(axpy(k1, 2, k2), 1, axpy(axpy(k3, 1, k3), 1, k4)));
  }
  return s;
}

}  // namespace

TEST_CASE("relativistic exact orbit matches a long-double RK4 reference in proper time") {
  for (double c : {2.0, 5.0, 30.0}) {
    const Problem P(c);
    const Vec<double, 2> x0(0.4, 0.0), u0(0.0, 2.0);
    const ExactOrbit orbit(P, x0, u0);
    const RelState s0 = P.initial(x0, u0);
    LState ref{0, 0.4L, 0, (long double)s0.gamma, 0, 2.0L};
    double tau = 0;
    for (int seg = 1; seg <= 4; ++seg) {  // 4 × 5 = 20 units of proper time
      ref = rk4(ref, c, 5.0L, 200000);
      tau += 5.0;
      const RelState ex = orbit.at(tau);
      INFO("c = ", c, ", tau = ", tau);
      CHECK(std::abs(ex.x(0) - double(ref.x0)) <= 1e-11);
      CHECK(std::abs(ex.x(1) - double(ref.x1)) <= 1e-11);
      CHECK(std::abs(ex.u(0) - double(ref.u0)) <= 1e-10);
      CHECK(std::abs(ex.u(1) - double(ref.u1)) <= 1e-10);
      CHECK(std::abs(ex.gamma - double(ref.g)) <= 1e-12);
      CHECK(std::abs(ex.t - double(ref.t)) <= 1e-10 * std::max(1.0, std::abs(ex.t)));
    }
  }
}

TEST_CASE("relativistic exact orbit: invariants, start point, Newtonian limit") {
  const Problem P(5.0);
  const Vec<double, 2> x0(0.4, 0.0), u0(0.0, 2.0);
  const ExactOrbit orbit(P, x0, u0);
  const RelState a = orbit.at(0.0);
  CHECK((a.x - x0).norm() <= 1e-15);
  CHECK((a.u - u0).norm() <= 1e-14);
  const Invariants i0 = invariants(P, P.initial(x0, u0));
  for (double tau : {0.7, 3.3, 17.0, 400.0}) {
    const Invariants i = invariants(P, orbit.at(tau));
    CHECK(std::abs(i.energy - i0.energy) <= 1e-12 * P.c * P.c);
    CHECK(std::abs(i.L - i0.L) <= 1e-13);
    CHECK(std::abs(i.shell - 1.0) <= 1e-13);
  }
  // As c → ∞ the orbit becomes the Newtonian ellipse e = 0.6 (a = 1) and stops precessing.
  const ExactOrbit far(Problem(1e4), x0, u0);
  CHECK(std::abs(far.eccentricity() - 0.6) <= 1e-6);
  CHECK(std::abs(far.precession_per_revolution()) <= 1e-6);
  // Not bound, or falling into the centre: typed errors.
  CHECK_THROWS_AS(ExactOrbit(Problem(5.0), x0, Vec<double, 2>(0.0, 3.0)), ArgumentError);
  CHECK_THROWS_AS(ExactOrbit(Problem(1.0), x0, u0), ArgumentError);
  CHECK_THROWS_AS(Problem(0.0), ArgumentError);
}

TEST_CASE("SS-T8: the generic solver on (3.20), the form (3.22) and the composition (3.19) agree") {
  const Problem P(5.0);
  const RelState s0 = P.initial(Vec<double, 2>(0.4, 0.0), Vec<double, 2>(0.0, 2.0));
  const double h = 0.05;
  auto del = make_del_integrator<3>(discrete_lagrangian_320(P));
  RelState a = s0;
  double worst_ab = 0, worst_ag = 0, bound = 0;
  for (int k = 0; k < 800; ++k) {
    // one step of each from the same state
    RelState b1 = a, g1 = a;
    KSymplectic{P}.step(a, h);
    Vi322{P}.step(b1, h);
    Vec<double, 3> X(g1.t, g1.x(0), g1.x(1));
    Vec<double, 3> p = canonical_momentum(P, g1);
    del.reset();
    del.step(X, p, h);
    g1 = from_canonical(P, X, p);
    const auto diff = [](const RelState& u, const RelState& v) {
      return std::max({std::abs(u.t - v.t) / std::max(1.0, std::abs(u.t)),
                       (u.x - v.x).lpNorm<Eigen::Infinity>(), std::abs(u.gamma - v.gamma),
                       (u.u - v.u).lpNorm<Eigen::Infinity>()});
    };
    // Round-off model: 64 ulps of the state, plus the rounding of the clock difference
    // t_{n+1} − t_n (ulp(t)) times |∇φ|, which (3.22) and (3.20) form and (3.19) does not.
    bound = std::max(bound, 64 * kEps * (a.u.norm() + std::abs(a.t) * P.grad_phi(a.x).norm()));
    worst_ab = std::max(worst_ab, diff(a, b1));
    worst_ag = std::max(worst_ag, diff(a, g1));
  }
  MESSAGE("one-step differences: (3.22) vs (3.19) ", worst_ab, ", generic (3.20) vs (3.19) ",
          worst_ag);
  CHECK(worst_ab <= bound);
  CHECK(worst_ag <= bound);
}
