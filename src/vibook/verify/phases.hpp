/// \file phases.hpp
/// \brief The criteria every route of `vibook verify` judges by, in one place: symplecticity,
/// symmetry and reversibility of a one-step map judged by how their defects scale with the
/// step, the reversing symmetry of the intended system, and consistency. The map study
/// (map_study.hpp: --method, --tableau, --composition, the black boxes, the field audit) and the
/// typed discrete Lagrangian's route (--ld) both call these, so a method gets the same verdict
/// whichever door it came in by.
///
/// Chapter: \ref chapter-verify, section "The criteria of every route".
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "vibook/verify/verify.hpp"

namespace vibook::verify {

/// A defect of the one-step map measured at the step sizes h·2^k, k = 0, 1, …, judged by its
/// resolution and its growth (chapter "The criteria of every route"): the verdict is NO when a
/// defect is resolved (defect > resolution_factor × its resolution) and grows from the
/// smallest step to the largest resolved one at least like h^growth_threshold (1/2: it grows
/// with h at all; a consistent method's defect grows like h^(p+1) ≥ h², a system's lack of the
/// reversing symmetry like h, and the difference quotients' error is inside the resolution), the
/// smallest
/// step's value taken as max(defect, resolution), so that the exponent is a lower bound.
struct ScalingJudgement {
  std::vector<double> h;           ///< the step sizes tried
  std::vector<double> defect;      ///< NaN where the method could not take the step
  std::vector<double> resolution;  ///< what the measurement cannot tell from zero there
  std::vector<std::string> error;  ///< why a step size has no defect (empty otherwise)
  bool resolved = false;           ///< some defect above resolution_factor × its resolution
  double growth = std::numeric_limits<double>::quiet_NaN();  ///< lower bound of the exponent
  double growth_threshold = 0.5, resolution_factor = 10;
  bool passed = true;
  std::string why;  ///< one line: what decided

  /// "h = 0.05: 1.2e-14 (res 3e-13), …"
  std::string shown() const;
  nlohmann::json to_json() const;
};

/// Judge `j` (h, defect, resolution filled) in place; returns it.
ScalingJudgement& judge_scaling(ScalingJudgement& j);

/// The number of step sizes h, 2h, 4h, 8h at which each scaling test is made.
constexpr int kScalingSizes = 4;

/// The largest resolution at which a Jacobian is taken as measured (symplecticity_by_scaling).
constexpr double kMaxResolution = 1e-4;

/// Symplecticity: D(h) = |JᵀΩJ − Ω|_max / max(1, |J|_max²), J by fourth-order central
/// differences at the relative increment 1e-3; its resolution from a second Jacobian at twice
/// the increment, N = 4n |J_δ − J_2δ|_max / max(1, |J|_max), at least 2^10 u; a resolution above
/// kMaxResolution at any size is a NO (the Jacobian cannot be measured). The largest over `states`
/// at each size. A step size at which the method fails (NumericalError) is left out; the smallest
/// must succeed (its error propagates).
/// With `tangent` (a constrained system: an orthonormal basis U of the tangent space of the
/// constraint manifold at a state, as columns), the test is that of the map restricted to the
/// manifold: D(h) = |(JU)ᵀΩ(JU) − UᵀΩU|_max / max(1, |JU|_max²), JU by the same differences
/// along U's columns (increment relative to max(1, |z|_max)).
using TangentBasis = std::function<Eigen::MatrixXd(const Eigen::VectorXd&)>;
ScalingJudgement symplecticity_by_scaling(const Step& step,
                                          const std::vector<Eigen::VectorXd>& states, double h,
                                          int sizes = kScalingSizes,
                                          const TangentBasis& tangent = {});

/// A constraint kept by the map: the largest `residual` over `steps` steps from z0 at each step
/// size h·2^k, with the resolution 2^10 u max(1, |z|_max)² over the run (a quadratic constraint
/// evaluated at a state of that size, as a solve to round-off leaves it; the residual does not
/// accumulate, each step solves for it anew). A method that keeps the constraint leaves
/// round-off; one that does not leaves a residual that grows with h.
ScalingJudgement constraint_by_scaling(const Step& step, const Eigen::VectorXd& z0, double h,
                                       long long steps, const Observable& residual,
                                       int sizes = kScalingSizes);

/// Symmetry: |Φ_{−h}(Φ_h(z)) − z|_max / max(1, |z|_max), resolution 2^12 u max(1, |J|_max) with
/// J the Jacobian of one step (the round-off of two solves amplified by the map).
ScalingJudgement symmetry_by_scaling(const Step& step, const std::vector<Eigen::VectorXd>& states,
                                     double h, int sizes = kScalingSizes);

/// The reversing symmetry ρ in place: (q, p) ↦ (q, −p), and (q, p, t) ↦ (q, −p, −t) for the
/// state of a time-dependent system (its clock last).
void reverse_momenta(Eigen::VectorXd& z);

/// A state of a time-dependent system carries its time last (z = (q, p, t), an odd size): the
/// symplecticity test reads the time-t map's Jacobian in (q, p), ρ reverses t too, and the
/// symmetry test steps back in time with the step.

/// Reversibility under ρ(q, p) = (q, −p): |ρΦ_hρΦ_h(z) − z|_max / max(1, |z|_max), with the
/// resolution of symmetry_by_scaling.
ScalingJudgement reversibility_by_scaling(const Step& step,
                                          const std::vector<Eigen::VectorXd>& states, double h,
                                          int sizes = kScalingSizes);

/// Does the intended system have the reversing symmetry ρ(q, p) = (q, −p)? H(q, −p) = H(q, p)
/// within 1e-12 relative at each of `states` and at each with its momenta scaled by 1/2 and 2.
/// `why` says which state broke it.
struct ReversingSymmetry {
  bool holds = true;
  std::string why;
};
ReversingSymmetry momentum_reversal(const Observable& H,
                                    const std::vector<Eigen::VectorXd>& states);

/// Consistency: a method whose exact conditions give an order below 1, or whose measured order
/// is below 1/2, is not consistent and never passes (chapter "The criteria of every route").
/// `conditions_order` NaN where there are no exact conditions; `measured` NaN where no order was
/// measured.
struct ConsistencyJudgement {
  bool passed = true;
  std::string why;
};
ConsistencyJudgement judge_consistency(double conditions_order, double measured);

}  // namespace vibook::verify
