/// \file galerkin.hpp
/// \brief Galerkin variational integrators (Marsden & West 2001, §2.6; Hairer, Lubich &
/// Wanner, *Geometric Numerical Integration*, §VI.6.3): the discrete Lagrangian is the action
/// of a polynomial of degree s through the step, evaluated by an s-node quadrature rule, with
/// the polynomial's interior control points eliminated by the discrete Euler–Lagrange solver.
///
///   L_d(q0, q1, h) = ext over Q^1 … Q^{s−1} of  h Σ_i b_i L(q(c_i h), q̇(c_i h)),
///   q(τh) = Σ_ν ℓ_ν(τ) Q^ν,  Q^0 = q0, Q^s = q1, control times d_ν = ν/s,
///
/// in vibook's scaling L_d ≈ h·L. With Gauss–Legendre nodes it is the s-stage Gauss collocation
/// method (order 2s); with Gauss–Lobatto nodes the s-stage Lobatto IIIA–IIIB pair (order
/// 2s − 2). HLW Theorem VI.6.4 states the equivalence with the partitioned Runge–Kutta method
/// a_ij = ∫_0^{c_i} ℓ̃_j, â_ij = b_j(1 − a_ji/b_i) (ℓ̃_j the Lagrange polynomials on the nodes);
/// the doctests check it step by step (galerkin_test.cpp), against PartitionedRungeKutta below.
///
/// The quadrature nodes and weights are computed from their defining equations (roots of the
/// Legendre polynomial P_s, or of P'_{s−1} with the end points, by Newton's method in long
/// double), not typed.
///
/// One step: given (q0, p0), Newton's method on the s·N unknowns (Q^1 … Q^{s−1}, q1) together,
///   ∂A/∂Q^ν = 0 (ν = 1 … s−1),   p0 + ∂A/∂Q^0 = 0,
/// then p1 = ∂A/∂Q^s, with A the quadrature action; every derivative, the Newton Jacobian (a
/// block of A's Hessian) included, by nested forward AutoDiff on the one callable L(q, v) (on V
/// alone when L declares itself |v|²/2 − V(q): galerkin_detail::UnitMassMechanical). The
/// unknowns are carried as increments Q^ν = q0 + h W_ν (see step()), so that the momenta are
/// not differences of positions over h.
///
/// Chapter: \ref chapter-verify.
#pragma once

#include <algorithm>
#include <cmath>
#include <concepts>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "vibook/core/autodiff.hpp"
#include "vibook/core/errors.hpp"
#include "vibook/core/newton.hpp"
#include "vibook/core/scalar.hpp"
#include "vibook/core/types.hpp"

namespace vibook {

/// A quadrature rule on [0, 1]: nodes c_i and weights b_i, in the scalar T.
template <class T>
struct QuadratureT {
  std::string name;  ///< "gauss" or "lobatto"
  std::vector<T> c, b;
  int order = 0;  ///< the order of the variational integrator built on it (2s or 2s − 2)
};
using Quadrature = QuadratureT<double>;

namespace galerkin_detail {

// P_n(x) and P_n'(x) on [−1, 1] by the three-term recurrence, in the scalar R.
template <class R>
void legendre(int n, R x, R& p, R& dp) {
  R p0 = R(1), p1 = x;
  if (n == 0) {
    p = R(1);
    dp = R(0);
    return;
  }
  for (int k = 2; k <= n; ++k) {
    const R p2 = (R(2 * k - 1) * x * p1 - R(k - 1) * p0) / R(k);
    p0 = p1;
    p1 = p2;
  }
  p = p1;
  dp = R(n) * (x * p1 - p0) / (x * x - R(1));  // valid off ±1 (Gauss nodes and Lobatto interiors)
}

// Lagrange basis polynomial j on the nodes x, and its derivative, at t.
template <class R>
R lagrange(const std::vector<R>& x, std::size_t j, R t) {
  R r = R(1);
  for (std::size_t m = 0; m < x.size(); ++m)
    if (m != j) r *= (t - x[m]) / (x[j] - x[m]);
  return r;
}
template <class R>
R lagrange_derivative(const std::vector<R>& x, std::size_t j, R t) {
  R sum = R(0);
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (k == j) continue;
    R term = R(1) / (x[j] - x[k]);
    for (std::size_t m = 0; m < x.size(); ++m)
      if (m != j && m != k) term *= (t - x[m]) / (x[j] - x[m]);
    sum += term;
  }
  return sum;
}

// The scalar the integrator's basis coefficients are computed in: long double for double (as
// the nodes are), T itself for a wider type.
template <class T>
using BasisReal = std::conditional_t<std::is_same_v<T, double>, long double, T>;

}  // namespace galerkin_detail

