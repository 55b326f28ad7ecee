// Sharma et al. 2022: the studies beyond Figs. 1–2.
//   sharma-fig3      Fig. 3, t(a) over one period (S-F3)
//   sharma-fig4      Fig. 4, the h0 study at e = 0.7 (S-F4)
//   sharma-fig5      Fig. 5, 18-digit MPFR and the solver tolerance (S-F5)
//   check-s-eq29     §3.3 (28)–(30): the accumulated discrete-energy error against the bound,
//                    ≥ 1e6 steps, both energy-target policies (S-EQ29)
//   check-s-eq39     §3.2 (24)–(25), §4.2 (39)–(41) read from the paper, against the library's
//                    L_d (25) and its derivatives (S-EQ39)
//   check-s-l1       §4.1 (31)–(37): the fixed-Δa VI of the transformed Lagrangian (S-L1)
//   epavi-existence  where EpAVI can step at all, over e (beyond the paper; Shibberu)
#include <cmath>
#include <fstream>
#include <numbers>
#include <random>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "vibook/core/order.hpp"
#include "vibook/core/parallel.hpp"
#include "vibook/epavi/checks.hpp"
#include "vibook/epavi/sharma_runs.hpp"
#include "vibook/modified/printed_checks.hpp"

namespace vibook::checks {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

std::ostream* ptr(std::optional<std::ofstream>& f) { return f ? &*f : nullptr; }

void push_run(claims::ClaimResult& c, const std::string& name, const AdaptiveRun& r) {
  c.values.push_back({name + "_steps", double(r.steps)});
  c.values.push_back({name + "_mean_step_over_h0", r.mean_step});
  c.values.push_back({name + "_max_step_over_h0", r.max_step});
  c.values.push_back({name + "_max_dE_d", r.max_dEd});
  c.values.push_back({name + "_max_dH", r.max_dH});
}

// ---- Fig. 3: t(a) over one period -------------------------------------------------------
// The fictitious time is a = k·h0 for every method (Δa scaled so that t'(0) = 1), so the slope
// of t(a) is h_k/h0 and its mean over the period is the mean step of the text.
std::vector<claims::ClaimResult> run_fig3(const Context& ctx) {
  claims::ClaimResult c;
  c.id = "S-F3";
  c.source = "sharma-fig3";
  bool ok = true;
  std::string txt;
  for (double e : {0.1, 0.7}) {
    const std::string tag = e < 0.5 ? "e01" : "e07";
    auto f_ep = open_csv(ctx, tag + "_epavi.csv"), f_a1 = open_csv(ctx, tag + "_avi1.csv"),
         f_a2 = open_csv(ctx, tag + "_avi2.csv");
    const State<2> s0 = kepler_perihelion_state(e);
    const double H0 = energy(Kepler{}, s0.q, s0.p);
    const AdaptiveRun ep = run_epavi<double>(e, 0.001, kTwoPi, {}, ptr(f_ep));
    const AdaptiveRun a1 = run_avi(e, 0.001, kTwoPi, MonitorArclength{H0}, ptr(f_a1));
    const AdaptiveRun a2 = run_avi(e, 0.001, kTwoPi, MonitorQuadratic{}, ptr(f_a2));
    // Mean step over exactly one cycle: the run ends at the first t_k ≥ 2π, so the mean over
    // the cycle is 2π/(k·h0) with k the (fractional) number of steps to 2π.
    push_run(c, tag + "_epavi", ep);
    push_run(c, tag + "_avi1", a1);
    push_run(c, tag + "_avi2", a2);
    c.values.push_back({tag + "_epavi_min_step_over_h0", ep.min_step});
    c.values.push_back({tag + "_avi2_min_step_over_h0", a2.min_step});
    const double pe = e < 0.5 ? 1.17 : 6.22, pa = e < 0.5 ? 1.23 : 7.93;
    // [s-f3-criterion]
    // Criterion (fixed with S-F3 of Figs. 1–2): the printed means within 0.01 h0, and
    // 0 < t'(a) bounded (every step positive, the largest finite).
    const bool here = std::abs(ep.mean_step - pe) <= 0.01 && std::abs(a2.mean_step - pa) <= 0.01 &&
                      ep.min_step > 0 && a2.min_step > 0 && std::isfinite(ep.max_step) &&
                      !ep.failure && !a2.failure;
    // [s-f3-criterion]
    ok = ok && here;
    txt += fmt::format(
        "e = {}: one cycle, mean steps EpAVI {:.3f} h0 (printed {}), AVI1 {:.3f}, AVI2 {:.3f} h0 "
        "(printed {}); t'(a) = h_k/h0 in [{:.3f}, {:.3f}] (EpAVI), [{:.3f}, {:.3f}] (AVI2). ",
        e, ep.mean_step, pe, a1.mean_step, a2.mean_step, pa, ep.min_step, ep.max_step, a2.min_step,
        a2.max_step);
  }
  c.status = ok ? claims::Status::reproduced : claims::Status::not_reproduced;
  c.note = txt + (ok ? "Printed means reproduced within 0.01 h0 over one cycle; t'(a) > 0 and "
                       "bounded."
                     : "Not met (criterion: printed means within 0.01 h0, 0 < t'(a) < ∞).");
  return {c};
}

// ---- Fig. 4: the h0 study at e = 0.7 ----------------------------------------------------
std::vector<claims::ClaimResult> run_fig4(const Context& ctx) {
  const double e = 0.7, T = 10 * kTwoPi;
  claims::ClaimResult c;
  c.id = "S-F4";
  c.source = "sharma-fig4";
  AdaptiveRun ep[2], a2[2];
  const double h0s[2] = {0.001, 0.01};
  for (int i = 0; i < 2; ++i) {
    const std::string tag = i == 0 ? "h0_0.001" : "h0_0.01";
    auto f_ep = open_csv(ctx, tag + "_epavi.csv"), f_a2 = open_csv(ctx, tag + "_avi2.csv");
    ep[i] = run_epavi<double>(e, h0s[i], T, {}, ptr(f_ep), i == 0 ? 10 : 1);
    a2[i] = run_avi(e, h0s[i], T, MonitorQuadratic{}, ptr(f_a2), i == 0 ? 10 : 1);
    push_run(c, tag + "_epavi", ep[i]);
    push_run(c, tag + "_avi2", a2[i]);
  }
  // [s-f4-criterion]
  // Criterion, fixed before measuring: AVI2's energy error grows with h0 (ratio > 10, about
  // h0² = 100 for a second-order method); EpAVI's changes "little" (ratio within [0.1, 10]);
  // h_k/h0 nearly independent of h0 (mean and max step within 5%). The text says EpAVI's
  // error is smaller at the smaller h0 and also calls it an "unexpected decrease for larger
  // time-steps": we report which direction holds.
  const double ra = a2[1].max_dH / a2[0].max_dH, re = ep[1].max_dEd / ep[0].max_dEd;
  const double rm = ep[1].mean_step / ep[0].mean_step, rx = ep[1].max_step / ep[0].max_step;
  const double am = a2[1].mean_step / a2[0].mean_step;
  c.values.push_back({"avi2_energy_err_ratio_h0_0.01_over_0.001", ra});
  c.values.push_back({"epavi_energy_err_ratio_h0_0.01_over_0.001", re});
  c.values.push_back({"epavi_mean_step_ratio", rm});
  c.values.push_back({"epavi_max_step_ratio", rx});
  c.values.push_back({"avi2_mean_step_ratio", am});
  const bool ok = ra > 10 && re >= 0.1 && re <= 10 && std::abs(rm - 1) <= 0.05 &&
                  std::abs(rx - 1) <= 0.05 && std::abs(am - 1) <= 0.05;
  // [s-f4-criterion]
  c.status = ok ? claims::Status::reproduced_with_caveat : claims::Status::not_reproduced;
  c.note = fmt::format(
      "e = 0.7, 10 periods. AVI2 energy error {:.2g} (h0 = 0.001) → {:.2g} (h0 = 0.01), ratio "
      "{:.3g}. EpAVI discrete energy error {:.2g} → {:.2g}, ratio {:.3g}: {} at the larger h0 in "
      "this run (both are random walks of round-off residuals; ten times fewer steps make the "
      "walk √10 smaller in expectation, but one pair of walks can fall either way). h_k/h0: "
      "EpAVI mean {:.3f} → {:.3f}, max {:.2f} → {:.2f}; AVI2 mean {:.3f} → {:.3f}. {}",
      a2[0].max_dH, a2[1].max_dH, ra, ep[0].max_dEd, ep[1].max_dEd, re,
      re < 1 ? "smaller" : "larger", ep[0].mean_step, ep[1].mean_step, ep[0].max_step,
      ep[1].max_step, a2[0].mean_step, a2[1].mean_step,
      ok ? "Criteria met (AVI2 ratio > 10, EpAVI ratio in [0.1, 10], step profiles within 5%); "
           "caveat: the span (10 periods) is our reading."
         : "Not met (AVI2 ratio > 10, EpAVI ratio in [0.1, 10], step profiles within 5%).");
  return {c};
}

// ---- Fig. 5: 18-digit MPFR and the solver tolerance -------------------------------------
std::vector<claims::ClaimResult> run_fig5(const Context& ctx) {
  const double e = 0.7, h0 = 0.001, T = kTwoPi;  // one period: 18-digit MPFR costs ~5 ms/step
  const double tols[] = {1e-10, 1e-12, 1e-14, 1e-16, 1e-17};
  constexpr int n = 5;
  AdaptiveRun r[n];
  std::optional<std::ofstream> files[n];
  for (int i = 0; i < n; ++i) files[i] = open_csv(ctx, fmt::format("tol_{:.0e}.csv", tols[i]));
  MpfrDigits digits(18);  // process-wide in Boost 1.74: set once, before the threads start
  parallel_for(n, 0, [&](std::size_t i) {
    EpAVI<Kepler, mpfr_real>::Options opt;
    opt.tol = tols[i];
    r[i] = run_epavi<mpfr_real>(e, h0, T, opt, ptr(files[i]), 1);
  });
  claims::ClaimResult c;
  c.id = "S-F5";
  c.source = "sharma-fig5";
  bool monotone = true;
  for (int i = 0; i < n; ++i) {
    c.values.push_back({fmt::format("tol_{:.0e}_max_dE_d", tols[i]), r[i].max_dEd});
    c.values.push_back({fmt::format("tol_{:.0e}_mean_step_over_h0", tols[i]), r[i].mean_step});
    c.values.push_back({fmt::format("tol_{:.0e}_max_residual", tols[i]), r[i].max_residual});
    if (i > 0 && !(r[i].max_dEd < r[i - 1].max_dEd)) monotone = false;
  }
  // Unit round-off of 18 significant digits as MPFR sets it (bits = ⌈18·log2(10)⌉ + 1).
  const double u = to_double(unit_roundoff<mpfr_real>());
  const double E = 0.5;  // |E| = 1/(2a) for the semi-major axis a = 1
  double profile = 0;
  for (int i = 1; i < n; ++i)
    profile = std::max(profile, std::abs(r[i].mean_step / r[n - 1].mean_step - 1));
  c.values.push_back({"mpfr18_unit_roundoff", u});
  c.values.push_back({"max_rel_change_of_mean_step", profile});
  // [s-f5-criterion]
  // Criterion, fixed before this run (after a first reading of the tolerance as a bound on
  // the step Δt had shown no effect at all, see the chapter): the drift falls monotonically as
  // the tolerance falls; at 1e-17 every step's energy residual is at round-off (≤ 10 u|E|);
  // the step profile changes by less than 1e-4 (mean step).
  const bool roundoff = r[n - 1].max_residual <= 10 * u * E;
  const bool ok = monotone && roundoff && profile <= 1e-4;
  // [s-f5-criterion]
  for (const auto& x : r)
    if (x.failure) c.note += "Run failed: " + *x.failure + ". ";
  c.status = ok ? claims::Status::reproduced_with_caveat : claims::Status::not_reproduced;
  // How far the residual lies from the bound, and where the verdict would flip.
  const double over = r[n - 1].max_residual / (u * E);
  c.values.push_back({"residual_at_1e-17_in_u_E", over});
  if (!ok) {
    const bool only_roundoff = monotone && profile <= 1e-4 && !roundoff;
    c.cause = only_roundoff && over <= 20 ? "edge-of-criterion" : "does-not-hold";
    c.headline =
        only_roundoff
            ? fmt::format(
                  "at tol = 1e-17 the largest per-step energy residual is {:.1f} u|E|, "
                  "{:.2f}× the criterion's 10 u|E|: the verdict would be reproduced with "
                  "a bound of {:.0f} u|E| fixed beforehand; the drift's decrease with "
                  "the tolerance and the step profile hold",
                  over, over / 10, std::ceil(over))
            : fmt::format("{}{}{}", monotone ? "" : "the drift does not fall monotonically; ",
                          profile <= 1e-4 ? "" : "the step profile changes; ",
                          roundoff ? "" : fmt::format("residual {:.1f} u|E| at 1e-17", over));
  }
  c.note += fmt::format(
      "e = 0.7, h0 = 0.001, one period, MPFR with 18 digits (u = {:.2g}). Max |E_k − E_1| for "
      "tol = 1e-10, 1e-12, 1e-14, 1e-16, 1e-17: {:.2g}, {:.2g}, {:.2g}, {:.2g}, {:.2g}; largest "
      "per-step residual at 1e-17: {:.2g} = {:.1f} u|E|. Mean step changes by at most {:.1e}. {}",
      u, r[0].max_dEd, r[1].max_dEd, r[2].max_dEd, r[3].max_dEd, r[4].max_dEd,
      r[n - 1].max_residual, r[n - 1].max_residual / (u * E), profile,
      ok ? "The trend and the step profile are reproduced. Caveat: at 1e-17 the residuals are at "
           "round-off but they still add up over the steps, so the drift after ~1000 steps is "
           "about N·u|E|, not u|E| — conservation 'up to precision' holds per step, not for the "
           "accumulated energy."
         : fmt::format("Not met as a whole (criterion: monotone decrease, residual ≤ 10 u|E| at "
                       "1e-17, mean step within 1e-4): the decrease with the tolerance {} and the "
                       "step profile {}, but 18 digits do not give conservation up to precision: "
                       "the energy equation's own evaluation error near perihelion leaves "
                       "per-step residuals of up to {:.0f} u|E|, which add up to {:.0f} u|E| "
                       "over the period.",
                       monotone ? "is reproduced" : "is NOT monotone",
                       profile <= 1e-4 ? "is unchanged" : "changes",
                       r[n - 1].max_residual / (u * E), r[n - 1].max_dEd / (u * E)));
  return {c};
}

// ---- (28)–(30): accumulated discrete-energy error against the bound --------------------
std::vector<claims::ClaimResult> run_eq29(const Context& ctx) {
  const double e = 0.7, h0 = 0.01;
  const long long N = 1'000'000;
  // Steps per period ≈ 2π/(6.2·h0) ≈ 101: 1e6 steps ≈ 9900 periods. Both policies run to the
  // same time; the envelope of |E_k − E_1| is sampled at k = 2^j for the growth exponent β.
  struct Out {
    AdaptiveRun run;
  };
  Out out[2];
  const double T = double(N) * 6.25 * h0;  // mean step 6.23 h0: just over N steps
  auto f_prev = open_csv(ctx, "previous.csv"), f_init = open_csv(ctx, "initial.csv");
  // The E_1 target runs a fifth of the span beside it (the second core; it shows the absence
  // of accumulation without doubling the cost).
  parallel_for(2, 0, [&](std::size_t i) {
    EpAVI<Kepler>::Options opt;
    opt.energy_target = i == 0 ? EnergyTarget::previous : EnergyTarget::initial;
    out[i].run =
        run_epavi<double>(e, h0, i == 0 ? T : T / 5, opt, ptr(i == 0 ? f_prev : f_init), 1000);
  });
  claims::ClaimResult c;
  c.id = "S-EQ29";
  c.source = "check-s-eq29";
  const AdaptiveRun& p = out[0].run;
  const AdaptiveRun& q = out[1].run;
  // [s-eq29-criterion]
  const double bound_k = double(p.steps) * p.max_jump;
  c.values = {{"steps", double(p.steps)},
              {"final_abs_dE_d", std::abs(p.final_dEd)},
              {"max_abs_dE_d", p.max_dEd},
              {"sum_abs_jumps", p.sum_abs_jump},
              {"k_times_max_jump", bound_k},
              {"max_abs_dE_d_over_k_max_jump", p.max_dEd / bound_k},
              {"initial_target_max_abs_dE_d", q.max_dEd},
              {"initial_target_steps", double(q.steps)}};
  const bool ok = p.steps >= N && p.max_dEd <= p.sum_abs_jump && p.sum_abs_jump <= bound_k &&
                  !p.failure && !q.failure;
  // [s-eq29-criterion]
  c.status = ok ? claims::Status::reproduced : claims::Status::not_reproduced;
  c.note = fmt::format(
      "EpAVI in double, e = 0.7, h0 = 0.01, {} steps (t = {:.4g}). |E_N − E_1| = {:.3g}, max_k "
      "|E_k − E_1| = {:.3g} ≤ Σ|E_i − E_{{i−1}}| = {:.3g} ≤ k·max|E_i − E_{{i−1}}| = {:.3g}: the "
      "bound holds and is {:.2g}× too pessimistic. Targeting E_1 in every step instead of the "
      "previous E_k: max |E_k − E_1| = {:.3g} over {} steps (no accumulation: each E_k carries "
      "only its own residual).{}",
      p.steps, p.t_end, std::abs(p.final_dEd), p.max_dEd, p.sum_abs_jump, bound_k,
      bound_k / p.max_dEd, q.max_dEd, q.steps,
      p.failure ? " Run failed: " + *p.failure : std::string());
  return {c};
}

// ---- (24), (25), (39)–(41): read from the paper, against the library's L_d ----------------
std::vector<claims::ClaimResult> run_eq39(const Context&) {
  std::vector<claims::FormulaComparison> cs;
  std::vector<std::pair<std::string, double>> route;
  {
    const std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());  // GiNaC: one thread
    cs = printed_detail::sharma_discrete_prints("eq39", "check-s-eq39", &route);
  }
  // [s-eq39-criterion]
  // Each display read from the paper's LaTeX and compared exactly (GiNaC, radicals in normal
  // form) with the library's extended midpoint L_d (25) over the Kepler Lagrangian: (39)–(40)
  // with −D2 L_d, (41) with D1 L_d, as the time-marching step (15)–(16) solves them. A second
  // route, fixed beforehand: the display as the comparison left it (corrected where it was)
  // evaluated in binary64 at 1000 random points must match the integrator's AutoDiff
  // derivatives to 1e3·ε relative (|q| ≤ 1.5, Δt ≥ 1e-3: cancellation stays below ~100 ulp).
  const double tol = 1e3 * kEps;
  claims::ClaimResult c;
  c.id = "S-EQ39";
  c.source = "check-s-eq39";
  double worst = 0;
  for (const auto& [name, v] : route) {
    c.values.push_back({name, v});
    worst = std::max(worst, v);
  }
  c.status = worst <= tol ? claims::Status::reproduced : claims::Status::not_reproduced;
  // [s-eq39-criterion]
  c.note = fmt::format(
      "The Kepler Hamiltonian (24), the midpoint L_d (25) and the midpoint equations (39)–(41), "
      "read from the paper and compared exactly with the library's L_d (25) and its "
      "derivatives. Second route: each of (39)–(41) as left by the comparison, evaluated at "
      "1000 random points (|q| ≤ 1.5, Δt ∈ [1e-3, 0.1]) against the integrator's AutoDiff "
      "derivatives: largest relative deviation {:.2g} (criterion {:.2g}).",
      worst, tol);
  std::vector<claims::ClaimResult> errata;
  printed::conclude(c, cs, errata);
  std::vector<claims::ClaimResult> out{c};
  out.insert(out.end(), errata.begin(), errata.end());
  return out;
}

