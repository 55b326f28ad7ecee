/// \file engine.hpp
/// \brief The modified-equation engine (Vermeeren 2017, §3–5; Shen & Sun 2025, §4): from a
/// discrete Lagrangian, written once as the C++ template the integrators use, to the
/// expansion L_disc([x], h) (V (13)), the meshed modified Lagrangian (V Def. 6), the modified
/// equation (V §4.6, and V §3.2 as a cross-check), the modified Lagrangian L_mod,k (V Def. 8)
/// and the modified Hamiltonian (series Legendre transform).
///
/// Every result is a list of coefficients of h^0, h^1, …, h^K: scalars in the jet symbols
/// x1…xN, v1…vN (ẋ), x1_2 (ẍ1), … and the derivative symbols U, U_1, U_11, … of an abstract
/// potential; vectors (one entry per degree of freedom) for equations.
///
/// Example (Störmer–Verlet, generic 1-DOF potential, Vermeeren (22)):
/// \code
///   using namespace vibook::modified;
///   Engine E(make_discrete_lagrangian(Method::sv, Potential::generic, 1), 4);
///   auto f = E.modified_equation();  // f[0][0] = -U_1, f[2][0] = (U_111 v1^2 - U_11 U_1)/12
/// \endcode
///
/// Chapter: \ref chapter-modified.
#pragma once

#include <algorithm>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "vibook/core/errors.hpp"
#include "vibook/core/types.hpp"
#include "vibook/modified/canonical.hpp"
#include "vibook/modified/ginac_eigen.hpp"
#include "vibook/modified/ginac_lock.hpp"
#include "vibook/modified/jets.hpp"
#include "vibook/modified/series.hpp"

