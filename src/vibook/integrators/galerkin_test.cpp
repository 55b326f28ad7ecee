// Doctests of the Galerkin variational integrators (galerkin.hpp): the quadrature rules from
// their defining equations, and HLW Theorem VI.6.4 step by step (the Galerkin discrete
// Lagrangian with Gauss or Lobatto nodes is the partitioned Runge–Kutta method with
// a_ij = ∫_0^{c_i} ℓ̃_j and â_ij = b_j(1 − a_ji/b_i)), on the Kepler problem.
#include "vibook/integrators/galerkin.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "vibook/core/precision.hpp"
#include "vibook/core/scalar.hpp"
#include "vibook/integrators/step_difference_test.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/problems/problems.hpp"

using namespace vibook;

namespace {

// ∫_0^1 x^k by the rule, minus 1/(k+1).
double moment_error(const Quadrature& q, int k) {
  double sum = 0;
  for (std::size_t i = 0; i < q.c.size(); ++i) sum += q.b[i] * std::pow(q.c[i], k);
  return sum - 1.0 / (k + 1);
}

template <class Problem>
auto mechanical(Problem P) {
  // the return type declared: an AutoDiff expression returned by value would refer to
  // temporaries of the lambda
  return [P](const auto& q, const auto& v) -> std::remove_cvref_t<decltype(q(0))> {
    using T = std::remove_cvref_t<decltype(q(0))>;
    return constant<T>(0.5) * squared_norm(v) - P.template potential<T>(q);
  };
}

// The largest one-step difference |Φ_Galerkin(z_k) − Φ_PRK(z_k)| along `steps` Galerkin steps of
// h on Kepler (e = 0.5, from perihelion), relative to |z_k|: each map applied to the same state,
// so that nothing accumulates. The Galerkin integrator with the stage count at run time (the
// one `vibook verify --method` runs; the fixed-S instances follow it to round-off, below).
double galerkin_vs_prk(const Quadrature& galerkin_rule, const Quadrature& prk_rule, int steps,
                       double h) {
  GalerkinIntegrator<2, Eigen::Dynamic, decltype(mechanical(Kepler{}))> g(mechanical(Kepler{}),
                                                                          galerkin_rule);
  PartitionedRungeKutta<Kepler> prk(Kepler{}, prk_rule);
  Vec<double, 2> q(0.5, 0), p(0, std::sqrt(3.0));
  double worst = 0;
  for (int k = 0; k < steps; ++k) {
    Vec<double, 2> q2 = q, p2 = p;
    g.step(q, p, h);
    prk.step(q2, p2, h);
    const double size = std::max(q.lpNorm<Eigen::Infinity>(), p.lpNorm<Eigen::Infinity>());
    worst = std::max({worst, (q - q2).lpNorm<Eigen::Infinity>() / size,
                      (p - p2).lpNorm<Eigen::Infinity>() / size});
  }
  return worst;
}

}  // namespace

TEST_CASE("quadrature rules: Gauss exact to degree 2s-1, Lobatto to 2s-3, and no further") {
  for (int s = 1; s <= 6; ++s) {
    const Quadrature g = gauss_rule(s);
    CAPTURE(s);
    for (int k = 0; k <= 2 * s - 1; ++k) CHECK(std::abs(moment_error(g, k)) <= 4e-16);
    CHECK(std::abs(moment_error(g, 2 * s)) > 1e-12);  // round-off leaves < 1e-15
  }
  for (int s = 2; s <= 6; ++s) {
    const Quadrature l = lobatto_rule(s);
    CAPTURE(s);
    CHECK(l.c.front() == 0.0);
    CHECK(l.c.back() == 1.0);
    for (int k = 0; k <= 2 * s - 3; ++k) CHECK(std::abs(moment_error(l, k)) <= 4e-16);
    CHECK(std::abs(moment_error(l, 2 * s - 2)) > 1e-12);
  }
  // known closed forms: Gauss 2 nodes 1/2 ∓ √3/6; Lobatto 3 nodes (0, 1/2, 1), (1/6, 2/3, 1/6)
  const Quadrature g2 = gauss_rule(2), l3 = lobatto_rule(3);
  CHECK(std::abs(g2.c[0] - (0.5 - std::sqrt(3.0) / 6)) <= 1e-16);
  CHECK(std::abs(l3.c[1] - 0.5) <= 1e-16);
  CHECK(std::abs(l3.b[1] - 2.0 / 3) <= 2e-16);
  CHECK(std::abs(l3.b[0] - 1.0 / 6) <= 2e-16);
}

