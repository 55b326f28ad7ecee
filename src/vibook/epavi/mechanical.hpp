/// \file mechanical.hpp
/// \brief EpAVI in closed form for mechanical Lagrangians L = ½|v|² − V(q): Sharma et al.
/// 2022, the time-marching form (15)–(18) of the midpoint extended discrete Lagrangian (25),
/// with every derivative written out from ∇V and ∇²V, a Newton iteration on the step Δt whose
/// derivative comes from the implicit function theorem, and a discrete energy whose per-step
/// error has no preferred sign.
///
/// The generic path (EpAVI, mechanics/extended.hpp) differentiates any extended discrete
/// Lagrangian by nested AutoDiff and finds Δt by a secant and bracket search; it stays the
/// reference, and this stepper hands it any step it cannot take itself.
///
/// **The equations, written out.** With τ = t_{k+1} − t_k, Δq = q_{k+1} − q_k,
/// q̄ = (q_k + q_{k+1})/2, G = ∇V(q̄), H = ∇²V(q̄), (25) is
///   L_d = |Δq|²/(2τ) − τ V(q̄),
/// and (15)–(18) become
///   (15) Δq + (τ²/2) G − τ p_k = 0                 (the momentum equation times τ)
///   (16) g(τ) = |Δq|²/(2τ²) + V(q̄) − E_k = 0
///   (17) p_{k+1} = Δq/τ − (τ/2) G
///   (18) E_{k+1} = |Δq|²/(2τ²) + V(q̄)              (= E_k + g: (16) telescopes exactly)
/// (15) is solved for q_{k+1}(τ) by Newton with A = I + (τ²/4) H. Differentiating (15) and (16)
/// along q_{k+1}(τ) and using (15) to cancel the terms of order 1/τ gives, with u = Δq/τ,
///   dg/dτ = −(τ/4) (uᵀ A⁻¹ H u + Gᵀ A⁻¹ G),
/// so Newton on (16) needs no secant and no nested AutoDiff.
///
/// **Why a second phase.** q_{k+1} is rounded to T: one unit in its last place changes g by
/// about |u|/τ · ulp(q), far more than the explicit τ-dependence ∂g/∂τ = −|u|²/τ moves it per
/// unit of τ. As a function of the rounded τ, g is a saw-tooth around its smooth mean, and the
/// zero of the mean is known only to the height of a tooth. Newton with dg/dτ brings the mean
/// to zero (phase 1). Then q_{k+1} stays the representable point found and τ alone moves
/// (phase 2) to the representable τ nearest the zero of (16), which for fixed q_{k+1} is
/// τ* = |Δq|/√(2(E_k − V(q̄))): a move of the order of the rounding of q_{k+1}, so (15) still
/// holds to that order (its residual is reported). g is evaluated in a wider type (long double for
/// double; the wider types are their own, and there phase 2 is Newton on 2τ²g), so the residual
/// left is set by the spacing of representable τ and is as often positive as negative: the
/// discrete energy E_k performs a random walk (Brouwer's law) instead of drifting.
/// Options::tol is honoured as in the generic path: phase 1 stops as soon as |g| <= tol·|E_k|;
/// with a tol looser than the default (4 units of round-off) that ends the step, so a loose tol
/// leaves residuals up to tol·|E_k| (Sharma's Fig. 5); at the default, phase 2 always runs.
///
/// **Cost.** τ and q_{k+1} start from the polynomials through the last eight steps
/// (core/extrapolate.hpp); the Newton matrix of (15) comes from ∇²V at the start's midpoint,
/// so the solve is Newton's own iteration; it stops on the contraction its corrections show
/// (before the second, on the one seen in earlier steps); q_{k+1} follows a Newton update of τ
/// along its Taylor polynomial; the first value of g, when clearly above the floor, is taken
/// in T. Every shortcut is checked at the end of the step by the residual of (15) at the point
/// returned. Newton matrices, derivatives and bounds are estimates and are computed in double
/// in every precision; residuals, positions and steps stay in T, and (16) in W.
///
/// Chapter: \ref chapter-epavi.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <utility>

