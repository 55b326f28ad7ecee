// `vibook verify --method gauss:S|lobatto:S`: a Galerkin variational integrator
// (integrators/galerkin.hpp) judged by its measured order against an independent reference,
// symplecticity, reversibility and energy (verify_method.cpp).
#pragma once

#include <string>

namespace vibook::cli {

/// The options of a catalogue-method verification, as typed; `given` flags say which the user
/// set.
struct MethodOptions {
  std::string method, problem, q0, p0, t_end, h_list, expected, order_tol, h, steps, floor,
      json_out;
  bool json_given = false, t_end_given = false, h_list_given = false, expected_given = false,
       order_tol_given = false;
};

/// Run it; the exit status as for `vibook verify` (0 pass, 5 a verdict failed, 2, 3, 4).
int run_method(const MethodOptions& o);

}  // namespace vibook::cli
