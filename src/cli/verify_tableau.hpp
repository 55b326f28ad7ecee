// `vibook verify --tableau FILE`: a partitioned Runge–Kutta method from its tableau
// (vibook/verify/tableau_study.hpp) judged by its measured order against an independent
// reference, symplecticity, reversibility and energy (verify_tableau.cpp).
#pragma once

#include <string>

namespace vibook::cli {

/// The options of a tableau verification, as typed; `given` flags say which the user set.
struct TableauOptions {
  std::string file, problem, q0, p0, t_end, h_list, expected, order_tol, h, steps, floor, json_out;
  bool json_given = false, t_end_given = false, h_list_given = false, expected_given = false,
       order_tol_given = false, symmetric = false;
};

/// Run it; the exit status as for `vibook verify` (0 pass, 5 a verdict failed, 2, 3, 4).
int run_tableau(const TableauOptions& o);

}  // namespace vibook::cli
