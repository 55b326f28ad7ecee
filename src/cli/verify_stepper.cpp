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
#include "vibook/verify/black_box.hpp"
#include "vibook/verify/expression.hpp"
#include "vibook/verify/line_protocol.hpp"
#include "vibook/verify/stepper_abi.h"

namespace vibook::cli {

namespace {

using nlohmann::json;

std::string vec_text(const double* v, int n) {
  return cli::vec_text(std::vector<double>(v, v + n));
}

// --- the two kinds of black box: a library (vibook/verify/black_box.hpp) and a command ------

using verify::BlackBox;

// --- the system the stepper is meant for ------------------------------------------------------

struct Plan {
  std::unique_ptr<verify::TypedDiscreteLagrangian> system;
  std::string hamiltonian, system_from;
  int dim = 0;
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
  {
    std::lock_guard<std::mutex> lock(modified::ginac_mutex());
    verify::TypedTexts t{"", o.potential, "", p.hamiltonian, dim};
    t.system_only = true;
    p.system = std::make_unique<verify::TypedDiscreteLagrangian>(t);
  }
  p.dim = p.system->dim();
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
  if (o.t_end_given) {
    p.study.t_end = parse_number("--t-end", o.t_end);
    if (!(p.study.t_end > 0) || p.study.t_end > 1e4)
      throw ArgumentError("--t-end", "must lie in (0, 1e4]");
  }
  if (!o.expected_given)
    throw ArgumentError("--expected-order",
                        "is required with a black-box stepper: the order it is documented to "
                        "have (the verdict tests it)");
  p.expected = parse_number("--expected-order", o.expected);
  if (!(p.expected > 0 && p.expected <= verify::kMaxOrder))
    throw ArgumentError("--expected-order",
                        fmt::format("must lie in (0, {:g}]", verify::kMaxOrder));
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

// --- work against precision, beside two built-in methods (report only) -----------------------
// The black box's error at T against the independent reference, at five step sizes spread over
// the range its order was fitted on, beside the classical Runge–Kutta method (order 4, not
// symplectic) and, when H = |p|²/2 + V, Störmer–Verlet, both stepped on the typed system here.
// Steps are the work measure every one-step method shares; the wall-clock seconds of each run
// (the only work measure a black box has) are added with --timings, which makes the report
// differ from run to run.
template <int N>
void work_precision(const StepperOptions& o, const verify::TypedDiscreteLagrangian& sys,
                    const Plan& p, const MapStudy& s, MapReport& rep) {
  using Clock = std::chrono::steady_clock;
  if (!rep.js.contains("reference") || !rep.js.contains("order")) return;
  const std::vector<double> ref = rep.js["reference"]["state"].get<std::vector<double>>();
  Eigen::VectorXd zref(2 * N);
  for (int i = 0; i < 2 * N; ++i) zref(i) = ref[static_cast<std::size_t>(i)];
  // Five step sizes, log-spaced between the largest and smallest h of the order fit, each
  // rounded to T/n so that every run ends at T.
  const auto& jo = rep.js["order"];
  double hmax = 0, hmin = INFINITY;
  for (std::size_t i = 0; i < jo["h"].size(); ++i)
    if (jo["used_in_fit"][i].get<bool>()) {
      hmax = std::max(hmax, jo["h"][i].get<double>());
      hmin = std::min(hmin, jo["h"][i].get<double>());
    }
  if (!(hmax > 0)) return;
  std::vector<double> hs;
  for (int k = 0; k < 5; ++k) {
    const double h = hmax * std::pow(hmin / hmax, k / 4.0);
    const double n = std::ceil(s.t_end / h - 1e-9);
    if (hs.empty() || s.t_end / n < hs.back()) hs.push_back(s.t_end / n);
  }
  auto field = [&sys](const Vec<double, N>& q, const Vec<double, N>& pp) {
    return sys.hamilton_field<N, double>(q, pp);
  };
  MapStudy rk4 = s, sv = s;
  rk4.propagate = nullptr;
  rk4.step = [field](Eigen::VectorXd& z, double h) {
    auto f = [&](const Eigen::VectorXd& y) {
      const Vec<double, 2 * N> r = field(y.head<N>(), y.tail<N>());
      return Eigen::VectorXd(r);
    };
    const Eigen::VectorXd k1 = f(z), k2 = f(z + 0.5 * h * k1), k3 = f(z + 0.5 * h * k2),
                          k4 = f(z + h * k3);
    z += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  };
  struct Method {
    std::string name, key;
    const MapStudy* study;
  };
  std::vector<Method> methods = {{"black box", "black_box", &s}, {"RK4", "rk4", &rk4}};
  // Störmer–Verlet only where H = |p|²/2 + V (the force −∇V is the field's p-part).
  const bool separable = p.system_from == "--potential" || p.system_from.rfind("--problem", 0) == 0;
  if (separable) {
    sv.propagate = nullptr;
    sv.step = [field](Eigen::VectorXd& z, double h) {
      Vec<double, N> q = z.head<N>(), pp = z.tail<N>();
      pp += 0.5 * h * field(q, pp).template tail<N>();
      q += h * pp;
      pp += 0.5 * h * field(q, pp).template tail<N>();
      z << q, pp;
    };
    methods.insert(methods.begin() + 1, {"Störmer-Verlet", "stormer_verlet", &sv});
  }
  std::vector<double> steps;
  for (double h : hs) steps.push_back(std::ceil(s.t_end / h - 1e-9));
  {
    std::vector<std::string> cells;
    for (double n : steps) cells.push_back(fmt::format("{:>8.0f}", n));
    rep.line("work-precision", fmt::format("{:<15}{}", "steps", fmt::join(cells, "  ")));
  }
  json jm = json::object();
  for (const auto& m : methods) {
    std::vector<double> err, secs;
    for (double h : hs) {
      const auto t0 = Clock::now();
      double e = std::numeric_limits<double>::quiet_NaN();
      try {
        e = (run_map(*m.study, s.z0, h, s.t_end) - zref).template lpNorm<Eigen::Infinity>();
      } catch (const NumericalError&) {
        // a step size the method cannot take: no point
      }
      secs.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
      err.push_back(e);
    }
    jm[m.key] = {{"error", err}};
    if (o.timings) jm[m.key]["seconds"] = secs;
    std::vector<std::string> cells;
    for (std::size_t i = 0; i < hs.size(); ++i)
      cells.push_back(o.timings ? fmt::format("{:.2e} ({:.3g} s)", err[i], secs[i])
                                : fmt::format("{:.2e}", err[i]));
    rep.line("", fmt::format("{:<15}{}", m.name, fmt::join(cells, "  ")));
  }
  rep.line("", fmt::format("(error at T = {:g} against the reference; {}; report only)", s.t_end,
                           o.timings ? "seconds per run in parentheses"
                                     : "--timings adds the seconds of each run"));
  rep.js["work_precision"] = {{"h", hs},
                              {"steps", steps},
                              {"methods", jm},
                              {"note",
                               "error at T against the reference; rk4 and stormer_verlet "
                               "(when H = |p|^2/2 + V) are stepped by vibook on the same "
                               "system; report only"}};
}

template <int N>
int run_n(const StepperOptions& o, const Plan& p) {
  const verify::TypedDiscreteLagrangian& sys = *p.system;
  MapReport rep;
  Eigen::VectorXd z0(2 * N);
  for (int i = 0; i < N; ++i) {
    z0(i) = p.q0[static_cast<std::size_t>(i)];
    z0(N + i) = p.p0[static_cast<std::size_t>(i)];
  }

  // The black box, and a first step from the initial state: a stepper that cannot take it is
  // refused as an argument, before any measurement.
  std::unique_ptr<BlackBox> box;
  if (o.lib_given) {
    // The library runs in a child process of its own (forked, the protocol of --stepper-cmd
    // inside): an abort() or a crash in it ends the child, never vibook, and it is held to
    // --stepper-timeout like a command.
    const std::string lib = o.lib, arg = o.arg;
    auto host = std::make_unique<verify::LineProtocolStepper>(
        [lib, arg] { return verify::serve_stepper_library(lib, arg, N); }, N, p.timeout);
    bool ended = false;
    if (const std::string why = host->handshake(ended); !why.empty())
      throw ArgumentError("--stepper-lib", ended ? "could not be loaded: " + why +
                                                       " (not a shared library vibook "
                                                       "can load, or one that crashed "
                                                       "while loading)"
                                                 : why);
    box = std::move(host);
  } else
    box = std::make_unique<verify::LineProtocolStepper>(o.cmd, N, p.timeout);
  const std::string which = o.lib_given ? "--stepper-lib" : "--stepper-cmd";
  auto finite = [](const Eigen::VectorXd& z) { return z.allFinite(); };
  {
    Eigen::VectorXd z = z0;
    try {
      box->run(p.study.h, 1, z.data(), z.data() + N);
    } catch (const verify::StepperKilled& e) {
      // A crash is the method's code failing, not a refusal of the arguments.
      throw NumericalError(
          fmt::format("the stepper's first step of h = {:g} from the initial "
                      "state: {}",
                      p.study.h, e.what()));
    } catch (const NumericalError& e) {
      throw ArgumentError(which, fmt::format("the stepper did not take a first step of h = {:g} "
                                             "from the initial state: {}",
                                             p.study.h, e.what()));
    }
    if (!finite(z))
      throw ArgumentError(which, fmt::format("the stepper's first step of h = {:g} from the "
                                             "initial state returned a non-finite state",
                                             p.study.h));
  }
  BlackBox* raw = box.get();
  auto where = [](const Eigen::VectorXd& z) {
    return fmt::format("q = {}, p = {}", vec_text(z.data(), N), vec_text(z.data() + N, N));
  };
  MapStudy s = p.study;
  s.step = [raw, where, finite](Eigen::VectorXd& z, double h) {
    const Eigen::VectorXd start = z;
    try {
      raw->run(h, 1, z.data(), z.data() + N);
    } catch (const NumericalError& e) {
      throw NumericalError(
          fmt::format("a step of h = {:g} from {}: {}", h, where(start), e.what()));
    }
    if (!finite(z))
      throw NumericalError(
          fmt::format("a step of h = {:g} from {} returned a non-finite state", h, where(start)));
  };
  // A run of the order study is one request (both routes talk to a child process).
  s.propagate = [raw, where, finite](Eigen::VectorXd& z, double h, long long n) {
    const Eigen::VectorXd start = z;
    try {
      raw->run(h, n, z.data(), z.data() + N);
    } catch (const NumericalError& e) {
      throw NumericalError(
          fmt::format("{} steps of h = {:g} from {}: {}", n, h, where(start), e.what()));
    }
    if (!finite(z))
      throw NumericalError(
          fmt::format("{} steps of h = {:g} from {} returned a non-finite "
                      "state",
                      n, h, where(start)));
  };
  // The energy runs' states, a block of steps a request (a library's host answers them all;
  // a command, one step a request as before).
  s.every = [raw, where, finite](Eigen::VectorXd& z, double h, long long n,
                                 const std::function<void()>& each) {
    Eigen::VectorXd start = z;
    try {
      raw->every(h, n, z.data(), z.data() + N, [&] {
        if (!finite(z))
          throw NumericalError(fmt::format("a step of h = {:g} from {} returned a non-finite state",
                                           h, where(start)));
        each();
        start = z;
      });
    } catch (const NumericalError& e) {
      if (!finite(z)) throw;
      throw NumericalError(
          fmt::format("a step of h = {:g} from {}: {}", h, where(start), e.what()));
    }
  };
  set_typed_system<N>(s, sys, z0);
  s.expected = p.expected;
  // A command answers a whole run at once, but at the speed of its language: the walk of step
  // counts stops at 1e5 steps a run (a library: 1e6, as for the compositions).
  if (o.cmd_given) s.max_substeps = 1e5;
  s.symmetric_claimed = o.symmetric;
  s.symmetric_note = " (reported only: --symmetric makes it part of the verdict)";

  if (o.lib_given)
    rep.line("stepper",
             fmt::format("library {} (vibook stepper ABI {}){}", o.lib, VIBOOK_STEPPER_ABI_VERSION,
                         o.arg.empty() ? "" : ", --stepper-arg '" + o.arg + "'"));
  else
    rep.line("stepper", fmt::format("command '{}' (line protocol 1)", o.cmd));
  rep.line("system", fmt::format("H = {} ({}), {} degree{} of freedom", p.hamiltonian,
                                 p.system_from, N, N == 1 ? "" : "s"));
  rep.line("initial state",
           fmt::format("q0 = {}, p0 = {}", vec_text(z0.data(), N), vec_text(z0.data() + N, N)));
  rep.line("expected order", fmt::format("{:g} (--expected-order)", p.expected));
  rep.js["stepper"] = {{"kind", o.lib_given ? "library" : "command"},
                       {"library", o.lib_given ? json(o.lib) : json(nullptr)},
                       {"command", o.cmd_given ? json(o.cmd) : json(nullptr)},
                       {"arg", o.arg},
                       {"abi_version", VIBOOK_STEPPER_ABI_VERSION},
                       {"dof", N}};
  rep.js["system"] = {{"hamiltonian", p.hamiltonian},
                      {"from", p.system_from},
                      {"potential", o.potential},
                      {"q0", p.q0},
                      {"p0", p.p0}};
  measure_map(s, rep);
  work_precision<N>(o, sys, p, s, rep);
  box.reset();  // the child process ends before the report is printed
  rep.variational_order_not_derived(
      "a black-box stepper has no discrete Lagrangian to expand; its order is "
      "the measured one");
  return rep.finish(o);
}

}  // namespace

int run_stepper(const StepperOptions& o) {
  const Plan p = check(o);
  switch (p.dim) {
    case 1:
      return run_n<1>(o, p);
    case 2:
      return run_n<2>(o, p);
    case 3:
      return run_n<3>(o, p);
    case 4:
      return run_n<4>(o, p);
    case 5:
      return run_n<5>(o, p);
    default:
      return run_n<6>(o, p);
  }
}

}  // namespace vibook::cli
