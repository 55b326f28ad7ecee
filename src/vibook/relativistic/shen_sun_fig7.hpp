/// \file shen_sun_fig7.hpp
/// \brief Relativistic Kepler measurements shared by the ledger checks and their doctests.
///
/// Chapter: \ref chapter-relativistic.
#pragma once

#include <array>
#include <vector>

#include "vibook/core/types.hpp"

namespace vibook::checks {

/// The speed of light chosen for Fig. 7 (the paper gives none): the precession is visible.
inline constexpr double kFig7SpeedOfLight = 5.0;
/// The speeds of light of the precession sweep, from strongly relativistic to nearly Newtonian.
inline constexpr std::array<double, 7> kSweepSpeeds = {2.0, 3.0, 5.0, 10.0, 20.0, 50.0, 100.0};

/// One-step comparisons along 800 steps from the Fig. 7 data (see check-ss-t8).
struct SsT8Measurement {
  double vi322_vs_composition = 0, generic_vs_composition = 0, printed_319_vs_composition = 0;
  double bound = 0;  ///< round-off bound 64ε(|u| + |t||∇φ|), the largest along the run
  int max_newton_iterations = 0;
  /// (t, x₁, x₂) after each step of the composition, from the start (steps + 1 entries): the
  /// two-step equations of Theorem 8 are evaluated along it.
  std::vector<std::array<double, 3>> trajectory;
};
SsT8Measurement ss_t8_measure(double c, double h, int steps);

}  // namespace vibook::checks
