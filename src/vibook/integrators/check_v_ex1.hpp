/// \file check_v_ex1.hpp
/// \brief Claim V-EX1 measurements, shared by the ledger check and its doctest.
///
/// Chapter: \ref chapter-vi.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "vibook/core/tolerance.hpp"

namespace vibook::checks {

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

/// Measured order of one method: fitted slope, expected order, step sizes used.
struct MeasuredOrder {
  std::string method;
  double expected = 0;
  double slope = 0;
  int points = 0;
};
/// Two-sided order criterion of the test suite: |slope − p| < 0.1.
inline constexpr double kOrderTolerance = 0.1;

/// Global error at T = 3 on Kepler e = 0.5 (nonlinear) against the exact solution, for
/// h = 3/64 ... 3/4096, errors below 1e-11 (round-off plateau) not fitted.
std::vector<MeasuredOrder> kernel_orders();

/// Vermeeren Prop. 1: the discrete Euler–Lagrange expression D2 L_d(x(t−h), x(t)) +
/// D1 L_d(x(t), x(t+h)), divided by h, evaluated on the exact Kepler solution (where the
/// Euler–Lagrange expression vanishes), as h → 0: its fitted order for each discrete
/// Lagrangian of Example 1.
std::vector<MeasuredOrder> del_consistency_orders();

}  // namespace vibook::checks
