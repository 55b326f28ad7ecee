/// \file method_symbolic.hpp
/// \brief The variational order of a Galerkin method or a composition derived by the symbolic
/// engine (issue #25, item 2), for `vibook verify --method` and `--composition`: L_d − L_d^E
/// expanded in h along the solutions of the intended Lagrangian (Marsden & West 2001, §2.3.1
/// and Theorem 2.3.1), the method's L_d written with its interior points (the Galerkin control
/// points of modified/galerkin_dl.hpp; the points a composition's stages pass through) and
/// those eliminated as series. Printed beside the measured variational order; part of the
/// verdict when derived and the expected order is an integer (as for a typed `--ld`).
///
/// Chapter: \ref chapter-verify (section "The variational order of a composition or a Galerkin
/// method").
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vibook/core/types.hpp"
#include "vibook/modified/engine.hpp"
#include "vibook/modified/galerkin_dl.hpp"
#include "vibook/modified/ginac_eigen.hpp"
#include "vibook/verify/composition_study.hpp"
#include "vibook/verify/expression.hpp"
#include "vibook/verify/method_study.hpp"

namespace vibook::verify {

/// When the engine is run: `auto` where it is quick (one degree of freedom, a Lagrangian
/// polynomial in q and v, or order at most 4; Kepler in 2-D to h^7 takes minutes), `always`,
/// `never` (`vibook verify --symbolic`).
enum class SymbolicUse { automatic, always, never };

/// "auto", "always", "never"; ArgumentError("--symbolic") otherwise.
SymbolicUse parse_symbolic_use(const std::string& s);

/// Set `study.derive_variational_order` for the Galerkin method `spec` on the Lagrangian `L` of
/// `dim` degrees of freedom (1 to 3; the engine's symbols J.x(0, i), J.x(1, i) are passed for
/// q_i, v_i). Gauss with four nodes is derived on cut_quadrature (by default in one degree of
/// freedom only: in two it takes minutes). With SymbolicUse::never the report says why it was
/// not derived.
void derive_galerkin_variational_order(const MethodSpec& spec, int dim,
                                       modified::SymbolicLagrangian L, SymbolicUse use,
                                       MapStudy& study);

/// A Galerkin rule without a closed form (Gauss with four nodes or more) as the engine takes it:
/// the nodes computed at 120 digits and cut to 30, placed symmetrically about 1/2, the weights
/// their interpolatory ones in exact arithmetic (method_symbolic.cpp says why the cut and the
/// threshold composition_zero_below() separate rounding from a defect).
modified::ExactQuadrature cut_quadrature(const Quadrature& rule);
/// The variational order the engine derives for the Galerkin method of `rule` on a test
/// problem's Lagrangian, through h^{K+1}: the first k whose term of L_d − L_d^E has a number at
/// or above `zero_below` (any nonzero number when unset); −1 when there is none. For tests.
int galerkin_variational_order(const modified::ExactQuadrature& rule, const std::string& problem,
                               int K, std::optional<GiNaC::numeric> zero_below);

/// The same for a composition on a test problem ("pendulum", "kepler", "henon-heiles"): bases
/// sv, midpoint, se and se-adjoint, coefficients exact rationals (a typed list of exact
/// decimals or ratios; ruth3). Otherwise the report says why it is not derived.
void derive_composition_variational_order(const CompositionSpec& spec, const std::string& problem,
                                          SymbolicUse use, MapStudy& study);

/// A catalogue entry's coefficients as the engine takes them: computed at kCompositionDigits
/// digits, the rationals of their first 30 (Ruth's exactly), with the adjoint marks. A composition
/// of these has terms of L_d − L_d^E near the coefficients' rounding; the derivation counts a term
/// with every number below kCompositionZeroBelow as zero and says so in the report.
std::vector<std::pair<GiNaC::numeric, bool>> catalogue_rationals(const std::string& name);
/// 1e-20, the threshold for every coefficient cut to finite precision (the catalogue's and
/// cut_quadrature's): the least precise catalogue entry (Kahan & Li's, as published) has 26
/// digits.
GiNaC::numeric composition_zero_below();

/// The variational order the engine derives for the composition of `base` (sv, midpoint, se,
/// se-adjoint) with `stages` on a test problem's Lagrangian, through h^{K+1}: the first k
/// whose term of L_d − L_d^E has a number at or above `zero_below` (any nonzero number when
/// unset); −1 when there is none. The route the report takes, for tests.
int composition_variational_order(const std::string& base,
                                  const std::vector<std::pair<GiNaC::numeric, bool>>& stages,
                                  const std::string& problem, int K,
                                  std::optional<GiNaC::numeric> zero_below);

/// Shen & Sun 2025, Theorem 10, on a Runge–Kutta–Nyström tableau (c, ā, b̄ and the velocity
/// weights b, their b̂): the first two coefficients of the modified equation
/// ẍ = f + h f^[1] + h² f^[2] + …, f^[1] = α f'ẋ and f^[2] = β₁ f''⟨ẋ,ẋ⟩ + β₂ f'f, with
///   α  = −1 + Σ_i (b_i c_i + b̄_i),
///   β₁ = −1/12 + ½ [1 + Σ_i (b_i c_i² + 2(b̄_i − b_i) c_i − b̄_i)],
///   β₂ = −1/12 + ½ [1 + Σ_i (2 b̄_i c_i − b_i c_i − b̄_i) + 2 Σ_i Σ_j b_i (ā_ij − c_i b̄_j)],
/// as the theorem prints them with the weight b_i of the last sum restored (the ledger's
/// SS-ERR-L421); the theorem assumes Σ b_i = 1. Each is computed exactly on the rationals of
/// the entries' 120 digits, and compared with the modified equation the engine derives for the
/// same tableau on a generic force in one degree of freedom (modified::nystrom_modified_equation).
struct NystromTheorem10 {
  double alpha = 0, beta1 = 0, beta2 = 0;
  double weights_residual = 0;  ///< |Σ b_i − 1|
  /// The largest coefficient of (engine − theorem) in the h and h² terms (0: they agree
  /// exactly, as every number is a rational).
  double h1_difference = 0, h2_difference = 0;
};
NystromTheorem10 nystrom_theorem10(const std::vector<mpfr_real>& c,
                                   const std::vector<std::vector<mpfr_real>>& abar,
                                   const std::vector<mpfr_real>& bbar,
                                   const std::vector<mpfr_real>& b);

/// A discrete Lagrangian L_d(q0, q1, h) on the engine's symbols (positions as vectors of
/// expressions).
using SymbolicStageDl = std::function<modified::ex(
    const std::vector<modified::ex>&, const std::vector<modified::ex>&, const modified::ex&)>;

/// The same for a composition of `ld` (`vibook verify --composition ld`, the typed L_d): its
/// stages `ld`, and `-ld(q1, q0, -h)` for those marked '*', measured against the intended `L`
/// in `dim` = 1…3 degrees of freedom. Coefficients exact rationals, as above.
void derive_composition_variational_order(const CompositionSpec& spec, int dim,
                                          const SymbolicStageDl& ld, modified::SymbolicLagrangian L,
                                          SymbolicUse use, MapStudy& study);

struct TableauSpec;  // verify/tableau_study.hpp

/// The same for a symplectic tableau (`vibook verify --tableau`): its discrete Lagrangian from
/// a and b (modified::prk_dl), the entries read exactly as written; with decimals of more than
/// six significant digits among them (D in the shortest) a term whose every number is below
/// 10^-(D-5) counts as zero, and below D = 25 it is not derived. Nothing is installed for a tableau that fails the symplecticity conditions or
/// an RKN tableau (the tableau route reports why). An empty `L` (a system typed as a
/// Hamiltonian) is reported as not derived.
void derive_tableau_variational_order(const TableauSpec& spec, int dim,
                                      modified::SymbolicLagrangian L, SymbolicUse use,
                                      MapStudy& study);

/// The intended Lagrangian of a typed system on the engine's symbols: L(q, v) as typed after
/// --lagrangian, or |v|²/2 − V(q) with V typed after --potential (not for a system typed as a
/// Hamiltonian other than |p|²/2 + V). `sys` must outlive it.
template <int N>
modified::SymbolicLagrangian typed_lagrangian(const TypedDiscreteLagrangian* sys) {
  return [sys](const std::vector<modified::ex>& q, const std::vector<modified::ex>& v) {
    Vec<modified::ex, N> x, u;
    for (int i = 0; i < N; ++i) {
      x(i) = q[static_cast<std::size_t>(i)];
      u(i) = v[static_cast<std::size_t>(i)];
    }
    if (!sys->default_system() && !sys->has_hamiltonian())
      return sys->lagrangian<N, modified::ex>(x, u);
    return modified::exact_rationals(u.squaredNorm() / 2 - sys->potential<N, modified::ex>(x));
  };
}

/// The intended Lagrangian |v|²/2 − U(q) of a test problem ("pendulum", "kepler",
/// "henon-heiles") on symbols.
modified::SymbolicLagrangian test_problem_lagrangian(const std::string& problem);

}  // namespace vibook::verify
