/// \file prk.hpp
/// \brief A partitioned Runge–Kutta method from its tableau, for a mechanical problem
/// H = ½|p|² + U(q) (PartitionedRkMethod) or any Hamiltonian H(q, p) (HamiltonianPrkMethod, at
/// the end): the route `vibook verify --tableau FILE` takes any pair (a, b) for q and (â, b̂)
/// for p, explicit or implicit.
///
/// **The method** (Hairer, Lubich and Wanner, *Geometric Numerical Integration*, §II.2.2):
///
///     P_i = p0 − h Σ_j â_ij ∇U(Q_j),   Q_i = q0 + h Σ_j a_ij P_j,
///     p1  = p0 − h Σ_i b̂_i ∇U(Q_i),    q1  = q0 + h Σ_i b_i P_i.
///
/// With q' = p the momenta stages enter linearly, so the stages are solved in the increments
/// W_i = (Q_i − q0)/h alone: W = c̃ p0 − h M ∇U(q0 + h W), with c̃_i = Σ_j a_ij and M = A Â.
/// Newton's method on W, with the Jacobian I + h² M ⊗ ∇²U(Q) (∇²U by AutoDiff of the
/// problem's gradient). Carrying increments rather than Q keeps the round-off of q1 − q0 at
/// u·|W| h instead of u·|q| (the same choice as the Galerkin integrator).
///
/// **Symplectic tableaus are variational.** When b = b̂ and b_i â_ij + b_j a_ji = b_i b_j
/// (HLW §VI.4), the method is the variational partitioned Runge–Kutta method of the
/// discrete Lagrangian L_d(q0, q1, h) = h Σ_i b_i L(Q_i, Q̇_i) extremized over the stage
/// velocities (HLW Theorem VI.6.4 for the Galerkin case; Marsden & West 2001, §2.6.5); for
/// L = ½|v|² − U the stage velocities are Q̇_i = P_i, so along the step
/// L_d = h Σ_i b_i (½|P_i|² − U(Q_i)), which `action()` returns.
///
/// Chapter: \ref chapter-verify (section "A method from its tableau").
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
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
#include "vibook/integrators/rkn.hpp"

namespace vibook {

/// A partitioned Runge–Kutta tableau with entries in T: the q-part (a, b) and the p-part
/// (â, b̂), s stages each. PrkTableau is the double one; a double-double one carries the
/// entries to 32 digits for the order study in extended precision.
template <class T>
struct PrkTableauT {
  std::vector<std::vector<T>> a, ahat;
  std::vector<T> b, bhat;
  int stages() const { return static_cast<int>(b.size()); }
};
using PrkTableau = PrkTableauT<double>;

/// The method of prk.hpp with S stages on a mechanical problem (`Problem::N`,
/// `Problem::gradient`, a templated `Problem::potential`). `step` has the interface of the
/// kernels: it advances (q, p) in place, reports the residual and iterations, and throws
/// SolveError (leaving q and p as they were) when Newton does not converge or the result is
/// not finite. S may be Eigen::Dynamic: the number of stages is then the tableau's, and the
/// stage system is sized at run time (one instance serves every tableau).
/// T is the arithmetic of the whole step (double, or double-double for the order study of
/// high-order methods, whose asymptotic range lies below double's round-off).
template <int S, class Problem, class T = double>
class PartitionedRkMethod {
  static constexpr bool fixed = S != Eigen::Dynamic;
  // per-stage vectors: on the stack when S is fixed
  template <class X>
  using PerStage = std::conditional_t<fixed, std::array<X, fixed ? S : 1>, std::vector<X>>;

 public:
  static constexpr int N = Problem::N;
  static constexpr int U = fixed ? S * N : Eigen::Dynamic;
  /// The problem's force depends on the time: `gradient(q, t)` and `potential(q, t)`.
  static constexpr bool timed_problem = requires(const Problem& P, const Vec<T, N>& q, const T& t) {
    P.gradient(q, t);
  };