// ---- Lemma 1, (31)–(37): the fixed-Δa VI of the transformed Lagrangian ------------------
std::vector<claims::ClaimResult> run_l1(const Context&) {
  // L̄(q̄, q̄') = t'·L(q, q'/t') (31) and L̄_d = Δa·L̄(midpoint, difference/Δa) (35), with
  // q̄ = (t, q). Written in vibook's convention (L_d ≈ Δa·L̄), generic in the scalar.
  const auto L = mechanical_lagrangian(Kepler{});
  auto Lbar_d = [L](double da) {
    return [L, da](const auto& X0, const auto& X1, const auto&) -> scalar_t<decltype(X0)> {
      using S = scalar_t<decltype(X0)>;
      const auto mid = ((X0 + X1) * constant<S>(0.5)).eval();
      const auto vel = ((X1 - X0) / constant<S>(da)).eval();
      const S tprime = vel(0);
      const Vec<S, 2> q = mid.template tail<2>(), v = vel.template tail<2>() / tprime;
      return S(constant<S>(da) * tprime * L(q, v));
    };
  };
  // An EpAVI trajectory (e = 0.7, h0 = 0.01, two periods).
  const double e = 0.7, h0 = 0.01;
  const KeplerOrbit orbit = KeplerOrbit::perihelion(e);
  const State<2> s0 = kepler_perihelion_state(e);
  EpAVI<Kepler> m{Kepler{}};
  auto s = m.start(0.0, s0.q, h0, orbit.at(h0).q);
  // Positions and the steps EpAVI actually took (it evaluates (25) at (0, Δt) and sums the
  // times with compensation, so differences of the rounded t_k are not its steps).
  std::vector<Vec<double, 3>> X;
  std::vector<double> dts = {h0};
  X.push_back(Vec<double, 3>(0.0, s0.q(0), s0.q(1)));
  X.push_back(Vec<double, 3>(s.t, s.q(0), s.q(1)));
  double max_rel_ep = 0;
  while (s.t < 2 * kTwoPi) {
    const ExtendedStepReport rep = m.step(s);
    max_rel_ep = std::max(max_rel_ep, rep.energy_residual);
    X.push_back(Vec<double, 3>(s.t, s.q(0), s.q(1)));
    dts.push_back(m.integrator().last_step());
  }
  // Residuals of (36)–(37): D2 L̄_d(k−1, k) + D1 L̄_d(k, k+1) for any Δa (arbitrary: (35) is
  // homogeneous of degree one in the velocities, so Δa cancels).
  double worst = 0;
  for (double da : {1e-3, 0.01, 1.0}) {
    const auto Ld = Lbar_d(da);
    for (std::size_t k = 1; k + 1 < X.size(); ++k) {
      // The three points in a time origin at t_k: (−Δt_{k−1}, 0, Δt_k).
      Vec<double, 3> Xm = X[k - 1], X0 = X[k], Xp = X[k + 1];
      Xm(0) = -dts[k - 1], X0(0) = 0.0, Xp(0) = dts[k];
      const auto a = ad::two_point<3>(Ld, Xm, X0, 0.0);
      const auto b = ad::two_point<3>(Ld, X0, Xp, 0.0);
      const Vec<double, 3> r = a.D2 + b.D1;
      const double scale = std::max(a.D2.lpNorm<Eigen::Infinity>(), b.D1.lpNorm<Eigen::Infinity>());
      worst = std::max(worst, r.lpNorm<Eigen::Infinity>() / scale);
    }
  }
  // [s-l1-criterion]
  // Bound fixed beforehand: the EpAVI steps were solved to 4ε relative; the residual of the
  // same equations in a different (algebraically equal) form: ≤ 1e3·ε relative.
  claims::ClaimResult c;
  c.id = "S-L1";
  c.source = "check-s-l1";
  c.values = {{"steps", double(X.size() - 1)},
              {"max_rel_residual_36_37", worst},
              {"epavi_max_energy_residual", max_rel_ep}};
  c.status = worst <= 1e3 * kEps ? claims::Status::reproduced : claims::Status::not_reproduced;
  // [s-l1-criterion]
  c.note = fmt::format(
      "The discrete Euler–Lagrange equations (36)–(37) of L̄_d (35) for L̄ (31), with Δa = 1e-3, "
      "0.01 and 1, evaluated by AutoDiff along an EpAVI trajectory (e = 0.7, h0 = 0.01, {} "
      "steps, two periods; times in an origin at t_k with the steps EpAVI took): largest "
      "relative residual {:.2g} (bound 1e3ε). Algebraically, "
      "Δa·t'·L(q, q'/t') with t' = Δt/Δa is (t_k+1 − t_k)·L(q_mid, Δq/Δt), which is (25): Δa "
      "drops out, so the fixed-Δa VI is EpAVI for every Δa.",
      X.size() - 1, worst);
  return {c};
}

