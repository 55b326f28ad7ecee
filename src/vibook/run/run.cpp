// `vibook run` as a library call (run.hpp): one problem, one method, the trajectory streamed as
// CSV. The adaptive methods are in adaptive.cpp (their own unit: EpAVI in five scalar types).
#include "vibook/run/run.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "vibook/core/angle.hpp"
#include "vibook/core/errors.hpp"
#include "vibook/core/output_file.hpp"
#include "vibook/core/recorder.hpp"
#include "vibook/integrators/kernels.hpp"
#include "vibook/integrators/splitting.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/mechanics/del_solver.hpp"
#include "vibook/mechanics/discrete_lagrangian.hpp"
#include "vibook/problems/problems.hpp"
#include "vibook/relativistic/exact.hpp"
#include "vibook/relativistic/relativistic.hpp"
#include "vibook/run/run_impl.hpp"

namespace vibook::run {
using namespace detail;
namespace {

template <class Problem, class Stepper>
void integrate(const Problem& P, Stepper stepper, bool implicit, const Settings& o,
               const Hooks& hooks) {
  constexpr int N = Problem::N;
  constexpr bool kepler = std::is_same_v<Problem, Kepler>;

  // Initial state.
  State<N> s;
  if constexpr (kepler) {
    if (o.e) {
      require_argument(o.q0.empty() && o.p0.empty(), "--e",
                       "give either --e or --q0/--p0, not both");
      s = kepler_perihelion_state(*o.e);
    } else if (!o.q0.empty() || !o.p0.empty()) {
      s.q = vector_arg<N>(o.q0, "--q0");
      s.p = vector_arg<N>(o.p0, "--p0");
    } else {
      s = kepler_perihelion_state(0.5);
    }
  } else {
    require_argument(!o.e, "--e", "only applies to --problem kepler");
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
    require_argument(std::isfinite(*o.periods) && *o.periods > 0, "--periods",
                     "must be a positive number");
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
    require_argument(std::isfinite(T) && T > 0, "--t-end", "must be a positive number");
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

  Progress progress(steps, o.max_seconds, hooks);
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
}

// Relativistic Kepler in proper time (Shen & Sun 2025, (3.16)–(3.22)).
template <class Method>
void integrate_relativistic(const relativistic::Problem& P, Method method, const Settings& o,
                            const Hooks& hooks) {
  using namespace relativistic;
  const Vec<double, 2> x0 = o.q0.empty() ? Vec<double, 2>(0.4, 0.0) : vector_arg<2>(o.q0, "--q0");
  const Vec<double, 2> u0 = o.p0.empty() ? Vec<double, 2>(0.0, 2.0) : vector_arg<2>(o.p0, "--p0");
  try {
    ExactOrbit check(P, x0, u0);  // a bound precessing orbit, or a clear error
  } catch (const ArgumentError& e) {
    throw ArgumentError("--q0/--p0/--c", e.what());
  }
  const double T = o.tau_end.value_or(40.0);
  require_argument(std::isfinite(T) && T > 0, "--tau-end", "must be a positive number");
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
  Progress progress(steps, o.max_seconds, hooks);
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
}

template <class Problem>
void dispatch_method(const Problem& P, const Settings& o, const Hooks& hooks) {
  constexpr int N = Problem::N;
  const auto L = mechanical_lagrangian(P);
  if (o.method == "epavi" || o.method == "avi1" || o.method == "avi2") {
    if constexpr (std::is_same_v<Problem, Kepler>) {
      return integrate_adaptive_kepler(o, hooks);
    } else {
      throw ArgumentError("--method", "epavi, avi1 and avi2 are implemented for --problem kepler");
    }
  }
  if (o.method == "se") return integrate(P, SymplecticEuler<Problem>(P), false, o, hooks);
  if (o.method == "se-adjoint")
    return integrate(P, SymplecticEulerAdjoint<Problem>(P), false, o, hooks);
  if (o.method == "sv") return integrate(P, StormerVerlet<Problem>(P), false, o, hooks);
  if (o.method == "midpoint") return integrate(P, ImplicitMidpoint<Problem>(P), true, o, hooks);
  if (o.method == "vi1" || o.method == "vi1-adjoint" || o.method == "vi2" ||
      o.method == "vi2-adjoint") {
    if constexpr (std::is_same_v<Problem, Kepler>) {
      const auto split = WeightedSplit<Kepler>::alpha(o.alpha.value_or(0.5));
      return integrate(
          P, SplittingKernel<WeightedSplit<Kepler>>(split, parse_splitting_method(o.method)), false,
          o, hooks);
    } else {
      throw ArgumentError("--method", "the splitting methods are implemented for --problem kepler");
    }
  }
  // del-generic: the generic discrete Euler–Lagrange solver on the chosen discrete Lagrangian.
  const auto& d = o.discrete_lagrangian;
  if (d == "midpoint") return integrate(P, make_del_integrator<N>(midpoint_dl(L)), true, o, hooks);
  if (d == "sv") return integrate(P, make_del_integrator<N>(stormer_verlet_dl(L)), true, o, hooks);
  if (d == "se")
    return integrate(P, make_del_integrator<N>(symplectic_euler_dl(L)), true, o, hooks);
  return integrate(P, make_del_integrator<N>(symplectic_euler_adjoint_dl(L)), true, o, hooks);
}

}  // namespace

void run_trajectory(const Settings& o, const Hooks& hooks) {
  if (o.problem == "relativistic-kepler") {
    const relativistic::Problem P(o.c.value_or(0));  // c <= 0: ArgumentError naming --c
    if (o.method == "k-symplectic")
      return integrate_relativistic(P, relativistic::KSymplectic{P}, o, hooks);
    if (o.method == "vi") return integrate_relativistic(P, relativistic::Vi322{P}, o, hooks);
    return integrate_relativistic(P, relativistic::Vi2{P}, o, hooks);
  }
  if (o.problem == "harmonic") return dispatch_method(HarmonicOscillator{}, o, hooks);
  if (o.problem == "pendulum") return dispatch_method(Pendulum{}, o, hooks);
  return dispatch_method(Kepler{}, o, hooks);
}

}  // namespace vibook::run