/// The s-node Gauss–Legendre rule on [0, 1] (exact for degree 2s − 1), 1 ≤ s ≤ 8.
inline Quadrature gauss_rule(int s) {
  if (s < 1 || s > 8) throw std::invalid_argument("gauss_rule: s must lie in 1..8");
  Quadrature q{"gauss", {}, {}, 2 * s};
  for (int i = 1; i <= s; ++i) {
    long double x = std::cos(3.14159265358979323846L * (i - 0.25L) / (s + 0.5L)), p, dp;
    for (int it = 0; it < 100; ++it) {
      galerkin_detail::legendre(s, x, p, dp);
      const long double dx = p / dp;
      x -= dx;
      if (std::fabs(dx) < 1e-19L) break;
    }
    galerkin_detail::legendre(s, x, p, dp);
    q.c.insert(q.c.begin(), static_cast<double>((1 + x) / 2));  // ascending
    q.b.insert(q.b.begin(), static_cast<double>(1 / ((1 - x * x) * dp * dp)));
  }
  return q;
}

/// The s-node Gauss–Lobatto rule on [0, 1] (end points included, exact for degree 2s − 3),
/// 2 ≤ s ≤ 8.
inline Quadrature lobatto_rule(int s) {
  if (s < 2 || s > 8) throw std::invalid_argument("lobatto_rule: s must lie in 2..8");
  Quadrature q{"lobatto", {0.0}, {}, 2 * s - 2};
  const int n = s - 1;  // interior nodes: the roots of P_n'
  std::vector<long double> interior;
  for (int i = 1; i < s - 1; ++i) {
    long double x = -std::cos(3.14159265358979323846L * i / n), p, dp;
    for (int it = 0; it < 100; ++it) {
      // f = P_n', f' = P_n'' = (2x P_n' − n(n+1) P_n)/(1 − x²)
      galerkin_detail::legendre(n, x, p, dp);
      const long double d2 = (2 * x * dp - n * (n + 1) * p) / (1 - x * x);
      const long double dx = dp / d2;
      x -= dx;
      if (std::fabs(dx) < 1e-19L) break;
    }
    interior.push_back(x);
  }
  const long double w_end = 1.0L / (s * (s - 1));  // 2/(s(s−1)) on [−1, 1], halved
  q.b.push_back(static_cast<double>(w_end));
  for (long double x : interior) {
    long double p, dp;
    galerkin_detail::legendre(n, x, p, dp);
    q.c.push_back(static_cast<double>((1 + x) / 2));
    q.b.push_back(static_cast<double>(1 / (s * (s - 1) * p * p)));
  }
  q.c.push_back(1.0);
  q.b.push_back(static_cast<double>(w_end));
  return q;
}

/// The same rule in a wider scalar T (double-double, for the order studies beyond double):
/// each interior node refined by Newton's method on its defining equation in T, from the long
/// double node, and the weights recomputed in T from the same formulas.
template <class T>
QuadratureT<T> quadrature_in(const Quadrature& r) {
  using std::abs;
  QuadratureT<T> q{r.name, {}, {}, r.order};
  const int s = static_cast<int>(r.c.size());
  const T eps = unit_roundoff<T>();
  for (int i = 0; i < s; ++i) {
    if (r.name == "lobatto" && (i == 0 || i == s - 1)) {
      q.c.push_back(T(i == 0 ? 0 : 1));
      q.b.push_back(T(1) / T(s * (s - 1)));
      continue;
    }
    T x = T(2) * T(r.c[static_cast<std::size_t>(i)]) - T(1), p, dp;
    const int n = r.name == "lobatto" ? s - 1 : s;
    for (int it = 0; it < 20; ++it) {
      galerkin_detail::legendre(n, x, p, dp);
      T dx;
      if (r.name == "lobatto")  // f = P_n', f' = (2x P_n' − n(n+1) P_n)/(1 − x²)
        dx = dp / ((T(2) * x * dp - T(n * (n + 1)) * p) / (T(1) - x * x));
      else
        dx = p / dp;
      x -= dx;
      if (abs(dx) <= T(4) * eps) break;
    }
    galerkin_detail::legendre(n, x, p, dp);
    q.c.push_back((T(1) + x) / T(2));
    q.b.push_back(r.name == "lobatto" ? T(1) / (T(s * (s - 1)) * p * p)
                                      : T(1) / ((T(1) - x * x) * dp * dp));
  }
  return q;
}

