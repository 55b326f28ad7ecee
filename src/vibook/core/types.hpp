/// \file types.hpp
/// \brief Fixed-size Eigen vector and matrix aliases used throughout vibook.
#pragma once

#ifdef __FAST_MATH__
#error "vibook must not be compiled with -ffast-math: its tests measure round-off."
#endif

#include <type_traits>

#include <Eigen/Dense>

namespace vibook {

/// Column vector of fixed dimension N over scalar S (S = double, an AutoDiff type, ...).
template <class S, int N>
using Vec = Eigen::Matrix<S, N, 1>;

/// N-by-N matrix over scalar S.
template <class S, int N>
using Mat = Eigen::Matrix<S, N, N>;

/// The constant x in the scalar type S, for literals in code that is generic in its scalar.
/// For S = double or an AutoDiff scalar over double, `0.5 * x` works as written; over a
/// wider type (dd_real, Boost.Multiprecision) nested AutoDiff needs two conversions from
/// `double`, which C++ does not chain: write `constant<S>(0.5) * x` there.
template <class S>
S constant(double x) {
  if constexpr (requires { typename S::DerType; }) {
    return S(constant<typename S::Scalar>(x));
  } else {
    return S(x);
  }
}

/// The value x of the scalar T as a constant of S, S being T or (nested) AutoDiff over it:
/// no derivatives.
template <class S, class T>
S constant_of(const T& x) {
  if constexpr (std::is_same_v<S, T>) {
    return x;
  } else if constexpr (requires { typename S::DerType; }) {
    return S(constant_of<typename S::Scalar>(x));
  } else {
    return S(x);
  }
}

/// |v|² = Σ v_i², written as a loop. Eigen's squaredNorm() and dot() construct `Scalar(0)` from
/// an int, which nested AutoDiff over dd_real or Boost.Multiprecision cannot do; use this in
/// Lagrangians meant for the wider precisions (precision.hpp).
template <class Derived>
typename Derived::Scalar squared_norm(const Eigen::MatrixBase<Derived>& v) {
  typename Derived::Scalar acc = v(0) * v(0);
  for (Eigen::Index i = 1; i < v.size(); ++i) acc += v(i) * v(i);
  return acc;
}

/// Phase-space state (q, p) of a system with N degrees of freedom.
template <int N>
struct State {
  Vec<double, N> q = Vec<double, N>::Zero();
  Vec<double, N> p = Vec<double, N>::Zero();
};

}  // namespace vibook
