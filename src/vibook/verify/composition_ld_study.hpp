/// \file composition_ld_study.hpp
/// \brief A composition built on the user's own typed discrete Lagrangian (`vibook verify
/// --composition ld`), measured by the composition study. Internal: not installed.
///
/// Chapter: \ref chapter-verify (section "Compositions").
#pragma once

#include <string>
#include <vector>

#include "vibook/verify/composition_study.hpp"
#include "vibook/verify/expression.hpp"
#include "vibook/verify/method_symbolic.hpp"

namespace vibook::verify {

/// The texts of a composition of a typed discrete Lagrangian (`--composition ld`) and the
/// system it is measured on (--potential, --lagrangian or --hamiltonian, as typed; the report
/// and the JSON name them), from (q0, p0).
struct TypedLdSystem {
  std::string ld, potential, lagrangian, hamiltonian;
  std::vector<double> q0, p0;
};

/// Measure the composition `spec` built on the typed discrete Lagrangian `dl` (1 to 3 degrees of
/// freedom): whether L_d is symmetric (by the engine, else at 16 random points to 1e-13
/// relative), its variational order derived by the engine where `symbolic` allows, then every
/// phase of measure_composition on the typed system (the Legendre transform of a typed
/// Lagrangian, else Hamilton's equations of the typed H). A splitting (spec.flows) is stepped
/// by its explicit flows on H = |p|²/2 + V. With the settings of `study` (its step and
/// measurement options); appended to `rep`. `dl` must outlive the call.
void measure_ld_composition(CompositionSpec spec, const TypedDiscreteLagrangian& dl,
                            const TypedLdSystem& system, const MapStudy& study,
                            SymbolicUse symbolic, MapMeasurement& rep);

/// The stage discrete Lagrangian a splitting on a typed potential is measured with (symplectic
/// Euler's, drift then kick, whose value gives the variational order): with V(q1), or for a
/// time-dependent V its kinetic part alone (the variational order is then not measured, and V
/// has no time inside an L_d).
std::string splitting_stage_ld(bool time_dependent);

/// A typed discrete Lagrangian of a time-dependent system, L_d(t, q0, q1, h) with t the step's
/// start time (`vibook verify --ld` when a text uses t; chapter "Verify your own integrator",
/// section "Time-dependent systems"): its discrete Euler–Lagrange step p0 = −D1 L_d(t, q0, q1,
/// h), p1 = D2 L_d(t, q0, q1, h) (Newton on nested AutoDiff of the tree) as the map of a study
/// whose state carries the clock (MapStudy::timed), measured by measure_map against the typed
/// system (Hamilton's equations of H(q, p, t), or the Euler–Lagrange equations of L(q, v, t)).
/// `dl` must have a Hamiltonian or a Lagrangian (not only a potential) and a time-dependent
/// system (an ArgumentError naming --ld when only L_d uses t). Appended to `rep`.
void measure_timed_ld(const TypedDiscreteLagrangian& dl, const TypedLdSystem& system,
                      const MapStudy& study, MapMeasurement& rep);

}  // namespace vibook::verify