/// "gauss:S" or "lobatto:S" (S the number of stages).
inline Quadrature quadrature_rule(const std::string& family, int s) {
  if (family == "gauss") return gauss_rule(s);
  if (family == "lobatto") return lobatto_rule(s);
  throw std::invalid_argument("quadrature_rule: unknown family '" + family + "'");
}

namespace galerkin_detail {

// A Lagrangian that declares itself L = |v|²/2 − V(q) (unit mass: `unit_mass_mechanical`)
// and gives V by `potential(q)`. Its derivatives in (q, v) are known apart from V's:
// ∇_v L = v, ∇²_vv L = I, ∇²_qv L = 0; only V is differentiated, in N variables instead of 2N
// (the nested AutoDiff over double-double of the Galerkin order studies spent most of its time
// differentiating the kinetic term in directions that cannot change it).
template <class L, int N, class T>
concept UnitMassMechanical = L::unit_mass_mechanical &&
    requires(const L& l, const Vec<ad::Dual2<N, T>, N>& q) {
  { l.potential(q) } -> std::same_as<ad::Dual2<N, T>>;
};

}  // namespace galerkin_detail

/// The Galerkin variational integrator of the file comment for a Lagrangian `L(q, v)` (a
/// callable templated on the scalar, returning a scalar), N degrees of freedom, S stages
/// (the polynomial's degree and the number of quadrature nodes). S may be Eigen::Dynamic: the
/// number of stages is then the rule's, and the step's matrices are sized at run time (one
/// instance serves every rule; the same arithmetic, a little slower). `step` has the interface
/// of DelIntegrator: it advances (q, p) in place, reports the residual and iterations, and
/// throws SolveError (leaving q, p unchanged) when Newton does not converge or the result is
/// not finite. T is the scalar of the state and the solve (double, or double-double with the
/// rule from quadrature_in and Newton's stopping rule at T's round-off).
template <int N, int S, class Lagrangian, class T = double>
class GalerkinIntegrator {
  static constexpr bool fixed = S != Eigen::Dynamic;

 public:
  static constexpr int dim = N;
  static constexpr int M = fixed ? (S + 1) * N : Eigen::Dynamic;  ///< all control points
  static constexpr int U = fixed ? S * N : Eigen::Dynamic;  ///< interior control points and q1

  GalerkinIntegrator(Lagrangian L, QuadratureT<T> rule, NewtonOptions options = {})
      : L_(std::move(L)),
        rule_(std::move(rule)),
        options_(options),
        s_(static_cast<int>(rule_.c.size())) {
    if ((fixed && s_ != S) || s_ < 1 || rule_.b.size() != rule_.c.size())
      throw std::invalid_argument("GalerkinIntegrator: the rule must have S nodes and weights");
    using R = galerkin_detail::BasisReal<T>;
    std::vector<R> d(static_cast<std::size_t>(s_ + 1));
    for (int nu = 0; nu <= s_; ++nu) d[static_cast<std::size_t>(nu)] = R(nu) / R(s_);
    ell_.resize(static_cast<std::size_t>(s_ * (s_ + 1)));
    dell_.resize(ell_.size());
    for (int i = 0; i < s_; ++i)
      for (int nu = 0; nu <= s_; ++nu) {
        const R t = R(rule_.c[static_cast<std::size_t>(i)]);
        ell(i, nu) = static_cast<T>(galerkin_detail::lagrange(d, static_cast<std::size_t>(nu), t));
        dell(i, nu) = static_cast<T>(
            galerkin_detail::lagrange_derivative(d, static_cast<std::size_t>(nu), t));
      }
  }

  const QuadratureT<T>& rule() const { return rule_; }

  /// The start time t of the next step, for a time-dependent Lagrangian: one callable as
  /// L(q, v, t) is evaluated at node i at the time t + c_i h (Marsden & West 2001, §4.1: the
  /// quadrature of ∫ L(q, q', t) dt over the step). An autonomous L(q, v) ignores it.
  void set_time(T t) { t_ = t; }

