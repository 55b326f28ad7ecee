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
#include "signals.hpp"
#include "vibook/avi/avi.hpp"
#include "vibook/core/angle.hpp"
#include "vibook/core/errors.hpp"
#include "vibook/core/output_file.hpp"
#include "vibook/core/precision.hpp"
#include "vibook/core/recorder.hpp"
#include "vibook/epavi/epavi.hpp"
#include "vibook/epavi/mechanical.hpp"
#include "vibook/integrators/kernels.hpp"
#include "vibook/integrators/splitting.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/mechanics/del_solver.hpp"
#include "vibook/mechanics/discrete_lagrangian.hpp"
#include "vibook/problems/problems.hpp"
#include "vibook/relativistic/exact.hpp"
#include "vibook/relativistic/relativistic.hpp"

namespace vibook::cli {
namespace {

// Every option is kept as the text the user typed and parsed strictly in validate(): CLI11's
// own conversions accept an empty value as "not given" and drop empty list elements.
struct RunOptions {
  std::string problem, method, discrete_lagrangian = "midpoint", csv = "-";
  std::string precision = "double", energy_target = "previous", solver = "closed-form";
  std::string h_text, t_end_text, periods_text, e_text, c_text, tau_end_text, h0_text, tol_text,
      alpha_text, digits_text, every_text, q0_text, p0_text;
  // Parsed and checked:
  double h = 0.01;
  std::optional<double> t_end, periods, e, c, tau_end, h0, tol, alpha;
  std::optional<unsigned> digits;
  double max_seconds = 0;  ///< 0: no limit
  std::string max_seconds_text;
  std::vector<double> q0, p0;
  long long every = 1;
  std::string plan_arg = "--h";  ///< named when the step plan is impossible
};

void require(bool ok, const std::string& arg, const std::string& msg) {
  if (!ok) throw ArgumentError(arg, msg);
}

// At most this many steps in one run (a plan of more is a typing error, or a study for the
// benchmarks, not for `vibook run`).
constexpr double kMaxSteps = 1e12;

// Number of steps and the last step's size for a run to t_end with step h: round(T/h) steps
// when T/h is within rounding of an integer (h = T/n ends exactly at T); otherwise ceil(T/h)
// steps, the last one shortened so that the run ends at T. `arg` is named when the plan has no
// step or more than kMaxSteps.
std::pair<long long, double> step_plan(double T, double h, const std::string& arg) {
  require(h <= T * (1 + 64 * kEps), arg,
          fmt::format("the step {:.6g} is longer than the whole run (to {:.6g}): no step to take",
                      h, T));
  const double ratio = T / h;
  require(ratio <= kMaxSteps, arg,
          fmt::format("step {:.3g} up to {:.3g} makes {:.3g} steps, more than the 1e12 a run may "
                      "take",
                      h, T, ratio));
  const double n = std::nearbyint(ratio);
  if (std::abs(ratio - n) <= 64 * kEps * std::max(1.0, ratio)) {
    return {static_cast<long long>(n), h};
  }
  const double full = std::floor(ratio);
  return {static_cast<long long>(full) + 1, T - full * h};
}

std::string state_text(const double* q, const double* p, int n) {
  std::string s = "q = (";
  for (int i = 0; i < n; ++i) s += fmt::format("{}{:.17g}", i ? ", " : "", q[i]);
  s += "), p = (";
  for (int i = 0; i < n; ++i) s += fmt::format("{}{:.17g}", i ? ", " : "", p[i]);
  return s + ")";
}

// A computed output value that is not finite ends the run as a numerical failure.
template <class Row>
void require_finite_row(const Row& row, const std::vector<std::string>& cols) {
  for (std::size_t i = 0; i < cols.size(); ++i)
    if (!std::isfinite(row[i]))
      throw NumericalError(fmt::format("the output column {} is not finite ({})", cols[i], row[i]));
}

// SIGINT, SIGTERM and SIGHUP during an integration are deferred to the step loop
// (signals.hpp): it sees them at its next step (Progress::update) and stops like a failed
// step, keeping the rows written so far in FILE.partial. Every other phase (and every other
// command) ends at once, with its temporaries removed.

// A failure of the step loop, rethrown with its place and what was kept: an interruption stays
// an interruption (exit 128 + signal), anything else is a numerical failure (exit 3).
[[noreturn]] void rethrow_with(const NumericalError& e, const std::string& message) {
  if (const auto* i = dynamic_cast<const Interrupted*>(&e)) throw Interrupted(i->signal(), message);
  throw NumericalError(message);
}

class Progress {
 public:
  Progress(long long total, double max_seconds)
      : total_(total), max_seconds_(max_seconds), tty_(::isatty(STDERR_FILENO) != 0) {}
  void update(long long k) {
    if (const int s = pending_signal(); s != 0)
      throw Interrupted(s, fmt::format("interrupted by {}", signal_name(s)));
    if ((k & 0x3ff) != 0 || (!tty_ && max_seconds_ == 0)) return;
    const auto now = std::chrono::steady_clock::now();
    // --max-seconds: the run stops like a failed step (status 3, rows kept in FILE.partial).
    if (max_seconds_ > 0 && std::chrono::duration<double>(now - start_).count() >= max_seconds_)
      throw NumericalError(fmt::format("stopped by --max-seconds {:g}", max_seconds_));
    if (!tty_ || (k & 0x3fff) != 0) return;
    if (now - start_ < std::chrono::seconds(2) || now - last_ < std::chrono::milliseconds(500))
      return;
    last_ = now;
    std::fprintf(stderr, "\rvibook run: step %lld of %lld (%.0f%%)", k, total_,
                 100.0 * double(k) / double(total_));
    shown_ = true;
  }
  ~Progress() {
    if (shown_) std::fprintf(stderr, "\n");
  }