#include "vibook/core/autodiff.hpp"
#include "vibook/core/errors.hpp"
#include "vibook/core/extrapolate.hpp"
#include "vibook/core/format.hpp"
#include "vibook/core/scalar.hpp"
#include "vibook/core/types.hpp"
#include "vibook/epavi/epavi.hpp"

namespace vibook {

/// The type in which the energy equation is evaluated: long double for double (64-bit
/// significand on x86-64), the type itself otherwise.
template <class T>
struct WiderScalar {
  using type = T;
};
template <>
struct WiderScalar<double> {
  using type = long double;
};

/// EpAVI (Sharma et al. 2022, §2.2, (15)–(18) of (25)) for a mechanical problem L = ½|v|² − V(q)
/// whose potential and gradient are templated
/// on the scalar (`potential(q)`, `gradient(q)`), computed in T. Same options, state, start-up
/// and reports as EpAVI<Problem, T>; the two give the same trajectory to the conditioning of
/// (16) (epavi_test.cpp).
template <class Problem, class T = double>
class MechanicalEpAVI {
 public:
  static constexpr int N = Problem::N;
  using Reference = EpAVI<Problem, T>;
  using State = ExtendedState<N, T>;
  using Options = typename Reference::Options;
  using VecN = Vec<T, N>;
  using W = typename WiderScalar<T>::type;
  using VecW = Vec<W, N>;
  /// The Newton matrices, derivatives and bounds of the step are estimates: they scale
  /// corrections that are already small, and double serves them in every precision (for
  /// double-double and quad that saves most of the arithmetic). Residuals, positions and steps
  /// stay in T, and (16) in W.
  using VecD = Vec<double, N>;
  using MatD = Mat<double, N>;
  /// How many earlier steps the start of a step is extrapolated from.
  static constexpr int kHistory = 8;

  explicit MechanicalEpAVI(Problem P, Options options = {})
      : P_(P), reference_(P, options), options_(reference_.integrator().options()) {
    u_ = unit_roundoff<T>();
    ud_ = to_double(u_);
  }

  const Options& options() const { return options_; }
  /// Steps handed to the generic path so far (no Newton convergence near the predicted step).
  long long fallbacks() const { return fallbacks_; }

  /// The generic path, with what each step remembers of the earlier ones (to take the same
  /// step both ways from one state: `generic().set_history(history())`).
  using History = typename Reference::Integrator::History;
  History history() const { return h_; }
  typename Reference::Integrator& generic() { return reference_.integrator(); }

  /// Start from (t0, q0) with the first step to (t0 + h0, q1): p1 by (17), E1 by (18).
  State start(const T& t0, const VecN& q0, const T& h0, const VecN& q1) {
    const VecN dq = q1 - q0;
    const VecN G = P_.gradient(midpoint(q0, q1));
    G_last_ = G;
    State s;
    s.t = t0 + h0;
    s.q = q1;
    s.p = dq / h0 - G * half(h0);
    s.E = T(energy(q0, q1, h0));
    h_ = History{};
    h_.E_start = s.E;
    h_.last_dt = h0;
    h_.increment = dq;
    theta_ = -1;
    taus_.clear(), positions_.clear();
    taus_.push(h0), positions_.push(q0), positions_.push(q1);
    return s;
  }

  /// One step of (15)–(18). Throws SolveError as EpAVI::step does.
  ExtendedStepReport step(State& s) { return take_step(s, true); }

  /// (18) in the wide type: |Δq|²/(2τ²) + V(q̄), the discrete energy of the step q0 → q1.
  W energy(const VecN& q0, const VecN& q1, const T& tau) const {
    const auto [kinetic2, potential] = wide_parts(q0, q1);
    const W tw = W(tau);
    return kinetic2 / (W(2.0) * tw * tw) + potential;
  }

