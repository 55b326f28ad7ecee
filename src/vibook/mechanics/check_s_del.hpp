/// \file check_s_del.hpp
/// \brief Claim S-DEL measurements, shared by the ledger check and its doctest.
///
/// Chapter: \ref chapter-extended.
#pragma once

#include <limits>

#include "vibook/core/tolerance.hpp"

namespace vibook::checks {

// [s-del-criterion]
/// "To round-off" for the two-step residual: 64 ulps of |p| + |E|, fixed before measuring.
inline constexpr double kSDelTolerance = 64 * kEps;
// [s-del-criterion]

struct SDelMeasurement {
  double two_step_residual = 0;      ///< max |(11), (12)| / (|p| + |E|) along the run
  double printed_eq14_residual = 0;  ///< (16) with (14) as printed, same scale
  double energy_drift = 0;           ///< max |E_k − E_1| / |E_1|
  double discrete_energy = 0, continuous_energy = 0;
  double min_step = std::numeric_limits<double>::infinity(), max_step = 0;
  double max_energy_residual = 0;  ///< max |D1 L_d − E_k| of the step solves
  int max_iterations = 0;          ///< most energy-equation evaluations in one step
};

SDelMeasurement s_del_kepler(int steps);
SDelMeasurement s_del_pendulum(int steps);

}  // namespace vibook::checks
