// `vibook run`: its options parsed and checked, then the library's run (vibook/run/run.hpp):
// one problem integrated by one method, the trajectory streamed as CSV.
#include <cmath>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "args.hpp"
#include "cli.hpp"
#include "vibook/core/errors.hpp"
#include "vibook/core/output_file.hpp"
#include "vibook/core/precision.hpp"
#include "vibook/core/tolerance.hpp"
#include "vibook/run/run.hpp"

namespace vibook::cli {
namespace {

// Every option is kept as the text the user typed and parsed strictly when the command runs:
// CLI11's own conversions accept an empty value as "not given" and drop empty list elements.
struct RunOptions : run::Settings {
  std::string h_text, t_end_text, periods_text, e_text, c_text, tau_end_text, h0_text, tol_text,
      alpha_text, digits_text, every_text, q0_text, p0_text, max_seconds_text;
};

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
      require_argument(o->max_seconds > 0 && o->max_seconds <= 1e7, "--max-seconds",
                       "must be a positive number of seconds, at most 1e7");
    }
    if (given("--digits")) {
      const long long d = parse_integer("--digits", o->digits_text);
      require_argument(
          d >= kMpfrMinDigits && d <= kMpfrMaxDigits, "--digits",
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
    require_argument(std::isfinite(o->h) && o->h > 0, "--h", "must be a positive finite number");
    if (o->t_end)
      require_argument(std::isfinite(*o->t_end) && *o->t_end > 0, "--t-end",
                       "must be a positive finite number");
    if (o->periods)
      require_argument(std::isfinite(*o->periods) && *o->periods > 0, "--periods",
                       "must be a positive finite number");
    if (o->h0)
      require_argument(std::isfinite(*o->h0) && *o->h0 > 0, "--h0",
                       "must be a positive finite number");
    require_argument(o->every >= 1, "--every", "must be at least 1");
    if (o->e) require_argument(*o->e >= 0 && *o->e < 1, "--e", "eccentricity must lie in [0, 1)");
    // Options of one family of methods are refused elsewhere, never silently ignored.
    const bool adaptive = o->method == "epavi" || o->method == "avi1" || o->method == "avi2";
    const bool epavi = o->method == "epavi";
    require_argument(adaptive || !given("--h0"), "--h0",
                     "applies to the adaptive methods epavi, avi1, avi2");
    require_argument(epavi || !given("--tol"), "--tol",
                     "applies to epavi only (the other implicit methods use Newton at 4 ulp)");
    require_argument(epavi || !given("--energy-target"), "--energy-target",
                     "applies to epavi only");
    require_argument(epavi || !given("--solver"), "--solver", "applies to epavi only");
    require_argument(epavi || o->precision == "double", "--precision",
                     "only epavi is templated on the scalar; the other methods run in double");
    require_argument(!o->digits || o->precision == "mpfr", "--digits",
                     "applies to --precision mpfr only");
    require_argument(o->method == "del-generic" || !given("--discrete-lagrangian"),
                     "--discrete-lagrangian", "applies to --method del-generic only");
    if (o->tol) {
      require_argument(std::isfinite(*o->tol) && *o->tol > 0, "--tol", "must be a positive number");
      // The range ExtendedDelIntegrator accepts, checked here so that no output starts first.
      const double u =
          with_precision(parse_precision(o->precision), o->digits.value_or(18), [](auto zero) {
            using T = decltype(zero);
            return to_double(unit_roundoff<T>());
          });
      require_argument(
          *o->tol >= u && *o->tol < 1e-2, "--tol",
          fmt::format("must lie in [{:.3g}, 1e-2) (the round-off of --precision {} up to "
                      "1e-2), got {:.3g}",
                      u, o->precision, *o->tol));
    }
    require_argument(!(given("--h") && given("--h0")), "--h0",
                     "give --h0 or --h (the first step of an adaptive method), not both");
    if (o->c) {
      require_argument(std::isfinite(*o->c) && *o->c > 0, "--c",
                       "the speed of light must be positive");
      // c² and c⁴ occur in the energy and the exact orbit: they must be finite numbers.
      require_argument(
          std::isfinite(*o->c * *o->c * *o->c * *o->c), "--c",
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
      require_argument(rel_only || o->method == "vi2", "--method",
                       "relativistic-kepler takes k-symplectic, vi or vi2");
    } else {
      require_argument(!rel_only, "--method",
                       "k-symplectic and vi are for --problem relativistic-kepler");
      require_argument(
          !splitting || o->problem == "kepler", "--method",
          "vi1, vi1-adjoint, vi2 and vi2-adjoint split the Kepler potential: use --problem "
          "kepler");
    }
    require_argument(
        !o->alpha || (splitting && !rel), "--alpha",
        "applies to the splitting methods vi1, vi1-adjoint, vi2, vi2-adjoint on kepler");
    if (rel) {
      require_argument(o->c.has_value(), "--c",
                       "the speed of light is required for relativistic-kepler");
      require_argument(!o->t_end && !o->periods, o->t_end ? "--t-end" : "--periods",
                       "relativistic-kepler runs in proper time: use --tau-end");
      require_argument(!o->e, "--e", "does not apply to relativistic-kepler; give --q0 and --p0");
    } else {
      require_argument(!o->c, "--c", "only applies to --problem relativistic-kepler");
      require_argument(!o->tau_end, "--tau-end", "only applies to --problem relativistic-kepler");
    }
    const DeferSignals signals;  // from here on, an interruption keeps FILE.partial
    run::Hooks hooks;
    hooks.pending_signal = pending_signal;
    hooks.signal_name = signal_name;
    run::run_trajectory(*o, hooks);
    return kOk;
  };
}

}  // namespace vibook::cli