 private:
  /// The step. With `shortcuts`, a momentum solve may stop after its first correction on the
  /// contraction earlier solves showed (solve_momentum), and after a Newton update of τ the
  /// position may follow its Taylor polynomial instead of a new solve; the final check of (15)
  /// verifies either, and a step that fails it is taken again without them.
  ///
  /// Everything the step calls is inlined into it (`flatten`; the generic path and the error
  /// messages are kept out of line): in a translation unit that instantiates much else (the
  /// command line, the benchmarks) GCC's inlining budget otherwise runs out, and the double
  /// step took nearly twice as long in the benchmark as in a small program.
  [[gnu::flatten]] ExtendedStepReport take_step(State& s, bool shortcuts) {
    ExtendedStepReport rep;
    // The estimates are taken in double, which needs T's unit round-off (times the sizes of a
    // step) inside double's range: true up to about 280 decimal digits. Beyond, for MPFR at
    // more digits, every step is the generic path's (fallbacks() counts them).
    if (!(ud_ > kSmallestRoundoff)) return remember(fall_back(s, rep), s);
    took_shortcut_ = false;
    shortcuts_ = shortcuts;
    const State k = s;
    const T target = options_.energy_target == EnergyTarget::previous ? k.E : h_.E_start;
    const W targetW = W(target);
    // The predicted step, as in the generic path: Δt_{k−1}²/Δt_{k−2}, ratio clamped to [½, 2].
    const T center = h_.predicted_step();

    // The start: once eight steps of this trajectory are known, τ and q_{k+1} extrapolated
    // from them (core/extrapolate.hpp). The steps carry the noise (16) leaves (a tooth of g,
    // about 1e-8 relative in double for Kepler at h0 = 1e-3), so one Newton update of τ is
    // still needed, but q_{k+1} starts about 1e-11 away instead of 1e-9. Before, the predicted
    // step and (15) itself with ∇V at the previous step's midpoint, off by O(τ³).
    if (positions_.count() == 0 || !(positions_.newest() == k.q))
      taus_.clear(), positions_.clear(), positions_.push(k.q);
    const bool extrapolate = taus_.count() == kHistory && positions_.count() == kHistory;
    T tau = extrapolate ? extrapolated(taus_) : center;
    if (!near(tau, center)) tau = center;
    VecN x = extrapolate ? extrapolated(positions_)
                         : VecN(k.q + k.p * tau - G_last_ * half(T(tau * tau)));
    VecN G;
    // The Newton matrix of (15), from ∇²V at the start's midpoint (in double: it only scales
    // corrections). Taken here, it does not wait for the solve, and the solve is Newton's
    // iteration from its first correction: one correction is usually enough, in double from a
    // start 1e-11 away, in the wider types from 1e-14 to their round-off. The first Newton
    // update of τ below uses it too (q_{k+1} moves by about 1e-11 relative in the solve, and
    // ∇²V with it); later updates, after larger moves, take it again.
    H_ = hessian(midpoint(k.q, x));
    MatD Ainv = inverse_newton_matrix(H_, tau);
    W gW(0);
    using std::abs;
    // [epavi-closed-form-step]
    // Phase 1: Newton on (16) with the total derivative dg/dτ.
    bool converged = false;
    for (int it = 0; it < kMaxPhase1; ++it) {
      try {
        solve_momentum(k, tau, Ainv, x, G, rep.newton_iterations);
      } catch (const SolveError&) {
        break;  // (15) not solved at this trial step: the generic path searches instead
      }
      ++rep.root_iterations;
      const W floor_here = floor(k, x, tau, G, target);
      // (16) in T first, when the wide type is wider: a value that is clearly above the floor
      // only feeds the Newton update of τ, which T's accuracy serves. Whether (16) holds, and
      // the value phase 2 starts from, always come from the wide type.
      bool wide = true;
      if constexpr (!std::is_same_v<W, T>) {
        const auto [g, error] = energy_in_t(k.q, x, tau, target);
        if (is_finite(W(g)) && W(abs(g)) > floor_here + W(error)) gW = W(g), wide = false;
      }
      if (wide) gW = wide_energy(k.q, x, tau, targetW);
      if (!is_finite(gW)) break;
      if (abs(gW) <= floor_here) {
        converged = true;
        break;
      }
      if (it > 0) {
        H_ = hessian(midpoint(k.q, x));
        Ainv = inverse_newton_matrix(H_, tau);
      }
      const double taud = to_double(tau);
      const double inv_tau = 1.0 / taud;  // for the estimates below (not for the step itself)
      const VecD v = lower(VecN(x - k.q)) * inv_tau, Gd = lower(G);
      const VecD AHv = Ainv * VecD(H_ * v), AG = Ainv * Gd;
      const double dg = -taud * 0.25 * (v.dot(AHv) + Gd.dot(AG));
      const T next = tau - T(to_double(gW) / dg);
      if (!is_finite(W(next)) || !near(next, center)) break;
      // Newton's start for (15) at the new step: q_{k+1} moved along its Taylor polynomial in
      // τ. Differentiating (15), A x' = p_k − τG and A x'' = −G − τ H x' + O(τ²), with
      // x = q_{k+1}(τ) and A = I + τ²H/4. x' is a full-size vector: it is computed in T.
      const VecN dx_dtau = apply_inverse(Ainv, VecN(k.p - G * tau), taud);
      const VecD dxd_dtau = lower(dx_dtau);
      const VecD H_dx = H_ * dxd_dtau;
      const VecD d2x_dtau2 = Ainv * VecD(-Gd - H_dx * taud);
      const T dtau = next - tau;
      const double dtd = to_double(dtau);
      x += (dx_dtau + lift(VecD(d2x_dtau2 * (dtd * 0.5)))) * dtau;
      tau = next;
      // The quadratic move is exact to |x‴|·|δτ|³/6, where x‴ = −(3/2)H x' + O(τ); the bound
      // below, 3|H||x'| + |G|/τ, is twice that and more. Below the rounding of q_{k+1}, (15)
      // needs no new solve. (16) is checked at the moved point; if it does not hold to the
      // tooth height, the loop solves as usual. Either way the residual of (15) at the point
      // returned is measured at the end of the step.
      const double x3 = 3.0 * H_.template lpNorm<Eigen::Infinity>() *
                            dxd_dtau.template lpNorm<Eigen::Infinity>() +
                        Gd.template lpNorm<Eigen::Infinity>() * inv_tau;
      // Whether (16) can hold at the new step at all: Newton's next residual is about
      // |g''|δτ²/2 = |dg/dτ|δτ²/(2τ) (g'' ≈ g'/τ, from the formula for dg/dτ above). In double
      // precision one Newton step usually gets below the tooth height; in the wider types the
      // first does not, and checking (16) there would cost an evaluation for nothing.
      const bool newton_done = W(std::abs(dg) * dtd * dtd * inv_tau * 0.5) <= floor_here;
      if (shortcuts_ && newton_done &&
          x3 * std::abs(dtd) * dtd * dtd <=
              6.0 * ud_ * lower(x).template lpNorm<Eigen::Infinity>()) {
        gW = wide_energy(k.q, x, tau, targetW);
        ++rep.root_iterations;
        // The floor moves with the point by O(δτ/τ) relative: the one just computed serves.
        if (is_finite(gW) && abs(gW) <= floor_here) {
          converged = took_shortcut_ = true;  // x is the Taylor move's, not a solve's
          break;
        }
      }
    }
    if (!converged) return remember(fall_back(s, rep), s);
    // Phase 2: q_{k+1} stays the representable point found; τ alone moves, to the
    // representable τ nearest the zero of (16). With q_{k+1} fixed, (16) is
    // g(τ) = |Δq|²/(2τ²) + rest, rest = V(q̄) − E_k, whose zero is τ* = |Δq|/√(−2 rest).
    // When the wide type is wider than T, τ* is computed in it and rounded to T. When it is T
    // itself, Newton runs from where phase 1 stopped until the update rounds to nothing, on
    // h(τ) = 2τ²g = |Δq|² + 2τ² rest (same sign and zero as g, no division), with h′ ≈ −2|Δq|²/τ
    // near the zero, so δτ = hτ/(2|Δq|²), an update of a few units of τ's last place computed in
    // double: τ* computed in double-double (libqd's square root) and polished left residuals of
    // one sign, and E_k drifted (z = 9 over 2e5 steps). The move is of the order of the
    // rounding of q_{k+1} (|δτ| ≈ ulp(q)/|Δq/τ|), so (15) stays satisfied to the same order;
    // its residual is measured again below.
    // A tolerance looser than the default, once met, ends the step here. Otherwise phase 2
    // always runs: where phase 1 stops, Newton has approached the zero from one side, and a
    // residual left there would carry that side's sign into E_{k+1}.
    const T tau1 = tau;  // where phase 1 stopped, with q_{k+1} solved from (15)
    const bool loose = options_.tol > 4 * ud_ * (1 + 1e-9);
    if (!(loose && abs(gW) <= W(options_.tol) * abs(targetW))) {
      // |Δq|² and V(q̄) − E_k of the last evaluation in the wide type, which was at this x.
      const W kinetic2 = last_kinetic2_, rest = last_rest_;
      if constexpr (!std::is_same_v<W, T>) {
        using std::sqrt;
        const T root = rest < W(0) ? T(sqrt(W(kinetic2 / (W(-2.0) * rest)))) : T(0);
        if (is_finite(W(root)) && near(root, center)) {
          tau = root;
          gW = kinetic2 / (W(2.0) * W(tau) * W(tau)) + rest;
        }
      } else {
        const double k2 = to_double(kinetic2);
        for (int it = 0; it < kMaxPhase2 && k2 > 0; ++it) {
          const T next = tau + T(to_double(scaled_residual(tau)) * to_double(tau) / (2.0 * k2));
          if (next == tau || !is_finite(W(next))) break;
          tau = next;
          gW = residual_from_scaled(scaled_residual(tau), tau);
        }
      }
    }
    // (17)–(18) at the chosen point.
    const VecN dq = x - k.q;
    G = P_.gradient(midpoint(k.q, x));
    // The momentum solve may stop on its contraction estimate, and phase 1 may move q_{k+1}
    // along its Taylor polynomial without a new solve: both are checked here, by the Newton
    // correction that (15) would still ask for at the (q_{k+1}, τ) where phase 1 stopped (∇V
    // at its midpoint is the G just computed: phase 2 moves τ only). A correction above the
    // solve's own bound sends the step to the generic path.
    {
      using std::abs;
      const VecN F1 = dq + G * half(T(tau1 * tau1)) - k.p * tau1;
      // A⁻¹ of the last Newton update of τ: close enough to scale a correction this small.
      const VecD correction = Ainv * lower(F1);
      const VecD dqd = lower(dq), xd = lower(x), qd = lower(k.q);
      const double scale = dqd.template lpNorm<Eigen::Infinity>();
      for (int i = 0; i < N; ++i)
        if (!(std::abs(correction(i)) <= rounding_bound(xd(i), qd(i), scale))) {
          theta_ = -1;
          // A shortcut was taken: the step once more without any (shortcuts = false cannot
          // take this branch again). At e = 0.7 about 2% of the steps land just above the
          // bound after a Taylor move, in double-double at h0 = 1e-3 and in double at
          // h0 = 0.01; none in double or long double at h0 = 1e-3.
          if (took_shortcut_) {
            ExtendedStepReport again = take_step(s, false);
            again.root_iterations += rep.root_iterations;
            again.newton_iterations += rep.newton_iterations;
            return again;
          }
          return remember(fall_back(s, rep), s);
        }
    }
    const VecN F = dq + G * half(T(tau * tau)) - k.p * tau;
    rep.energy_residual = std::abs(to_double(T(gW)));
    rep.momentum_residual = to_double(T(F.template lpNorm<Eigen::Infinity>() / tau));
    h_.prev_dt = h_.last_dt;
    h_.last_dt = tau;
    h_.increment = dq;
    s.t = h_.advance(k.t, tau);
    s.q = x;
    s.p = dq / tau - G * half(tau);
    G_last_ = G;
    s.E = T(targetW + gW);
    return remember(rep, s);
    // [epavi-closed-form-step]
  }

