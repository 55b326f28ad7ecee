// Doctests of the engine's variational order of compositions and Galerkin rules whose
// coefficients are known to finite precision (method_symbolic.hpp): the catalogue's
// coefficients and Gauss 4's nodes cut to 30 digits, and the threshold below which a term of
// L_d − L_d^E counts as zero.
#include <doctest/doctest.h>

#include <cmath>
#include <optional>
#include <string>
#include <thread>

#include "vibook/core/precision.hpp"
#include "vibook/verify/expression.hpp"
#include "vibook/verify/map_study.hpp"
#include "vibook/verify/method_study.hpp"
#include "vibook/verify/method_symbolic.hpp"

TEST_CASE(
    "derived variational order at 30 digits: yoshida4 is 4 and an eleventh-digit error is 2") {
  using namespace vibook::verify;
  const auto st = catalogue_rationals("yoshida4");
  REQUIRE(st.size() == 3);
  // the triple jump cut to 30 digits: order 4 once the cut's terms (near 1e-30) count as zero
  CHECK(composition_variational_order("sv", st, "pendulum", 4, composition_zero_below()) == 4);
  // an exact zero test sees the cut: the three coefficients cut to 30 digits add up to 1 only
  // to about 1e-30, which shows at h^1 (order 0); the threshold is what makes the route work
  CHECK(composition_variational_order("sv", st, "pendulum", 4, std::nullopt) == 0);
  // the outer coefficient off in its eleventh digit, the middle one keeping the sum 1 and the
  // palindrome: the third-order conditions fail by 1e-11, and the threshold must not hide it
  auto wrong = st;
  const GiNaC::numeric delta = GiNaC::numeric(1) / GiNaC::numeric(10).power(11);
  wrong[0].first += delta;
  wrong[2].first += delta;
  wrong[1].first -= 2 * delta;
  CHECK(composition_variational_order("sv", wrong, "pendulum", 4, composition_zero_below()) == 2);
}

TEST_CASE(
    "Shen & Sun's Theorem 10 on an RKN tableau: velocity Verlet and RKN4 agree with the engine, "
    "and a tableau outside the theorem's assumption does not") {
  using namespace vibook;
  using verify::nystrom_theorem10;
  const vibook::MpfrDigits digits(120);
  using R = mpfr_real;
  // velocity Verlet: c = (0, 1), abar = [[0, 0], [1/2, 0]], bbar = (1/2, 0), b = (1/2, 1/2).
  // Symmetric: no h term; f^[2] = -(f''<x',x'> + f'f)/12, the Stormer-Verlet modified equation.
  const auto vv = nystrom_theorem10({R(0), R(1)}, {{R(0), R(0)}, {R("0.5"), R(0)}},
                                    {R("0.5"), R(0)}, {R("0.5"), R("0.5")});
  CHECK(vv.alpha == 0);
  CHECK(std::abs(vv.beta1 + 1.0 / 12) <= 1e-15);
  CHECK(std::abs(vv.beta2 + 1.0 / 12) <= 1e-15);
  CHECK(vv.h1_difference == 0);
  CHECK(vv.h2_difference == 0);
  // The classical RKN4 (Hairer, Norsett & Wanner I, Table II.14.3): order 4, so no h or h^2
  // term at all, by the theorem and by the engine.
  const R sixth = R(1) / 6, third = R(1) / 3;
  const auto rkn4 =
      nystrom_theorem10({R(0), R("0.5"), R(1)},
                        {{R(0), R(0), R(0)}, {R("0.125"), R(0), R(0)}, {R(0), R("0.5"), R(0)}},
                        {sixth, third, R(0)}, {sixth, R(2) * third, sixth});
  CHECK(std::abs(rkn4.alpha) <= 1e-100);
  CHECK(std::abs(rkn4.beta1) <= 1e-100);
  CHECK(std::abs(rkn4.beta2) <= 1e-100);
  CHECK(rkn4.h1_difference <= 1e-100);
  CHECK(rkn4.h2_difference <= 1e-100);
  // Explicit Euler-Nystrom with its velocity weight doubled (sum b = 2): the theorem assumes
  // sum b = 1, and the comparison with the engine must see it.
  const auto bad = nystrom_theorem10({R(0)}, {{R(0)}}, {R(0)}, {R(2)});
  CHECK(bad.weights_residual == 1.0);
  CHECK(bad.h1_difference + bad.h2_difference > 1e-3);
}

