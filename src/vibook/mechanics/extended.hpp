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
#pragma once

#include <fmt/format.h>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>

#include "vibook/core/autodiff.hpp"
#include "vibook/core/errors.hpp"
#include "vibook/core/newton.hpp"
#include "vibook/core/types.hpp"
#include "vibook/mechanics/discrete_lagrangian.hpp"

namespace vibook {

/// State of the time-marching form: (t_k, q_k, p_k, E_k).
template <int N>
struct ExtendedState {
  double t = 0;
  Vec<double, N> q = Vec<double, N>::Zero();
  Vec<double, N> p = Vec<double, N>::Zero();
  double E = 0;
};

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
    const auto qm = ((q0 + q1) * 0.5).eval();
    const auto v = ((q1 - q0) / dt).eval();
    return S(dt * L(qm, v));
  };
}

/// Report of one extended step: the energy-equation residual |D1 L_d − E_k| at the returned
/// point, the momentum-equation residual, and the iteration counts of both solves.
struct ExtendedStepReport {
  double energy_residual = 0;    ///< |D1 L_d(k, k+1) − E_k|
  double momentum_residual = 0;  ///< |p_k + D2 L_d(k, k+1)|_inf
  int root_iterations = 0;       ///< evaluations of the energy equation (bracketing + TOMS 748)
  int newton_iterations = 0;     ///< Newton iterations of the momentum equations, in total
};

/// The time-marching form (15)–(18) of the extended discrete Euler–Lagrange equations for any
/// extended discrete Lagrangian `L_d(t0, q0, t1, q1)` (t scalar, q an N-vector, generic in the
/// scalar type): each step solves
///   −D2 L_d(t_k, q_k, t_{k+1}, q_{k+1}) = p_k,   D1 L_d(t_k, q_k, t_{k+1}, q_{k+1}) = E_k
///   (15)–(16)
/// for (t_{k+1}, q_{k+1}), then sets p_{k+1} = D4 L_d and E_{k+1} = −D3 L_d (17)–(18).
///
/// **How (15)–(16) are solved.** Not as one coupled Newton system: the energy equation fixes
/// Δt = t_{k+1} − t_k through an effect of order Δt², so the coupled Jacobian is nearly
/// singular and Newton from the previous step diverges (we measured this). Instead, for each
/// trial Δt the momentum equations (15) are solved for q_{k+1}(Δt) by Newton (well
/// conditioned), and the scalar energy equation g(Δt) = D1 L_d − E_k = 0 is solved by a
/// bracketed root finder (Boost.Math TOMS 748). The bracket is grown geometrically from the
/// previous step Δt_{k−1} (ratio first_ratio, squared each time, up to max_ratio), which
/// keeps to the root that continues the previous step. If no sign change is found there, no
/// admissible step exists near the previous one, and the step throws SolveError saying so.
template <int N, class ExtendedDiscreteLagrangian>
class ExtendedDelIntegrator {
 public:
  static constexpr int M = N + 1;  ///< extended configuration (t, q)

  struct Options {
    NewtonOptions newton{};
    double max_ratio = 64.0;  ///< how far the bracket may grow from the previous step
    double first_ratio =
        1.015625;  ///< the first bracket [Δt/r, Δt·r]; r is squared until max_ratio
    int max_root_iterations = 200;
  };

  explicit ExtendedDelIntegrator(ExtendedDiscreteLagrangian Ld, Options options = {})
      : extended_{std::move(Ld)}, options_(options) {}

  /// The state after a first step from (t0, q0) to (t1, q1) (e.g. taken from an exact
  /// solution): p1 = D4 L_d, E1 = −D3 L_d (17)–(18).
  ExtendedState<N> start(double t0, const Vec<double, N>& q0, double t1, const Vec<double, N>& q1) {
    const auto d = derivatives(t0, q0, t1, q1);
    ExtendedState<N> s;
    s.t = t1;
    s.q = q1;
    s.p = d.D2.template tail<N>();
    s.E = -d.D2(0);
    last_dt_ = t1 - t0;
    increment_ = q1 - q0;
    return s;
  }

