/// \file black_box_study.cpp
/// \brief A black-box stepper as a map study's one-step map, and its work–precision table
/// (black_box_study.hpp).
#include "vibook/verify/black_box_study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "vibook/core/errors.hpp"
#include "vibook/verify/constrained.hpp"
#include "vibook/verify/line_protocol.hpp"
#include "vibook/verify/typed_system.hpp"

namespace vibook::verify {

namespace {

using nlohmann::json;

std::string where(const Eigen::VectorXd& z, int dof) {
  const std::vector<double> q(z.data(), z.data() + dof), p(z.data() + dof, z.data() + 2 * dof);
  return fmt::format("q = {}, p = {}", vec_text(q), vec_text(p));
}

bool finite(const Eigen::VectorXd& z) { return z.allFinite(); }

}  // namespace

void check_first_step(BlackBox& box, const Eigen::VectorXd& z0, double h, int dof,
                      const std::string& option) {
  Eigen::VectorXd z = z0;
  try {
    box.run(h, 1, z.data(), z.data() + dof);
  } catch (const StepperKilled& e) {
    // A crash is the method's code failing, not a refusal of the arguments.
    throw NumericalError(
        fmt::format("the stepper's first step of h = {:g} from the initial "
                    "state: {}",
                    h, e.what()));
  } catch (const NumericalError& e) {
    throw ArgumentError(option, fmt::format("the stepper did not take a first step of h = {:g} "
                                            "from the initial state: {}",
                                            h, e.what()));
  }
  if (!finite(z))
    throw ArgumentError(option, fmt::format("the stepper's first step of h = {:g} from the "
                                            "initial state returned a non-finite state",
                                            h));
}

void set_black_box_map(MapStudy& s, BlackBox& box, int dof) {
  BlackBox* raw = &box;
  const int N = dof;
  // A time-dependent system's state carries the clock last (MapStudy::timed): the stepper is
  // told the start time of each request, and the clock advances by the steps taken.
  s.step = [raw, N](Eigen::VectorXd& z, double h) {
    const Eigen::VectorXd start = z;
    const bool timed = z.size() == 2 * N + 1;
    if (timed) raw->set_time(z(2 * N));
    try {
      raw->run(h, 1, z.data(), z.data() + N);
      if (timed) z(2 * N) += h;
    } catch (const NumericalError& e) {
      throw NumericalError(
          fmt::format("a step of h = {:g} from {}: {}", h, where(start, N), e.what()));
    }
    if (!finite(z))
      throw NumericalError(fmt::format("a step of h = {:g} from {} returned a non-finite state", h,
                                       where(start, N)));
  };
  // A run of the order study is one request (both kinds talk to a child process).
  s.propagate = [raw, N](Eigen::VectorXd& z, double h, long long n) {
    const Eigen::VectorXd start = z;
    const bool timed = z.size() == 2 * N + 1;
    if (timed) raw->set_time(z(2 * N));
    try {
      raw->run(h, n, z.data(), z.data() + N);
      if (timed) z(2 * N) = start(2 * N) + double(n) * h;
    } catch (const NumericalError& e) {
      throw NumericalError(
          fmt::format("{} steps of h = {:g} from {}: {}", n, h, where(start, N), e.what()));
    }
    if (!finite(z))
      throw NumericalError(
          fmt::format("{} steps of h = {:g} from {} returned a non-finite "
                      "state",
                      n, h, where(start, N)));
  };
  // The energy runs' states, a block of steps a request (a library's host answers them all;
  // a command, one step a request).
  s.every = [raw, N](Eigen::VectorXd& z, double h, long long n, const std::function<void()>& each) {
    Eigen::VectorXd start = z;
    const bool timed = z.size() == 2 * N + 1;
    const double t0 = timed ? z(2 * N) : 0.0;
    long long k = 0;
    if (timed) raw->set_time(t0);
    try {
      raw->every(h, n, z.data(), z.data() + N, [&] {
        if (!finite(z))
          throw NumericalError(fmt::format("a step of h = {:g} from {} returned a non-finite state",
                                           h, where(start, N)));
        if (timed) z(2 * N) = t0 + double(++k) * h;
        each();
        start = z;
      });
    } catch (const NumericalError& e) {
      if (!finite(z)) throw;
      throw NumericalError(
          fmt::format("a step of h = {:g} from {}: {}", h, where(start, N), e.what()));
    }
  };
}

namespace {

// --- work against precision, beside two built-in methods (report only) -----------------------
// The black box's error at T against the independent reference, at five step sizes spread over
// the range its order was fitted on, beside the classical Runge–Kutta method (order 4, not
// symplectic) and, when H = |p|²/2 + V, Störmer–Verlet, both stepped on the typed system here.
// Steps are the work measure every one-step method shares; the wall-clock seconds of each run
// (the only work measure a black box has) are added with --timings, which makes the report
// differ from run to run.
template <int N>
void work_precision(const MapStudy& s, const TypedDiscreteLagrangian& sys, bool separable,
                    bool timings, MapMeasurement& rep) {
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
    if (timings) jm[m.key]["seconds"] = secs;
    std::vector<std::string> cells;
    for (std::size_t i = 0; i < hs.size(); ++i)
      cells.push_back(timings ? fmt::format("{:.2e} ({:.3g} s)", err[i], secs[i])
                              : fmt::format("{:.2e}", err[i]));
    rep.line("", fmt::format("{:<15}{}", m.name, fmt::join(cells, "  ")));
  }
  rep.line("", fmt::format("(error at T = {:g} against the reference; {}; report only)", s.t_end,
                           timings ? "seconds per run in parentheses"
                                   : "--timings adds the seconds of each run"));
  rep.js["work_precision"] = {{"h", hs},
                              {"steps", steps},
                              {"methods", jm},
                              {"note",
                               "error at T against the reference; rk4 and stormer_verlet "
                               "(when H = |p|^2/2 + V) are stepped by vibook on the same "
                               "system; report only"}};
}

}  // namespace

