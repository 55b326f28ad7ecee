// `vibook run` (run.hpp) with the adaptive methods of Sharma et al. 2022 on Kepler: EpAVI (in
// any precision) and AVI1/AVI2. Its own unit: EpAVI is instantiated for five scalar types and
// two solvers.
#include <iostream>

#include "vibook/avi/avi.hpp"
#include "vibook/core/angle.hpp"
#include "vibook/core/output_file.hpp"
#include "vibook/core/recorder.hpp"
#include "vibook/epavi/epavi.hpp"
#include "vibook/epavi/mechanical.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/run/run_impl.hpp"

namespace vibook::run::detail {

// Adaptive methods (Sharma et al. 2022): EpAVI and AVI1/AVI2. The run stops at the first
// step that reaches T (the steps are chosen by the method, not by the user).
void integrate_adaptive_kepler(const Settings& o, const Hooks& hooks) {
  constexpr int N = 2;
  const Kepler P;
  const double h0 = o.h0.value_or(o.h);
  require_argument(std::isfinite(h0) && h0 > 0, "--h0", "must be a positive finite number");
  const bool from_state = !o.q0.empty() || !o.p0.empty();
  require_argument(!(o.e && from_state), "--e", "give either --e or --q0/--p0, not both");
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
    require_argument(
        h0 * vp <= rp, o.h0 ? "--h0" : "--h",
        fmt::format("the first step {:.3g} moves the body {:.3g} at the pericentre, farther "
                    "than its distance {:.3g} from the centre (e = {:.9g}): take a first "
                    "step below {:.3g}",
                    h0, h0 * vp, rp, ecc, rp / vp));
  }
  const double Tend = o.periods ? *o.periods * (from_state ? orbit.period() : 2 * std::numbers::pi)
                                : o.t_end.value_or(10.0);
  require_argument(std::isfinite(Tend) && Tend > 0, o.periods ? "--periods" : "--t-end",
                   "must be a positive number");
  // The steps are the method's; at least about Tend/h0 of them are planned for.
  step_plan(Tend, h0, o.plan_arg);

  const bool epavi = o.method == "epavi";
  if (!epavi) {
    require_argument(o.precision == "double", "--precision",
                     "only epavi is templated on the scalar; avi1 and avi2 run in double");
    require_argument(!o.tol, "--tol", "applies to epavi only (avi1/avi2 use Newton at 4 ulp)");
    require_argument(o.energy_target == "previous", "--energy-target", "applies to epavi only");
  }
  require_argument(!o.digits || o.precision == "mpfr", "--digits",
                   "applies to --precision mpfr only");
  if (o.tol)
    require_argument(std::isfinite(*o.tol) && *o.tol > 0, "--tol", "must be a positive number");
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
  Progress progress(static_cast<long long>(Tend / h0), o.max_seconds, hooks);
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
}

}  // namespace vibook::run::detail
