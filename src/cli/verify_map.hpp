// The measurements `vibook verify` makes on a one-step map z = (q, p) ↦ Φ_h(z) of Hamilton's
// equations, whatever produced the map: a composition of a catalogue method
// (verify_composition.cpp) or another program's stepper behind the C ABI or the line protocol
// (verify_stepper.cpp). The reference is the continuous system integrated in double-double
// (never the method itself); the order is fitted two-sided in a window fixed beforehand;
// symplecticity and reversibility come from the map's Jacobian and its ρ-conjugate; the energy
// from a long run. Every part is printed even after one fails; the verdict names the parts that
// failed.
#pragma once

#include <cmath>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "args.hpp"
#include "cli.hpp"
#include "vibook/core/precision.hpp"
#include "vibook/verify/reference.hpp"
#include "vibook/verify/verify.hpp"

namespace vibook::cli {

/// The nonlinear test problems of the composition, Galerkin and black-box routes: the name,
/// the Hamiltonian as printed, and the initial state (the Kepler orbit has eccentricity 0.5).
struct TestProblem {
  std::string name, hamiltonian;
  std::vector<double> q0, p0;
  std::string expression;  ///< H in verify's expression language (the black-box route)
};
const std::vector<TestProblem>& test_problems();

/// The test problem named by --problem (empty: kepler); ArgumentError naming --problem
/// otherwise.
const TestProblem& find_test_problem(const std::string& name);

/// The step `raw` of an N-degree-of-freedom map, with every NumericalError it throws rewritten
/// to name the step size and the state the step started from.
verify::Step naming_failures(verify::Step raw, int n);

/// "(a, b, …)" with 6 significant digits.
std::string vec_text(const std::vector<double>& v);

/// The report being written: its text lines, its JSON, the parts required by the verdict and
/// those that failed, and the first numerical failure (for the one line on stderr).
struct MapReport {
  std::ostringstream out;
  nlohmann::json js;
  std::vector<std::string> failed, required;
  int rc = kOk;
  std::string first_error;

  /// One line: the label in a column of 21 characters, then the text.
  void line(const std::string& label, const std::string& text);
  /// A part stopped by a numerical failure: printed, failed, status 3.
  void numerical(const std::string& part, const std::exception& e);
  /// The verdict line; the report to stdout, the one-line summary to stderr, the JSON to
  /// `json_out` when given. Returns the exit status (0, 3 or 5; 4 from a failed write).
  int finish(bool json_given, const std::string& json_out);
};

/// What is measured, and how.
struct MapStudy {
  verify::Step step;  ///< one step of the map under test
  /// Optional: n steps of size h at once (a line-protocol stepper answers one request for a
  /// whole run); by default `step` n times.
  std::function<void(Eigen::VectorXd& z, double h, long long n)> propagate;
  Eigen::VectorXd z0;
  verify::Field<dd_real> field;  ///< Hamilton's equations, for the reference
  std::string equations = "Hamilton's equations";
  verify::Observable H;  ///< the energy
  double t_end = 5, h = 0.05, order_tol = 0.2, expected = 2;
  long long steps = 100000;
  std::vector<double> hs;  ///< --h-list (empty: the walk of step counts)
  std::optional<double> floor;
  double substeps = 1;  ///< evaluations of the base method in one step (the walk's cost)
  double max_substeps = 1e6;
  bool require_reversible = false;
  std::string reversible_note;  ///< appended to the line when reversibility is not required
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

/// The reference, order, symplecticity, reversibility and energy parts, appended to `r`.
void measure_map(const MapStudy& s, MapReport& r);

/// Integrate over [0, T] with steps of h, the last shortened to end at T (verify::integrate),
/// through `propagate` when the study has one.
Eigen::VectorXd run_map(const MapStudy& s, const Eigen::VectorXd& z0, double h, double T);

}  // namespace vibook::cli
