/// \file map_study.hpp
/// \brief The measurements `vibook verify` makes on a one-step map z = (q, p) ↦ Φ_h(z) of
/// Hamilton's equations, whatever produced the map: a composition of a catalogue method, a
/// Galerkin integrator, or another program's stepper behind the C ABI or the line protocol.
/// The reference is the continuous system integrated in double-double (never the method
/// itself); the order is fitted two-sided in a window fixed beforehand; symplecticity (at h,
/// 2h and 4h) and reversibility come from the map's Jacobian and its ρ-conjugate; the energy
/// from a long run. Every part is measured even after one fails; `failed` names the parts that
/// failed. The command (`src/cli`) prints the report and the field audit records it in the
/// ledger, from the same measurement.
///
/// Chapter: \ref chapter-verify.
#pragma once

#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "vibook/core/precision.hpp"
#include "vibook/verify/reference.hpp"
#include "vibook/verify/verify.hpp"

namespace vibook::verify {

/// The largest order a route accepts (--expected-order, a tableau file's 'order'). No cap below
/// what the measurement can use: the order study fits slopes, not a table of orders, and
/// Gauss's method with six stages is of order 12.
constexpr double kMaxOrder = 20;

/// The nonlinear test problems of the composition, Galerkin and black-box routes: the name,
/// the Hamiltonian as printed, and the initial state (the Kepler orbit has eccentricity 0.5).
struct TestProblem {
  std::string name, hamiltonian;
  std::vector<double> q0, p0;
  std::string expression;  ///< H in verify's expression language (the black-box route)
};
const std::vector<TestProblem>& test_problems();

/// The test problem of that name (empty: kepler), or nullptr.
const TestProblem* find_problem(const std::string& name);

/// The step `raw` of an N-degree-of-freedom map, with every NumericalError it throws rewritten
/// to name the step size and the state the step started from.
verify::Step naming_failures(verify::Step raw, int n);

/// "(a, b, …)" with 6 significant digits.
std::string vec_text(const std::vector<double>& v);

/// The report being written: its text lines, its JSON, the parts required by the verdict and
/// those that failed, and the first numerical failure. The command prints it (cli/verify_map);
/// the field audit (field_audit.cpp) reads its JSON.
struct MapMeasurement {
  std::ostringstream out;
  nlohmann::json js;
  std::vector<std::string> failed, required;
  bool numerical_failure = false;
  std::string first_error;

