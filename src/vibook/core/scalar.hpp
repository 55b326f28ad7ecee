/// \file scalar.hpp
/// \brief What the solvers need to know of a scalar type: its nearest double, whether it is
/// finite, its unit round-off. Built in for double, long double and float; precision.hpp adds
/// libqd's dd_real and Boost.Multiprecision (include it to use them, and link
/// vibook::precision). Keeping those out of here is what lets the core headers (newton.hpp,
/// the integrators) be used with Eigen alone.
///
/// To teach vibook a scalar type of your own, specialise ScalarTraits:
/// \code
///   template <> struct vibook::ScalarTraits<MyReal> {
///     static double to_double(const MyReal& x);
///     static bool is_finite(const MyReal& x);
///     static MyReal unit_roundoff();  // 2^(1-p) for a p-bit significand
///   };
/// \endcode
/// A specialisation is found wherever it is declared before use, whatever the include order.
/// It may also give `static MyReal half(const MyReal& x)`, x/2 exactly, where that is cheaper
/// than a product with 0.5 (libqd's dd_real does); half() below uses it when present.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

namespace vibook {

/// Customisation point for scalar types (see the file comment).
template <class T, class Enable = void>
struct ScalarTraits;

/// The built-in floating-point types.
template <class T>
struct ScalarTraits<T, std::enable_if_t<std::is_floating_point_v<T>>> {
  static double to_double(T x) { return static_cast<double>(x); }
  static bool is_finite(T x) { return std::isfinite(x); }
  static T unit_roundoff() { return std::numeric_limits<T>::epsilon(); }
};

/// Nearest double.
template <class T>
double to_double(const T& x) {
  return ScalarTraits<T>::to_double(x);
}

/// Is x finite (no NaN, no infinity)?
template <class T>
bool is_finite(const T& x) {
  return ScalarTraits<T>::is_finite(x);
}

/// x/2: ScalarTraits<T>::half when the traits give one, else the product with 0.5.
template <class T>
T half(const T& x) {
  if constexpr (requires { ScalarTraits<T>::half(x); })
    return ScalarTraits<T>::half(x);
  else
    return x * T(0.5);
}

/// Unit round-off (2^{1−p}) of the type, at the current precision for run-time precisions.
template <class T>
T unit_roundoff() {
  return ScalarTraits<T>::unit_roundoff();
}

}  // namespace vibook
