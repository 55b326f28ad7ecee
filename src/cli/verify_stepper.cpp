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
#include "verify_routes.hpp"

#include <cmath>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "args.hpp"
#include "verify_map.hpp"
#include "vibook/verify/black_box_study.hpp"
#include "vibook/verify/constrained.hpp"
#include "vibook/verify/expression.hpp"
#include "vibook/verify/line_protocol.hpp"

namespace vibook::cli {

namespace {

using nlohmann::json;

// --- the two kinds of black box: a library (vibook/verify/black_box.hpp) and a command ------

using verify::BlackBox;

// --- the system the stepper is meant for ------------------------------------------------------

struct Plan {
  std::unique_ptr<verify::TypedDiscreteLagrangian> system;
  verify::BlackBoxSetup setup;  // the stepper, the system, the initial state
  double timeout = 60;
  MapStudy study;  // the measurement settings (--t-end, --h-list, --h, --steps, …)
};

Plan check(const VerifyOptions& o) {
  Plan p;
  const bool lib = o.has("--stepper-lib"), cmd = o.has("--stepper-cmd");
  if (lib == cmd)
    throw ArgumentError(lib ? "--stepper-cmd" : "--stepper-lib",
                        "give one stepper: --stepper-lib LIB.so or --stepper-cmd 'CMD'");
  if (lib && o.stepper_lib.empty()) throw ArgumentError("--stepper-lib", "is empty");
  if (cmd && o.stepper_cmd.find_first_not_of(" \t") == std::string::npos)
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
    p.setup.hamiltonian = o.hamiltonian.empty() ? "p^2/2 + V(q)" : o.hamiltonian;
    p.setup.system_from = o.hamiltonian.empty() ? "--potential" : "--hamiltonian";
  } else {
    named = &find_test_problem(o.problem);
    if (!o.potential.empty() || !o.dim.empty())
      throw ArgumentError(o.dim.empty() ? "--potential" : "--dim",
                          "does not apply to --problem (use --hamiltonian for another system)");
    p.setup.hamiltonian = named->expression;
    p.setup.system_from = "--problem " + named->name;
    dq0 = named->q0;
    dp0 = named->p0;
  }
  int dim = named ? static_cast<int>(named->q0.size()) : 0;
  if (!o.dim.empty()) dim = check_dim(o, verify::kMaxDim);
  if (o.has("--stepper-protocol")) {
    if (!cmd)
      throw ArgumentError("--stepper-protocol",
                          "applies only to --stepper-cmd (a library speaks the C ABI)");
    if (o.stepper_protocol != "1" && o.stepper_protocol != "2")
      throw ArgumentError("--stepper-protocol", "must be 1 or 2, got '" + o.stepper_protocol + "'");
    p.setup.protocol = o.stepper_protocol == "2" ? 2 : 1;
  }
  {
    verify::TypedTexts t{"", o.potential, "", p.setup.hamiltonian, dim};
    t.system_only = true;
    t.allow_time = true;
    t.constraints = o.constraints;
    p.system = std::make_unique<verify::TypedDiscreteLagrangian>(t);
  }
  const int n = p.system->dim();
  // A time-dependent system needs a stepper that is told the time (a library: checked when it
  // is loaded, by its ABI version).
  if (p.system->time_dependent()) {
    if (cmd && p.setup.protocol != 2)
      throw ArgumentError("--stepper-protocol",
                          "the system depends on t: line protocol 1 carries no time; a stepper "
                          "that takes requests 'T H N q.. p..' is given with --stepper-protocol "
                          "2");
  }
  if (dq0.empty()) {
    dq0.assign(static_cast<std::size_t>(n), 0.1);
    dp0.assign(static_cast<std::size_t>(n), 0.1);
  }
  const std::string why = fmt::format("the system has {} degrees of freedom", n);
  p.setup.q0 = parse_state("--q0", o.q0, dq0, why);
  p.setup.p0 = parse_state("--p0", o.p0, dp0, why);
  if (constrained) {  // the counts and the state on the manifold, before the stepper starts
    MapStudy scratch;
    verify::set_constrained_typed_system(scratch, *p.system, o.potential, p.setup.q0, p.setup.p0);
  }
  check_t_end(o, p.study);
  if (!o.has("--expected-order"))
    throw ArgumentError("--expected-order",
                        "is required with a black-box stepper: the order it is documented to "
                        "have (the verdict tests it)");
  p.study.expected = check_expected_order(o.expected);
  check_study_options(o, p.study);
  if (!o.stepper_timeout.empty()) {
    p.timeout = parse_number("--stepper-timeout", o.stepper_timeout);
    if (!(p.timeout > 0 && p.timeout <= 86400))
      throw ArgumentError("--stepper-timeout", "must lie in (0, 86400] seconds");
  }
  if (cmd && !o.stepper_arg.empty())
    throw ArgumentError("--stepper-arg",
                        "applies only to --stepper-lib (put a command's "
                        "arguments in the command)");
  return p;
}

int run(const VerifyOptions& o, const Plan& p) {
  const int N = p.system->dim();
  MapReport rep;
  Eigen::VectorXd z0(2 * N);
  for (int i = 0; i < N; ++i) {
    z0(i) = p.setup.q0[static_cast<std::size_t>(i)];
    z0(N + i) = p.setup.p0[static_cast<std::size_t>(i)];
  }

  // The black box, and a first step from the initial state: a stepper that cannot take it is
  // refused as an argument, before any measurement.
  std::unique_ptr<BlackBox> box;
  int abi = 0;  // a library's ABI version
  if (o.has("--stepper-lib")) {
    // The library runs in a child process of its own (forked, the protocol of --stepper-cmd
    // inside): an abort() or a crash in it ends the child, never vibook, and it is held to
    // --stepper-timeout like a command.
    const std::string lib = o.stepper_lib, arg = o.stepper_arg;
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
    box = std::make_unique<verify::LineProtocolStepper>(o.stepper_cmd, N, p.timeout,
                                                        p.setup.protocol);
  verify::check_first_step(*box, z0, p.study.h, N,
                           o.has("--stepper-lib") ? "--stepper-lib" : "--stepper-cmd");
  verify::BlackBoxSetup setup = p.setup;
  setup.library = o.has("--stepper-lib");
  setup.path = setup.library ? o.stepper_lib : o.stepper_cmd;
  setup.arg = o.stepper_arg;
  setup.abi = abi;
  setup.potential = o.potential;
  setup.constraints = o.constraints;
  setup.timings = o.timings;
  verify::measure_black_box(*box, *p.system, setup, p.study, rep);
  box.reset();  // the child process ends before the report is printed
  return rep.finish(o);
}

}  // namespace

int run_stepper(const VerifyOptions& o) { return run(o, check(o)); }

}  // namespace vibook::cli