  /// One line: the label in a column of 21 characters, then the text.
  void line(const std::string& label, const std::string& text);
  /// A part stopped by a numerical failure: printed, failed, remembered.
  void numerical(const std::string& part, const std::exception& e);
};

/// One step of a variational method that also gives its discrete Lagrangian along the step:
/// advances z = (q, p) in place and returns L_d(q0, q1, h) in Marsden & West's scaling
/// (L_d ≈ the action ∫ L dt over the step). For a composition it is the sum of the stages'
/// discrete Lagrangians at the positions the stages pass through (the interior points of the
/// composed L_d); for a Galerkin method the quadrature action at the solved polynomial.
using GeneratingStep = std::function<double(Eigen::VectorXd& z, double h)>;

/// x rounded to double-double: its double, then the double nearest the rest (a coefficient
/// known to 120 digits, for a step in double-double).
inline dd_real to_dd(const mpfr_real& x) {
  const double hi = static_cast<double>(x);
  const double lo = static_cast<double>(mpfr_real(x - hi));
  return dd_real(hi, lo);
}

/// A state in double-double, and one step of a map in that arithmetic.
using VecXdd = Eigen::Matrix<dd_real, Eigen::Dynamic, 1>;
using StepDD = std::function<void(VecXdd& z, const dd_real& h)>;
/// GeneratingStep in double-double: advances z and returns L_d(q0, q1, h).
using GeneratingStepDD = std::function<dd_real(VecXdd& z, const dd_real& h)>;

/// A position–momentum method in double-double (anything with `step(Vec<dd_real, N>& q,
/// Vec<dd_real, N>& p, const dd_real& h)` and, for the second, `action()`, its discrete
/// Lagrangian along the last step) as a StepDD and a GeneratingStepDD, each on its own instance
/// from `make()` (a std::shared_ptr); `with_action` false leaves the second empty.
template <int N, class Make>
std::pair<StepDD, GeneratingStepDD> dd_steps(Make make, bool with_action = true) {
  auto advance = [](auto& m, VecXdd& z, const dd_real& h) {
    Vec<dd_real, N> q = z.template head<N>(), p = z.template tail<N>();
    m.step(q, p, h);
    z.template head<N>() = q;
    z.template tail<N>() = p;
  };
  auto stepper = make();
  StepDD step = [stepper, advance](VecXdd& z, const dd_real& h) { advance(*stepper, z, h); };
  if (!with_action) return {step, GeneratingStepDD{}};
  auto generating = make();
  return {step, [generating, advance](VecXdd& z, const dd_real& h) {
            advance(*generating, z, h);
            return generating->action();
          }};
}

/// The expected order from which the order study runs in double-double when the method has a
/// step in it (MapStudy::step_dd): from order 6 on, double's window [1e-12, 1e-6] lies in the
/// pre-asymptotic range of the test problems (Gauss's method with 4 stages measures 7.5 there).
constexpr double kExtendedOrder = 6;

/// What is measured, and how.
struct MapStudy {
  verify::Step step;  ///< one step of the map under test
  /// Optional: the same map in double-double. With it, and an expected order of at least
  /// kExtendedOrder, the order study runs in double-double with its window down to 1e-25 (and a
  /// tenth of the walk's budget of substeps).
  StepDD step_dd;
  /// Optional: n steps of size h at once (a line-protocol stepper answers one request for a
  /// whole run); by default `step` n times.
  std::function<void(Eigen::VectorXd& z, double h, long long n)> propagate;
  /// Optional: n steps of size h at once with every state (`each` after each step, z holding
  /// it): the energy runs, which look at every state, then take a few requests instead of one a
  /// step (a library's host); by default `step` n times.
  std::function<void(Eigen::VectorXd& z, double h, long long n, const std::function<void()>& each)>
      every;
  Eigen::VectorXd z0;
  /// Optional, a constrained system (constrained.hpp): the residuals at z of the position
  /// constraint, |g(q)|_max, and of the hidden constraint, |G(q) p|_max. With it both are judged
  /// along runs (constraint_by_scaling), and symplecticity is that of the map restricted to the
  /// constraint manifold, whose tangent space `tangent` spans.
  std::function<double(const Eigen::VectorXd&z)> position_residual, hidden_residual;
  std::function<Eigen::MatrixXd(const Eigen::VectorXd& z)> tangent;
  /// The system depends on the time explicitly: the state carries the clock last,
  /// z = (q, p, t) (2n + 1 components, z0's t the start time), `field` has t' = 1, the step
  /// reads its start time from z and advances it by h. The order is read on (q, p), the
  /// symplecticity on the time-t map, ρ reverses t too, and the energy (not conserved) is not
  /// judged (chapter "Verify your own integrator", section "Time-dependent systems").
  bool timed = false;
  verify::Field<dd_real> field;  ///< Hamilton's equations, for the reference (unless `reference`)
  /// Optional: the reference in the system's own coordinates, used instead of integrating
  /// `field`. Called with z0 = (q, p) and a time t, it returns the exact solution's (q, p) at
  /// t; with `action` true, one more component, ∫_0^t L dt along it (the variational order's
  /// exact side). A typed Lagrangian's reference integrates its Euler–Lagrange equations in
  /// (q, v), which needs no Legendre transform inside the field.
  std::function<Reference<dd_real>(const std::vector<dd_real>& z0, double t, bool action)>
      reference;
  std::string equations = "Hamilton's equations";
  verify::Observable H;  ///< the energy
  /// Optional: the energy in double-double (a test problem's), for the variational order's
  /// exact side in double-double.
  std::function<dd_real(const VecXdd& z)> H_dd;
  double t_end = 5, h = 0.05, order_tol = 0.2, expected = 2;
  long long steps = 100000;
  std::vector<double> hs;  ///< --h-list (empty: the walk of step counts)
  std::optional<double> floor;
  double substeps = 1;  ///< evaluations of the base method in one step (the walk's cost)
  double max_substeps = 1e6;
  /// The method is said to be symmetric (--symmetric, its source, or its structure): symmetry
  /// joins the verdict, and reversibility too where the intended system has the reversing
  /// symmetry ρ(q, p) = (q, −p) (phases.hpp).
  bool symmetric_claimed = false;
  std::string symmetric_note;  ///< appended to the line when symmetry is not required
  /// The method's exact answer on symplecticity, where its conditions settle it (a tableau's at
  /// 120 digits): an exact NO fails the verdict whatever the measurement says; both are shown.
  std::optional<bool> exact_symplectic;
  std::string exact_symplectic_from;
  /// The order the method's exact conditions give (a composition's), NaN where it has none:
  /// below 1 the method is not consistent and never passes (judge_consistency).
  double conditions_order = std::numeric_limits<double>::quiet_NaN();
  /// Optional: the method's step with its discrete Lagrangian. When given, the variational
  /// order is measured and reported beside the order (measure_variational_order).
  GeneratingStep generating;
  /// Optional: the same in double-double. With it, H_dd, no `reference` and an expected order
  /// of at least kExtendedOrder, the variational order is measured in double-double, its window
  /// down to 1e-25 (measure_variational_order).
  GeneratingStepDD generating_dd;
  std::string generating_from;  ///< how the step's L_d is formed, for the report
  /// Optional: the variational order derived (symbolically), reported right after the measured
  /// one; it may add "variational order" to the verdict (method_symbolic.hpp).
  std::function<void(const MapStudy&, MapMeasurement&)> derive_variational_order;
};

/// The system a method is measured on, for a route that reports one method on several kinds of
/// system (a test problem, or one typed by the user): how to set it in the study (z0, the
/// reference's field, the energy; a no-op when the caller set them), the report's line naming
/// it, and its JSON.
struct StudySystem {
  std::function<void(MapStudy&)> set;
  std::string line;
  nlohmann::json js;
};

/// A test problem as the system (set_problem below; its line and JSON name it).
StudySystem test_problem_system(const TestProblem& problem, const std::vector<double>& q0,
                                const std::vector<double>& p0);

/// The test problem's part of a study: z0 = (q0, p0), Hamilton's equations of its typed
/// potential in double-double (the reference) and its energy (problems/, kepler/).
void set_problem(MapStudy& s, const TestProblem& problem, const std::vector<double>& q0,
                 const std::vector<double>& p0);

/// The order study of every route, measured against a reference solution (zref, its
/// double-double digits zref_dd and estimated error): with `hs` empty, the walk of step counts
/// T·2^(k/4) until the error leaves the window [1e-12, 1e-6]·scale (1e-25 in double-double),
/// the fit on the run of settled local slopes; with `hs`, exactly those step sizes. In
/// double-double when the study has step_dd and expects order kExtendedOrder or more, or when
/// in double the local slopes never settle. Chapter "Verify your own integrator", the order
/// criterion.
struct OrderStudy {
  bool extended = false;       ///< runs in double-double
  bool fallback = false;       ///< the window was not reached: the 6 smallest step sizes
  bool settled_tried = false;  ///< enough points to look for settled local slopes
  bool retried = false;        ///< double's slopes did not settle: run again in double-double
  double window_low = 0, roundoff_h = 0, settled_from = 0, settled_to = 0, scale = 1;
  /// The smallest error when the walk stopped at roundoff_h. In double-double far above the
  /// floor (above kStallAboveFloor times it) that is not round-off but a defect of the method
  /// (its coefficients, its solve): the report says so.
  double stalled_error = 0;
  std::vector<double> hs, err;  ///< every run's step size and error at T
  PlateauFit fit;
  bool passed = false;  ///< |fitted − expected| < order_tol
};
OrderStudy study_order(const MapStudy& s, const Eigen::VectorXd& zref,
                       const std::vector<dd_real>& zref_dd, double ref_error);

/// The order study's lines ("order", "  points"), its JSON ("order") and, when it did not
/// pass, "order" among the failed parts.
void report_order(const MapStudy& s, const OrderStudy& o, MapMeasurement& rep);

/// The reference, order, symplecticity, reversibility and energy parts, appended to `r`.
void measure_map(const MapStudy& s, MapMeasurement& r);

/// The variational order, measured (Marsden & West 2001, §2.3.1): L_d is of variational
/// order r when L_d(q(0), q(h), h) − ∫_0^h L dt = O(h^{r+1}) along the exact solutions. For each
/// h of a walk and each of the states z(T/4), z(T/2), z(3T/4) of the exact solution, the exact
/// side is the action of the reference solution (Hamilton's equations in double-double, with
/// ∫ p·q' dt as an extra component, less h·H); the method's side is `generating` from the
/// momentum that makes its q1 equal the exact q(h) (Newton, central-difference Jacobian). The
/// exponent r + 1 is fitted to the largest of the three defects in the window
/// [1e-12, 1e-8]·scale, scale = max(1, |H0|, ½|p0|²), with an O(h) correction term. With
/// MapStudy::generating_dd (and H_dd) and an expected order of at least kExtendedOrder, the
/// steps, the shooting and the exact side's energy are in double-double and the window reaches
/// down to 1e-25·scale: in double the window of an eighth-order method is still
/// pre-asymptotic. Reported (text and JSON "variational_order"), never part of the verdict.
void measure_variational_order(const MapStudy& s, MapMeasurement& r);

/// Integrate over [0, T] with steps of h, the last shortened to end at T (verify::integrate),
/// through `propagate` when the study has one.
Eigen::VectorXd run_map(const MapStudy& s, const Eigen::VectorXd& z0, double h, double T);

}  // namespace vibook::verify
