/// \file extended.hpp
/// \brief Extended (time-as-variable) discrete mechanics, Sharma et al. 2022 §2.2, (9)–(18):
/// an extended discrete Lagrangian L_d(t0, q0, t1, q1) in, a variational integrator with
/// adaptive time steps out. Discrete momentum p_k and discrete energy E_k, the two-step
/// equations (11)–(12) and the time-marching form (15)–(18), all from the one callable by
/// Eigen AutoDiff.
///
/// **Sign of the discrete energy.** vibook uses E_k = −D3 L_d(t_{k−1}, q_{k−1}, t_k, q_k),
/// as in (18); this is what (12) and (16) need, and it equals the energy H for
/// L_d = (t1 − t0) L. The paper's (14) prints it without the minus (erratum S-ERR-14).
///
/// Chapter: \ref chapter-extended.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "vibook/core/autodiff.hpp"
#include "vibook/core/errors.hpp"
#include "vibook/core/format.hpp"
#include "vibook/core/newton.hpp"
#include "vibook/core/root.hpp"
#include "vibook/core/types.hpp"
#include "vibook/mechanics/discrete_lagrangian.hpp"

namespace vibook {

/// State of the time-marching form: (t_k, q_k, p_k, E_k), in the scalar type T.
template <int N, class T = double>
struct ExtendedState {
  T t = T(0);
  Vec<T, N> q = Vec<T, N>::Zero();
  Vec<T, N> p = Vec<T, N>::Zero();
  T E = T(0);
};

/// Which discrete energy a step solves the energy equation (16) for.
enum class EnergyTarget {
  previous,  ///< E_k = −D3 L_d of the previous step, as in (16)–(18): the telescoping of (28)
  initial,   ///< always E_1, the energy fixed by the start-up step
};

// [extended-midpoint-dl]
// Sharma et al. 2022, (25): the midpoint extended discrete Lagrangian.
/// L_d(t0, q0, t1, q1) = (t1 − t0) · L((q0 + q1)/2, (q1 − q0)/(t1 − t0)) for any continuous
/// Lagrangian L(q, v) generic in its scalar (autonomous here; the time arguments enter only
/// through the step t1 − t0).
template <class Lagrangian>
auto extended_midpoint_dl(Lagrangian L) {
  return [L = std::move(L)](const auto& t0, const auto& q0, const auto& t1,
                            const auto& q1) -> scalar_t<decltype(t0)> {
    using S = scalar_t<decltype(t0)>;
    const S dt = t1 - t0;
    const auto qm = ((q0 + q1) * constant<S>(0.5)).eval();
    const auto v = ((q1 - q0) / dt).eval();
    return S(dt * L(qm, v));
  };
}
// [extended-midpoint-dl]

/// Report of one extended step: the energy-equation residual |D1 L_d − E_k| at the returned
/// point, the momentum-equation residual, and the iteration counts of both solves.
struct ExtendedStepReport {
  double energy_residual = 0;    ///< |D1 L_d(k, k+1) − E_k|
  double momentum_residual = 0;  ///< |p_k + D2 L_d(k, k+1)|_inf
  int root_iterations = 0;       ///< evaluations of the energy equation (bracketing + TOMS 748)
  int newton_iterations = 0;     ///< Newton iterations of the momentum equations, in total
};

/// The time-marching form (15)–(18) of Sharma et al. 2022, §2.2, of the extended discrete
/// Euler–Lagrange equations for any
/// extended discrete Lagrangian `L_d(t0, q0, t1, q1)` (t scalar, q an N-vector, generic in the
/// scalar type): each step solves
///   −D2 L_d(t_k, q_k, t_{k+1}, q_{k+1}) = p_k,   D1 L_d(t_k, q_k, t_{k+1}, q_{k+1}) = E_k
///   (15)–(16)
/// for (t_{k+1}, q_{k+1}), then sets p_{k+1} = D4 L_d and E_{k+1} = −D3 L_d (17)–(18).
///
/// **How Sharma et al.'s (15)–(16) are solved.** Not as one coupled Newton system: the energy
/// equation fixes Δt = t_{k+1} − t_k through an effect of order Δt², so the coupled Jacobian is
/// nearly singular and Newton from the previous step diverges (we measured this). Instead, for each
/// trial Δt the momentum equations (15) are solved for q_{k+1}(Δt) by Newton (well
/// conditioned), and the scalar energy equation g(Δt) = D1 L_d − E_k = 0 is solved by a
/// bracketed root finder (Anderson–Björck with bisection safeguard, core/root.hpp). The bracket is
/// grown geometrically (ratio first_ratio, squared each time, up to max_ratio) around the step
/// predicted from the last two, Δt_{k−1}²/Δt_{k−2} (the ratio of successive steps changes
/// slowly), which keeps to the root that continues the motion. If no sign change is found there,
/// no admissible step exists near the previous one, and the step throws SolveError saying so.
///
/// **Scalar type.** Everything is computed in T (double, long double, dd_real, quad,
/// mpfr_real; see precision.hpp); the reports are in double.
///
/// **Tolerance.** Options::tol is a tolerance on the *equations*, relative: the energy equation
/// stops when |D1 L_d − E_k| <= tol·|E_k|, the momentum equations when |p_k + D2 L_d|_inf <=
/// tol·|p_k|_inf. Both also stop when the unknowns no longer move by more than 4 units of T's
/// round-off, which is what the default tol (4 units of round-off) amounts to. A loose tol
/// leaves a residual of that size in every step (Sharma et al.'s Fig. 5 study).
template <int N, class ExtendedDiscreteLagrangian, class T = double>
class ExtendedDelIntegrator {
 public:
  static constexpr int M = N + 1;  ///< extended configuration (t, q)

