/// \file avi.hpp
/// \brief Adaptive variational integrators with monitor functions (Schmitt & Leok), as
/// compared in Sharma et al. 2022 §3.1, (19)–(23), (26)–(27): the implicit midpoint rule with
/// a fixed step Δa on the Poincaré-transformed Hamiltonian ḡ(q)(H(q, p) + p^t), for a
/// mechanical H = ½|p|² + V(q).
///
/// Chapter: \ref chapter-avi.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <boost/math/tools/toms748_solve.hpp>

#include "vibook/core/autodiff.hpp"
#include "vibook/core/errors.hpp"
#include "vibook/core/extrapolate.hpp"
#include "vibook/core/format.hpp"
#include "vibook/core/newton.hpp"
#include "vibook/core/types.hpp"
#include "vibook/problems/problems.hpp"

namespace vibook {

// Sharma et al. 2022, (26): arclength monitor g1(q) = (2(H0 − V(q)) + ∇Vᵀ∇V)^{−1/2} (M = I).
/// Monitor g1 of AVI1; H0 is the energy of the initial state.
struct MonitorArclength {
  double H0 = 0;
  template <class Problem, class S>
  S operator()(const Problem& P, const Vec<S, Problem::N>& q) const {
    return (*this)(P, q, Vec<S, Problem::N>(P.gradient(q)));
  }
  /// g1 at q given ∇V(q) (a step that has the gradient already passes it).
  template <class Problem, class S>
  S operator()(const Problem& P, const Vec<S, Problem::N>& q,
               const Vec<S, Problem::N>& grad_V) const {
    using std::sqrt;
    return S(1.0 / sqrt(2.0 * (H0 - P.potential(q)) + grad_V.squaredNorm()));
  }
  /// ∇g1 = g1³ (∇V − ∇²V ∇V), written out (the Newton matrix of AdaptiveMidpoint::step).
  template <class Problem>
  Vec<double, Problem::N> gradient(const Problem& P, const Vec<double, Problem::N>& q) const {
    const Vec<double, Problem::N> g = P.gradient(q);
    const double m = (*this)(P, q, g);
    return (g - ad::potential_hessian(P, q) * g) * (m * m * m);
  }
};

// Sharma et al. 2022, (27): g2(q) = qᵀq, motivated by Kepler's second law.
/// Monitor g2 of AVI2.
struct MonitorQuadratic {
  template <class Problem, class S>
  S operator()(const Problem&, const Vec<S, Problem::N>& q) const {
    return S(q.squaredNorm());
  }
  /// ∇g2 = 2q.
  template <class Problem>
  Vec<double, Problem::N> gradient(const Problem&, const Vec<double, Problem::N>& q) const {
    return q * 2.0;
  }
};

/// State of an adaptive integrator: time, position, momentum.
template <int N>
struct TimedState {
  double t = 0;
  Vec<double, N> q = Vec<double, N>::Zero();
  Vec<double, N> p = Vec<double, N>::Zero();
};

/// The monitor's gradient at q: the monitor's own `gradient(P, q)` when it has one, else one
/// level of forward AutoDiff through its templated operator().
template <class Problem, class Monitor, int N>
Vec<double, N> monitor_gradient(const Monitor& g, const Problem& P, const Vec<double, N>& q) {
  if constexpr (requires { g.gradient(P, q); })
    return g.gradient(P, q);
  else
    return g(P, ad::variables<N>(q)).derivatives();
}

/// AVI: one step of (21)–(23) with step Δa in the fictitious time a,
///   q1 − q0 = Δa g(q̄) p̄,   p1 − p0 = −Δa g(q̄) ∇V(q̄),   t1 − t0 = Δa g(q̄),
/// with q̄, p̄ the averages. Every step reports residual and iterations; a failure throws
/// SolveError.
///
/// **The step, reduced to the midpoint.** With c = Δa g(q̄), the second equation gives
/// p̄ = p0 − (c/2)∇V(q̄) explicitly, and the first becomes N equations for q̄ alone,
///   F(q̄) = 2(q̄ − q0) − c p0 + (c²/2) ∇V(q̄) = 0,
/// after which q1 = 2q̄ − q0, p1 = p0 − c∇V(q̄), t1 = t0 + c: the same step as the 2N-system
/// (`step_full_system`, the reference; a doctest compares the two), with F the residual of the
/// first equation and the second satisfied to rounding by construction. Newton on F uses
///   F'(q̄) = 2I − Δa (p0 − c∇V) ∇gᵀ + (c²/2) ∇²V,
/// with the monitor's gradient and the problem's Hessian (the helpers above). The matrix is
/// kept from step to step, and evaluated again after a step that needed more than one
/// correction or when an update fails to shrink eightfold. The step starts from the polynomial
/// through the last eight midpoints (core/extrapolate.hpp: Δa is fixed, so the midpoints are
/// equally spaced in a and smooth) when the state passed in is the one the last step returned
/// with the same Δa; otherwise, and again after a failure from that start, from the explicit
/// Euler midpoint q0 + (Δa g(q0)/2) p0 with a fresh matrix. The point returned is
/// the last one evaluated, accepted when the Newton correction it still asks for is below
/// NewtonOptions' rule, so q1, p1, t1 and the residual reported all belong to one q̄.
///
/// **The next step's first evaluation is taken early.** An evaluation (∇V and c at a
/// midpoint) is paired with the one at the midpoint the next step will start from should
/// this one be accepted (the extrapolation with it appended, SampleHistory::next_after). The
/// two are independent, so an out-of-order processor computes them side by side instead of
/// one after the other; a step that continues the trajectory then begins with its first
/// evaluation done. It is the evaluation the next step would make itself, to the last bit:
/// the trajectory, the residuals and the iteration counts are those of evaluating in turn.
/// A pair whose midpoint is not accepted is dropped. ∇V and the monitor are thus evaluated at
/// points a step may never start from; like every problem and monitor here, they must be
/// free of side effects.
template <class Problem, class Monitor>
class AdaptiveMidpoint {
 public:
  static constexpr int N = Problem::N;
  static constexpr int M = 2 * N;
  using VecN = Vec<double, N>;
  using MatN = Mat<double, N>;

