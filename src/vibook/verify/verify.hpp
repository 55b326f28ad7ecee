/// \file verify.hpp
/// \brief Verify a one-step method of your own: measured convergence order (two-sided),
/// symplecticity and time-reversibility defects of the one-step map, and the long-time
/// behaviour of the energy error (bounded, random walk or drift, by a fitted exponent).
///
/// A method is given to these helpers as a *step*: any callable
/// `step(Eigen::VectorXd& z, double h)` that advances the phase-space state z = (q, p) (first
/// half positions, second half momenta) by one step of size h in place. A DelIntegrator is
/// wrapped in one line (see examples/henon_heiles_simpson.cpp):
/// \code
///   vibook::DelIntegrator<2, decltype(Ld)> vi(Ld);
///   auto step = [&](Eigen::VectorXd& z, double h) { vibook::verify::step_qp<2>(vi, z, h); };
/// \endcode
/// Each result carries the numbers it was judged on and the criterion, so that a report can
/// print both; none of these functions prints or throws on a failed criterion (`passed` says).
///
/// Chapter: \ref chapter-verify.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "vibook/core/order.hpp"

namespace vibook::verify {

/// A one-step method on the phase-space state z = (q, p): `step(z, h)` advances z in place.
using Step = std::function<void(Eigen::VectorXd& z, double h)>;
/// A scalar function of the state, e.g. the Hamiltonian.
using Observable = std::function<double(const Eigen::VectorXd& z)>;

/// Advance a position–momentum integrator (DelIntegrator, ExplicitKernel, … : anything with
/// `step(Vec<double,N>& q, Vec<double,N>& p, double h)`) on the packed state z = (q, p).
/// A state of 2N + 1 components is that of a time-dependent system, z = (q, p, t): the
/// integrator is told the step's start time (`set_time`) and the clock advances by h.
template <int N, class Integrator>
void step_qp(Integrator& integrator, Eigen::VectorXd& z, double h) {
  Eigen::Matrix<double, N, 1> q = z.head<N>(), p = z.segment<N>(N);
  const bool timed = z.size() == 2 * N + 1;
  if (timed) {
    if constexpr (requires { integrator.set_time(z(2 * N)); })
      integrator.set_time(z(2 * N));
    else
      throw std::logic_error("step_qp: this integrator does not step a time-dependent system");
  }
  integrator.step(q, p, h);
  z.head<N>() = q;
  z.segment<N>(N) = p;
  if (timed) z(2 * N) += h;
}

/// Integrate from z0 over [0, T] with steps of size h (the last one shortened to end at T).
inline Eigen::VectorXd integrate(const Step& step, Eigen::VectorXd z0, double h, double T) {
  if (!(h > 0) || !(T >= 0) || !std::isfinite(h) || !std::isfinite(T))
    throw std::invalid_argument("integrate: need h > 0 and T >= 0, both finite");
  const double n = std::ceil(T / h - 1e-9);
  if (n > 1e12) throw std::invalid_argument("integrate: more than 1e12 steps");
  const long long steps = static_cast<long long>(n);
  for (long long k = 0; k < steps; ++k) {
    const double hk = k + 1 == steps ? T - h * double(k) : h;
    step(z0, hk);
  }
  return z0;
}

// -------------------------------------------------------------------------------------------
// Convergence order
// -------------------------------------------------------------------------------------------

/// Result of convergence_order: the error at time T for each step size, the fitted slope
/// of log(error) against log(h) over the points above `floor`, and the two-sided verdict
/// |slope − expected| < tolerance.
struct ConvergenceStudy {
  std::vector<double> h;
  std::vector<double> error;  ///< max-norm distance to the reference at T
  double order = std::numeric_limits<double>::quiet_NaN();
  int points = 0;  ///< points used in the fit (error above floor)
  double expected = 0;
  double tolerance = 0;
  double floor = 0;
  bool passed = false;
};

/// Measured order at time T against `reference` (the exact solution, or a run of a
/// higher-order method or of this one at a much smaller step, accurate well below the
/// smallest error). Errors at or below `floor` (the round-off plateau, or the reference's own
/// error) are left out of the fit; at least 3 points must remain.
inline ConvergenceStudy convergence_order(const Step& step, const Eigen::VectorXd& z0, double T,
                                          const Eigen::VectorXd& reference,
                                          const std::vector<double>& hs, double expected,
                                          double tolerance, double floor) {
  ConvergenceStudy s;
  s.expected = expected;
  s.tolerance = tolerance;
  s.floor = floor;
  for (double h : hs) {
    const Eigen::VectorXd z = integrate(step, z0, h, T);
    s.h.push_back(h);
    s.error.push_back((z - reference).lpNorm<Eigen::Infinity>());
  }
  try {
    const OrderFit f = fit_order(s.h, s.error, floor, 3);
    s.order = f.slope;
    s.points = f.points;
    s.passed = std::abs(f.slope - expected) < tolerance;
  } catch (const std::invalid_argument&) {
    s.passed = false;  // fewer than 3 points above the floor: nothing measured
  }
  return s;
}

/// One method of a work–precision comparison: its name and its step.
struct NamedStep {
  std::string name;
  Step step;
};

/// Result of work_precision: for each method, the error at T against `reference` for each
/// step size, with the work measured in steps (deterministic, unlike wall-clock time: the
/// benchmarks under tests/bench measure time).
struct WorkPrecision {
  std::vector<double> h;
  std::vector<double> steps;  ///< steps to T for each h
  std::vector<std::string> methods;
  std::vector<std::vector<double>> error;  ///< error[m][i]: method m at h[i]
};

/// Every method at every step size, against one reference (DiffEqDevTools' WorkPrecisionSet
/// is the model; here for one-step methods on a phase-space state).
inline WorkPrecision work_precision(const std::vector<NamedStep>& methods,
                                    const Eigen::VectorXd& z0, double T,
                                    const Eigen::VectorXd& reference,
                                    const std::vector<double>& hs) {
  WorkPrecision w;
  w.h = hs;
  for (double h : hs) w.steps.push_back(std::ceil(T / h - 1e-9));
  for (const auto& m : methods) {
    w.methods.push_back(m.name);
    w.error.emplace_back();
    for (double h : hs)
      w.error.back().push_back((integrate(m.step, z0, h, T) - reference).lpNorm<Eigen::Infinity>());
  }
  return w;
}

/// An order fitted where the data show the asymptotic range: the points below `floor` (the
/// reference's error and the round-off of the state, when known) are left out, and then, from
/// the smallest h upwards, every point whose error falls by less than half the typical rate
/// (the median of the local slopes of the points above it) — the round-off plateau, found
/// from the data, never assumed.
struct PlateauFit {
  double slope = std::numeric_limits<double>::quiet_NaN();
  int points = 0;
  std::vector<bool> used;  ///< per input point: in the fit
  double floor = 0;        ///< the floor applied before the plateau search
  int plateau = 0;         ///< points left out as the plateau (beyond the floor)
};

/// The smallest and largest of xs over the points the fit used (+inf and 0 when it used none):
/// the step sizes or errors a report quotes for the fit.
inline std::pair<double, double> used_range(const PlateauFit& f, const std::vector<double>& xs) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  for (std::size_t i = 0; i < xs.size() && i < f.used.size(); ++i)
    if (f.used[i]) {
      lo = std::min(lo, xs[i]);
      hi = std::max(hi, xs[i]);
    }
  return {lo, hi};
}

