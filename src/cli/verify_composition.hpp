// `vibook verify --composition BASE --coefficients NAME|LIST`: a composition method judged by
// its order conditions (at 120 digits), its measured order against an independent reference,
// symplecticity, reversibility and energy (verify_composition.cpp).
#pragma once

#include <string>

namespace vibook::cli {

/// The options of a composition verification, as typed; `given` flags say which the user set
/// (the defaults of the step sizes depend on the expected order).
struct CompositionOptions {
  std::string base, coefficients, problem, q0, p0, t_end, h_list, expected, order_tol, h, steps,
      floor, json_out;
  bool json_given = false, t_end_given = false, h_list_given = false, expected_given = false,
       order_tol_given = false;
};

/// Run it; the exit status as for `vibook verify` (0 pass, 5 a verdict failed, 2, 3, 4).
int run_composition(const CompositionOptions& o);

}  // namespace vibook::cli