  AdaptiveMidpoint(Problem P, Monitor g, NewtonOptions options = {})
      : P_(P), g_(g), options_(options) {}

  /// The physical step Δt = Δa g(q̄) that one step of size Δa takes from s (solves the step).
  double physical_step(TimedState<N> s, double da) {
    const double t0 = s.t;
    step(s, da);
    return s.t - t0;
  }

  /// Δa such that the first step from s has physical length h0 exactly (root of
  /// Δa ↦ physical_step(s, Δa) − h0, bracketed around h0/g(q0), solved by TOMS 748).
  double step_for_first_step(const TimedState<N>& s, double h0) {
    const double guess = h0 / g_(P_, s.q);
    auto f = [&](double da) { return physical_step(s, da) - h0; };
    double lo = 0.5 * guess, hi = 2.0 * guess;
    const std::uintmax_t max_it = 100;
    std::uintmax_t it = max_it;
    std::pair<double, double> r;
    try {
      r = boost::math::tools::toms748_solve(f, lo, hi,
                                            boost::math::tools::eps_tolerance<double>(52), it);
    } catch (const NumericalError&) {
      throw;
    } catch (const std::exception& e) {
      // Boost reports an unbracketed or non-finite function with its own exception types.
      throw SolveError("adaptive midpoint start: no step size Δa in [" + text::g(lo, 3) + ", " +
                           text::g(hi, 3) + "] gives a first step of physical length h0 = " +
                           text::g(h0, 3) + " (" + e.what() + ")",
                       SolveReport{std::numeric_limits<double>::quiet_NaN(), int(it), false});
    }
    if (it >= max_it || !std::isfinite(r.first) || !std::isfinite(r.second))
      throw SolveError("adaptive midpoint start: the step size for h0 = " + text::g(h0, 3) +
                           " did not converge in " + std::to_string(max_it) + " iterations",
                       SolveReport{std::numeric_limits<double>::quiet_NaN(), int(it), false});
    return 0.5 * (r.first + r.second);
  }

