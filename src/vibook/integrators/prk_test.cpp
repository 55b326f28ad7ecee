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
#include <vector>

#include "vibook/core/order.hpp"
#include "vibook/core/precision.hpp"
#include "vibook/integrators/galerkin.hpp"
#include "vibook/integrators/step_difference_test.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/verify/reference.hpp"
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

namespace {

// Kepler as a Hamiltonian H(q, p) = |p|²/2 − 1/|q| for HamiltonianPrkMethod.
struct KeplerH {
  static constexpr int N = 2;
  template <class T>
  T hamiltonian(const Vec<T, 2>& q, const Vec<T, 2>& p) const {
    using std::sqrt;
    return T(p.squaredNorm() / 2) - T(1) / T(sqrt(T(q.squaredNorm())));
  }
  template <class T>
  Vec<T, 4> gradient(const Vec<T, 4>& z) const {
    using std::sqrt;
    const T r2 = z(0) * z(0) + z(1) * z(1);
    const T r3 = r2 * T(sqrt(r2));
    Vec<T, 4> g;
    g << z(0) / r3, z(1) / r3, z(2), z(3);
    return g;
  }
};

// A position-dependent mass, H = p²/(2(1 + q²)) + q²/2 + q⁴/4: not separable.
struct MassH {
  static constexpr int N = 1;
  template <class T>
  T hamiltonian(const Vec<T, 1>& q, const Vec<T, 1>& p) const {
    return T(p(0) * p(0) / (T(2) * (T(1) + q(0) * q(0)))) + q(0) * q(0) / T(2) +
           q(0) * q(0) * q(0) * q(0) / T(4);
  }
  template <class T>
  Vec<T, 2> gradient(const Vec<T, 2>& z) const {
    const T m = T(1) + z(0) * z(0);
    Vec<T, 2> g;
    g << -z(1) * z(1) * z(0) / (m * m) + z(0) + z(0) * z(0) * z(0), z(1) / m;
    return g;
  }
};

// The error at T = 1 of the method of `t` on MassH from (q, p) = (0.5, 0.3), against the GBS
// reference in double-double (verify/reference.hpp), for steps 1/n.
std::vector<double> mass_errors(const PrkTableau& t, const std::vector<int>& ns) {
  const verify::Field<dd_real> f = [](const std::vector<dd_real>& y) {
    const Vec<dd_real, 2> g = MassH{}.gradient(Vec<dd_real, 2>(y[0], y[1]));
    return std::vector<dd_real>{g(1), -g(0)};
  };
  const auto ref = verify::reference_solution<dd_real>(f, {dd_real(0.5), dd_real(0.3)}, 1.0);
  std::vector<double> err;
  for (int n : ns) {
    HamiltonianPrkMethod<MassH> m(MassH{}, t);
    Vec<double, 1> q(0.5), p(0.3);
    for (int k = 0; k < n; ++k) m.step(q, p, 1.0 / n);
    err.push_back(
        std::max(std::abs(q(0) - to_double(ref.y[0])), std::abs(p(0) - to_double(ref.y[1]))));
  }
  return err;
}

}  // namespace

TEST_CASE("tableau method on any H: the mechanical step when separable and order 4 when not") {
  // On Kepler, H = |p|²/2 − 1/|q|, the general solver (stage positions and momenta together)
  // gives PartitionedRkMethod's step (momenta eliminated) and its discrete Lagrangian, from
  // the same state at every step, to round-off.
  const verify::TableauSpec lob = verify::read_tableau(kTableaus + "lobatto3-iiia-iiib.json");
  PartitionedRkMethod<Eigen::Dynamic, Kepler> mech(Kepler{}, lob.tableau);
  HamiltonianPrkMethod<KeplerH> general(KeplerH{}, lob.tableau);
  const test::StepDifference d = test::step_difference(mech, general, 40, 0.05);
  CHECK(d.converged);
  CHECK(d.state <= 64 * 2.2e-16 * 2);  // |z| <= 2
  CHECK(d.action <= 64 * 2.2e-16);     // |L_d| < 1 for h = 0.05

  // Non-separable: Gauss 2 and Lobatto IIIA-IIIB have order 4 against an independent
  // reference, two-sided, over steps 1/8 … 1/64 (errors 1e-6 … 1e-10, far above round-off);
  // the file with one entry mistyped does not reach it.
  const std::vector<int> ns{8, 16, 32, 64};
  std::vector<double> hs;
  for (int n : ns) hs.push_back(1.0 / n);
  for (const char* file : {"gauss2.json", "lobatto3-iiia-iiib.json"}) {
    INFO(file);
    const std::vector<double> e = mass_errors(verify::read_tableau(kTableaus + file).tableau, ns);
    CHECK(e.back() > 1e-13);  // above the round-off plateau
    CHECK(std::abs(fit_order(hs, e, 0.0).slope - 4) < 0.1);
  }
  const std::vector<double> typo =
      mass_errors(verify::read_tableau(kTableaus + "wrong-lobatto3-typo.json").tableau, ns);
  CHECK(std::abs(fit_order(hs, typo, 0.0).slope - 4) > 1);

  // a solve that cannot converge in one iteration is a typed failure, the state unchanged
  HamiltonianPrkMethod<MassH> limited(MassH{}, lob.tableau, NewtonOptions{.max_iterations = 1});
  Vec<double, 1> q(0.5), p(0.3);
  CHECK_THROWS_AS(limited.step(q, p, 0.1), SolveError);
  CHECK(q(0) == 0.5);
  CHECK(p(0) == 0.3);
  CHECK_THROWS_AS((HamiltonianPrkMethod<MassH>(MassH{}, PrkTableau{})), std::invalid_argument);
}
