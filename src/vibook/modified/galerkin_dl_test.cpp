// Doctests of the symbolic Galerkin discrete Lagrangian (galerkin_dl.hpp): the closed-form
// quadrature rules against their defining equations, and the engine's variational order of the
// Galerkin methods (Marsden & West 2001, §2.6 and Theorem 2.3.1) against the orders the theory
// gives, with wrong rules that must come out lower.
#include <cmath>

#include <doctest/doctest.h>

#include "vibook/integrators/galerkin.hpp"
#include "vibook/modified/canonical.hpp"
#include "vibook/modified/galerkin_dl.hpp"

using namespace vibook;
using namespace vibook::modified;
using GiNaC::numeric;

namespace {

// The pendulum, L = |v|²/2 + cos q, on the engine's symbols.
ex pendulum(const std::vector<ex>& q, const std::vector<ex>& v) {
  return v[0] * v[0] / 2 + GiNaC::cos(q[0]);
}

VariationalOrder galerkin_order(const ExactQuadrature& rule, int K) {
  auto J = std::make_shared<JetSpace>(1);
  Engine E(galerkin_dl(rule, pendulum, J, "Galerkin"), K);
  return E.variational_order(pendulum({J->x(0, 0)}, {J->x(1, 0)}));
}

}  // namespace

TEST_CASE("galerkin symbolic: the closed-form rules satisfy their defining equations") {
  // A rule with s nodes is exact for degree 2s − 1 (Gauss) or 2s − 3 (Lobatto, end points
  // fixed), and these moment equations determine it; the next degree is not integrated
  // exactly. Checked in exact arithmetic, and the nodes against galerkin.hpp's (computed by
  // Newton's method in long double) to 1e-15.
  const struct {
    const char* family;
    int s, degree;
  } rules[] = {{"gauss", 1, 1},   {"gauss", 2, 3},   {"gauss", 3, 5},  {"lobatto", 2, 1},
               {"lobatto", 3, 3}, {"lobatto", 4, 5}, {"lobatto", 5, 7}};
  for (const auto& r : rules) {
    const std::string family = r.family;
    CAPTURE(family);
    CAPTURE(r.s);
    const auto q = exact_quadrature(r.family, r.s);
    REQUIRE(q.has_value());
    REQUIRE(q->c.size() == static_cast<std::size_t>(r.s));
    auto moment = [&](int k) {
      ex m = 0;
      for (int i = 0; i < r.s; ++i) m += q->b[i] * (k == 0 ? ex(1) : GiNaC::pow(q->c[i], k));
      return GiNaC::expand(m - numeric(1, k + 1));
    };
    for (int k = 0; k <= r.degree; ++k) CHECK(vanishes(moment(k)));
    CHECK(!vanishes(moment(r.degree + 1)));
    const Quadrature num = quadrature_rule(r.family, r.s);
    for (int i = 0; i < r.s; ++i) {
      CHECK(std::abs(GiNaC::ex_to<numeric>(GiNaC::evalf(q->c[i])).to_double() - num.c[i]) < 1e-15);
      CHECK(std::abs(GiNaC::ex_to<numeric>(GiNaC::evalf(q->b[i])).to_double() - num.b[i]) < 1e-15);
    }
  }
  CHECK(!exact_quadrature("gauss", 4).has_value());
  CHECK(!exact_quadrature("radau", 2).has_value());
}