namespace vibook::modified {

/// Highest order in h the engine accepts (the command line checks it).
inline constexpr int max_order = 10;

/// A discrete Lagrangian as a symbolic expression in (q0, q1, h), in vibook's scaling
/// L_d ≈ h·L (Vermeeren's L_disc is L_d / h).
///
/// A *three-point* discrete Lagrangian L_d(q0, qm, q1, h) has an interior node qm (a
/// composition over half steps, Shen & Sun (3.8)). The engine eliminates qm exactly, order by
/// order in h, from ∂L_d/∂qm = 0 (the discrete Euler–Lagrange equation at the interior node),
/// which leaves the one-step discrete Lagrangian of the same x_n sequence.
///
/// A discrete Lagrangian with *several* interior points (a Galerkin L_d before its interior
/// control points are eliminated, Marsden & West 2001 §2.6: symbolic_dl_interior) lists all of
/// their coordinates in qm, point by point, with each coordinate's degree of freedom in
/// qm_dof and the fraction τ of the step at which Newton's method on series starts it, on the
/// chord q0 + τ(q1 − q0), in qm_at. All of them are eliminated together.
struct SymbolicDL {
  std::shared_ptr<JetSpace> jets;
  std::vector<GiNaC::symbol> q0, q1;
  std::vector<GiNaC::symbol> qm;  ///< interior node(s) of L_d (empty for a two-point L_d)
  /// For each qm[k]: its degree of freedom and the start τ (empty: qm[i] is degree of freedom
  /// i of one interior node, started at τ = 1/2).
  std::vector<int> qm_dof;
  std::vector<GiNaC::numeric> qm_at;
  /// Place the interior node on the curve, qm = x(t), instead of eliminating it (the reading
  /// of Shen & Sun's proof of Theorem 12; not the discrete Lagrangian of the x_n sequence).
  bool interior_on_curve = false;
  /// Degrees of freedom whose second derivative the modified equation gives (all when
  /// empty). The others keep every derivative as a free symbol: Sharma et al. §4.3 solve for
  /// q'' only, with t', t'', … left free, because the energy equation is redundant.
  std::vector<int> solve_for;
  ex Ld;
  std::string description;
  /// Floating-point numbers met in the template whose exact binary64 value is almost surely
  /// not the number meant (0.1, 1.0/6): one message each, sorted (GiNaC's traversal order
  /// varies from run to run). What else happens to them is the InexactLiterals policy.
  std::vector<std::string> inexact_literals;
};

/// What symbolic_dl does when the template holds a floating-point number whose exact binary64
/// value is almost surely not the number meant (0.1, 1.0/6, a division by 6.0: the symbolic
/// engine would otherwise derive everything with 6004799503160661/36028797018963968 where the
/// author meant 1/6).
enum class InexactLiterals {
  warn,     ///< default: print each message once to stderr ("vibook: warning: ..."), go on
  error,    ///< throw ArgumentError naming the template's description and the first literal
  collect,  ///< only list them in SymbolicDL::inexact_literals (the caller reports them)
};

/// Apply `policy` to `dl.inexact_literals` (symbolic_dl and symbolic_dl3 call this).
void apply_inexact_policy(const SymbolicDL& dl, InexactLiterals policy);

/// Evaluate a discrete-Lagrangian template (any callable `dl(q0, q1, h)` generic in its
/// scalar, as written for the integrators) on GiNaC symbols. Floating-point literals in the
/// template become the rationals they represent; those that are not short binary fractions
/// (0.5 is, 0.1 and 1.0/6 are not) are warned about, or refused, or listed (`policy`).
///
/// **Comparing two engines.** Each JetSpace makes symbols of its own: x1 of one and x1 of
/// another print alike but are different GiNaC symbols, so `f - g` of expressions from two
/// engines does not cancel. Build both discrete Lagrangians on one shared JetSpace (pass the
/// same `jets`), or compare the printed forms with canonical_string (canonical.hpp), which
/// does not depend on which symbols they are.
template <int N, class DL>
SymbolicDL symbolic_dl(const DL& dl, std::shared_ptr<JetSpace> jets, std::string description,
                       InexactLiterals policy = InexactLiterals::warn) {
  SymbolicDL out;
  out.jets = std::move(jets);
  out.description = std::move(description);
  Vec<ex, N> a, b;
  for (int i = 0; i < N; ++i) {
    out.q0.emplace_back(N == 1 ? "q0" : "q0_" + std::to_string(i + 1));
    out.q1.emplace_back(N == 1 ? "q1" : "q1_" + std::to_string(i + 1));
    a(i) = out.q0.back();
    b(i) = out.q1.back();
  }
  const ex h = out.jets->h();
  out.Ld = exact_rationals(dl(a, b, h), &out.inexact_literals);
  std::sort(out.inexact_literals.begin(), out.inexact_literals.end());  // not GiNaC's order
  apply_inexact_policy(out, policy);
  return out;
}

/// The same for a discrete Lagrangian `dl(q0, Q, q1, h)` with interior points Q (a
/// std::vector of `at.size()` points Vec<ex, N>), point j started at the fraction at[j] of the
/// step. The symbols are Q1, Q2, … (Q1_1, Q1_2, … for N > 1).
template <int N, class DL>
SymbolicDL symbolic_dl_interior(const DL& dl, std::shared_ptr<JetSpace> jets,
                                std::string description, const std::vector<GiNaC::numeric>& at,
                                InexactLiterals policy = InexactLiterals::warn) {
  SymbolicDL out;
  out.jets = std::move(jets);
  out.description = std::move(description);
  Vec<ex, N> a, b;
  std::vector<Vec<ex, N>> m(at.size());
  for (int i = 0; i < N; ++i) {
    out.q0.emplace_back(N == 1 ? "q0" : "q0_" + std::to_string(i + 1));
    out.q1.emplace_back(N == 1 ? "q1" : "q1_" + std::to_string(i + 1));
    a(i) = out.q0.back();
    b(i) = out.q1.back();
  }
  for (std::size_t j = 0; j < at.size(); ++j)
    for (int i = 0; i < N; ++i) {
      const std::string name = "Q" + std::to_string(j + 1);
      out.qm.emplace_back(N == 1 ? name : name + "_" + std::to_string(i + 1));
      out.qm_dof.push_back(i);
      out.qm_at.push_back(at[j]);
      m[j](i) = out.qm.back();
    }
  const ex h = out.jets->h();
  out.Ld = exact_rationals(dl(a, m, b, h), &out.inexact_literals);
  std::sort(out.inexact_literals.begin(), out.inexact_literals.end());  // not GiNaC's order
  apply_inexact_policy(out, policy);
  return out;
}

/// The same for a three-point discrete Lagrangian `dl(q0, qm, q1, h)`.
template <int N, class DL>
SymbolicDL symbolic_dl3(const DL& dl, std::shared_ptr<JetSpace> jets, std::string description,
                        InexactLiterals policy = InexactLiterals::warn) {
  SymbolicDL out;
  out.jets = std::move(jets);
  out.description = std::move(description);
  Vec<ex, N> a, m, b;
  for (int i = 0; i < N; ++i) {
    out.q0.emplace_back(N == 1 ? "q0" : "q0_" + std::to_string(i + 1));
    out.qm.emplace_back(N == 1 ? "qm" : "qm_" + std::to_string(i + 1));
    out.q1.emplace_back(N == 1 ? "q1" : "q1_" + std::to_string(i + 1));
    a(i) = out.q0.back();
    m(i) = out.qm.back();
    b(i) = out.q1.back();
  }
  const ex h = out.jets->h();
  out.Ld = exact_rationals(dl(a, m, b, h), &out.inexact_literals);
  std::sort(out.inexact_literals.begin(), out.inexact_literals.end());  // not GiNaC's order
  apply_inexact_policy(out, policy);
  return out;
}

/// An abstract potential U_f(q) of N degrees of freedom for the templates' `potential(q)`.
template <int N>
struct AbstractPotential {
  static constexpr int N_ = N;
  int family = 0;
  template <class S>
  S potential(const Vec<S, N>& q) const {
    std::vector<ex> args;
    for (int i = 0; i < N; ++i) args.push_back(q(i));
    return abstract_call(family, args);
  }
};

enum class Method { sv, se, se_adjoint, midpoint, vi1, vi1_adjoint, vi2 };
enum class Potential { generic, kepler, pendulum, harmonic };

/// "sv", "se", … ; ArgumentError("--method") otherwise.
Method parse_method(const std::string& s);
/// "generic", "kepler", …; ArgumentError("--potential") otherwise.
Potential parse_potential(const std::string& s);

/// The discrete Lagrangian of a method on a mechanical Lagrangian ½|v|² − U(q), built from
/// the integrators' templates (discrete_lagrangian.hpp, splitting.hpp). Kepler is 2-D; the
/// pendulum and the oscillator 1-D; a generic potential has `dim` degrees of freedom (1–3).
/// For vi1/vi1-adjoint with a generic potential the pieces φ^[i] are abstract functions
/// phi1, phi2, …; with a concrete one they are α·U and (1 − α)·U with `alpha` (a symbol
/// named alpha when not given). vi2 is the three-point L_d*(x0, xm, h/2) + L_d(xm, x1, h/2).
SymbolicDL make_discrete_lagrangian(Method m, Potential p, int dim,
                                    std::optional<GiNaC::numeric> alpha = std::nullopt);

/// The result of Engine::variational_order.
struct VariationalOrder {
  /// r, the first k with defect[k] ≠ 0; −1 when every coefficient through h^{checked + 1}
  /// vanishes (the variational order is then more than `checked`).
  int order = -1;
  int checked = 0;  ///< the last k computed (the engine's order K)
  /// L_d − L_d^E = Σ_k h^{k+1} defect[k] along the solutions of L, k = 0…checked.
  std::vector<ex> defect;
};

/// Derivations to order K in h, computed on demand and cached.
class Engine {
 public:
  /// `order` ≥ 0 and ≤ max_order (ArgumentError("--order") otherwise).
  Engine(SymbolicDL dl, int order);