  /// One step of (15)–(18). Throws SolveError when no admissible step exists near the
  /// previous one, or when a solve fails.
  ExtendedStepReport step(ExtendedState<N>& s) {
    ExtendedStepReport rep;
    const ExtendedState<N> k = s;
    // q_{k+1}(Δt): Newton on (15), started from the previous increment scaled to Δt.
    auto solve_q = [&](double dt) {
      Vec<double, N> q1 = k.q + increment_ * (dt / last_dt_);
      auto fj = [&](const Vec<double, N>& x, Vec<double, N>& F, Mat<double, N>& J) {
        const auto d = derivatives(k.t, k.q, k.t + dt, x);
        F = d.D1.template tail<N>() + k.p;
        J = d.D12.template bottomRightCorner<N, N>();
      };
      const SolveReport r =
          newton_solve<N>(q1, fj, options_.newton, "extended step: momentum equation (15)", &k.q);
      rep.newton_iterations += r.iterations;
      rep.momentum_residual = r.residual;
      return q1;
    };
    auto g = [&](double dt) {
      ++rep.root_iterations;
      const Vec<double, N> q1 = solve_q(dt);
      return derivatives(k.t, k.q, k.t + dt, q1).D1(0) - k.E;
    };
    // Bracket the root that continues the previous step: grow geometrically on both sides of
    // Δt_{k−1}; if both sides change sign at the same level, keep the root nearer in ratio.
    auto solve_in = [&](double lo, double hi, double glo, double ghi) {
      std::uintmax_t it = std::uintmax_t(options_.max_root_iterations);
      const auto r = boost::math::tools::toms748_solve(
          g, lo, hi, glo, ghi, boost::math::tools::eps_tolerance<double>(52), it);
      return std::abs(g(r.first)) <= std::abs(g(r.second)) ? r.first : r.second;
    };
    const double g0 = g(last_dt_);
    double dt = last_dt_;
    if (g0 != 0.0) {
      double a_prev = last_dt_, ga_prev = g0, b_prev = last_dt_, gb_prev = g0;
      bool found = false;
      for (double f = options_.first_ratio; !found; f *= f) {
        f = std::min(f, options_.max_ratio);
        const double a = last_dt_ / f, b = last_dt_ * f;
        const double ga = g(a), gb = g(b);
        const bool lower = (ga < 0) != (ga_prev < 0), upper = (gb < 0) != (gb_prev < 0);
        if (lower && upper) {
          const double r1 = solve_in(a, a_prev, ga, ga_prev), r2 = solve_in(b_prev, b, gb_prev, gb);
          dt = std::abs(std::log(r1 / last_dt_)) <= std::abs(std::log(r2 / last_dt_)) ? r1 : r2;
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
        throw SolveError(
            fmt::format("extended step at t = {:.17g}: the energy equation D1 L_d = E_k "
                        "has no root for a step in [{:.3g}, {:.3g}] (previous step "
                        "{:.3g}): no admissible time step",
                        k.t, last_dt_ / options_.max_ratio, last_dt_ * options_.max_ratio,
                        last_dt_),
            SolveReport{std::abs(g0), rep.root_iterations, false});
      }
    }
    const Vec<double, N> q1 = solve_q(dt);
    const auto d = derivatives(k.t, k.q, k.t + dt, q1);
    rep.energy_residual = std::abs(d.D1(0) - k.E);
    last_dt_ = dt;
    increment_ = q1 - k.q;
    s.t = k.t + dt;
    s.q = q1;
    s.p = d.D2.template tail<N>();
    s.E = -d.D2(0);
    return rep;
  }

  /// Residuals of the two-step equations (11) (N components) and (12) (last component) at
  /// (t_{k−1}, q_{k−1}), (t_k, q_k), (t_{k+1}, q_{k+1}):
  ///   D4 L_d(k−1, k) + D2 L_d(k, k+1)   and   D3 L_d(k−1, k) + D1 L_d(k, k+1).
  Vec<double, M> two_step_residual(double tm, const Vec<double, N>& qm, double t,
                                   const Vec<double, N>& q, double tp,
                                   const Vec<double, N>& qp) const {
    const auto a = derivatives(tm, qm, t, q), b = derivatives(t, q, tp, qp);
    Vec<double, M> r;
    r.template head<N>() = a.D2.template tail<N>() + b.D1.template tail<N>();
    r(N) = a.D2(0) + b.D1(0);
    return r;
  }

  /// All first derivatives of L_d at (t0, q0, t1, q1): D1 = ∇ w.r.t. (t0, q0), D2 = ∇ w.r.t.
  /// (t1, q1) (component 0 is the time derivative).
  ad::TwoPoint<M> derivatives(double t0, const Vec<double, N>& q0, double t1,
                              const Vec<double, N>& q1) const {
    Vec<double, M> X0, X1;
    X0 << t0, q0;
    X1 << t1, q1;
    return ad::two_point<M>(extended_, X0, X1, 0.0);
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
  double last_dt_ = 0;
  Vec<double, N> increment_ = Vec<double, N>::Zero();
};

template <int N, class ExtendedDiscreteLagrangian>
ExtendedDelIntegrator<N, ExtendedDiscreteLagrangian> make_extended_del_integrator(
    ExtendedDiscreteLagrangian Ld,
    typename ExtendedDelIntegrator<N, ExtendedDiscreteLagrangian>::Options options = {}) {
  return ExtendedDelIntegrator<N, ExtendedDiscreteLagrangian>(std::move(Ld), options);
}

}  // namespace vibook
