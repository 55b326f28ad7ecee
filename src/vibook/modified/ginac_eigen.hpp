/// \file ginac_eigen.hpp
/// \brief GiNaC expressions as an Eigen scalar, so that the discrete Lagrangians written for
/// the integrators (templates over the scalar type) can be evaluated symbolically. Only the
/// arithmetic the discrete Lagrangians use is needed: +, −, ×, / and scalar × vector.
#pragma once

#include <ginac/ginac.h>
#include <Eigen/Core>

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
