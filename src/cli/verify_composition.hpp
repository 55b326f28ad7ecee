// `vibook verify --composition BASE --coefficients NAME|LIST`: a composition method judged by
// its order conditions (at 120 digits), its measured order against an independent reference,
// symplecticity, reversibility and energy (verify_composition.cpp).
#pragma once

#include <string>

#include "study_options.hpp"
#include "vibook/verify/composition_study.hpp"

namespace vibook::cli {

/// The options of a composition verification, as typed; `given` flags say which the user set
/// (the defaults of the step sizes depend on the expected order).
struct CompositionOptions : StudyOptions {
  std::string base, coefficients;
  std::string splitting;  ///< --splitting: a catalogue name or the flows (the base is then se)
  /// --composition ld: the typed discrete Lagrangian and the system, as for --ld
  std::string ld, potential, lagrangian, hamiltonian, dim;
  std::string symbolic = "auto";  ///< --symbolic: when the engine derives the variational order
  /// The system may depend on the time t (a splitting on --potential: its drifts carry the time)
  bool allow_time = false;
};

/// Run it; the exit status as for `vibook verify` (0 pass, 5 a verdict failed, 2, 3, 4).
int run_composition(const CompositionOptions& o);

/// --composition ld (verify_composition_ld.cpp): the base is the --ld typed; `spec` holds the
/// parsed coefficients (its base is set there).
int run_composition_ld(const CompositionOptions& o, verify::CompositionSpec spec);

/// `vibook verify --ld` for a time-dependent system (t in a text): the DEL step of L_d(t, q0,
/// q1, h) measured by the map study (verify::measure_timed_ld), the report printed; the options
/// checked before any work (ArgumentError naming one).
int run_timed_ld(const CompositionOptions& o);

}  // namespace vibook::cli
