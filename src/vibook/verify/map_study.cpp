// The measurements of a one-step map of Hamilton's equations (map_study.hpp), shared by
// `vibook verify --composition`, `--method`, the black-box steppers and the field audit.
#include "vibook/verify/map_study.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "vibook/core/errors.hpp"
#include "vibook/integrators/kernels.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/problems/problems.hpp"

namespace vibook::verify {

using nlohmann::json;

const std::vector<TestProblem>& test_problems() {
  static const std::vector<TestProblem> p = {
      {"kepler",
       "H = |p|^2/2 - 1/|q| (eccentricity 0.5, period 2 pi)",
       {0.5, 0},
       {0, std::sqrt(3.0)},
       "p^2/2 - 1/(q^2)^(1/2)"},
      {"pendulum", "H = p^2/2 - cos(q)", {1}, {0.5}, "p^2/2 - cos(q[1])"},
      {"henon-heiles",
       "H = |p|^2/2 + (x^2 + y^2)/2 + x^2 y - y^3/3",
       {0, 0.1},
       {0.35, 0},
       "p^2/2 + (q[1]^2 + q[2]^2)/2 + q[1]^2*q[2] - q[2]^3/3"}};
  return p;
}

const TestProblem* find_problem(const std::string& name) {
  const std::string want = name.empty() ? "kepler" : name;
  for (const auto& q : test_problems())
    if (q.name == want) return &q;
  return nullptr;
}

Step naming_failures(Step raw, int n) {
  return [raw = std::move(raw), n](Eigen::VectorXd& z, double h) {
    const Eigen::VectorXd start = z;
    try {
      raw(z, h);
    } catch (const NumericalError& e) {
      const std::vector<double> q(start.data(), start.data() + n),
          p(start.data() + n, start.data() + 2 * n);
      throw NumericalError(fmt::format("a step of h = {:g} from q = {}, p = {}: {}", h, vec_text(q),
                                       vec_text(p), e.what()));
    }
  };
}

std::string vec_text(const std::vector<double>& v) {
  std::vector<std::string> s;
  for (double x : v) s.push_back(fmt::format("{:.6g}", x));
  return "(" + fmt::format("{}", fmt::join(s, ", ")) + ")";
}

void MapMeasurement::line(const std::string& label, const std::string& text) {
  out << fmt::format("{:<21}{}\n", label, text);
}

void MapMeasurement::numerical(const std::string& part, const std::exception& e) {
  line(part, std::string("FAILED (numerical): ") + e.what());
  failed.push_back(part);
  numerical_failure = true;
  if (first_error.empty()) first_error = part + ": " + e.what();
}

namespace {

template <class P>
void set_mechanical(MapStudy& s, const P& prob, const std::vector<double>& q0,
                    const std::vector<double>& p0) {
  constexpr int N = P::N;
  if (q0.size() != std::size_t(N) || p0.size() != std::size_t(N))
    throw std::invalid_argument("set_problem: the state has the wrong number of components");
  Eigen::VectorXd z0(2 * N);
  for (int i = 0; i < N; ++i) {
    z0(i) = q0[static_cast<std::size_t>(i)];
    z0(N + i) = p0[static_cast<std::size_t>(i)];
  }
  s.z0 = z0;
  s.field = [prob](const std::vector<dd_real>& y) {
    Vec<dd_real, N> q;
    for (int i = 0; i < N; ++i) q(i) = y[static_cast<std::size_t>(i)];
    const Vec<dd_real, N> g = prob.template gradient<dd_real>(q);
    std::vector<dd_real> r(2 * N);
    for (int i = 0; i < N; ++i) {
      r[static_cast<std::size_t>(i)] = y[static_cast<std::size_t>(N + i)];
      r[static_cast<std::size_t>(N + i)] = -g(i);
    }
    return r;
  };
  s.H = [prob](const Eigen::VectorXd& z) {
    return energy(prob, Vec<double, N>(z.head<N>()), Vec<double, N>(z.tail<N>()));
  };
}

}  // namespace

void set_problem(MapStudy& s, const TestProblem& problem, const std::vector<double>& q0,
                 const std::vector<double>& p0) {
  if (problem.name == "pendulum") return set_mechanical(s, Pendulum{}, q0, p0);
  if (problem.name == "henon-heiles") return set_mechanical(s, HenonHeiles{}, q0, p0);
  if (problem.name == "kepler") return set_mechanical(s, Kepler{}, q0, p0);
  throw std::invalid_argument("set_problem: no test problem '" + problem.name + "'");
}

StudySystem test_problem_system(const TestProblem& problem, const std::vector<double>& q0,
                                const std::vector<double>& p0) {
  return {[&problem, q0, p0](MapStudy& s) { set_problem(s, problem, q0, p0); },
          fmt::format("{}: {}, q0 = {}, p0 = {}", problem.name, problem.hamiltonian, vec_text(q0),
                      vec_text(p0)),
          {{"name", problem.name}, {"q0", q0}, {"p0", p0}}};
}

Eigen::VectorXd run_map(const MapStudy& s, const Eigen::VectorXd& z0, double h, double T) {
  if (!s.propagate) return integrate(s.step, z0, h, T);
  if (!(h > 0) || !(T >= 0) || !std::isfinite(h) || !std::isfinite(T))
    throw std::invalid_argument("run_map: need h > 0 and T >= 0, both finite");
  // The same steps as integrate: n − 1 of h, then the last one shortened to end at T.
  const long long n = static_cast<long long>(std::ceil(T / h - 1e-9));
  Eigen::VectorXd z = z0;
  if (n >= 2) s.propagate(z, h, n - 1);
  if (n >= 1) s.propagate(z, T - h * double(n - 1), 1);
  return z;
}

namespace {

// Without --h-list the order study walks the step counts n = ⌈T·2^(k/4)⌉, k = 0, 1, … (h = T/n,
// so h ≤ 1 and every run ends exactly at T). The fit takes the points whose error lies in
// the asymptotic window [1e-12, 1e-6]·max(1, |z(T)|), fixed beforehand whatever the method:
// above it, compositions with large substeps (Yoshida's eighth order) are still far from their
// asymptotic range; below it, round-off takes over. The walk stops below the window or when a
// run would take more than 1e6 substeps; a low-order method that never
// reaches the window is fitted on its 6 smallest step sizes. fit_order_plateau's search for the
// round-off plateau applies in both cases.
constexpr double kWindowLow = 1e-12;
constexpr double kWindow = 1e-6;

}  // namespace

namespace {

// The exact solution from z0 = (q, p) over t: the study's own reference when it has one, else
// Hamilton's equations `s.field` in double-double. With `action`, one more component,
// ∫_0^t L dt: for Hamilton's equations ∫ p·q' dt integrated beside them, less t·H(z0) (L =
// p·q' − H, and H is constant along the exact solution).
Reference<dd_real> exact_solution(const MapStudy& s, const std::vector<dd_real>& z0, double t,
                                  bool action) {
  if (s.reference) return s.reference(z0, t, action);
  if (!action) return reference_solution<dd_real>(s.field, z0, t);
  const std::size_t n = z0.size() / 2;
  const Field<dd_real> field = [&s, n](const std::vector<dd_real>& y) {
    std::vector<dd_real> f = s.field(std::vector<dd_real>(y.begin(), y.end() - 1));
    dd_real a = 0.0;
    for (std::size_t i = 0; i < n; ++i) a += y[n + i] * f[i];
    f.push_back(a);
    return f;
  };
  std::vector<dd_real> y0 = z0;
  y0.emplace_back(0.0);
  Reference<dd_real> r = reference_solution<dd_real>(field, y0, t);
  Eigen::VectorXd z(static_cast<Eigen::Index>(z0.size()));
  for (std::size_t i = 0; i < z0.size(); ++i) z(static_cast<Eigen::Index>(i)) = to_double(z0[i]);
  r.y.back() = r.y.back() - dd_real(t) * dd_real(s.H(z));
  return r;
}

}  // namespace

void measure_map(const MapStudy& s, MapMeasurement& rep) {
  const Step& step = s.step;
  const Eigen::VectorXd& z0 = s.z0;
  // --- the reference: Hamilton's equations in double-double by GBS extrapolation -----------
  Eigen::VectorXd zref;
  double ref_error = NAN;
  try {
    using T = dd_real;
    std::vector<T> y0(static_cast<std::size_t>(z0.size()));
    for (Eigen::Index i = 0; i < z0.size(); ++i) y0[static_cast<std::size_t>(i)] = T(z0(i));
    const auto r = exact_solution(s, y0, s.t_end, false);
    zref.resize(z0.size());
    for (Eigen::Index i = 0; i < z0.size(); ++i)
      zref(i) = to_double(r.y[static_cast<std::size_t>(i)]);
    ref_error = r.error;
    rep.line("reference", fmt::format("{} by GBS extrapolation (order 16) in "
                                      "double-double, {} macro-steps: estimated error {:.1e}",
                                      s.equations, r.macro_steps, ref_error));
    rep.js["reference"] = {{"T", s.t_end},
                           {"state", std::vector<double>(zref.data(), zref.data() + zref.size())},
                           {"estimated_error", ref_error},
                           {"macro_steps", r.macro_steps}};
  } catch (const NumericalError& e) {
    rep.numerical("reference", e);
  }

  // --- measured order -----------------------------------------------------------------------
  rep.required.push_back("order");
  if (zref.size() == z0.size()) {
    try {
      const double scale = std::max(1.0, zref.lpNorm<Eigen::Infinity>());
      const double floor =
          s.floor ? *s.floor
                  : std::max(10 * ref_error, 16 * std::numeric_limits<double>::epsilon() * scale);
      std::vector<double> hs, err, windowed;
      bool fallback = false;
      // The walk stops at round-off: inside the window, an octave of h (4 step sizes) without
      // an error below the smallest so far means the errors no longer follow the method's
      // order (a typed method stepped in position form loses digits like 1/h); the points past
      // the smallest error are then left out.
      double roundoff_h = 0;
      if (!s.hs.empty()) {
        hs = s.hs;
        for (double h : hs)
          err.push_back((run_map(s, z0, h, s.t_end) - zref).lpNorm<Eigen::Infinity>());
        windowed = err;
      } else {
        double best = std::numeric_limits<double>::infinity();
        std::size_t best_at = 0;
        int since_best = 0;
        for (int k = 0;; ++k) {
          const double n = std::ceil(s.t_end * std::exp2(0.25 * k));
          if (!hs.empty() && std::abs(s.t_end / n - hs.back()) == 0) continue;
          const double h = s.t_end / n;
          if (s.substeps * n > s.max_substeps) break;
          double e = std::numeric_limits<double>::quiet_NaN();
          try {
            e = (run_map(s, z0, h, s.t_end) - zref).lpNorm<Eigen::Infinity>();
          } catch (const NumericalError&) {
            // a step too large for the base method's solve: no point here
          }
          hs.push_back(h);
          err.push_back(e);
          const bool in = e <= kWindow * scale && e >= kWindowLow * scale;
          windowed.push_back(in ? e : std::numeric_limits<double>::quiet_NaN());
          if (e < kWindowLow * scale) break;
          if (e < best) {
            best = e;
            best_at = hs.size() - 1;
            since_best = 0;
          } else if (std::isfinite(e) && best <= kWindow * scale && ++since_best == 4) {
            roundoff_h = hs[best_at];
            for (std::size_t i = best_at + 1; i < windowed.size(); ++i)
              windowed[i] = std::numeric_limits<double>::quiet_NaN();
            break;
          }
        }
        if (std::count_if(windowed.begin(), windowed.end(),
                          [](double x) { return std::isfinite(x); }) < 3) {
          fallback = true;
          windowed = err;
          for (std::size_t i = 0; i + 6 < windowed.size(); ++i)
            windowed[i] = std::numeric_limits<double>::quiet_NaN();
        }
      }
      const PlateauFit fit = fit_order_plateau(hs, windowed, floor);
      const bool ok = std::isfinite(fit.slope) && std::abs(fit.slope - s.expected) < s.order_tol;
      if (!ok) rep.failed.push_back("order");
      // The points of the fit, in brief (all of them in the JSON).
      double hmin = INFINITY, hmax = 0, emin = INFINITY, emax = 0;
      for (std::size_t i = 0; i < hs.size(); ++i)
        if (fit.used[i]) {
          hmin = std::min(hmin, hs[i]);
          hmax = std::max(hmax, hs[i]);
          emin = std::min(emin, err[i]);
          emax = std::max(emax, err[i]);
        }
      const std::string points =
          fit.points > 0
              ? fmt::format(
                    "h from {:.3g} to {:.3g}, errors from {:.2e} to {:.2e}; {} of {} runs "
                    "fitted ({})",
                    hmax, hmin, emax, emin, fit.points, hs.size(),
                    !s.hs.empty() ? std::string("--h-list, above the floor and the plateau")
                    : fallback
                        ? std::string("the window [1e-12, 1e-6]·scale was not reached: the 6 "
                                      "smallest step sizes")
                        : std::string("errors in the window [1e-12, 1e-6]·scale") +
                              (roundoff_h > 0
                                   ? fmt::format("; round-off below h = {:.3g}: no smaller "
                                                 "error over the next octave of h",
                                                 roundoff_h)
                                   : std::string()))
              : fmt::format("{} runs, none usable", hs.size());
      rep.line(
          "order",
          std::isfinite(fit.slope)
              ? fmt::format("{:.3f} over {} step sizes at T = {:g} (floor {:.1e}); expected {:g} "
                            "(|p - {:g}| < {:g}): {}",
                            fit.slope, fit.points, s.t_end, fit.floor, s.expected, s.expected,
                            s.order_tol, ok ? "yes" : "NO")
              : fmt::format("not measured: {} of {} errors lie in the window and above the floor "
                            "{:.1e} (--h-list to choose the step sizes): NO",
                            fit.points, hs.size(), fit.floor));
      rep.line("  points", points);
      std::vector<bool> used = fit.used;
      rep.js["order"] = {
          {"h", hs},
          {"error", err},
          {"used_in_fit", used},
          {"fitted", std::isfinite(fit.slope) ? json(fit.slope) : json(nullptr)},
          {"floor", fit.floor},
          {"window",
           s.hs.empty() && !fallback ? json({kWindowLow * scale, kWindow * scale}) : json(nullptr)},
          {"fitted_on", !s.hs.empty() ? "--h-list"
                        : fallback    ? "the 6 smallest step sizes"
                                      : "the window"},
          {"expected", s.expected},
          {"tolerance", s.order_tol},
          {"passed", ok}};
      if (roundoff_h > 0) rep.js["order"]["roundoff_below_h"] = roundoff_h;
    } catch (const NumericalError& e) {
      rep.numerical("order", e);
    }
  } else {
    rep.line("order", "not measured: no reference solution");
    rep.failed.push_back("order");
  }

  if (s.generating) measure_variational_order(s, rep);
  if (s.derive_variational_order) s.derive_variational_order(s, rep);

  // --- symplecticity and reversibility -------------------------------------------------------
  std::vector<Eigen::VectorXd> states{z0};
  if (zref.size() == z0.size()) states.push_back(zref);
  // Symplecticity at the step sizes h, 2h and 4h. A symplectic map leaves only the difference
  // quotient's error at every size; a non-symplectic method of order p leaves O(h^(p+1)), which
  // at one small step can hide below any tolerance that round-off allows (an eighth-order
  // Runge-Kutta method: 4e-11 at h = 0.05 on Kepler), but grows by 2^(p+1) with each doubling.
  // The defect is relative to max(1, |J|^2), the size of J^T W J's entries, so that a map with
  // a large Jacobian is not failed for its difference quotients' round-off.
  rep.required.push_back("symplectic");
  try {
    constexpr double kSymplecticTol = 1e-8;
    double worst = 0, worst_h = s.h;
    std::vector<std::string> shown;
    json per = json::array();
    for (int k = 0; k < 3; ++k) {
      const double hk = s.h * std::exp2(k);
      double dk = 0;
      try {
        for (const auto& z : states) {
          const Eigen::Index n = z.size() / 2;
          Eigen::MatrixXd W = Eigen::MatrixXd::Zero(2 * n, 2 * n);
          W.topRightCorner(n, n) = Eigen::MatrixXd::Identity(n, n);
          W.bottomLeftCorner(n, n) = -Eigen::MatrixXd::Identity(n, n);
          const Eigen::MatrixXd J = step_jacobian(step, z, hk);
          if (!J.allFinite()) throw NumericalError("the Jacobian of the map is not finite");
          const double size = std::max(1.0, J.lpNorm<Eigen::Infinity>());
          dk = std::max(dk, (J.transpose() * W * J - W).lpNorm<Eigen::Infinity>() / (size * size));
        }
      } catch (const NumericalError& e) {
        if (k == 0) throw;
        // a step too large for the method: the sizes below it decide
        shown.push_back(fmt::format("h = {:g}: no step", hk));
        per.push_back({{"h", hk}, {"defect", nullptr}, {"error", e.what()}});
        continue;
      }
      shown.push_back(fmt::format("h = {:g}: {:.1e}", hk, dk));
      per.push_back({{"h", hk}, {"defect", dk}});
      if (dk >= worst) {
        worst = dk;
        worst_h = hk;
      }
    }
    const bool ok = worst <= kSymplecticTol;
    rep.line("symplectic",
             fmt::format("defect |J^T W J - W| / max(1, |J|^2): {} (each <= {:.0e}): {}",
                         fmt::join(shown, ", "), kSymplecticTol, ok ? "yes" : "NO"));
    if (!ok) rep.failed.push_back("symplectic");
    rep.js["symplecticity"] = {{"defect", worst},
                               {"at_h", worst_h},
                               {"by_step_size", per},
                               {"relative_to", "max(1, |J|_max^2)"},
                               {"tolerance", kSymplecticTol},
                               {"passed", ok}};
  } catch (const NumericalError& e) {
    rep.numerical("symplectic", e);
  }
  if (s.require_reversible) rep.required.push_back("time-reversible");
  try {
    const auto rev = reversibility_defect(step, states, s.h, 1e-12);
    rep.line("time-reversible",
             fmt::format("defect = {:.2e} (<= {:.0e}): {}{}", rev.defect, rev.tolerance,
                         rev.passed ? "yes" : "NO", s.require_reversible ? "" : s.reversible_note));
    if (s.require_reversible && !rev.passed) rep.failed.push_back("time-reversible");
    rep.js["reversibility"] = {{"defect", rev.defect},
                               {"tolerance", rev.tolerance},
                               {"required", s.require_reversible},
                               {"passed", rev.passed}};
  } catch (const NumericalError& e) {
    rep.numerical("time-reversible", e);
  }

  // --- energy -------------------------------------------------------------------------------
  rep.required.push_back("energy");
  try {
    const Observable& H = s.H;
    const double H0 = H(z0);
    const double scale =
        std::max({std::abs(H0), 0.5 * z0.tail(z0.size() / 2).squaredNorm(), 1e-300});
    const auto en = energy_behaviour(step, H, z0, s.h, s.steps);
    const long long k1 = std::min<long long>(s.steps, 4096);
    const auto e1 = energy_behaviour(step, H, z0, s.h, k1);
    const auto e2 = energy_behaviour(step, H, z0, s.h / 2, 2 * k1);
    const double h_exp = e1.max_error > 0 && e2.max_error > 0
                             ? std::log2(e1.max_error / e2.max_error)
                             : std::numeric_limits<double>::quiet_NaN();
    // The scaling with h is read only where the run at h/2 stays well above round-off (a
    // high-order method reaches it at h/2, and its ratio then says nothing about h^p).
    const double roundoff_h2 =
        64 * std::sqrt(double(2 * k1)) * std::numeric_limits<double>::epsilon() / 2 * scale;
    const bool scaling = std::isfinite(h_exp) && e2.max_error > 100 * roundoff_h2;
    const auto ev =
        judge_energy(en, scale, s.expected, scaling ? en.max_error / std::exp2(h_exp) : -1);
    rep.line("energy",
             fmt::format("{} over {} steps of h = {:g}: {}", ev.verdict, en.steps, s.h, ev.why));
    if (!ev.passed) rep.failed.push_back("energy");
    rep.js["energy"] = {{"steps", en.steps},         {"h", s.h},
                        {"max_error", en.max_error}, {"relative_error", ev.relative},
                        {"exponent", en.exponent},   {"verdict", ev.verdict},
                        {"passed", ev.passed}};
  } catch (const NumericalError& e) {
    rep.numerical("energy", e);
  }
}

namespace {

// The walk of the variational order: h = 2^(-j/4) from 1 down to 2^-16, stopping below the
// window; a method whose defects never enter the window (variational order 0) is fitted on its
// 6 smallest step sizes, as in the order study.
constexpr int kVarFirst = 0, kVarLast = 64;
constexpr double kVarWindowLow = 1e-12, kVarWindow = 1e-8;

// The shooting: q1(p0') = q(h) to a few units in the last place of the positions.
constexpr int kShootIterations = 30;

}  // namespace

// Marsden & West (2001), §2.3.1: the variational order of L_d, measured along the exact
// solution (map_study.hpp).
void measure_variational_order(const MapStudy& s, MapMeasurement& rep) {
  const Eigen::Index n2 = s.z0.size(), n = n2 / 2;
  const Eigen::VectorXd p0 = s.z0.tail(n);
  json jv;
  try {
    const double H0 = s.H(s.z0);
    const double scale = std::max({1.0, std::abs(H0), 0.5 * p0.squaredNorm()});
    const double eps = std::numeric_limits<double>::epsilon();
    // The points of the exact solution where the defect is measured: z(t) at t = T/4, T/2 and
    // 3T/4, not the initial state alone. The test problems start at a point of symmetry
    // (Kepler's perihelion; q·p = 0), where the terms of L_d − L_d^E that are odd under time
    // reversal vanish, and a method of order 3 shows a defect of h^5 there.
    std::vector<Eigen::VectorXd> starts;
    for (int k = 1; k <= 3; ++k) {
      std::vector<dd_real> y(static_cast<std::size_t>(n2));
      for (Eigen::Index i = 0; i < n2; ++i) y[static_cast<std::size_t>(i)] = dd_real(s.z0(i));
      const auto r = exact_solution(s, y, s.t_end * k / 4, false);
      Eigen::VectorXd z(n2);
      for (Eigen::Index i = 0; i < n2; ++i) z(i) = to_double(r.y[static_cast<std::size_t>(i)]);
      starts.push_back(z);
    }

    // |L_d(q0, q(h), h) − L_d^E| from one state of the orbit; NaN where the method's step or the
    // shooting fails (a step too large for it).
    auto defect_from = [&](const Eigen::VectorXd& z0, double h, int& iterations) {
      std::vector<dd_real> y0;
      for (Eigen::Index i = 0; i < n2; ++i) y0.emplace_back(z0(i));
      const Eigen::VectorXd q0 = z0.head(n);
      // the action of the exact solution from z0 over h: ∫ L dt
      const auto ref = exact_solution(s, y0, h, true);
      Eigen::VectorXd target(n);
      for (Eigen::Index i = 0; i < n; ++i)
        target(i) = to_double(ref.y[static_cast<std::size_t>(i)]);
      const dd_real exact = ref.y.back();
      const double tol = 8 * eps * std::max(1.0, target.lpNorm<Eigen::Infinity>());
      Eigen::VectorXd p = z0.tail(n);
      auto shoot = [&](const Eigen::VectorXd& pp, double& Ld) {
        Eigen::VectorXd z(n2);
        z << q0, pp;
        Ld = s.generating(z, h);
        return Eigen::VectorXd(z.head(n) - target);
      };
      for (iterations = 0; iterations < kShootIterations; ++iterations) {
        double Ld = 0;
        const Eigen::VectorXd r = shoot(p, Ld);
        if (!r.allFinite() || !std::isfinite(Ld)) break;
        if (r.lpNorm<Eigen::Infinity>() <= tol) return std::abs(to_double(dd_real(Ld) - exact));
        Eigen::MatrixXd J(n, n);
        for (Eigen::Index k = 0; k < n; ++k) {
          const double d = 1e-6 * std::max(1.0, std::abs(p(k)));
          Eigen::VectorXd pp = p, pm = p;
          pp(k) += d;
          pm(k) -= d;
          double unused = 0;
          J.col(k) = (shoot(pp, unused) - shoot(pm, unused)) / (2 * d);
        }
        const Eigen::VectorXd dp = J.fullPivLu().solve(-r);
        if (!dp.allFinite()) break;
        p += dp;
      }
      return std::numeric_limits<double>::quiet_NaN();
    };
    // The largest defect over the points of the orbit.
    auto defect = [&](double h, int& iterations) {
      double worst = 0;
      iterations = 0;
      for (const auto& z : starts) {
        int it = 0;
        const double d = defect_from(z, h, it);
        iterations = std::max(iterations, it);
        if (!std::isfinite(d)) return d;
        worst = std::max(worst, d);
      }
      return worst;
    };

    std::vector<double> hs, ds, windowed;
    std::vector<int> its;
    for (int j = kVarFirst; j <= kVarLast; ++j) {
      const double h = std::exp2(-0.25 * j);
      int it = 0;
      double d = std::numeric_limits<double>::quiet_NaN();
      try {
        d = defect(h, it);
      } catch (const NumericalError&) {
        // a step too large for the method: no point here
      }
      hs.push_back(h);
      ds.push_back(d);
      its.push_back(it);
      const bool in = d <= kVarWindow * scale && d >= kVarWindowLow * scale;
      windowed.push_back(in ? d : std::numeric_limits<double>::quiet_NaN());
      if (d < kVarWindowLow * scale) break;
    }
    // Only the run of points in the window that ends at the smallest step counts: a defect
    // that changes sign in the pre-asymptotic range passes through the window there too.
    {
      std::size_t i = windowed.size();
      while (i > 0 && !std::isfinite(windowed[i - 1])) --i;  // below the window at the end
      while (i > 0 && std::isfinite(windowed[i - 1])) --i;   // the run
      for (std::size_t k = 0; k < i; ++k) windowed[k] = std::numeric_limits<double>::quiet_NaN();
    }
    bool fallback = false;
    if (std::count_if(windowed.begin(), windowed.end(), [](double x) { return std::isfinite(x); }) <
        4) {
      fallback = true;
      windowed = ds;
      for (std::size_t i = 0; i + 6 < windowed.size(); ++i)
        windowed[i] = std::numeric_limits<double>::quiet_NaN();
    }
    // log d = a + (r + 1) log h + c h: the defect is a power series in h, and its next term
    // changes the local slope by O(h), which a plain fit over the window reads as a lower
    // order (the local slopes of a sixth-order composition on Kepler climb from 6.2 to 6.9
    // across the window).
    std::vector<bool> used(hs.size(), false);
    std::vector<std::size_t> pts;
    for (std::size_t i = 0; i < hs.size(); ++i)
      if (std::isfinite(windowed[i]) && windowed[i] > 0) pts.push_back(i);
    double exponent = std::numeric_limits<double>::quiet_NaN(), plain = exponent;
    if (pts.size() >= 3) {
      const Eigen::Index m = static_cast<Eigen::Index>(pts.size());
      Eigen::MatrixXd A(m, 3);
      Eigen::VectorXd y(m);
      for (Eigen::Index i = 0; i < m; ++i) {
        const std::size_t k = pts[static_cast<std::size_t>(i)];
        A.row(i) << 1.0, std::log(hs[k]), hs[k];
        y(i) = std::log(windowed[k]);
        used[k] = true;
      }
      plain = A.leftCols(2).colPivHouseholderQr().solve(y)(1);
      exponent = m >= 4 ? Eigen::VectorXd(A.colPivHouseholderQr().solve(y))(1) : plain;
    }
    const double r = exponent - 1;
    const bool agrees_expected = std::isfinite(r) && std::abs(r - s.expected) < s.order_tol;
    double hmin = INFINITY, hmax = 0;
    for (std::size_t i = 0; i < hs.size(); ++i)
      if (used[i]) {
        hmin = std::min(hmin, hs[i]);
        hmax = std::max(hmax, hs[i]);
      }
    std::string measured;
    if (rep.js.contains("order") && rep.js["order"]["fitted"].is_number() && std::isfinite(r)) {
      const double slope = rep.js["order"]["fitted"].get<double>();
      const bool agrees = std::abs(slope - r) < s.order_tol;
      jv["agrees_with_measured"] = agrees;
      measured = fmt::format("; measured order {:.3f}: {}", slope, agrees ? "agrees" : "differs");
    }
    rep.line(
        "variational order",
        std::isfinite(r)
            ? fmt::format("{:.2f} (measured; reported, not part of the verdict): "
                          "|L_d - L_d^E| ~ h^{:.2f}; expected {:g}: {}{}",
                          r, exponent, s.expected, agrees_expected ? "agrees" : "differs", measured)
            : fmt::format("not measured: {} of {} defects usable", pts.size(), hs.size()));
    if (!pts.empty())
      rep.line(
          "  points",
          fmt::format("largest over z(T/4), z(T/2), z(3T/4); h from {:.3g} to {:.3g}, {} of {} "
                      "step sizes fitted ({}); L_d is {}",
                      hmax, hmin, pts.size(), hs.size(),
                      fallback ? "the window [1e-12, 1e-8]·scale was not reached: the 6 "
                                 "smallest step sizes"
                               : "defects in the window [1e-12, 1e-8]·scale, with an O(h) "
                                 "correction",
                      s.generating_from));
    jv["h"] = hs;
    jv["defect"] = ds;
    jv["shooting_iterations"] = its;
    jv["used_in_fit"] = used;
    jv["fitted_exponent"] = std::isfinite(exponent) ? json(exponent) : json(nullptr);
    jv["plain_fit_exponent"] = std::isfinite(plain) ? json(plain) : json(nullptr);
    jv["order"] = std::isfinite(r) ? json(r) : json(nullptr);
    jv["window"] = fallback ? json(nullptr) : json({kVarWindowLow * scale, kVarWindow * scale});
    jv["expected"] = s.expected;
    jv["tolerance"] = s.order_tol;
    jv["source"] =
        "measured: L_d(q0, q(h), h) - the action of the exact solution, Marsden & West 2001, "
        "Sec. 2.3.1; L_d is " +
        s.generating_from;
    jv["derived"] = false;
    jv["measured"] = true;
    jv["agrees_with_expected"] = agrees_expected;
    jv["judged"] = false;
    rep.js["variational_order"] = jv;
  } catch (const NumericalError& e) {
    // reported only: a failure here is printed, and the verdict does not depend on it
    rep.line("variational order", std::string("not measured (numerical): ") + e.what());
    rep.js["variational_order"] = {{"measured", false}, {"error", e.what()}};
  }
}

}  // namespace vibook::verify