TEST_CASE("galerkin symbolic: variational order 2s for Gauss and 2s - 2 for Lobatto") {
  // On the pendulum: the first nonvanishing coefficient of L_d − L_d^E is at h^{r+1} with r the
  // method's order (Marsden & West Theorem 2.3.1, HLW Theorem VI.6.4), checked two-sided: every
  // earlier coefficient vanishes, that one does not.
  const struct {
    const char* family;
    int s, order;
  } cases[] = {{"gauss", 1, 2}, {"gauss", 2, 4}, {"lobatto", 2, 2}, {"lobatto", 3, 4}};
  for (const auto& c : cases) {
    const std::string family = c.family;
    CAPTURE(family);
    CAPTURE(c.s);
    const auto r = galerkin_order(*exact_quadrature(c.family, c.s), c.order);
    CHECK(r.order == c.order);
  }
  // Two degrees of freedom (Hénon–Heiles): Lobatto 3 has two interior control points, four
  // unknowns, eliminated together by Gaussian elimination on series.
  {
    auto J = std::make_shared<JetSpace>(2);
    const auto hh = [](const std::vector<ex>& q, const std::vector<ex>& v) -> ex {
      const ex &x = q[0], &y = q[1];
      return (v[0] * v[0] + v[1] * v[1]) / 2 - (x * x + y * y) / 2 - x * x * y + y * y * y / 3;
    };
    Engine E(galerkin_dl(*exact_quadrature("lobatto", 3), hh, J, "Lobatto 3"), 4);
    REQUIRE(E.discrete_lagrangian().qm.size() == 4);
    const auto r = E.variational_order(hh({J->x(0, 0), J->x(0, 1)}, {J->x(1, 0), J->x(1, 1)}));
    CHECK(r.order == 4);
  }
  // Wrong rules. Lobatto's three nodes with the weights 1/4, 1/2, 1/4: the cubic through the
  // step has a mode τ(τ − 1/2)(τ − 1) that vanishes at every node, and its velocities there
  // (1/2, −1/4, 1/2) no longer average to zero under these weights, so the eliminated control
  // points move it by O(1) and L_d/h does not tend to L: variational order 0. Gauss nodes
  // misplaced at 1/2 ± 1/5 (the moment of degree 2 wrong): variational order 2.
  ExactQuadrature bad = *exact_quadrature("lobatto", 3);
  bad.b = {numeric(1, 4), numeric(1, 2), numeric(1, 4)};
  CHECK(galerkin_order(bad, 4).order == 0);
  ExactQuadrature moved = *exact_quadrature("gauss", 2);
  moved.c = {numeric(3, 10), numeric(7, 10)};
  CHECK(galerkin_order(moved, 4).order == 2);
}

TEST_CASE("prk symbolic: a symplectic tableau's variational order from a and b, two-sided") {
  // prk_dl (Suris; Marsden & West 2001): on the pendulum, Lobatto IIIA-IIIB (three stages,
  // order 4) gives the Galerkin lobatto:3's L_d - L_d^E term for term (HLW Theorem VI.6.4), the
  // Stormer-Verlet pair order 2 and symplectic Euler (one stage, no interior point) order 1,
  // each with its first term nonzero. The wrong input: Lobatto IIIA-IIIB's middle row of a
  // changed to (1/4, 1/4, 0), which stays a symplectic pair with ahat rebuilt from the
  // conditions but drops to order 2.
  auto order_of = [](const std::vector<std::vector<ex>>& a, const std::vector<ex>& b, int K) {
    auto J = std::make_shared<JetSpace>(1);
    Engine E(prk_dl(a, b, pendulum, J, "tableau"), K);
    return E.variational_order(pendulum({J->x(0, 0)}, {J->x(1, 0)}));
  };
  const numeric sixth(1, 6), two3(2, 3);
  const std::vector<ex> b3 = {sixth, two3, sixth};
  const VariationalOrder lobatto = order_of(
      {{0, 0, 0}, {numeric(5, 24), numeric(1, 3), numeric(-1, 24)}, {sixth, two3, sixth}}, b3, 4);
  CHECK(lobatto.order == 4);
  const VariationalOrder galerkin = galerkin_order(*exact_quadrature("lobatto", 3), 4);
  REQUIRE(lobatto.defect.size() == galerkin.defect.size());
  for (std::size_t k = 0; k < lobatto.defect.size(); ++k)  // (each on its own jets: as text)
    CHECK(canonical_string(lobatto.defect[k], Format::text) ==
          canonical_string(galerkin.defect[k], Format::text));
  CHECK(!vanishes(lobatto.defect[4]));
  const numeric half(1, 2);
  CHECK(order_of({{0, 0}, {half, half}}, {half, half}, 2).order == 2);
  CHECK(order_of({{1}}, {1}, 1).order == 1);
  const VariationalOrder wrong =
      order_of({{0, 0, 0}, {numeric(1, 4), numeric(1, 4), 0}, {sixth, two3, sixth}}, b3, 4);
  CHECK(wrong.order == 2);
  // a zero weight leaves its stage velocity undetermined: refused
  CHECK_THROWS_AS(order_of({{0, 0}, {half, half}}, {1, 0}, 2), std::invalid_argument);
}