/// Fit error ≈ C h^p as described at PlateauFit. `floor` < 0: no floor. At least 3 points
/// must remain, else slope is NaN and points the number that remained.
inline PlateauFit fit_order_plateau(const std::vector<double>& h, const std::vector<double>& err,
                                    double floor) {
  PlateauFit f;
  f.floor = floor;
  f.used.assign(h.size(), false);
  std::vector<std::size_t> idx;
  for (std::size_t i = 0; i < h.size(); ++i)
    if (h[i] > 0 && std::isfinite(err[i]) && err[i] > 0 && err[i] > floor) idx.push_back(i);
  std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return h[a] > h[b]; });
  auto local = [&](std::size_t a, std::size_t b) {
    return std::log(err[a] / err[b]) / std::log(h[a] / h[b]);
  };
  while (idx.size() > 3) {
    const std::size_t m = idx.size();
    std::vector<double> slopes;
    for (std::size_t k = 0; k + 2 < m; ++k) slopes.push_back(local(idx[k], idx[k + 1]));
    std::sort(slopes.begin(), slopes.end());
    const double median = slopes[slopes.size() / 2];
    const double last = local(idx[m - 2], idx[m - 1]);
    if (median > 0.5 && last < 0.5 * median) {
      idx.pop_back();
      ++f.plateau;
    } else {
      break;
    }
  }
  f.points = static_cast<int>(idx.size());
  if (idx.size() < 3) return f;
  std::vector<double> hh, ee;
  for (std::size_t i : idx) {
    hh.push_back(h[i]);
    ee.push_back(err[i]);
    f.used[i] = true;
  }
  f.slope = fit_order(hh, ee, 0.0, 3).slope;
  return f;
}

