// The options every one-step-map route of `vibook verify` takes (--method, --tableau,
// --composition, the black-box steppers), as typed; `given` flags say which the user set.
// verify_map.hpp checks them (check_initial_state, check_study_options).
#pragma once

#include <string>

namespace vibook::cli {

struct StudyOptions {
  std::string problem, q0, p0, t_end, h_list, expected, order_tol, h, steps, floor, json_out,
      report;
  bool json_given = false, report_given = false, t_end_given = false, h_list_given = false,
       expected_given = false, order_tol_given = false;
  bool symmetric = false;  ///< --symmetric: symmetry (and reversibility) join the verdict
};

/// A catalogue route's own system instead of --problem (--method, --tableau): L = |v|²/2 − V(q)
/// with V typed after --potential, 1 to 3 degrees of freedom (--dim fixes the number); for
/// --method also any L(q, v) typed after --lagrangian (which may call the V of --potential).
struct TypedPotentialOptions {
  std::string potential, dim, lagrangian;
  bool potential_given = false, lagrangian_given = false;
};

}  // namespace vibook::cli