// ---- where EpAVI can step: the existence map over e -------------------------------------
std::vector<claims::ClaimResult> run_existence(const Context& ctx) {
  std::vector<double> es;
  for (int i = 0; i <= 18; ++i) es.push_back(0.05 * i);
  for (double e : {0.72, 0.74, 0.76, 0.78, 0.97, 0.99}) es.push_back(e);
  std::sort(es.begin(), es.end());
  const double h0s[] = {1e-2, 1e-3, 1e-4};
  struct Cell {
    double e, h0;
    AdaptiveRun r;
  };
  std::vector<Cell> cells;
  for (double h0 : h0s)
    for (double e : es) cells.push_back({e, h0, {}});
  parallel_for(cells.size(), 0, [&](std::size_t i) {
    // One period; h0 = 1e-4 at small e takes 60 000 steps, so it stops at a quarter period
    // (the failures seen happen within the first quarter, on the way out from perihelion).
    const double T = cells[i].h0 < 5e-4 ? kTwoPi / 4 : kTwoPi;
    cells[i].r = run_epavi<double>(cells[i].e, cells[i].h0, T, {});
  });
  auto f = open_csv(ctx, "existence.csv");
  if (f) *f << "e,h0,completed,t_reached,steps\n";
  claims::ClaimResult c;
  c.id = "S-X-EXIST";
  c.source = "epavi-existence";
  std::string txt;
  int failures = 0;
  for (double h0 : h0s) {
    double largest_ok = -1, smallest_fail = 2;
    for (const Cell& x : cells) {
      if (x.h0 != h0) continue;
      if (f)
        *f << fmt::format("{},{},{},{:.17g},{}\n", x.e, x.h0, x.r.failure ? 0 : 1,
                          x.r.failure ? x.r.failure_t : x.r.t_end, x.r.steps);
      if (x.r.failure) {
        ++failures;
        smallest_fail = std::min(smallest_fail, x.e);
      } else if (smallest_fail > 1) {
        largest_ok = x.e;
      }
    }
    c.values.push_back({fmt::format("h0_{:g}_largest_e_completed", h0), largest_ok});
    c.values.push_back({fmt::format("h0_{:g}_smallest_e_failed", h0), smallest_fail});
    txt += fmt::format("h0 = {:g}: completes for e ≤ {:g}, first failure at e = {:g}. ", h0,
                       largest_ok, smallest_fail <= 1 ? smallest_fail : NAN);
  }
  // Is a failure a missed root or no root at all? Rerun e = 0.8, h0 = 1e-3 to its failure and
  // scan the energy equation over Δt ∈ [1e-6, 10] on a logarithmic grid of 701 points.
  double g_min = INFINITY, g_at_min_dt = NAN;
  int sign_changes = 0;
  {
    const double e = 0.8, h0 = 1e-3;
    const KeplerOrbit orbit = KeplerOrbit::perihelion(e);
    const State<2> s0 = kepler_perihelion_state(e);
    EpAVI<Kepler> m{Kepler{}};
    auto s = m.start(0.0, s0.q, h0, orbit.at(h0).q);
    try {
      while (s.t < kTwoPi) m.step(s);
    } catch (const SolveError&) {
      double prev = NAN;
      for (int i = 0; i <= 700; ++i) {
        const double dt = 1e-6 * std::pow(10.0, i / 100.0);
        const double g = m.integrator().energy_equation(s, dt, s.E);
        if (g < g_min) g_min = g, g_at_min_dt = dt;
        if (i > 0 && (g < 0) != (prev < 0)) ++sign_changes;
        prev = g;
      }
    }
  }
  // The spurious root: e = 0.7, h0 = 1e-3 at t ≈ 0.3 (on the way out), scan the same grid and
  // list the sign changes; trial steps where the momentum equation has no solution are skipped.
  std::vector<double> roots;
  double chosen = NAN;
  {
    const double e = 0.7, h0 = 1e-3;
    const KeplerOrbit orbit = KeplerOrbit::perihelion(e);
    const State<2> s0 = kepler_perihelion_state(e);
    EpAVI<Kepler> m{Kepler{}};
    auto s = m.start(0.0, s0.q, h0, orbit.at(h0).q);
    while (s.t < 0.3) m.step(s);
    const auto k = s;
    const double t_before = s.t;
    double prev = NAN, prev_dt = NAN;
    for (int i = 0; i <= 700; ++i) {
      const double dt = 1e-6 * std::pow(10.0, i / 100.0);
      double g = NAN;
      try {
        g = m.integrator().energy_equation(k, dt, k.E);
      } catch (const SolveError&) {
      }
      if (std::isfinite(g) && std::isfinite(prev) && (g < 0) != (prev < 0))
        roots.push_back(std::sqrt(dt * prev_dt));
      if (std::isfinite(g)) prev = g, prev_dt = dt;
    }
    m.step(s);
    chosen = s.t - t_before;
  }
  c.values.push_back({"e0.7_t0.3_roots_found", double(roots.size())});
  c.values.push_back({"e0.7_t0.3_step_taken", chosen});
  if (roots.size() >= 2) c.values.push_back({"e0.7_t0.3_far_root", roots.back()});
  std::vector<std::string> root_text;
  for (const double x : roots) root_text.push_back(fmt::format("{:.3g}", x));
  txt += fmt::format(
      "The spurious root: at e = 0.7, h0 = 1e-3, t ≈ 0.3 the same scan finds {} sign change(s), "
      "near Δt = {}; the step taken is {:.4g}, and the far root ({:.3g}× larger) lies outside the "
      "factor-64 bracket grown from the previous step, so it is never taken. ",
      roots.size(), fmt::join(root_text, ", "), chosen,
      roots.size() >= 2 ? roots.back() / chosen : NAN);
  c.values.push_back({"e0.8_h0_0.001_scan_min_energy_residual", g_min});
  c.values.push_back({"e0.8_h0_0.001_scan_sign_changes", double(sign_changes)});
  txt += fmt::format(
      "At the failing state for e = 0.8, h0 = 1e-3 the energy equation D1 L_d − E_k, scanned "
      "over Δt ∈ [1e-6, 10] (701 log-spaced points), stays positive: minimum {:.3g} at Δt = "
      "{:.3g}, {} sign changes. No admissible root exists there (a fold, not a missed root). ",
      g_min, g_at_min_dt, sign_changes);
  // [s-x-exist-criterion]
  // The claim (Shibberu): for some states no admissible root exists. Reproduced if
  // some run stops with the typed failure; every failure must be the typed SolveError.
  c.status = failures > 0 && sign_changes == 0 && g_min > 0 ? claims::Status::reproduced
                                                            : claims::Status::not_reproduced;
  // [s-x-exist-criterion]
  c.note = txt +
           "Each run starts at perihelion and lasts one period (a quarter for h0 = 1e-4); a "
           "failure is the typed SolveError 'no admissible time step' (the energy equation has "
           "no sign change within a factor 64 of the previous step).";
  return {c};
}

}  // namespace

