// Doctests of composition.hpp: the free-algebra BCH against cases known in closed form, the
// catalogue's order conditions at 120 digits, Newton from the published digits, deliberately
// wrong compositions that the conditions must flag, and measured orders (two-sided, on the
// nonlinear Hénon–Heiles problem, against the continuous equations in double-double).
#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <string>
#include <vector>

#include "vibook/core/order.hpp"
#include "vibook/core/precision.hpp"
#include "vibook/integrators/composition.hpp"
#include "vibook/integrators/kernels.hpp"
#include "vibook/integrators/rkn.hpp"
#include "vibook/integrators/splitting_sequence.hpp"
#include "vibook/problems/problems.hpp"
#include "vibook/verify/reference.hpp"
#include "vibook/verify/verify.hpp"

using namespace vibook;
namespace comp = vibook::composition;

namespace {

constexpr int kDigits = 120;

comp::Stages<mpfr_real> stages_of(std::initializer_list<const char*> texts) {
  comp::Stages<mpfr_real> s;
  for (const char* t : texts) s.push_back(comp::parse_stage<mpfr_real>("--coefficients", t));
  return s;
}

// Error at T = 5 of the composed method on Hénon–Heiles against the continuous equations.
template <class Base, class Adjoint>
double henon_heiles_error(const comp::Stages<mpfr_real>& st, double h) {
  std::vector<double> c;
  std::vector<bool> a;
  for (const auto& s : st) {
    c.push_back(static_cast<double>(s.c));
    a.push_back(s.adjoint);
  }
  const HenonHeiles P;
  comp::Composed<Base, Adjoint> m(Base{P}, Adjoint{P}, c, a);
  Eigen::VectorXd z0(4);
  z0 << 0, 0.1, 0.35, 0;
  static const Eigen::VectorXd ref = [&] {
    const verify::Field<dd_real> f = [&](const std::vector<dd_real>& y) {
      Vec<dd_real, 2> q(y[0], y[1]);
      const Vec<dd_real, 2> g = P.gradient<dd_real>(q);
      return std::vector<dd_real>{y[2], y[3], -g(0), -g(1)};
    };
    std::vector<dd_real> y0{dd_real(0), dd_real(0.1), dd_real(0.35), dd_real(0)};
    const auto r = verify::reference_solution<dd_real>(f, y0, 5.0);
    Eigen::VectorXd z(4);
    for (int i = 0; i < 4; ++i) z(i) = to_double(r.y[static_cast<std::size_t>(i)]);
    return z;
  }();
  const verify::Step step = [&](Eigen::VectorXd& z, double hh) { verify::step_qp<2>(m, z, hh); };
  return (verify::integrate(step, z0, h, 5.0) - ref).lpNorm<Eigen::Infinity>();
}

}  // namespace

TEST_CASE("composition: the free algebra and BCH against closed forms") {
  const MpfrDigits digits(kDigits);
  // odd letters up to weight 5: compositions of 1..5 into odd parts, 1+1+2+3+5, and the empty word
  CHECK(comp::WordAlgebra(5, true).size() == 13);
  CHECK(comp::WordAlgebra(4, false).size() == 16);  // 2^4 words of weight <= 4 with letters 1..4
  // Two half steps of a symmetric base commute: log = 2(X1/2 + X3/8 + X5/32) = X1 + X3/4 + X5/16.
  const comp::WordAlgebra A(5, true);
  const auto L = comp::composition_log(A, stages_of({"1/2", "1/2"}));
  CHECK(std::abs(static_cast<double>(L[static_cast<std::size_t>(A.letter(1))]) - 1) < 1e-100);
  CHECK(std::abs(static_cast<double>(L[static_cast<std::size_t>(A.letter(3))]) - 0.25) < 1e-100);
  CHECK(std::abs(static_cast<double>(L[static_cast<std::size_t>(A.letter(5))]) - 0.0625) < 1e-100);
  // A base step followed by its adjoint (general base): Φ*_{h/2}∘Φ_{h/2} is symmetric, so its
  // even-weight coefficients vanish and it has order 2 — while Φ_{h/2}∘Φ_{h/2} has order 1.
  const auto sym = comp::order_conditions(stages_of({"1/2", "1/2*"}), false, 4);
  CHECK(sym.order == 2);
  CHECK(sym.residual[3] < 1e-100);  // weight 4: zero by symmetry
  CHECK(comp::order_conditions(stages_of({"1/2", "1/2"}), false, 4).order == 1);
}