  /// One step. The control points are carried as increments, Q^ν = q0 + h W_ν (W_0 = 0), and
  /// the action over h as Φ(q0, W) = A/h = Σ_i b_i L(q0 + h Σ_ν ℓ_ν(c_i) W_ν,
  /// Σ_ν ℓ'_ν(c_i) W_ν): since Σ_ν ℓ'_ν = 0 the velocities are sums of W, not differences of
  /// positions over h, so round-off does not grow like u/h as the step shrinks. Then
  /// ∂A/∂Q^ν = ∂Φ/∂W_ν (ν ≥ 1) and ∂A/∂Q^0 = h ∂Φ/∂q0 − Σ_ν ∂Φ/∂W_ν, so the equations are
  /// ∂Φ/∂W_ν = 0 (ν = 1 … S−1) and p0 + h ∂Φ/∂q0 − ∂Φ/∂W_S = 0 for W = (W_1 … W_S); then
  /// q1 = q0 + h W_S and p1 = ∂Φ/∂W_S = p0 + h ∂Φ/∂q0.
  SolveReport step(Vec<T, N>& q, Vec<T, N>& p, T h) {
    const int ns = s_, u = ns * N, m = (ns + 1) * N;
    const Vec<T, N> q0 = q, p0 = p;
    // guess W_ν = d_ν p0 (the straight line with velocity p0: unit mass)
    Vec<T, U> w = Vec<T, U>::Zero(u);
    for (int nu = 1; nu <= ns; ++nu) w.template segment<N>((nu - 1) * N) = (T(nu) / T(ns)) * p0;
    Vec<T, M> grad = Vec<T, M>::Zero(m);
    Mat<T, M> hess = Mat<T, M>::Zero(m, m);
    T phi = T(0);  // Φ = A/h at the last evaluation
    // Φ's gradient and Hessian in X = (q0, W): Φ = Σ_i b_i L(B_i X) with B_i the linear map to
    // (q, v) at node i, so they are Σ b_i B_iᵀ ∇L and Σ b_i B_iᵀ ∇²L B_i, with ∇L and ∇²L in the
    // 2N variables (q, v) by nested AutoDiff (small, whatever S is).
    auto derivatives = [&](const Vec<T, U>& x) {
      constexpr int K = 2 * N;
      using Out = ad::Dual2<K, T>;
      grad.setZero();
      hess.setZero();
      phi = T(0);
      for (int i = 0; i < ns; ++i) {
        // B = [a ⊗ I_N; d ⊗ I_N] with a = (1, h ℓ_1, …, h ℓ_S), d = (0, ℓ'_1, …, ℓ'_S) at node i
        auto a = [&](int nu) { return nu == 0 ? T(1) : T(h * ell(i, nu)); };
        auto dd = [&](int nu) { return nu == 0 ? T(0) : T(dell(i, nu)); };
        Vec<T, K> z;
        for (int k = 0; k < N; ++k) {
          T qk = q0(k), vk = T(0);
          for (int nu = 1; nu <= ns; ++nu) {
            qk += h * ell(i, nu) * x((nu - 1) * N + k);
            vk += dell(i, nu) * x((nu - 1) * N + k);
          }
          z(k) = qk;
          z(N + k) = vk;
        }
        const T b = rule_.b[static_cast<std::size_t>(i)];
        Vec<T, K> g;
        Mat<T, K> Hl;
        if constexpr (galerkin_detail::UnitMassMechanical<Lagrangian, N, T>) {
          // L = |v|²/2 − V(q): the same numbers the general path below computes (its kinetic
          // term's q-derivatives are exact zeros, its v-derivatives v and I exactly), V's
          // derivatives in the N position variables only.
          const ad::Dual2<N, T> V =
              L_.potential(ad::variables2<N, T>(Vec<T, N>(z.template head<N>())));
          const Vec<T, N> v = z.template tail<N>();
          phi += b * (constant<T>(0.5) * squared_norm(v) - V.value().value());
          Hl.setZero();
          for (int k = 0; k < N; ++k) {
            g(k) = T(0) - V.value().derivatives()(k);
            g(N + k) = v(k);
            Hl(N + k, N + k) = T(1);
            for (int j = 0; j < N; ++j) Hl(k, j) = T(0) - V.derivatives()(j).derivatives()(k);
          }
        } else {
          const Vec<Out, K> Y = ad::variables2<K, T>(z);
          const Vec<Out, N> qq = Y.template head<N>(), vv = Y.template tail<N>();
          const Out l = [&] {
            if constexpr (std::is_invocable_v<const Lagrangian&, const Vec<Out, N>&,
                                              const Vec<Out, N>&, const Out&>) {
              const Out ti = constant_of<Out>(T(t_ + rule_.c[static_cast<std::size_t>(i)] * h));
              static_assert(ad::returns_scalar<decltype(L_(qq, vv, ti)), Out>,
                            VIBOOK_RETURNS_SCALAR_MESSAGE);
              return L_(qq, vv, ti);
            } else {
              static_assert(ad::returns_scalar<decltype(L_(qq, vv)), Out>,
                            VIBOOK_RETURNS_SCALAR_MESSAGE);
              return L_(qq, vv);
            }
          }();
          g = l.value().derivatives();
          for (int j = 0; j < K; ++j) Hl.col(j) = l.derivatives()(j).derivatives();
          phi += b * l.value().value();
        }
        // Bᵀ g and Bᵀ ∇²L B block by block: with B = [a ⊗ I; d ⊗ I], block (μ, ν) of
        // Bᵀ ∇²L B is a_μ a_ν H_qq + a_μ d_ν H_qv + d_μ a_ν H_vq + d_μ d_ν H_vv (N × N each),
        // about N times fewer operations than the general product and no dense B (the
        // double-double order studies of the Galerkin methods spent a third of their time there)
        const Mat<T, N> Hqq = Hl.template topLeftCorner<N, N>(),
                        Hqv = Hl.template topRightCorner<N, N>(),
                        Hvq = Hl.template bottomLeftCorner<N, N>(),
                        Hvv = Hl.template bottomRightCorner<N, N>();
        const Vec<T, N> gq = g.template head<N>(), gv = g.template tail<N>();
        for (int mu = 0; mu <= ns; ++mu) {
          const T am = b * a(mu), dm = b * dd(mu);
          grad.template segment<N>(mu * N) += am * gq + dm * gv;
          const Mat<T, N> rq = am * Hqq + dm * Hvq, rv = am * Hqv + dm * Hvv;
          for (int nu = 0; nu <= ns; ++nu)
            hess.template block<N, N>(mu * N, nu * N) += a(nu) * rq + dd(nu) * rv;
        }
      }
    };
    auto fj = [&](const Vec<T, U>& x, Vec<T, U>& F, Mat<T, U>& J) {
      derivatives(x);
      // rows: F_0 = p0 + h Φ_q0 − Φ_{W_S}, then Φ_{W_1} … Φ_{W_{S−1}}
      F.template head<N>() = p0 + h * grad.template head<N>() - grad.template tail<N>();
      J.template topRows<N>() =
          h * hess.template block<N, U>(0, N, N, u) - hess.template block<N, U>(m - N, N, N, u);
      if (ns > 1) {
        F.tail(u - N) = grad.segment(N, u - N);
        J.bottomRows(u - N) = hess.block(N, N, u - N, u);
      }
    };
    // The updates are judged against the size of the momenta as well as each component's own
    // (a component of W near zero would otherwise ask for more than round-off allows).
    NewtonOptions opt = options_;
    if constexpr (std::is_same_v<T, double>) {
      opt.step_abs =
          std::max(opt.step_abs, 4 * std::numeric_limits<double>::epsilon() *
                                     std::max(1.0, p0.template lpNorm<Eigen::Infinity>()));
    } else {  // the stopping rule at T's round-off
      opt.step_rel = std::min(opt.step_rel, 4 * to_double(unit_roundoff<T>()));
      opt.step_abs = std::max(
          opt.step_abs, 4 * to_double(unit_roundoff<T>()) *
                            std::max(1.0, to_double(T(p0.template lpNorm<Eigen::Infinity>()))));
    }
    const SolveReport rep = newton_solve<U>(w, fj, opt, "Galerkin step");
    if (!rep.converged) throw SolveError("Galerkin step", rep);
    derivatives(w);
    const Vec<T, N> q1 = q0 + h * w.template tail<N>();
    // p1 = ∂A/∂Q^S = ∂Φ/∂W_S; at the solution this equals p0 + h ∂Φ/∂q0 (a common shift of all
    // control points changes A by h ∂Φ/∂q0, and the other partial derivatives are −p0 and 0).
    // The second form sums b_i ∂L/∂q, not Lagrange-derivative coefficients of size up to S²
    // times ∂L/∂v, and leaves u|p| of round-off instead of about 10 u|p|.
    const Vec<T, N> p1 = p0 + h * grad.template head<N>();
    auto finite = [](const Vec<T, N>& v) {
      for (Eigen::Index i = 0; i < v.size(); ++i)
        if (!std::isfinite(to_double(v(i)))) return false;
      return true;
    };
    if (!finite(q1) || !finite(p1)) throw SolveError("Galerkin step: non-finite state", rep);
    q = q1;
    p = p1;
    action_ = h * phi;
    return rep;
  }