TEST_CASE("quadrature rules in double-double: exact to 1e-30 where the rule is, and no further") {
  // quadrature_in refines each node by Newton's method in double-double. The moments the rule
  // integrates exactly vanish to double-double's round-off (measured: below 1e-31); the first
  // one it does not integrate stays at its true size (above 1e-6 up to five nodes), so a rule left
  // at double's nodes (moments near 1e-17) fails the first bound.
  auto moment = [](const QuadratureT<dd_real>& q, int k) {
    dd_real sum(0.0);
    for (std::size_t i = 0; i < q.c.size(); ++i) {
      dd_real x(1.0);
      for (int j = 0; j < k; ++j) x *= q.c[i];
      sum += q.b[i] * x;
    }
    return std::abs(to_double(sum - dd_real(1.0) / dd_real(double(k + 1))));
  };
  for (int s = 1; s <= 5; ++s) {
    CAPTURE(s);
    const QuadratureT<dd_real> g = quadrature_in<dd_real>(gauss_rule(s));
    for (int k = 0; k <= 2 * s - 1; ++k) CHECK(moment(g, k) <= 1e-30);
    CHECK(moment(g, 2 * s) > 1e-8);
    if (s < 2) continue;
    const QuadratureT<dd_real> l = quadrature_in<dd_real>(lobatto_rule(s));
    for (int k = 0; k <= 2 * s - 3; ++k) CHECK(moment(l, k) <= 1e-30);
    CHECK(moment(l, 2 * s - 2) > 1e-8);
  }
}

TEST_CASE(
    "Galerkin step in double-double: the double step to its round-off, and its own to 1e-30") {
  // The same step of lobatto:4 on the pendulum from (1, 0.5), h = 0.1, in double and in
  // double-double: they agree to a few units of double's round-off (the double step's own
  // error), and two double-double steps from the same state agree exactly. An error in the
  // generic code (a coefficient left in double, a wrong node) would separate them by far more.
  auto L = mechanical(Pendulum{});
  GalerkinIntegrator<1, Eigen::Dynamic, decltype(L)> in_double(L, lobatto_rule(4));
  GalerkinIntegrator<1, Eigen::Dynamic, decltype(L), dd_real> in_dd(
      L, quadrature_in<dd_real>(lobatto_rule(4)));
  Vec<double, 1> q{1.0}, p{0.5};
  Vec<dd_real, 1> Q{dd_real(1.0)}, P{dd_real(0.5)};
  in_double.step(q, p, 0.1);
  in_dd.step(Q, P, dd_real(0.1));
  CHECK(std::abs(to_double(Q(0)) - q(0)) <= 8 * 2.2e-16);
  CHECK(std::abs(to_double(P(0)) - p(0)) <= 8 * 2.2e-16);
  CHECK(std::abs(to_double(in_dd.action()) - in_double.action()) <= 8 * 2.2e-16);
  // the method is symmetric and the pendulum reversible: from (q1, -p1) one step of h returns
  // to (q0, -p0), to double-double's round-off
  Vec<dd_real, 1> Q2 = Q, P2 = -P;
  in_dd.step(Q2, P2, dd_real(0.1));
  CHECK(std::abs(to_double(Q2(0) - dd_real(1.0))) <= 1e-29);
  CHECK(std::abs(to_double(P2(0) + dd_real(0.5))) <= 1e-29);
}

