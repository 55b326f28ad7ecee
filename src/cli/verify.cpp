// `vibook verify`: a discrete Lagrangian typed as an expression, checked against the system the
// user meant (a Lagrangian, a Hamiltonian, or L = |v|²/2 − V): consistency of its leading term,
// order against an independent reference (the continuous equations by GBS extrapolation in
// double-double), symplecticity, reversibility, the energy of the intended system judged by
// magnitude and trend, and the modified equation, Lagrangian and Hamiltonian from the engine.
// Every part that was computed is printed and written, even when a later part fails.

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "args.hpp"
#include "cli.hpp"
#include "verify_map.hpp"
#include "verify_routes.hpp"
#include "vibook/core/output_file.hpp"
#include "vibook/core/progress.hpp"
#include "vibook/modified/engine.hpp"
#include "vibook/verify/expression.hpp"
#include "vibook/verify/ld_study.hpp"

namespace vibook::cli {

namespace {

// --report DIR on every route, before any work: a new directory (or an earlier report) in a
// writable one, and not the place of --json-out.
void check_report(const VerifyOptions& o) {
  if (o.report_given) check_report_directory(o.report, "--report");
  if (o.json_given && o.report_given) {
    // The JSON file may not be the report directory, nor lie inside it (the report replaces
    // its own entries).
    const auto j = std::filesystem::absolute(o.json_out).lexically_normal();
    const auto r = std::filesystem::absolute(report_directory(o.report)).lexically_normal();
    const auto rel = j.lexically_relative(r);
    if (j == r || (!rel.empty() && *rel.begin() != ".."))
      throw ArgumentError("--json-out", "'" + o.json_out +
                                            "' is the --report directory or in it; "
                                            "the report holds verify.json already");
  }
}

// Every argument checked before any work (exit 2 naming it).
verify::LdSettings check(const VerifyOptions& o, const verify::TypedDiscreteLagrangian& dl) {
  verify::LdSettings p;
  p.dim = dl.dim();
  const std::vector<double> dflt(static_cast<std::size_t>(p.dim), 0.1);
  const std::string why = fmt::format("the expressions are {}-dimensional", p.dim);
  p.q0 = parse_state("--q0", o.q0, dflt, why);
  p.p0 = parse_state("--p0", o.p0, dflt, why);
  p.t_end = checked_t_end(o.t_end);
  if (o.has("--h-list")) p.hs = parse_step_list("--h-list", o.h_list, p.t_end, kMaxStepsLog10);
  p.expected = check_expected_order(o.expected);
  p.order_tol = checked_order_tol(o.order_tol);
  if (!o.floor.empty()) p.floor = checked_floor(o.floor);
  check_energy_run(o, p.h, p.steps);
  if (!o.adaptive.empty() && o.adaptive != "epavi")
    throw ArgumentError("--adaptive",
                        "must be epavi (the energy-preserving adaptive integrator of Sharma et "
                        "al. 2022), got '" +
                            o.adaptive + "'");
  p.adaptive_epavi = o.adaptive == "epavi";
  p.adaptive_steps = parse_integer("--adaptive-steps", o.adaptive_steps);
  if (p.adaptive_steps < 256 || p.adaptive_steps > 100000000)
    throw ArgumentError("--adaptive-steps", "must lie in [256, 1e8]");
  const long long k = parse_integer("--modified-order", o.modified_order);
  if (k < 0 || k > 6) throw ArgumentError("--modified-order", "must lie in [0, 6]");
  p.modified_order = static_cast<int>(k);
  p.format = modified::parse_format(o.format);
  if (p.format == modified::Format::python)
    throw ArgumentError("--format", "verify prints text or latex");
  if (o.json_given) check_output_path(o.json_out, "--json-out", true);
  p.symmetric = o.symmetric;
  p.work_precision = o.report_given;
  p.reference_evaluation = o.reference;
  p.timings = o.timings;
  p.ld_text = o.ld;
  p.potential_text = o.potential;
  p.lagrangian_text = o.lagrangian;
  p.hamiltonian_text = o.hamiltonian;
  return p;
}

// `vibook verify --ld`: the library's study (vibook/verify/ld_study.hpp), printed: the text
// report, one line on stderr when it did not pass, the JSON, the report page.
int run_typed(const VerifyOptions& o, const verify::TypedDiscreteLagrangian& dl,
              const verify::LdSettings& s) {
  const verify::LdStudy st = verify::run_ld_study(dl, s);
  std::cout << st.text;
  std::cout.flush();
  if (!st.error_line.empty()) eprint(st.error_line);
  if (o.json_given) write_output_file(o.json_out, st.js.dump(2) + "\n", "--json-out");
  if (!o.report_given) return st.status;
  const std::filesystem::path final_dir = report_directory(o.report);
  const std::string render_error = verify::write_ld_report(st, s, command_line(), final_dir);
  std::cout << "report: " << (final_dir / "index.html").string() << '\n';
  if (!render_error.empty() && st.status == kOk) {
    eprint(fmt::format("vibook: --report: figure not drawn: {}\n", render_error));
    return kFailure;
  }
  return st.status;
}

// --- the route table -----------------------------------------------------------------------
// Each route of `vibook verify` is chosen by one option and takes the options every route
// shares plus its own; any other option given is refused, naming it, before any work. Where an
// option is refused for a reason worth saying (a Hamiltonian for a Galerkin method, which
// discretizes a Lagrangian), the route's notes say it.
struct Route {
  const char* name;                // the option that chooses it, or its name
  std::vector<const char*> takes;  // beyond kCommon
  std::vector<std::pair<const char*, const char*>> notes;  // option, why it does not apply
};

// The options of every route.
const std::vector<const char*> kCommon = {
    "--q0",        "--p0",        "--t-end",       "--h-list",   "--expected-order",
    "--order-tol", "--floor",     "--h",           "--steps",    "--json-out",
    "--report",    "--symmetric", "--max-seconds", "--progress", "--timings"};

// The routes, in the order their choosing options are looked for.
const std::vector<std::pair<std::vector<const char*>, Route>>& routes() {
  static const std::vector<std::pair<std::vector<const char*>, Route>> table = {
      {{"--splitting"},
       {"--splitting",
        {"--splitting", "--problem", "--potential", "--dim", "--symbolic"},
        {{"--hamiltonian", "a splitting runs on --problem or on H = |p|^2/2 + V with --potential"},
         {"--lagrangian",
          "a splitting runs on --problem or on H = |p|^2/2 + V with --potential"}}}},
      {{"--tableau"},
       {"--tableau",
        {"--tableau", "--problem", "--potential", "--hamiltonian", "--dim", "--symbolic"},
        {{"--lagrangian",
          "a partitioned Runge-Kutta method runs on Hamilton's equations; type H after "
          "--hamiltonian (or V after --potential)"}}}},
      {{"--method"},
       {"--method",
        {"--method", "--problem", "--potential", "--lagrangian", "--dim", "--symbolic",
         "--constraint"},
        {{"--hamiltonian",
          "a Galerkin method discretizes a Lagrangian; type it after --lagrangian (or V after "
          "--potential)"}}}},
      {{"--stepper-lib", "--stepper-cmd"},
       {"a black-box stepper",
        {"--stepper-lib", "--stepper-cmd", "--stepper-arg", "--stepper-timeout",
         "--stepper-protocol", "--problem", "--hamiltonian", "--potential", "--dim",
         "--constraint"},
        {{"--symbolic", "the variational order of a black box is measured"}}}},
      {{"--composition"},
       {"--composition",
        {"--composition", "--coefficients", "--problem", "--symbolic", "--ld", "--lagrangian",
         "--hamiltonian", "--potential", "--dim", "--constraint"},
        {}}},
  };
  return table;
}

// The typed --ld, when no other route is chosen.
const Route kLd = {
    "--ld",
    {"--ld", "--potential", "--lagrangian", "--hamiltonian", "--dim", "--adaptive",
     "--adaptive-steps", "--modified-order", "--format", "--reference", "--constraint"},
    {{"--problem",
      "the --ld route runs on the system of --potential, "
      "--lagrangian or --hamiltonian"},
     {"--symbolic", "the variational order of a typed --ld is always derived"}}};

// The route the options choose, every option given checked against it (ArgumentError naming
// the first option that does not apply).
const Route& route_of(const VerifyOptions& o, const CLI::App& c) {
  const Route* chosen = nullptr;
  const char* by = nullptr;
  for (const auto& [choosers, route] : routes())
    for (const char* opt : choosers)
      if (c.count(opt) > 0) {
        if (chosen != nullptr && chosen != &route)
          throw ArgumentError(opt, fmt::format("does not apply to {}: give one method", by));
        chosen = &route;
        by = opt;
      }
  const Route& r = chosen ? *chosen : kLd;
  // --composition BASE other than ld (and rattle, on a constrained system) runs on --problem
  // only; constraints are composed with RATTLE alone
  const bool composition = r.name == std::string("--composition");
  const bool other_base = composition && o.composition != "ld" && o.composition != "rattle";
  if (composition && o.composition != "rattle" && !o.constraints.empty())
    throw ArgumentError("--constraint",
                        "does not apply to --composition " + o.composition +
                            ": only RATTLE's steps are composed on a constraint manifold "
                            "(--composition rattle)");
  for (const CLI::Option* opt : c.get_options()) {
    const std::string name = opt->get_name();
    if (opt->count() == 0 || name.rfind("--", 0) != 0) continue;
    auto in = [&](const std::vector<const char*>& list) {
      return std::find_if(list.begin(), list.end(), [&](const char* x) { return name == x; }) !=
             list.end();
    };
    if (other_base && (name == "--ld" || name == "--lagrangian" || name == "--hamiltonian" ||
                       name == "--potential" || name == "--dim"))
      throw ArgumentError(name,
                          "applies to --composition ld only (the composition of the --ld "
                          "typed); the other bases run on --problem");
    if (in(kCommon) || in(r.takes)) continue;
    if (name == "--constraint")
      throw ArgumentError(name, fmt::format("does not apply to {}: constraints are stepped by "
                                            "--method rattle (or shake), its compositions "
                                            "(--composition rattle), the constrained "
                                            "discrete Euler-Lagrange equations of an --ld and "
                                            "a black-box stepper",
                                            r.name));
    for (const auto& [n, why] : r.notes)
      if (name == n)
        throw ArgumentError(name, fmt::format("does not apply to {}: {}", r.name, why));
    throw ArgumentError(name,
                        fmt::format("does not apply to {} (see vibook verify --help)", r.name));
  }
  return r;
}

int run(const VerifyOptions& o, const CLI::App& c) {
  double max_seconds = 0;
  if (!o.max_seconds.empty()) {
    max_seconds = parse_number("--max-seconds", o.max_seconds);
    if (!(max_seconds > 0 && max_seconds <= 1e7))
      throw ArgumentError("--max-seconds", "must be a positive number of seconds, at most 1e7");
  }
  // An option given with an empty value is a mistake, never a request for the default.
  for (const auto& [opt, value] : std::initializer_list<std::pair<const char*, const std::string*>>{
           {"--problem", &o.problem},
           {"--q0", &o.q0},
           {"--p0", &o.p0},
           {"--ld", &o.ld},
           {"--potential", &o.potential},
           {"--lagrangian", &o.lagrangian},
           {"--hamiltonian", &o.hamiltonian},
           {"--coefficients", &o.coefficients},
           {"--method", &o.method},
           {"--tableau", &o.tableau},
           {"--composition", &o.composition},
           {"--splitting", &o.splitting}})
    if (o.has(opt) && value->find_first_not_of(" \t") == std::string::npos)
      throw ArgumentError(opt, "is empty");
  // The typed expressions' derivatives are derived symbolically: the limit covers that too.
  const Watchdog watchdog("verify", max_seconds, o.progress);
  const Route& r = route_of(o, c);
  check_report(o);
  if (r.name == std::string("--splitting")) {
    // A splitting method (verify_composition.cpp): its flows, through its equivalent
    // composition of symplectic Euler and its adjoint, on --problem or --potential.
    if (o.has("--dim") && !o.has("--potential"))
      throw ArgumentError("--dim", "applies to --splitting only with --potential");
    return run_composition(o);
  }
  // A partitioned Runge-Kutta method from its tableau (verify_tableau.cpp).
  if (r.name == std::string("--tableau")) return run_tableau(o);
  if (o.has("--constraint") && r.name != std::string("a black-box stepper") &&
      r.name != std::string("--composition")) {
    // Constraints typed as expressions (verify_constrained.cpp): RATTLE or its unprojected
    // variant, or the constrained DEL of the --ld, on H = |p|^2/2 + V.
    if (r.name == std::string("--method")) {
      if (o.method != "rattle" && o.method != "shake")
        throw ArgumentError("--constraint",
                            "does not apply to --method " + o.method +
                                ": the Galerkin methods do not step constraints (--method rattle "
                                "does, and the constrained DEL of an --ld)");
      if (o.has("--lagrangian"))
        throw ArgumentError("--lagrangian", "does not apply to --method " + o.method +
                                                ": RATTLE steps H = |p|^2/2 + V (--potential)");
      return run_constrained_typed(o, o.method == "rattle" ? verify::ConstrainedStep::rattle
                                                           : verify::ConstrainedStep::shake);
    }
    for (const char* opt : {"--lagrangian", "--hamiltonian", "--adaptive", "--adaptive-steps",
                            "--modified-order", "--format", "--reference"})
      if (o.has(opt))
        throw ArgumentError(opt,
                            "does not apply to an --ld with --constraint: the constrained system "
                            "is H = |p|^2/2 + V(q) (--potential) on the constraint manifold, "
                            "measured by the map study");
    if (o.ld.empty())
      throw ArgumentError("--ld",
                          "is required with --constraint (or --method "
                          "rattle)");
    return run_constrained_typed(o, verify::ConstrainedStep::del);
  }
  // A Galerkin variational integrator from the catalogue (verify_method.cpp), on a test
  // problem or on the --potential or --lagrangian typed.
  if (r.name == std::string("--method")) return run_method(o);
  // Another program's stepper as a black box (verify_stepper.cpp).
  if (r.name == std::string("a black-box stepper")) return run_stepper(o);
  if (r.name != std::string("--ld")) {
    // A composition method (verify_composition.cpp); with base ld, of the --ld typed
    // (verify_composition_ld.cpp), on the system of --potential, --lagrangian or --hamiltonian.
    if (o.composition == "ld" && !o.has("--ld"))
      throw ArgumentError("--ld", "is required with --composition ld");
    return run_composition(o);
  }
  if (o.has("--adaptive-steps") && !o.has("--adaptive"))
    throw ArgumentError("--adaptive-steps", "applies only with --adaptive epavi");
  if (o.ld.empty() && !o.has("--ld"))
    throw ArgumentError("--ld",
                        "is required (or --method NAME:S, --tableau FILE, --composition BASE "
                        "--coefficients LIST|NAME, --splitting SEQ, --stepper-lib or "
                        "--stepper-cmd)");
  progress::set_stage("reading the expressions and deriving L_d's derivatives");
  const int dim = o.dim.empty() ? 0 : static_cast<int>(parse_integer("--dim", o.dim));
  if (!o.dim.empty() && (dim < 1 || dim > verify::kMaxDim))
    throw ArgumentError("--dim", fmt::format("must lie in 1..{}", verify::kMaxDim));
  std::unique_ptr<verify::TypedDiscreteLagrangian> dl;
  {
    verify::TypedTexts texts{o.ld, o.potential, o.lagrangian, o.hamiltonian, dim};
    texts.allow_time = true;
    dl = std::make_unique<verify::TypedDiscreteLagrangian>(texts);
  }
  if (dl->time_dependent() || dl->ld_uses_t()) {
    // A time-dependent system: the DEL step with the clock, in the map study; the phases of the
    // autonomous --ld route that assume a conserved energy or an autonomous L_d are refused.
    for (const char* opt :
         {"--adaptive", "--adaptive-steps", "--modified-order", "--format", "--reference"})
      if (o.has(opt))
        throw ArgumentError(opt,
                            "applies to an autonomous --ld only (the system here depends on "
                            "t: the EpAVI conserves an energy it does not have, and the "
                            "modified equation and the compiled tape are autonomous)");
    return run_timed_ld(o);
  }
  return run_typed(o, *dl, check(o, *dl));
}

}  // namespace

std::function<int()> add_verify_command(CLI::App& app) {
  auto o = std::make_shared<VerifyOptions>();
  auto* c = app.add_subcommand(
      "verify",
      "Verify a discrete Lagrangian typed as an expression against the system you meant: "
      "consistency, order against an independent reference, symplecticity, reversibility, "
      "energy, modified equation");
  c->add_option("--ld", o->ld,
                "discrete Lagrangian L_d(q0, q1, h) ≈ h·L in q0, q1 (components q0[1], …), h, "
                "V(...) and grad(V)(...), e.g. 'h*((q1-q0)^2/(2*h^2) - "
                "(V(q0)+4*V((q0+q1)/2)+V(q1))/6)'; u^2 is |u|^2, [a, b] a vector (required, "
                "and with --composition ld; not with --method, --tableau, a stepper or another "
                "--composition base)");
  c->add_option("--method", o->method,
                "verify a catalogue method instead of an --ld: gauss:S (S = 1-4) or lobatto:S "
                "(S = 2-5), the Galerkin variational integrator with S stages (Gauss "
                "collocation, order 2S; Lobatto IIIA-IIIB, order 2S-2), on --problem or on "
                "--potential (1-3 dimensions)");
  c->add_option("--symbolic", o->symbolic,
                "with --method, --composition or --tableau: when the symbolic engine "
                "derives the variational order beside the measured one: auto (default: where it "
                "is quick, i.e. one degree of freedom, a polynomial Lagrangian, or order <= 4), "
                "always, never");
  c->add_option("--tableau", o->tableau,
                "verify a partitioned Runge-Kutta method instead of an --ld: a JSON file with "
                "the tableau (a, b; ahat, bhat for the momenta; order, symmetric, name, source), "
                "entries as decimals or ratios such as \"5/24\"; see examples/tableaus; on "
                "--problem or --potential (1-3 dimensions)");
  c->add_option("--composition", o->composition,
                "verify a composition of this base method instead of an --ld: sv, midpoint, se, "
                "se-adjoint, or Shen & Sun's vi1, vi1-adjoint, vi2 (on --problem); or ld, the "
                "--ld typed (its adjoint -L_d(q1, q0, -h) for '*' stages; dimensions 1-3) on the "
                "system of --potential or --hamiltonian; or rattle, RATTLE on a constrained "
                "system (--potential with --constraint, or --problem spherical-pendulum or "
                "double-pendulum) (order conditions at 120 digits, measured order, "
                "symplecticity, reversibility, energy)");
  c->add_option(
      "--splitting", o->splitting,
      "verify a splitting method of H = T(p) + V(q) instead of an --ld: its flows in "
      "the order they act, 'drift:c1,kick:d1,drift:c2,...' (coefficients as ratios, "
      "decimals or expressions such as 1/(2-2^(1/3)) or 1/2-sqrt(3)/6), or a catalogue "
      "name (leapfrog, forest-ruth, omelyan-2, saba-2, saba-3, saba-4, sbab-2, sbab-3, ruth-3); on "
      "--problem, or on H = |p|^2/2 + V with --potential (order conditions for two flows "
      "at 120 digits, its equivalent "
      "composition of symplectic Euler, measured order, symplecticity, symmetry, "
      "energy)");
  c->add_option("--coefficients", o->coefficients,
                "with --composition: a catalogue name (yoshida4, suzuki4, yoshida6, yoshida8, "
                "mclachlan8, kahanli6, kahanli8, ruth3) or the stages' coefficients in order of "
                "application, e.g. '7/24*,3/8,3/8*,-25/24,1*' (decimals or ratios; '*' marks the "
                "adjoint)");
  c->add_option("--problem", o->problem,
                "with --method, --tableau, --composition or a stepper: the nonlinear test "
                "problem, kepler (default, eccentricity 0.5), pendulum or henon-heiles "
                "(--method, --tableau and --composition ld take --potential instead; --method "
                "also --lagrangian, --tableau also --hamiltonian)");
  c->add_option("--stepper-lib", o->stepper_lib,
                "verify another library's one-step method as a black box: a shared library "
                "with the C ABI of vibook/verify/stepper_abi.h (needs --expected-order; the "
                "system from --problem or --hamiltonian)");
  c->add_option("--stepper-cmd", o->stepper_cmd,
                "verify a program's one-step method as a black box through the line protocol: "
                "vibook writes 'H N q.. p..' (N steps of H), the program answers 'q.. p..' or "
                "'error REASON' (needs --expected-order; the system from --problem or "
                "--hamiltonian)");
  c->add_option("--stepper-arg", o->stepper_arg,
                "with --stepper-lib: the text passed to vibook_stepper_create (e.g. which method)");
  c->add_option("--stepper-protocol", o->stepper_protocol,
                "with --stepper-cmd: the line protocol's version, 1 (default; requests 'H N q.. "
                "p..') or 2 (requests 'T H N q.. p..', T the start time: needed for a "
                "time-dependent system, t in --hamiltonian or --potential)");
  c->add_option("--stepper-timeout", o->stepper_timeout,
                "with --stepper-cmd or --stepper-lib: seconds to wait for one answer (default "
                "60)");
  c->add_option("--lagrangian", o->lagrangian,
                "the intended Lagrangian L(q, v) in q, v (q[1], v[2], …), V(...), grad(V)(...); "
                "default v^2/2 - V(q); with --method: the system the Galerkin method runs on");
  c->add_option("--hamiltonian", o->hamiltonian,
                "the intended Hamiltonian H(q, p) instead, in q, p, V(...), grad(V)(...); with "
                "--tableau: the system the method runs on");
  c->add_option("--potential", o->potential,
                "V in x, y, z (or q, q[1], …), e.g. 'x^2/2+y^2/2+x^2*y-y^3/3' (a leading minus: "
                "--potential='-cos(x)'); required unless --lagrangian or --hamiltonian is given; "
                "with --method or --tableau: the system L = v^2/2 - V(q) the method runs on");
  c->add_option("--constraint", o->constraints,
                "a holonomic constraint g(q) = 0 in x, y, z (or q, q[1], ...), repeatable, e.g. "
                "'x^2+y^2+z^2-1'; with --method rattle|shake, an --ld (its constrained discrete "
                "Euler-Lagrange equations) or a black-box stepper, on H = |p|^2/2 + V with "
                "--potential, 2-4 positions, --q0 and --p0 on the constraint manifold")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  c->add_option("--dim", o->dim,
                fmt::format("dimension 1-{} (default: from the expressions)", verify::kMaxDim));
  c->add_option("--q0", o->q0, "initial position, comma-separated (default 0.1 in each)");
  c->add_option("--p0", o->p0, "initial momentum dL/dv, comma-separated (default 0.1 in each)");
  c->add_option("--t-end", o->t_end, "time of the order study (default 5)");
  c->add_option("--h-list", o->h_list,
                "step sizes of the order study (default: the walk h = T/ceil(T 2^(k/4)), k = 0, "
                "1, ..., until the error leaves the window)");
  c->add_option("--expected-order", o->expected, "order to test against (default 2)");
  c->add_option("--order-tol", o->order_tol, "accepted |fitted - expected| (default 0.2)");
  c->add_option("--floor", o->floor,
                "errors at or below this are left out of the order fit (default: found from the "
                "data above max(10 x the reference's error, 16 u))");
  c->add_option("--h", o->h, "step of the symplecticity, reversibility and energy tests (0.05)");
  c->add_option("--steps", o->steps, "steps of the energy test (default 100000)");
  c->add_option("--adaptive", o->adaptive,
                "also run the --ld as an energy-preserving adaptive integrator: epavi (Sharma et "
                "al. 2022: the extended L_d(t0, q0, t1, q1) = L_d(q0, q1, t1 - t0), the step from "
                "the energy condition (16), the first step --h from the reference); reports the "
                "energy of the intended system, the steps, and where no admissible step exists");
  c->add_option("--adaptive-steps", o->adaptive_steps,
                "with --adaptive: steps of the adaptive run (default 10000)");
  c->add_option("--modified-order", o->modified_order,
                "highest h power of the modified equation (2)");
  c->add_option("--format", o->format, "modified equation as text (default) or latex");
  c->add_option("--json-out", o->json_out, "also write every measurement as JSON to this file");
  c->add_option("--report", o->report,
                "also write an HTML report into this new directory, on every route: the "
                "verdicts' table, the report, CSV and JSON (with --ld also figures and "
                "work-precision beside Störmer-Verlet and the implicit midpoint rule)");
  c->add_flag("--symmetric", o->symmetric,
              "the method is meant to be symmetric (its own adjoint), on every route: its "
              "symmetry becomes part of the verdict, and its time-reversibility too where the "
              "intended system is reversible (otherwise both are reported only)");
  c->add_option("--max-seconds", o->max_seconds,
                "stop with status 3, naming the part reached, if verify takes longer");
  c->add_flag("--progress", o->progress,
              "show the part being measured on standard error also when it is not a terminal");
  c->add_flag("--reference", o->reference,
              "step the method through nested AutoDiff on the expression tree instead of the "
              "compiled tape (slower; the path the tape is checked against)");
  c->add_flag("--timings", o->timings,
              "print the time of each part (and put it in the report, which then differs from "
              "run to run)");
  return [o, c] {
    for (const CLI::Option* opt : c->get_options())
      if (opt->count() > 0) o->given.insert(opt->get_name());
    o->json_given = o->has("--json-out");
    o->report_given = o->has("--report");
    return run(*o, *c);
  };
}

}  // namespace vibook::cli
