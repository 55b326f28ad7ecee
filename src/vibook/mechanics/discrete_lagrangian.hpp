/// \file discrete_lagrangian.hpp
/// \brief Discrete Lagrangians from a continuous one: Vermeeren 2017, §2, Example 1 (a)–(d).
///
/// **Scaling convention.** In vibook a discrete Lagrangian `L_d(q0, q1, h)` approximates the
/// action over one step, L_d ≈ ∫ L dt ≈ h·L (the convention of Marsden & West). Then the
/// discrete Legendre maps have no extra factor: p0 = −D1 L_d, p1 = D2 L_d.
/// Vermeeren (2017) and Shen & Sun (2025) write L_disc ≈ L instead; the two are related by
/// L_d = h·L_disc. Use scaled_by_step() to bring an L_disc written in their convention into
/// ours.
///
/// A continuous Lagrangian is any callable `L(q, v)` that is generic in its scalar type (a
/// generic lambda): vibook evaluates it on double and on (nested) AutoDiff scalars.
///
/// **Return the scalar type, not an expression.** With Eigen AutoDiff, `a - b` is an
/// expression object that refers to temporaries; returned from a lambda with a deduced return
/// type it dangles. Write `-> vibook::scalar_t<decltype(h)>` (or of q). The derivative helpers
/// check this at compile time. Mixed second derivatives use nested AutoDiff, on which
/// Eigen's sqrt, sin, cos, exp and log work but `pow` does not: write integer powers as
/// products (q*q*q*q).
///
/// Chapter: \ref chapter-vi.
#pragma once

#include <type_traits>
#include <utility>

#include "vibook/core/types.hpp"

namespace vibook {

/// The scalar type of an Eigen expression or of a scalar.
template <class T>
struct scalar_of {
  using type = T;
};
template <class T>
requires requires {
  typename T::Scalar;
} &&(!requires { typename T::DerType; }) struct scalar_of<T> {
  using type = typename T::Scalar;
};
/// scalar_t<decltype(x)>: the scalar of a vector, or the type of a scalar (without cv/ref).
template <class T>
using scalar_t = typename scalar_of<std::remove_cvref_t<T>>::type;

// [discrete-lagrangians]
// Vermeeren 2017, Example 1(a): L_disc = L((x_j + x_{j+1})/2, (x_{j+1} − x_j)/h).
/// Midpoint discrete Lagrangian; generates the implicit midpoint rule.
template <class Lagrangian>
auto midpoint_dl(Lagrangian L) {
  return
      [L = std::move(L)](const auto& q0, const auto& q1, const auto& h) -> scalar_t<decltype(h)> {
        const auto qm = ((q0 + q1) * 0.5).eval();
        const auto v = ((q1 - q0) / h).eval();
        return h * L(qm, v);
      };
}

// Vermeeren 2017, Example 1(b): L_disc = ½ L(x_j, v) + ½ L(x_{j+1}, v), v = (x_{j+1} − x_j)/h.
/// Trapezoidal discrete Lagrangian; generates Störmer–Verlet for separable L.
template <class Lagrangian>
auto stormer_verlet_dl(Lagrangian L) {
  return
      [L = std::move(L)](const auto& q0, const auto& q1, const auto& h) -> scalar_t<decltype(h)> {
        const auto v = ((q1 - q0) / h).eval();
        return h * (0.5 * L(q0, v) + 0.5 * L(q1, v));
      };
}
// [discrete-lagrangians]

// Vermeeren 2017, Example 1(d); Shen & Sun 2025, (4.16): L_disc = L(x_{j+1}, v).
/// Discrete Lagrangian of the symplectic Euler method `se` of vibook: for a separable
/// L = ½|v|² − U(q) it generates q1 = q0 + h p0, p1 = p0 − h ∇U(q1) ("drift, then kick").
template <class Lagrangian>
auto symplectic_euler_dl(Lagrangian L) {
  return
      [L = std::move(L)](const auto& q0, const auto& q1, const auto& h) -> scalar_t<decltype(h)> {
        const auto v = ((q1 - q0) / h).eval();
        return h * L(q1, v);
      };
}

// Vermeeren 2017, Example 1(c): L_disc = L(x_j, v).
/// Discrete Lagrangian of the adjoint method `se-adjoint`: for separable L it generates
/// p1 = p0 − h ∇U(q0), q1 = q0 + h p1 ("kick, then drift").
template <class Lagrangian>
auto symplectic_euler_adjoint_dl(Lagrangian L) {
  return
      [L = std::move(L)](const auto& q0, const auto& q1, const auto& h) -> scalar_t<decltype(h)> {
        const auto v = ((q1 - q0) / h).eval();
        return h * L(q0, v);
      };
}

/// Bring a discrete Lagrangian written in the papers' scaling (L_disc ≈ L) into vibook's
/// (L_d ≈ h·L): L_d(q0, q1, h) = h · L_disc(q0, q1, h).
template <class DiscreteLagrangian>
auto scaled_by_step(DiscreteLagrangian Ldisc) {
  return
      [Ld = std::move(Ldisc)](const auto& q0, const auto& q1,
                              const auto& h) -> scalar_t<decltype(h)> { return h * Ld(q0, q1, h); };
}

/// The mechanical Lagrangian L = ½|v|² − U(q) of a problem with a templated potential.
template <class Problem>
auto mechanical_lagrangian(Problem problem) {
  return [P = std::move(problem)](const auto& q, const auto& v) -> scalar_t<decltype(q)> {
    using S = scalar_t<decltype(q)>;
    return constant<S>(0.5) * squared_norm(v) - P.potential(q);
  };
}

}  // namespace vibook