TEST_CASE("composition: the catalogue reaches its documented order, Newton reproduces it") {
  const MpfrDigits digits(kDigits);
  for (const auto& e : comp::catalogue()) {
    CAPTURE(e.name);
    comp::Refinement rf;
    const auto st = comp::catalogue_stages<mpfr_real>(e.name, kDigits, &rf);
    CHECK(static_cast<int>(st.size()) == e.stages);
    const bool symmetric_base = e.base == "symmetric";
    const auto oc = comp::order_conditions(st, symmetric_base, e.order + 1);
    CHECK(oc.order == e.order);  // exactly: the next weight does not vanish
    CHECK(oc.residual[static_cast<std::size_t>(e.order)] > 1e-6);
    if (symmetric_base) CHECK(comp::is_symmetric(st, true, 1e-100));
    if (rf.iterations > 0) {
      CHECK(rf.converged);
      CHECK(rf.final_residual < 1e-100);
      CHECK(rf.max_change < 2e-12);  // the published digits are the solution to 11-12 digits
    }
  }
  // The finding the chapter reports: the circulating 15-digit values of Yoshida's eighth-order
  // solution A satisfy the weight-7 conditions only to about 1e-11.
  comp::Refinement rf8;
  comp::catalogue_stages<mpfr_real>("yoshida8", kDigits, &rf8);
  CHECK(rf8.published_residual.at(6) > 1e-12);
  CHECK(rf8.published_residual.at(6) < 1e-10);
  comp::Refinement rf6;
  comp::catalogue_stages<mpfr_real>("yoshida6", kDigits, &rf6);
  CHECK(rf6.published_residual.at(4) < 1e-12);
}

TEST_CASE("composition: deliberately wrong compositions are flagged by the conditions") {
  const MpfrDigits digits(kDigits);
  // Yoshida 6 with w1 off by 1e-11 and w0 recomputed (still consistent): weight 3 fails.
  const auto bad6 = comp::order_conditions(
      stages_of({"0.784513610477560", "0.235573213359357", "-1.17767998416887", "1.315186320663906",
                 "-1.17767998416887", "0.235573213359357", "0.784513610477560"}),
      true, 7);
  CHECK(bad6.residual[0] < 1e-100);
  CHECK(bad6.order == 2);
  CHECK(bad6.residual[2] > 1e-12);
  CHECK(bad6.residual[2] < 1e-9);
  // The same, unperturbed, from the published digits: order 6 at the default tolerance.
  CHECK(comp::order_conditions(
            stages_of({"0.784513610477560", "0.235573213359357", "-1.17767998417887",
                       "1.31518632068391", "-1.17767998417887", "0.235573213359357",
                       "0.784513610477560"}),
            true, 7)
            .order == 6);
  // Ruth's third-order method with each (adjoint, base) pair applied in the other order: order 2.
  CHECK(comp::order_conditions(stages_of({"3/8", "7/24*", "-25/24", "3/8*", "0", "1*"}), false, 4)
            .order == 2);
  // The adjoint of a composition has its order.
  const auto ruth = comp::catalogue_stages<mpfr_real>("ruth3", kDigits);
  CHECK(comp::order_conditions(comp::adjoint(ruth), false, 4).order == 3);
  CHECK_FALSE(comp::is_symmetric(ruth, false));
  // The triple jump on a first-order base: order 1.
  CHECK(comp::order_conditions(comp::catalogue_stages<mpfr_real>("yoshida4", kDigits), false, 5)
            .order == 1);
}

