/// \file typed_potential.hpp
/// \brief The potential typed after `vibook verify --potential` (and the Hamiltonian typed after
/// `--hamiltonian`) as a problem type of the catalogue's integrators (the Galerkin methods,
/// method_typed_impl.hpp; the partitioned Runge–Kutta methods of a tableau,
/// tableau_typed_impl.hpp): potential<T>(q) evaluated on the expression's tree in any scalar type,
/// its gradient by forward AutoDiff on top. Internal: not installed.
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
  /// The same at the time t, for a time-dependent V(q, t) (the integrators then call set_time
  /// and evaluate each stage at its own time).
  template <class T, class Time>
  T potential(const Vec<T, N>& q, const Time& t) const {
    return sys->potential<N, T>(q, constant_of<T>(t));
  }
  template <class T, class Time>
  Vec<T, N> gradient(const Vec<T, N>& q, const Time& t) const {
    using D = ad::Dual<N, T>;
    Vec<D, N> x;
    for (int i = 0; i < N; ++i) x(i) = D(q(i), N, i);
    return sys->potential<N, D>(x, constant_of<D>(t)).derivatives();
  }
};

/// The Hamiltonian typed after `vibook verify --hamiltonian` as a problem type of
/// HamiltonianPrkMethod (tableau_typed_impl.hpp): H(q, p) on the expression's tree, ∇H by one
/// forward-mode AutoDiff pass on top (T may itself be an AutoDiff scalar, for the Hessian).
template <int Dim>
struct TypedHamiltonian {
  static constexpr int N = Dim;
  const TypedDiscreteLagrangian* sys = nullptr;
  template <class T>
  T hamiltonian(const Vec<T, N>& q, const Vec<T, N>& p) const {
    return sys->hamiltonian<N, T>(q, p);
  }
  /// (∂H/∂q, ∂H/∂p) at z = (q, p).
  template <class T>
  Vec<T, 2 * N> gradient(const Vec<T, 2 * N>& z) const {
    using D = ad::Dual<2 * N, T>;
    Vec<D, N> q, p;
    for (int i = 0; i < N; ++i) {
      q(i) = D(z(i), 2 * N, i);
      p(i) = D(z(N + i), 2 * N, N + i);
    }
    return sys->hamiltonian<N, D>(q, p).derivatives();
  }
  /// The same at the time t, for a time-dependent H(q, p, t).
  template <class T, class Time>
  T hamiltonian(const Vec<T, N>& q, const Vec<T, N>& p, const Time& t) const {
    return sys->hamiltonian<N, T>(q, p, constant_of<T>(t));
  }
  template <class T, class Time>
  Vec<T, 2 * N> gradient(const Vec<T, 2 * N>& z, const Time& t) const {
    using D = ad::Dual<2 * N, T>;
    Vec<D, N> q, p;
    for (int i = 0; i < N; ++i) {
      q(i) = D(z(i), 2 * N, i);
      p(i) = D(z(N + i), 2 * N, N + i);
    }
    return sys->hamiltonian<N, D>(q, p, constant_of<D>(t)).derivatives();
  }
};

}  // namespace vibook::verify