  int order() const { return K_; }
  /// Derive on the reference path: the original algorithms, kept to check the fast ones
  /// against (`vibook modified --reference`, tests/cli/modified_reference.sh). Derivatives
  /// by GiNaC's diff symbol by symbol (JetSpace::set_reference), every jet series carried to
  /// the full precision, eight Newton steps at full precision for an interior node. Set
  /// before the first derivation.
  void use_reference_path(bool on) {
    reference_ = on;
    dl_.jets->set_reference(on);
  }
  const JetSpace& jets() const { return *dl_.jets; }
  const SymbolicDL& discrete_lagrangian() const { return dl_; }

  /// V (13): L_disc([x], h) = Σ h^k ℓ_k, in Vermeeren's scaling (L_disc = L_d / h).
  const std::vector<ex>& l_disc();
  /// V Def. 6: L_mesh = Σ_i (2^{1−2i} − 1) B_{2i}/(2i)! h^{2i} D^{2i} L_disc.
  const std::vector<ex>& l_mesh();
  /// The modified equation ẍ = Σ h^k f_k(x, ẋ) from the Euler–Lagrange equation of L_mesh
  /// (V §4.6); f[k][i] is the h^k coefficient of component i.
  const std::vector<std::vector<ex>>& modified_equation();
  /// The same from the Taylor expansion of the discrete Euler–Lagrange equation (V §3.2).
  std::vector<std::vector<ex>> modified_equation_direct();
  /// V Def. 8: L_mod,K(x, ẋ, h).
  const std::vector<ex>& l_mod();
  /// Series Legendre transform of L_mod,K: H_mod,K(x, p, h) in the symbols x_i, p_i.
  std::vector<ex> h_mod();

