/// \file check_v_ex1.hpp
/// \brief Claim V-EX1 measurements, shared by the ledger check and its doctest.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "vibook/core/tolerance.hpp"

namespace vibook::figures {

/// Agreement between a fast kernel and the generic solver on the kernel's discrete Lagrangian.
struct KernelAgreement {
  double one_step = 0.0;    ///< max one-step difference, relative to |q| + |p|
  double trajectory = 0.0;  ///< difference of the two trajectories at the end, relative
  int max_iterations = 0;   ///< most Newton iterations the generic solver took
  double max_residual = 0.0;
};

/// "To round-off" for one step: 64 ulps of the state. Fixed before measuring; the truncation
/// error of any of these methods at h = 0.05 is above 1e-5, eleven orders larger.
inline constexpr double kOneStepTolerance = 64 * kEps;
/// The trajectories separate by accumulated round-off only: 400 steps × 64 ulps.
inline constexpr double kTrajectoryTolerance = 400 * 64 * kEps;

/// For each "problem/method": agreement over 400 steps of h = 0.05.
std::vector<std::pair<std::string, KernelAgreement>> v_ex1_agreements();

/// |−D1 L_disc| / |p| with Vermeeren's scaling L_disc ≈ L; equals 1/h.
double v_ex1_literal_scaling_factor();

}  // namespace vibook::figures
