// Shen & Sun 2025, §2: the Helmholtz conditions (Theorems 2–4) on the paper's examples and a
// negative control (SS-T2), and the Noether characteristics of the Kepler invariants
// (Propositions 2 and 4, SS-P4).
#include <cmath>
#include <functional>
#include <random>

#include <fmt/format.h>

#include "vibook/core/autodiff.hpp"
#include "vibook/core/tolerance.hpp"
#include "vibook/kepler/checks.hpp"
#include "vibook/mechanics/discrete_lagrangian.hpp"
#include "vibook/mechanics/helmholtz.hpp"

namespace vibook::checks {

namespace {

// Identity mass matrix of dimension n in the scalar of x.
template <int n>
auto unit_mass() {
  return [](const auto& x, const auto&) {
    using S = scalar_t<decltype(x)>;
    Mat<S, n> M;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) M(i, j) = constant<S>(i == j ? 1.0 : 0.0);
    return M;
  };
}

// −∇φ for φ = −1/|x| (attractive Coulomb/Kepler), any dimension.
template <int n>
auto coulomb_force() {
  return [](const auto&, const auto& x, const auto&) {
    using S = scalar_t<decltype(x)>;
    using std::sqrt;
    const S r2 = squared_norm(x);
    const S inv_r3 = constant<S>(1) / (r2 * sqrt(r2));
    Vec<S, n> F;
    for (int i = 0; i < n; ++i) F(i) = -x(i) * inv_r3;
    return F;
  };
}

// Lorentz-type force v × B(x) + E(x) in 3-D, i.e. f = A(x) v + φ(x) with A_ij = −ε_ijk B_k
// antisymmetric; (2.5b) holds iff div B = 0. `divergence_free` picks B = (x1, −x2, 1) (closed
// two-form) or B = (x1, x2, 1) (div B = 2: the negative control).
auto lorentz_force(bool divergence_free) {
  return [divergence_free](const auto&, const auto& x, const auto& v) {
    using S = scalar_t<decltype(x)>;
    Vec<S, 3> B;
    B(0) = x(0);
    B(1) = divergence_free ? S(-x(1)) : S(x(1));
    B(2) = constant<S>(1);
    const auto E = coulomb_force<3>()(x(0), x, v);
    Vec<S, 3> F;
    F(0) = v(1) * B(2) - v(2) * B(1) + E(0);
    F(1) = v(2) * B(0) - v(0) * B(2) + E(1);
    F(2) = v(0) * B(1) - v(1) * B(0) + E(2);
    return F;
  };
}

std::vector<claims::ClaimResult> run_t2(const Context&) {
  HelmholtzOptions opt;
  opt.x_shift = Vec<double, 3>(3.0, 0.0, 0.0);  // keep |x| ≥ 2, away from the singularity
  const double c_light = 3.0;                   // |v| ≤ √3 < c in the sampled box
  struct Case {
    const char* name;
    bool expected;
    HelmholtzReport r;
  };
  std::vector<Case> cases;
  cases.push_back({"kepler", true, helmholtz_check<2>(unit_mass<2>(), coulomb_force<2>(), opt)});
  cases.push_back({"relativistic_2_7", true,
                   helmholtz_check<2>(
                       [c_light](const auto&, const auto& v) {
                         using S = scalar_t<decltype(v)>;
                         using std::sqrt;
                         const S gamma = constant<S>(1) /
                                         sqrt(constant<S>(1) -
                                              squared_norm(v) / constant<S>(c_light * c_light));
                         Mat<S, 2> M;
                         M(0, 0) = gamma, M(1, 1) = gamma, M(0, 1) = constant<S>(0),
                              M(1, 0) = constant<S>(0);
                         return M;
                       },
                       coulomb_force<2>(), opt)});
  cases.push_back(
      {"lorentz_div_B_0", true, helmholtz_check<3>(unit_mass<3>(), lorentz_force(true), opt)});
  cases.push_back({"damped_oscillator", false,
                   helmholtz_check<2>(
                       unit_mass<2>(),
                       [](const auto&, const auto& x, const auto& v) {
                         using S = scalar_t<decltype(x)>;
                         return Vec<S, 2>(-x(0) - constant<S>(0.1) * v(0),
                                          -x(1) - constant<S>(0.1) * v(1));
                       },
                       opt)});
  cases.push_back({"lorentz_div_B_2_control", false,
                   helmholtz_check<3>(unit_mass<3>(), lorentz_force(false), opt)});
  claims::ClaimResult c;
  // [ss-t2-criterion]
  c.id = "SS-T2";
  c.source = "check-ss-t2";
  bool ok = true;
  std::string txt;
  for (const auto& k : cases) {
    c.values.push_back({std::string(k.name) + "_res_2_2a", k.r.residual_a});
    c.values.push_back({std::string(k.name) + "_res_2_2b", k.r.residual_b});
    c.values.push_back({std::string(k.name) + "_res_2_2c", k.r.residual_c});
    c.values.push_back({std::string(k.name) + "_variational", k.r.variational ? 1.0 : 0.0});
    ok = ok && k.r.variational == k.expected;
    txt += fmt::format("{}: {} (largest relative residuals {:.1e}, {:.1e}, {:.1e}); ", k.name,
                       k.r.variational ? "variational" : "NOT variational", k.r.residual_a,
                       k.r.residual_b, k.r.residual_c);
  }
  c.status = ok ? claims::Status::reproduced : claims::Status::not_reproduced;
  // [ss-t2-criterion]
  c.note = fmt::format(
      "(2.2a)–(2.2c) at {} random (t, x, ẋ, ẍ) per system, x ∈ (3, 0[, 0]) + [−1, 1]^n, ẋ, ẍ ∈ "
      "[−1, 1]^n, c = 3; verdict: every residual ≤ 1e3ε relative to its terms. {}{}",
      opt.samples, txt,
      ok ? "All as the paper states; the divergence-full control fails (2.5b) as Theorem 3 "
           "predicts."
         : "Not as stated.");
  return {c};
}

// Proposition 2 invariants and Proposition 4 characteristics, generic in the scalar.
struct Invariant {
  const char* name;
  std::function<ad::Dual<4>(const Vec<ad::Dual<4>, 2>&, const Vec<ad::Dual<4>, 2>&)> P;
  std::function<Vec<double, 2>(const Vec<double, 2>&, const Vec<double, 2>&)> Q;
};

std::vector<claims::ClaimResult> run_p4(const Context&) {
  using D = ad::Dual<4>;
  using std::sqrt;
  auto r = [](const Vec<D, 2>& x) { return D(sqrt(x(0) * x(0) + x(1) * x(1))); };
  std::vector<Invariant> inv = {
      {"H",
       [&](const Vec<D, 2>& x, const Vec<D, 2>& v) {
         return D(0.5 * (v(0) * v(0) + v(1) * v(1)) - 1.0 / r(x));
       },
       [](const Vec<double, 2>&, const Vec<double, 2>& v) { return v; }},
      {"m", [](const Vec<D, 2>& x, const Vec<D, 2>& v) { return D(x(0) * v(1) - x(1) * v(0)); },
       [](const Vec<double, 2>& x, const Vec<double, 2>&) { return Vec<double, 2>(-x(1), x(0)); }},
      {"A1",
       [&](const Vec<D, 2>& x, const Vec<D, 2>& v) {
         const D vv = v(0) * v(0) + v(1) * v(1), xv = x(0) * v(0) + x(1) * v(1);
         return D(x(0) * vv - v(0) * xv - x(0) / r(x));
       },
       [](const Vec<double, 2>& x, const Vec<double, 2>& v) {
         return Vec<double, 2>(-x(1) * v(1), 2 * x(0) * v(1) - v(0) * x(1));
       }},
      {"A2",
       [&](const Vec<D, 2>& x, const Vec<D, 2>& v) {
         const D vv = v(0) * v(0) + v(1) * v(1), xv = x(0) * v(0) + x(1) * v(1);
         return D(x(1) * vv - v(1) * xv - x(1) / r(x));
       },
       [](const Vec<double, 2>& x, const Vec<double, 2>& v) {
         return Vec<double, 2>(2 * x(1) * v(0) - x(0) * v(1), -x(0) * v(0));
       }},
  };
  std::mt19937_64 rng(20250402);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::vector<double> worst(inv.size(), 0.0);
  for (int s = 0; s < 500; ++s) {
    // (Drawn one by one, the second component first: argument evaluation order is unspecified,
    // GCC and clang differ, and this is the order the book's numbers were first drawn in.)
    const double xy = U(rng), xx = 2.0 + U(rng), vy = U(rng), vx = U(rng), ay = U(rng), ax = U(rng);
    const Vec<double, 2> x(xx, xy), v(vx, vy), a(ax, ay);
    const double r3 = std::pow(x.norm(), 3);
    const Vec<double, 2> N = a + x / r3;  // the Kepler equation of motion, ẍ + x/|x|³
    Vec<double, 4> z;
    z << x, v;
    for (std::size_t k = 0; k < inv.size(); ++k) {
      const Vec<double, 4> g = ad::gradient<4>(
          [&](const auto& Z) {
            const Vec<D, 2> xx = Z.template head<2>(), vv = Z.template tail<2>();
            return inv[k].P(xx, vv);
          },
          z);
      const double dPdt = g.head<2>().dot(v) + g.tail<2>().dot(a);
      const double rhs = N.dot(inv[k].Q(x, v));
      const double scale = g.head<2>().cwiseAbs().dot(v.cwiseAbs()) +
                           g.tail<2>().cwiseAbs().dot(a.cwiseAbs()) + std::abs(rhs) + 1e-300;
      worst[k] = std::max(worst[k], std::abs(dPdt - rhs) / scale);
    }
  }
  // [ss-p4-criterion]
  const double tol = 1e3 * kEps;
  claims::ClaimResult c;
  c.id = "SS-P4";
  c.source = "check-ss-p4";
  bool ok = true;
  for (std::size_t k = 0; k < inv.size(); ++k) {
    c.values.push_back({fmt::format("{}_max_rel_residual", inv[k].name), worst[k]});
    ok = ok && worst[k] <= tol;
  }
  c.status = ok ? claims::Status::reproduced : claims::Status::not_reproduced;
  // [ss-p4-criterion]
  c.note = fmt::format(
      "dP/dt = N[x]·Q with N[x] = ẍ + x/|x|³, checked at 500 random (x, ẋ, ẍ), x ∈ (2, 0) + "
      "[−1, 1]², identically in ẍ: largest relative residuals H {:.1e}, m {:.1e}, A1 {:.1e}, "
      "A2 {:.1e} (bound 1e3ε). The LRL vector of Prop. 2 and the characteristics of Prop. 4 "
      "are right. (The proof's N[x] is printed with ẋ where ẍ is meant: SS-ERR-P4, read from "
      "the paper by check-modified.)",
      worst[0], worst[1], worst[2], worst[3]);
  return {c};
}

}  // namespace

Check check_ss_t2() {
  return {"check-ss-t2",
          "Helmholtz conditions on Kepler, (2.7), Lorentz, damped (Shen–Sun Thms 2–4)",
          false,
          {"SS-T2"},
          run_t2};
}
Check check_ss_p4() {
  return {"check-ss-p4",
          "Noether characteristics of H, m, A (Shen–Sun Props 2, 4)",
          false,
          {"SS-P4"},
          run_p4};
}

}  // namespace vibook::checks
