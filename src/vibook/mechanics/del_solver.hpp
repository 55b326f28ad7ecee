/// \file del_solver.hpp
/// \brief The generic variational integrator: any discrete Lagrangian in, a symplectic
/// one-step map (q_k, p_k) -> (q_{k+1}, p_{k+1}) out. Vermeeren 2017 §2, (4)–(5), in the
/// scaling L_d ≈ h·L (see discrete_lagrangian.hpp).
///
/// Chapter: \ref chapter-vi.
#pragma once

#include <concepts>

#include "vibook/core/autodiff.hpp"
#include "vibook/core/errors.hpp"
#include "vibook/core/newton.hpp"
#include "vibook/core/types.hpp"

namespace vibook {

/// Position–momentum form of the discrete Euler–Lagrange equations,
///   p_k     = −D1 L_d(q_k, q_{k+1}, h)   (solved for q_{k+1} by Newton's method),
///   p_{k+1} =  D2 L_d(q_k, q_{k+1}, h),
/// with every derivative, including the Newton Jacobian D2 D1 L_d, taken by Eigen AutoDiff
/// from the one callable `L_d(q0, q1, h)`. No derivative is written by hand. A discrete
/// Lagrangian compiled to a tape (verify/tape.hpp) brings D1, D2 and D2 D1 itself
/// (`newton_parts`, `d2`) and is stepped through them, with the same guess and Newton.
///
/// Each step reports the residual |p_k + D1 L_d|_inf at the returned q_{k+1} and the number
/// of Newton iterations; a step that does not converge throws SolveError. A compiled L_d whose
/// D2 D1 L_d does not depend on q_{k+1} (`jacobian_constant()`) is solved by
/// affine_newton_solve: the same iterates, one factorisation a step, and the residual reported
/// at the last evaluation, before Newton's last (negligible) update.
///
/// The Newton guess: the previous increment, q_k + (q_k − q_{k−1}), when the q passed in is
/// the one the previous step returned; otherwise q_k + h p_k. The latter is right to O(h²)
/// only for the kinetic energy ½|v|² (unit mass): for a mass matrix M it is off by
/// h (M⁻¹ − I) p_k, and Newton starts from there (a poor start for a heavy or light mass
/// shows as more iterations in the SolveReport, or a SolveError). A state changed by hand, or
/// one moved between integrators, is detected by comparing q with the last one returned, so
/// reset() is needed only to force the q + h p guess.
template <int N, class DiscreteLagrangian>
class DelIntegrator {
 public:
  static constexpr int dim = N;

  explicit DelIntegrator(DiscreteLagrangian Ld, NewtonOptions options = {})
      : Ld_(std::move(Ld)), options_(options) {}

  /// Advance (q, p) by one step of size h. Throws SolveError if Newton fails or the new
  /// momentum is not finite (q and p are then left as they were).
  SolveReport step(Vec<double, N>& q, Vec<double, N>& p, double h) {
    if (have_increment_ && q != last_q_) have_increment_ = false;  // not our last state
    Vec<double, N> q1 =
        have_increment_ ? Vec<double, N>(q + increment_) : Vec<double, N>(q + h * p);
    const Vec<double, N> q0 = q;
    const Vec<double, N> p0 = p;
    auto fj = [&](const Vec<double, N>& x, Vec<double, N>& F, Mat<double, N>& J,
                  bool with_jacobian) {
      if constexpr (compiled) {
        Ld_.newton_parts(q0, x, h, F, J, with_jacobian);
        F += p0;
      } else {
        const auto d = ad::two_point<N>(Ld_, q0, x, h);
        F = p0 + d.D1;
        J = d.D12;
      }
    };
    static constexpr const char* what = "discrete Euler-Lagrange step";
    SolveReport rep;
    if constexpr (compiled) {
      // D2 D1 L_d free of q_(k+1) (the tape computes it once a step): the equation is affine
      // in q_(k+1), and Newton's iterates need one factorisation and two evaluations.
      // Its systems are small and its steps cheap: J dx = F by SmallSystemSolve.
      using Linear = SmallSystemSolve;
      rep = Ld_.jacobian_constant()
                ? affine_newton_solve<N, decltype(fj)&, double, Linear>(q1, fj, options_, what, &q0)
                : newton_solve<N, decltype(fj)&, double, Linear>(q1, fj, options_, what, &q0);
    } else {
      rep = newton_solve<N>(q1, fj, options_, what, &q0);
    }
    // The momentum at the new point: Newton's residual does not see every part of L_d (on
    // the tape, D1 L_d of the trapezoidal rule has no V(q1)), so a q1 outside the domain of
    // L_d shows here first; it is an error of the step, not a NaN handed on.
    const Vec<double, N> p1 = momentum_plus(q0, q1, h);
    if (!p1.allFinite())
      throw SolveError(
          "discrete Euler-Lagrange step: the new momentum D2 L_d(q_k, q_(k+1), h) is not "
          "finite (q_(k+1) outside the domain of the discrete Lagrangian?)",
          rep);
    p = p1;
    increment_ = q1 - q0;
    have_increment_ = true;
    q = q1;
    last_q_ = q1;
    return rep;
  }