  /// (18) − E_k in T, and a bound on its rounding error (8u times the sizes of its terms).
  std::pair<T, T> energy_in_t(const VecN& q0, const VecN& q1, const T& tau, const T& target) const {
    using std::abs;
    const T kinetic = (q1 - q0).squaredNorm() / (T(2) * tau * tau);
    const T potential = P_.potential(midpoint(q0, q1));
    return {kinetic + potential - target,
            T(8) * u_ * (abs(kinetic) + abs(potential) + abs(target))};
  }

  /// g = (18) − E_k in the wide type, keeping |Δq|² and V(q̄) − E_k for phase 2.
  W wide_energy(const VecN& q0, const VecN& q1, const T& tau, const W& target) {
    const auto [kinetic2, potential] = wide_parts(q0, q1);
    last_kinetic2_ = kinetic2;
    last_rest_ = potential - target;
    if constexpr (std::is_same_v<W, T>) {
      return residual_from_scaled(scaled_residual(tau), tau);
    } else {
      const W tw = W(tau);
      return last_kinetic2_ / (W(2.0) * tw * tw) + last_rest_;
    }
  }

  /// 2τ²g = |Δq|² + 2τ²(V(q̄) − E_k) in the wide type, at the parts of the last wide_energy:
  /// (16) without its division, with g's sign and its cancellation in the wide type.
  W scaled_residual(const T& tau) const {
    const W tw = W(tau);
    return last_kinetic2_ + W(2.0) * last_rest_ * (tw * tw);
  }