// -------------------------------------------------------------------------------------------
// Symplecticity and reversibility of the one-step map
// -------------------------------------------------------------------------------------------

/// The fourth-order central difference (8(Φ(+d) − Φ(−d)) − (Φ(+2d) − Φ(−2d)))/(12d) of a
/// displaced step `at(s)` (the state after one step from the start moved by s·d). The four
/// steps are taken in one fixed order, −2, +2, −1, +1: the operands of one expression are
/// evaluated in an unspecified order (GCC and clang differ), and a stateful black box would
/// see it. This is the order GCC took when the book's numbers were first measured.
template <class At>
Eigen::VectorXd central_difference(const At& at, double d) {
  const Eigen::VectorXd m2 = at(-2.0), p2 = at(2.0), m1 = at(-1.0), p1 = at(1.0);
  return (8 * (p1 - m1) - (p2 - m2)) / (12 * d);
}

/// Jacobian of the one-step map z ↦ Φ_h(z) by fourth-order central differences with relative
/// increment `delta` in each coordinate (error ~ delta⁴ + (solver tolerance)/delta).
inline Eigen::MatrixXd step_jacobian(const Step& step, const Eigen::VectorXd& z, double h,
                                     double delta = 1e-3) {
  // A time-dependent system's state z = (q, p, t) carries the clock last: the Jacobian is that
  // of the time-t map, the derivatives in (q, p) only (a column fewer).
  const Eigen::Index n = z.size(), cols = n - n % 2;
  Eigen::MatrixXd J(n, cols);
  for (Eigen::Index j = 0; j < cols; ++j) {
    const double d = delta * std::max(1.0, std::abs(z(j)));
    auto at = [&](double s) {
      Eigen::VectorXd w = z;
      w(j) += s * d;
      step(w, h);
      return w;
    };
    J.col(j) = central_difference(at, d);
  }
  return J;
}

/// Result of a defect measurement: the largest defect over the sample states, and the
/// verdict defect <= tolerance.
struct Defect {
  double defect = 0;
  double tolerance = 0;
  int samples = 0;
  bool passed = false;
};

/// Symplecticity: max over the states of |Jᵀ Ω J − Ω|_max, J the Jacobian of Φ_h (by
/// step_jacobian), Ω = [[0, I], [−I, 0]]. A symplectic method gives the difference-quotient
/// error only (about 1e-9 with the default increment); a non-symplectic one of order p
/// gives O(h^{p+1}).
inline Defect symplecticity_defect(const Step& step, const std::vector<Eigen::VectorXd>& states,
                                   double h, double tolerance, double delta = 1e-3) {
  Defect d;
  d.tolerance = tolerance;
  for (const auto& z : states) {
    const Eigen::Index n = z.size() / 2;
    if (z.size() != 2 * n) throw std::invalid_argument("symplecticity_defect: odd state size");
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    W.topRightCorner(n, n) = Eigen::MatrixXd::Identity(n, n);
    W.bottomLeftCorner(n, n) = -Eigen::MatrixXd::Identity(n, n);
    const Eigen::MatrixXd J = step_jacobian(step, z, h, delta);
    d.defect = std::max(d.defect, (J.transpose() * W * J - W).lpNorm<Eigen::Infinity>());
    ++d.samples;
  }
  d.passed = d.defect <= tolerance;
  return d;
}

/// Time reversibility with respect to ρ(q, p) = (q, −p): max over the states of
/// |ρ Φ_h ρ Φ_h (z) − z|_max / max(1, |z|_max). A symmetric method on a reversible system
/// (H even in p) returns to z up to the solver's tolerance.
inline Defect reversibility_defect(const Step& step, const std::vector<Eigen::VectorXd>& states,
                                   double h, double tolerance) {
  Defect d;
  d.tolerance = tolerance;
  for (const auto& z0 : states) {
    const Eigen::Index n = z0.size() / 2;
    Eigen::VectorXd z = z0;
    step(z, h);
    z.tail(n) *= -1;
    step(z, h);
    z.tail(n) *= -1;
    const double scale = std::max(1.0, z0.lpNorm<Eigen::Infinity>());
    d.defect = std::max(d.defect, (z - z0).lpNorm<Eigen::Infinity>() / scale);
    ++d.samples;
  }
  d.passed = d.defect <= tolerance;
  return d;
}