  /// The discrete Lagrangian of the last step, L_d(q0, q1, h) = A = h Φ at the solved
  /// polynomial (Marsden & West's scaling, L_d ≈ ∫ L dt): the quadrature action with the
  /// interior control points at their extremum for the step's two ends.
  T action() const { return action_; }

 private:
  // ℓ_ν(c_i) and ℓ'_ν(c_i), i < s, ν ≤ s
  T& ell(int i, int nu) { return ell_[static_cast<std::size_t>(i * (s_ + 1) + nu)]; }
  T& dell(int i, int nu) { return dell_[static_cast<std::size_t>(i * (s_ + 1) + nu)]; }

  Lagrangian L_;
  QuadratureT<T> rule_;
  NewtonOptions options_;
  int s_;  ///< the number of stages (S when S is fixed)
  std::vector<T> ell_, dell_;
  T action_ = T(0);
  T t_ = T(0);  ///< the start time of the next step (set_time)
};

/// The partitioned Runge–Kutta method HLW Theorem VI.6.4 pairs with the Galerkin integrator on
/// a rule (c, b): a_ij = ∫_0^{c_i} ℓ̃_j(τ) dτ, â_ij = b_j (1 − a_ji / b_i), for a mechanical
/// problem H = ½|p|² + V(q) (`Problem::gradient`). The stage equations are solved by fixed-point
/// iteration (for the doctest's small steps), to round-off. Gauss: â = a (collocation);
/// Lobatto: a is IIIA, â is IIIB.
template <class Problem>
class PartitionedRungeKutta {
 public:
  static constexpr int N = Problem::N;
  PartitionedRungeKutta(Problem P, const Quadrature& rule) : P_(std::move(P)), b_(rule.b) {
    const std::size_t s = rule.c.size();
    std::vector<long double> c(rule.c.begin(), rule.c.end());
    a_.assign(s, std::vector<double>(s));
    ahat_.assign(s, std::vector<double>(s));
    // ∫_0^{c_i} ℓ̃_j by the s-node Gauss rule mapped to [0, c_i] (exact: degree s − 1)
    const Quadrature g = gauss_rule(static_cast<int>(s));
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j) {
        long double sum = 0;
        for (std::size_t k = 0; k < s; ++k)
          sum += g.b[k] * galerkin_detail::lagrange(c, j, c[i] * g.c[k]);
        a_[i][j] = static_cast<double>(c[i] * sum);
      }
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j) ahat_[i][j] = b_[j] * (1 - a_[j][i] / b_[i]);
  }

  const std::vector<std::vector<double>>& a() const { return a_; }
  const std::vector<std::vector<double>>& ahat() const { return ahat_; }

  void step(Vec<double, N>& q, Vec<double, N>& p, double h) const {
    const std::size_t s = b_.size();
    std::vector<Vec<double, N>> Q(s, q), F(s), P(s, p);
    for (int it = 0; it < 200; ++it) {
      for (std::size_t j = 0; j < s; ++j) F[j] = -P_.gradient(Q[j]);
      double change = 0;
      for (std::size_t i = 0; i < s; ++i) {
        Vec<double, N> Pi = p;
        for (std::size_t j = 0; j < s; ++j) Pi += h * ahat_[i][j] * F[j];
        P[i] = Pi;
      }
      for (std::size_t i = 0; i < s; ++i) {
        Vec<double, N> Qi = q;
        for (std::size_t j = 0; j < s; ++j) Qi += h * a_[i][j] * P[j];
        change = std::max(change, (Qi - Q[i]).template lpNorm<Eigen::Infinity>());
        Q[i] = Qi;
      }
      if (change == 0) break;
    }
    for (std::size_t j = 0; j < s; ++j) F[j] = -P_.gradient(Q[j]);
    Vec<double, N> q1 = q, p1 = p;
    for (std::size_t j = 0; j < s; ++j) {
      Vec<double, N> Pj = p;
      for (std::size_t k = 0; k < s; ++k) Pj += h * ahat_[j][k] * F[k];
      q1 += h * b_[j] * Pj;
      p1 += h * b_[j] * F[j];
    }
    q = q1;
    p = p1;
  }

 private:
  Problem P_;
  std::vector<double> b_;
  std::vector<std::vector<double>> a_, ahat_;
};

}  // namespace vibook