  /// g from 2τ²g, the quotient in double. Used where the wide type is T itself (double-double,
  /// quad: a division there is a software routine). g is small wherever it decides anything, so
  /// its relative accuracy of 1e-16 adds nothing to E_{k+1} = E_k + g, and the comparisons with
  /// the floor and the Newton updates of τ need a few digits.
  static W residual_from_scaled(const W& scaled, const T& tau) {
    const double t = to_double(tau);
    return W(to_double(scaled) / (2.0 * t * t));
  }

  /// |q1 − q0|² and V((q0 + q1)/2) in the wide type: the two parts of (18).
  std::pair<W, W> wide_parts(const VecN& q0, const VecN& q1) const {
    const VecW a = q0.template cast<W>(), b = q1.template cast<W>();
    return {(b - a).squaredNorm(), P_.potential(midpoint(a, b))};
  }

  static constexpr int kMaxPhase1 = 30;
  static constexpr double kSmallestRoundoff = 1e-280;
  static constexpr int kMaxPhase2 = 8;

  /// The polynomial extrapolation of the last kHistory values (SampleHistory::next). In the
  /// wider types it is taken as the newest value plus the weighted differences to it, the sum
  /// in double: its error, about 1e-16 of the differences, is far below that of the
  /// extrapolation itself (1e-14 relative), and it saves kHistory products in T per component.
  template <class V>
  static V extrapolated(const SampleHistory<V, T, kHistory>& h) {
    if constexpr (std::is_same_v<T, double>) {
      return h.next();
    } else {
      const V& x0 = h.newest();
      if constexpr (std::is_same_v<V, T>) {
        double sum = 0;
        for (int j = 1; j < kHistory; ++j)
          sum += SampleHistory<V, T, kHistory>::weight(kHistory, j) * to_double(T(h.value(j) - x0));
        return x0 + T(sum);
      } else {
        VecD sum = VecD::Zero();
        for (int j = 1; j < kHistory; ++j)
          sum += lower(VecN(h.value(j) - x0)) * SampleHistory<V, T, kHistory>::weight(kHistory, j);
        return x0 + lift(sum);
      }
    }
  }