 private:
  long long total_;
  double max_seconds_;
  bool tty_, shown_ = false;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), last_ = start_;
};

template <int N>
Vec<double, N> vector_arg(const std::vector<double>& v, const char* name) {
  require(v.size() == N, name,
          fmt::format("expects {} comma-separated number(s) for this problem", N));
  Vec<double, N> out;
  for (int i = 0; i < N; ++i) {
    require(std::isfinite(v[i]), name, "values must be finite");
    out(i) = v[i];
  }
  return out;
}

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

// Adaptive methods (Sharma et al. 2022): EpAVI and AVI1/AVI2. The run stops at the first
// step that reaches T (the steps are chosen by the method, not by the user).
int integrate_adaptive_kepler(const RunOptions& o) {
  constexpr int N = 2;
  const Kepler P;
  const double h0 = o.h0.value_or(o.h);
  require(std::isfinite(h0) && h0 > 0, "--h0", "must be a positive finite number");
  const bool from_state = !o.q0.empty() || !o.p0.empty();
  require(!(o.e && from_state), "--e", "give either --e or --q0/--p0, not both");
  State<N> s0 = o.e ? kepler_perihelion_state(*o.e) : kepler_perihelion_state(0.5);
  if (from_state) {
    s0.q = vector_arg<N>(o.q0, "--q0");
    s0.p = vector_arg<N>(o.p0, "--p0");
  }
  // The exact orbit gives the start-up step (and the period): it must be a bound orbit.
  const KeplerOrbit orbit = [&] {
    try {
      return from_state ? KeplerOrbit::from_state(s0.q, s0.p)
                        : KeplerOrbit::perihelion(o.e.value_or(0.5));
    } catch (const ArgumentError& e) {
      throw ArgumentError("--q0/--p0", e.what());
    }
  }();
  // The start-up step comes from the exact orbit; a first step that carries the body past the
  // pericentre distance in one go cannot resolve the orbit (with e = 0.999999 and h0 = 0.01
  // the run "succeeded" while H jumped from -0.5 to +14.5). Time scale of the pericentre
  // passage: r_p / v_p with r_p = a(1 - e), v_p = sqrt((1 + e) / (a(1 - e))) (mu = 1).
  {
    const double a = orbit.semi_major_axis(), ecc = orbit.eccentricity();
    const double rp = a * (1 - ecc), vp = std::sqrt((1 + ecc) / rp);
    require(h0 * vp <= rp, o.h0 ? "--h0" : "--h",
            fmt::format("the first step {:.3g} moves the body {:.3g} at the pericentre, farther "
                        "than its distance {:.3g} from the centre (e = {:.9g}): take a first "
                        "step below {:.3g}",
                        h0, h0 * vp, rp, ecc, rp / vp));
  }
  const double Tend = o.periods ? *o.periods * (from_state ? orbit.period() : 2 * std::numbers::pi)
                                : o.t_end.value_or(10.0);
  require(std::isfinite(Tend) && Tend > 0, o.periods ? "--periods" : "--t-end",
          "must be a positive number");
  // The steps are the method's; at least about Tend/h0 of them are planned for.
  step_plan(Tend, h0, o.plan_arg);

  const bool epavi = o.method == "epavi";
  if (!epavi) {
    require(o.precision == "double", "--precision",
            "only epavi is templated on the scalar; avi1 and avi2 run in double");
    require(!o.tol, "--tol", "applies to epavi only (avi1/avi2 use Newton at 4 ulp)");
    require(o.energy_target == "previous", "--energy-target", "applies to epavi only");
  }
  require(!o.digits || o.precision == "mpfr", "--digits", "applies to --precision mpfr only");
  if (o.tol) require(std::isfinite(*o.tol) && *o.tol > 0, "--tol", "must be a positive number");
  OutputFile csv(o.csv, "--csv");
  std::vector<std::string> cols = {"step", "t", "dt", "q1",  "q2",   "p1",
                                   "p2",   "H", "L",  "ecc", "omega"};
  if (epavi) cols.insert(cols.end(), {"E_d", "E_d_drift"});
  cols.insert(cols.end(), {"residual", "iterations"});
  TrajectoryRecorder rec(csv.stream(), cols, o.every);
  std::vector<double> row(cols.size());
  AngleUnwrapper omega;
  auto offer = [&](long long k, double t, double dt, const Vec<double, N>& q,
                   const Vec<double, N>& p, double Ed, double Ed_drift, double residual,
                   int iterations) {
    const KeplerInvariants inv = kepler_invariants(q, p);
    const double omega_unwrapped = omega(inv.omega);
    std::size_t c = 0;
    for (double v :
         {double(k), t, dt, q(0), q(1), p(0), p(1), inv.H, inv.L, inv.ecc, omega_unwrapped})
      row[c++] = v;
    if (epavi) {
      row[c++] = Ed;
      row[c++] = Ed_drift;
    }
    row[c++] = residual;
    row[c++] = double(iterations);
    require_finite_row(row, cols);
    rec.offer(k, row);
  };
  Progress progress(static_cast<long long>(Tend / h0), o.max_seconds);
  long long k = 0;
  // The state the current step starts from, in double, for the message if it fails.
  double t_before = 0;
  Vec<double, N> q_before = s0.q, p_before = s0.p;
  auto check_finite = [](double t, const Vec<double, N>& q, const Vec<double, N>& p) {
    if (!std::isfinite(t) || !q.allFinite() || !p.allFinite())
      throw NumericalError("the state became non-finite");
  };
  try {
    if (epavi) {
      // Start-up as in the paper: the first step of length h0 from the exact solution. The
      // state is carried in the chosen precision T; E_d_drift = E_k − E_1 is formed in T.
      const Precision prec = parse_precision(o.precision);
      with_precision(prec, o.digits.value_or(18), [&](auto zero) {
        using T = decltype(zero);
        typename EpAVI<Kepler, T>::Options opt;
        opt.tol = o.tol.value_or(0.0);
        opt.energy_target =
            o.energy_target == "initial" ? EnergyTarget::initial : EnergyTarget::previous;
        auto lift = [](const Vec<double, 2>& v) { return Vec<T, 2>(T(v(0)), T(v(1))); };
        auto down = [](const Vec<T, 2>& v) {
          return Vec<double, 2>(to_double(v(0)), to_double(v(1)));
        };
        // --solver: the closed form for L = ½|v|² − V (epavi/mechanical.hpp) or the generic
        // nested-AutoDiff path (mechanics/extended.hpp); the same equations (15)–(18).
        auto go = [&](auto& m) {
          auto s = m.start(T(0), lift(s0.q), T(h0), lift(orbit.at(h0).q));
          const T E1 = s.E;
          // The momentum at t0 from the discrete Legendre transform of the first step.
          offer(0, 0.0, 0.0, s0.q, s0.p, to_double(s.E), 0.0, 0.0, 0);
          k = 1;
          offer(1, to_double(s.t), h0, down(s.q), down(s.p), to_double(s.E), 0.0, 0.0, 0);
          while (s.t < T(Tend)) {
            const T t0 = s.t;
            t_before = to_double(s.t), q_before = down(s.q), p_before = down(s.p);
            const ExtendedStepReport r = m.step(s);
            ++k;
            check_finite(to_double(s.t), down(s.q), down(s.p));
            if (rec.due(k) || s.t >= T(Tend))
              offer(k, to_double(s.t), to_double(T(s.t - t0)), down(s.q), down(s.p), to_double(s.E),
                    to_double(T(s.E - E1)), r.energy_residual, r.root_iterations);
            progress.update(k);
          }
        };
        if (o.solver == "generic") {
          EpAVI<Kepler, T> m{Kepler{}, opt};
          go(m);
        } else {
          MechanicalEpAVI<Kepler, T> m{Kepler{}, opt};
          go(m);
        }
        return 0;
      });
    } else {
      TimedState<N> s{0.0, s0.q, s0.p};
      const double H0 = energy(P, s0.q, s0.p);
      auto run = [&](auto monitor) {
        AdaptiveMidpoint<Kepler, decltype(monitor)> m(Kepler{}, monitor);
        const double da = m.step_for_first_step(s, h0);
        offer(0, 0.0, 0.0, s.q, s.p, 0.0, 0.0, 0.0, 0);
        while (s.t < Tend) {
          const double t0 = s.t;
          t_before = s.t, q_before = s.q, p_before = s.p;
          const SolveReport r = m.step(s, da);
          ++k;
          check_finite(s.t, s.q, s.p);
          if (rec.due(k) || s.t >= Tend)
            offer(k, s.t, s.t - t0, s.q, s.p, 0.0, 0.0, r.residual, r.iterations);
          progress.update(k);
        }
      };
      if (o.method == "avi1")
        run(MonitorArclength{H0});
      else
        run(MonitorQuadratic{});
    }
  } catch (const NumericalError& e) {
    rec.finish();
    // EpAVI's "no admissible time step" names its time and state itself.
    const std::string what = e.what();
    const std::string where =
        what.starts_with("extended step at t =") || what.starts_with("EpAVI step at t =")
            ? fmt::format("(step {})", k + 1)
            : fmt::format("at step {} (t = {:.17g}), from {}", k + 1, t_before,
                          state_text(q_before.data(), p_before.data(), N));
    rethrow_with(e, fmt::format("{} {}; {}", what, where, csv.keep_partial()));
  }
  rec.finish();
  csv.commit();
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