  PartitionedRkMethod(Problem P, const PrkTableauT<T>& t, NewtonOptions options = {})
      : P_(std::move(P)), t_(t), options_(options), s_(t_.stages()) {
    const auto n = static_cast<std::size_t>(s_);
    if ((fixed && s_ != S) || s_ < 1 || t_.bhat.size() != n || t_.a.size() != n ||
        t_.ahat.size() != n)
      throw std::invalid_argument("PartitionedRkMethod: the tableau must have S stages");
    M_.assign(n, std::vector<T>(n));
    c_.assign(n, T(0));
    for (std::size_t i = 0; i < n; ++i) {
      if (t_.a[i].size() != n || t_.ahat[i].size() != n)
        throw std::invalid_argument("PartitionedRkMethod: a and ahat must be S x S");
      T ci(0);
      for (std::size_t j = 0; j < n; ++j) {
        ci += t_.a[i][j];
        T m(0);
        for (std::size_t k = 0; k < n; ++k) m += t_.a[i][k] * t_.ahat[k][j];
        M_[i][j] = m;
      }
      c_[i] = ci;
    }
  }

  /// The Runge–Kutta–Nyström method of an RKN tableau (rkn.hpp): the same stage system with
  /// M = ā and c̃ = c, then q1 = q0 + h p0 + h² Σ b̄_i f(Q_i), p1 = p0 + h Σ b_i f(Q_i). It has
  /// no momenta stages, so action() is NaN (no discrete Lagrangian is formed).
  PartitionedRkMethod(Problem P, const RknTableauT<T>& t, NewtonOptions options = {})
      : P_(std::move(P)), options_(options), s_(t.stages()), rkn_(true) {
    const auto n = static_cast<std::size_t>(s_);
    if ((fixed && s_ != S) || s_ < 1 || t.c.size() != n || t.bbar.size() != n || t.abar.size() != n)
      throw std::invalid_argument("PartitionedRkMethod: the RKN tableau must have S stages");
    for (const auto& r : t.abar)
      if (r.size() != n) throw std::invalid_argument("PartitionedRkMethod: abar must be S x S");
    M_ = t.abar;
    c_ = t.c;
    t_.b = t.b;
    rkn_bbar_ = t.bbar;
  }

  /// The start time t of the next step, for a time-dependent force: stage i is evaluated at
  /// t + c_i h with c_i = Σ_j a_ij (an RKN tableau's c), the time being a position of the
  /// extended system whose velocity is 1 (chapter "Verify your own
  /// integrator", section "Time-dependent systems").
  void set_time(const T& t) requires timed_problem { time_ = t; }