  /// (a + b)/2, componentwise (half() halves a double-double without a product).
  template <class S>
  static Vec<S, N> midpoint(const Vec<S, N>& a, const Vec<S, N>& b) {
    Vec<S, N> m;
    for (int i = 0; i < N; ++i) m(i) = half(S(a(i) + b(i)));
    return m;
  }

  /// A vector of T in double (to_double: libqd's dd_real has no conversion Eigen's cast
  /// could use), and back (Eigen's cast).
  static VecD lower(const VecN& v) {
    return v.unaryExpr([](const T& x) { return to_double(x); });
  }
  static VecN lift(const VecD& d) { return d.template cast<T>(); }

  /// Whether a trial step lies in (center/2, 2 center), the generic path's bracket.
  static bool near(const T& tau, const T& center) {
    const double t = to_double(tau), c = to_double(center);
    return t > c / 2 && t < c * 2;
  }

  /// A⁻¹r for a full-size r in T: A = I + B with B = τ²H/4, so A⁻¹r = r − A⁻¹Br, and only the
  /// small term A⁻¹Br (about 1e-5 of r for Kepler at h0 = 1e-3) is taken in double.
  VecN apply_inverse(const MatD& Ainv, const VecN& r, double tau) const {
    if constexpr (std::is_same_v<T, double>) {
      (void)tau;
      return Ainv * r;
    } else {
      return r - lift(VecD(Ainv * VecD(H_ * lower(r)) * (tau * tau * 0.25)));
    }
  }