  using State = ExtendedState<N, T>;
  using VecN = Vec<T, N>;

  struct Options {
    double tol = 0;  ///< relative tolerance of both solves; 0 = 4 units of T's round-off
    EnergyTarget energy_target = EnergyTarget::previous;
    int max_newton_iterations = 50;
    double max_ratio = 64.0;  ///< how far the bracket may grow from the previous step
    double first_ratio =
        1.0 + 1.0 / 1024;  ///< the first bracket [Δt/r, Δt·r]; r is squared until max_ratio
    int max_root_iterations = 0;  ///< 0: 40 + 4 × (bits of T), enough to bisect to round-off
    /// L_d depends on the times only through t1 − t0 (time-translation invariant, e.g. (25)
    /// for an autonomous L): evaluate it at (0, q_k, Δt, q_{k+1}), so that Δt is not quantized
    /// to ulp(t_k), and accumulate t_k with Kahan's compensated summation. Without this, the
    /// resolution of Δt — and with it the energy residual — degrades in proportion to t.
    bool time_translation_invariant = false;
    int max_secant_iterations = 12;
  };

  explicit ExtendedDelIntegrator(ExtendedDiscreteLagrangian Ld, Options options = {})
      : extended_{std::move(Ld)}, options_(options) {
    const double u = to_double(unit_roundoff<T>());
    if (options_.tol == 0) options_.tol = 4 * u;
    if (!(options_.tol >= u && options_.tol < 1e-2))
      throw ArgumentError("--tol", "must lie in [" + text::g(u, 3) +
                                       ", 1e-2) (the round-off of the chosen precision up to "
                                       "1e-2), got " +
                                       text::g(options_.tol, 3));
    newton_.step_rel = 4 * u;
    newton_.max_iterations = options_.max_newton_iterations;
    if (options_.max_root_iterations == 0)
      options_.max_root_iterations = 40 + 4 * int(std::ceil(-std::log2(u)));
  }

  const Options& options() const { return options_; }

  /// The state after a first step from (t0, q0) to (t1, q1) (e.g. taken from an exact
  /// solution): p1 = D4 L_d, E1 = −D3 L_d (17)–(18).
  State start(const T& t0, const VecN& q0, const T& t1, const VecN& q1) {
    const T dt0 = t1 - t0;
    const auto d = options_.time_translation_invariant ? derivatives(T(0), q0, dt0, q1)
                                                       : derivatives(t0, q0, t1, q1);
    t_compensation_ = T(0);
    State s;
    s.t = t1;
    s.q = q1;
    s.p = d.D2.template tail<N>();
    s.E = -d.D2(0);
    E_start_ = s.E;
    prev_dt_ = T(0);
    last_dt_ = t1 - t0;
    increment_ = q1 - q0;
    return s;
  }