// -------------------------------------------------------------------------------------------
// Long-time energy behaviour
// -------------------------------------------------------------------------------------------

/// Result of energy_behaviour: the envelope max_{k ≤ K} |H_k − H_0| at K = 2^j steps, and its
/// fitted exponent β in envelope ≈ C K^β over the second half of the run (the first steps
/// show the O(h^p) oscillation building up, not the trend). β ≈ 0: bounded (a symplectic
/// method away from resonance); β ≈ 1/2: a random walk of round-off (Brouwer's law);
/// β ≈ 1: a drift.
struct EnergyBehaviour {
  long long steps = 0;
  double h = 0;
  std::vector<double> envelope_steps;
  std::vector<double> envelope;
  double max_error = 0;
  double exponent = std::numeric_limits<double>::quiet_NaN();
  double bounded_below = 0.25;  ///< the verdict "bounded" is exponent < bounded_below
  bool bounded = false;
};

/// One step of a method whose steps need not be of one size (an adaptive method): advance z
/// in place, or return false when the method cannot take the step (then z is left as it was).
using Advance = std::function<bool(Eigen::VectorXd& z)>;

/// Run up to `steps` steps of `advance` from z0 and measure |H − H(z0)|; h is the nominal
/// step, for the report. If `advance` stops early, `steps` in the result is the number taken
/// and the envelope ends there. Memory O(log steps).
inline EnergyBehaviour energy_envelope(const Advance& advance, const Observable& H,
                                       Eigen::VectorXd z, double h, long long steps,
                                       double bounded_below = 0.25) {
  if (steps < 64) throw std::invalid_argument("energy_behaviour: need at least 64 steps");
  EnergyBehaviour r;
  r.steps = steps;
  r.h = h;
  r.bounded_below = bounded_below;
  const double H0 = H(z);
  long long next = 1;
  double env = 0;
  for (long long k = 1; k <= steps; ++k) {
    if (!advance(z)) {
      r.steps = k - 1;
      if (k > 1 && r.envelope_steps.back() != double(k - 1)) {
        r.envelope_steps.push_back(double(k - 1));
        r.envelope.push_back(env);
      }
      break;
    }
    const double e = std::abs(H(z) - H0);
    if (!std::isfinite(e)) {
      env = std::numeric_limits<double>::infinity();
      r.envelope_steps.push_back(double(k));
      r.envelope.push_back(env);
      break;
    }
    env = std::max(env, e);
    if (k == next || k == steps) {
      r.envelope_steps.push_back(double(k));
      r.envelope.push_back(env);
      next *= 2;
    }
  }
  r.max_error = env;
  // Fit over the points with K >= sqrt(steps) (the second half in log K).
  std::vector<double> kk, ee;
  for (std::size_t i = 0; i < r.envelope.size(); ++i)
    if (r.envelope_steps[i] * r.envelope_steps[i] >= double(r.envelope_steps.back())) {
      kk.push_back(r.envelope_steps[i]);
      ee.push_back(r.envelope[i]);
    }
  try {
    r.exponent = fit_order(kk, ee, 0.0, 3).slope;
    r.bounded = std::isfinite(env) && r.exponent < bounded_below;
  } catch (const std::invalid_argument&) {
    r.bounded = false;
  }
  return r;
}

/// Run `steps` steps of size h from z0 and measure |H − H(z0)|. Memory O(log steps).
inline EnergyBehaviour energy_behaviour(const Step& step, const Observable& H, Eigen::VectorXd z,
                                        double h, long long steps, double bounded_below = 0.25) {
  return energy_envelope(
      [&](Eigen::VectorXd& x) {
        step(x, h);
        return true;
      },
      H, std::move(z), h, steps, bounded_below);
}

