// `vibook verify --tableau FILE`: a partitioned Runge–Kutta method from its tableau
// (vibook/verify/tableau_study.hpp) judged by its measured order against an independent
// reference, symplecticity, reversibility and energy (verify_tableau.cpp).
#pragma once

#include <string>

#include "study_options.hpp"

namespace vibook::cli {

/// The options of a tableau verification, as typed; `given` flags say which the user set.
struct TableauOptions : StudyOptions, TypedPotentialOptions {
  std::string file;
  /// --hamiltonian: any H(q, p) typed, instead of |p|²/2 + V(q) (HamiltonianPrkMethod)
  std::string hamiltonian;
  bool hamiltonian_given = false;
};

/// Run it; the exit status as for `vibook verify` (0 pass, 5 a verdict failed, 2, 3, 4).
int run_tableau(const TableauOptions& o);

}  // namespace vibook::cli