  SolveReport step(Vec<T, N>& q, Vec<T, N>& p, const T& h) {
    const int ns = s_;
    const Vec<T, N> q0 = q, p0 = p;
    // W_i = (Q_i − q0)/h, started from the straight line W_i = c̃_i p0
    Vec<T, U> w = Vec<T, U>::Zero(ns * N);
    for (int i = 0; i < ns; ++i) w.template segment<N>(i * N) = c_[i] * p0;
    auto fj = [&](const Vec<T, U>& x, Vec<T, U>& F, Mat<T, U>& J, bool with_jacobian) {
      PerStage<Vec<T, N>> g = per_stage<Vec<T, N>>();
      PerStage<Mat<T, N>> Hs = per_stage<Mat<T, N>>();
      for (int k = 0; k < ns; ++k) {
        const Vec<T, N> Qk = q0 + h * x.template segment<N>(k * N);
        g[k] = force(Qk, h, k);
        if (with_jacobian)
          Hs[k] = ad::jacobian<N>([&](const auto& y) { return force(y, h, k); }, Qk);
      }
      for (int i = 0; i < ns; ++i) {
        Vec<T, N> Fi = x.template segment<N>(i * N) - c_[i] * p0;
        for (int k = 0; k < ns; ++k) Fi += h * M_[i][k] * g[k];
        F.template segment<N>(i * N) = Fi;
        if (with_jacobian)
          for (int k = 0; k < ns; ++k) {
            Mat<T, N> block = (h * h * M_[i][k]) * Hs[k];
            if (i == k) block += Mat<T, N>::Identity();
            J.template block<N, N>(i * N, k * N) = block;
          }
      }
    };
    NewtonOptions opt = options_;
    if constexpr (!std::is_same_v<T, double>)  // the stopping rule at T's round-off
      opt.step_rel = std::min(opt.step_rel, 4 * to_double(unit_roundoff<T>()));
    opt.step_abs = std::max(opt.step_abs,
                            4 * to_double(unit_roundoff<T>()) *
                                std::max(1.0, to_double(T(p0.template lpNorm<Eigen::Infinity>()))));
    const SolveReport rep = newton_solve<U, decltype(fj)&, T, SmallSystemSolve>(
        w, fj, opt, "partitioned Runge-Kutta stages");
    PerStage<Vec<T, N>> g = per_stage<Vec<T, N>>(), Pst = per_stage<Vec<T, N>>();
    T action(0);
    for (int k = 0; k < ns; ++k)
      g[k] = force(Vec<T, N>(q0 + h * w.template segment<N>(k * N)), h, k);
    if (rkn_) {  // q1 = q0 + h p0 − h² Σ b̄_i ∇U(Q_i), p1 = p0 − h Σ b_i ∇U(Q_i)
      Vec<T, N> dq = p0, dp = Vec<T, N>::Zero();
      for (int i = 0; i < ns; ++i) {
        dq -= h * rkn_bbar_[static_cast<std::size_t>(i)] * g[i];
        dp -= t_.b[static_cast<std::size_t>(i)] * g[i];
      }
      const Vec<T, N> q1 = q0 + h * dq, p1 = p0 + h * dp;
      if (!std::isfinite(to_double(T(q1.template lpNorm<Eigen::Infinity>()))) ||
          !std::isfinite(to_double(T(p1.template lpNorm<Eigen::Infinity>()))))
        throw SolveError("Runge-Kutta-Nystrom step: non-finite state", rep);
      q = q1;
      p = p1;
      action_ = T(std::numeric_limits<double>::quiet_NaN());
      return rep;
    }
    Vec<T, N> dq = Vec<T, N>::Zero(), dp = Vec<T, N>::Zero();
    for (int i = 0; i < ns; ++i) {
      Pst[i] = p0;
      for (int j = 0; j < ns; ++j) Pst[i] -= h * t_.ahat[i][j] * g[j];
      dq += t_.b[i] * Pst[i];
      dp -= t_.bhat[i] * g[i];
      const Vec<T, N> Qi = q0 + h * w.template segment<N>(i * N);
      T Ui;
      if constexpr (timed_problem)
        Ui = P_.template potential<T>(Qi, T(time_ + c_[i] * h));
      else
        Ui = P_.template potential<T>(Qi);
      action += t_.b[i] * (T(0.5) * Pst[i].squaredNorm() - Ui);
    }
    const Vec<T, N> q1 = q0 + h * dq, p1 = p0 + h * dp;
    if (!std::isfinite(to_double(T(q1.template lpNorm<Eigen::Infinity>()))) ||
        !std::isfinite(to_double(T(p1.template lpNorm<Eigen::Infinity>()))))
      throw SolveError("partitioned Runge-Kutta step: non-finite state", rep);
    q = q1;
    p = p1;
    action_ = h * action;
    return rep;
  }

  /// h Σ b_i (½|P_i|² − U(Q_i)) of the last step: its discrete Lagrangian L_d(q0, q1, h) when
  /// the tableau satisfies the symplecticity conditions (file comment).
  T action() const { return action_; }

 private:
  // ∇U at stage k's position Q (any scalar, for the Jacobian's AutoDiff), at its time when the
  // force depends on it.
  template <class V>
  auto force(const V& Q, const T& h, int k) const {
    if constexpr (timed_problem)
      return P_.gradient(Q, T(time_ + c_[static_cast<std::size_t>(k)] * h));
    else
      return P_.gradient(Q);
  }

  template <class X>
  PerStage<X> per_stage() const {
    if constexpr (fixed)
      return {};
    else
      return PerStage<X>(static_cast<std::size_t>(s_));
  }