  /// Marsden & West (2001) §2.3.1: L_d is of *variational order* r when
  /// L_d(q(0), q(h), h) − L_d^E(q(0), q(h), h) = O(h^{r+1}) on the solutions q of the
  /// Euler–Lagrange equations of the intended Lagrangian `L`, where L_d^E (their (2.3.1),
  /// the exact discrete Lagrangian) is the action of the solution from q(0) to q(h); their
  /// Theorem 2.3.1 makes the method's order at least r. `L` is written in the jet symbols
  /// J.x(0, i) and J.x(1, i) and must be regular. The defect is expanded around the step's
  /// midpoint (V (13) for L_d, the midpoint Taylor rule for the action), the jets of order
  /// ≥ 2 replaced along ẍ = F(x, ẋ) of L, and tested for zero coefficient by coefficient
  /// through h^{order()+1}.
  VariationalOrder variational_order(const ex& L);
  /// The modified equation as a first-order system in (x, p), p = ∂L_mod/∂ẋ the momentum of
  /// the Legendre transform: ẋ_i = ∂H_mod/∂p_i, ṗ_i = −∂H_mod/∂x_i (with the chain rule
  /// through a generic potential's derivatives). Returns {ẋ, ṗ}, each [k][i] the h^k
  /// coefficient of component i.
  std::pair<std::vector<std::vector<ex>>, std::vector<std::vector<ex>>> vector_field();

  /// Euler–Lagrange expression Σ_ℓ (−1)^ℓ D^ℓ ∂L/∂x^{(ℓ)} of L = Σ h^k L[k] (any order).
  std::vector<std::vector<ex>> euler_lagrange(const std::vector<ex>& L) const;
  /// The two-term expression ∂L/∂x − D ∂L/∂ẋ that Vermeeren §4.6 writes for the meshed
  /// Lagrangian (on meshed-critical families the higher terms are of higher order).
  std::vector<std::vector<ex>> euler_lagrange_two_term(const std::vector<ex>& L) const;
  /// Solve E = Σ h^k E[k] = 0 for ẍ to order `order` by recursive elimination (V §4.6).
  std::vector<std::vector<ex>> solve_for_acceleration(const std::vector<std::vector<ex>>& E,
                                                      int order) const;
  /// The Lagrange coefficient (2^{1−2i} − 1) B_{2i}/(2i)! of Lemma 6.
  static GiNaC::numeric mesh_coefficient(int i);