TEST_CASE("composition: parsing coefficients") {
  const MpfrDigits digits(kDigits);
  const auto s = comp::parse_stage<mpfr_real>("--coefficients", " 7/24* ");
  CHECK(s.adjoint);
  CHECK(abs(s.c - mpfr_real(7) / 24) < mpfr_real("1e-110"));
  CHECK_FALSE(comp::parse_stage<mpfr_real>("--coefficients", "-1.5e-1").adjoint);
  for (const char* bad : {"", "*", "abc", "1/0", "1/2/3", "0x1", "1..2", "1e", "inf", "nan"}) {
    CAPTURE(bad);
    CHECK_THROWS_AS(comp::parse_stage<mpfr_real>("--coefficients", bad), ArgumentError);
  }
}

TEST_CASE("composition: measured orders on Hénon–Heiles, two-sided") {
  const MpfrDigits digits(kDigits);
  auto fitted = [](auto error_at, std::vector<double> hs) {
    std::vector<double> e;
    for (double h : hs) e.push_back(error_at(h));
    return fit_order(hs, e, 1e-13, 3).slope;
  };
  using SV = StormerVerlet<HenonHeiles>;
  using SE = SymplecticEuler<HenonHeiles>;
  using SEA = SymplecticEulerAdjoint<HenonHeiles>;
  const auto y6 = comp::catalogue_stages<mpfr_real>("yoshida6", kDigits);
  const double p6 =
      fitted([&](double h) { return henon_heiles_error<SV, SV>(y6, h); }, {0.2, 0.1, 0.05});
  CHECK(std::abs(p6 - 6) < 0.2);
  const auto r3 = comp::catalogue_stages<mpfr_real>("ruth3", kDigits);
  const double p3 =
      fitted([&](double h) { return henon_heiles_error<SE, SEA>(r3, h); }, {0.05, 0.025, 0.0125});
  CHECK(std::abs(p3 - 3) < 0.2);
  // the swapped pairs: measured order 2, as the conditions say
  const auto sw = stages_of({"3/8", "7/24*", "-25/24", "3/8*", "0", "1*"});
  const double p2 =
      fitted([&](double h) { return henon_heiles_error<SE, SEA>(sw, h); }, {0.05, 0.025, 0.0125});
  CHECK(std::abs(p2 - 2) < 0.2);
}

// --- splittings (splitting_sequence.hpp) ------------------------------------------------------

TEST_CASE("splitting: coefficients as expressions, sequences, and the equivalent composition") {
  const MpfrDigits digits(kDigits);
  using R = mpfr_real;
  const R theta = comp::evaluate_coefficient<R>("--splitting", "1/(2 - 2^(1/3))");
  CHECK(abs(theta - R(1) / (2 - cbrt(R(2)))) < R("1e-115"));
  CHECK(abs(comp::evaluate_coefficient<R>("--splitting", "1/2-sqrt(3)/6") -
            (R(1) / 2 - sqrt(R(3)) / 6)) < R("1e-115"));
  CHECK(comp::evaluate_coefficient<R>("--splitting", "-(3)*-2") == 6);
  for (const char* bad : {"", "1/0", "sqrt(-1)", "(1", "2^", "1..2", "x", "(-8)^(1/3)", "1 2"})
    CHECK_THROWS_AS(comp::evaluate_coefficient<R>("--splitting", bad), ArgumentError);
  CHECK_THROWS_AS(comp::parse_sequence<R>("--splitting", "drift:1,push:1"), ArgumentError);
  CHECK_THROWS_AS(comp::parse_sequence<R>("--splitting", "drift 1"), ArgumentError);
  // Ruth's method as published (kick first) is the catalogue's composition 7/24*, 3/8, 3/8*,
  // -25/24, 1* of symplectic Euler (drift, then kick) and its adjoint (*).
  const auto ruth = comp::parse_sequence<R>("--splitting", comp::find_splitting("ruth-3")->flows);
  const auto st = comp::as_symplectic_euler_composition(ruth, 1e-100);
  const auto want = comp::catalogue_stages<R>("ruth3", kDigits);
  REQUIRE(st.size() == want.size());
  for (std::size_t i = 0; i < st.size(); ++i) {
    CHECK(abs(st[i].c - want[i].c) < R("1e-115"));
    CHECK(st[i].adjoint == want[i].adjoint);
  }
  // Leapfrog, drift first: se at h/2, then its adjoint: Störmer-Verlet. Merged flows: a kick
  // written in two halves is one kick.
  const auto lf = comp::as_symplectic_euler_composition(
      comp::parse_sequence<R>("--splitting", "drift:1/2,kick:1/4,kick:3/4,drift:1/2"), 1e-100);
  REQUIRE(lf.size() == 2);
  CHECK((lf[0].c == R(1) / 2 && !lf[0].adjoint && lf[1].c == R(1) / 2 && lf[1].adjoint));
  // Inconsistent (the drifts sum to 1, the kicks to 1/2): no equivalent composition.
  CHECK(comp::as_symplectic_euler_composition(
            comp::parse_sequence<R>("--splitting", "drift:1/2,kick:1/2,drift:1/2"), 1e-100)
            .empty());
  CHECK(comp::is_palindrome(comp::parse_sequence<R>("--splitting", "drift:1/2,kick:1,drift:1/2"),
                            1e-60));
  CHECK_FALSE(comp::is_palindrome(comp::parse_sequence<R>("--splitting", "drift:1,kick:1"), 1e-60));
}

