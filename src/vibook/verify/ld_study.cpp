// The study of a typed discrete Lagrangian (ld_study.hpp), compiled once for every dimension:
// each phase below states what it measures and how it is judged; the criteria of the scaling
// phases are those of every route (phases.hpp, book chapter "Verify your own integrator",
// section "The criteria of every route").
#include "vibook/verify/ld_study.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <mutex>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "vibook/core/progress.hpp"
#include "vibook/modified/series.hpp"
#include "vibook/verify/map_study.hpp"
#include "vibook/verify/phases.hpp"

namespace vibook::verify {

using nlohmann::json;

namespace {

std::string vtext(const Eigen::VectorXd& v) {
  return vec_text(std::vector<double>(v.data(), v.data() + v.size()));
}

// Where the integrator is, for the message of a step that fails.
struct Where {
  std::string phase;
  long long step = 0;
  double t = 0;
  double h = 0;
  void start(std::string p, double step_size) {
    phase = std::move(p);
    step = 0;
    t = 0;
    h = step_size;
  }
};

}  // namespace

std::unique_ptr<LdKernel> make_ld_kernel(const TypedDiscreteLagrangian& dl,
                                         bool reference_evaluation) {
  switch (dl.dim()) {
    case 1:
      return detail::make_ld_kernel_n<1>(dl, reference_evaluation);
    case 2:
      return detail::make_ld_kernel_n<2>(dl, reference_evaluation);
    case 3:
      return detail::make_ld_kernel_n<3>(dl, reference_evaluation);
    case 4:
      return detail::make_ld_kernel_n<4>(dl, reference_evaluation);
    case 5:
      return detail::make_ld_kernel_n<5>(dl, reference_evaluation);
    case 6:
      return detail::make_ld_kernel_n<6>(dl, reference_evaluation);
    default:
      throw ArgumentError("dimension", fmt::format("{} is not in 1..{}", dl.dim(), kMaxDim));
  }
}

LdStudy run_ld_study(const TypedDiscreteLagrangian& dl, const LdSettings& p) {
  using Clock = std::chrono::steady_clock;
  LdStudy study;
  const int n = dl.dim();
  const std::unique_ptr<LdKernel> kernel = make_ld_kernel(dl, p.reference_evaluation);
  LdKernel& K = *kernel;
  Eigen::VectorXd z0(2 * n);
  for (int i = 0; i < n; ++i) {
    z0(i) = p.q0[i];
    z0(n + i) = p.p0[i];
  }
  std::vector<LdPhase>& phases = study.phases;
  json js;
  js["input"] = {{"ld", p.ld_text},
                 {"potential", p.potential_text},
                 {"lagrangian", p.lagrangian_text},
                 {"hamiltonian", p.hamiltonian_text},
                 {"intended", dl.has_hamiltonian()  ? "hamiltonian"
                              : dl.default_system() ? "L = |v|^2/2 - V(q)"
                                                    : "lagrangian"},
                 {"dim", n},
                 {"evaluation", K.evaluation_kind()},
                 {"q0", p.q0},
                 {"p0", p.p0}};
  std::ostringstream out;  // the text report, printed at the end whatever happened
  auto line = [&](const std::string& label, const std::string& text) {
    out << fmt::format("{:<21}{}\n", label, text);
  };
  // Run one part: a failure is recorded with its reason and exit status, never thrown on.
  auto run = [&](const std::string& name, auto&& body) {
    LdPhase ph;
    ph.name = name;
    progress::set_stage(name);
    const auto t0 = Clock::now();
    try {
      body();
      ph.status = "ok";
    } catch (const NumericalError& e) {
      ph.status = "failed";
      ph.reason = e.what();
      ph.exit = kLdNumerical;
    } catch (const ArgumentError& e) {
      ph.status = "failed";
      ph.reason = e.what();
      ph.exit = kLdBadArgument;
    } catch (const std::exception& e) {
      ph.status = "failed";
      ph.reason = e.what();
      ph.exit = kLdFailure;
    }
    ph.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    phases.push_back(ph);
    return ph.status == "ok";
  };
  auto failed_line = [&](const std::string& label) {
    const LdPhase& ph = phases.back();
    line(label, "FAILED (" + std::string(ph.exit == kLdNumerical ? "numerical" : "error") +
                    "): " + ph.reason);
  };

  out << fmt::format("{:<21}{}\n", "discrete Lagrangian", p.ld_text);
  if (dl.has_hamiltonian())
    line("intended system", "H = " + p.hamiltonian_text);
  else if (!dl.default_system())
    line("intended system", "L = " + p.lagrangian_text);
  else
    line("intended system",
         "L = v^2/2 - V(q) (the default; --lagrangian or --hamiltonian to change)");
  line("potential", (p.potential_text.empty() ? std::string("(none)") : p.potential_text) +
                        fmt::format("   ({}-dimensional)", n));
  line("evaluation", K.evaluation());

  // --- the stability hint: the largest frequency of V at q0 (unit mass) ---------------------
  const double omega = K.largest_frequency(p.q0);
  auto hint = [&](double h) -> std::string {
    if (omega * h > 2)
      return fmt::format(
          " The largest frequency of V at q0 is ω = {:.4g} (unit mass): ωh = {:.3g} exceeds 2, "
          "the stability limit of explicit two-step methods such as Störmer–Verlet.",
          omega, omega * h);
    return {};
  };

  // Why an order may not show: the step sizes do not resolve the fastest frequency at q0.
  auto resolution_hint = [&](bool passed, const std::vector<double>& hs) -> std::string {
    if (passed || hs.empty()) return {};
    const double hmax = *std::max_element(hs.begin(), hs.end());
    const double hmin = *std::min_element(hs.begin(), hs.end());
    if (!(omega * hmax > 1)) return {};
    return fmt::format(
        " (ω = {:.4g} at q0: ωh runs from {:.3g} to {:.3g}, and the order shows only once ωh is "
        "small; try smaller --h-list)",
        omega, omega * hmax, omega * hmin);
  };

  // A step of the typed method with its place recorded, for a failure's message.
  Where where;
  struct NewtonStats {
    long long steps = 0, iterations = 0;
    int max_iterations = 0;
    double max_residual = 0;
  } newton;
  auto stepper = [&](bool warm, bool count) -> Step {
    return [&, warm, count](Eigen::VectorXd& z, double h) {
      if (!warm) K.reset();
      try {
        const SolveReport rep = K.step(z, h);
        if (count) {
          ++newton.steps;
          newton.iterations += rep.iterations;
          newton.max_iterations = std::max(newton.max_iterations, rep.iterations);
          newton.max_residual = std::max(newton.max_residual, rep.residual);
        }
      } catch (const NumericalError& e) {
        Eigen::VectorXd zz = z;
        throw NumericalError(fmt::format(
            "{}: step {} at t = {:.6g} from q = {}, p = {}, h = {:g}: {}.{}", where.phase,
            where.step + 1, where.t, vtext(zz.head(n)), vtext(zz.tail(n)), h, e.what(), hint(h)));
      }
      ++where.step;
      where.t += h;
    };
  };
  const Step step = stepper(false, false);

  // --- 0. regularity: D1 D2 L_d invertible at the first step, or the discrete Euler–Lagrange
  // equations cannot be solved for q1 (every numerical part below then fails; exit 3).
  json jreg;
  if (!run("regularity", [&] {
        Eigen::VectorXd qa(n), qb(n);
        for (int i = 0; i < n; ++i) {
          qa(i) = p.q0[i];
          qb(i) = p.q0[i] + p.h * p.p0[i];
        }
        const auto d = K.two_point(qa, qb, p.h);
        const double det = d.det;
        const double scale = std::pow(d.D12.cwiseAbs().maxCoeff(), n);
        jreg = {{"det_D1D2", std::isfinite(det) ? json(det) : json(nullptr)}, {"h", p.h}};
        // Not finite is not degenerate: say which value failed, and where.
        const auto where = [&] {
          return fmt::format("q0 = q(0) = {}, q1 = q(0) + h p(0) = {}, h = {:g}", vtext(qa),
                             vtext(qb), p.h);
        };
        if (!std::isfinite(d.value))
          throw NumericalError(fmt::format(
              "the discrete Lagrangian is not finite at the initial state: L_d = {:g} at {} "
              "(a logarithm or root of a negative number, a division by zero or an overflow)",
              d.value, where()));
        if (!d.D1.allFinite() || !d.D2.allFinite() || !std::isfinite(det))
          throw NumericalError(fmt::format(
              "the derivatives of the discrete Lagrangian are not finite at the initial state "
              "(L_d = {:g}, det D1 D2 L_d = {:g}) at {}",
              d.value, det, where()));
        if (!(std::abs(det) > 1e-12 * scale))
          throw NumericalError(fmt::format(
              "the discrete Lagrangian is degenerate at the initial state: det D1 D2 L_d = {:.3g} "
              "at {} (its discrete Euler-Lagrange equations cannot be solved for q1)",
              det, where()));
      }))
    failed_line("regularity");
  js["regularity"] = jreg;

  // --- 1. consistency: h^-1 L_d → L as h → 0 ------------------------------------------------
  bool consistent = false;
  bool unscaled = false;  // L_d/h has negative powers of h: not of the size h·L
  json jcons;
  run("consistency", [&] {
    std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
    std::vector<GiNaC::symbol> x, v;
    std::vector<modified::ex> X(n), Xh(n), Vv(n);
    const GiNaC::symbol h("h");
    for (int i = 0; i < n; ++i) {
      x.emplace_back(n == 1 ? "x" : "x" + std::to_string(i + 1));
      v.emplace_back(n == 1 ? "v" : "v" + std::to_string(i + 1));
      X[i] = x.back();
      Vv[i] = v.back();
      Xh[i] = x.back() + h * v.back();
    }
    const modified::ex ld = K.ld_symbolic(X, Xh, modified::ex(h)) / h;
    modified::ex L0;
    try {
      const modified::ex ser = GiNaC::expand(GiNaC::series_to_poly(ld.series(h == 0, 1)));
      const int low = ser.ldegree(h);
      if (low < 0) {
        // A negative power of h: L_d is not of the size h·L; there is no leading term to
        // compare, and the verdict is "no" (the numerics still run and say what they see).
        const auto lead =
            modified::canonical_string(GiNaC::expand(ser.coeff(h, low)), modified::Format::text);
        jcons["leading_term"] = fmt::format("({})*h^{}", lead, low);
        jcons["passed"] = false;
        unscaled = true;
        jcons["reason"] = fmt::format(
            "h^-1 L_d has a term ({})*h^{} that grows as h -> 0: L_d is not of the size h·L", lead,
            low);
        line("consistency", "NO, " + jcons["reason"].get<std::string>());
        return;
      }
      L0 = ser.subs(h == 0);
    } catch (const std::exception& e) {
      throw NumericalError(std::string("the leading term of h^-1 L_d(x, x + h v, h) as h -> 0 "
                                       "could not be formed: ") +
                           e.what());
    }
    auto txt = [&](const modified::ex& e) {
      return modified::canonical_string(GiNaC::expand(e), modified::Format::text);
    };
    jcons["leading_term"] = txt(L0);
    std::string verdict;
    if (!dl.has_hamiltonian()) {
      const modified::ex L = K.lagrangian_symbolic(X, Vv);
      jcons["intended"] = txt(L);
      const modified::ex diff = GiNaC::expand(L0 - L);
      consistent = modified::vanishes(diff);
      if (!consistent) {
        // which part differs: the terms with v (kinetic) and those without
        auto split = [&](const modified::ex& e, bool with_v) {
          modified::ex part = 0;
          const modified::ex ee = GiNaC::expand(e);
          const GiNaC::exvector terms = GiNaC::is_a<GiNaC::add>(ee)
                                            ? GiNaC::exvector(ee.begin(), ee.end())
                                            : GiNaC::exvector{ee};
          for (const auto& t : terms) {
            bool has_v = false;
            for (const auto& s : v) has_v = has_v || t.has(s);
            if (has_v == with_v) part += t;
          }
          return part;
        };
        std::vector<std::string> parts;
        for (const bool with_v : {true, false}) {
          const modified::ex a = split(L0, with_v), b = split(L, with_v);
          if (!modified::vanishes(GiNaC::expand(a - b)))
            parts.push_back(fmt::format(
                "the {} is {}, expected {}",
                with_v ? "kinetic part (terms in v)" : "part without v (minus the potential)",
                txt(a), txt(b)));
        }
        verdict = fmt::format("{}", fmt::join(parts, "; "));
      }
    } else {
      // Against H: at sample states (q, p), v = dH/dp, and the leading term must give
      // L0(q, v) = p·v − H(q, p) and dL0/dv = p.
      std::mt19937_64 rng(20261124);
      std::uniform_real_distribution<double> U(-0.5, 0.5);
      double worst = 0;
      std::string at;
      for (int s = 0; s < 8; ++s) {
        Eigen::VectorXd y(2 * n);
        for (int i = 0; i < n; ++i) {
          y(i) = p.q0[i] + (s ? U(rng) : 0.0);
          y(n + i) = p.p0[i] + (s ? U(rng) : 0.0);
        }
        Eigen::VectorXd g;
        const double Hv = K.hamiltonian_gradient(y, g);
        GiNaC::exmap m;
        double pv = 0;
        for (int i = 0; i < n; ++i) {
          m[x[i]] = y(i);
          m[v[i]] = g(n + i);
          pv += y(n + i) * g(n + i);
        }
        auto num = [&](const modified::ex& e) {
          return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(m))).to_double();
        };
        const double lhs = num(L0), rhs = pv - Hv;
        double dev = std::abs(lhs - rhs) / std::max(1.0, std::abs(rhs));
        for (int i = 0; i < n; ++i)
          dev = std::max(
              dev, std::abs(num(L0.diff(v[i])) - y(n + i)) / std::max(1.0, std::abs(y(n + i))));
        if (dev > worst) {
          worst = dev;
          at = fmt::format("at q = {}, p = {}: L0(q, dH/dp) = {:.6g}, p·v − H = {:.6g}",
                           vtext(y.head(n)), vtext(y.tail(n)), lhs, rhs);
        }
      }
      jcons["max_relative_deviation"] = worst;
      consistent = worst <= 1e-10;
      if (!consistent)
        verdict = "the leading term " + txt(L0) + " is not the Legendre transform of H: " + at;
    }
    jcons["passed"] = consistent;
    if (!consistent) jcons["reason"] = verdict;
    line("consistency", consistent ? "h^-1 L_d -> the intended L as h -> 0: yes"
                                   : "h^-1 L_d -> " + txt(L0) + " as h -> 0: NO, " + verdict);
  });
  if (phases.back().status != "ok") failed_line("consistency");
  js["consistency"] = jcons;

  // --- 2. the reference: the continuous equations in double-double --------------------------
  Eigen::VectorXd zref;
  double ref_error = NAN;
  json jref;
  // --adaptive epavi: the positions at h and h/2, the start-up steps of the adaptive runs
  std::array<Eigen::VectorXd, 2> q_start;
  const bool have_ref = run("reference", [&] {
    const LdReference r = K.reference(p);
    zref = r.z;
    ref_error = r.error;
    q_start = r.q_start;
    jref["macro_steps"] = r.macro_steps;
    jref["evaluations"] = r.evaluations;
    jref["method"] = "Gragg-Bulirsch-Stoer extrapolation, 8 columns (order 16), double-double";
    jref["equations"] = dl.has_hamiltonian() ? "Hamilton's equations of H"
                                             : "Euler-Lagrange equations of the intended L";
    jref["T"] = p.t_end;
    jref["state"] = std::vector<double>(zref.data(), zref.data() + zref.size());
    jref["estimated_error"] = ref_error;
    line("reference",
         fmt::format("{} by GBS extrapolation (order 16) in double-double, {} macro-steps: "
                     "estimated error {:.1e}",
                     dl.has_hamiltonian() ? "Hamilton's equations of H"
                                          : "the Euler-Lagrange equations of L",
                     static_cast<long>(jref["macro_steps"]), ref_error));
  });
  if (!have_ref) failed_line("reference");
  js["reference"] = jref;

  // --- 3. order against the reference: the order study of every route (map_study.hpp) -----
  // The walk of step sizes, the window, the settled local slopes and the tolerance are those
  // of the other routes; the typed method steps in double (its compiled tape), so the window
  // is double's [1e-12, 1e-6] (chapter "Verify your own integrator", the order criterion).
  std::vector<double> order_err, order_h;
  PlateauFit fit;
  bool order_passed = false;
  json jorder;
  if (!have_ref) {
    phases.push_back({"order", "skipped", "no reference solution", kLdOk, 0});
    line("order", "not measured: no reference solution");
  } else if (run("order", [&] {
               MapStudy ms;
               ms.step = step;
               // Each run restarts the place a failure is reported at: n − 1 steps of h, then
               // the last one shortened to end at T (run_map).
               bool last_pending = false;
               ms.propagate = [&](Eigen::VectorXd& z, double h, long long count) {
                 if (count > 1 || !last_pending)
                   where.start(fmt::format("order study at h = {:g}", h), h);
                 last_pending = count > 1;
                 for (long long k = 0; k < count; ++k) step(z, h);
               };
               ms.z0 = z0;
               ms.t_end = p.t_end;
               ms.hs = p.hs;
               ms.floor = p.floor;
               ms.order_tol = p.order_tol;
               ms.expected = p.expected;
               // no double-double digits: study_order reads them only in runs in
               // double-double, which need a step_dd (the typed L_d steps in double)
               const OrderStudy o = study_order(ms, zref, {}, ref_error);
               MapMeasurement mm;
               report_order(ms, o, mm);
               out << mm.out.str();
               jorder = mm.js["order"];
               jorder["reference"] = "independent (continuous equations)";
               order_err = o.err;
               order_h = o.hs;
               fit = o.fit;
               order_passed = o.passed;
               const std::string why = resolution_hint(order_passed, order_h);
               if (!why.empty()) line("", why.substr(1));
             })) {
  } else {
    failed_line("order");
  }
  js["order"] = jorder;

  // --- 3b. the variational order from the engine (Marsden & West 2001, §2.3.1) ---------------
  // L_d − L_d^E along the solutions of the intended L, expanded in h to the expected order: the
  // first term that does not vanish is h^{r+1}, r the variational order. It is judged like the
  // measured order, two-sided: r must be the expected order (an integer), so that every term
  // below h^{p+1} vanishes and the h^{p+1} term does not.
  json jvar;
  const bool var_judged = p.expected == std::floor(p.expected) && p.expected <= modified::max_order;
  const int var_k = static_cast<int>(std::min<double>(std::ceil(p.expected), modified::max_order));
  if (n > 3) {
    phases.push_back({"variational order", "skipped",
                      "the symbolic engine is run for at most 3 dimensions", kLdOk, 0});
    line("variational order", "not derived: the symbolic engine is run for at most 3 dimensions");
  } else if (unscaled) {
    // Not an error of the run: the verdict on consistency (above) says why, status 5.
    const std::string why =
        "L_d is not of the size h·L (see consistency), so L_d - L_d^E has "
        "no expansion in powers of h";
    phases.push_back({"variational order", "skipped", why, kLdOk, 0});
    line("variational order", "not derived: " + why);
    jvar = {{"derived", false}, {"reason", why}};
  } else if (run("variational order", [&] {
               jvar["checked_to"] = fmt::format("h^{}", var_k + 1);
               jvar["expected"] = p.expected;
               jvar["source"] =
                   "engine: L_d - L_d^E along the solutions of the intended L, expanded about the "
                   "step's midpoint (Marsden & West 2001, Sec. 2.3.1)";
               int r = 0;
               std::string first_term;
               if (dl.has_hamiltonian() && !consistent) {
                 // The Legendre transform of H is not the limit of L_d/h (consistency, above):
                 // the h^1 term of L_d − L_d^E does not vanish.
                 jvar["lagrangian_from"] = "none: h^-1 L_d does not tend to the Lagrangian of H";
                 first_term = "the h^1 term, see consistency";
               } else {
                 std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
                 auto jets = std::make_shared<modified::JetSpace>(n);
                 modified::Engine engine(K.symbolic(jets), var_k);
                 modified::ex L;
                 if (dl.has_hamiltonian()) {
                   // The Lagrangian of H: the leading term of L_d/h, which the consistency part
                   // has checked to be H's Legendre transform.
                   L = engine.l_disc().at(0);
                   jvar["lagrangian_from"] = "the leading term of h^-1 L_d, checked against H";
                 } else {
                   std::vector<modified::ex> X(n), V(n);
                   for (int i = 0; i < n; ++i) {
                     X[i] = jets->x(0, i);
                     V[i] = jets->x(1, i);
                   }
                   L = K.lagrangian_symbolic(X, V);
                   jvar["lagrangian_from"] = "the intended L";
                 }
                 const auto vo = engine.variational_order(L);
                 json terms = json::array();
                 for (const auto& d : vo.defect)
                   terms.push_back(modified::canonical_string(d, modified::Format::text));
                 jvar["defect"] = terms;  // [k]: the coefficient of h^{k+1} in L_d − L_d^E
                 r = vo.order;
                 if (r >= 0) first_term = terms[r].get<std::string>();
               }
               jvar["order"] = r >= 0 ? json(r) : json(nullptr);
               const bool agrees_expected = r >= 0 && r == p.expected;
               if (var_judged) jvar["passed"] = agrees_expected;
               std::string measured;
               if (jorder.is_object() && jorder.contains("fitted") &&
                   jorder["fitted"].is_number()) {
                 const double slope = jorder["fitted"].get<double>();
                 const bool agrees = r >= 0 && std::abs(slope - r) < p.order_tol;
                 jvar["agrees_with_measured"] = agrees;
                 measured = fmt::format("; measured {:.3f}: {}", slope,
                                        agrees ? "agrees" : "DISAGREES (a finding)");
               }
               const std::string term =
                   first_term.size() <= 100
                       ? first_term
                       : fmt::format("a {}-character expression, in the JSON", first_term.size());
               const std::string value =
                   r >= 0
                       ? fmt::format("{}: L_d - L_d^E = h^{} ({}) + O(h^{})", r, r + 1, term, r + 2)
                       : fmt::format(
                             "more than {}: every term of L_d - L_d^E through h^{} "
                             "vanishes",
                             var_k, var_k + 1);
               line("variational order",
                    value +
                        (var_judged ? fmt::format("; expected {:g}: {}", p.expected,
                                                  agrees_expected ? "yes" : "NO")
                                    : fmt::format("; expected {:g}: not judged (not an integer "
                                                  "up to {})",
                                                  p.expected, modified::max_order)) +
                        measured);
             })) {
  } else {
    failed_line("variational order");
  }
  js["variational_order"] = jvar;

  // --- 4. symplecticity and reversibility of the one-step map ---------------------------------
  std::vector<Eigen::VectorXd> states{z0};
  if (zref.size() == z0.size()) states.push_back(zref);
  // Judged by scaling at h, 2h, 4h, 8h, as on every route (vibook/verify/phases.hpp).
  json jsym, jsymm, jrev;
  if (run("symplecticity", [&] {
        where.start("symplecticity test", p.h);
        const auto sym = symplecticity_by_scaling(step, states, p.h);
        jsym = sym.to_json();
        jsym["relative_to"] = "max(1, |J|_max^2)";
        line("symplectic", fmt::format("defect |J^T W J - W| / max(1, |J|^2): {}: {}", sym.shown(),
                                       sym.passed ? "yes" : "NO"));
        line("", sym.why);
      })) {
  } else {
    failed_line("symplectic");
  }
  js["symplecticity"] = jsym;
  if (run("symmetry", [&] {
        where.start("symmetry test", p.h);
        const auto sy = symmetry_by_scaling(step, states, p.h);
        jsymm = sy.to_json();
        jsymm["required"] = p.symmetric;
        line("symmetric",
             fmt::format("defect |Phi_-h(Phi_h(z)) - z| / max(1, |z|): {}: {}{}", sy.shown(),
                         sy.passed ? "yes" : "NO",
                         p.symmetric ? ""
                                     : " (reported only; --symmetric makes it part of the "
                                       "verdict)"));
        line("", sy.why);
      })) {
  } else {
    failed_line("symmetric");
  }
  js["symmetry"] = jsymm;
  // Is the intended system itself reversible under (q, p) -> (q, -p)? (A magnetic one is not.)
  bool system_reversible = true;
  try {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> U(-0.5, 0.5);
    for (int s = 0; s < 4 && system_reversible; ++s) {
      Eigen::VectorXd q(n), w(n);
      for (int i = 0; i < n; ++i) q(i) = p.q0[i] + U(rng), w(i) = p.p0[i] + U(rng);
      double a, b;
      if (dl.has_hamiltonian()) {
        a = K.hamiltonian(q, w);
        b = K.hamiltonian(q, -w);
      } else {
        a = K.lagrangian(q, w);
        b = K.lagrangian(q, -w);
      }
      system_reversible = std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(a));
    }
  } catch (const std::exception&) {
    system_reversible = true;
  }
  if (run("reversibility", [&] {
        where.start("reversibility test", p.h);
        const auto rev = reversibility_by_scaling(step, states, p.h);
        jrev = rev.to_json();
        jrev["system_reversible"] = system_reversible;
        jrev["required"] = p.symmetric && system_reversible;
        line("time-reversible",
             fmt::format("defect |rho Phi_h rho Phi_h(z) - z| / max(1, |z|): {}: {}{}", rev.shown(),
                         rev.passed ? "yes" : "NO",
                         !system_reversible
                             ? " (the intended system is not reversible under (q, p) -> (q, -p): "
                               "not judged)"
                         : p.symmetric ? ""
                                       : " (reported only; --symmetric makes it part of the "
                                         "verdict)"));
        line("", rev.why);
      })) {
  } else {
    failed_line("time-reversible");
  }
  js["reversibility"] = jrev;

  // --- 5. energy of the intended system -------------------------------------------------------
  // H(q, p): typed, ½|p|² + V for the default system, else the Legendre transform of L (v
  // from dL/dv = p by Newton in double).
  const std::string energy_name = dl.has_hamiltonian()  ? "H as typed"
                                  : dl.default_system() ? "H = |p|^2/2 + V(q)"
                                                        : "H = p.v - L(q, v), the Legendre "
                                                          "transform of L";
  const std::function<double(const Eigen::VectorXd&)> energy = [&](const Eigen::VectorXd& z) {
    return K.energy(z);
  };
  EnergyBehaviour en;
  EnergyVerdict ev;
  json jen;
  // The energy scale the errors are relative to: |H0|, or the kinetic energy where H0 ≈ 0.
  auto energy_scale = [&] {
    return std::max({std::abs(energy(z0)), 0.5 * z0.tail(n).squaredNorm(), 1e-300});
  };
  if (run("energy", [&] {
        const double H0 = energy(z0);
        const double scale = energy_scale();
        where.start(fmt::format("energy run, h = {:g}", p.h), p.h);
        K.reset();
        en = energy_behaviour(stepper(true, true), energy, z0, p.h, p.steps);
        // the same span, shorter, at h and h/2: how the error scales with h
        const long long k1 = std::min<long long>(p.steps, 4096);
        where.start(fmt::format("energy scaling run, h = {:g}", p.h), p.h);
        K.reset();
        const auto e1 = energy_behaviour(stepper(true, false), energy, z0, p.h, k1);
        where.start(fmt::format("energy scaling run, h = {:g}", p.h / 2), p.h / 2);
        K.reset();
        const auto e2 = energy_behaviour(stepper(true, false), energy, z0, p.h / 2, 2 * k1);
        // the error's scaling with h from the short pair, applied to the long run's maximum
        const double h_exp = e1.max_error > 0 && e2.max_error > 0
                                 ? std::log2(e1.max_error / e2.max_error)
                                 : std::numeric_limits<double>::quiet_NaN();
        ev = judge_energy(en, scale, p.expected,
                          std::isfinite(h_exp) ? en.max_error / std::exp2(h_exp) : -1);
        jen = {{"energy", energy_name},
               {"steps", en.steps},
               {"h", en.h},
               {"H0", H0},
               {"scale", ev.scale},
               {"envelope_steps", en.envelope_steps},
               {"envelope", en.envelope},
               {"max_error", en.max_error},
               {"relative_error", ev.relative},
               {"exponent", en.exponent},
               {"roundoff_bound", ev.roundoff_bound},
               {"large_bound", ev.large_bound},
               {"h_exponent", std::isfinite(ev.h_exponent) ? json(ev.h_exponent) : json(nullptr)},
               {"verdict", ev.verdict},
               {"why", ev.why},
               {"newton_mean_iterations",
                newton.steps ? double(newton.iterations) / double(newton.steps) : 0.0},
               {"newton_max_iterations", newton.max_iterations},
               {"newton_max_residual", newton.max_residual},
               {"passed", ev.passed}};
        line("energy", fmt::format("{} steps of h = {:g}, {}: {} ({})", en.steps, en.h, energy_name,
                                   ev.verdict, ev.why));
        line("Newton",
             fmt::format("mean {:.2f}, max {} iterations per step; largest residual "
                         "{:.1e}",
                         newton.steps ? double(newton.iterations) / double(newton.steps) : 0.0,
                         newton.max_iterations, newton.max_residual));
      })) {
  } else {
    failed_line("energy");
  }
  js["energy"] = jen;

  // --- 5b. beyond Sharma: the typed L_d as an energy-preserving adaptive integrator ----------
  // Sharma et al. 2022, §2.2: the extended L_d(t0, q0, t1, q1) = L_d(q0, q1, t1 − t0), the
  // step from the energy condition (16) (verify/adaptive.hpp). Judged on the intended energy,
  // as the fixed-step run; a state where (16) has no admissible root ends the run, and the
  // scan there says whether it is a fold (a property of the method) or a missed root.
  json jada;
  AdaptiveStudy ada;
  EnergyVerdict ada_ev;
  if (p.adaptive_epavi && !have_ref) {
    phases.push_back(
        {"adaptive", "skipped", "no reference solution to take the first step from", kLdOk, 0});
    line("adaptive (EpAVI)", "not run: no reference solution to take the first step from");
  } else if (p.adaptive_epavi && !run("adaptive", [&] {
               const double scale = energy_scale();
               ada = K.epavi(z0, q_start[0], p.h, p.adaptive_steps);
               // how the error scales with the first step: h and h/2, over about the same span
               const long long k1 = std::min<long long>(p.adaptive_steps, 1024);
               const auto a1 = K.epavi(z0, q_start[0], p.h, k1);
               const auto a2 = K.epavi(z0, q_start[1], p.h / 2, 2 * k1);
               const double half =
                   a1.failure.happened || a2.failure.happened ? -1 : a2.energy.max_error;
               ada_ev = judge_energy(
                   ada.energy, scale, p.expected,
                   half > 0 ? ada.energy.max_error * half / std::max(a1.energy.max_error, 1e-300)
                            : -1);
               const auto& f = ada.failure;
               const bool passed = !f.happened && ada_ev.passed;
               jada = {{"method",
                        "EpAVI: extended L_d(t0, q0, t1, q1) = L_d(q0, q1, t1 - t0), "
                        "Sharma et al. 2022 (15)-(18)"},
                       {"h0", p.h},
                       {"steps_requested", p.adaptive_steps},
                       {"steps_taken", ada.steps_taken},
                       {"t_reached", ada.t_reached},
                       {"dt_min", ada.dt_min},
                       {"dt_max", ada.dt_max},
                       {"E1", ada.E1},
                       {"discrete_energy_drift", ada.discrete_energy_drift},
                       {"max_energy_residual", ada.max_energy_residual},
                       {"max_momentum_residual", ada.max_momentum_residual},
                       {"mean_root_evaluations", ada.mean_root_evaluations},
                       {"mean_newton_iterations", ada.mean_newton_iterations},
                       {"energy", energy_name},
                       {"envelope_steps", ada.energy.envelope_steps},
                       {"envelope", ada.energy.envelope},
                       {"max_error", ada.energy.max_error},
                       {"relative_error", ada_ev.relative},
                       {"exponent", std::isfinite(ada.energy.exponent) ? json(ada.energy.exponent)
                                                                       : json(nullptr)},
                       {"h_exponent",
                        std::isfinite(ada_ev.h_exponent) ? json(ada_ev.h_exponent) : json(nullptr)},
                       {"verdict", f.happened ? "no admissible step" : ada_ev.verdict},
                       {"why", ada_ev.why},
                       {"passed", passed}};
               if (f.happened)
                 jada["no_admissible_step"] = {{"step", f.step},
                                               {"t", f.t},
                                               {"message", f.message},
                                               {"scan_dt", {f.scan_lo, f.scan_hi}},
                                               {"scan_points", f.scan_points},
                                               {"sign_changes", f.sign_changes},
                                               {"far_sign_changes", f.far_sign_changes},
                                               {"min_abs_residual", f.scan_min_abs},
                                               {"at_dt", f.scan_min_dt}};
               line("adaptive (EpAVI)",
                    fmt::format("{} of {} steps from h0 = {:g} (the first to the reference's "
                                "q(h0)), t reached {:.6g}, steps in [{:.3g}, {:.3g}]",
                                ada.steps_taken, p.adaptive_steps, p.h, ada.t_reached, ada.dt_min,
                                ada.dt_max));
               if (f.happened)
                 line("",
                      fmt::format("NO ADMISSIBLE STEP at step {}, t = {:.6g}: the energy "
                                  "equation (16) D1 L_d - E_k, scanned over dt in [{:.3g}, "
                                  "{:.3g}] ({} points), has no sign change (min |D1 L_d - E_k| "
                                  "= {:.3g} at dt = {:.3g}): its root has disappeared (a fold), "
                                  "as for EpAVI on Kepler orbits in the EpAVI chapter{}",
                                  f.step, f.t, f.scan_lo, f.scan_hi, f.scan_points, f.scan_min_abs,
                                  f.scan_min_dt,
                                  f.far_sign_changes > 0
                                      ? fmt::format("; a root near dt = {:.3g}, beyond the "
                                                    "factor 64 the step searches, is not the "
                                                    "motion's",
                                                    f.far_root)
                                      : std::string()));
               line("", fmt::format("{}: {} ({}); discrete energy E_k kept to {:.1e} (E_1 = "
                                    "{:.10g}); mean {:.1f} energy-equation evaluations a step",
                                    energy_name,
                                    f.happened ? "up to there, " + ada_ev.verdict : ada_ev.verdict,
                                    ada_ev.why, ada.discrete_energy_drift, ada.E1,
                                    ada.mean_root_evaluations));
             }))
    failed_line("adaptive (EpAVI)");
  if (p.adaptive_epavi) js["adaptive"] = jada;

  // --- 6. work-precision beside two classical methods (report only) ---------------------------
  WorkPrecision wp;
  bool have_wp = false;
  if (p.work_precision && have_ref && !dl.has_hamiltonian()) {
    have_wp = run("work-precision", [&] {
      std::vector<NamedStep> methods{{"typed", step}};
      for (auto& m : K.classical_steppers()) methods.push_back(std::move(m));
      const std::vector<double> hs = p.hs.empty() ? kWorkPrecisionSteps : p.hs;
      where.start("work-precision runs", hs[0]);
      wp = work_precision(methods, z0, p.t_end, zref, hs);
    });
    if (!have_wp) failed_line("work-precision");
  }

  // --- 7. the engine: modified equation, Lagrangian, Hamiltonian ------------------------------
  std::vector<std::vector<std::string>> terms;
  std::vector<std::string> lagrangian, hamiltonian;
  std::string lagrangian_error, hamiltonian_error;
  if (n > 3) {
    phases.push_back(
        {"modified", "skipped", "the symbolic engine is run for at most 3 dimensions", kLdOk, 0});
    line("modified equation", "not derived: the symbolic engine is run for at most 3 dimensions");
  } else if (unscaled) {
    const std::string why = "L_d is not of the size h·L (see consistency): no modified equation";
    phases.push_back({"modified", "skipped", why, kLdOk, 0});
    line("modified equation", "not derived: " + why);
  } else if (run("modified", [&] {
               std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
               auto jets = std::make_shared<modified::JetSpace>(n);
               modified::Engine engine(K.symbolic(jets), p.modified_order);
               const auto& f = engine.modified_equation();
               for (std::size_t k = 0; k < f.size(); ++k) {
                 terms.emplace_back();
                 for (int i = 0; i < n; ++i)
                   terms.back().push_back(modified::canonical_string(f[k][i], p.format));
               }
               try {
                 for (const auto& l : engine.l_mod())
                   lagrangian.push_back(modified::canonical_string(l, p.format));
               } catch (const std::exception& e) {
                 lagrangian_error = e.what();  // e.g. a Lagrangian that is not regular
               }
               if (lagrangian_error.empty()) {
                 try {
                   for (const auto& hk : engine.h_mod())
                     hamiltonian.push_back(modified::canonical_string(hk, p.format));
                 } catch (const std::exception& e) {
                   hamiltonian_error = e.what();
                 }
               } else {
                 hamiltonian_error = "needs the modified Lagrangian";
               }
             })) {
    out << "modified equation    x'' = sum_k h^k f_k:\n";
    for (std::size_t k = 0; k < terms.size(); ++k)
      for (int i = 0; i < n; ++i) out << fmt::format("  f_{}[{}] = {}\n", k, i + 1, terms[k][i]);
    out << "modified Lagrangian  L_mod = sum_k h^k L_k:\n";
    if (!lagrangian_error.empty()) out << "  not derived: " << lagrangian_error << '\n';
    for (std::size_t k = 0; k < lagrangian.size(); ++k)
      out << fmt::format("  L_{} = {}\n", k, lagrangian[k]);
    out << "modified Hamiltonian H_mod = sum_k h^k H_k:\n";
    if (!hamiltonian_error.empty()) out << "  not derived: " << hamiltonian_error << '\n';
    for (std::size_t k = 0; k < hamiltonian.size(); ++k)
      out << fmt::format("  H_{} = {}\n", k, hamiltonian[k]);
  } else {
    failed_line("modified equation");
  }
  js["modified_equation"] = terms;
  js["modified_lagrangian"] = lagrangian;
  js["modified_hamiltonian"] = hamiltonian;
  if (!lagrangian_error.empty()) js["modified_lagrangian_error"] = lagrangian_error;
  if (!hamiltonian_error.empty()) js["modified_hamiltonian_error"] = hamiltonian_error;

  // --- the verdicts, and every phase's status ---------------------------------------------------
  json jph = json::array();
  // The exit status: a bad argument found late (2), an output not written (4), a numerical
  // failure (3), then the verdicts (5, below), then any other failure (1).
  auto rank = [](int e) {
    return e == kLdBadArgument ? 5
           : e == kLdIo        ? 4
           : e == kLdNumerical ? 3
           : e == kLdFailure   ? 1
                               : 0;
  };
  int rc = kLdOk;
  for (const auto& ph : phases) {
    json e = {{"phase", ph.name}, {"status", ph.status}};
    if (!ph.reason.empty()) e["reason"] = ph.reason;
    jph.push_back(e);
    if (ph.status == "failed" && rank(ph.exit) > rank(rc)) rc = ph.exit;
  }
  js["phases"] = jph;
  // The verdict: consistency with the intended system, the order against the independent
  // reference, symplecticity and the energy, each as measured above (reversibility only when
  // the method is declared symmetric and the intended system is reversible).
  std::vector<std::pair<std::string, const json*>> required = {
      {"consistency", &jcons}, {"order", &jorder}, {"symplecticity", &jsym}, {"energy", &jen}};
  if (p.symmetric) required.emplace_back("symmetry", &jsymm);
  if (p.symmetric && system_reversible) required.emplace_back("reversibility", &jrev);
  // The variational order, when the engine derived it and the expected order is an integer.
  if (jvar.contains("passed")) required.emplace_back("variational order", &jvar);
  if (p.adaptive_epavi) required.emplace_back("adaptive", &jada);
  std::vector<std::string> required_names, failed_checks;
  for (const auto& [name, j] : required) {
    required_names.push_back(name);
    if (!j->is_object() || !j->value("passed", false)) failed_checks.push_back(name);
  }
  js["verdict"] = {
      {"passed", failed_checks.empty()}, {"failed", failed_checks}, {"required", required_names}};
  line("verdict",
       fmt::format("{} ({})", failed_checks.empty() ? "PASS" : "FAIL",
                   fmt::join(failed_checks.empty() ? required_names : failed_checks, ", ")));
  // A failed verdict outranks a symbolic part that failed (status 1); a numerical failure (3)
  // outranks both, since a verdict after it was not measured.
  if ((rc == kLdOk || rc == kLdFailure) && !failed_checks.empty()) rc = kLdVerdict;
  if (p.timings) {
    out << "timings             ";
    for (const auto& ph : phases) out << fmt::format(" {} {:.2f} s;", ph.name, ph.seconds);
    out << '\n';
  }
  // One line for stderr when it did not pass: the first part that failed, or the verdicts.
  for (const auto& ph : phases)
    if (ph.status == "failed" && ph.exit == rc) {
      std::string reason = ph.reason;
      std::replace(reason.begin(), reason.end(), '\n', ' ');
      study.error_line = fmt::format("vibook: error: verify: {}: {}\n", ph.name, reason);
      break;
    }
  if (rc == kLdVerdict)
    study.error_line = fmt::format("vibook: verify: FAIL ({}); the report above says why\n",
                                   fmt::join(failed_checks, ", "));
  study.text = out.str();
  study.status = rc;
  study.failed_checks = failed_checks;
  study.js = std::move(js);
  study.order_error = order_err;
  study.order_h = order_h;
  study.fit = fit;
  study.order_passed = order_passed;
  study.ref_error = ref_error;
  study.consistent = consistent;
  study.system_reversible = system_reversible;
  study.var_k = var_k;
  study.energy = en;
  study.energy_verdict = ev;
  study.adaptive = ada;
  study.adaptive_verdict = ada_ev;
  study.newton_steps = newton.steps;
  study.newton_iterations = newton.iterations;
  study.newton_max_iterations = newton.max_iterations;
  study.newton_max_residual = newton.max_residual;
  study.have_work_precision = have_wp;
  study.wp = wp;
  study.modified_terms = terms;
  study.modified_lagrangian = lagrangian;
  study.modified_hamiltonian = hamiltonian;
  study.lagrangian_error = lagrangian_error;
  study.hamiltonian_error = hamiltonian_error;
  return study;
}

}  // namespace vibook::verify