  static bool is_finite(const W& w) { return ScalarTraits<W>::is_finite(w); }

  /// ∇²V(x) in double, by the problem's own Hessian or AutoDiff (ad::potential_hessian).
  MatD hessian(const VecN& x) const { return ad::potential_hessian(P_, lower(x)); }

  /// A⁻¹ for A = I + (τ²/4) H: A is I plus a small perturbation wherever (15) is solvable at
  /// all, so the explicit inverse (closed-form cofactors for N <= 4 in Eigen) is accurate and
  /// far cheaper than a pivoted factorization of a 2×2 system.
  static MatD inverse_newton_matrix(const MatD& H, const T& tau) {
    const double t = to_double(tau);
    return MatD(MatD::Identity() + H * (t * t * 0.25)).inverse();
  }

  /// (15) for q_{k+1} = x at step τ: Newton with the Jacobian A held fixed (A differs from the
  /// exact Jacobian by O(τ²) changes of ∇²V, so the iteration contracts by far more than a
  /// Newton step needs). G is ∇V at the last midpoint used; the residual of (15) is measured at
  /// the point the step returns.
  void solve_momentum(const State& k, const T& tau, const MatD& Ainv, VecN& x, VecN& G,
                      int& iterations) {
    const T half_tau2 = half(T(tau * tau));
    const double taud = to_double(tau);
    double previous = 0;  // max |dx| of the last iteration
    // Before a second iteration shows the contraction, the contraction seen in earlier steps
    // (twice it) stands in: A changes by O(τ³) from step to step. The step's final check of
    // (15) verifies the point returned either way, and a step that fails it is taken again
    // without this shortcut.
    const double theta_before = shortcuts_ && theta_ >= 0 ? 2 * theta_ : 1.0;
    for (int it = 1; it <= options_.max_newton_iterations; ++it) {
      G = P_.gradient(midpoint(k.q, x));
      const VecN F = (x - k.q) + G * half_tau2 - k.p * tau;
      // The correction A⁻¹F. In the wider types A⁻¹ rounded to double would leave 1e-16 of
      // each correction behind, far above their rounding, and cost a further iteration: there
      // it is taken as F − A⁻¹BF (apply_inverse).
      const VecN dxT = apply_inverse(Ainv, F, taud);
      x -= dxT;
      const VecD dx = lower(dxT);
      ++iterations;
      const VecD xd = lower(x), qd = lower(k.q);
      const double scale = lower(VecN(x - k.q)).template lpNorm<Eigen::Infinity>();
      const double size = dx.template lpNorm<Eigen::Infinity>();
      // The contraction θ = |dx_k|/|dx_{k−1}| of this solve: the next correction would be
      // about θ|dx_k|, so once θ/(1 − θ)·|dx_k| is below the bound the iterate is converged
      // without another evaluation of ∇V (the stopping rule of simplified Newton methods).
      const double theta = it >= 2 && previous > 0 ? size / previous : theta_before;
      const double ahead = theta < 0.5 ? theta / (1 - theta) : -1.0;
      // What the next steps assume: the contraction seen, but a smaller one only slowly (a
      // correction that happens to come out small says little about the next solve).
      if (it >= 2 && previous > 0) theta_ = std::max(theta, theta_ * 0.25);
      previous = size;
      bool small = true, converged_ahead = ahead >= 0;
      for (int i = 0; i < N; ++i) {
        if (!std::isfinite(dx(i)) || !std::isfinite(xd(i)))
          fail_momentum(to_double(k.t), to_double(tau), "gave a non-finite value",
                        to_double(T(F.template lpNorm<Eigen::Infinity>())), iterations);
        const double bound = rounding_bound(xd(i), qd(i), scale);
        if (std::abs(dx(i)) > bound) small = false;
        if (!(ahead * std::abs(dx(i)) <= bound)) converged_ahead = false;
      }
      if (small || converged_ahead) {
        if (it == 1 && !small) took_shortcut_ = true;
        // ∇V at the point returned, to first order: the last force was taken before the last
        // correction moved the midpoint by dx/2. The Taylor move's velocity p_k − τG needs it
        // (from a start 1e-14 away, in double-double, the uncorrected G put the moved point
        // just outside (15)'s bound in about 5% of the steps).
        G -= lift(VecD(H_ * dx * 0.5));
        return;
      }
    }
    fail_momentum(
        to_double(k.t), to_double(tau),
        "did not converge in " + std::to_string(options_.max_newton_iterations) + " iterations", 0,
        iterations);
  }

