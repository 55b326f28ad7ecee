// The verification of a typed discrete Lagrangian (`vibook verify --ld`): consistency of its
// leading term, order against an independent reference (the continuous equations by GBS
// extrapolation in double-double), symplecticity, reversibility, the energy of the intended
// system judged by magnitude and trend, and the modified equation, Lagrangian and Hamiltonian
// from the engine. Included only by the generated verify_typed_N.cpp, one per dimension.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <nlohmann/json.hpp>

#include "args.hpp"
#include "cli.hpp"
#include "verify_composition.hpp"
#include "verify_map.hpp"
#include "verify_method.hpp"
#include "verify_stepper.hpp"
#include "verify_typed.hpp"
#include "vibook/core/output_file.hpp"
#include "vibook/core/precision.hpp"
#include "vibook/core/progress.hpp"
#include "vibook/mechanics/del_solver.hpp"
#include "vibook/mechanics/discrete_lagrangian.hpp"
#include "vibook/modified/canonical.hpp"
#include "vibook/modified/engine.hpp"
#include "vibook/modified/series.hpp"
#include "vibook/plot/gnuplot.hpp"
#include "vibook/verify/adaptive.hpp"
#include "vibook/verify/expression.hpp"
#include "vibook/verify/phases.hpp"
#include "vibook/verify/reference.hpp"
#include "vibook/verify/tape.hpp"
#include "vibook/verify/verify.hpp"
#include "vibook_book_stylesheet.hpp"
#include "watchdog.hpp"

