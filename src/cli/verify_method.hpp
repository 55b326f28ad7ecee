// `vibook verify --method gauss:S|lobatto:S`: a Galerkin variational integrator
// (integrators/galerkin.hpp) judged by its measured order against an independent reference,
// symplecticity, reversibility and energy (verify_method.cpp), on a test problem or on the
// user's own potential (--potential) or Lagrangian (--lagrangian), with its variational order
// derived by the symbolic engine beside the measured one (--symbolic).
#pragma once

#include <string>

#include "study_options.hpp"

namespace vibook::cli {

/// The options of a catalogue-method verification, as typed; `given` flags say which the user
/// set.
struct MethodOptions : StudyOptions, TypedPotentialOptions {
  std::string method;
  std::string symbolic = "auto";  ///< --symbolic: when the engine derives the variational order
};

/// Run it; the exit status as for `vibook verify` (0 pass, 5 a verdict failed, 2, 3, 4).
int run_method(const MethodOptions& o);

}  // namespace vibook::cli
