/// \file constrained.hpp
/// \brief Constrained mechanical systems for `vibook verify` (chapter "Verify your own
/// integrator", section "Constrained systems"): H = |p|²/2 + V(q) on the cotangent bundle of
/// Q = {q : g(q) = 0}, with m holonomic constraints g in Cartesian coordinates, and the
/// RATTLE method (Andersen 1983; Leimkuhler & Skeel 1994; HLW §VII.1.4) measured on it by the
/// map study: the order against the index-1 equations integrated in double-double, the
/// position constraint g(q) = 0 and the hidden constraint G(q) p = 0 (G = ∂g/∂q) along runs,
/// symplecticity of the map restricted to the tangent space of the constraint manifold,
/// symmetry, reversibility and the energy.
#pragma once

#include <string>
#include <vector>

#include "vibook/verify/expression.hpp"
#include "vibook/verify/map_study.hpp"

namespace vibook::verify {

/// A test problem with constraints: its name, H and g as printed, and an initial state on the
/// constraint manifold (g(q0) = 0 and G(q0) p0 = 0 to rounding).
struct ConstrainedProblem {
  std::string name, hamiltonian, constraints;
  std::vector<double> q0, p0;
  /// The same system in the expression language (--potential and --constraint texts): it is
  /// stepped and measured through them, as a typed system is.
  std::string potential;
  std::vector<std::string> constraint_texts;
};

/// The spherical pendulum (q ∈ R³, |q| = 1, V = q₃) and the planar double pendulum in the
/// Cartesian positions of its two bobs (q ∈ R⁴, unit lengths and masses, V = y₁ + y₂).
const std::vector<ConstrainedProblem>& constrained_problems();

/// The constrained problem of that name, or nullptr.
const ConstrainedProblem* find_constrained_problem(const std::string& name);

/// RATTLE on `problem` from (q0, p0), measured by measure_map (`study` holds the measurement
/// settings), appended to `rep`. With `project_velocity` false the method is RATTLE's first
/// half alone, the momentum left unprojected on the hidden constraint (`shake`: SHAKE's
/// positions with velocities that leave the cotangent bundle; a deliberately wrong method).
/// An ArgumentError naming --q0 or --p0 when the state is not on the manifold (residual above
/// 1e-10); the constraint forces' solves report their residual and iterations in a SolveError.
void measure_constrained(const ConstrainedProblem& problem, bool project_velocity,
                         const std::vector<double>& q0, const std::vector<double>& p0,
                         MapStudy study, MapMeasurement& rep);

/// The most positions a typed constrained system takes (each dimension is compiled apart).
inline constexpr int kMaxConstrainedDim = 4;

/// What steps a typed constrained system (measure_constrained_typed).
enum class ConstrainedStep {
  rattle,  ///< RATTLE (H = |p|²/2 + V)
  shake,   ///< RATTLE without the velocity projection (deliberately wrong)
  del      ///< the constrained discrete Euler–Lagrange equations of the typed --ld
};

/// The texts a typed constrained system was given by, for the report and the JSON.
struct ConstrainedTexts {
  std::string potential, ld;
};

/// A typed constrained system (`--potential` with `--constraint`, 2 to kMaxConstrainedDim
/// positions, at least one and fewer constraints than positions; `sys` holds them) from (q0, p0),
/// stepped by RATTLE, by its unprojected variant, or by the constrained discrete Euler–Lagrange
/// equations of the typed --ld (Marsden & West 2001, §3.5, with multipliers λ for the positions and
/// μ projecting the momentum onto the hidden constraint), measured by measure_map like the test
/// problems (`study` holds the settings; for `del` its symmetric_claimed is kept, RATTLE is
/// symmetric). An ArgumentError naming --q0 or --p0 when the state is off the manifold, naming
/// --constraint for a count or dimension out of range. `sys` must outlive the call.
void measure_constrained_typed(const TypedDiscreteLagrangian& sys, const ConstrainedTexts& texts,
                               ConstrainedStep step, const std::vector<double>& q0,
                               const std::vector<double>& p0, MapStudy study, MapMeasurement& rep);

/// The system part of a study on a typed constrained system (as measure_constrained_typed
/// sets it: z0, the index-1 reference in double-double, the energy, the constraint residuals and
/// the tangent space of T*Q), for a map set by someone else (a black-box stepper). The same
/// ArgumentErrors. `sys` must outlive the study.
/// `where` ends the messages of a state off the manifold.
void set_constrained_typed_system(MapStudy& study, const TypedDiscreteLagrangian& sys,
                                  const std::string& potential, const std::vector<double>& q0,
                                  const std::vector<double>& p0,
                                  const std::string& where = "of the --constraint equations");

struct CompositionSpec;  // verify/composition_study.hpp

/// A composition of RATTLE steps (`vibook verify --composition rattle --coefficients …` with
/// --potential and --constraint; Reich 1996): the stages of `spec` (a catalogue entry or a
/// typed list; an adjoint stage is RATTLE again, RATTLE being symmetric) each a whole RATTLE
/// step of size γ_i h on the typed constrained system, measured by measure_composition with the
/// phases of measure_constrained_typed (its constraint residuals, symplecticity on the
/// manifold, the index-1 reference); the variational order is not measured. The same
/// ArgumentErrors as measure_constrained_typed. `given` names where the system came from in
/// the report ("--potential", or a constrained test problem). `sys` must outlive the call.
void measure_constrained_composition(const CompositionSpec& spec,
                                     const TypedDiscreteLagrangian& sys,
                                     const std::string& potential, const std::vector<double>& q0,
                                     const std::vector<double>& p0, MapStudy study,
                                     MapMeasurement& rep, const std::string& given = "--potential");

/// RATTLE (`project`) or its unprojected variant on the typed constrained system, as a study's
/// map (z = (q, p)); the multipliers' solves report residual and iterations in a SolveError.
/// `sys` must outlive it.
Step typed_rattle_step(const TypedDiscreteLagrangian& sys, const std::string& potential,
                       bool project);

}  // namespace vibook::verify