  Problem P_;
  PrkTableauT<T> t_;
  NewtonOptions options_;
  int s_;                          ///< the number of stages (S when S is fixed)
  std::vector<std::vector<T>> M_;  ///< M_ij = Σ_k a_ik â_kj
  std::vector<T> c_;               ///< c̃_i = Σ_j a_ij
  T action_ = T(0);
  T time_ = T(0);            ///< the start time of the next step (set_time)
  bool rkn_ = false;         ///< an RKN tableau's method (its own constructor)
  std::vector<T> rkn_bbar_;  ///< its b̄
};

/// The method of the same tableau on any Hamiltonian H(q, p) (Hairer, Lubich and Wanner, §II.2.2,
/// (2.2)): with Z_i = (Q_i, P_i),
///
///     Q_i = q0 + h Σ_j a_ij ∂H/∂p(Z_j),   P_i = p0 − h Σ_j â_ij ∂H/∂q(Z_j),
///     q1  = q0 + h Σ_i b_i ∂H/∂p(Z_i),     p1  = p0 − h Σ_i b̂_i ∂H/∂q(Z_i).
///
/// For a non-separable H the stage momenta no longer drop out, so Newton's method runs on the
/// 2sN increments X_i = (Q_i − q0)/h, Y_i = (P_i − p0)/h together (started from
/// X_i = c_i ∂H/∂p(z0), Y_i = −ĉ_i ∂H/∂q(z0), the row sums of a and â), with the Jacobian from
/// the Hessian of H at each stage (AutoDiff on `Problem::gradient`). For H = ½|p|² + U it is
/// PartitionedRkMethod's step (the doctests hold the two to round-off). When the tableau is
/// symplectic the method is variational (HLW §VI.6.3), and its discrete Lagrangian is
/// L_d = h Σ_i b_i (P_i·Q̇_i − H(Z_i)) with Q̇_i = ∂H/∂p(Z_i), the Lagrangian L = p·q̇ − H at the
/// stages; `action()` returns it.
///
/// `Problem` has `N`, `template <class T> Vec<T, 2N> gradient(const Vec<T, 2N>& z)` (∇H at
/// z = (q, p): ∂H/∂q, then ∂H/∂p) and `template <class T> T hamiltonian(q, p)`. `step` has the
/// interface of the kernels (SolveError, q and p unchanged, when Newton fails or the result is
/// not finite). The stage system is sized at run time.
template <class Problem>
class HamiltonianPrkMethod {
 public:
  static constexpr int N = Problem::N;
  /// H depends on the time: `gradient(z, t)` and `hamiltonian(q, p, t)`.
  static constexpr bool timed_problem =
      requires(const Problem& P, const Vec<double, 2 * N>& z, double t) {
    P.gradient(z, t);
  };

  HamiltonianPrkMethod(Problem P, const PrkTableau& t, NewtonOptions options = {})
      : P_(std::move(P)), t_(t), options_(options), s_(t_.stages()) {
    const auto n = static_cast<std::size_t>(s_);
    if (s_ < 1 || t_.bhat.size() != n || t_.a.size() != n || t_.ahat.size() != n)
      throw std::invalid_argument("HamiltonianPrkMethod: a, ahat, b and bhat must have s stages");
    for (std::size_t i = 0; i < n; ++i)
      if (t_.a[i].size() != n || t_.ahat[i].size() != n)
        throw std::invalid_argument("HamiltonianPrkMethod: a and ahat must be s x s");
  }

  /// The start time t of the next step, for a time-dependent H: stage i at t + c_i h,
  /// c_i = Σ_j a_ij (as PartitionedRkMethod::set_time).
  void set_time(double t) requires timed_problem { time_ = t; }