TEST_CASE("splitting: the two-flow order conditions against known orders, and wrong variants") {
  const MpfrDigits digits(kDigits);
  using R = mpfr_real;
  // The free algebra's log of exp(A) exp(B): A + B + [A, B]/2 + ... (the word AB has 1/2).
  {
    const comp::TwoLetterAlgebra T(3);
    const auto L = comp::splitting_log(T, comp::parse_sequence<R>("--splitting", "drift:1,kick:1"));
    CHECK(abs(L[static_cast<std::size_t>(comp::TwoLetterAlgebra::index(2, 1u))] - R(1) / 2) <
          R("1e-115"));  // A B
    CHECK(abs(L[static_cast<std::size_t>(comp::TwoLetterAlgebra::index(2, 2u))] + R(1) / 2) <
          R("1e-115"));  // B A
    // BCH at weight 3: (1/12)[A,[A,B]] gives the word AAB the coefficient 1/12.
    CHECK(abs(L[static_cast<std::size_t>(comp::TwoLetterAlgebra::index(3, 1u))] - R(1) / 12) <
          R("1e-115"));
  }
  // Every catalogue entry reaches exactly its documented order (the next weight fails): for two
  // generic flows, or, for an RKN splitting, by the Nystrom trees of its RKN tableau, its
  // generic order then lower. Every entry's Nystrom order is at least its generic one.
  for (const auto& e : comp::splitting_catalogue()) {
    INFO(e.name);
    const auto seq = comp::parse_sequence<R>("--splitting", e.flows);
    const auto oc = comp::splitting_order_conditions(seq, e.order + 2);
    const auto by_trees = comp::splitting_nystrom_conditions(seq, e.order + 2);
    CHECK(by_trees.order >= oc.order);
    if (e.rkn) {
      CHECK(oc.order < e.order);
      CHECK(by_trees.order == e.order);
    } else {
      CHECK(oc.order == e.order);
    }
  }
  // McLachlan and Atela's method with its flows in the other order (drift first): order 1 by
  // both algebras, a wrong step structure; and with two digits of its third kick transposed
  // (0.75623 for 0.75632): the kicks no longer sum to 1, order 0.
  {
    std::string f = comp::find_splitting("mclachlan-atela-4")->flows;
    std::vector<std::string> items;
    for (std::size_t from = 0; from <= f.size();) {
      const std::size_t comma = std::min(f.find(',', from), f.size());
      items.push_back(f.substr(from, comma - from));
      from = comma + 1;
    }
    std::string swapped;
    for (std::size_t i = 0; i + 1 < items.size(); i += 2)
      swapped += (i ? "," : "") + items[i + 1] + "," + items[i];
    auto nystrom_order = [](const std::string& flows) {
      return comp::splitting_nystrom_conditions(comp::parse_sequence<R>("--splitting", flows), 6)
          .order;
    };
    CHECK(nystrom_order(f) == 4);
    CHECK(nystrom_order(swapped) == 1);
    std::string typo = f;
    typo.replace(typo.find("0.7563200005"), 12, "0.7562300005");
    CHECK(nystrom_order(typo) == 0);
    // a drift moved by 1e-9: the drifts' total misses 1 and the order is 0 (the positions'
    // condition of order 1), where the tableau alone, which folds the total into bbar, would
    // not show it at order 1
    std::string moved = f;
    moved.replace(moved.find("0.1288461583653841854"), 21, "0.1288461593653841854");
    CHECK(nystrom_order(moved) == 0);
  }
  // The Laskar-Robutel methods' nodes and weights are quadrature rules, Gauss (SABA_n, exact to
  // degree 2n - 1) and Lobatto (SBAB_n, n + 1 nodes, the same degree): the words with a single
  // kick B vanish up to weight 2n (their error is O(h^2n eps + h^2 eps^2)). A node or weight
  // typed wrong breaks this, though not the generic order 2.
  for (const auto& method :
       {std::pair{"saba-2", 2}, std::pair{"saba-3", 3}, std::pair{"saba-4", 4},
        std::pair{"sbab-2", 2}, std::pair{"sbab-3", 3}}) {
    const auto& [name, n] = method;
    INFO(method.first);  // (the pair's member: doctest's INFO captures it in a lambda)
    const comp::TwoLetterAlgebra T(2 * n);
    const auto L = comp::splitting_log(
        T, comp::parse_sequence<R>("--splitting", comp::find_splitting(name)->flows));
    R worst = 0;
    for (int len = 2; len <= 2 * n; ++len)
      for (unsigned bits = 0; bits < (1u << len); ++bits)
        if (std::popcount(bits) == 1) {
          const R c = abs(L[static_cast<std::size_t>(comp::TwoLetterAlgebra::index(len, bits))]);
          if (c > worst) worst = c;
        }
    CHECK(worst < R("1e-100"));
  }
  // SABA_4 with its Gauss weights swapped: still symmetric and of order 2, but no longer the
  // quadrature: a single-kick word of weight 3 does not vanish.
  {
    std::string f = comp::find_splitting("saba-4")->flows;
    for (std::size_t at = 0; (at = f.find("(18-sqrt(30))", at)) != std::string::npos; ++at)
      f[at + 3] = '#';
    for (std::size_t at = 0; (at = f.find("(18+sqrt(30))", at)) != std::string::npos; ++at)
      f[at + 3] = '-';
    for (auto& ch : f)
      if (ch == '#') ch = '+';
    const auto seq = comp::parse_sequence<R>("--splitting", f);
    CHECK(comp::splitting_order_conditions(seq, 4).order == 2);
    const comp::TwoLetterAlgebra T(3);
    const auto L = comp::splitting_log(T, seq);
    CHECK(abs(L[static_cast<std::size_t>(comp::TwoLetterAlgebra::index(3, 2u))]) > R("1e-3"));
  }
  // Forest-Ruth stepped as a non-palindromic sequence (its last half drift moved to the front,
  // so that the first drift is whole): order 1. One kick's sign flipped: not consistent.
  const std::string t = "(2-2^(1/3))";
  const auto moved = comp::splitting_order_conditions(
      comp::parse_sequence<R>("--splitting", "drift:1/" + t + ",kick:1/" + t +
                                                 ",drift:(1-2^(1/3))/(2*" + t + "),kick:-2^(1/3)/" +
                                                 t + ",drift:(1-2^(1/3))/(2*" + t + "),kick:1/" +
                                                 t),
      6);
  CHECK(moved.order == 1);
  const auto flipped = comp::splitting_order_conditions(
      comp::parse_sequence<R>("--splitting", "drift:1/(2*" + t + "),kick:-1/" + t +
                                                 ",drift:(1-2^(1/3))/(2*" + t + "),kick:-2^(1/3)/" +
                                                 t + ",drift:(1-2^(1/3))/(2*" + t + "),kick:1/" +
                                                 t + ",drift:1/(2*" + t + ")"),
      6);
  CHECK(flipped.order == 0);
}