  /// One step of (21)–(23) from s, solved for the midpoint q̄ (see the class).
  SolveReport step(TimedState<N>& s, double da) {
    const bool continues = mid_.count() > 0 && da == last_da_ && s.q == last_q_ && s.p == last_p_;
    if (!continues) mid_.clear(), have_jacobian_ = false, have_next_ = false;
    const TimedState<N> start = s;
    try {
      if (have_next_) return solve(s, da, next_, true);
      return solve(s, da, {continues ? extrapolated_midpoint(s.q) : cold_midpoint(s, da)}, false);
    } catch (const SolveError&) {
      if (!continues) throw;
    }
    // From the extrapolation and the kept Newton matrix the iteration failed: once more from
    // the explicit Euler midpoint with a fresh matrix, as without a history.
    s = start;
    mid_.clear(), have_jacobian_ = false;
    return solve(s, da, {cold_midpoint(s, da)}, false);
  }

  /// The same step by simplified Newton on the full 2N-system (21)–(22) in z = (q1, p1) from
  /// an explicit Euler guess, with the AutoDiff Jacobian: the reference `step` is checked
  /// against. Does not touch the history `step` extrapolates from.
  SolveReport step_full_system(TimedState<N>& s, double da) const {
    Vec<double, M> z0, z1;
    z0 << s.q, s.p;
    const double g0 = g_(P_, s.q);
    z1 << s.q + da * g0 * s.p, s.p - da * g0 * P_.gradient(s.q);  // explicit Euler guess
    auto residual = [&](const auto& z) {
      using S = typename std::remove_cvref_t<decltype(z)>::Scalar;
      const Vec<S, N> q1 = z.template head<N>(), p1 = z.template tail<N>();
      const Vec<S, N> qa = (q1 + s.q.template cast<S>()) * 0.5,
                      pa = (p1 + s.p.template cast<S>()) * 0.5;
      const S g = g_(P_, qa);
      Vec<S, M> F;
      F.template head<N>() = q1 - s.q.template cast<S>() - (da * g) * pa;
      F.template tail<N>() = p1 - s.p.template cast<S>() + (da * g) * P_.gradient(qa);
      return F;
    };
    const SolveReport rep = simplified_newton_solve<M>(
        z1, [&](const Vec<double, M>& z) { return Vec<double, M>(residual(z)); },
        [&](const Vec<double, M>& z) { return ad::jacobian<M>(residual, z); }, options_,
        "adaptive midpoint step (21)-(22)", &z0);
    const Vec<double, N> qa = (z1.template head<N>() + s.q) * 0.5;
    s.t += da * g_(P_, qa);  // (23)
    s.q = z1.template head<N>();
    s.p = z1.template tail<N>();
    return rep;
  }

 private:
  /// ∇V and c = Δa g at a midpoint m: what an iteration evaluates.
  struct Evaluation {
    VecN m = VecN::Zero(), G = VecN::Zero();
    double c = 0;
  };

  Evaluation evaluate(const VecN& m, double da) const {
    Evaluation e{m, P_.gradient(m), 0.0};
    e.c = da * monitor_at(m, e.G);
    return e;
  }

