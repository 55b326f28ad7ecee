// Shen & Sun 2025, Fig. 1 and (4.20): the pendulum with potential φ = cos x, symplectic Euler
// (4.16) with (x0, v0, h) = (π/2, 0.5, 0.25). The discrete points, the level set of H through
// the initial point and those of the modified Hamiltonians H_mod,1 and H_mod,2 (series Legendre
// transforms of the engine's L_mod,1 and L_mod,2); the spread of each along the discrete orbit.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "vibook/integrators/kernels.hpp"
#include "vibook/mechanics/discrete_lagrangian.hpp"
#include "vibook/modified/checks.hpp"
#include "vibook/modified/compiled.hpp"
#include "vibook/modified/engine.hpp"

namespace vibook::checks {

namespace {

using LD = long double;

// Shen & Sun's pendulum: L = ½ẋ² − φ(x), φ = cos x (vibook's Pendulum is −cos x, shifted by π).
struct CosinePendulum {
  static constexpr int N = 1;
  template <class S>
  S potential(const Vec<S, 1>& q) const {
    using std::cos;
    return cos(q(0));
  }
  template <class S>
  Vec<S, 1> gradient(const Vec<S, 1>& q) const {
    using std::sin;
    return Vec<S, 1>(-sin(q(0)));
  }
};

std::vector<claims::ClaimResult> run_ss_fig1(const Context& ctx) {
  const std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());  // GiNaC: one thread
  const double x0 = std::numbers::pi / 2, p0 = 0.5, h = 0.25;
  const int steps = 2000;
  auto J = std::make_shared<modified::JetSpace>(1);
  modified::Engine E(
      modified::symbolic_dl<1>(symplectic_euler_dl(mechanical_lagrangian(CosinePendulum{})), J,
                               "symplectic Euler (4.16), φ = cos x"),
      2);
  const auto H = E.h_mod();
  const std::vector<GiNaC::symbol> vars = {J->x(0, 0), J->p(0), J->h()};
  std::vector<modified::Compiled> Hk;  // H (order 0), H_mod,1, H_mod,2
  modified::ex acc = 0;
  for (int k = 0; k <= 2; ++k) {
    acc += GiNaC::pow(J->h(), k) * H[k];
    Hk.emplace_back(acc, vars);
  }
  auto value = [&](int k, double xx, double pp) {
    return static_cast<double>(Hk[k]({LD(xx), LD(pp), LD(h)}));
  };
  SymplecticEuler<CosinePendulum> se;
  Vec<double, 1> q(x0), pm(p0);
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) lo[k] = hi[k] = value(k, x0, p0);
  double xmin = x0, xmax = x0;
  std::optional<std::ofstream> fd;
  if (ctx.out_dir) {
    fd.emplace(*ctx.out_dir / "discrete.csv");
    *fd << "n,x,p\n";
  }
  for (int n = 0; n <= steps; ++n) {
    if (fd && n <= 200) *fd << fmt::format("{},{:.17g},{:.17g}\n", n, q(0), pm(0));
    for (int k = 0; k < 3; ++k) {
      const double v = value(k, q(0), pm(0));
      lo[k] = std::min(lo[k], v);
      hi[k] = std::max(hi[k], v);
    }
    xmin = std::min(xmin, q(0));
    xmax = std::max(xmax, q(0));
    se.step(q, pm, h);
  }
  const double spread[3] = {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};

  if (ctx.out_dir) {
    // Level sets through the initial point: for each x, the roots p of H_k(x, p) = H_k(x0, p0)
    // on p ∈ [−3, 3] (scan and bisection). Each is a closed curve around its centroid, written
    // in the order of the angle about it and closed, so that it is drawn as a line.
    const char* names[3] = {"level_H.csv", "level_Hmod1.csv", "level_Hmod2.csv"};
    for (int k = 0; k < 3; ++k) {
      std::vector<std::pair<double, double>> curve;
      const double c = value(k, x0, p0);
      for (int i = 0; i <= 600; ++i) {
        const double xx = xmin - 0.3 + (xmax - xmin + 0.6) * i / 600;
        double pa = -3, ga = value(k, xx, pa) - c;
        for (int j = 1; j <= 1200; ++j) {
          const double pb = -3 + 6.0 * j / 1200, gb = value(k, xx, pb) - c;
          if ((ga < 0) != (gb < 0)) {
            double a = pa, b = pb, fa = ga;
            for (int it = 0; it < 60; ++it) {
              const double mid = 0.5 * (a + b), fm = value(k, xx, mid) - c;
              if ((fm < 0) == (fa < 0)) {
                a = mid;
                fa = fm;
              } else {
                b = mid;
              }
            }
            curve.emplace_back(xx, 0.5 * (a + b));
          }
          pa = pb;
          ga = gb;
        }
      }
      double cx = 0, cp = 0;
      for (const auto& [xx, pp] : curve) {
        cx += xx / static_cast<double>(curve.size());
        cp += pp / static_cast<double>(curve.size());
      }
      std::stable_sort(curve.begin(), curve.end(), [&](const auto& a, const auto& b) {
        return std::atan2(a.second - cp, a.first - cx) < std::atan2(b.second - cp, b.first - cx);
      });
      if (!curve.empty()) curve.push_back(curve.front());
      std::ofstream f(*ctx.out_dir / names[k]);
      f << "x,p\n";
      for (const auto& [xx, pp] : curve) f << fmt::format("{:.12g},{:.12g}\n", xx, pp);
    }
  }

  claims::ClaimResult c;
  c.id = "SS-F1";
  c.source = "shen-sun-fig1";
  c.values = {{"spread_H", spread[0]},
              {"spread_Hmod1", spread[1]},
              {"spread_Hmod2", spread[2]},
              {"ratio_Hmod1_over_H", spread[1] / spread[0]}};
  // [ss-f1-criterion]
  const bool closer = spread[1] < 0.2 * spread[0];
  c.status = closer ? claims::Status::reproduced : claims::Status::not_reproduced;
  // [ss-f1-criterion]
  c.note = fmt::format(
      "Pendulum φ = cos x, symplectic Euler (4.16), (x0, p0, h) = (π/2, 0.5, 0.25), {} steps. "
      "Spread (max − min) along the discrete orbit: H {:.3e}, H_mod,1 {:.3e}, H_mod,2 {:.3e} "
      "(ratio H_mod,1/H {:.3f}; \"far more closely\" read as below 0.2). H_mod,k is the engine's "
      "series Legendre transform of L_mod,k; (4.20) itself is read from the paper and compared "
      "with it by check-modified.",
      steps, spread[0], spread[1], spread[2], spread[1] / spread[0]);
  return {c};
}

}  // namespace

Check shen_sun_fig1() {
  return {"shen-sun-fig1",
          "Pendulum, symplectic Euler h = 0.25: level sets of H, H_mod,1 and H_mod,2 with the "
          "discrete orbit (Shen–Sun Fig. 1, (4.20))",
          true,
          {"SS-F1"},
          run_ss_fig1};
}

}  // namespace vibook::checks