/// The verdict on the energy, by magnitude first and then by trend, with the numbers that
/// decided it. With r = max |H − H₀| / scale over the run of K steps:
/// - "blows up": r is not finite;
/// - "conserved to round-off": r ≤ roundoff_factor·√K·u (u the unit round-off of double);
/// - "drifts" (envelope exponent β ≥ 0.75) or "grows" (β ≥ 0.25, a random walk above
///   round-off);
/// - "bounded": β < 0.25 and, when a second run at h/2 is given, the error shrinks at least like
///   h^{p − 1/2} (p the expected order); otherwise "bounded, not O(h^p)";
/// - "large": r > large_bound, only when no run at h/2 is given (its scaling, not the size,
///   decides otherwise: a first-order symplectic method's few per cent at h = 0.05 are bounded
///   and O(h), as they should be; chapter "Verify your own integrator", "The criteria of every
///   route").
/// Passed: "conserved to round-off" and "bounded".
struct EnergyVerdict {
  std::string verdict;
  bool passed = false;
  double relative = 0;        ///< r
  double scale = 1;           ///< the energy scale r is relative to
  double roundoff_bound = 0;  ///< roundoff_factor·√K·u
  double large_bound = 0;
  double exponent = std::numeric_limits<double>::quiet_NaN();    ///< β
  double h_exponent = std::numeric_limits<double>::quiet_NaN();  ///< log2(r(h)/r(h/2))
  std::string why;  ///< one line: the numbers that decided it
};

inline EnergyVerdict judge_energy(const EnergyBehaviour& e, double scale, double expected_order,
                                  double half_step_max_error = -1, double roundoff_factor = 64,
                                  double large_bound = 1e-2) {
  EnergyVerdict v;
  v.scale = scale > 0 ? scale : 1;
  v.relative = e.max_error / v.scale;
  v.roundoff_bound =
      roundoff_factor * std::sqrt(double(e.steps)) * std::numeric_limits<double>::epsilon() / 2;
  v.large_bound = large_bound;
  v.exponent = e.exponent;
  char buf[512];
  if (!std::isfinite(v.relative)) {
    v.verdict = "blows up";
    v.why = "the energy error is not finite";
    return v;
  }
  if (v.relative <= v.roundoff_bound) {
    v.verdict = "conserved to round-off";
    v.passed = true;
    std::snprintf(buf, sizeof buf, "relative error %.2e <= %g*sqrt(K)*u = %.2e (K = %lld)",
                  v.relative, roundoff_factor, v.roundoff_bound, e.steps);
    v.why = buf;
    return v;
  }
  if (half_step_max_error <= 0 && v.relative > large_bound) {
    v.verdict = "large";
    std::snprintf(buf, sizeof buf, "relative error %.3g > %g (envelope exponent %.2f)", v.relative,
                  large_bound, e.exponent);
    v.why = buf;
    v.why += " (no run at h/2 to read its scaling: the size decides)";
    return v;
  }
  if (!(e.exponent < 0.25)) {
    v.verdict = e.exponent >= 0.75 ? "drifts" : "grows";
    std::snprintf(buf, sizeof buf,
                  "envelope exponent %.2f (>= %s), relative error %.2e above round-off %.2e",
                  e.exponent, e.exponent >= 0.75 ? "0.75: a drift" : "0.25: a random walk",
                  v.relative, v.roundoff_bound);
    v.why = buf;
    return v;
  }
  if (half_step_max_error > 0 && e.max_error > 0) {
    v.h_exponent = std::log2(e.max_error / half_step_max_error);
    if (v.h_exponent < expected_order - 0.5) {
      v.verdict = "bounded, not O(h^p)";
      std::snprintf(buf, sizeof buf,
                    "no trend (exponent %.2f), but the error shrinks like h^%.2f from h to h/2, "
                    "not h^%g",
                    e.exponent, v.h_exponent, expected_order);
      v.why = buf;
      return v;
    }
  }
  v.verdict = "bounded";
  v.passed = true;
  if (std::isfinite(v.h_exponent))
    std::snprintf(buf, sizeof buf,
                  "no trend (envelope exponent %.2f < 0.25), relative error %.2e, shrinking like "
                  "h^%.2f",
                  e.exponent, v.relative, v.h_exponent);
  else
    std::snprintf(buf, sizeof buf, "no trend (envelope exponent %.2f < 0.25), relative error %.2e",
                  e.exponent, v.relative);
  v.why = buf;
  return v;
}

}  // namespace vibook::verify
