/// \file avi.hpp
/// \brief Adaptive variational integrators with monitor functions (Schmitt & Leok), as
/// compared in Sharma et al. 2022 §3.1, (19)–(23), (26)–(27): the implicit midpoint rule with
/// a fixed step Δa on the Poincaré-transformed Hamiltonian ḡ(q)(H(q, p) + p^t), for a
/// mechanical H = ½|p|² + V(q).
///
/// Chapter: \ref chapter-avi.
#pragma once

#include <cmath>
#include <limits>
#include <utility>

#include <boost/math/tools/toms748_solve.hpp>

#include "vibook/core/autodiff.hpp"
#include "vibook/core/errors.hpp"
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
    using std::sqrt;
    const Vec<S, Problem::N> g = P.gradient(q);
    return S(1.0 / sqrt(2.0 * (H0 - P.potential(q)) + g.squaredNorm()));
  }
};

// Sharma et al. 2022, (27): g2(q) = qᵀq, motivated by Kepler's second law.
/// Monitor g2 of AVI2.
struct MonitorQuadratic {
  template <class Problem, class S>
  S operator()(const Problem&, const Vec<S, Problem::N>& q) const {
    return S(q.squaredNorm());
  }
};

/// State of an adaptive integrator: time, position, momentum.
template <int N>
struct TimedState {
  double t = 0;
  Vec<double, N> q = Vec<double, N>::Zero();
  Vec<double, N> p = Vec<double, N>::Zero();
};

/// AVI: one step of (21)–(23) with step Δa in the fictitious time a,
///   q1 − q0 = Δa g(q̄) p̄,   p1 − p0 = −Δa g(q̄) ∇V(q̄),   t1 − t0 = Δa g(q̄),
/// with q̄, p̄ the averages. (q1, p1) by simplified Newton (the Jacobian by AutoDiff, once per
/// step); every step reports residual and iterations, a failure throws SolveError.
template <class Problem, class Monitor>
class AdaptiveMidpoint {
 public:
  static constexpr int N = Problem::N;
  static constexpr int M = 2 * N;

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

  SolveReport step(TimedState<N>& s, double da) {
    Vec<double, M> z0, z1;
    z0 << s.q, s.p;
    const double g0 = g_(P_, s.q);
    z1 << s.q + da * g0 * s.p, s.p - da * g0 * P_.gradient(s.q);  // explicit Euler guess
    // [avi-step]
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
    // [avi-step]
    // Simplified Newton: the AutoDiff Jacobian once per step (it changes by O(Δa) over it).
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
  Problem P_;
  Monitor g_;
  NewtonOptions options_;
};

}  // namespace vibook
