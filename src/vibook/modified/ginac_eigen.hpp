/// \file ginac_eigen.hpp
/// \brief GiNaC expressions as an Eigen scalar, so that the discrete Lagrangians written for
/// the integrators (templates over the scalar type) can be evaluated symbolically. Only the
/// arithmetic the discrete Lagrangians use is needed: +, −, ×, / and scalar × vector.
///
/// Chapter: \ref chapter-modified.
#pragma once

#include <cmath>
#include <cstdint>
#include <stdexcept>

#include <ginac/ginac.h>
#include <Eigen/Core>

#include "vibook/core/types.hpp"

namespace Eigen {
template <>
struct NumTraits<GiNaC::ex> : GenericNumTraits<GiNaC::ex> {
  using Real = GiNaC::ex;
  using NonInteger = GiNaC::ex;
  using Nested = GiNaC::ex;
  using Literal = GiNaC::ex;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 1,
    AddCost = 10,
    MulCost = 10
  };
};
template <class BinOp>
struct ScalarBinaryOpTraits<GiNaC::ex, double, BinOp> {
  using ReturnType = GiNaC::ex;
};
template <class BinOp>
struct ScalarBinaryOpTraits<double, GiNaC::ex, BinOp> {
  using ReturnType = GiNaC::ex;
};
}  // namespace Eigen

namespace vibook {
/// constant<ex>(x): the exact rational value of the binary64 number x (0.5 is 1/2, 1 is 1).
/// GiNaC would make ex(x) a floating-point number, and a floating-point number times an exact
/// rational is a floating-point number again: a Kepler potential written as
/// `-constant<S>(1) / r` times the split weight 3/10 became −0.3 in binary64, so
/// `vibook modified --alpha 3/10` printed 18014398509481983/18014398509481984 for 1.
template <>
inline GiNaC::ex constant<GiNaC::ex>(double x) {
  if (!std::isfinite(x)) throw std::domain_error("vibook::constant<GiNaC::ex>: non-finite literal");
  if (x == 0) return GiNaC::ex(GiNaC::numeric(0));
  int e2 = 0;
  const double m = std::frexp(x, &e2);  // x = m · 2^e2, |m| in [1/2, 1)
  const auto mant = static_cast<std::int64_t>(std::ldexp(m, 53));
  return GiNaC::numeric(static_cast<long>(mant)) * GiNaC::pow(GiNaC::numeric(2), e2 - 53);
}
}  // namespace vibook
