// The command's side of the measurements of a one-step map (vibook/verify/map_study.hpp): the
// options common to the composition, Galerkin and black-box routes, checked before any work,
// and the report printed with its exit status.
#pragma once

#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "args.hpp"
#include "cli.hpp"
#include "study_options.hpp"
#include "vibook/core/precision.hpp"
#include "vibook/verify/expression.hpp"
#include "vibook/verify/map_study.hpp"
#include "vibook/verify/reference.hpp"
#include "vibook/verify/typed_system.hpp"
#include "vibook/verify/verify.hpp"

namespace vibook::cli {

using verify::MapStudy;
using verify::measure_map;
using verify::naming_failures;
using verify::run_map;
using verify::test_problems;
using verify::TestProblem;
using verify::vec_text;

using verify::euler_lagrange_acceleration;
using verify::lagrangian_derivatives;
using verify::largest_symmetric_eigenvalue;
using verify::set_typed_hamiltonian;
using verify::set_typed_lagrangian;
using verify::set_typed_potential;
using verify::set_typed_system;
using verify::typed_hamilton_field;

/// The test problem named by --problem (empty: kepler); ArgumentError naming --problem
/// otherwise.
const TestProblem& find_test_problem(const std::string& name);

/// The report of a command: the measurement, and the exit status it ends with.
struct MapReport : verify::MapMeasurement {
  /// The variational order line of a route the engine does not reach (yet), with the reason;
  /// the JSON says "derived": false. Nothing is judged on it.
  void variational_order_not_derived(const std::string& reason);
  /// The verdict line; the report to stdout, the one-line summary to stderr, the JSON to
  /// --json-out and the page to --report when given. Returns the exit status (0, 3 or 5; 4
  /// from a failed write).
  int finish(const StudyOptions& o);
};

/// The measurement options common to the routes, checked before any work (ArgumentError naming
/// the option): --order-tol, --h-list (inside (0, T], at most 1e7 steps), --floor, --h,
/// --steps, into `s` (whose values are the defaults). `Options` has the string fields
/// order_tol, h_list, floor, h, steps and the flags order_tol_given, h_list_given; s.t_end
/// is already set.
template <class Options>
void check_study_options(const Options& o, MapStudy& s) {
  if (o.order_tol_given) {
    s.order_tol = parse_number("--order-tol", o.order_tol);
    if (!(s.order_tol > 0 && s.order_tol <= 1))
      throw ArgumentError("--order-tol", "must lie in (0, 1]");
  }
  if (o.h_list_given) s.hs = parse_step_list("--h-list", o.h_list, s.t_end, 7);
  if (!o.floor.empty()) {
    s.floor = parse_number("--floor", o.floor);
    if (!(*s.floor >= 0) || !std::isfinite(*s.floor))
      throw ArgumentError("--floor", "must be a finite number >= 0");
  }
  if (!o.h.empty()) s.h = parse_number("--h", o.h);
  s.symmetric_claimed = o.symmetric;
  if (!o.steps.empty()) s.steps = parse_integer("--steps", o.steps);
  if (s.steps < 1024 || s.steps > 100000000)
    throw ArgumentError("--steps", "must lie in [1024, 1e8]");
  if (!(s.h > 0) || !std::isfinite(s.h) || s.h * double(s.steps) > 1e9)
    throw ArgumentError("--h", "must be a positive finite step (h·steps at most 1e9)");
}

/// --q0 and --p0 (default: the problem's), then --t-end into s.t_end, checked before any work
/// (ArgumentError naming the option). `Options` has the string fields q0, p0, t_end and the
/// flag t_end_given.
template <class Options>
void check_initial_state(const Options& o, const TestProblem& problem, std::vector<double>& q0,
                         std::vector<double>& p0, MapStudy& s) {
  const std::size_t n = problem.q0.size();
  auto vector_or = [&](const std::string& arg, const std::string& text,
                       const std::vector<double>& dflt) {
    std::vector<double> v = text.empty() ? dflt : parse_list(arg, text);
    if (v.size() != n)
      throw ArgumentError(arg, fmt::format("has {} components; {} has {} degrees of freedom",
                                           v.size(), problem.name, n));
    for (double x : v)
      if (!std::isfinite(x)) throw ArgumentError(arg, "must be finite");
    return v;
  };
  q0 = vector_or("--q0", o.q0, problem.q0);
  p0 = vector_or("--p0", o.p0, problem.p0);
  if (problem.name == "kepler" && std::hypot(q0[0], q0[1]) < 1e-3)
    throw ArgumentError("--q0", "lies at (or within 1e-3 of) the Kepler singularity q = 0");
  if (o.t_end_given) {
    s.t_end = parse_number("--t-end", o.t_end);
    if (!(s.t_end > 0) || s.t_end > 1e4) throw ArgumentError("--t-end", "must lie in (0, 1e4]");
  }
}

/// --expected-order as a number in (0, kMaxOrder] (an ArgumentError naming it otherwise).
inline double check_expected_order(const std::string& text) {
  const double e = parse_number("--expected-order", text);
  if (!(e > 0 && e <= verify::kMaxOrder))
    throw ArgumentError("--expected-order",
                        fmt::format("must lie in (0, {:g}]", verify::kMaxOrder));
  return e;
}

/// The same for a system typed as an expression with `n` degrees of freedom: --q0 and --p0
/// default to 0.1 in every component.
template <class Options>
void check_typed_initial_state(const Options& o, int n, std::vector<double>& q0,
                               std::vector<double>& p0, MapStudy& s) {
  auto vector_or = [&](const std::string& arg, const std::string& text) {
    std::vector<double> v = text.empty() ? std::vector<double>(static_cast<std::size_t>(n), 0.1)
                                         : parse_list(arg, text);
    if (static_cast<int>(v.size()) != n)
      throw ArgumentError(arg, fmt::format("has {} components; the expressions are "
                                           "{}-dimensional",
                                           v.size(), n));
    for (double x : v)
      if (!std::isfinite(x)) throw ArgumentError(arg, "must be finite");
    return v;
  };
  q0 = vector_or("--q0", o.q0);
  p0 = vector_or("--p0", o.p0);
  if (o.t_end_given) {
    s.t_end = parse_number("--t-end", o.t_end);
    if (!(s.t_end > 0) || s.t_end > 1e4) throw ArgumentError("--t-end", "must lie in (0, 1e4]");
  }
}

/// --potential (with --dim) of a catalogue route (`route`: "--method", "--tableau"), checked
/// before any work: the typed system, whose Hamiltonian |p|²/2 + V(q) gives the reference and
/// the energy, in 1 to 3 dimensions; then --q0, --p0 (default 0.1 each) and --t-end. An
/// ArgumentError names --potential, --problem, --dim, --q0, --p0 or --t-end.
/// `allow_time`: the route steps a time-dependent system (the time t in the texts); otherwise a
/// text with t is refused by name.
std::unique_ptr<verify::TypedDiscreteLagrangian> check_typed_potential(
    const TypedPotentialOptions& t, const StudyOptions& o, const char* route,
    std::vector<double>& q0, std::vector<double>& p0, MapStudy& s, bool allow_time = false);

/// --lagrangian (with --potential for a V it calls, and --dim) of `vibook verify --method`,
/// checked before any work: the typed L(q, v) in 1 to 3 dimensions, then --q0, --p0 (default
/// 0.1 each; p0 is the canonical momentum ∂L/∂v) and --t-end. An ArgumentError names
/// --lagrangian, --potential, --problem, --dim, --q0, --p0 or --t-end.
std::unique_ptr<verify::TypedDiscreteLagrangian> check_typed_lagrangian(
    const TypedPotentialOptions& t, const StudyOptions& o, const char* route,
    std::vector<double>& q0, std::vector<double>& p0, MapStudy& s, bool allow_time = false);

/// --hamiltonian `hamiltonian` (with --potential for a V it calls, and --dim) of a catalogue
/// route, checked before any work: the typed H(q, p) in 1 to 3 dimensions, then --q0, --p0
/// (default 0.1 each) and --t-end. An ArgumentError names --hamiltonian, --potential, --problem,
/// --dim, --q0, --p0 or --t-end.
std::unique_ptr<verify::TypedDiscreteLagrangian> check_typed_hamiltonian(
    const TypedPotentialOptions& t, const std::string& hamiltonian, const StudyOptions& o,
    const char* route, std::vector<double>& q0, std::vector<double>& p0, MapStudy& s,
    bool allow_time = false);

}  // namespace vibook::cli