  /// Forget the previous increment: the next guess is q + h p. (A state that is not the last
  /// one returned is detected without it.)
  void reset() { have_increment_ = false; }

  /// Discrete Legendre map p_k = −D1 L_d(q_k, q_{k+1}, h)   (Vermeeren (5), first half).
  Vec<double, N> momentum_minus(const Vec<double, N>& q0, const Vec<double, N>& q1,
                                double h) const {
    if constexpr (compiled) {
      Vec<double, N> D1;
      Mat<double, N> D12;
      Ld_.newton_parts(q0, q1, h, D1, D12, false);
      return -D1;
    } else {
      return -ad::gradient<N>([&](const auto& x) { return Ld_(x, lift(q1, x), lift(h, x)); }, q0);
    }
  }

  /// Discrete Legendre map p_{k+1} = D2 L_d(q_k, q_{k+1}, h)   (Vermeeren (5), second half).
  Vec<double, N> momentum_plus(const Vec<double, N>& q0, const Vec<double, N>& q1, double h) const {
    if constexpr (compiled) {
      return Ld_.d2(q0, q1, h);
    } else {
      return ad::gradient<N>([&](const auto& x) { return Ld_(lift(q0, x), x, lift(h, x)); }, q1);
    }
  }

  /// Left-hand side of the two-step discrete Euler–Lagrange equation, Vermeeren (4):
  /// D2 L_d(q_{k−1}, q_k, h) + D1 L_d(q_k, q_{k+1}, h).
  Vec<double, N> del_residual(const Vec<double, N>& qm, const Vec<double, N>& q,
                              const Vec<double, N>& qp, double h) const {
    return momentum_plus(qm, q, h) - momentum_minus(q, qp, h);
  }

  const DiscreteLagrangian& lagrangian() const { return Ld_; }

 private:
  // A discrete Lagrangian that brings its own compiled derivatives (verify/tape.hpp:
  // CompiledDiscreteLagrangian) is used through them; any other callable through AutoDiff.
  static constexpr bool compiled = requires(const DiscreteLagrangian& L, const Vec<double, N>& q,
                                            double h, Vec<double, N>& g, Mat<double, N>& J) {
    L.newton_parts(q, q, h, g, J, true);
    { L.d2(q, q, h) } -> std::convertible_to<Vec<double, N>>;
    { L.jacobian_constant() } -> std::convertible_to<bool>;
  };

  // Constant of the AutoDiff vector type of `like`, with zero derivatives.
  template <class Like>
  static auto lift(const Vec<double, N>& v, const Like&) {
    using S = typename Like::Scalar;
    return v.template cast<S>().eval();
  }
  template <class Like>
  static auto lift(double v, const Like&) {
    using S = typename Like::Scalar;
    return S(v);
  }

  DiscreteLagrangian Ld_;
  NewtonOptions options_;
  Vec<double, N> increment_ = Vec<double, N>::Zero();
  Vec<double, N> last_q_ = Vec<double, N>::Zero();
  bool have_increment_ = false;
};

/// Deduction helper: make_del_integrator<N>(L_d).
template <int N, class DiscreteLagrangian>
DelIntegrator<N, DiscreteLagrangian> make_del_integrator(DiscreteLagrangian Ld,
                                                         NewtonOptions options = {}) {
  return DelIntegrator<N, DiscreteLagrangian>(std::move(Ld), options);
}

}  // namespace vibook
