// The command's side of the measurements of a one-step map (vibook/verify/map_study.hpp): the
// options common to the composition, Galerkin and black-box routes, checked before any work,
// and the report printed with its exit status.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cli.hpp"
#include "verify_routes.hpp"
#include "vibook/core/precision.hpp"
#include "vibook/verify/expression.hpp"
#include "vibook/verify/map_study.hpp"
#include "vibook/verify/reference.hpp"
#include "vibook/verify/typed_system.hpp"
#include "vibook/verify/verify.hpp"

namespace vibook::cli {

using verify::MapStudy;
using verify::set_typed_hamiltonian;
using verify::set_typed_lagrangian;
using verify::set_typed_potential;
using verify::TestProblem;

/// The test problem named by --problem (empty: kepler); ArgumentError naming --problem
/// otherwise.
const TestProblem& find_test_problem(const std::string& name);

/// The report of a command: the measurement, and the exit status it ends with.
struct MapReport : verify::MapMeasurement {
  /// The verdict line; the report to stdout, the one-line summary to stderr, the JSON to
  /// --json-out and the page to --report when given. Returns the exit status (0, 3 or 5; 4
  /// from a failed write).
  int finish(const VerifyOptions& o);
};

/// The limits every route takes (the chapter's "criteria of every route"): the order study's
/// time T = --t-end, its step counts T/h (--h-list), and the energy run's time h·steps (the
/// messages say 1e4 and 1e9).
inline constexpr double kMaxTEnd = 1e4;
inline constexpr int kMaxStepsLog10 = 7;
inline constexpr double kMaxRunTime = 1e9;

/// The numbers every route checks the same way, before any work (ArgumentError naming the
/// option): --t-end in (0, 1e4], --order-tol in (0, 1], --floor a finite number >= 0, and the
/// energy run's --h and --steps (steps in [1024, 1e8], h positive, h·steps at most 1e9).
double checked_t_end(const std::string& text);
double checked_order_tol(const std::string& text);
double checked_floor(const std::string& text);
void check_energy_run(const VerifyOptions& o, double& h, long long& steps);

/// The measurement options common to the routes, checked before any work (ArgumentError naming
/// the option): --order-tol, --h-list (inside (0, T], at most 1e7 steps), --floor, --h,
/// --steps, --symmetric, into `s` (whose values are the defaults; s.t_end is already set).
void check_study_options(const VerifyOptions& o, MapStudy& s);

/// --t-end, when given, into s.t_end: in (0, 1e4].
void check_t_end(const VerifyOptions& o, MapStudy& s);

/// --q0 and --p0 (default: the problem's), then --t-end into s.t_end, checked before any work
/// (ArgumentError naming the option).
void check_initial_state(const VerifyOptions& o, const TestProblem& problem,
                         std::vector<double>& q0, std::vector<double>& p0, MapStudy& s);

/// --expected-order as a number in (0, kMaxOrder] (an ArgumentError naming it otherwise).
double check_expected_order(const std::string& text);

/// The same for a system typed as an expression with `n` degrees of freedom: --q0 and --p0
/// default to 0.1 in every component.
void check_typed_initial_state(const VerifyOptions& o, int n, std::vector<double>& q0,
                               std::vector<double>& p0, MapStudy& s);

/// --dim, when given: in 1..`max` (ArgumentError "must lie in 1..MAX`with`"); 0 otherwise.
int check_dim(const VerifyOptions& o, int max, const std::string& with = "");

/// The system of a catalogue route (`route`: "--method", "--tableau"), checked before any
/// work: `option` ("--potential", "--lagrangian" or "--hamiltonian") gives it, the typed
/// L(q, v) or H(q, p) (|p|²/2 + V(q) for --potential), which may call the V of --potential, in
/// 1 to 3 dimensions; then --q0, --p0 (default 0.1 each; p0 is the canonical momentum) and
/// --t-end. An ArgumentError names the option, --potential, --problem, --dim, --q0, --p0 or
/// --t-end. `allow_time`: the route steps a time-dependent system (the time t in the texts);
/// otherwise a text with t is refused by name.
std::unique_ptr<verify::TypedDiscreteLagrangian> check_typed_system(
    const VerifyOptions& o, const std::string& option, const char* route, std::vector<double>& q0,
    std::vector<double>& p0, MapStudy& s, bool allow_time);

}  // namespace vibook::cli
