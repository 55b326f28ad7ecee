// Doctests of the partitioned Runge–Kutta method from a tableau (prk.hpp) and of reading a
// tableau file (verify/tableau_study.hpp): the Newton stage solve gives the fixed-point solve's
// step for the same tableau, the Lobatto IIIA-IIIB file gives the Galerkin lobatto:3 step and
// discrete Lagrangian (HLW Theorem VI.6.4), and the example files' conditions are what they
// should be.
#include "vibook/integrators/prk.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "vibook/integrators/galerkin.hpp"
#include "vibook/integrators/step_difference_test.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/verify/tableau_study.hpp"

using namespace vibook;

namespace {

const std::string kTableaus = std::string(VIBOOK_FIGURES_DIR) + "/../examples/tableaus/";

auto kepler_lagrangian() {
  return [](const auto& q, const auto& v) -> std::remove_cvref_t<decltype(q(0))> {
    using T = std::remove_cvref_t<decltype(q(0))>;
    return constant<T>(0.5) * squared_norm(v) - Kepler{}.template potential<T>(q);
  };
}

// The largest one-step difference between the tableau method and the Galerkin lobatto:3 step,
// in the state (relative to its size) and in the discrete Lagrangian (relative to |L_d|), from
// the states of 40 Galerkin steps of h on Kepler (e = 0.5, from perihelion).
struct Difference {
  double state = 0, action = 0;
};
Difference tableau_vs_galerkin(const PrkTableau& t, double h) {
  GalerkinIntegrator<2, 3, decltype(kepler_lagrangian())> g(kepler_lagrangian(), lobatto_rule(3));
  PartitionedRkMethod<3, Kepler> m(Kepler{}, t);
  Vec<double, 2> q(0.5, 0), p(0, std::sqrt(3.0));
  Difference d;
  for (int k = 0; k < 40; ++k) {
    Vec<double, 2> q2 = q, p2 = p;
    g.step(q, p, h);
    m.step(q2, p2, h);
    const double size = std::max(q.lpNorm<Eigen::Infinity>(), p.lpNorm<Eigen::Infinity>());
    d.state = std::max({d.state, (q - q2).lpNorm<Eigen::Infinity>() / size,
                        (p - p2).lpNorm<Eigen::Infinity>() / size});
    d.action = std::max(d.action, std::abs(g.action() - m.action()) / std::abs(g.action()));
  }
  return d;
}

}  // namespace

TEST_CASE("tableau method: Newton on the stages gives the fixed-point step of the same tableau") {
  // Gauss 3 from its collocation coefficients, solved two ways: equal to 64 units of round-off
  const PartitionedRungeKutta<Kepler> fixed(Kepler{}, gauss_rule(3));
  PrkTableau t{fixed.a(), fixed.ahat(), gauss_rule(3).b, gauss_rule(3).b};
  PartitionedRkMethod<3, Kepler> newton(Kepler{}, t);
  Vec<double, 2> q(0.5, 0), p(0, std::sqrt(3.0));
  double worst = 0;
  for (int k = 0; k < 40; ++k) {
    Vec<double, 2> q2 = q, p2 = p;
    const SolveReport r = newton.step(q, p, 0.05);
    CHECK(r.converged);
    fixed.step(q2, p2, 0.05);
    worst =
        std::max({worst, (q - q2).lpNorm<Eigen::Infinity>(), (p - p2).lpNorm<Eigen::Infinity>()});
  }
  CHECK(worst <= 64 * 2.2e-16 * 2);
  // a solve that does not converge (one Newton iteration allowed) is a typed failure, the
  // state unchanged
  PartitionedRkMethod<3, Kepler> limited(Kepler{}, t, NewtonOptions{.max_iterations = 1});
  Vec<double, 2> q0(0.5, 0), p0(0, std::sqrt(3.0)), q1 = q0, p1 = p0;
  CHECK_THROWS_AS(limited.step(q1, p1, 0.05), SolveError);
  CHECK(q1 == q0);
  CHECK(p1 == p0);
}

TEST_CASE("tableau file: Lobatto IIIA-IIIB is the Galerkin lobatto:3 method, a typo is not") {
  const verify::TableauSpec right = verify::read_tableau(kTableaus + "lobatto3-iiia-iiib.json");
  CHECK(right.tableau.stages() == 3);
  CHECK(right.symplectic_conditions);
  CHECK(right.symplectic_residual <= 1e-100);  // ratios read exactly at 120 digits
  CHECK(right.row_sum_residual <= 1e-100);
  CHECK(right.documented_order.value_or(0) == 4);
  // HLW Theorem VI.6.4: the same step, and h Σ b_i (|P_i|²/2 − U(Q_i)) is the Galerkin
  // quadrature action, the discrete Lagrangian (measured: a few units of round-off)
  const Difference d = tableau_vs_galerkin(right.tableau, 0.05);
  CHECK(d.state <= 64 * 2.2e-16);
  CHECK(d.action <= 64 * 2.2e-16);
  // one entry mistyped (5/8 for 5/6): the conditions fail at 120 digits and the step differs
  const verify::TableauSpec typo = verify::read_tableau(kTableaus + "wrong-lobatto3-typo.json");
  CHECK_FALSE(typo.symplectic_conditions);
  CHECK(typo.symplectic_residual >= 1e-3);
  CHECK(tableau_vs_galerkin(typo.tableau, 0.05).state > 1e6 * 64 * 2.2e-16);
  // Lobatto IIIA for both halves: b = bhat holds, the symplecticity condition does not
  const verify::TableauSpec iiia =
      verify::read_tableau(kTableaus + "wrong-lobatto3-iiia-only.json");
  CHECK(iiia.bhat_residual == 0);
  CHECK_FALSE(iiia.symplectic_conditions);
  // Gauss 2 from 45-digit decimals: the symplecticity condition holds exactly (the irrational
  // parts cancel), the row sums to the digits given
  const verify::TableauSpec g2 = verify::read_tableau(kTableaus + "gauss2.json");
  CHECK(g2.symplectic_conditions);
  CHECK(g2.row_sum_residual <= 1e-44);
}

TEST_CASE("tableau method: the run-time stage count gives the fixed-S step to round-off") {
  // PartitionedRkMethod<Eigen::Dynamic, P> (what `vibook verify --tableau` runs) against the
  // fixed-size instance on the Lobatto IIIA-IIIB tableau, from the same state at every step
  const PartitionedRungeKutta<Kepler> prk(Kepler{}, lobatto_rule(3));
  PrkTableau t{prk.a(), prk.ahat(), lobatto_rule(3).b, lobatto_rule(3).b};
  PartitionedRkMethod<3, Kepler> fixed(Kepler{}, t);
  PartitionedRkMethod<Eigen::Dynamic, Kepler> dynamic(Kepler{}, t);
  const test::StepDifference d = test::step_difference(fixed, dynamic, 40, 0.1);
  CHECK(d.converged);
  CHECK(d.state <= 16 * 2.2e-16 * 2);  // |z| <= 2
  CHECK(d.action <= 16 * 2.2e-16);     // |L_d| < 1 for h = 0.1
  // a tableau of another size is refused by the fixed instance, an empty one by both
  CHECK_THROWS_AS((PartitionedRkMethod<2, Kepler>(Kepler{}, t)), std::invalid_argument);
  CHECK_THROWS_AS((PartitionedRkMethod<Eigen::Dynamic, Kepler>(Kepler{}, PrkTableau{})),
                  std::invalid_argument);
}
