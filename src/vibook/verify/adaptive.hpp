/// \file adaptive.hpp
/// \brief Any fixed-step discrete Lagrangian run as an energy-preserving adaptive variational
/// integrator: Sharma et al. 2022, §2.2, the extended discrete Lagrangian with the step as a
/// variable, L_d(t0, q0, t1, q1) = L_d(q0, q1, t1 − t0), marched by (15)–(18) with the energy
/// condition (16). For the midpoint L_d this is EpAVI, (25); for any other L_d it is the
/// construction the paper applies to (25), applied to the user's method.
///
/// Chapter: \ref chapter-verify (section "Beyond Sharma: your L_d as an EpAVI").
#pragma once

#include <cmath>
#include <limits>
#include <string>

#include <fmt/format.h>

#include "vibook/core/errors.hpp"
#include "vibook/core/types.hpp"
#include "vibook/mechanics/extended.hpp"
#include "vibook/verify/verify.hpp"

namespace vibook::verify {

// [extended-from-fixed]
// Sharma et al. 2022, §2.2: a fixed-step L_d(q0, q1, h) made an extended discrete Lagrangian
// by letting the step be the difference of the two times, h = t1 − t0 (as (25) does for the
// midpoint rule). It depends on the times only through t1 − t0, so the discrete energy
// E_k = −D3 L_d is the quantity (16) keeps.
template <class FixedStepLd>
auto extended_from_fixed(FixedStepLd ld) {
  return [ld = std::move(ld)](const auto& t0, const auto& q0, const auto& t1,
                              const auto& q1) -> scalar_t<decltype(t0)> {
    using S = scalar_t<decltype(t0)>;
    return ld(q0, q1, S(t1 - t0));
  };
}
// [extended-from-fixed]

/// Where an adaptive run stopped because the energy equation (16) had no admissible root: the
/// step, the time, the solver's message, and the scan of D1 L_d − E_k over Δt at that state
/// (as the EpAVI chapter does): no sign change within the factor the step searches (64 of the
/// predicted step) means a fold, a root that has disappeared, not one the solver missed.
struct AdaptiveFailure {
  bool happened = false;
  long long step = 0;  ///< the step that could not be taken (1 = the start-up step)
  double t = 0;        ///< the time it starts from
  std::string message;
  double scan_lo = 0, scan_hi = 0;  ///< the scanned Δt range
  int scan_points = 0;              ///< points of the scan where the momentum equation solved
  int sign_changes = 0;             ///< within the factor max_ratio (64) of the predicted step
  int far_sign_changes = 0;         ///< farther out: roots EpAVI never takes (not the motion's)
  double far_root = std::numeric_limits<double>::quiet_NaN();      ///< the first of those
  double scan_min_abs = std::numeric_limits<double>::quiet_NaN();  ///< min |D1 L_d − E_k|
  double scan_min_dt = std::numeric_limits<double>::quiet_NaN();
};

/// The measurements of one adaptive run.
struct AdaptiveStudy {
  EnergyBehaviour energy;  ///< |H − H(z0)| of the intended system along the run
  long long steps_taken = 0;
  double t_reached = 0;
  double dt_min = std::numeric_limits<double>::infinity(), dt_max = 0;
  double E1 = 0;                     ///< the discrete energy fixed by the start-up step
  double discrete_energy_drift = 0;  ///< max_k |E_k − E_1|
  double max_energy_residual = 0, max_momentum_residual = 0;
  double mean_root_evaluations = 0, mean_newton_iterations = 0;
  Eigen::VectorXd z_end;  ///< (q, p) after the last step taken
  AdaptiveFailure failure;
};

/// Run the fixed-step L_d(q0, q1, h) (N-dimensional, generic in its scalar) as an EpAVI from
/// z0 = (q0, p0): a start-up step of length h0 to q1 (taken from an accurate solution of the
/// intended system), then up to `steps` − 1 steps of (15)–(18). H is the intended system's
/// energy in (q, p). A step the energy equation cannot take ends the run and is recorded in
/// `failure` when the scan around the previous step finds no sign change (a fold); when the
/// scan finds one, the solver missed a root, and the SolveError is rethrown with the scan's
/// finding (a numerical failure, not a property of the method).
template <int N, class FixedStepLd>
AdaptiveStudy epavi_study(const FixedStepLd& ld, const Observable& H, const Eigen::VectorXd& z0,
                          const Vec<double, N>& q1, double h0, long long steps) {
  using Ext = decltype(extended_from_fixed(ld));
  using Integrator = ExtendedDelIntegrator<N, Ext>;
  typename Integrator::Options opt;
  opt.time_translation_invariant = true;
  Integrator vi(extended_from_fixed(ld), opt);
  ExtendedState<N> s;
  AdaptiveStudy a;
  long long root_evaluations = 0, newton_iterations = 0, solved = 0;
  auto advance = [&](Eigen::VectorXd& z) -> bool {
    if (a.failure.happened) return false;
    if (a.steps_taken == 0) {
      const Vec<double, N> q0 = z.head<N>();
      s = vi.start(0.0, q0, h0, q1);
      a.E1 = s.E;
      a.dt_min = a.dt_max = h0;
    } else {
      const ExtendedState<N> k = s;
      try {
        const ExtendedStepReport r = vi.step(s);
        root_evaluations += r.root_iterations;
        newton_iterations += r.newton_iterations;
        ++solved;
        a.max_energy_residual = std::max(a.max_energy_residual, r.energy_residual);
        a.max_momentum_residual = std::max(a.max_momentum_residual, r.momentum_residual);
      } catch (const SolveError& e) {
        AdaptiveFailure& f = a.failure;
        f.step = a.steps_taken + 1;
        f.t = k.t;
        f.message = e.what();
        // Scan D1 L_d − E_k over three decades either side of the predicted step. A sign
        // change within the factor max_ratio the step searches is a root it missed; one
        // farther out is a root the method never takes (the EpAVI chapter's spurious root,
        // a few hundred times the physical step), noted but not the continuation.
        const double center = vi.history().predicted_step();
        const double ratio = vi.options().max_ratio;
        f.scan_lo = center * 1e-3;
        f.scan_hi = center * 1e3;
        double prev = std::numeric_limits<double>::quiet_NaN(), prev_dt = prev;
        double crossing = prev;
        for (int i = 0; i <= 600; ++i) {
          const double dt = f.scan_lo * std::pow(10.0, i / 100.0);
          double g = std::numeric_limits<double>::quiet_NaN();
          try {
            g = vi.energy_equation(k, dt, k.E);
          } catch (const SolveError&) {
          }
          if (!std::isfinite(g)) continue;
          ++f.scan_points;
          if (!(std::abs(g) >= f.scan_min_abs)) f.scan_min_abs = std::abs(g), f.scan_min_dt = dt;
          if (std::isfinite(prev) && (g < 0) != (prev < 0)) {
            const double root = std::sqrt(dt * prev_dt);
            if (root >= center / ratio && root <= center * ratio) {
              ++f.sign_changes;
              if (!std::isfinite(crossing)) crossing = root;
            } else {
              ++f.far_sign_changes;
              if (!std::isfinite(f.far_root)) f.far_root = root;
            }
          }
          prev = g;
          prev_dt = dt;
        }
        if (f.sign_changes > 0 || f.scan_points == 0)
          throw SolveError(
              fmt::format("adaptive step {} at t = {:.6g}: {}; {}", f.step, f.t, f.message,
                          f.scan_points == 0
                              ? "the momentum equation (15) has no solution at any step scanned"
                              : fmt::format("the energy equation changes sign near Δt = {:.3g} "
                                            "(a root the solver did not reach)",
                                            crossing)),
              e.report());
        f.happened = true;
        s = k;
        return false;
      }
      const double dt = vi.last_step();
      a.dt_min = std::min(a.dt_min, dt);
      a.dt_max = std::max(a.dt_max, dt);
    }
    ++a.steps_taken;
    a.t_reached = s.t;
    a.discrete_energy_drift = std::max(a.discrete_energy_drift, std::abs(s.E - a.E1));
    z.head<N>() = s.q;
    z.tail<N>() = s.p;
    a.z_end = z;
    return true;
  };
  a.energy = energy_envelope(advance, H, z0, h0, steps);
  if (solved > 0) {
    a.mean_root_evaluations = double(root_evaluations) / double(solved);
    a.mean_newton_iterations = double(newton_iterations) / double(solved);
  }
  return a;
}

}  // namespace vibook::verify
