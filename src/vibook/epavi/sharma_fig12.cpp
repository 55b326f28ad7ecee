// Sharma et al. 2022, §3.2, Figures 1 (e = 0.1) and 2 (e = 0.7): EpAVI against AVI1 and AVI2
// on Kepler from h0 = 0.001: time steps h_k/h0, energy errors, trajectory errors against the
// exact solution (Kepler's equation, not a numerical reference as in the paper).
//
// Reading: the paper does not state the time span of Figs. 1–2; we integrate 10 periods
// (t ∈ [0, 20π]). Beside EpAVI's discrete energy error |E_k − E_1| (the paper's quantity) we
// record its continuous energy error |H(q_k, p_k) − H_0|, the like-for-like comparison with AVI.
#include <cmath>
#include <fstream>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "vibook/avi/avi.hpp"
#include "vibook/core/order.hpp"
#include "vibook/core/recorder.hpp"
#include "vibook/epavi/checks.hpp"
#include "vibook/epavi/epavi.hpp"
#include "vibook/epavi/mechanical.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/modified/printed_checks.hpp"

namespace vibook::checks {

namespace {

struct Series {
  double mean_step = 0, max_step = 0;  // in units of h0
  double max_energy_err = 0;           // |H − H0| (AVI) or |E_k − E_1| (EpAVI)
  double max_H_err = 0;                // |H(q_k, p_k) − H0|, all methods
  double final_traj_err = 0;           // max(|q1 − q1ex|, |q2 − q2ex|) at the end
  double growth_exponent = 0;          // fitted p in traj_err ~ t^p over the second half
  long steps = 0;
};

constexpr double kH0 = 0.001;
constexpr int kPeriods = 10;

// Runs one method, streaming a decimated CSV; `next` advances the state, returns false never.
template <class Step, class Get>
Series run_method(double e, Step&& step, Get&& get, std::ostream* csv) {
  const KeplerOrbit orbit = KeplerOrbit::perihelion(e);
  const State<2> s0 = kepler_perihelion_state(e);
  const double H0 = energy(Kepler{}, s0.q, s0.p);
  const double T = kPeriods * 2 * std::numbers::pi;
  std::optional<TrajectoryRecorder> rec;
  if (csv)
    rec.emplace(*csv,
                std::vector<std::string>{"step", "t", "h_over_h0", "energy_err", "H_err", "q1_err",
                                         "q2_err"},
                25);
  Series out;
  std::vector<double> ts, errs;
  double t = 0, sum = 0;
  long k = 0;
  while (t < T) {
    const double t0 = t;
    step();
    double energy_err = 0;
    Vec<double, 2> q, p;
    get(t, q, p, energy_err);
    ++k;
    const double h = (t - t0) / kH0;
    sum += h;
    out.max_step = std::max(out.max_step, h);
    const double Herr = std::abs(energy(Kepler{}, q, p) - H0);
    out.max_energy_err = std::max(out.max_energy_err, energy_err < 0 ? Herr : energy_err);
    out.max_H_err = std::max(out.max_H_err, Herr);
    const Vec<double, 2> ex = orbit.at(t).q;
    const double e1 = std::abs(q(0) - ex(0)), e2 = std::abs(q(1) - ex(1));
    out.final_traj_err = std::max(e1, e2);
    if (t > 0.5 * T && k % 50 == 0) {
      ts.push_back(t);
      errs.push_back(std::max(e1, e2));
    }
    if (rec)
      rec->offer(k, std::array<double, 7>{double(k), t, h, energy_err < 0 ? Herr : energy_err, Herr,
                                          e1, e2});
  }
  if (rec) rec->finish();
  out.steps = k;
  out.mean_step = sum / double(k);
  // Error growth exponent: slope of log(error envelope) against log t over the second half.
  std::vector<double> env_t, env_e;
  double env = 0;
  for (std::size_t i = 0; i < ts.size(); ++i) {
    env = std::max(env, errs[i]);
    if (i % 20 == 0) {
      env_t.push_back(ts[i]);
      env_e.push_back(env);
    }
  }
  try {
    out.growth_exponent = fit_order(env_t, env_e, 0.0, 3).slope;
  } catch (const std::invalid_argument&) {
    out.growth_exponent = NAN;
  }
  return out;
}

struct Fig12 {
  Series epavi, avi1, avi2;
  /// max |E_k − E_1| of the generic path (nested AutoDiff, secant; mechanics/extended.hpp) over
  /// the same span: the comparison that shows how much of an energy drift was the solver's.
  double generic_max_energy_err = 0;
};
claims::ClaimResult mean_steps(double e, const Fig12& r, double printed_epavi, double printed_avi2);

Fig12 compute(double e, const Context& ctx) {
  const State<2> s0 = kepler_perihelion_state(e);
  const double H0 = energy(Kepler{}, s0.q, s0.p);
  const KeplerOrbit orbit = KeplerOrbit::perihelion(e);
  std::optional<std::ofstream> f_ep, f_a1, f_a2;
  if (ctx.out_dir) {
    f_ep.emplace(*ctx.out_dir / "epavi.csv");
    f_a1.emplace(*ctx.out_dir / "avi1.csv");
    f_a2.emplace(*ctx.out_dir / "avi2.csv");
  }
  Fig12 r;
  {
    MechanicalEpAVI<Kepler> m{Kepler{}};  // closed form (epavi/mechanical.hpp)
    ExtendedState<2> s = m.start(0.0, s0.q, kH0, orbit.at(kH0).q);
    const double E1 = s.E;
    bool first = true;
    r.epavi = run_method(
        e,
        [&] {
          if (first)
            first = false;
          else
            m.step(s);
        },
        [&](double& t, Vec<double, 2>& q, Vec<double, 2>& p, double& err) {
          t = s.t, q = s.q, p = s.p, err = std::abs(s.E - E1);
        },
        f_ep ? &*f_ep : nullptr);
  }
  {
    EpAVI<Kepler> m{Kepler{}};
    ExtendedState<2> s = m.start(0.0, s0.q, kH0, orbit.at(kH0).q);
    const double E1 = s.E, T = kPeriods * 2 * std::numbers::pi;
    while (s.t < T) {
      m.step(s);
      r.generic_max_energy_err = std::max(r.generic_max_energy_err, std::abs(s.E - E1));
    }
  }
  auto avi = [&](auto monitor, std::ostream* csv) {
    AdaptiveMidpoint<Kepler, decltype(monitor)> m(Kepler{}, monitor);
    TimedState<2> s{0.0, s0.q, s0.p};
    const double da = m.step_for_first_step(s, kH0);
    return run_method(
        e, [&] { m.step(s, da); },
        [&](double& t, Vec<double, 2>& q, Vec<double, 2>& p, double& err) {
          t = s.t, q = s.q, p = s.p, err = -1.0;  // AVI: the energy error is |H − H0|
        },
        csv);
  };
  r.avi1 = avi(MonitorArclength{H0}, f_a1 ? &*f_a1 : nullptr);
  r.avi2 = avi(MonitorQuadratic{}, f_a2 ? &*f_a2 : nullptr);
  return r;
}

// Sharma Fig. 3 text: mean steps (printed to two decimals). Our means are over 10 periods of
// the same runs (periodic motion: the same as over one). Tolerance 0.01 h0, twice the printed
// rounding; chosen after the values were first seen (stated in the note).
void push_series(claims::ClaimResult& c, const char* name, const Series& s) {
  c.values.push_back({fmt::format("{}_mean_step_over_h0", name), s.mean_step});
  c.values.push_back({fmt::format("{}_max_step_over_h0", name), s.max_step});
  c.values.push_back({fmt::format("{}_max_energy_err", name), s.max_energy_err});
  c.values.push_back({fmt::format("{}_max_continuous_H_err", name), s.max_H_err});
  c.values.push_back({fmt::format("{}_final_trajectory_err", name), s.final_traj_err});
  c.values.push_back({fmt::format("{}_trajectory_err_growth_exponent", name), s.growth_exponent});
}

claims::ClaimResult mean_steps(double e, const Fig12& r, double printed_epavi,
                               double printed_avi2) {
  claims::ClaimResult c;
  c.id = "S-F3";
  c.source = e < 0.5 ? "sharma-fig1" : "sharma-fig2";
  c.values = {{fmt::format("e{}_epavi_mean_step_over_h0", e), r.epavi.mean_step},
              {fmt::format("e{}_avi2_mean_step_over_h0", e), r.avi2.mean_step},
              {fmt::format("e{}_epavi_printed", e), printed_epavi},
              {fmt::format("e{}_avi2_printed", e), printed_avi2}};
  const bool ok = std::abs(r.epavi.mean_step - printed_epavi) <= 0.01 &&
                  std::abs(r.avi2.mean_step - printed_avi2) <= 0.01 && r.epavi.max_step > 0;
  c.status = ok ? claims::Status::reproduced_with_caveat : claims::Status::not_reproduced;
  c.note = fmt::format(
      "e = {}: mean steps EpAVI {:.3f} h0 (printed {}), AVI2 {:.3f} h0 (printed {}); every step "
      "positive and bounded (0 < t'(a) ≤ const). Caveats: averaged over 10 periods of the Fig. "
      "{} run; tolerance 0.01 h0 (twice the printed rounding) chosen after first seeing the "
      "values. "
      "The t(a) curves over one cycle are sharma-fig3.",
      e, r.epavi.mean_step, printed_epavi, r.avi2.mean_step, printed_avi2, e < 0.5 ? 1 : 2);
  return c;
}

// A claim carrying the measured series of the three methods.
claims::ClaimResult series_claim(const char* id, const char* source, const Fig12& r) {
  claims::ClaimResult c;
  c.id = id;
  c.source = source;
  push_series(c, "epavi", r.epavi);
  push_series(c, "avi1", r.avi1);
  push_series(c, "avi2", r.avi2);
  c.values.push_back({"epavi_generic_path_max_energy_err", r.generic_max_energy_err});
  return c;
}

// [sharma-trajectory-criterion]
// Trajectory criterion shared by both figures (fixed before measuring): final errors within a
// factor 3 of each other, EpAVI not worse than the better AVI by more than 10% ("marginally
// better"), growth exponent of the error envelope in [0.7, 1.3] ("slow linear growth").
bool trajectories_ok(const Fig12& r, std::string& why) {
  const double a = r.epavi.final_traj_err, b = r.avi1.final_traj_err, c = r.avi2.final_traj_err;
  const double hi = std::max({a, b, c}), lo = std::min({a, b, c});
  bool ok = true;
  if (hi > 3 * lo) ok = false, why += "trajectory errors differ by more than 3x; ";
  if (a > 1.1 * std::min(b, c)) ok = false, why += "EpAVI trajectory error not the smallest; ";
  for (const Series* s : {&r.epavi, &r.avi1, &r.avi2}) {
    if (!(s->growth_exponent >= 0.7 && s->growth_exponent <= 1.3)) {
      ok = false;
      why += fmt::format("growth exponent {:.2f} not linear; ", s->growth_exponent);
      break;
    }
  }
  return ok;
}
// [sharma-trajectory-criterion]

std::vector<claims::ClaimResult> run_fig1(const Context& ctx) {
  const Fig12 r = compute(0.1, ctx);
  claims::ClaimResult c = series_claim("S-F1", "sharma-fig1", r);
  std::string why;
  // [sharma-fig1-criterion]
  // (a) EpAVI and AVI1 nearly the same steps (mean within 10%), AVI2 marginally larger (mean
  //     ratio to EpAVI in (1, 1.25]); (b) AVI energy errors about 1e-7 (within [1e-8, 1e-6]),
  //     EpAVI about 1e-14 (≤ 1e-12); (c) trajectories, see trajectories_ok.
  const double r1 = r.avi1.mean_step / r.epavi.mean_step, r2 = r.avi2.mean_step / r.epavi.mean_step;
  bool ok = true;
  if (!(std::abs(r1 - 1) <= 0.1))
    ok = false, why += fmt::format("AVI1/EpAVI mean step {:.3f}; ", r1);
  if (!(r2 > 1 && r2 <= 1.25)) ok = false, why += fmt::format("AVI2/EpAVI mean step {:.3f}; ", r2);
  for (const Series* s : {&r.avi1, &r.avi2}) {
    if (!(s->max_energy_err >= 1e-8 && s->max_energy_err <= 1e-6)) {
      ok = false, why += fmt::format("AVI energy error {:.2g} not about 1e-7; ", s->max_energy_err);
    }
  }
  if (!(r.epavi.max_energy_err <= 1e-12))
    ok = false, why += "EpAVI discrete energy error above 1e-12; ";
  ok = trajectories_ok(r, why) && ok;
  c.status = ok ? claims::Status::reproduced_with_caveat : claims::Status::not_reproduced;
  // [sharma-fig1-criterion]
  if (!ok) {
    c.cause = "does-not-hold";
    c.headline = why.substr(0, why.size() - 2);
  }
  const claims::ClaimResult f3 = mean_steps(0.1, r, 1.17, 1.23);
  c.note = fmt::format(
      "e = 0.1, h0 = 0.001, 10 periods (the span is our reading), exact Kepler reference. "
      "Mean steps: EpAVI {:.3f} h0, AVI1 {:.3f} h0, AVI2 {:.3f} h0. Like for like, EpAVI's "
      "continuous energy error |H − H0| is {:.2g} (its discrete energy error {:.2g}; the "
      "generic nested-AutoDiff path on the same orbit: {:.2g}). {}",
      r.epavi.mean_step, r.avi1.mean_step, r.avi2.mean_step, r.epavi.max_H_err,
      r.epavi.max_energy_err, r.generic_max_energy_err,
      ok ? "All criteria met; caveat: the time span and the comparison quantity are our readings."
         : "Not met: " + why);
  // The monitor functions (26)–(27) as printed, against the ones AVI1 and AVI2 step with.
  std::vector<claims::FormulaComparison> cs;
  {
    const std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());  // GiNaC: one thread
    cs = printed_detail::sharma_discrete_prints("monitors", "sharma-fig1");
  }
  std::vector<claims::ClaimResult> out;
  printed::conclude(c, cs, out);
  out.insert(out.begin(), {c, f3});
  return out;
}

std::vector<claims::ClaimResult> run_fig2(const Context& ctx) {
  const Fig12 r = compute(0.7, ctx);
  claims::ClaimResult c = series_claim("S-F2", "sharma-fig2", r);
  std::string why;
  // [s-f2-criterion]
  // AVI steps significantly larger than EpAVI's (mean ratio ≥ 1.1); steps grow 12–15× h0 (max
  // step of each method in [12, 15]); AVI energy errors about 1e-4 ([1e-5, 1e-3]); EpAVI about
  // 1e-13 (≤ 1e-11); trajectories as in Fig. 1.
  bool ok = true;
  for (const auto& [name, s] : {std::pair{"AVI1", &r.avi1}, std::pair{"AVI2", &r.avi2}}) {
    if (!(s->mean_step >= 1.1 * r.epavi.mean_step))
      ok = false, why += fmt::format("{} mean step only {:.3f}× EpAVI's (≥ 1.1 claimed); ", name,
                                     s->mean_step / r.epavi.mean_step);
    if (!(s->max_energy_err >= 1e-5 && s->max_energy_err <= 1e-3)) {
      ok = false,
      why += fmt::format("{} energy error {:.2g} not about 1e-4; ", name, s->max_energy_err);
    }
  }
  for (const auto& [name, s] :
       {std::pair{"EpAVI", &r.epavi}, std::pair{"AVI1", &r.avi1}, std::pair{"AVI2", &r.avi2}}) {
    if (!(s->max_step >= 12 && s->max_step <= 15))
      ok = false,
      why += fmt::format("{} largest step {:.1f} h0 outside 12–15; ", name, s->max_step);
  }
  if (!(r.epavi.max_energy_err <= 1e-11))
    ok = false, why += "EpAVI discrete energy error above 1e-11; ";
  ok = trajectories_ok(r, why) && ok;
  c.status = ok ? claims::Status::reproduced_with_caveat : claims::Status::not_reproduced;
  // [s-f2-criterion]
  if (!ok) {
    c.cause = "does-not-hold";
    c.headline = why.substr(0, why.size() - 2);
  }
  const claims::ClaimResult f3 = mean_steps(0.7, r, 6.22, 7.93);
  c.note = fmt::format(
      "e = 0.7, h0 = 0.001, 10 periods (our reading of the span), exact Kepler reference. Mean "
      "steps: EpAVI {:.3f} h0, AVI1 {:.3f} h0, AVI2 {:.3f} h0; largest steps {:.1f}, {:.1f}, "
      "{:.1f} h0. "
      "Like for like, EpAVI's continuous energy error |H − H0| is {:.2g} (its discrete energy "
      "error {:.2g}; the generic nested-AutoDiff path on the same orbit: {:.2g}). {}",
      r.epavi.mean_step, r.avi1.mean_step, r.avi2.mean_step, r.epavi.max_step, r.avi1.max_step,
      r.avi2.max_step, r.epavi.max_H_err, r.epavi.max_energy_err, r.generic_max_energy_err,
      ok ? "All criteria met; caveat: the time span and the comparison quantity are our readings."
         : "Not met: " + why);
  if (r.avi2.max_step > 15) {
    c.note += fmt::format(
        " For AVI2 the growth beyond 15 h0 follows from its monitor: Δt = Δa·g2 and g2 = qᵀq, so "
        "the aphelion/perihelion step ratio is ((1+e)/(1−e))² = {:.2f}.",
        std::pow(1.7 / 0.3, 2));
  }
  return {c, f3};
}

}  // namespace

Check sharma_fig1() {
  return {"sharma-fig1",
          "EpAVI vs AVI1/AVI2 on Kepler e = 0.1 (Sharma Fig. 1)",
          true,
          {"S-F1", "S-F3"},
          run_fig1};
}
Check sharma_fig2() {
  return {"sharma-fig2",
          "EpAVI vs AVI1/AVI2 on Kepler e = 0.7 (Sharma Fig. 2)",
          true,
          {"S-F2", "S-F3"},
          run_fig2};
}

}  // namespace vibook::checks
