// `vibook run`: integrate one problem with one method and stream the trajectory as CSV.
#include <unistd.h>
#include <csignal>

#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <optional>
#include <sstream>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "args.hpp"
#include "cli.hpp"
#include "run_common.hpp"
#include "signals.hpp"
#include "vibook/core/angle.hpp"
#include "vibook/core/errors.hpp"
#include "vibook/core/output_file.hpp"
#include "vibook/core/precision.hpp"
#include "vibook/core/recorder.hpp"
#include "vibook/integrators/kernels.hpp"
#include "vibook/integrators/splitting.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/mechanics/del_solver.hpp"
#include "vibook/mechanics/discrete_lagrangian.hpp"
#include "vibook/problems/problems.hpp"
#include "vibook/relativistic/exact.hpp"
#include "vibook/relativistic/relativistic.hpp"

namespace vibook::cli {
using namespace run_detail;
namespace {

template <class Problem, class Stepper>
int integrate(const Problem& P, Stepper stepper, bool implicit, const RunOptions& o) {
  constexpr int N = Problem::N;
  constexpr bool kepler = std::is_same_v<Problem, Kepler>;

  // Initial state.
  State<N> s;
  if constexpr (kepler) {
    if (o.e) {
      require(o.q0.empty() && o.p0.empty(), "--e", "give either --e or --q0/--p0, not both");
      s = kepler_perihelion_state(*o.e);
    } else if (!o.q0.empty() || !o.p0.empty()) {
      s.q = vector_arg<N>(o.q0, "--q0");
      s.p = vector_arg<N>(o.p0, "--p0");
    } else {
      s = kepler_perihelion_state(0.5);
    }
  } else {
    require(!o.e, "--e", "only applies to --problem kepler");
    s.q = o.q0.empty() ? Vec<double, N>::Constant(1.0) : vector_arg<N>(o.q0, "--q0");
    s.p = o.p0.empty() ? Vec<double, N>::Zero() : vector_arg<N>(o.p0, "--p0");
  }

  // The initial state, checked before any output: a finite state with a finite energy (the
  // Kepler problem is singular at q = 0; 1e308 overflows the energy).
  {
    const double H0 = energy(P, s.q, s.p);
    if (!s.q.allFinite() || !s.p.allFinite() || !std::isfinite(H0))
      throw ArgumentError("--q0/--p0",
                          fmt::format("the initial state {} has no finite energy (H = {})",
                                      state_text(s.q.data(), s.p.data(), N), H0));
  }

  // End time.
  double T = 0;
  if (o.periods) {
    require(std::isfinite(*o.periods) && *o.periods > 0, "--periods", "must be a positive number");
    double period = 0;
    if constexpr (kepler) {
      // From --e the orbit has a = 1 by construction: period exactly 2π.
      try {
        period = o.e ? 2 * std::numbers::pi : KeplerOrbit::from_state(s.q, s.p).period();
      } catch (const ArgumentError& e) {
        throw ArgumentError("--q0/--p0", e.what());  // "initial state: ... not bound"
      }
    } else if constexpr (std::is_same_v<Problem, HarmonicOscillator>) {
      period = 2 * std::numbers::pi;
    } else {
      throw ArgumentError("--periods", "is defined for kepler and harmonic only; use --t-end");
    }
    T = *o.periods * period;
  } else {
    T = o.t_end.value_or(10.0);
    require(std::isfinite(T) && T > 0, "--t-end", "must be a positive number");
  }
  const auto [steps, last_h] = step_plan(T, o.h, o.plan_arg);

  // Output: a temporary file renamed onto --csv when the run completes (output_file.hpp).
  OutputFile csv(o.csv, "--csv");
  std::ostream& out = csv.stream();

  std::vector<std::string> cols = {"step", "t"};
  if constexpr (kepler) {
    cols.insert(cols.end(), {"q1", "q2", "p1", "p2", "H", "L", "ecc", "omega"});
  } else {
    cols.insert(cols.end(), {"q", "p", "H"});
  }
  if (implicit) cols.insert(cols.end(), {"residual", "iterations"});
  TrajectoryRecorder rec(out, cols, o.every);

  // omega is unwrapped between consecutive written rows: exact as long as the perihelion
  // turns by less than π between two of them.
  std::vector<double> row(cols.size());
  AngleUnwrapper omega;
  SolveReport rep{0.0, 0, true};
  auto offer = [&](long long k, double t) {
    std::size_t c = 0;
    row[c++] = double(k);
    row[c++] = t;
    if constexpr (kepler) {
      const KeplerInvariants inv = kepler_invariants(s.q, s.p);
      const double omega_unwrapped = omega(inv.omega);
      for (double v : {s.q(0), s.q(1), s.p(0), s.p(1), inv.H, inv.L, inv.ecc, omega_unwrapped})
        row[c++] = v;
    } else {
      for (double v : {s.q(0), s.p(0), energy(P, s.q, s.p)}) row[c++] = v;
    }
    if (implicit) {
      row[c++] = rep.residual;
      row[c++] = double(rep.iterations);
    }
    require_finite_row(row, cols);
    rec.offer(k, row);
  };

  Progress progress(steps, o.max_seconds);
  long long k = 0;
  State<N> before = s;  // the state a failing step started from
  try {
    offer(0, 0.0);
    for (k = 1; k <= steps; ++k) {
      const double hk = k == steps ? last_h : o.h;
      before = s;
      rep = stepper.step(s.q, s.p, hk);
      if (!s.q.allFinite() || !s.p.allFinite()) {
        throw NumericalError("the state became non-finite");
      }
      if (rec.due(k) || k == steps) offer(k, k == steps ? T : double(k) * o.h);
      progress.update(k);
    }
  } catch (const NumericalError& e) {
    rec.finish();
    const std::string where =
        k == 0 ? fmt::format("the initial state, {}", state_text(s.q.data(), s.p.data(), N))
               : fmt::format("step {} (t = {:.17g}), from {}", k, double(k - 1) * o.h,
                             state_text(before.q.data(), before.p.data(), N));
    rethrow_with(e, fmt::format("{} at {}; {}", e.what(), where, csv.keep_partial()));
  }
  rec.finish();
  csv.commit();
  return kOk;
}

// Relativistic Kepler in proper time (Shen & Sun 2025, (3.16)–(3.22)).
template <class Method>
int integrate_relativistic(const relativistic::Problem& P, Method method, const RunOptions& o) {
  using namespace relativistic;
  const Vec<double, 2> x0 = o.q0.empty() ? Vec<double, 2>(0.4, 0.0) : vector_arg<2>(o.q0, "--q0");
  const Vec<double, 2> u0 = o.p0.empty() ? Vec<double, 2>(0.0, 2.0) : vector_arg<2>(o.p0, "--p0");
  try {
    ExactOrbit check(P, x0, u0);  // a bound precessing orbit, or a clear error
  } catch (const ArgumentError& e) {
    throw ArgumentError("--q0/--p0/--c", e.what());
  }
  const double T = o.tau_end.value_or(40.0);
  require(std::isfinite(T) && T > 0, "--tau-end", "must be a positive number");
  const auto [steps, last_h] = step_plan(T, o.h, o.plan_arg);
  OutputFile out(o.csv, "--csv");
  const std::vector<std::string> cols = {"step", "tau", "t",      "x1", "x2",   "gamma",
                                         "u1",   "u2",  "energy", "L",  "shell"};
  TrajectoryRecorder rec(out.stream(), cols, o.every);
  RelState s = P.initial(x0, u0);
  auto offer = [&](long long k, double tau) {
    const Invariants inv = invariants(P, s);
    const std::array<double, 11> row{double(k), tau,    s.t,        s.x(0), s.x(1),   s.gamma,
                                     s.u(0),    s.u(1), inv.energy, inv.L,  inv.shell};
    require_finite_row(row, cols);
    rec.offer(k, row);
  };
  Progress progress(steps, o.max_seconds);
  long long k = 0;
  RelState before = s;
  try {
    offer(0, 0.0);
    for (k = 1; k <= steps; ++k) {
      before = s;
      method.step(s, k == steps ? last_h : o.h);
      if (!s.x.allFinite() || !s.u.allFinite() || !std::isfinite(s.gamma))
        throw NumericalError("the state became non-finite");
      if (rec.due(k) || k == steps) offer(k, k == steps ? T : double(k) * o.h);
      progress.update(k);
    }
  } catch (const NumericalError& e) {
    rec.finish();
    rethrow_with(e, fmt::format("{} at step {} (tau = {:.17g}), from x = ({:.17g}, {:.17g}), "
                                "u = ({:.17g}, {:.17g}); {}",
                                e.what(), k, double(std::max(k - 1, 0LL)) * o.h, before.x(0),
                                before.x(1), before.u(0), before.u(1), out.keep_partial()));
  }
  rec.finish();
  out.commit();
  return kOk;
}

template <class Problem>
int dispatch_method(const Problem& P, const RunOptions& o) {
  constexpr int N = Problem::N;
  const auto L = mechanical_lagrangian(P);
  if (o.method == "epavi" || o.method == "avi1" || o.method == "avi2") {
    if constexpr (std::is_same_v<Problem, Kepler>) {
      return integrate_adaptive_kepler(o);
    } else {
      throw ArgumentError("--method", "epavi, avi1 and avi2 are implemented for --problem kepler");
    }
  }
  if (o.method == "se") return integrate(P, SymplecticEuler<Problem>(P), false, o);
  if (o.method == "se-adjoint") return integrate(P, SymplecticEulerAdjoint<Problem>(P), false, o);
  if (o.method == "sv") return integrate(P, StormerVerlet<Problem>(P), false, o);
  if (o.method == "midpoint") return integrate(P, ImplicitMidpoint<Problem>(P), true, o);
  if (o.method == "vi1" || o.method == "vi1-adjoint" || o.method == "vi2" ||
      o.method == "vi2-adjoint") {
    if constexpr (std::is_same_v<Problem, Kepler>) {
      const auto split = WeightedSplit<Kepler>::alpha(o.alpha.value_or(0.5));
      return integrate(
          P, SplittingKernel<WeightedSplit<Kepler>>(split, parse_splitting_method(o.method)), false,
          o);
    } else {
      throw ArgumentError("--method", "the splitting methods are implemented for --problem kepler");
    }
  }
  // del-generic: the generic discrete Euler–Lagrange solver on the chosen discrete Lagrangian.
  const auto& d = o.discrete_lagrangian;
  if (d == "midpoint") return integrate(P, make_del_integrator<N>(midpoint_dl(L)), true, o);
  if (d == "sv") return integrate(P, make_del_integrator<N>(stormer_verlet_dl(L)), true, o);
  if (d == "se") return integrate(P, make_del_integrator<N>(symplectic_euler_dl(L)), true, o);
  return integrate(P, make_del_integrator<N>(symplectic_euler_adjoint_dl(L)), true, o);
}

/// The problem a method is implemented for when it is only one (what --problem defaults to);
/// otherwise ArgumentError naming --problem.
std::string problem_of(const std::string& method) {
  for (const char* m : {"epavi", "avi1", "avi2", "vi1", "vi1-adjoint", "vi2-adjoint"})
    if (method == m) return "kepler";
  if (method == "k-symplectic" || method == "vi") return "relativistic-kepler";
  throw ArgumentError("--problem", "required with --method " + method +
                                       ": harmonic, pendulum, kepler or relativistic-kepler");
}

}  // namespace

std::function<int()> add_run_command(CLI::App& app) {
  auto o = std::make_shared<RunOptions>();
  auto* run = app.add_subcommand(
      "run", "Integrate a problem with a method and write the trajectory as CSV");
  run->add_option("--problem", o->problem,
                  "harmonic, pendulum, kepler or relativistic-kepler (default: the one problem "
                  "the method is implemented for: kepler for epavi, avi1, avi2, vi1, "
                  "vi1-adjoint, vi2-adjoint; relativistic-kepler for k-symplectic, vi)")
      ->check(CLI::IsMember({"harmonic", "pendulum", "kepler", "relativistic-kepler"}));
  run->add_option("--method", o->method,
                  "se (drift-kick symplectic Euler), se-adjoint (kick-drift), sv (Störmer–Verlet), "
                  "midpoint (implicit midpoint), del-generic (generic solver); for "
                  "relativistic-kepler: k-symplectic (3.19), vi (3.20)/(3.22), vi2 (3.8); adaptive "
                  "(kepler): epavi, avi1, avi2 (Sharma et al. 2022); splitting (kepler, Shen & "
                  "Sun 2025): vi1, vi1-adjoint, vi2 (3.8), vi2-adjoint (3.7)")
      ->required()
      ->check(CLI::IsMember({"se", "se-adjoint", "sv", "midpoint", "del-generic", "epavi", "avi1",
                             "avi2", "k-symplectic", "vi", "vi1", "vi1-adjoint", "vi2",
                             "vi2-adjoint"}));
  run->add_option("--discrete-lagrangian", o->discrete_lagrangian,
                  "for del-generic: midpoint, sv, se or se-adjoint (default midpoint)")
      ->check(CLI::IsMember({"midpoint", "sv", "se", "se-adjoint"}));
  run->add_option("--h", o->h_text, "step size (default 0.01)");
  auto* t_end = run->add_option("--t-end", o->t_end_text, "final time (default 10)");
  auto* periods =
      run->add_option("--periods", o->periods_text, "final time in periods (kepler, harmonic)");
  t_end->excludes(periods);
  run->add_option("--e", o->e_text,
                  "kepler: eccentricity in [0,1); starts at perihelion of the orbit with a = 1");
  run->add_option("--q0", o->q0_text, "initial position, comma-separated");
  run->add_option("--p0", o->p0_text,
                  "initial momentum, comma-separated (relativistic-kepler: u0 = γẋ0; default 0,2 "
                  "with --q0 0.4,0, the paper's Fig. 7 data)");
  run->add_option("--h0", o->h0_text, "epavi/avi1/avi2: the first step (default: --h)");
  run->add_option("--precision", o->precision,
                  "epavi: arithmetic of the whole step: double (default), long-double, "
                  "double-double (libqd), quad (float128), mpfr (see --digits)")
      ->check(CLI::IsMember({"double", "long-double", "double-double", "quad", "mpfr"}));
  run->add_option("--digits", o->digits_text,
                  "--precision mpfr: significant decimal digits (default 18, the paper's VPA)");
  run->add_option("--tol", o->tol_text,
                  "epavi: relative tolerance of the step solves (default 4 units of round-off "
                  "of the precision)");
  run->add_option("--energy-target", o->energy_target,
                  "epavi: solve the energy equation for the previous step's E_k (previous, the "
                  "paper) or always for E_1 (initial)")
      ->check(CLI::IsMember({"previous", "initial"}));
  run->add_option("--solver", o->solver,
                  "epavi: closed-form (default: derivatives of (25) written out for "
                  "L = |v|^2/2 - V, Newton on the step, unbiased energy residual) or generic "
                  "(nested AutoDiff of any extended L_d, secant and bracket search; the reference)")
      ->check(CLI::IsMember({"closed-form", "generic"}));
  run->add_option("--alpha", o->alpha_text,
                  "vi1/vi2 on kepler: split φ^[1] = αφ, φ^[2] = (1−α)φ (default 0.5, the paper's)");
  run->add_option("--c", o->c_text, "relativistic-kepler: the speed of light (required)");
  run->add_option("--tau-end", o->tau_end_text,
                  "relativistic-kepler: final proper time (default 40)");
  run->add_option("--every", o->every_text, "write every K-th state (first and last always)");
  run->add_option("--csv", o->csv, "output file (default '-': standard output)");
  run->add_option("--max-seconds", o->max_seconds_text,
                  "stop with status 3 after this many seconds, keeping the rows in FILE.partial");

  return [o, run]() -> int {
    if (!*run) return -1;
    // --- every argument parsed and checked before any work ---------------------------------
    const auto given = [&](const char* name) { return run->count(name) > 0; };
    if (!given("--problem")) o->problem = problem_of(o->method);
    const auto number = [&](const char* name, const std::string& text) -> std::optional<double> {
      if (!given(name)) return std::nullopt;
      return parse_number(name, text);
    };
    if (given("--h")) o->h = parse_number("--h", o->h_text);
    o->t_end = number("--t-end", o->t_end_text);
    o->periods = number("--periods", o->periods_text);
    o->e = number("--e", o->e_text);
    o->c = number("--c", o->c_text);
    o->tau_end = number("--tau-end", o->tau_end_text);
    o->h0 = number("--h0", o->h0_text);
    o->tol = number("--tol", o->tol_text);
    o->alpha = number("--alpha", o->alpha_text);
    if (given("--q0")) o->q0 = parse_list("--q0", o->q0_text);
    if (given("--p0")) o->p0 = parse_list("--p0", o->p0_text);
    if (given("--every")) o->every = parse_integer("--every", o->every_text);
    if (given("--max-seconds")) {
      o->max_seconds = parse_number("--max-seconds", o->max_seconds_text);
      require(o->max_seconds > 0 && o->max_seconds <= 1e7, "--max-seconds",
              "must be a positive number of seconds, at most 1e7");
    }
    if (given("--digits")) {
      const long long d = parse_integer("--digits", o->digits_text);
      require(d >= kMpfrMinDigits && d <= kMpfrMaxDigits, "--digits",
              fmt::format("must lie in [{}, {}], got {} (the solvers' tolerances are doubles, "
                          "which end near 1e-308)",
                          kMpfrMinDigits, kMpfrMaxDigits, d));
      o->digits = static_cast<unsigned>(d);
    }
    o->plan_arg = given("--h0")  ? "--h0"
                  : given("--h") ? "--h"
                  : o->periods   ? "--periods"
                  : o->t_end     ? "--t-end"
                  : o->tau_end   ? "--tau-end"
                                 : "--h";
    require(std::isfinite(o->h) && o->h > 0, "--h", "must be a positive finite number");
    if (o->t_end)
      require(std::isfinite(*o->t_end) && *o->t_end > 0, "--t-end",
              "must be a positive finite number");
    if (o->periods)
      require(std::isfinite(*o->periods) && *o->periods > 0, "--periods",
              "must be a positive finite number");
    if (o->h0)
      require(std::isfinite(*o->h0) && *o->h0 > 0, "--h0", "must be a positive finite number");
    require(o->every >= 1, "--every", "must be at least 1");
    if (o->e) require(*o->e >= 0 && *o->e < 1, "--e", "eccentricity must lie in [0, 1)");
    // Options of one family of methods are refused elsewhere, never silently ignored.
    const bool adaptive = o->method == "epavi" || o->method == "avi1" || o->method == "avi2";
    const bool epavi = o->method == "epavi";
    require(adaptive || !given("--h0"), "--h0",
            "applies to the adaptive methods epavi, avi1, avi2");
    require(epavi || !given("--tol"), "--tol",
            "applies to epavi only (the other implicit methods use Newton at 4 ulp)");
    require(epavi || !given("--energy-target"), "--energy-target", "applies to epavi only");
    require(epavi || !given("--solver"), "--solver", "applies to epavi only");
    require(epavi || o->precision == "double", "--precision",
            "only epavi is templated on the scalar; the other methods run in double");
    require(!o->digits || o->precision == "mpfr", "--digits", "applies to --precision mpfr only");
    require(o->method == "del-generic" || !given("--discrete-lagrangian"), "--discrete-lagrangian",
            "applies to --method del-generic only");
    if (o->tol) {
      require(std::isfinite(*o->tol) && *o->tol > 0, "--tol", "must be a positive number");
      // The range ExtendedDelIntegrator accepts, checked here so that no output starts first.
      const double u =
          with_precision(parse_precision(o->precision), o->digits.value_or(18), [](auto zero) {
            using T = decltype(zero);
            return to_double(unit_roundoff<T>());
          });
      require(*o->tol >= u && *o->tol < 1e-2, "--tol",
              fmt::format("must lie in [{:.3g}, 1e-2) (the round-off of --precision {} up to "
                          "1e-2), got {:.3g}",
                          u, o->precision, *o->tol));
    }
    require(!(given("--h") && given("--h0")), "--h0",
            "give --h0 or --h (the first step of an adaptive method), not both");
    if (o->c) {
      require(std::isfinite(*o->c) && *o->c > 0, "--c", "the speed of light must be positive");
      // c² and c⁴ occur in the energy and the exact orbit: they must be finite numbers.
      require(std::isfinite(*o->c * *o->c * *o->c * *o->c), "--c",
              fmt::format("{:.3g} is too large (c^4 overflows); the limit c → ∞ is --problem "
                          "kepler",
                          *o->c));
    }
    // The output path, checked now (it is opened only when the run starts).
    check_output_path(o->csv, "--csv");
    const bool rel = o->problem == "relativistic-kepler";
    const bool rel_only = o->method == "k-symplectic" || o->method == "vi";
    const bool splitting = o->method == "vi1" || o->method == "vi1-adjoint" || o->method == "vi2" ||
                           o->method == "vi2-adjoint";
    if (rel) {
      require(rel_only || o->method == "vi2", "--method",
              "relativistic-kepler takes k-symplectic, vi or vi2");
    } else {
      require(!rel_only, "--method", "k-symplectic and vi are for --problem relativistic-kepler");
      require(!splitting || o->problem == "kepler", "--method",
              "vi1, vi1-adjoint, vi2 and vi2-adjoint split the Kepler potential: use --problem "
              "kepler");
    }
    require(!o->alpha || (splitting && !rel), "--alpha",
            "applies to the splitting methods vi1, vi1-adjoint, vi2, vi2-adjoint on kepler");
    if (rel) {
      require(o->c.has_value(), "--c", "the speed of light is required for relativistic-kepler");
      require(!o->t_end && !o->periods, o->t_end ? "--t-end" : "--periods",
              "relativistic-kepler runs in proper time: use --tau-end");
      require(!o->e, "--e", "does not apply to relativistic-kepler; give --q0 and --p0");
      const relativistic::Problem P(*o->c);  // c <= 0: ArgumentError naming --c
      const DeferSignals signals;
      if (o->method == "k-symplectic")
        return integrate_relativistic(P, relativistic::KSymplectic{P}, *o);
      if (o->method == "vi") return integrate_relativistic(P, relativistic::Vi322{P}, *o);
      return integrate_relativistic(P, relativistic::Vi2{P}, *o);
    }
    const DeferSignals signals;  // from here on, an interruption keeps FILE.partial
    require(!o->c, "--c", "only applies to --problem relativistic-kepler");
    require(!o->tau_end, "--tau-end", "only applies to --problem relativistic-kepler");
    if (o->problem == "harmonic") return dispatch_method(HarmonicOscillator{}, *o);
    if (o->problem == "pendulum") return dispatch_method(Pendulum{}, *o);
    return dispatch_method(Kepler{}, *o);
  };
}

}  // namespace vibook::cli