TEST_CASE("Galerkin variational integrators are the partitioned Runge-Kutta methods (HLW VI.6.4)") {
  // One step of each from the same state, along 40 steps of h = 0.05: equal to 64 units of
  // round-off relative to the state (both solve their stage equations to round-off; measured:
  // at most 10 u). A first version that carried the control points themselves, not increments,
  // differed by 5 to 13 u/h: its momenta were differences of positions over h.
  constexpr double kH = 0.05;
  constexpr double kTol = 64 * 2.2e-16;
  CHECK(galerkin_vs_prk(gauss_rule(1), gauss_rule(1), 40, kH) <= kTol);
  CHECK(galerkin_vs_prk(gauss_rule(2), gauss_rule(2), 40, kH) <= kTol);
  CHECK(galerkin_vs_prk(gauss_rule(3), gauss_rule(3), 40, kH) <= kTol);
  CHECK(galerkin_vs_prk(gauss_rule(4), gauss_rule(4), 40, kH) <= kTol);
  CHECK(galerkin_vs_prk(lobatto_rule(2), lobatto_rule(2), 40, kH) <= kTol);
  CHECK(galerkin_vs_prk(lobatto_rule(3), lobatto_rule(3), 40, kH) <= kTol);
  CHECK(galerkin_vs_prk(lobatto_rule(4), lobatto_rule(4), 40, kH) <= kTol);
  // the tableaux: Gauss is its own symplectic conjugate; Lobatto IIIA's conjugate is IIIB
  // (for 3 stages, first column (1/6, 1/6, 1/6), last (0, 0, 0))
  const PartitionedRungeKutta<Kepler> gauss3(Kepler{}, gauss_rule(3)),
      lob3(Kepler{}, lobatto_rule(3));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) CHECK(std::abs(gauss3.a()[i][j] - gauss3.ahat()[i][j]) <= 1e-15);
  for (int i = 0; i < 3; ++i) {
    CHECK(std::abs(lob3.ahat()[i][0] - 1.0 / 6) <= 1e-15);
    CHECK(std::abs(lob3.ahat()[i][2]) <= 1e-15);
  }
  // deliberately different methods are told apart, by far more than the bound: Gauss 2 against
  // Lobatto 2 (orders 4 and 2), Lobatto 3 against Gauss 3 (orders 4 and 6; the local errors
  // differ by about h^5)
  CHECK(galerkin_vs_prk(gauss_rule(2), lobatto_rule(2), 40, kH) > 1000 * kTol);
  CHECK(galerkin_vs_prk(lobatto_rule(3), gauss_rule(3), 40, kH) > 1000 * kTol);
}

TEST_CASE("Galerkin integrator: the run-time stage count gives the fixed-S step to round-off") {
  // GalerkinIntegrator<N, Eigen::Dynamic, L> (what `vibook verify --method` runs) against the
  // fixed-size instance, state by state along 40 steps of Kepler (e = 0.5), and the discrete
  // Lagrangian of each step; a rule of another size is refused by the fixed instance.
  const auto L = mechanical(Kepler{});
  auto compare = [](auto& fixed, auto& dynamic) {
    const test::StepDifference d = test::step_difference(fixed, dynamic, 40, 0.1);
    CHECK(d.converged);
    CHECK(d.state <= 16 * 2.2e-16 * 2);  // |z| <= 2
    CHECK(d.action <= 16 * 2.2e-16);     // |L_d| < 1 for h = 0.1
  };
  GalerkinIntegrator<2, 3, decltype(L)> lobatto3(L, lobatto_rule(3));
  GalerkinIntegrator<2, Eigen::Dynamic, decltype(L)> lobatto3_dynamic(L, lobatto_rule(3));
  compare(lobatto3, lobatto3_dynamic);
  GalerkinIntegrator<2, 2, decltype(L)> gauss2(L, gauss_rule(2));
  GalerkinIntegrator<2, Eigen::Dynamic, decltype(L)> gauss2_dynamic(L, gauss_rule(2));
  compare(gauss2, gauss2_dynamic);
  using Fixed3 = GalerkinIntegrator<2, 3, decltype(L)>;
  CHECK_THROWS_AS(Fixed3(L, gauss_rule(2)), std::invalid_argument);
  using Dynamic = GalerkinIntegrator<2, Eigen::Dynamic, decltype(L)>;
  CHECK_THROWS_AS(Dynamic(L, Quadrature{}), std::invalid_argument);
}