  /// Newton on F(q̄) = 0 from e.m (with ∇V and c there already in e when `evaluated`), then
  /// (21)–(23) at the accepted midpoint. Everything it calls is inlined into it (`flatten`,
  /// as for the closed-form EpAVI step: epavi/mechanical.hpp).
  [[gnu::flatten]] SolveReport solve(TimedState<N>& s, double da, Evaluation e, bool evaluated) {
    have_next_ = false;
    SolveReport rep;
    Evaluation next;  // at the next step's start, should e.m be accepted
    VecN F;
    double last = 0;
    bool fresh = false;  // whether Jinv_ was evaluated in this step
    const int max_it = options_.max_iterations;
    for (rep.iterations = 1; rep.iterations <= max_it; ++rep.iterations) {
      // [avi-step]
      if (rep.iterations > 1 || !evaluated) {
        e = evaluate(e.m, da);
        next = evaluate(next_start(s.q, e.m), da);  // independent of e: computed alongside
      }
      // Sharma et al. 2022, (21)–(22) with p̄ eliminated: F(q̄) = 2(q̄ − q0) − c p0 + (c²/2)∇V(q̄).
      const VecN& m = e.m;
      const VecN& G = e.G;
      const double c = e.c;
      F = (m - s.q) * 2.0 - (s.p - G * (0.5 * c)) * c;
      // [avi-step]
      rep.residual = F.template lpNorm<Eigen::Infinity>();
      if (!std::isfinite(rep.residual) || !std::isfinite(c)) break;
      if (!have_jacobian_) Jinv_ = inverse_jacobian(s, da, m, G, c), have_jacobian_ = fresh = true;
      VecN dx = Jinv_ * F;
      double size = dx.template lpNorm<Eigen::Infinity>();
      if (!std::isfinite(size))
        throw newton_detail::singular_jacobian("adaptive midpoint step (21)-(22)", rep);
      if (rep.iterations > 1 && size > last * 0.125 && !fresh) {  // slow: a fresh matrix
        Jinv_ = inverse_jacobian(s, da, m, G, c), fresh = true;
        dx = Jinv_ * F;
        size = dx.template lpNorm<Eigen::Infinity>();
      }
      // NewtonOptions' rule, applied to q1 = 2q̄ − q0, whose correction is twice dx.
      if (rep.residual <= options_.residual_abs ||
          newton_detail::update_is_small<N>(VecN(m * 2.0 - s.q), dx, s.q, options_.step_rel,
                                            options_.step_abs, 2.0)) {
        rep.converged = true;
        break;
      }
      last = size;
      e.m -= dx;
    }
    if (!rep.converged) {
      have_jacobian_ = false;
      throw newton_detail::no_convergence("adaptive midpoint step (21)-(22)", rep, max_it);
    }
    // A step that needed more than one correction asks for a fresh matrix in the next one.
    if (rep.iterations > 2) have_jacobian_ = false;
    // The pair taken with the accepted midpoint (none when it was accepted as it came in).
    if (rep.iterations > 1 || !evaluated) next_ = next, have_next_ = true;
    mid_.push(e.m);
    s.q = e.m * 2.0 - s.q;
    s.p = s.p - e.G * e.c;
    s.t += e.c;
    last_q_ = s.q, last_p_ = s.p, last_da_ = da;
    return rep;
  }

  /// The monitor at q with ∇V(q) = G: passed on when the monitor takes it (g1 needs ∇V).
  double monitor_at(const VecN& q, const VecN& G) const {
    if constexpr (requires { g_(P_, q, G); })
      return g_(P_, q, G);
    else
      return g_(P_, q);
  }

  /// F'(q̄)⁻¹ (see the class), with ∇g from the monitor and ∇²V from the problem.
  MatN inverse_jacobian(const TimedState<N>& s, double da, const VecN& m, const VecN& G,
                        double c) const {
    const VecN dg = monitor_gradient(g_, P_, m);
    const MatN J = MatN::Identity() * 2.0 - (s.p - G * c) * (da * dg).transpose() +
                   ad::potential_hessian(P_, m) * (0.5 * c * c);
    return J.inverse();
  }

  /// The explicit Euler midpoint q0 + (Δa g(q0)/2) p0: the start without a history.
  VecN cold_midpoint(const TimedState<N>& s, double da) const {
    return s.q + s.p * (0.5 * da * g_(P_, s.q));
  }

  /// The next midpoint extrapolated from the last ones: with one, linearly through q0 (which
  /// lies half a step after it); with n >= 2, the polynomial through the last n (up to 8).
  VecN extrapolated_midpoint(const VecN& q0) const {
    return mid_.count() == 1 ? VecN(q0 * 2.0 - mid_.newest()) : mid_.next();
  }

  /// What extrapolated_midpoint will return in the next step if this step, from q0, accepts
  /// the midpoint m (and so returns q1 = 2m − q0): the same arithmetic, to the last bit.
  VecN next_start(const VecN& q0, const VecN& m) const {
    if (mid_.count() == 0) {
      const VecN q1 = m * 2.0 - q0;
      return q1 * 2.0 - m;
    }
    return mid_.next_after(m);
  }

  Problem P_;
  Monitor g_;
  NewtonOptions options_;
  SampleHistory<VecN, double, 8> mid_;  ///< the last midpoints of the current trajectory
  VecN last_q_ = VecN::Zero(), last_p_ = VecN::Zero();
  double last_da_ = 0;
  MatN Jinv_ = MatN::Identity();  ///< F'⁻¹, kept from step to step while it contracts
  bool have_jacobian_ = false;
  Evaluation next_;  ///< the evaluation at the next step's start (see the class)
  bool have_next_ = false;
};

}  // namespace vibook