  /// One step of (15)–(18). Throws SolveError when no admissible step exists near the
  /// previous one, or when a solve fails.
  ExtendedStepReport step(State& s) {
    ExtendedStepReport rep;
    const State k = s;
    const T target = options_.energy_target == EnergyTarget::previous ? k.E : E_start_;
    const T t0e = options_.time_translation_invariant ? T(0) : k.t;
    // q_{k+1}(Δt): Newton on (15), started from the previous increment scaled to Δt.
    // Newton starts from the increment of the latest solve, scaled to the trial Δt.
    T dt_seen = last_dt_;
    VecN increment_seen = increment_;
    auto solve_q = [&](const T& dt) {
      VecN q1 = k.q + increment_seen * T(dt / dt_seen);
      auto fj = [&](const VecN& x, VecN& F, Mat<T, N>& J) {
        const auto d = derivatives(t0e, k.q, T(t0e + dt), x);
        F = d.D1.template tail<N>() + k.p;
        J = d.D12.template bottomRightCorner<N, N>();
      };
      NewtonOptions nopt = newton_;
      nopt.residual_abs = options_.tol * to_double(T(k.p.template lpNorm<Eigen::Infinity>()));
      const SolveReport r =
          newton_solve<N>(q1, fj, nopt, "extended step: momentum equation (15)", &k.q);
      rep.newton_iterations += r.iterations;
      rep.momentum_residual = r.residual;
      dt_seen = dt;
      increment_seen = q1 - k.q;
      return q1;
    };
    T closest(std::numeric_limits<double>::infinity());
    auto g = [&](const T& dt) -> T {
      using std::abs;
      ++rep.root_iterations;
      const VecN q1 = solve_q(dt);
      const T r = derivatives(t0e, k.q, T(t0e + dt), q1).D1(0) - target;
      if (abs(r) < closest) closest = abs(r);
      return r;
    };
    using std::abs;
    const T bracket_tol(4 * to_double(unit_roundoff<T>()));
    const T f_tol = T(options_.tol) * abs(target);
    // Bracket the root that continues the previous step: grow geometrically on both sides of
    // Δt_{k−1}; if both sides change sign at the same level, keep the root nearer in ratio.
    auto solve_in = [&](const T& lo, const T& hi, const T& glo, const T& ghi) {
      const RootResult<T> r =
          bracketed_root(g, lo, hi, glo, ghi, bracket_tol, options_.max_root_iterations, f_tol);
      if (!r.converged)
        throw SolveError("extended step at t = " + text::g(to_double(k.t), 17) +
                             ": the energy equation did not converge in " +
                             std::to_string(r.evaluations) + " evaluations (residual " +
                             text::e(std::abs(to_double(r.fx)), 3) + ")",
                         SolveReport{std::abs(to_double(r.fx)), rep.root_iterations, false});
      return r.x;
    };
    // The predicted step: geometric extrapolation of the last two, the ratio clamped to [1/2, 2].
    const T center = history().predicted_step();
    auto log_ratio = [&](const T& x) {
      using std::log;
      using std::abs;
      return abs(log(x / center));
    };
    const T g0 = g(center);
    T dt = center;
    // Secant from the prediction first (a few evaluations when the prediction is good); it
    // stops at |g| <= f_tol, at an update below 4 units of round-off, or when |g| no longer
    // falls (the evaluation noise of g is reached: g is nearly flat in Δt). A secant iterate
    // leaving [center/2, 2·center] or not converging hands over to the bracket search.
    bool secant_ok = abs(g0) <= f_tol;
    if (!secant_ok) {
      T x0 = center, f0 = g0, x1 = center * T(1 + 1.0 / (1 << 20));
      T f1 = g(x1);
      T best_x = abs(f1) < abs(f0) ? x1 : x0, best_f = abs(f1) < abs(f0) ? f1 : f0;
      int stalls = 0;
      for (int it = 0; it < options_.max_secant_iterations; ++it) {
        if (abs(best_f) <= f_tol) {
          secant_ok = true;
          break;
        }
        if (f1 == f0) break;
        const T x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
        if (!(x2 > center / T(2) && x2 < center * T(2))) break;
        const T f2 = g(x2);
        if (abs(f2) < abs(best_f)) best_x = x2, best_f = f2;
        // At the noise floor of g (g is nearly flat in Δt) the updates wander at random; two
        // evaluations without progress, or an update below round-off, end the iteration with
        // the best point seen. Stopping at the first stall would keep the residual one-signed
        // (a one-sided approach), and the residuals add up in E_k.
        if (abs(f2) >= abs(f1)) ++stalls;
        if (abs(x2 - x1) <= bracket_tol * abs(x2) || stalls >= 2) {
          secant_ok = true;
          break;
        }
        x0 = x1, f0 = f1, x1 = x2, f1 = f2;
      }
      if (secant_ok) dt = best_x;
    }
    if (!secant_ok) {
      dt = center;
      T a_prev = center, ga_prev = g0, b_prev = center, gb_prev = g0;
      bool found = false;
      for (double f = options_.first_ratio; !found; f *= f) {
        f = std::min(f, options_.max_ratio);
        const T a = center / T(f), b = center * T(f);
        const T ga = g(a), gb = g(b);
        const T zero(0);
        const bool lower = (ga < zero) != (ga_prev < zero), upper = (gb < zero) != (gb_prev < zero);
        if (lower && upper) {
          const T r1 = solve_in(a, a_prev, ga, ga_prev), r2 = solve_in(b_prev, b, gb_prev, gb);
          dt = log_ratio(r1) <= log_ratio(r2) ? r1 : r2;
          found = true;
        } else if (lower) {
          dt = solve_in(a, a_prev, ga, ga_prev);
          found = true;
        } else if (upper) {
          dt = solve_in(b_prev, b, gb_prev, gb);
          found = true;
        }
        a_prev = a, ga_prev = ga, b_prev = b, gb_prev = gb;
        if (f >= options_.max_ratio) break;
      }
      if (!found) {
        std::string q, p;
        for (int i = 0; i < N; ++i) {
          q += (i ? ", " : "") + text::g(to_double(k.q(i)), 17);
          p += (i ? ", " : "") + text::g(to_double(k.p(i)), 17);
        }
        throw SolveError("extended step at t = " + text::g(to_double(k.t), 17) + ", q = (" + q +
                             "), p = (" + p + "), E = " + text::g(to_double(target), 17) +
                             ": the energy equation D1 L_d = E_k has no root for a step in [" +
                             text::g(to_double(center) / options_.max_ratio, 3) + ", " +
                             text::g(to_double(center) * options_.max_ratio, 3) +
                             "] (previous step " + text::g(to_double(last_dt_), 3) +
                             "; closest |D1 L_d - E_k| = " + text::e(to_double(closest), 3) +
                             "): no admissible time step",
                         SolveReport{to_double(closest), rep.root_iterations, false});
      }
    }
    const VecN q1 = solve_q(dt);
    const auto d = derivatives(t0e, k.q, T(t0e + dt), q1);
    rep.energy_residual = std::abs(to_double(T(d.D1(0) - target)));
    prev_dt_ = last_dt_;
    last_dt_ = dt;
    increment_ = q1 - k.q;
    if (options_.time_translation_invariant) {  // Kahan: t_{k+1} = t_k + Δt, compensated
      History h = history();
      s.t = h.advance(k.t, dt);
      t_compensation_ = h.t_compensation;
    } else {
      s.t = k.t + dt;
    }
    s.q = q1;
    s.p = d.D2.template tail<N>();
    s.E = -d.D2(0);
    return rep;
  }