namespace vibook::cli {

using nlohmann::json;

inline std::string html_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

inline std::string vec_text(const Eigen::VectorXd& v) {
  std::vector<std::string> s;
  for (Eigen::Index i = 0; i < v.size(); ++i) s.push_back(fmt::format("{:.6g}", v(i)));
  return "(" + fmt::format("{}", fmt::join(s, ", ")) + ")";
}

// One part of the verification: its status and, when it failed, why.
struct Phase {
  std::string name;
  std::string status = "not run";  // "ok", "failed", "skipped", "not run"
  std::string reason;
  int exit = kOk;  // the exit status its failure asks for
  double seconds = 0;
};

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

template <int N>
int run_verify(const VerifyOptions& o, const verify::TypedDiscreteLagrangian& dl, const Plan& p) {
  using Clock = std::chrono::steady_clock;
  const auto Ld = dl.bind<N>();
  // The method is stepped through the compiled tape (verify/tape.hpp: D1 L_d, D2 L_d and
  // D2 D1 L_d as straight-line code), or with --reference through nested AutoDiff on the
  // expression tree, the path the tape is checked against.
  DelIntegrator<N, decltype(Ld)> vi_tree(Ld);
  std::optional<DelIntegrator<N, verify::CompiledDiscreteLagrangian<N>>> vi_tape;
  if (!o.reference) {
    std::lock_guard<std::mutex> lock(modified::ginac_mutex());
    vi_tape.emplace(verify::CompiledDiscreteLagrangian<N>(dl));
  }
  struct {
    decltype(vi_tree)& tree;
    decltype(vi_tape)& tape;
    SolveReport step(Vec<double, N>& q, Vec<double, N>& p, double h) {
      return tape ? tape->step(q, p, h) : tree.step(q, p, h);
    }
    void reset() {
      tree.reset();
      if (tape) tape->reset();
    }
  } vi{vi_tree, vi_tape};
  std::string evaluation = "nested forward AutoDiff on the expression tree (--reference)";
  if (vi_tape) {
    const auto& c = vi_tape->lagrangian();
    const auto st = c.stats();
    evaluation = fmt::format(
        "compiled tape, {}: {} instructions per Newton iteration and {} once a step{}, {} for "
        "the momentum{} (--reference: nested AutoDiff)",
        c.native() ? std::string("run as native code")
                   : "interpreted (no native code: " + c.native_reason() + ")",
        st.newton_instructions - st.newton_prefix, st.newton_prefix,
        st.carried > 0 ? fmt::format(" ({} with the {} values the last momentum carries over)",
                                     st.newton_prefix_carried, st.carried)
                       : std::string(),
        st.momentum_instructions,
        c.jacobian_constant() ? "; D2 D1 L_d is free of q1, so Newton factors its matrix once"
                              : "");
  }
  Eigen::VectorXd z0(2 * N);
  for (int i = 0; i < N; ++i) {
    z0(i) = p.q0[i];
    z0(N + i) = p.p0[i];
  }
  std::vector<Phase> phases;
  json js;
  js["input"] = {{"ld", o.ld},
                 {"potential", o.potential},
                 {"lagrangian", o.lagrangian},
                 {"hamiltonian", o.hamiltonian},
                 {"intended", dl.has_hamiltonian()  ? "hamiltonian"
                              : dl.default_system() ? "L = |v|^2/2 - V(q)"
                                                    : "lagrangian"},
                 {"dim", N},
                 {"evaluation", !vi_tape                         ? "autodiff"
                                : vi_tape->lagrangian().native() ? "native"
                                                                 : "tape"},
                 {"q0", p.q0},
                 {"p0", p.p0}};
  std::ostringstream out;  // the text report, printed at the end whatever happened
  auto line = [&](const std::string& label, const std::string& text) {
    out << fmt::format("{:<21}{}\n", label, text);
  };
  // Run one part: a failure is recorded with its reason and exit status, never thrown on.
  auto run = [&](const std::string& name, auto&& body) {
    Phase ph;
    ph.name = name;
    progress::set_stage(name);
    const auto t0 = Clock::now();
    try {
      body();
      ph.status = "ok";
    } catch (const NumericalError& e) {
      ph.status = "failed";
      ph.reason = e.what();
      ph.exit = kNumerical;
    } catch (const ArgumentError& e) {
      ph.status = "failed";
      ph.reason = e.what();
      ph.exit = kBadArgument;
    } catch (const std::exception& e) {
      ph.status = "failed";
      ph.reason = e.what();
      ph.exit = kFailure;
    }
    ph.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    phases.push_back(ph);
    return ph.status == "ok";
  };
  auto failed_line = [&](const std::string& label) {
    const Phase& ph = phases.back();
    line(label, "FAILED (" + std::string(ph.exit == kNumerical ? "numerical" : "error") +
                    "): " + ph.reason);
  };

  out << fmt::format("{:<21}{}\n", "discrete Lagrangian", o.ld);
  if (dl.has_hamiltonian())
    line("intended system", "H = " + o.hamiltonian);
  else if (!dl.default_system())
    line("intended system", "L = " + o.lagrangian);
  else
    line("intended system",
         "L = v^2/2 - V(q) (the default; --lagrangian or --hamiltonian to change)");
  line("potential", (o.potential.empty() ? std::string("(none)") : o.potential) +
                        fmt::format("   ({}-dimensional)", N));
  line("evaluation", evaluation);

  // --- the stability hint: the largest frequency of V at q0 (unit mass) ---------------------
  double omega = 0;
  if (dl.has_potential()) {
    try {
      Vec<double, N> q;
      for (int i = 0; i < N; ++i) q(i) = p.q0[i];
      double value = 0;
      Vec<double, N> g;
      Mat<double, N> H;
      verify::value_gradient_hessian<N, double>([&](const auto& x) { return dl.potential<N>(x); },
                                                q, value, g, H);
      // (1 x 1 directly: GCC 12 warns, falsely, of bounds in the copy of a 1 x 1 matrix)
      double lmax = H(0, 0);
      if constexpr (N > 1) lmax = largest_symmetric_eigenvalue(H);
      omega = lmax > 0 ? std::sqrt(lmax) : 0;
    } catch (const std::exception&) {
      omega = 0;
    }
  }
  auto hint = [&](double h) -> std::string {
    if (omega * h > 2)
      return fmt::format(
          " The largest frequency of V at q0 is ω = {:.4g} (unit mass): ωh = {:.3g} exceeds 2, "
          "the stability limit of explicit two-step methods such as Störmer–Verlet.",
          omega, omega * h);
    return {};
  };

  // Why an order may not show: the step sizes do not resolve the fastest frequency at q0.
  auto resolution_hint = [&](bool passed) -> std::string {
    const double hmax = *std::max_element(p.hs.begin(), p.hs.end());
    const double hmin = *std::min_element(p.hs.begin(), p.hs.end());
    if (passed || !(omega * hmax > 1)) return {};
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
  auto stepper = [&](bool warm, bool count) -> verify::Step {
    return [&, warm, count](Eigen::VectorXd& z, double h) {
      if (!warm) vi.reset();
      Vec<double, N> q = z.head<N>(), pk = z.tail<N>();
      try {
        const SolveReport rep = vi.step(q, pk, h);
        if (count) {
          ++newton.steps;
          newton.iterations += rep.iterations;
          newton.max_iterations = std::max(newton.max_iterations, rep.iterations);
          newton.max_residual = std::max(newton.max_residual, rep.residual);
        }
      } catch (const NumericalError& e) {
        Eigen::VectorXd zz = z;
        throw NumericalError(
            fmt::format("{}: step {} at t = {:.6g} from q = {}, p = {}, h = {:g}: {}.{}",
                        where.phase, where.step + 1, where.t, vec_text(zz.head(N)),
                        vec_text(zz.tail(N)), h, e.what(), hint(h)));
      }
      z.head<N>() = q;
      z.tail<N>() = pk;
      ++where.step;
      where.t += h;
    };
  };
  const verify::Step step = stepper(false, false);

  // --- 0. regularity: D1 D2 L_d invertible at the first step, or the discrete Euler–Lagrange
  // equations cannot be solved for q1 (every numerical part below then fails; exit 3).
  json jreg;
  if (!run("regularity", [&] {
        Vec<double, N> qa, qb;
        for (int i = 0; i < N; ++i) {
          qa(i) = p.q0[i];
          qb(i) = p.q0[i] + p.h * p.p0[i];
        }
        const auto d = ad::two_point<N>(Ld, qa, qb, p.h);
        const double det = d.D12.determinant();
        const double scale = std::pow(d.D12.cwiseAbs().maxCoeff(), N);
        jreg = {{"det_D1D2", std::isfinite(det) ? json(det) : json(nullptr)}, {"h", p.h}};
        // Not finite is not degenerate: say which value failed, and where.
        const auto where = [&] {
          return fmt::format("q0 = q(0) = {}, q1 = q(0) + h p(0) = {}, h = {:g}", vec_text(qa),
                             vec_text(qb), p.h);
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
    std::lock_guard<std::mutex> lock(modified::ginac_mutex());
    std::vector<GiNaC::symbol> x, v;
    Vec<modified::ex, N> X, Xh, Vv;
    const GiNaC::symbol h("h");
    for (int i = 0; i < N; ++i) {
      x.emplace_back(N == 1 ? "x" : "x" + std::to_string(i + 1));
      v.emplace_back(N == 1 ? "v" : "v" + std::to_string(i + 1));
      X(i) = x.back();
      Vv(i) = v.back();
      Xh(i) = x.back() + h * v.back();
    }
    const modified::ex ld = dl.evaluate<N, modified::ex>(X, Xh, modified::ex(h)) / h;
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
      const modified::ex L = dl.lagrangian<N, modified::ex>(X, Vv);
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
        Vec<double, 2 * N> y;
        for (int i = 0; i < N; ++i) {
          y(i) = p.q0[i] + (s ? U(rng) : 0.0);
          y(N + i) = p.p0[i] + (s ? U(rng) : 0.0);
        }
        double Hv = 0;
        Vec<double, 2 * N> g;
        Mat<double, 2 * N> Hm;
        verify::value_gradient_hessian<2 * N, double>(
            [&](const auto& w) {
              using S = scalar_t<decltype(w)>;
              Vec<S, N> q = w.template head<N>(), pp = w.template tail<N>();
              return dl.hamiltonian<N, S>(q, pp);
            },
            y, Hv, g, Hm);
        GiNaC::exmap m;
        double pv = 0;
        for (int i = 0; i < N; ++i) {
          m[x[i]] = y(i);
          m[v[i]] = g(N + i);
          pv += y(N + i) * g(N + i);
        }
        auto num = [&](const modified::ex& e) {
          return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(m))).to_double();
        };
        const double lhs = num(L0), rhs = pv - Hv;
        double dev = std::abs(lhs - rhs) / std::max(1.0, std::abs(rhs));
        for (int i = 0; i < N; ++i)
          dev = std::max(
              dev, std::abs(num(L0.diff(v[i])) - y(N + i)) / std::max(1.0, std::abs(y(N + i))));
        if (dev > worst) {
          worst = dev;
          at = fmt::format("at q = {}, p = {}: L0(q, dH/dp) = {:.6g}, p·v − H = {:.6g}",
                           vec_text(y.head(N)), vec_text(y.tail(N)), lhs, rhs);
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
  std::array<Vec<double, N>, 2> q_start;
  const bool have_ref = run("reference", [&] {
    using T = dd_real;
    verify::Field<T> f;
    std::vector<T> y0(2 * N);
    auto starts = [&] {
      if (!p.adaptive_epavi) return;
      for (int j = 0; j < 2; ++j) {
        const auto r = verify::reference_solution<T>(f, y0, j == 0 ? p.h : p.h / 2);
        for (int i = 0; i < N; ++i) q_start[j](i) = to_double(r.y[static_cast<std::size_t>(i)]);
      }
    };
    if (dl.has_hamiltonian()) {
      f = typed_hamilton_field<N>(dl);
      for (int i = 0; i < N; ++i) {
        y0[static_cast<std::size_t>(i)] = T(p.q0[i]);
        y0[static_cast<std::size_t>(N + i)] = T(p.p0[i]);
      }
    } else {
      auto derivatives = [&](const Vec<T, N>& q, const Vec<T, N>& v, Vec<T, 2 * N>& g,
                             Mat<T, 2 * N>& H) {
        Vec<T, 2 * N> w;
        w << q, v;
        T value;
        lagrangian_derivatives<N, T>(dl, w, value, g, H);
      };
      f = [&](const std::vector<T>& y) {
        Vec<T, N> q, v;
        for (int i = 0; i < N; ++i) {
          q(i) = y[static_cast<std::size_t>(i)];
          v(i) = y[static_cast<std::size_t>(N + i)];
        }
        Vec<T, 2 * N> g;
        Mat<T, 2 * N> H;
        derivatives(q, v, g, H);
        const Vec<T, N> a = euler_lagrange_acceleration<N, T>(g, H, v);
        std::vector<T> r(2 * N);
        for (int i = 0; i < N; ++i) {
          r[static_cast<std::size_t>(i)] = v(i);
          r[static_cast<std::size_t>(N + i)] = a(i);
        }
        return r;
      };
      // the initial velocity: dL/dv(q0, v) = p0, by Newton from v = p0
      Vec<T, N> q, v;
      for (int i = 0; i < N; ++i) {
        q(i) = T(p.q0[i]);
        v(i) = T(p.p0[i]);
      }
      bool done = false;
      for (int it = 0; it < 60 && !done; ++it) {
        Vec<T, 2 * N> g;
        Mat<T, 2 * N> H;
        derivatives(q, v, g, H);
        Vec<T, N> F;
        for (int i = 0; i < N; ++i) F(i) = g(N + i) - T(p.p0[i]);
        const Mat<T, N> M = H.template bottomRightCorner<N, N>();
        const Vec<T, N> dv = M.partialPivLu().solve(F);
        v -= dv;
        double nd = 0, nv = 1;
        for (int i = 0; i < N; ++i) {
          nd = std::max(nd, std::abs(to_double(dv(i))));
          nv = std::max(nv, std::abs(to_double(v(i))));
        }
        if (!std::isfinite(nd)) break;
        done = nd <= 1e-28 * nv;
      }
      if (!done)
        throw NumericalError(fmt::format(
            "the Legendre map dL/dv(q0, v) = p0 has no solution near v = p0 (q0 = {}, p0 = {}): "
            "the intended Lagrangian is not regular there",
            fmt::join(p.q0, ", "), fmt::join(p.p0, ", ")));
      for (int i = 0; i < N; ++i) {
        y0[static_cast<std::size_t>(i)] = q(i);
        y0[static_cast<std::size_t>(N + i)] = v(i);
      }
      // the state at T in (q, p): p = dL/dv at the end
      const auto r = verify::reference_solution<T>(f, y0, p.t_end);
      Vec<T, N> qe, ve;
      for (int i = 0; i < N; ++i) {
        qe(i) = r.y[static_cast<std::size_t>(i)];
        ve(i) = r.y[static_cast<std::size_t>(N + i)];
      }
      Vec<T, 2 * N> g;
      Mat<T, 2 * N> H;
      derivatives(qe, ve, g, H);
      zref.resize(2 * N);
      for (int i = 0; i < N; ++i) {
        zref(i) = to_double(qe(i));
        zref(N + i) = to_double(g(N + i));
      }
      ref_error = r.error;
      jref["macro_steps"] = r.macro_steps;
      jref["evaluations"] = r.evaluations;
      starts();
      f = nullptr;
    }
    if (dl.has_hamiltonian()) {
      const auto r = verify::reference_solution<T>(f, y0, p.t_end);
      zref.resize(2 * N);
      for (int i = 0; i < 2 * N; ++i) zref(i) = to_double(r.y[static_cast<std::size_t>(i)]);
      ref_error = r.error;
      jref["macro_steps"] = r.macro_steps;
      jref["evaluations"] = r.evaluations;
      starts();
    }
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

  // --- 3. order against the reference -------------------------------------------------------
  std::vector<double> order_err;
  verify::PlateauFit fit;
  bool order_passed = false;
  json jorder;
  if (!have_ref) {
    phases.push_back({"order", "skipped", "no reference solution", kOk, 0});
    line("order", "not measured: no reference solution");
  } else if (run("order", [&] {
               for (double h : p.hs) {
                 where.start(fmt::format("order study at h = {:g}", h), h);
                 const Eigen::VectorXd z = verify::integrate(step, z0, h, p.t_end);
                 order_err.push_back((z - zref).lpNorm<Eigen::Infinity>());
               }
               const double scale = std::max(1.0, zref.lpNorm<Eigen::Infinity>());
               const double floor =
                   p.floor ? *p.floor
                           : std::max(10 * ref_error,
                                      16 * std::numeric_limits<double>::epsilon() * scale);
               fit = verify::fit_order_plateau(p.hs, order_err, floor);
               order_passed =
                   std::isfinite(fit.slope) && std::abs(fit.slope - p.expected) < p.order_tol;
               std::vector<bool> used = fit.used;
               jorder = {{"h", p.hs},
                         {"error", order_err},
                         {"used_in_fit", used},
                         {"fitted", std::isfinite(fit.slope) ? json(fit.slope) : json(nullptr)},
                         {"points", fit.points},
                         {"floor", fit.floor},
                         {"floor_from", p.floor ? "--floor" : "max(10 x reference error, 16 u)"},
                         {"plateau_points_left_out", fit.plateau},
                         {"expected", p.expected},
                         {"tolerance", p.order_tol},
                         {"T", p.t_end},
                         {"reference", "independent (continuous equations)"},
                         {"passed", order_passed}};
               const std::string what =
                   std::isfinite(fit.slope)
                       ? fmt::format("{:.3f} over {} step sizes at T = {:g}", fit.slope, fit.points,
                                     p.t_end)
                       : fmt::format("not measured: {} of {} errors lie above the floor {:.1e}",
                                     fit.points, p.hs.size(), fit.floor);
               line("order",
                    fmt::format("{} against the reference (floor {:.1e}{}); expected {:g} "
                                "(|p - {:g}| < {:g}): {}",
                                what, fit.floor,
                                fit.plateau
                                    ? fmt::format(", {} plateau points left out", fit.plateau)
                                    : std::string(),
                                p.expected, p.expected, p.order_tol, order_passed ? "yes" : "NO") +
                        resolution_hint(order_passed));
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
  if (N > 3) {
    phases.push_back({"variational order", "skipped",
                      "the symbolic engine is run for at most 3 dimensions", kOk, 0});
    line("variational order", "not derived: the symbolic engine is run for at most 3 dimensions");
  } else if (unscaled) {
    // Not an error of the run: the verdict on consistency (above) says why, status 5.
    const std::string why =
        "L_d is not of the size h·L (see consistency), so L_d - L_d^E has "
        "no expansion in powers of h";
    phases.push_back({"variational order", "skipped", why, kOk, 0});
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
                 std::lock_guard<std::mutex> lock(modified::ginac_mutex());
                 auto jets = std::make_shared<modified::JetSpace>(N);
                 modified::Engine engine(
                     modified::symbolic_dl<N>(Ld, jets, "typed discrete Lagrangian"), var_k);
                 modified::ex L;
                 if (dl.has_hamiltonian()) {
                   // The Lagrangian of H: the leading term of L_d/h, which the consistency part
                   // has checked to be H's Legendre transform.
                   L = engine.l_disc().at(0);
                   jvar["lagrangian_from"] = "the leading term of h^-1 L_d, checked against H";
                 } else {
                   Vec<modified::ex, N> X, V;
                   for (int i = 0; i < N; ++i) {
                     X(i) = jets->x(0, i);
                     V(i) = jets->x(1, i);
                   }
                   L = dl.lagrangian<N, modified::ex>(X, V);
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
        const auto sym = verify::symplecticity_by_scaling(step, states, p.h);
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
        const auto sy = verify::symmetry_by_scaling(step, states, p.h);
        jsymm = sy.to_json();
        jsymm["required"] = o.symmetric;
        line("symmetric",
             fmt::format("defect |Phi_-h(Phi_h(z)) - z| / max(1, |z|): {}: {}{}", sy.shown(),
                         sy.passed ? "yes" : "NO",
                         o.symmetric ? ""
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
      Vec<double, N> q, w;
      for (int i = 0; i < N; ++i) q(i) = p.q0[i] + U(rng), w(i) = p.p0[i] + U(rng);
      double a, b;
      if (dl.has_hamiltonian()) {
        a = dl.hamiltonian<N, double>(q, w);
        b = dl.hamiltonian<N, double>(q, Vec<double, N>(-w));
      } else {
        a = dl.lagrangian<N, double>(q, w);
        b = dl.lagrangian<N, double>(q, Vec<double, N>(-w));
      }
      system_reversible = std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(a));
    }
  } catch (const std::exception&) {
    system_reversible = true;
  }
  if (run("reversibility", [&] {
        where.start("reversibility test", p.h);
        const auto rev = verify::reversibility_by_scaling(step, states, p.h);
        jrev = rev.to_json();
        jrev["system_reversible"] = system_reversible;
        jrev["required"] = o.symmetric && system_reversible;
        line("time-reversible",
             fmt::format("defect |rho Phi_h rho Phi_h(z) - z| / max(1, |z|): {}: {}{}", rev.shown(),
                         rev.passed ? "yes" : "NO",
                         !system_reversible
                             ? " (the intended system is not reversible under (q, p) -> (q, -p): "
                               "not judged)"
                         : o.symmetric ? ""
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
  std::function<double(const Eigen::VectorXd&)> energy;
  std::string energy_name;
  if (dl.has_hamiltonian()) {
    energy_name = "H as typed";
    energy = [&](const Eigen::VectorXd& z) {
      return dl.hamiltonian<N, double>(Vec<double, N>(z.head<N>()), Vec<double, N>(z.tail<N>()));
    };
  } else if (dl.default_system()) {
    energy_name = "H = |p|^2/2 + V(q)";
    energy = [&](const Eigen::VectorXd& z) {
      return 0.5 * z.tail<N>().squaredNorm() + dl.potential<N, double>(Vec<double, N>(z.head<N>()));
    };
  } else {
    energy_name = "H = p.v - L(q, v), the Legendre transform of L";
    energy = [&](const Eigen::VectorXd& z) {
      const Vec<double, N> q = z.head<N>(), pk = z.tail<N>();
      Vec<double, N> v = pk;
      for (int it = 0; it < 50; ++it) {
        double value;
        Vec<double, N> g;
        Mat<double, N> H;
        verify::value_gradient_hessian<N, double>(
            [&](const auto& w) {
              using S = scalar_t<decltype(w)>;
              return dl.lagrangian<N, S>(q.template cast<S>(), w);
            },
            v, value, g, H);
        const Vec<double, N> dv = H.partialPivLu().solve(Vec<double, N>(g - pk));
        v -= dv;
        if (dv.template lpNorm<Eigen::Infinity>() <=
            1e-15 * std::max(1.0, v.template lpNorm<Eigen::Infinity>()))
          return pk.dot(v) - dl.lagrangian<N, double>(q, v);
        if (!dv.allFinite()) break;
      }
      throw NumericalError("energy: the Legendre map dL/dv(q, v) = p has no solution at q = " +
                           vec_text(q) + ", p = " + vec_text(pk));
    };
  }
  verify::EnergyBehaviour en;
  verify::EnergyVerdict ev;
  json jen;
  // The energy scale the errors are relative to: |H0|, or the kinetic energy where H0 ≈ 0.
  auto energy_scale = [&] {
    return std::max({std::abs(energy(z0)), 0.5 * z0.tail(N).squaredNorm(), 1e-300});
  };
  if (run("energy", [&] {
        const double H0 = energy(z0);
        const double scale = energy_scale();
        where.start(fmt::format("energy run, h = {:g}", p.h), p.h);
        vi.reset();
        en = verify::energy_behaviour(stepper(true, true), energy, z0, p.h, p.steps);
        // the same span, shorter, at h and h/2: how the error scales with h
        const long long k1 = std::min<long long>(p.steps, 4096);
        where.start(fmt::format("energy scaling run, h = {:g}", p.h), p.h);
        vi.reset();
        const auto e1 = verify::energy_behaviour(stepper(true, false), energy, z0, p.h, k1);
        where.start(fmt::format("energy scaling run, h = {:g}", p.h / 2), p.h / 2);
        vi.reset();
        const auto e2 = verify::energy_behaviour(stepper(true, false), energy, z0, p.h / 2, 2 * k1);
        // the error's scaling with h from the short pair, applied to the long run's maximum
        const double h_exp = e1.max_error > 0 && e2.max_error > 0
                                 ? std::log2(e1.max_error / e2.max_error)
                                 : std::numeric_limits<double>::quiet_NaN();
        ev = verify::judge_energy(en, scale, p.expected,
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
  verify::AdaptiveStudy ada;
  verify::EnergyVerdict ada_ev;
  if (p.adaptive_epavi && !have_ref) {
    phases.push_back(
        {"adaptive", "skipped", "no reference solution to take the first step from", kOk, 0});
    line("adaptive (EpAVI)", "not run: no reference solution to take the first step from");
  } else if (p.adaptive_epavi && !run("adaptive", [&] {
               const double scale = energy_scale();
               ada = verify::epavi_study<N>(Ld, energy, z0, q_start[0], p.h, p.adaptive_steps);
               // how the error scales with the first step: h and h/2, over about the same span
               const long long k1 = std::min<long long>(p.adaptive_steps, 1024);
               const auto a1 = verify::epavi_study<N>(Ld, energy, z0, q_start[0], p.h, k1);
               const auto a2 = verify::epavi_study<N>(Ld, energy, z0, q_start[1], p.h / 2, 2 * k1);
               const double half =
                   a1.failure.happened || a2.failure.happened ? -1 : a2.energy.max_error;
               ada_ev = verify::judge_energy(
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
  verify::WorkPrecision wp;
  bool have_wp = false;
  if (o.report_given && have_ref && !dl.has_hamiltonian()) {
    have_wp = run("work-precision", [&] {
      auto L = [&](const auto& q, const auto& v) -> scalar_t<decltype(q)> {
        using S = scalar_t<decltype(q)>;
        return dl.lagrangian<N, S>(Vec<S, N>(q), Vec<S, N>(v));
      };
      auto sv_dl = stormer_verlet_dl(L);
      auto mid_dl = midpoint_dl(L);
      DelIntegrator<N, decltype(sv_dl)> sv(sv_dl);
      DelIntegrator<N, decltype(mid_dl)> mid(mid_dl);
      const verify::Step sv_step = [&](Eigen::VectorXd& z, double h) {
        sv.reset();
        verify::step_qp<N>(sv, z, h);
      };
      const verify::Step mid_step = [&](Eigen::VectorXd& z, double h) {
        mid.reset();
        verify::step_qp<N>(mid, z, h);
      };
      where.start("work-precision runs", p.hs[0]);
      wp = verify::work_precision(
          {{"typed", step}, {"stormer_verlet", sv_step}, {"midpoint", mid_step}}, z0, p.t_end, zref,
          p.hs);
    });
    if (!have_wp) failed_line("work-precision");
  }

  // --- 7. the engine: modified equation, Lagrangian, Hamiltonian ------------------------------
  std::vector<std::vector<std::string>> terms;
  std::vector<std::string> lagrangian, hamiltonian;
  std::string lagrangian_error, hamiltonian_error;
  if (N > 3) {
    phases.push_back(
        {"modified", "skipped", "the symbolic engine is run for at most 3 dimensions", kOk, 0});
    line("modified equation", "not derived: the symbolic engine is run for at most 3 dimensions");
  } else if (unscaled) {
    const std::string why = "L_d is not of the size h·L (see consistency): no modified equation";
    phases.push_back({"modified", "skipped", why, kOk, 0});
    line("modified equation", "not derived: " + why);
  } else if (run("modified", [&] {
               std::lock_guard<std::mutex> lock(modified::ginac_mutex());
               auto jets = std::make_shared<modified::JetSpace>(N);
               modified::Engine engine(
                   modified::symbolic_dl<N>(Ld, jets, "typed discrete Lagrangian"),
                   p.modified_order);
               const auto& f = engine.modified_equation();
               for (std::size_t k = 0; k < f.size(); ++k) {
                 terms.emplace_back();
                 for (int i = 0; i < N; ++i)
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
      for (int i = 0; i < N; ++i) out << fmt::format("  f_{}[{}] = {}\n", k, i + 1, terms[k][i]);
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
    return e == kBadArgument ? 5 : e == kIo ? 4 : e == kNumerical ? 3 : e == kFailure ? 1 : 0;
  };
  int rc = kOk;
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
  if (o.symmetric) required.emplace_back("symmetry", &jsymm);
  if (o.symmetric && system_reversible) required.emplace_back("reversibility", &jrev);
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
  if ((rc == kOk || rc == kFailure) && !failed_checks.empty()) rc = kVerdict;
  if (o.timings) {
    out << "timings             ";
    for (const auto& ph : phases) out << fmt::format(" {} {:.2f} s;", ph.name, ph.seconds);
    out << '\n';
  }
  std::cout << out.str();
  std::cout.flush();
  // One line on stderr when it did not pass: the first part that failed, or the verdicts.
  for (const auto& ph : phases)
    if (ph.status == "failed" && ph.exit == rc) {
      std::string reason = ph.reason;
      std::replace(reason.begin(), reason.end(), '\n', ' ');
      eprint(fmt::format("vibook: error: verify: {}: {}\n", ph.name, reason));
      break;
    }
  if (rc == kVerdict)
    eprint(fmt::format("vibook: verify: FAIL ({}); the report above says why\n",
                       fmt::join(failed_checks, ", ")));
  if (o.json_given) write_output_file(o.json_out, js.dump(2) + "\n", "--json-out");
  if (!o.report_given) return rc;

  // The report: a directory filled beside its final name and renamed onto it at the end.
  namespace fs = std::filesystem;
  const fs::path final_dir = report_path(o.report);
  const fs::path tmp = temporary_directory_for(final_dir);
  bool rendered = false;
  std::string render_error;
  try {
    write_output_file((tmp / "verify.json").string(), js.dump(2) + "\n", "--report");
    std::ostringstream conv;
    if (have_wp) {
      conv << "h,steps,typed,stormer_verlet,midpoint\n";
      for (std::size_t i = 0; i < p.hs.size(); ++i)
        conv << fmt::format("{:.17g},{:.0f},{:.17g},{:.17g},{:.17g}\n", wp.h[i], wp.steps[i],
                            wp.error[0][i], wp.error[1][i], wp.error[2][i]);
    } else {
      conv << "h,steps,typed\n";
      for (std::size_t i = 0; i < order_err.size(); ++i)
        conv << fmt::format("{:.17g},{:.0f},{:.17g}\n", p.hs[i],
                            std::ceil(p.t_end / p.hs[i] - 1e-9), order_err[i]);
    }
    write_output_file((tmp / "convergence.csv").string(), conv.str(), "--report");
    std::ostringstream env;
    env << "steps,envelope\n";
    for (std::size_t i = 0; i < en.envelope.size(); ++i)
      env << fmt::format("{:.17g},{:.17g}\n", en.envelope_steps[i], en.envelope[i]);
    write_output_file((tmp / "energy.csv").string(), env.str(), "--report");
    if (!order_err.empty() && !en.envelope.empty()) {
      try {
        plot::render("verify-report", tmp);
        rendered = true;
        fs::remove(tmp / "gnuplot.log");
      } catch (const plot::PlotError& e) {
        render_error = e.what();
      }
    } else {
      render_error = "the order study or the energy run did not complete";
    }
    std::ostringstream html;
    const auto row = [&](const char* what, const std::string& measured,
                         const std::string& criterion, const std::string& holds, bool passed) {
      html << "<tr class=\"status-" << (passed ? "reproduced" : "not-reproduced") << "\"><td>"
           << what << "</td><td>" << html_escape(measured) << "</td><td>" << html_escape(criterion)
           << "</td><td class=\"holds\">" << html_escape(holds) << "</td></tr>\n";
    };
    auto phase_of = [&](const std::string& name) -> const Phase* {
      for (const auto& ph : phases)
        if (ph.name == name) return &ph;
      return nullptr;
    };
    // The book's own stylesheet (book/vibook.css, compiled in), so that the report's table
    // reads like the reproduction report: same borders, same status colours.
    write_output_file((tmp / "vibook.css").string(), std::string(kBookStylesheet), "--report");
    html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
            "<title>vibook verify</title>\n<link rel=\"stylesheet\" href=\"vibook.css\">\n"
            "<script type=\"text/x-mathjax-config\">MathJax.Hub.Config({tex2jax: {inlineMath: "
            "[['\\\\(','\\\\)']]}});</script>\n"
            "<script src=\"file:///usr/share/javascript/mathjax/MathJax.js?config=TeX-AMS_SVG\">"
            "</script>\n"
            "<style>\nbody{font-family:Roboto,'DejaVu Sans',sans-serif;max-width:1100px;"
            "margin:2em auto;padding:0 1em;color:#222;line-height:1.45}\n"
            "code,pre{font-family:'DejaVu Sans Mono',monospace;background:#fbfcfd}\n"
            "pre{padding:.6em;overflow-x:auto;border:1px solid #c4cfe5}\n"
            "h1,h2{color:#354c7b}\n</style></head><body>\n"
         << "<h1>vibook verify</h1>\n<p>vibook " << VIBOOK_VERSION << ". Command line:</p>\n<pre>"
         << html_escape(command_line()) << "</pre>\n<p>Discrete Lagrangian <code>"
         << html_escape(o.ld) << "</code>; intended system <code>"
         << html_escape(dl.has_hamiltonian()  ? "H = " + o.hamiltonian
                        : dl.default_system() ? std::string("L = |v|^2/2 - V(q)")
                                              : "L = " + o.lagrangian)
         << "</code>; potential <code>" << html_escape(o.potential.empty() ? "(none)" : o.potential)
         << "</code>; " << N << "-dimensional; initial state q0 = ("
         << html_escape(fmt::format("{}", fmt::join(p.q0, ", "))) << "), p0 = ("
         << html_escape(fmt::format("{}", fmt::join(p.p0, ", "))) << ").</p>\n"
         << "<table class=\"vibook-claims\"><tr><th>property</th><th>measured</th>"
            "<th>criterion</th><th>verdict</th></tr>\n";
    auto failed_row = [&](const char* what, const std::string& name) {
      const Phase* ph = phase_of(name);
      if (ph && ph->status != "ok")
        row(what, ph->status + (ph->reason.empty() ? "" : ": " + ph->reason), "—", ph->status,
            false);
      return ph && ph->status == "ok";
    };
    if (failed_row("consistency", "consistency"))
      row("consistency", "h⁻¹L_d → " + jcons.value("leading_term", std::string()) + " as h → 0",
          "the intended system", consistent ? "yes" : "no: " + jcons.value("reason", std::string()),
          consistent);
    if (failed_row("reference", "reference"))
      row("reference",
          fmt::format("{} macro-steps, estimated error {:.1e}",
                      static_cast<long>(jref["macro_steps"]), ref_error),
          "independent of the method", "—", true);
    if (phase_of("order") && phase_of("order")->status == "skipped")
      row("order", "not measured", "—", "skipped: no reference", false);
    else if (failed_row("order", "order")) {
      std::vector<std::string> used;
      for (std::size_t i = 0; i < fit.used.size(); ++i)
        if (fit.used[i]) used.push_back(fmt::format("{:g}", p.hs[i]));
      row("order",
          fmt::format("{:.3f} over h = {} at T = {:g} (floor {:.1e}, {} plateau points left out)",
                      fit.slope, fmt::join(used, ", "), p.t_end, fit.floor, fit.plateau),
          fmt::format("|p − {:g}| < {:g}", p.expected, p.order_tol), order_passed ? "yes" : "no",
          order_passed);
    }
    if (phase_of("variational order") && phase_of("variational order")->status == "skipped")
      row("variational order", "not derived", "—",
          "skipped: " + phase_of("variational order")->reason, false);
    else if (failed_row("variational order", "variational order")) {
      const bool judged = jvar.contains("passed");
      row("variational order",
          jvar["order"].is_null()
              ? "more than " + std::to_string(var_k) + " (L_d − L_d^E vanishes through " +
                    jvar.value("checked_to", std::string()) + ")"
              : fmt::format("{}: L_d − L_d^E = O(h^{})", int(jvar["order"]),
                            int(jvar["order"]) + 1),
          judged ? fmt::format("r = {:g}, from the engine", p.expected) : "not judged",
          judged ? (jvar["passed"] ? "yes" : "no") : "—", !judged || bool(jvar["passed"]));
    }
    const std::string by_scaling =
        "NO when resolved (> 10 × resolution) and growing at least like h^(1/2)";
    if (failed_row("symplecticity", "symplecticity"))
      row("symplecticity",
          fmt::format("|JᵀΩJ − Ω| at h, 2h, 4h, 8h (h = {:g}): {}", p.h,
                      jsym.value("why", std::string())),
          by_scaling, jsym["passed"] ? "yes" : "no", bool(jsym["passed"]));
    if (failed_row("symmetry", "symmetry"))
      row("symmetry",
          fmt::format("|Φ₋ₕΦₕ(z) − z| at h, 2h, 4h, 8h: {}", jsymm.value("why", std::string())),
          by_scaling,
          std::string(jsymm["passed"] ? "yes" : "no") + (o.symmetric ? "" : " (reported)"),
          !o.symmetric || bool(jsymm["passed"]));
    if (failed_row("time reversibility", "reversibility"))
      row("time reversibility",
          fmt::format("|ρΦρΦ(z) − z| at h, 2h, 4h, 8h: {}", jrev.value("why", std::string())),
          by_scaling,
          std::string(jrev["passed"] ? "yes" : "no") +
              (system_reversible ? "" : " (the system is not ρ-reversible)"),
          bool(jrev["passed"]));
    if (failed_row("energy", "energy")) {
      row("energy", fmt::format("{} steps of h = {:g}: {}", en.steps, en.h, ev.why),
          fmt::format("round-off: r ≤ {:.1e}; trend: exponent < 0.25; shrinking like h^(p−1/2)",
                      ev.roundoff_bound),
          ev.verdict, ev.passed);
      row("Newton",
          fmt::format("mean {:.2f}, max {} iterations per step, largest residual {:.1e}",
                      newton.steps ? double(newton.iterations) / double(newton.steps) : 0.0,
                      newton.max_iterations, newton.max_residual),
          "—", "—", true);
    }
    if (p.adaptive_epavi && failed_row("adaptive (EpAVI)", "adaptive"))
      row("adaptive (EpAVI)",
          fmt::format("{} of {} steps from h0 = {:g}, t reached {:.6g}, steps in [{:.3g}, "
                      "{:.3g}]; {}{}",
                      ada.steps_taken, p.adaptive_steps, p.h, ada.t_reached, ada.dt_min, ada.dt_max,
                      ada.failure.happened
                          ? fmt::format("no admissible step at t = {:.6g} (a fold: no sign "
                                        "change of (16) over dt in [{:.3g}, {:.3g}]); ",
                                        ada.failure.t, ada.failure.scan_lo, ada.failure.scan_hi)
                          : std::string(),
                      ada_ev.why),
          "every step exists; the intended energy as in the energy row",
          ada.failure.happened ? std::string("no admissible step") : ada_ev.verdict,
          bool(jada.value("passed", false)));
    html << "</table>\n";
    if (o.timings) {
      html << "<p>Timings (this machine; with --timings only, so that reports compare equal "
              "otherwise):";
      for (const auto& ph : phases) html << fmt::format(" {} {:.2f} s;", ph.name, ph.seconds);
      html << "</p>\n";
    }
    if (rendered)
      html << "<p><a href=\"verify-report.png\"><img src=\"verify-report.svg\" alt=\"error at T "
              "against steps; energy error envelope\"></a></p>\n<p>Left: error at T = "
           << fmt::format("{:g}", p.t_end)
           << " against the number of steps, every method against the independent reference "
              "(data: <a href=\"convergence.csv\">convergence.csv</a>). Right: the envelope "
              "max<sub>k≤K</sub>|H<sub>k</sub> − H<sub>0</sub>| (data: <a "
              "href=\"energy.csv\">energy.csv</a>).</p>\n";
    else
      html << "<p>No figure: " << html_escape(render_error)
           << " (data: <a href=\"convergence.csv\">convergence.csv</a>, <a "
              "href=\"energy.csv\">energy.csv</a>).</p>\n";
    // Formulas as LaTeX (MathJax, from the Debian package, when installed; else the source).
    auto formulas = [&](const char* title, const std::vector<std::string>& xs,
                        const std::string& error, auto label) {
      html << "<h2>" << title << "</h2>\n";
      if (!error.empty()) html << "<p>Not derived: " << html_escape(error) << "</p>\n";
      html << "<ul>\n";
      for (std::size_t k = 0; k < xs.size(); ++k)
        html << "<li>" << html_escape(label(k)) << ": "
             << (p.format == modified::Format::latex ? "\\(" + html_escape(xs[k]) + "\\)"
                                                     : "<code>" + html_escape(xs[k]) + "</code>")
             << "</li>\n";
      html << "</ul>\n";
    };
    std::vector<std::string> flat;
    std::vector<std::string> flat_labels;
    for (std::size_t k = 0; k < terms.size(); ++k)
      for (int i = 0; i < N; ++i) {
        flat.push_back(terms[k][static_cast<std::size_t>(i)]);
        flat_labels.push_back(fmt::format("h^{} term of x{}''", k, i + 1));
      }
    formulas("Modified equation", flat,
             phase_of("modified") && phase_of("modified")->status != "ok"
                 ? phase_of("modified")->reason
                 : std::string(),
             [&](std::size_t k) { return flat_labels[k]; });
    formulas("Modified Lagrangian", lagrangian, lagrangian_error,
             [](std::size_t k) { return fmt::format("h^{} term", k); });
    formulas("Modified Hamiltonian", hamiltonian, hamiltonian_error,
             [](std::size_t k) { return fmt::format("h^{} term", k); });
    html << "<p>Every number: <a href=\"verify.json\">verify.json</a>.</p>\n</body></html>\n";
    write_output_file((tmp / "index.html").string(), html.str(), "--report");
    commit_directory(tmp, final_dir);
  } catch (...) {
    discard_temporary_directory(tmp);
    throw;
  }
  std::cout << "report: " << (final_dir / "index.html").string() << '\n';
  if (!rendered && rc == kOk) {
    eprint(fmt::format("vibook: --report: figure not drawn: {}\n", render_error));
    return kFailure;
  }
  return rc;
}

}  // namespace vibook::cli
