// `vibook verify --stepper-lib LIB.so | --stepper-cmd 'CMD'` (issue #25, "any stepper as a black
// box"): a one-step method vibook did not write, reached through the C ABI of
// vibook/verify/stepper_abi.h (loaded with dlopen) or through a line protocol over a child
// process's stdin and stdout (so a Python or Julia script can be verified). The system it is
// meant for is named by the user (`--problem` or `--hamiltonian`), and every measurement is made
// against Hamilton's equations of that system integrated in double-double (verify_map.cpp):
// order (two-sided, against the documented order the user states with --expected-order),
// symplecticity and reversibility of the map, and the energy.
//
// The line protocol, version 1 (book: chapter "Verifying your own discrete Lagrangian"):
//   vibook writes one request per line:   H N q_1 … q_d p_1 … p_d
//     (N steps of size H from the state; numbers in decimal, 17 significant digits);
//   the stepper answers one line:         q_1 … q_d p_1 … p_d
//     (the state after the N steps), or a line beginning with `error` and a reason.
//   When vibook is done it closes the stepper's stdin; the stepper should then exit.
#include "verify_stepper.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "args.hpp"
#include "verify_map.hpp"
#include "vibook/core/output_file.hpp"
#include "vibook/modified/engine.hpp"
#include "vibook/verify/black_box_study.hpp"
#include "vibook/verify/constrained.hpp"
#include "vibook/verify/expression.hpp"
#include "vibook/verify/line_protocol.hpp"
#include "vibook/verify/stepper_abi.h"

