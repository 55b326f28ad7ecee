// A discrete Lagrangian that vibook does not ship — Simpson's rule for the potential of the
// Hénon–Heiles system — put through the three things a researcher wants to know:
//   1. the generic variational integrator (DelIntegrator) runs it, no derivative by hand;
//   2. the verification helpers measure its order, symplecticity, reversibility and energy;
//   3. the symbolic engine derives its modified equation from the same C++ template.
// Build it against an installed vibook (see CMakeLists.txt beside it). Exit status 0 when
// every measurement meets its criterion, 1 otherwise.
#include <cstdio>
#include <memory>

#include "vibook/mechanics/del_solver.hpp"
#include "vibook/mechanics/discrete_lagrangian.hpp"
#include "vibook/modified/engine.hpp"
#include "vibook/verify/verify.hpp"

// [henon-heiles-simpson]
// Hénon–Heiles: V(x, y) = (x² + y²)/2 + x²y − y³/3. Generic in the scalar, so that the same
// code runs on double, on nested AutoDiff (the solver's derivatives) and on GiNaC symbols (the
// engine). Integer literals keep the symbolic coefficients exact: y*y*y/3 is y³/3, where
// y*y*y/3.0 would put the binary64 number nearest 1/3 into the modified equation.
template <class S>
S henon_heiles(const vibook::Vec<S, 2>& q) {
  return (q(0) * q(0) + q(1) * q(1)) / 2 + q(0) * q(0) * q(1) - q(1) * q(1) * q(1) / 3;
}

// Simpson's rule for the action of L = |v|²/2 − V(q) over one step (vibook's scaling
// L_d ≈ h·L):  L_d = h·( |q1 − q0|²/(2h²) − (V(q0) + 4V((q0 + q1)/2) + V(q1))/6 ).
auto simpson_dl = [](const auto& q0, const auto& q1,
                     const auto& h) -> vibook::scalar_t<decltype(h)> {
  using S = vibook::scalar_t<decltype(h)>;
  const vibook::Vec<S, 2> v = (q1 - q0) / h;
  const vibook::Vec<S, 2> qm = (q0 + q1) / 2;
  const S kinetic = (v(0) * v(0) + v(1) * v(1)) / 2;
  const S potential = (henon_heiles<S>(q0) + 4 * henon_heiles<S>(qm) + henon_heiles<S>(q1)) / 6;
  return h * (kinetic - potential);
};
// [henon-heiles-simpson]

int main() {
  using vibook::verify::Step;
  bool ok = true;
  auto report = [&](const char* what, bool passed) {
    std::printf("  %-52s %s\n", what, passed ? "ok" : "FAILED");
    ok = ok && passed;
  };

  // 1. The generic solver: p_k = −D1 L_d(q_k, q_{k+1}), p_{k+1} = D2 L_d(q_k, q_{k+1}).
  vibook::DelIntegrator<2, decltype(simpson_dl)> vi(simpson_dl);
  const Step step = [&](Eigen::VectorXd& z, double h) {
    vi.reset();  // the helpers move z between calls: no warm start from the last increment
    vibook::verify::step_qp<2>(vi, z, h);
  };
  auto energy = [](const Eigen::VectorXd& z) {
    return (z(2) * z(2) + z(3) * z(3)) / 2 +
           henon_heiles<double>(vibook::Vec<double, 2>(z(0), z(1)));
  };
  Eigen::VectorXd z0(4);
  z0 << 0.0, 0.1, 0.35, 0.0;  // energy 0.066 < 1/6: a bounded, regular orbit
  std::printf("Simpson discrete Lagrangian on Hénon–Heiles, H(z0) = %.6f\n", energy(z0));

  // 2. Verification. Order: errors at T = 5 against the same method at h = 1e-4 (its error
  // is ~1e-9, below the fit's floor), two-sided |p − 2| < 0.1.
  const double T = 5.0;
  const Eigen::VectorXd ref = vibook::verify::integrate(step, z0, 1e-4, T);
  const auto order = vibook::verify::convergence_order(
      step, z0, T, ref, {0.2, 0.1, 0.05, 0.025, 0.0125}, 2.0, 0.1, 1e-8);
  std::printf("  measured order %.3f over %d step sizes\n", order.order, order.points);
  report("order 2 (|p - 2| < 0.1)", order.passed);

  const std::vector<Eigen::VectorXd> states{z0, ref};
  const auto sym = vibook::verify::symplecticity_defect(step, states, 0.1, 1e-8);
  std::printf("  symplecticity defect |J^T W J - W| = %.2e\n", sym.defect);
  report("symplectic (defect <= 1e-8)", sym.passed);

  const auto rev = vibook::verify::reversibility_defect(step, states, 0.1, 1e-13);
  std::printf("  reversibility defect = %.2e\n", rev.defect);
  report("time-reversible (defect <= 1e-13)", rev.passed);

  const Step warm = [&](Eigen::VectorXd& z, double h) { vibook::verify::step_qp<2>(vi, z, h); };
  vi.reset();
  const auto en = vibook::verify::energy_behaviour(warm, energy, z0, 0.05, 100000);
  std::printf("  energy over %lld steps: max |H - H0| = %.2e, envelope exponent %.3f\n", en.steps,
              en.max_error, en.exponent);
  report("energy bounded (exponent < 0.25)", en.bounded);

  // 3. The symbolic engine on the same template: the modified equation to order h^2.
  using namespace vibook::modified;
  auto jets = std::make_shared<JetSpace>(2);
  // A decimal such as 0.1 or 1.0 / 6 in the template would be warned about on stderr (the
  // default; InexactLiterals::error refuses it).
  SymbolicDL dl = symbolic_dl<2>(simpson_dl, jets, "Simpson, Hénon–Heiles");
  report("exact coefficients (no decimal literal in the template)", dl.inexact_literals.empty());
  Engine engine(std::move(dl), 2);
  const auto& f = engine.modified_equation();
  for (int k = 0; k <= 2; ++k)
    for (int i = 0; i < 2; ++i)
      std::printf("  h^%d term of x%d'': %s\n", k, i + 1, canonical_string(f[k][i]).c_str());
  report("no h^1 term (a symmetric method)", f[1][0].is_zero() && f[1][1].is_zero());
  // By hand: expanding the discrete Euler–Lagrange equation in h gives
  //   x'' = −∇V + (h²/12) ∇²V ∇V + O(h⁴)   (no velocity terms at h²);
  // the engine's terms must be these, from the same V (GiNaC differentiates it).
  vibook::Vec<GiNaC::ex, 2> x(jets->x(0, 0), jets->x(0, 1));
  const GiNaC::ex V = henon_heiles<GiNaC::ex>(x);
  bool by_hand = true;
  for (int i = 0; i < 2; ++i) {
    const GiNaC::symbol xi = jets->x(0, i);
    GiNaC::ex hess_grad = 0;
    for (int j = 0; j < 2; ++j) {
      const GiNaC::symbol xj = jets->x(0, j);
      hess_grad += V.diff(xi).diff(xj) * V.diff(xj);
    }
    by_hand = by_hand && (f[0][i] + V.diff(xi)).expand().is_zero() &&
              (f[2][i] - hess_grad / 12).expand().is_zero();
  }
  report("h^0 and h^2 terms = -grad V, (h^2/12) Hess V grad V", by_hand);

  std::printf("%s\n", ok ? "all checks passed" : "some checks FAILED");
  return ok ? 0 : 1;
}
