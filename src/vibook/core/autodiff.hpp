/// \file autodiff.hpp
/// \brief Eigen AutoDiff helpers: first derivatives, and mixed second derivatives by
/// nesting one AutoDiffScalar inside another (forward over forward).
///
/// User code writes a function once, templated on its scalar (a generic lambda is enough);
/// these helpers evaluate it on AutoDiff scalars. Constants may be written as plain
/// `double` literals: the trait specialisations below let nested AutoDiff scalars mix
/// with `double` inside Eigen expressions.
#pragma once

// Eigen/Dense must precede the unsupported AutoDiff module.
#include "vibook/core/types.hpp"

#include <unsupported/Eigen/AutoDiff>

#include <type_traits>

namespace Eigen {
// Eigen declares AutoDiffScalar<D> (op) D::Scalar. When D::Scalar is not double (nested
// AutoDiff, whose D::Scalar is itself an AutoDiffScalar, or AutoDiff over dd_real and
// Boost.Multiprecision), `vector * 0.5` would not compile. Declare the double case.
template <class T, int R, class BinOp>
requires(!std::is_same_v<T, double>) struct ScalarBinaryOpTraits<AutoDiffScalar<Matrix<T, R, 1>>,
                                                                 double, BinOp> {
  using ReturnType = AutoDiffScalar<Matrix<T, R, 1>>;
};
template <class T, int R, class BinOp>
requires(!std::is_same_v<T, double>) struct ScalarBinaryOpTraits<
    double, AutoDiffScalar<Matrix<T, R, 1>>, BinOp> {
  using ReturnType = AutoDiffScalar<Matrix<T, R, 1>>;
};
}  // namespace Eigen

namespace vibook::ad {

/// First-order forward AutoDiff scalar over T with N directional derivatives.
template <int N, class T = double>
using Dual = Eigen::AutoDiffScalar<Vec<T, N>>;

/// Second-order (nested) forward AutoDiff scalar: value and derivatives are Dual<N, T>.
template <int N, class T = double>
using Dual2 = Eigen::AutoDiffScalar<Eigen::Matrix<Dual<N, T>, N, 1>>;

/// Seed x as the N independent variables of a Dual<N, T> vector.
template <int N, class T = double>
Vec<Dual<N, T>, N> variables(const Vec<T, N>& x) {
  Vec<Dual<N, T>, N> v;
  for (int i = 0; i < N; ++i) v(i) = Dual<N, T>(x(i), N, i);
  return v;
}

/// Seed x as the N independent variables of a Dual2<N, T> vector: each variable's value a
/// Dual<N, T> seeded as by `variables`, and its outer derivatives the same unit vector (the
/// value, gradient and Hessian of f come out of one evaluation of f on them).
template <int N, class T = double>
Vec<Dual2<N, T>, N> variables2(const Vec<T, N>& x) {
  using In = Dual<N, T>;
  Vec<Dual2<N, T>, N> v;
  for (int i = 0; i < N; ++i) {
    v(i) = Dual2<N, T>(In(x(i), N, i));
    v(i).derivatives().setZero();
    v(i).derivatives()(i) = In(T(1));
  }
  return v;
}

/// Compile-time guard: a callable evaluated on AutoDiff scalars must return the scalar type
/// itself. An Eigen AutoDiff *expression* returned from a lambda with a deduced return type
/// refers to temporaries that are gone when the lambda returns.
template <class Result, class Scalar>
inline constexpr bool returns_scalar = std::is_same_v<std::remove_cvref_t<Result>, Scalar>;

#define VIBOOK_RETURNS_SCALAR_MESSAGE                                                    \
  "vibook: the function must return its scalar type, not an Eigen AutoDiff expression; " \
  "declare the lambda's return type, e.g. `-> vibook::scalar_t<decltype(h)>`"

/// Gradient of a scalar function f(Vec<S,N>) -> S at x.
template <int N, class F>
Vec<double, N> gradient(F&& f, const Vec<double, N>& x) {
  using R = decltype(f(variables<N>(x)));
  static_assert(returns_scalar<R, Dual<N>>, VIBOOK_RETURNS_SCALAR_MESSAGE);
  return f(variables<N>(x)).derivatives();
}

/// Jacobian of a vector function f(Vec<S,N>) -> Vec<S,N> at x (row i = d f_i / d x), in the
/// arithmetic T of x (double, or double-double for an order study in extended precision).
template <int N, class F, class T = double>
Mat<T, N> jacobian(F&& f, const Vec<T, N>& x) {
  const Vec<Dual<N, T>, N> y = f(variables<N, T>(x));
  Mat<T, N> J;
  for (int i = 0; i < N; ++i) J.row(i) = y(i).derivatives().transpose();
  return J;
}

/// Value and all first and mixed second derivatives of a two-point function F(a, b, c)
/// (c a parameter, not differentiated): D1 = dF/da, D2 = dF/db, D12(i, j) = d²F/da_i db_j.

template <int N, class T = double>
struct TwoPoint {
  T value{};
  Vec<T, N> D1, D2;
  Mat<T, N> D12;
};

/// Evaluate F(a, b, c) once on nested dual numbers: a carries the inner derivatives,
/// b the outer ones, so the mixed block comes out of a single evaluation.
template <int N, class F, class T = double>
TwoPoint<N, T> two_point(F&& f, const Vec<T, N>& a, const Vec<T, N>& b, const T& c) {
  using In = Dual<N, T>;
  using Out = Dual2<N, T>;
  Vec<Out, N> A, B;
  for (int i = 0; i < N; ++i) {
    A(i) = Out(In(a(i), N, i));
    A(i).derivatives().setZero();
    B(i) = Out(In(b(i)));
    B(i).derivatives().setZero();
    B(i).derivatives()(i) = In(T(1));
  }
  Out C{In(c)};
  C.derivatives().setZero();
  static_assert(returns_scalar<decltype(f(A, B, C)), Out>, VIBOOK_RETURNS_SCALAR_MESSAGE);
  const Out r = f(A, B, C);
  TwoPoint<N, T> out;
  out.value = r.value().value();
  out.D1 = r.value().derivatives();
  for (int j = 0; j < N; ++j) {
    out.D2(j) = r.derivatives()(j).value();
    out.D12.col(j) = r.derivatives()(j).derivatives();
  }
  return out;
}

/// ∇²V(x) of a mechanical problem: the problem's own `hessian(q)` when it has one (Kepler
/// writes it out), else one level of forward AutoDiff on its `gradient(q)`. Used by the
/// closed-form steppers (epavi/mechanical.hpp, avi/avi.hpp) for their Newton matrices.
template <class Problem, class T, int N>
Mat<T, N> potential_hessian(const Problem& P, const Vec<T, N>& x) {
  if constexpr (requires { P.hessian(x); }) {
    return P.hessian(x);
  } else {
    Vec<Dual<N, T>, N> y;
    for (int i = 0; i < N; ++i) y(i) = Dual<N, T>(x(i), N, i);
    const Vec<Dual<N, T>, N> g = P.gradient(y);
    Mat<T, N> H;
    for (int i = 0; i < N; ++i) H.row(i) = g(i).derivatives().transpose();
    return H;
  }
}

}  // namespace vibook::ad