  /// The energy equation at a trial step: D1 L_d(t_k, q_k, t_k + Δt, q_{k+1}(Δt)) − E, where
  /// q_{k+1}(Δt) solves the momentum equation (15) from state k. For studying where (16) has
  /// roots (the integrator's previous-step memory is used only for the Newton start).
  T energy_equation(const State& k, const T& dt, const T& E) {
    const T t0e = options_.time_translation_invariant ? T(0) : k.t;
    VecN q1 = k.q + increment_ * T(dt / last_dt_);
    auto fj = [&](const VecN& x, VecN& F, Mat<T, N>& J) {
      const auto d = derivatives(t0e, k.q, T(t0e + dt), x);
      F = d.D1.template tail<N>() + k.p;
      J = d.D12.template bottomRightCorner<N, N>();
    };
    newton_solve<N>(q1, fj, newton_, "energy_equation: momentum equation (15)", &k.q);
    return derivatives(t0e, k.q, T(t0e + dt), q1).D1(0) - E;
  }
  T last_step() const { return last_dt_; }

  /// What a step remembers of the earlier ones: the last two steps (for the prediction), the
  /// last increment q_{k+1} − q_k (Newton's start), the Kahan compensation of t and the
  /// start-up energy E_1. A faster stepper for a special class of L_d (epavi/mechanical.hpp)
  /// hands a step it cannot take over to this integrator through set_history.
  struct History {
    T last_dt = T(0), prev_dt = T(0), t_compensation = T(0), E_start = T(0);
    VecN increment = VecN::Zero();
    /// The step predicted from the last two: Δt_{k−1}²/Δt_{k−2}, the ratio clamped to
    /// [1/2, 2] (the ratio of successive steps changes slowly); Δt_{k−1} until two are known.
    T predicted_step() const {
      if (!(prev_dt > T(0))) return last_dt;
      return last_dt * std::clamp(T(last_dt / prev_dt), T(0.5), T(2));
    }
    /// t + Δt by Kahan's compensated summation, the compensation carried from step to step.
    T advance(const T& t, const T& dt) {
      const T y = dt - t_compensation;
      const T t1 = t + y;
      t_compensation = (t1 - t) - y;
      return t1;
    }
  };
  History history() const { return {last_dt_, prev_dt_, t_compensation_, E_start_, increment_}; }
  void set_history(const History& h) {
    last_dt_ = h.last_dt;
    prev_dt_ = h.prev_dt;
    t_compensation_ = h.t_compensation;
    E_start_ = h.E_start;
    increment_ = h.increment;
  }