void black_box_work_precision(const MapStudy& s, const TypedDiscreteLagrangian& sys, bool separable,
                              bool timings, MapMeasurement& rep) {
  if (s.timed) {
    // The two peers are stepped here on an autonomous field; a time-dependent system would
    // need their stage times too.
    rep.line("work-precision", "not run: the peers are stepped for autonomous systems only");
    return;
  }
  with_dim(sys.dim(),
           [&](auto n) { work_precision<decltype(n)::value>(s, sys, separable, timings, rep); });
}

void measure_black_box(BlackBox& box, const TypedDiscreteLagrangian& sys,
                       const BlackBoxSetup& setup, MapStudy s, MapMeasurement& rep) {
  using nlohmann::json;
  const int N = sys.dim();
  set_black_box_map(s, box, N);
  const bool constrained = sys.constraint_count() > 0;
  if (constrained)  // the index-1 reference, the constraint residuals, the manifold's tangents
    set_constrained_typed_system(s, sys, setup.potential, setup.q0, setup.p0);
  else
    set_typed_system(s, sys, setup.q0, setup.p0);
  if (!setup.library) s.max_substeps = 1e5;
  s.symmetric_note = " (reported only: --symmetric makes it part of the verdict)";
  if (setup.library)
    rep.line("stepper",
             fmt::format("library {} (vibook stepper ABI {}){}", setup.path, setup.abi,
                         setup.arg.empty() ? "" : ", --stepper-arg '" + setup.arg + "'"));
  else
    rep.line("stepper", fmt::format("command '{}' (line protocol {})", setup.path, setup.protocol));
  std::string constraints;
  for (int i = 0; i < sys.constraint_count(); ++i)
    constraints += fmt::format("{}g{} = {}", i ? ", " : "", i + 1, sys.constraint_text(i));
  rep.line("system", fmt::format("H = {} ({}), {} degree{} of freedom{}", setup.hamiltonian,
                                 setup.system_from, N, N == 1 ? "" : "s",
                                 constrained ? ", constraints " + constraints : ""));
  rep.line("initial state",
           fmt::format("q0 = {}, p0 = {}", vec_text(setup.q0), vec_text(setup.p0)));
  rep.line("expected order", fmt::format("{:g} (--expected-order)", s.expected));
  rep.js["stepper"] = {{"kind", setup.library ? "library" : "command"},
                       {"library", setup.library ? json(setup.path) : json(nullptr)},
                       {"command", !setup.library ? json(setup.path) : json(nullptr)},
                       {"arg", setup.arg},
                       {"abi_version", setup.library ? json(setup.abi) : json(nullptr)},
                       {"dof", N}};
  if (setup.protocol == 2) rep.js["stepper"]["line_protocol"] = 2;
  rep.js["system"] = {{"hamiltonian", setup.hamiltonian},
                      {"from", setup.system_from},
                      {"potential", setup.potential},
                      {"constraints", setup.constraints},
                      {"q0", setup.q0},
                      {"p0", setup.p0}};
  measure_map(s, rep);
  // Work against precision beside RK4 and, where H = |p|^2/2 + V, Stormer-Verlet (not for a
  // constrained system: neither keeps its constraints).
  const bool separable =
      setup.system_from == "--potential" || setup.system_from.rfind("--problem", 0) == 0;
  if (!constrained) black_box_work_precision(s, sys, separable, setup.timings, rep);
  const std::string why =
      "a black-box stepper has no discrete Lagrangian to expand; its order is the measured one";
  rep.line("variational order", "not derived: " + why);
  rep.js["variational_order"] = {{"derived", false}, {"reason", why}};
}

}  // namespace vibook::verify