namespace vibook::cli {

namespace {

using nlohmann::json;

// --- the two kinds of black box: a library (vibook/verify/black_box.hpp) and a command ------

using verify::BlackBox;

// --- the system the stepper is meant for ------------------------------------------------------

struct Plan {
  std::unique_ptr<verify::TypedDiscreteLagrangian> system;
  std::string hamiltonian, system_from;
  int dim = 0, protocol = 1;
  std::vector<double> q0, p0;
  double expected = 0, timeout = 60;
  MapStudy study;  // the measurement settings (--t-end, --h-list, --h, --steps, …)
};

Plan check(const StepperOptions& o) {
  Plan p;
  if (o.lib_given == o.cmd_given)
    throw ArgumentError(o.lib_given ? "--stepper-cmd" : "--stepper-lib",
                        "give one stepper: --stepper-lib LIB.so or --stepper-cmd 'CMD'");
  if (o.lib_given && o.lib.empty()) throw ArgumentError("--stepper-lib", "is empty");
  if (o.cmd_given && o.cmd.find_first_not_of(" \t") == std::string::npos)
    throw ArgumentError("--stepper-cmd", "is empty");
  if (!o.problem.empty() && !o.hamiltonian.empty())
    throw ArgumentError("--hamiltonian", "give the system once: --problem or --hamiltonian");
  const bool constrained = !o.constraints.empty();
  if (constrained && (o.potential.empty() || !o.hamiltonian.empty() || !o.problem.empty()))
    throw ArgumentError(!o.hamiltonian.empty() ? "--hamiltonian"
                        : !o.problem.empty()   ? "--problem"
                                               : "--potential",
                        "with --constraint the system is H = |p|^2/2 + V(q) with V from "
                        "--potential (type 0 for a free particle) on the constraint manifold");
  if (constrained && (o.q0.empty() || o.p0.empty()))
    throw ArgumentError(o.q0.empty() ? "--q0" : "--p0",
                        "is required with --constraint: a state on the constraint manifold, "
                        "g(q0) = 0 and G(q0) p0 = 0");
  for (const std::string& g : o.constraints)
    if (g.find_first_not_of(" \t") == std::string::npos)
      throw ArgumentError("--constraint", "is empty");
  const TestProblem* named = nullptr;
  std::vector<double> dq0, dp0;
  if (!o.hamiltonian.empty() || (!o.potential.empty() && o.problem.empty())) {
    p.hamiltonian = o.hamiltonian.empty() ? "p^2/2 + V(q)" : o.hamiltonian;
    p.system_from = o.hamiltonian.empty() ? "--potential" : "--hamiltonian";
  } else {
    named = &find_test_problem(o.problem);
    if (!o.potential.empty() || !o.dim.empty())
      throw ArgumentError(o.dim.empty() ? "--potential" : "--dim",
                          "does not apply to --problem (use --hamiltonian for another system)");
    p.hamiltonian = named->expression;
    p.system_from = "--problem " + named->name;
    dq0 = named->q0;
    dp0 = named->p0;
  }
  int dim = named ? static_cast<int>(named->q0.size()) : 0;
  if (!o.dim.empty()) {
    dim = static_cast<int>(parse_integer("--dim", o.dim));
    if (dim < 1 || dim > verify::kMaxDim)
      throw ArgumentError("--dim", fmt::format("must lie in 1..{}", verify::kMaxDim));
  }
  if (o.protocol_given) {
    if (!o.cmd_given)
      throw ArgumentError("--stepper-protocol",
                          "applies only to --stepper-cmd (a library speaks the C ABI)");
    if (o.protocol != "1" && o.protocol != "2")
      throw ArgumentError("--stepper-protocol", "must be 1 or 2, got '" + o.protocol + "'");
    p.protocol = o.protocol == "2" ? 2 : 1;
  }
  {
    std::lock_guard<std::mutex> lock(modified::ginac_mutex());
    verify::TypedTexts t{"", o.potential, "", p.hamiltonian, dim};
    t.system_only = true;
    t.allow_time = true;
    t.constraints = o.constraints;
    p.system = std::make_unique<verify::TypedDiscreteLagrangian>(t);
  }
  p.dim = p.system->dim();
  // A time-dependent system needs a stepper that is told the time (a library: checked when it
  // is loaded, by its ABI version).
  if (p.system->time_dependent()) {
    if (o.cmd_given && p.protocol != 2)
      throw ArgumentError("--stepper-protocol",
                          "the system depends on t: line protocol 1 carries no time; a stepper "
                          "that takes requests 'T H N q.. p..' is given with --stepper-protocol "
                          "2");
  }
  if (dq0.empty()) {
    dq0.assign(static_cast<std::size_t>(p.dim), 0.1);
    dp0.assign(static_cast<std::size_t>(p.dim), 0.1);
  }
  auto vector_or = [&](const std::string& arg, const std::string& text,
                       const std::vector<double>& dflt) {
    std::vector<double> v = text.empty() ? dflt : parse_list(arg, text);
    if (v.size() != static_cast<std::size_t>(p.dim))
      throw ArgumentError(arg, fmt::format("has {} components; the system has {} degrees of "
                                           "freedom",
                                           v.size(), p.dim));
    for (double x : v)
      if (!std::isfinite(x)) throw ArgumentError(arg, "must be finite");
    return v;
  };
  p.q0 = vector_or("--q0", o.q0, dq0);
  p.p0 = vector_or("--p0", o.p0, dp0);
  if (constrained) {  // the counts and the state on the manifold, before the stepper starts
    MapStudy scratch;
    verify::set_constrained_typed_system(scratch, *p.system, o.potential, p.q0, p.p0);
  }
  if (o.t_end_given) {
    p.study.t_end = parse_number("--t-end", o.t_end);
    if (!(p.study.t_end > 0) || p.study.t_end > 1e4)
      throw ArgumentError("--t-end", "must lie in (0, 1e4]");
  }
  if (!o.expected_given)
    throw ArgumentError("--expected-order",
                        "is required with a black-box stepper: the order it is documented to "
                        "have (the verdict tests it)");
  p.expected = check_expected_order(o.expected);
  check_study_options(o, p.study);
  if (!o.timeout.empty()) {
    p.timeout = parse_number("--stepper-timeout", o.timeout);
    if (!(p.timeout > 0 && p.timeout <= 86400))
      throw ArgumentError("--stepper-timeout", "must lie in (0, 86400] seconds");
  }
  if (o.cmd_given && !o.arg.empty())
    throw ArgumentError("--stepper-arg",
                        "applies only to --stepper-lib (put a command's "
                        "arguments in the command)");
  if (o.json_given) check_output_path(o.json_out, "--json-out", true);
  return p;
}

int run(const StepperOptions& o, const Plan& p) {
  const int N = p.dim;
  MapReport rep;
  Eigen::VectorXd z0(2 * N);
  for (int i = 0; i < N; ++i) {
    z0(i) = p.q0[static_cast<std::size_t>(i)];
    z0(N + i) = p.p0[static_cast<std::size_t>(i)];
  }

  // The black box, and a first step from the initial state: a stepper that cannot take it is
  // refused as an argument, before any measurement.
  std::unique_ptr<BlackBox> box;
  int abi = 0;  // a library's ABI version
  if (o.lib_given) {
    // The library runs in a child process of its own (forked, the protocol of --stepper-cmd
    // inside): an abort() or a crash in it ends the child, never vibook, and it is held to
    // --stepper-timeout like a command.
    const std::string lib = o.lib, arg = o.arg;
    auto host = std::make_unique<verify::LineProtocolStepper>(
        [lib, arg, N] { return verify::serve_stepper_library(lib, arg, N); }, N, p.timeout);
    bool ended = false;
    if (const std::string why = host->handshake(ended); !why.empty())
      throw ArgumentError("--stepper-lib", ended ? "could not be loaded: " + why +
                                                       " (not a shared library vibook "
                                                       "can load, or one that crashed "
                                                       "while loading)"
                                                 : why);
    if (p.system->time_dependent() && !host->takes_time())
      throw ArgumentError("--stepper-lib",
                          fmt::format("implements stepper ABI version {}, which has no time "
                                      "argument, and the system depends on t: a library for a "
                                      "time-dependent system implements version 2 "
                                      "(vibook_stepper_step_t, vibook/verify/stepper_abi.h)",
                                      host->abi_version()));
    abi = host->abi_version();
    box = std::move(host);
  } else
    box = std::make_unique<verify::LineProtocolStepper>(o.cmd, N, p.timeout, p.protocol);
  verify::check_first_step(*box, z0, p.study.h, N, o.lib_given ? "--stepper-lib" : "--stepper-cmd");
  MapStudy s = p.study;
  verify::set_black_box_map(s, *box, N);
  const bool constrained = p.system->constraint_count() > 0;
  if (constrained)  // the index-1 reference, the constraint residuals, the manifold's tangents
    verify::set_constrained_typed_system(s, *p.system, o.potential, p.q0, p.p0);
  else
    verify::set_typed_system(s, *p.system, p.q0, p.p0);
  s.expected = p.expected;
  // A command answers a whole run at once, but at the speed of its language: the walk of step
  // counts stops at 1e5 steps a run (a library: 1e6, as for the compositions).
  if (o.cmd_given) s.max_substeps = 1e5;
  s.symmetric_claimed = o.symmetric;
  s.symmetric_note = " (reported only: --symmetric makes it part of the verdict)";

  if (o.lib_given)
    rep.line("stepper", fmt::format("library {} (vibook stepper ABI {}){}", o.lib, abi,
                                    o.arg.empty() ? "" : ", --stepper-arg '" + o.arg + "'"));
  else
    rep.line("stepper", fmt::format("command '{}' (line protocol {})", o.cmd, p.protocol));
  std::string constraints;
  for (int i = 0; i < p.system->constraint_count(); ++i)
    constraints += fmt::format("{}g{} = {}", i ? ", " : "", i + 1, p.system->constraint_text(i));
  rep.line("system",
           fmt::format("H = {} ({}), {} degree{} of freedom{}", p.hamiltonian, p.system_from, N,
                       N == 1 ? "" : "s", constrained ? ", constraints " + constraints : ""));
  rep.line("initial state", fmt::format("q0 = {}, p0 = {}", vec_text(p.q0), vec_text(p.p0)));
  rep.line("expected order", fmt::format("{:g} (--expected-order)", p.expected));
  rep.js["stepper"] = {{"kind", o.lib_given ? "library" : "command"},
                       {"library", o.lib_given ? json(o.lib) : json(nullptr)},
                       {"command", o.cmd_given ? json(o.cmd) : json(nullptr)},
                       {"arg", o.arg},
                       {"abi_version", o.lib_given ? json(abi) : json(nullptr)},
                       {"dof", N}};
  if (p.protocol == 2) rep.js["stepper"]["line_protocol"] = 2;
  rep.js["system"] = {{"hamiltonian", p.hamiltonian},
                      {"from", p.system_from},
                      {"potential", o.potential},
                      {"constraints", o.constraints},
                      {"q0", p.q0},
                      {"p0", p.p0}};
  measure_map(s, rep);
  // Work against precision beside RK4 and, where H = |p|^2/2 + V, Stormer-Verlet (not for a
  // constrained system: neither keeps its constraints).
  const bool separable = p.system_from == "--potential" || p.system_from.rfind("--problem", 0) == 0;
  if (!constrained) verify::black_box_work_precision(s, *p.system, separable, o.timings, rep);
  box.reset();  // the child process ends before the report is printed
  rep.variational_order_not_derived(
      "a black-box stepper has no discrete Lagrangian to expand; its order is "
      "the measured one");
  return rep.finish(o);
}

}  // namespace

int run_stepper(const StepperOptions& o) { return run(o, check(o)); }

}  // namespace vibook::cli