  /// Residuals of the two-step equations (11) (N components) and (12) (last component) at
  /// (t_{k−1}, q_{k−1}), (t_k, q_k), (t_{k+1}, q_{k+1}):
  ///   D4 L_d(k−1, k) + D2 L_d(k, k+1)   and   D3 L_d(k−1, k) + D1 L_d(k, k+1).
  Vec<T, M> two_step_residual(const T& tm, const VecN& qm, const T& t, const VecN& q, const T& tp,
                              const VecN& qp) const {
    const auto a = derivatives(tm, qm, t, q), b = derivatives(t, q, tp, qp);
    Vec<T, M> r;
    r.template head<N>() = a.D2.template tail<N>() + b.D1.template tail<N>();
    r(N) = a.D2(0) + b.D1(0);
    return r;
  }

  /// All first derivatives of L_d at (t0, q0, t1, q1): D1 = ∇ w.r.t. (t0, q0), D2 = ∇ w.r.t.
  /// (t1, q1) (component 0 is the time derivative).
  ad::TwoPoint<M, T> derivatives(const T& t0, const VecN& q0, const T& t1, const VecN& q1) const {
    Vec<T, M> X0, X1;
    X0 << t0, q0;
    X1 << t1, q1;
    return ad::two_point<M>(extended_, X0, X1, T(0));
  }

 private:
  struct Extended {  // L_d as a function of the extended vectors X = (t, q)
    ExtendedDiscreteLagrangian Ld;
    template <class V, class S>
    S operator()(const V& X0, const V& X1, const S&) const {
      using Q = Vec<S, N>;
      const Q q0 = X0.template tail<N>(), q1 = X1.template tail<N>();
      return Ld(X0(0), q0, X1(0), q1);
    }
  };

  Extended extended_;
  Options options_;
  NewtonOptions newton_{};
  T E_start_ = T(0);
  T last_dt_ = T(0);
  T prev_dt_ = T(0);         ///< Δt_{k−2}, for the prediction; 0 until two steps are known
  T t_compensation_ = T(0);  ///< Kahan compensation of t (time_translation_invariant only)
  VecN increment_ = VecN::Zero();
};

template <int N, class T = double, class ExtendedDiscreteLagrangian>
ExtendedDelIntegrator<N, ExtendedDiscreteLagrangian, T> make_extended_del_integrator(
    ExtendedDiscreteLagrangian Ld,
    typename ExtendedDelIntegrator<N, ExtendedDiscreteLagrangian, T>::Options options = {}) {
  return ExtendedDelIntegrator<N, ExtendedDiscreteLagrangian, T>(std::move(Ld), options);
}

}  // namespace vibook
