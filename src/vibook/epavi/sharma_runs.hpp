/// \file sharma_runs.hpp
/// \brief Runs of EpAVI (any precision) and AVI1/AVI2 on Kepler from perihelion, as used by the
/// Sharma et al. 2022 studies (Figs. 3–5, (29), the existence map): statistics of one run and
/// an optional decimated CSV stream. Memory is constant in the number of steps.
///
/// Chapter: \ref chapter-epavi.
#pragma once

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <ostream>
#include <string>

#include "vibook/avi/avi.hpp"
#include "vibook/core/errors.hpp"
#include "vibook/core/precision.hpp"
#include "vibook/core/recorder.hpp"
#include "vibook/epavi/epavi.hpp"
#include "vibook/epavi/mechanical.hpp"
#include "vibook/kepler/kepler.hpp"

namespace vibook::checks {

/// Statistics of one adaptive run on Kepler. Energies: dEd = E_k − E_1 (EpAVI's discrete
/// energy; formed in the run's precision), dH = H(q_k, p_k) − H_0 (continuous).
struct AdaptiveRun {
  long long steps = 0;
  double t_end = 0;
  double mean_step = 0, max_step = 0, min_step = std::numeric_limits<double>::infinity();  // /h0
  double max_dEd = 0, final_dEd = 0;  ///< max |E_k − E_1| and the signed final value
  double max_jump = 0;                ///< max_i |E_i − E_{i−1}|
  double sum_abs_jump = 0;            ///< Σ_i |E_i − E_{i−1}|
  double max_dH = 0;
  double max_residual = 0;     ///< largest energy-equation residual reported by a step
  double mean_iterations = 0;  ///< root-finder evaluations (EpAVI) or Newton iterations (AVI)
  std::optional<std::string> failure;  ///< the SolveError message, if the run stopped early
  double failure_t = NAN;
};

/// Columns of the CSV written by the runs: a = k·h0 (fictitious time with t'(0) = 1), t,
/// h_k/h0, E_k − E_1 (EpAVI; 0 for AVI), H − H0.
inline const std::vector<std::string>& adaptive_columns() {
  static const std::vector<std::string> c = {"a", "t", "h_over_h0", "dE_d", "dH"};
  return c;
}

/// EpAVI in precision T from the perihelion of the orbit with eccentricity e, first step h0
/// from the exact solution, until t ≥ t_end. A SolveError ends the run (recorded, not thrown).
/// The studies run the closed-form stepper (epavi/mechanical.hpp); it takes the generic path's
/// options and hands it any step it cannot take.
template <class T>
AdaptiveRun run_epavi(double e, double h0, double t_end, typename EpAVI<Kepler, T>::Options opt,
                      std::ostream* csv = nullptr, std::int64_t every = 1) {
  const KeplerOrbit orbit = KeplerOrbit::perihelion(e);
  const State<2> s0 = kepler_perihelion_state(e);
  const double H0 = energy(Kepler{}, s0.q, s0.p);
  auto lift = [](const Vec<double, 2>& v) { return Vec<T, 2>(T(v(0)), T(v(1))); };
  MechanicalEpAVI<Kepler, T> m{Kepler{}, opt};
  auto s = m.start(T(0), lift(s0.q), T(h0), lift(orbit.at(h0).q));
  const T E1 = s.E;
  std::optional<TrajectoryRecorder> rec;
  if (csv) rec.emplace(*csv, adaptive_columns(), every);
  AdaptiveRun r;
  double sum = 1, its = 0;
  r.steps = 1;
  r.max_step = r.min_step = 1;
  T E_prev = s.E;
  try {
    while (s.t < T(t_end)) {
      const T t0 = s.t;
      const ExtendedStepReport rep = m.step(s);
      ++r.steps;
      const double h = to_double(T((s.t - t0) / T(h0)));
      sum += h;
      its += rep.root_iterations;
      r.max_step = std::max(r.max_step, h);
      r.min_step = std::min(r.min_step, h);
      const double jump = std::abs(to_double(T(s.E - E_prev)));
      E_prev = s.E;
      r.max_jump = std::max(r.max_jump, jump);
      r.sum_abs_jump += jump;
      const double dEd = to_double(T(s.E - E1));
      r.max_dEd = std::max(r.max_dEd, std::abs(dEd));
      r.max_residual = std::max(r.max_residual, rep.energy_residual);
      if (rec && (rec->due(r.steps) || !(s.t < T(t_end)))) {
        const Vec<double, 2> q(to_double(s.q(0)), to_double(s.q(1)));
        const Vec<double, 2> p(to_double(s.p(0)), to_double(s.p(1)));
        rec->offer(r.steps, std::array<double, 5>{double(r.steps) * h0, to_double(s.t), h, dEd,
                                                  energy(Kepler{}, q, p) - H0});
      }
      if (r.steps % 16 == 0 || !(s.t < T(t_end))) {  // H in double: sampled, cheap
        const Vec<double, 2> q(to_double(s.q(0)), to_double(s.q(1)));
        const Vec<double, 2> p(to_double(s.p(0)), to_double(s.p(1)));
        r.max_dH = std::max(r.max_dH, std::abs(energy(Kepler{}, q, p) - H0));
      }
    }
  } catch (const SolveError& err) {
    r.failure = err.what();
    r.failure_t = to_double(s.t);
  }
  if (rec) rec->finish();
  r.t_end = to_double(s.t);
  r.final_dEd = to_double(T(s.E - E1));
  r.mean_step = sum / double(r.steps);
  r.mean_iterations = its / double(std::max<long long>(1, r.steps - 1));
  return r;
}

/// AVI (Schmitt–Leok implicit midpoint with monitor g; Δa such that the first step is h0).
template <class Monitor>
AdaptiveRun run_avi(double e, double h0, double t_end, Monitor g, std::ostream* csv = nullptr,
                    std::int64_t every = 1) {
  const State<2> s0 = kepler_perihelion_state(e);
  const double H0 = energy(Kepler{}, s0.q, s0.p);
  AdaptiveMidpoint<Kepler, Monitor> m(Kepler{}, g);
  TimedState<2> s{0.0, s0.q, s0.p};
  const double da = m.step_for_first_step(s, h0);
  std::optional<TrajectoryRecorder> rec;
  if (csv) rec.emplace(*csv, adaptive_columns(), every);
  AdaptiveRun r;
  double sum = 0, its = 0;
  try {
    while (s.t < t_end) {
      const double t0 = s.t;
      const SolveReport rep = m.step(s, da);
      ++r.steps;
      const double h = (s.t - t0) / h0;
      sum += h;
      its += rep.iterations;
      r.max_step = std::max(r.max_step, h);
      r.min_step = std::min(r.min_step, h);
      const double dH = energy(Kepler{}, s.q, s.p) - H0;
      r.max_dH = std::max(r.max_dH, std::abs(dH));
      r.max_residual = std::max(r.max_residual, rep.residual);
      if (rec) rec->offer(r.steps, std::array<double, 5>{double(r.steps) * h0, s.t, h, 0.0, dH});
    }
  } catch (const SolveError& err) {
    r.failure = err.what();
    r.failure_t = s.t;
  }
  if (rec) rec->finish();
  r.t_end = s.t;
  r.mean_step = sum / double(std::max<long long>(1, r.steps));
  r.mean_iterations = its / double(std::max<long long>(1, r.steps));
  return r;
}

}  // namespace vibook::checks