Check sharma_fig3() {
  return {"sharma-fig3",
          "t(a) over one period, EpAVI, AVI1, AVI2 (Sharma Fig. 3)",
          true,
          {"S-F3"},
          run_fig3};
}
Check sharma_fig4() {
  return {"sharma-fig4",
          "EpAVI and AVI2 at h0 = 0.001 and 0.01, e = 0.7 (Sharma Fig. 4)",
          true,
          {"S-F4"},
          run_fig4};
}
Check sharma_fig5() {
  return {"sharma-fig5",
          "EpAVI with 18-digit MPFR over solver tolerances (Sharma Fig. 5)",
          true,
          {"S-F5"},
          run_fig5};
}
Check check_s_eq29() {
  return {"check-s-eq29",
          "Discrete-energy error over 1e6 steps against the bound (29)",
          false,
          {"S-EQ29"},
          run_eq29};
}
Check check_s_eq39() {
  return {"check-s-eq39",
          "(24), (25), (39)–(41) read from the paper, against the library's L_d (25)",
          false,
          {"S-EQ39", "S-ERR-39", "S-ERR-40"},
          run_eq39};
}
Check check_s_l1() {
  return {"check-s-l1",
          "Fixed-Δa VI of the transformed Lagrangian (31), (35)",
          false,
          {"S-L1"},
          run_l1};
}
Check epavi_existence() {
  return {"epavi-existence",
          "Where EpAVI can step: eccentricity × h0 map",
          true,
          {"S-X-EXIST"},
          run_existence};
}

}  // namespace vibook::checks
