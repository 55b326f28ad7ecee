// clang-format off
/// \file precision.hpp
/// \brief Opt-in extended precision: the floating-point types a vibook step can be templated
/// on, and what Eigen and the AutoDiff module need to use them. Use it through the CMake
/// target `vibook::precision` (or pkg-config `vibook-precision`), which links libqd, MPFR,
/// GMP and libquadmath; the rest of the core needs none of them.
///
/// | `--precision`   | C++ type             | significand | library                                   |
/// |-----------------|----------------------|-------------|-------------------------------------------|
/// | `double`        | `double`             | 53 bits     | —                                         |
/// | `long-double`   | `long double`        | 64 bits     | — (x87 extended on x86-64)                |
/// | `double-double` | `dd_real`            | 106 bits    | libqd (Debian `libqd-dev`)                |
/// | `quad`          | `vibook::quad`       | 113 bits    | Boost.Multiprecision float128 (libquadmath) |
/// | `mpfr`          | `vibook::mpfr_real`  | `--digits`  | Boost.Multiprecision + MPFR               |
///
/// `mpfr_real` has a run-time precision in decimal digits (Sharma et al.'s MATLAB VPA with 18
/// digits is `--precision mpfr --digits 18`); set it with MpfrDigits before creating values.
///
/// **Constants.** A Lagrangian evaluated on nested AutoDiff over one of these types cannot
/// mix in a `double` literal (C++ allows one user-defined conversion, the nesting needs two).
/// Write `constant<S>(0.5)` (types.hpp) for a literal in generic code, and `squared_norm(v)`
/// (types.hpp) for |v|²: Eigen's squaredNorm() and dot() build `Scalar(0)` from an int.
// clang-format on
#pragma once

#include <qd/dd_real.h>

#include <boost/multiprecision/eigen.hpp>
#include <boost/multiprecision/float128.hpp>
#include <boost/multiprecision/mpfr.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <string_view>

#include "vibook/core/errors.hpp"
#include "vibook/core/scalar.hpp"
#include "vibook/core/types.hpp"

namespace vibook {

/// IEEE binary128 through GCC's __float128 and libquadmath.
using quad = boost::multiprecision::float128;
/// MPFR with a run-time number of decimal digits; no expression templates (Eigen and AutoDiff
/// need plain values).
using mpfr_real = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<0>,
                                                boost::multiprecision::et_off>;

/// Sets the precision (decimal digits) of mpfr_real values created while the object lives;
/// restores the previous precision afterwards. In Boost 1.74 this default is process-wide, not
/// per thread: set it before starting threads that create mpfr_real values, never inside them.
/// The decimal digits `--precision mpfr` accepts. Below 8 the round-off (above 1e-8) cannot
/// resolve the solvers' default tolerance of 4 units; above 300 it falls below what a double
/// represents, and the solvers' tolerances (Options::tol, Newton's step_rel) are doubles.
inline constexpr unsigned kMpfrMinDigits = 8, kMpfrMaxDigits = 300;

class MpfrDigits {
 public:
  explicit MpfrDigits(unsigned digits) : previous_(mpfr_real::default_precision()) {
    if (digits < kMpfrMinDigits || digits > kMpfrMaxDigits)
      throw ArgumentError("--digits", "must lie in [" + std::to_string(kMpfrMinDigits) + ", " +
                                          std::to_string(kMpfrMaxDigits) + "], got " +
                                          std::to_string(digits));
    mpfr_real::default_precision(digits);
  }
  ~MpfrDigits() { mpfr_real::default_precision(previous_); }
  MpfrDigits(const MpfrDigits&) = delete;
  MpfrDigits& operator=(const MpfrDigits&) = delete;

 private:
  unsigned previous_;
};

/// libqd's double-double (106-bit significand).
template <>
struct ScalarTraits<dd_real> {
  static double to_double(const dd_real& x) { return ::to_double(x); }
  static bool is_finite(const dd_real& x) { return std::isfinite(x.x[0]) && std::isfinite(x.x[1]); }
  static dd_real unit_roundoff() { return dd_real(dd_real::_eps); }
  /// x/2, exactly and without a double-double product (optional member, see scalar.hpp).
  static dd_real half(const dd_real& x) { return mul_pwr2(x, 0.5); }
};

/// Boost.Multiprecision numbers (quad, mpfr_real): the round-off at the current precision.
template <class B, boost::multiprecision::expression_template_option E>
struct ScalarTraits<boost::multiprecision::number<B, E>> {
  using T = boost::multiprecision::number<B, E>;
  static double to_double(const T& x) { return x.template convert_to<double>(); }
  static bool is_finite(const T& x) { return boost::multiprecision::isfinite(x); }
  static T unit_roundoff() { return std::numeric_limits<T>::epsilon(); }
};

/// The precisions of the command line, in the order of the table above.
enum class Precision { double_, long_double, double_double, quad, mpfr };

/// Parses a `--precision` value; ArgumentError naming the argument otherwise.
inline Precision parse_precision(std::string_view s) {
  if (s == "double") return Precision::double_;
  if (s == "long-double") return Precision::long_double;
  if (s == "double-double") return Precision::double_double;
  if (s == "quad") return Precision::quad;
  if (s == "mpfr") return Precision::mpfr;
  throw ArgumentError("--precision", "unknown precision '" + std::string(s) +
                                         "' (double|long-double|double-double|quad|mpfr)");
}

inline const char* precision_name(Precision p) {
  switch (p) {
    case Precision::double_:
      return "double";
    case Precision::long_double:
      return "long-double";
    case Precision::double_double:
      return "double-double";
    case Precision::quad:
      return "quad";
    case Precision::mpfr:
      return "mpfr";
  }
  return "?";
}

/// Calls f(T{}) with T the C++ type of the precision (for mpfr_real, inside an MpfrDigits
/// scope of `digits`).
template <class F>
decltype(auto) with_precision(Precision p, unsigned digits, F&& f) {
  switch (p) {
    case Precision::long_double:
      return f((long double)0);
    case Precision::double_double:
      return f(dd_real(0.0));
    case Precision::quad:
      return f(quad(0));
    case Precision::mpfr: {
      MpfrDigits scope(digits);
      return f(mpfr_real(0));
    }
    case Precision::double_:
      break;
  }
  return f(0.0);
}

}  // namespace vibook

namespace Eigen {
/// Eigen's description of libqd's double-double (106-bit significand).
template <>
struct NumTraits<dd_real> : GenericNumTraits<dd_real> {
  using Real = dd_real;
  using NonInteger = dd_real;
  using Nested = dd_real;
  using Literal = dd_real;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 2,
    AddCost = 20,
    MulCost = 20
  };
  static dd_real epsilon() { return dd_real(dd_real::_eps); }
  static dd_real dummy_precision() { return dd_real(1e-28); }
  static dd_real highest() { return dd_real::_max; }
  static dd_real lowest() { return -dd_real::_max; }
  static int digits10() { return 31; }
};
template <class BinOp>
struct ScalarBinaryOpTraits<dd_real, double, BinOp> {
  using ReturnType = dd_real;
};
template <class BinOp>
struct ScalarBinaryOpTraits<double, dd_real, BinOp> {
  using ReturnType = dd_real;
};
}  // namespace Eigen
