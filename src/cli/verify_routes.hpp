// `vibook verify`: the options as typed, one set for every route, and the routes. verify.cpp
// registers the options and picks the route (its route table refuses, by name, an option the
// route does not take); each route checks its options before any work, hands the study to the
// library (vibook/verify/*_study.hpp) and prints its report (MapReport::finish, or the --ld
// study's own). Each returns the exit status of `vibook verify` (0 pass, 5 a verdict failed,
// 2, 3, 4).
#pragma once

#include <set>
#include <string>
#include <vector>

#include "vibook/verify/composition_study.hpp"
#include "vibook/verify/constrained.hpp"

namespace vibook::cli {

struct VerifyOptions {
  std::string ld, potential, lagrangian, hamiltonian, dim, q0, p0,
      t_end = "5", h_list, expected = "2", order_tol = "0.2", h = "0.05", steps = "100000",
      modified_order = "2", format = "text", json_out, report, floor, max_seconds, composition,
      coefficients, problem, stepper_lib, stepper_cmd, stepper_arg, stepper_timeout,
      stepper_protocol, method, tableau, splitting, adaptive, adaptive_steps = "10000",
      symbolic = "auto";
  std::vector<std::string> constraints;  ///< --constraint, repeatable
  bool json_given = false, report_given = false, timings = false, symmetric = false,
       progress = false, reference = false;
  std::set<std::string> given;  ///< the options the user gave ("--t-end", …)
  /// True when the user gave the option (a default value is never "given").
  bool has(const std::string& option) const { return given.count(option) > 0; }
};

/// --composition BASE --coefficients NAME|LIST, and --splitting (verify_composition.cpp).
int run_composition(const VerifyOptions& o);
/// --composition ld (verify_composition_ld.cpp): the base is the typed L_d `ld` (the --ld, or
/// a splitting's stage); `spec` holds the parsed coefficients; `allow_time`: the system may
/// depend on t.
int run_composition_ld(const VerifyOptions& o, verify::CompositionSpec spec, bool allow_time,
                       const std::string& ld);
/// --ld on a time-dependent system (t in a text): the DEL step of L_d(t, q0, q1, h) in the map
/// study (verify_composition_ld.cpp).
int run_timed_ld(const VerifyOptions& o);
/// --tableau FILE (verify_tableau.cpp).
int run_tableau(const VerifyOptions& o);
/// --method gauss:S|lobatto:S|rattle|shake (verify_method.cpp).
int run_method(const VerifyOptions& o);
/// --stepper-lib LIB.so or --stepper-cmd 'CMD' (verify_stepper.cpp).
int run_stepper(const VerifyOptions& o);
/// --constraint with --method rattle|shake (`step`) or an --ld (verify_constrained.cpp).
int run_constrained_typed(const VerifyOptions& o, verify::ConstrainedStep step);
/// `--composition rattle --coefficients …` with --potential and --constraint
/// (verify_constrained.cpp).
int run_constrained_composition(const VerifyOptions& o, verify::CompositionSpec spec,
                                const std::string& given);

}  // namespace vibook::cli