 private:
  SymbolicDL dl_;
  int K_;
  bool reference_ = false;
  std::vector<ex> ldisc_, lmesh_, lmod_;
  std::vector<std::vector<ex>> f_;
  /// The solved degrees of freedom (SymbolicDL::solve_for, or all).
  std::vector<int> solved() const;
  /// Series of x^{(ℓ)}, ℓ = 2…top, of the solved degrees of freedom on solutions of ẍ = F
  /// (F and the result indexed by position in solved()), for evaluating Σ_k h^k e[k] to
  /// O(h^cap) with `along`: top is the highest derivative in the e[k], and x^{(ℓ)} is kept only
  /// to O(h^{cap − k_ℓ}), k_ℓ the first k whose e[k] contains it (more is never used).
  std::vector<std::vector<Series>> jets_along(const std::vector<Series>& F,
                                              const std::vector<std::vector<ex>>& uses,
                                              int cap) const;
  /// L_d with interior points: their coordinates (qm) as series, from ∂L_d/∂qm = 0 with q0,
  /// q1 (and h) given as series in `subs` (Newton's method on series, started on the chord:
  /// the mean of q0, q1 for one interior node).
  std::vector<Series> interior_node(const std::map<ex, Series, GiNaC::ex_is_less>& subs,
                                    int cap) const;
  /// Σ h^k (e[k] with x^{(ℓ)} → jets), truncated at cap.
  Series along(const std::vector<ex>& e, const std::vector<std::vector<Series>>& jets,
               int cap) const;
};

/// A Nyström method (Shen & Sun (4.5)) for ẍ = f(x): stages x^i = x + c_i h v + h² Σ ā_ij f(x^j),
/// x_{n+1} = x + h v + h² Σ b̄_i f(x^i), v_{n+1} = v + h Σ b̂_i f(x^i).
/// The coefficients may be numbers or symbols (a symbolic tableau gives the modified equation
/// as a formula in them).
struct NystromTableau {
  std::vector<ex> c, bbar, bhat;
  std::vector<std::vector<ex>> abar;
};

/// Modified equation ẍ = Σ h^k f_k of a Nyström method on a generic 1-DOF force f (symbols f,
/// f_1, f_11, … for f, f', f'', … at x), to order K: the velocity is eliminated between two
/// steps, x(t+h) − 2x(t) + x(t−h) = h² Σ_i [(b̂_i − b̄_i) f(x^i(t−h)) + b̄_i f(x^i(t))] with the
/// stages x^i(t) = c_i x(t+h) + (1 − c_i) x(t) + h² Σ_j (ā_ij − c_i b̄_j) f(x^j(t)) (solved by
/// fixed-point iteration on series), and the result solved for ẍ as in V §4.6.
/// `printed_46` uses the elimination as Shen & Sun print it in (4.6) instead:
/// Σ_i [b̂_i f(x^i(t−h)) + (b̄_i − b̂_i) f(x^i(t))].
std::vector<std::vector<ex>> nystrom_modified_equation(std::shared_ptr<JetSpace> J,
                                                       const NystromTableau& tab, int K,
                                                       bool printed_46 = false);

/// Display form for a radial potential in two dimensions: powers of x1² + x2² become powers of
/// r = |x|, and x2² is replaced by r² − x1², which makes the expression canonical in
/// (x1, x2, r) with x2 to the first power at most. The value is unchanged.
ex radial_form(const ex& e, const GiNaC::symbol& x1, const GiNaC::symbol& x2,
               const GiNaC::symbol& r);

/// `--format` of `vibook modified` (Format is declared in canonical.hpp).
Format parse_format(const std::string& s);
/// Σ h^k c[k] + O(h^{K+1}) as text, LaTeX or Python (SymPy) source, every coefficient in
/// canonical order (canonical.hpp): the same text in every run.
std::string format_series(const std::vector<ex>& c, const GiNaC::symbol& h, Format f);

}  // namespace vibook::modified
