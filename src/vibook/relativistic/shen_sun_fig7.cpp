// Shen & Sun 2025, §3 (3.16)–(3.22) and §5 Figure 7: relativistic Kepler.
//
//   check-ss-t8             SS-T8 and the errata of the relativistic formulas
//   shen-sun-fig7           Fig. 7: orbits of (3.20) and (3.8) against the exact precessing
//                           orbit, c = 5 (the paper gives none), and the 3-D worldline
//   relativistic-precession the sweep over c: measured perihelion advance per revolution
//                           against 2π(1/Γ − 1)
#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "vibook/core/angle.hpp"
#include "vibook/core/autodiff.hpp"
#include "vibook/core/recorder.hpp"
#include "vibook/core/tolerance.hpp"
#include "vibook/mechanics/del_solver.hpp"
#include "vibook/mechanics/discrete_lagrangian.hpp"
#include "vibook/modified/printed_checks.hpp"
#include "vibook/plot/render3d.hpp"
#include "vibook/relativistic/checks.hpp"
#include "vibook/relativistic/exact.hpp"
#include "vibook/relativistic/precession.hpp"
#include "vibook/relativistic/shen_sun_fig7.hpp"

namespace vibook::checks {

using namespace vibook::relativistic;

namespace {
const Vec<double, 2> kX0(0.4, 0.0), kU0(0.0, 2.0);  // the paper's (x0, p0) = (0.4, 0, 0, 2)

double state_diff(const RelState& a, const RelState& b) {
  return std::max({std::abs(a.t - b.t), (a.x - b.x).lpNorm<Eigen::Infinity>(),
                   std::abs(a.gamma - b.gamma), (a.u - b.u).lpNorm<Eigen::Infinity>()});
}
}  // namespace

SsT8Measurement ss_t8_measure(double c, double h, int steps) {
  const Problem P(c);
  auto del = make_del_integrator<3>(discrete_lagrangian_320(P));
  RelState a = P.initial(kX0, kU0);
  SsT8Measurement m;
  m.trajectory.push_back({a.t, a.x(0), a.x(1)});
  for (int k = 0; k < steps; ++k) {
    RelState b = a, g = a, lit = a;
    Vec<double, 3> X(g.t, g.x(0), g.x(1));
    Vec<double, 3> p = canonical_momentum(P, g);
    del.reset();
    const SolveReport rep = del.step(X, p, h);
    m.max_newton_iterations = std::max(m.max_newton_iterations, rep.iterations);
    g = from_canonical(P, X, p);
    Vi322{P}.step(b, h);
    // (3.19) as printed: φ_{H_2} ∘ φ_{H_1} ∘ φ_{H_1}, no φ_{H_t}.
    flow_x(P, lit, 0, h);
    flow_x(P, lit, 0, h);
    flow_x(P, lit, 1, h);
    KSymplectic{P}.step(a, h);
    m.bound = std::max(m.bound, 64 * kEps * (a.u.norm() + std::abs(a.t) * P.grad_phi(a.x).norm()));
    m.vi322_vs_composition = std::max(m.vi322_vs_composition, state_diff(a, b));
    m.generic_vs_composition = std::max(m.generic_vs_composition, state_diff(a, g));
    m.printed_319_vs_composition = std::max(m.printed_319_vs_composition, state_diff(a, lit));
    m.trajectory.push_back({a.t, a.x(0), a.x(1)});
  }
  return m;
}

namespace {

std::vector<claims::ClaimResult> run_ss_t8(const Context&) {
  const double c = 5.0, h = 0.05;
  const SsT8Measurement m = ss_t8_measure(c, h, 800);
  std::vector<claims::ClaimResult> out;

  claims::ClaimResult t8;
  t8.id = "SS-T8";
  t8.source = "check-ss-t8";
  t8.values = {{"vi322_vs_composition_one_step_max", m.vi322_vs_composition},
               {"generic_320_vs_composition_one_step_max", m.generic_vs_composition},
               {"round_off_bound", m.bound},
               {"generic_max_newton_iterations", double(m.max_newton_iterations)}};
  // [ss-t8-criterion]
  const bool t8_ok = m.vi322_vs_composition <= m.bound && m.generic_vs_composition <= m.bound;
  t8.status = t8_ok ? claims::Status::reproduced : claims::Status::not_reproduced;
  // [ss-t8-criterion]
  t8.note = fmt::format(
      "c = {}, h = {}, 800 steps from the Fig. 7 data. The generic discrete Euler–Lagrange solver "
      "on (3.20), the explicit form (3.22) and the composition φ_H2∘φ_H1∘φ_Ht take the same step "
      "to round-off (bound 64ε(|u| + |t||∇φ|): (3.22) and (3.20) form t_(n+1) − t_n, which carries "
      "the rounding of t). As printed, (3.19) composes φ_H1 twice (SS-ERR-3.19, measured on the "
      "composition as we transcribe it: the reader evaluates expressions, not compositions of "
      "flows) and the t-equation of Theorem 8 lacks 1/c² (SS-ERR-T8, read from the paper).",
      c, h);
  if (t8_ok) {
    t8.errata.push_back("SS-ERR-3.19");
    t8.cause = "misprint";
    t8.headline = "(3.19) misprinted (SS-ERR-3.19): it composes φ_H1 twice where φ_Ht belongs";
    t8.status = claims::Status::erratum;
  }
  out.push_back(t8);

  const claims::ClaimResult e319 = claims::erratum(
      claims::ClaimInfo{"SS-ERR-3.19", "SS", "§3 (3.19)",
                        "K-symplectic composition repeats φ_H1 where φ_Ht belongs"},
      "check-ss-t8",
      {{"printed_composition_vs_322_one_step_max", m.printed_319_vs_composition},
       {"corrected_composition_vs_322_one_step_max", m.vi322_vs_composition}},
      m.printed_319_vs_composition > 1e3 * m.bound && t8_ok,

      "Printed: Φ_h = φ_HN∘…∘φ_H1∘φ_H1. The proof's (3.22) is φ_HN∘…∘φ_H1∘φ_Ht (the flow of "
      "H_t = −½c²γ², which advances t and kicks u, applied first). The printed composition never "
      "applies φ_Ht: it differs from (3.22) at first order in h, the corrected one only by "
      "round-off.");
  out.push_back(e319);

  // Signs of φ, measured on the Lagrangians by AutoDiff at x = (0.4, 0), γ = 1.1, u = (0, 2):
  // the radial component of ∂L/∂x (the force in the Euler–Lagrange equation d/dτ u = ∂L/∂x).
  const Vec<double, 2> x(0.4, 0.0);
  const double gamma = 1.1;
  auto radial_force = [&](auto L) {
    const Vec<double, 2> g = ad::gradient<2>([&](const auto& y) { return L(y); }, x);
    return g.dot(x) / x.norm();
  };
  const double f_fig7 = radial_force([&](const auto& y) -> scalar_t<decltype(y)> {
    return gamma / sqrt(y.squaredNorm());  // Fig. 7: L = −½c²γ² + ½u² + γ/|x| (x-dependent part)
  });
  const double f_sec3 = radial_force([&](const auto& y) -> scalar_t<decltype(y)> {
    return -(1.0 / sqrt(y.squaredNorm())) * gamma;  // (3.17) with §3's φ = 1/|x|: A·ẋ = −φγ
  });
  const claims::ClaimResult ephi = claims::erratum(
      claims::ClaimInfo{"SS-ERR-PHI", "SS", "§3 and §5 Fig. 7",
                        "Sign of the Coulomb potential: φ = 1/|x| (repulsive) vs the attractive "
                        "Fig. 7 Lagrangian"},
      "check-ss-t8", {{"radial_force_fig7_lagrangian", f_fig7}, {"radial_force_sec3_phi", f_sec3}},
      f_fig7 < 0 && f_sec3 > 0,

      "§3 takes φ(x) = 1/|x| in (2.7)/(3.16)–(3.17): with (3.17)'s A = (−φ, 0) the force on the "
      "particle points outwards (measured radial force > 0): no bound orbit. Fig. 7's Lagrangian "
      "L = −½c²γ² + ½u² + γ/|x| is (3.17) with φ = −1/|x|: the force points inwards (< 0) and the "
      "orbits are bound. vibook uses φ = −1/|x| (attractive), the reading Fig. 7 needs.");
  std::vector<claims::ClaimResult> errata = {ephi};

  // (2.7) and its Lagrangian, and Theorem 8's two-step equations, read from the paper: the
  // t-equation and the Lagrangian join the errata SS-ERR-T8 and SS-ERR-2.7 by name.
  std::vector<claims::FormulaComparison> cs;
  std::vector<std::pair<std::string, double>> route;
  {
    const std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());  // GiNaC: one thread
    cs = printed_detail::shen_sun_relativistic_prints("check-ss-t8", &m.trajectory, c, h, &route);
  }
  // [ss-t8-route-criterion]
  // The second route, fixed beforehand: each Theorem 8 equation as the comparison left it
  // (corrected where it was) holds along the composition's own 800 steps to 64 units of the
  // rounding of t (or x) in a second difference, 4ε·max|y|/h² (the bound of SS-T8 above).
  // The printed form of a corrected equation is reported, and must fail (> 1e6 units).
  auto has = [&](const std::string& n) {
    return std::any_of(route.begin(), route.end(), [&](const auto& r) { return r.first == n; });
  };
  for (const auto& [name, v] : route) {
    t8.values.push_back({name, v});
    std::string other = name;
    const auto at = other.find("_printed_");
    const bool superseded = at != std::string::npos && has(other.replace(at, 9, "_corrected_"));
    if (superseded ? !(v > 1e6) : !(v <= 64)) t8.status = claims::Status::not_reproduced;
  }
  // [ss-t8-route-criterion]
  printed::conclude(t8, cs, errata,
                    {{"L361", "SS-ERR-T8"}, {"I147.4", "SS-ERR-2.7"}, {"I321", "SS-ERR-PHI"}});
  out.front() = t8;
  out.insert(out.end(), errata.begin(), errata.end());
  return out;
}

// --- Fig. 7 -------------------------------------------------------------------------------
struct OrbitRun {
  double orbit_err = 0;     // max |r − r_exact(φ)| / r_exact(φ)
  double traj_err = 0;      // max |x − x_exact(τ)|
  double energy_drift = 0;  // max |E − E0| / c²
  double L_drift = 0, shell_drift = 0;
  std::optional<double> precession;
};

template <class Method>
OrbitRun run_orbit(const Problem& P, const ExactOrbit& ex, Method method, double h, long steps,
                   std::ostream* csv, std::vector<std::array<double, 3>>* worldline) {
  RelState s = P.initial(kX0, kU0);
  const Invariants i0 = invariants(P, s);
  OrbitRun out;
  PerihelionTracker tracker;
  AngleUnwrapper polar_angle;
  std::optional<TrajectoryRecorder> rec;
  if (csv)
    rec.emplace(*csv, std::vector<std::string>{"step", "tau", "t", "x1", "x2", "gamma", "u1", "u2",
                                               "energy", "L", "shell"});
  for (long k = 0; k <= steps; ++k) {
    if (k > 0) method.step(s, h);
    const double tau = double(k) * h;
    const Invariants inv = invariants(P, s);
    const double phi_unwrapped = polar_angle(std::atan2(s.x(1), s.x(0)));
    const double r_ex = ex.radius_at_angle(phi_unwrapped);
    out.orbit_err = std::max(out.orbit_err, std::abs(s.x.norm() - r_ex) / r_ex);
    out.traj_err = std::max(out.traj_err, (s.x - ex.at(tau).x).norm());
    out.energy_drift = std::max(out.energy_drift, std::abs(inv.energy - i0.energy) / (P.c * P.c));
    out.L_drift = std::max(out.L_drift, std::abs(inv.L - i0.L));
    out.shell_drift = std::max(out.shell_drift, std::abs(inv.shell - 1.0));
    tracker.add(s.x);
    if (rec)
      rec->offer(k, std::array<double, 11>{double(k), tau, s.t, s.x(0), s.x(1), s.gamma, s.u(0),
                                           s.u(1), inv.energy, inv.L, inv.shell});
    if (worldline) worldline->push_back({s.x(0), s.x(1), s.t});
  }
  if (rec) rec->finish();
  out.precession = tracker.advance_per_revolution();
  return out;
}

std::vector<claims::ClaimResult> run_fig7(const Context& ctx) {
  const double c = kFig7SpeedOfLight, h = 0.05, tau_end = 40.0;
  const long steps = std::lround(tau_end / h);
  const Problem P(c);
  const ExactOrbit ex(P, kX0, kU0);
  std::optional<std::ofstream> f_vi, f_vi2;
  if (ctx.out_dir) {
    f_vi.emplace(*ctx.out_dir / "vi.csv");
    f_vi2.emplace(*ctx.out_dir / "vi2.csv");
    std::ofstream e(*ctx.out_dir / "exact.csv");
    TrajectoryRecorder rec(e, {"tau", "t", "x1", "x2"});
    for (long k = 0; k <= steps; k += 4) {  // dots every 4 steps, as in the paper's figure
      const RelState s = ex.at(double(k) * h);
      rec.offer(k, std::array<double, 4>{double(k) * h, s.t, s.x(0), s.x(1)});
    }
    rec.finish();
  }
  std::vector<std::array<double, 3>> worldline;
  const OrbitRun vi = run_orbit(P, ex, Vi322{P}, h, steps, f_vi ? &*f_vi : nullptr, nullptr);
  const OrbitRun vi2 = run_orbit(P, ex, Vi2{P}, h, steps, f_vi2 ? &*f_vi2 : nullptr,
                                 ctx.out_dir ? &worldline : nullptr);

  claims::ClaimResult r;
  r.id = "SS-F7";
  r.source = "shen-sun-fig7";
  r.values = {{"c_chosen", c},
              {"Gamma", ex.Gamma()},
              {"exact_precession_per_rev", ex.precession_per_revolution()},
              {"vi_orbit_rel_err_max", vi.orbit_err},
              {"vi2_orbit_rel_err_max", vi2.orbit_err},
              {"vi_trajectory_err_max", vi.traj_err},
              {"vi2_trajectory_err_max", vi2.traj_err},
              {"vi_precession_per_rev", vi.precession.value_or(NAN)},
              {"vi2_precession_per_rev", vi2.precession.value_or(NAN)},
              {"vi_energy_drift_over_c2", vi.energy_drift},
              {"vi2_energy_drift_over_c2", vi2.energy_drift},
              {"vi_L_drift", vi.L_drift},
              {"vi2_L_drift", vi2.L_drift},
              {"vi_shell_drift", vi.shell_drift},
              {"vi2_shell_drift", vi2.shell_drift}};
  // [ss-f7-criterion]
  // Criteria fixed before measuring: both numerical orbits within 5% (radially) of the exact
  // orbit over τ ∈ [0, 40] — what "agree with the exact orbit" means at the scale of the
  // paper's plot — and the second-order method closer than the first-order one.
  auto meets = [](const OrbitRun& a, const OrbitRun& b) {
    return a.orbit_err < 0.05 && b.orbit_err < 0.05 && b.orbit_err < a.orbit_err;
  };
  const bool ok = meets(vi, vi2);
  r.status = ok ? claims::Status::reproduced_with_caveat : claims::Status::not_reproduced;
  // [ss-f7-criterion]
  // The paper gives no c: the same criterion, at the paper's h = 0.05 and τ ∈ [0, 40], for
  // every c of the sweep. Which c meet it decides whether the claim depends on the reading.
  std::vector<std::string> c_met, c_missed;
  for (double cs : kSweepSpeeds) {
    const Problem Ps(cs);
    const ExactOrbit exs(Ps, kX0, kU0);
    const OrbitRun a = run_orbit(Ps, exs, Vi322{Ps}, h, steps, nullptr, nullptr);
    const OrbitRun b = run_orbit(Ps, exs, Vi2{Ps}, h, steps, nullptr, nullptr);
    r.values.push_back({fmt::format("c{}_vi_orbit_rel_err_max", cs), a.orbit_err});
    r.values.push_back({fmt::format("c{}_vi2_orbit_rel_err_max", cs), b.orbit_err});
    (meets(a, b) ? c_met : c_missed).push_back(fmt::format("{}", cs));
  }
  if (!ok) {
    r.cause = c_met.empty() ? "does-not-hold" : "open-reading";
    // Over the sweep: which c meet the criterion, in words when none or all do.
    const std::string sweep =
        c_met.empty()      ? fmt::format("the criterion fails for every c of the sweep ({})",
                                         fmt::join(c_missed, ", "))
        : c_missed.empty() ? fmt::format("the criterion holds for every c of the sweep ({})",
                                         fmt::join(c_met, ", "))
                           : fmt::format(
                                 "over the sweep the criterion holds for c ∈ {{{}}} and fails for "
                                 "c ∈ {{{}}}",
                                 fmt::join(c_met, ", "), fmt::join(c_missed, ", "));
    r.headline = fmt::format(
        "at the paper's h = 0.05 the orbits are not within 5% of the exact precessing orbit at "
        "our c = {} ((3.20) {:.2g}, (3.8) {:.2g}); {}",
        c, vi.orbit_err, vi2.orbit_err, sweep);
  }
  r.note = fmt::format(
      "Readings: the paper gives no c; we take c = {} (exact precession {:.3f} rad per revolution, "
      "visible); t ∈ [0, 40] is read as proper time τ (the integrators step in τ; coordinate time "
      "reaches {:.2f}); the potential is attractive (SS-ERR-PHI). Criterion, fixed before "
      "measuring: both orbits within 5% (radially) of the exact precessing orbit over the run, "
      "(3.8) closer than (3.20). Measured at the paper's h = 0.05: {:.2g} for (3.20), {:.2g} for "
      "(3.8). The cause is the methods' own perihelion drift at this step: they advance the "
      "perihelion {:.3f} and {:.3f} rad per revolution against {:.3f}, an error comparable to the "
      "relativistic effect itself; with h = 5e-4 they agree with 2π(1/Γ − 1) (relativistic-"
      "precession). Energy c²γ + φ is conserved to round-off by both compositions; the mass shell "
      "γ² − |u|²/c² = 1 is not.",
      c, ex.precession_per_revolution(), ex.at(tau_end).t, vi.orbit_err, vi2.orbit_err,
      vi.precession.value_or(NAN), vi2.precession.value_or(NAN), ex.precession_per_revolution());

  if (ctx.out_dir) {
    // The 3-D worldline (x1, x2, t) of (3.8) over the exact orbit's, rendered off-screen.
    plot::Polyline3D num, exact_line;
    num.points = worldline;
    for (long k = 0; k <= steps; ++k) {
      const RelState s = ex.at(double(k) * h);
      exact_line.points.push_back({s.x(0), s.x(1), s.t});
    }
    exact_line.color = {0.55f, 0.55f, 0.55f};
    exact_line.width = 4.0f;
    num.color = {0.11f, 0.42f, 0.66f};
    try {
      plot::write_png(*ctx.out_dir / "shen-sun-fig7-worldline.png",
                      plot::render_lines({exact_line, num}, plot::View3D{}));
    } catch (const plot::RenderError& e) {
      r.note += fmt::format(" (3-D worldline not rendered: {})", e.what());
    }
  }
  return {r};
}

// --- the sweep over c ------------------------------------------------------------------------
std::vector<claims::ClaimResult> run_sweep(const Context& ctx) {
  // The signal at c = 100 is 5e-4 rad per revolution; the method's own (Newtonian) precession
  // error must sit well below it. h = 5e-4 makes it ~1e-6 (second order); it is measured
  // below at c = 1e4 and allowed for in the criterion.
  const double h = 5e-4;
  std::optional<std::ofstream> f;
  std::optional<TrajectoryRecorder> rec;
  if (ctx.out_dir) {
    f.emplace(*ctx.out_dir / "sweep.csv");
    rec.emplace(*f, std::vector<std::string>{"c", "exact", "vi2", "vi", "newtonian"});
  }
  claims::ClaimResult r;
  r.id = "SS-F7";
  r.source = "relativistic-precession";
  double worst_rel = 0;
  long i = 0;
  double floor = 0;  // the method's own precession, measured in the Newtonian limit
  {
    const Problem P(1e4);  // relativistic advance ~5e-8 rad: negligible
    const ExactOrbit ex(P, kX0, kU0);
    const long steps = std::lround(6.5 * ex.radial_period() / h);
    floor = std::abs(run_orbit(P, ex, Vi2{P}, h, steps, nullptr, nullptr).precession.value_or(NAN));
  }
  bool ok = std::isfinite(floor);
  for (double c : kSweepSpeeds) {
    const Problem P(c);
    const ExactOrbit ex(P, kX0, kU0);
    const long steps = std::lround(6.5 * ex.radial_period() / h);  // six perihelion passages
    const OrbitRun vi2 = run_orbit(P, ex, Vi2{P}, h, steps, nullptr, nullptr);
    const OrbitRun vi = run_orbit(P, ex, Vi322{P}, h, steps, nullptr, nullptr);
    const double exact = ex.precession_per_revolution();
    const double m2 = vi2.precession.value_or(NAN), m1 = vi.precession.value_or(NAN);
    worst_rel = std::max(worst_rel, std::abs(m2 - exact) / exact);
    // [ss-f7-precession-criterion]
    ok = ok && std::abs(m2 - exact) <= 0.01 * exact + floor;
    // [ss-f7-precession-criterion]
    r.values.push_back({fmt::format("c{}_exact", c), exact});
    r.values.push_back({fmt::format("c{}_vi2_measured", c), m2});
    if (rec) rec->offer(i++, std::array<double, 5>{c, exact, m2, m1, 0.0});
  }
  if (rec) rec->finish();
  r.values.push_back({"worst_rel_err_vi2_vs_2pi(1/Gamma-1)", worst_rel});
  r.values.push_back({"vi2_own_precession_at_c1e4", floor});
  r.status = ok ? claims::Status::reproduced : claims::Status::not_reproduced;
  r.note = fmt::format(
      "Sweep over c (h = 5e-4, method (3.8), six perihelion passages, Fig. 7 initial data): the "
      "measured perihelion advance per revolution matches 2π(1/Γ − 1), Γ = √(1 − 1/(c²L²)), within "
      "{:.2g} relative for every c (criterion: 1% plus the method's own precession, {:.2g} rad per "
      "revolution measured at c = 1e4), and vanishes like 1/c² towards the Newtonian limit.",
      worst_rel, floor);
  return {r};
}

}  // namespace

Check check_ss_t8() {
  return {"check-ss-t8",
          "Relativistic VI (3.20) = (3.22) = K-symplectic composition; errata of (2.7), (3.19), "
          "Thm 8, φ",
          false,
          {"SS-T8", "SS-ERR-3.19", "SS-ERR-T8", "SS-ERR-PHI", "SS-ERR-2.7"},
          run_ss_t8};
}

Check shen_sun_fig7() {
  return {"shen-sun-fig7",
          "Relativistic Kepler orbits of (3.20) and (3.8) against the exact orbit (SS Fig. 7)",
          true,
          {"SS-F7"},
          run_fig7};
}

Check relativistic_precession() {
  return {"relativistic-precession",
          "Perihelion advance per revolution against 2π(1/Γ − 1), swept over c",
          true,
          {"SS-F7"},
          run_sweep};
}

}  // namespace vibook::checks
