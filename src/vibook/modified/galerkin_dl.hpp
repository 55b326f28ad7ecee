/// \file galerkin_dl.hpp
/// \brief The Galerkin discrete Lagrangian of integrators/galerkin.hpp as a symbolic
/// expression, for the engine (Marsden & West 2001, §2.6; Hairer, Lubich & Wanner, §VI.6.3):
///
///   L_d(q0, Q^1 … Q^{s−1}, q1, h) = h Σ_i b_i L(Σ_ν ℓ_ν(c_i) Q^ν, Σ_ν ℓ'_ν(c_i) Q^ν / h),
///
/// the quadrature action of the degree-s polynomial through the control points Q^ν at the
/// times ν/s (Q^0 = q0, Q^s = q1), with the nodes c_i and weights b_i exact. The engine
/// eliminates the interior control points Q^1 … Q^{s−1} (∂L_d/∂Q^ν = 0) as series in h, which
/// leaves the Galerkin method's two-point discrete Lagrangian; Engine::variational_order then
/// expands its difference from the exact discrete Lagrangian.
///
/// Chapter: \ref chapter-verify (section "Galerkin variational integrators").
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "vibook/modified/engine.hpp"

namespace vibook::modified {

/// A quadrature rule on [0, 1] with exact nodes and weights (rationals and square roots of
/// rationals).
struct ExactQuadrature {
  std::vector<ex> c, b;
};

/// The s-node Gauss–Legendre (family "gauss", s = 1…3) or Gauss–Lobatto ("lobatto",
/// s = 2…5) rule in closed form; std::nullopt for the others (Gauss with 4 nodes and beyond
/// has nested radicals, on which the engine's zero test, exact over ℚ(√d), cannot be relied;
/// `vibook verify` derives Gauss 4 on its nodes cut to 30 digits, verify/method_symbolic.hpp).
/// The doctests check each rule against its defining equations: exact for polynomials of
/// degree 2s − 1 (Gauss) or 2s − 3 (Lobatto, with the end points as nodes).
std::optional<ExactQuadrature> exact_quadrature(const std::string& family, int s);

/// A Lagrangian L(q, v) on symbolic vectors of N components.
using SymbolicLagrangian = std::function<ex(const std::vector<ex>& q, const std::vector<ex>& v)>;

/// The discrete Lagrangian of the file comment, with s = rule.c.size() stages (the polynomial's
/// degree) and N = jets->dofs() degrees of freedom (1 to 3); its interior points are
/// SymbolicDL::qm, started on the chord at τ = ν/s.
SymbolicDL galerkin_dl(const ExactQuadrature& rule, const SymbolicLagrangian& L,
                       std::shared_ptr<JetSpace> jets, std::string description);

/// A symplectic partitioned Runge–Kutta method as a discrete Lagrangian, from its positions'
/// tableau (a, b) alone (Suris; Marsden & West 2001, on symplectic partitioned Runge–Kutta
/// methods; Hairer, Lubich & Wanner §VI.6):
///
///   L_d(q0, q1, h) = ext h Σ_i b_i L(q0 + h Σ_j a_ij V_j, V_i)  subject to  q1 = q0 + h Σ_j b_j
///   V_j,
///
/// whose discrete Euler–Lagrange equations are the method with â_ij = b_j (1 − a_ji / b_i).
/// The constraint fixes the stage velocity V_k of the largest weight (the first of equal ones);
/// each other V_j is the interior point X_j = q0 + (h/2) V_j of SymbolicDL::qm, started on the
/// chord at τ = 1/2 (where V_j = (q1 − q0)/h), for the engine to eliminate as series in h.
/// Entries exact (rationals); every b_i nonzero (std::invalid_argument otherwise);
/// N = jets->dofs() from 1 to 3.
SymbolicDL prk_dl(const std::vector<std::vector<ex>>& a, const std::vector<ex>& b,
                  const SymbolicLagrangian& L, std::shared_ptr<JetSpace> jets,
                  std::string description);

}  // namespace vibook::modified
