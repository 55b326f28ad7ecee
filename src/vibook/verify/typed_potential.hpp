/// \file typed_potential.hpp
/// \brief The potential typed after `vibook verify --potential` as a problem type of the
/// catalogue's integrators (the Galerkin methods, method_typed_impl.hpp; the partitioned
/// Runge–Kutta methods of a tableau, tableau_typed_impl.hpp): potential<T>(q) evaluated on the
/// expression's tree in any scalar type, its gradient by forward AutoDiff on top. Internal: not
/// installed.
#pragma once

#include "vibook/core/autodiff.hpp"
#include "vibook/verify/expression.hpp"

namespace vibook::verify {

template <int Dim>
struct TypedPotential {
  static constexpr int N = Dim;
  const TypedDiscreteLagrangian* sys = nullptr;
  template <class T>
  T potential(const Vec<T, N>& q) const {
    return sys->potential<N, T>(q);
  }
  /// ∇V(q), one forward-mode AutoDiff pass over the tree (T may itself be an AutoDiff scalar,
  /// when an integrator differentiates the force).
  template <class T>
  Vec<T, N> gradient(const Vec<T, N>& q) const {
    using D = ad::Dual<N, T>;
    Vec<D, N> x;
    for (int i = 0; i < N; ++i) x(i) = D(q(i), N, i);
    return sys->potential<N, D>(x).derivatives();
  }
};

}  // namespace vibook::verify