  /// The SolveError of a failed solve of (15) (out of line: the step's code stays compact).
  [[noreturn, gnu::noinline, gnu::cold]] static void fail_momentum(double t, double tau,
                                                                   const std::string& what,
                                                                   double residual,
                                                                   int iterations) {
    throw SolveError("EpAVI step at t = " + text::g(t, 17) + ": the momentum equation (15) " +
                         what + " at step " + text::g(tau, 17),
                     SolveReport{residual, iterations, false});
  }

  /// The size below which a Newton correction of component i of q_{k+1} is rounding: 2u times
  /// the largest of |q_{k+1,i}|, |q_{k,i}| and the step |q_{k+1} − q_k| (u of T, the sizes in
  /// double). The momentum solve stops on it, and the step's final check of (15) holds the
  /// point returned to it.
  double rounding_bound(double x_i, double q_i, double scale) const {
    return 2 * ud_ * std::max({std::abs(x_i), std::abs(q_i), scale});
  }

  /// Where phase 1 stops: the height of a tooth of g (what rounding q_{k+1} to T moves it by)
  /// plus the energy's own round-off, or tol·|E_k| if that is larger. An estimate, in double.
  W floor(const State& k, const VecN& x, const T& tau, const VecN& G, const T& target) const {
    const double t = to_double(tau);
    const double inv_tau2 = 1.0 / (t * t);
    const VecD xd = lower(x), dq = lower(VecN(x - k.q)), Gd = lower(G);
    double f = 0;
    for (int i = 0; i < N; ++i) {
      const double dgdq = std::abs(dq(i) * inv_tau2 + Gd(i) * 0.5);
      f += dgdq * ud_ * std::max(std::abs(xd(i)), std::abs(dq(i)));
    }
    const double E = std::abs(to_double(target));
    f = std::max(2 * f + ud_ * E, options_.tol * E);
    return W(f);
  }

  /// The step just taken, for the extrapolation of the next start.
  ExtendedStepReport remember(const ExtendedStepReport& rep, const State& s) {
    taus_.push(h_.last_dt), positions_.push(s.q);
    return rep;
  }

  [[gnu::noinline, gnu::cold]] ExtendedStepReport fall_back(State& s, ExtendedStepReport rep) {
    ++fallbacks_;
    auto& gen = reference_.integrator();
    gen.set_history(h_);
    ExtendedStepReport r = reference_.step(s);
    h_ = gen.history();
    G_last_ = P_.gradient(VecN(s.q - h_.increment * constant<T>(0.5)));
    r.root_iterations += rep.root_iterations;
    r.newton_iterations += rep.newton_iterations;
    return r;
  }

  Problem P_;
  Reference reference_;
  Options options_;
  T u_;
  double ud_;  ///< u_ in double, for the estimates
  long long fallbacks_ = 0;
  MatD H_ = MatD::Zero();       ///< ∇²V at the start's midpoint, or where τ was last updated
  VecN G_last_ = VecN::Zero();  ///< ∇V at the last step's midpoint
  double theta_ = -1;           ///< the contraction the solves of (15) showed (−1: none yet)
  bool took_shortcut_ = false;  ///< whether this step stopped a solve on theta_ or moved x
  bool shortcuts_ = true;       ///< whether this step may (see take_step)
  W last_kinetic2_ = W(0), last_rest_ = W(0);  ///< the parts of the last wide_energy
  History h_;  ///< the last steps, the last increment, the compensation of t, E_1
  SampleHistory<T, T, kHistory> taus_;          ///< the last steps τ of this trajectory
  SampleHistory<VecN, T, kHistory> positions_;  ///< the last positions, q_k newest
};

}  // namespace vibook
