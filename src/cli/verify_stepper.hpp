// `vibook verify --stepper-lib LIB.so` and `--stepper-cmd 'CMD'`: another program's one-step
// method judged as a black box (verify_stepper.cpp): its measured order against Hamilton's
// equations of the system it is meant for, symplecticity, reversibility and energy.
#pragma once

#include <string>
#include <vector>

#include "study_options.hpp"

namespace vibook::cli {

/// The options of a black-box verification, as typed; `given` flags say which the user set.
struct StepperOptions : StudyOptions {
  std::string lib, cmd, arg, timeout, hamiltonian, potential, dim, protocol;
  bool lib_given = false, cmd_given = false, protocol_given = false;
  bool timings = false;  ///< --timings: the seconds of each work-precision run
  /// --constraint (with --potential): the stepper steps a constrained system, measured with its
  /// constraint residuals and its symplecticity on the manifold
  std::vector<std::string> constraints;
};

/// Run it; the exit status as for `vibook verify` (0 pass, 5 a verdict failed, 2, 3, 4).
int run_stepper(const StepperOptions& o);

}  // namespace vibook::cli