  SolveReport step(Vec<double, N>& q, Vec<double, N>& p, double h) {
    const int ns = s_, half = ns * N;
    Vec<double, 2 * N> z0;
    z0 << q, p;
    std::vector<double> cs(static_cast<std::size_t>(ns));
    for (int i = 0; i < ns; ++i)
      for (int j = 0; j < ns; ++j) cs[static_cast<std::size_t>(i)] += t_.a[i][j];
    // ∇H at a stage (any scalar, for the Jacobian's AutoDiff), at its time when H depends on it
    auto grad = [&](const auto& z, int k) {
      if constexpr (timed_problem)
        return P_.gradient(z, time_ + cs[static_cast<std::size_t>(k)] * h);
      else
        return P_.gradient(z);
    };
    const Vec<double, 2 * N> g0 = [&] {
      if constexpr (timed_problem)
        return P_.gradient(z0, time_);
      else
        return P_.gradient(z0);
    }();
    Eigen::VectorXd x(2 * half);
    for (int i = 0; i < ns; ++i) {
      double c = 0, chat = 0;
      for (int j = 0; j < ns; ++j) {
        c += t_.a[i][j];
        chat += t_.ahat[i][j];
      }
      x.segment<N>(i * N) = c * g0.template tail<N>();
      x.segment<N>(half + i * N) = -chat * g0.template head<N>();
    }
    auto stage = [&](const Eigen::VectorXd& u, int k) {
      Vec<double, 2 * N> z;
      z << q + h * u.segment<N>(k * N), p + h * u.segment<N>(half + k * N);
      return z;
    };
    auto fj = [&](const Eigen::VectorXd& u, Eigen::VectorXd& F, Eigen::MatrixXd& J,
                  bool with_jacobian) {
      std::vector<Vec<double, 2 * N>> g(static_cast<std::size_t>(ns));
      std::vector<Mat<double, 2 * N>> H(static_cast<std::size_t>(ns));
      for (int k = 0; k < ns; ++k) {
        const auto kk = static_cast<std::size_t>(k);
        const Vec<double, 2 * N> z = stage(u, k);
        g[kk] = grad(z, k);
        if (with_jacobian)
          H[kk] = ad::jacobian<2 * N>([&](const auto& y) { return grad(y, k); }, z);
      }
      F = u;
      if (with_jacobian) J.setIdentity(2 * half, 2 * half);
      for (int i = 0; i < ns; ++i)
        for (int k = 0; k < ns; ++k) {
          const auto kk = static_cast<std::size_t>(k);
          const double a = t_.a[i][k], ah = t_.ahat[i][k];
          F.segment<N>(i * N) -= a * g[kk].template tail<N>();
          F.segment<N>(half + i * N) += ah * g[kk].template head<N>();
          if (!with_jacobian) continue;
          // rows of ∂H/∂q: [H_qq H_qp]; of ∂H/∂p: [H_pq H_pp]; a stage moves by h (X, Y)
          J.block<N, N>(i * N, k * N) -= (h * a) * H[kk].template block<N, N>(N, 0);
          J.block<N, N>(i * N, half + k * N) -= (h * a) * H[kk].template block<N, N>(N, N);
          J.block<N, N>(half + i * N, k * N) += (h * ah) * H[kk].template block<N, N>(0, 0);
          J.block<N, N>(half + i * N, half + k * N) += (h * ah) * H[kk].template block<N, N>(0, N);
        }
    };
    NewtonOptions opt = options_;
    opt.step_abs = std::max(opt.step_abs, 4 * std::numeric_limits<double>::epsilon() *
                                              std::max(1.0, g0.template lpNorm<Eigen::Infinity>()));
    const SolveReport rep =
        newton_solve<Eigen::Dynamic>(x, fj, opt, "partitioned Runge-Kutta stages (H(q, p))");
    Vec<double, N> dq = Vec<double, N>::Zero(), dp = Vec<double, N>::Zero();
    double action = 0;
    for (int i = 0; i < ns; ++i) {
      const Vec<double, 2 * N> z = stage(x, i);
      const Vec<double, 2 * N> g = grad(z, i);
      dq += t_.b[static_cast<std::size_t>(i)] * g.template tail<N>();
      dp -= t_.bhat[static_cast<std::size_t>(i)] * g.template head<N>();
      const Vec<double, N> Qi = z.template head<N>(), Pi = z.template tail<N>();
      double Hi;
      if constexpr (timed_problem)
        Hi = P_.template hamiltonian<double>(Qi, Pi, time_ + cs[static_cast<std::size_t>(i)] * h);
      else
        Hi = P_.template hamiltonian<double>(Qi, Pi);
      action += t_.b[static_cast<std::size_t>(i)] * (Pi.dot(g.template tail<N>()) - Hi);
    }
    const Vec<double, N> q1 = q + h * dq, p1 = p + h * dp;
    if (!q1.allFinite() || !p1.allFinite() || !std::isfinite(action))
      throw SolveError("partitioned Runge-Kutta step (H(q, p)): non-finite state", rep);
    q = q1;
    p = p1;
    action_ = h * action;
    return rep;
  }

  /// h Σ b_i (P_i·∂H/∂p(Z_i) − H(Z_i)) of the last step: its discrete Lagrangian when the
  /// tableau is symplectic (see above).
  double action() const { return action_; }

 private:
  Problem P_;
  PrkTableau t_;
  NewtonOptions options_;
  int s_;
  double action_ = 0;
  double time_ = 0;  ///< the start time of the next step (set_time)
};

}  // namespace vibook
