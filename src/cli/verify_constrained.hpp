// `vibook verify` on constraints typed after --constraint (verify_constrained.cpp).
#pragma once

#include <string>
#include <vector>

#include "study_options.hpp"
#include "vibook/verify/constrained.hpp"

namespace vibook::cli {

struct ConstrainedOptions : StudyOptions {
  std::string ld, potential, dim;
  std::vector<std::string> constraints;
  verify::ConstrainedStep step = verify::ConstrainedStep::rattle;
};

/// RATTLE (or shake) on H = |p|^2/2 + V with the typed constraints, or the constrained discrete
/// Euler-Lagrange equations of the typed --ld: the options checked before any work (an
/// ArgumentError naming one), then verify::measure_constrained_typed; the report printed.
int run_constrained_typed(const ConstrainedOptions& o);

}  // namespace vibook::cli