TEST_CASE(
    "cut Gauss 4: symmetric, exact below degree four, order beyond h^5, and a twelfth-digit "
    "error is caught") {
  using namespace vibook::verify;
  using GiNaC::numeric;
  const vibook::modified::ExactQuadrature q = cut_quadrature(vibook::gauss_rule(4));
  REQUIRE(q.c.size() == 4);
  auto moment = [](const vibook::modified::ExactQuadrature& r, int k) {
    numeric m = 0;
    for (std::size_t i = 0; i < r.c.size(); ++i)
      m += GiNaC::ex_to<numeric>(r.b[i]) * GiNaC::ex_to<numeric>(r.c[i]).power(k);
    return m - numeric(1, k + 1);
  };
  for (std::size_t i = 0; i < 4; ++i) {
    INFO("node " << i);
    CHECK(GiNaC::ex_to<numeric>(q.c[i] + q.c[3 - i]) == 1);  // symmetric, exactly
    CHECK(GiNaC::ex_to<numeric>(q.b[i] - q.b[3 - i]).is_zero());
  }
  const numeric tiny = numeric(1) / numeric(10).power(28);
  for (int k = 0; k < 8; ++k) {
    INFO("moment of degree " << k);
    if (k < 4)
      CHECK(moment(q, k).is_zero());  // interpolatory weights: exact
    else
      CHECK(abs(moment(q, k)) < tiny);  // Gauss's own moments: the 30-digit cut
  }
  // nothing through h^5 on the pendulum with the threshold (the cut leaves terms near 1e-34)
  CHECK(galerkin_variational_order(q, "pendulum", 4, composition_zero_below()) == -1);
  // the outer nodes moved by 1e-12 (symmetrically, weights kept): the moment of degree 2 is off
  // by about 1e-13, which L_d - L_d^E shows at h^3 (variational order 2); the threshold must
  // not hide it
  auto wrong = q;
  const numeric delta = numeric(1) / numeric(10).power(12);
  wrong.c[0] = wrong.c[0] + delta;
  wrong.c[3] = wrong.c[3] - delta;
  const int r = galerkin_variational_order(wrong, "pendulum", 4, composition_zero_below());
  CHECK(r == 2);
}

TEST_CASE(
    "two threads derive the Galerkin variational order and build typed systems side by side: "
    "each gets its own answer") {
  // The field audit's rows run in parallel; each makes a hook that keeps GiNaC objects (the
  // rule, the Lagrangian), runs it, copies and drops it, and builds typed systems. Built with
  // the `tsan` preset, ThreadSanitizer reports any of these outside modified::ginac_mutex();
  // in the other builds a use outside the lock is an occasional crash, and the test checks
  // the answers.
  using namespace vibook;
  using namespace vibook::verify;
  auto one = [](const std::string& family, int stages) {
    int derived = -1;
    for (int round = 0; round < 2; ++round) {
      MethodSpec spec;
      spec.name = family + ":" + std::to_string(stages);
      spec.stages = stages;
      spec.rule = quadrature_rule(family, stages);
      MapStudy study;
      study.expected = spec.rule.order;
      derive_galerkin_variational_order(spec, 1, test_problem_lagrangian("pendulum"),
                                        SymbolicUse::always, study);
      const MapStudy copy = study;  // the hook copied, then run from the copy
      MapMeasurement rep;
      copy.derive_variational_order(copy, rep);
      derived = rep.js["variational_order"]["engine"].value("order", -1);
      const TypedDiscreteLagrangian dl("(q1-q0)^2/(2*h) - h*(V(q0)+V(q1))/2", "-cos(x)");
      const TypedDiscreteLagrangian dl_copy = dl;
      if (dl_copy.dim() != 1) derived = -2;
    }
    return derived;
  };
  int gauss = -1, lobatto = -1;
  std::thread a([&] { gauss = one("gauss", 2); });
  std::thread b([&] { lobatto = one("lobatto", 3); });
  a.join();
  b.join();
  CHECK(gauss == 4);
  CHECK(lobatto == 4);
}
