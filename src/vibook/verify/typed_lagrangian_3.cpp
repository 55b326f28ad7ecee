/// \file typed_lagrangian_3.cpp
/// \brief set_typed_lagrangian's templates (typed_lagrangian_impl.hpp) for three degrees of
/// freedom, compiled apart from one and two (typed_lagrangian_study.cpp).
#include "vibook/verify/typed_lagrangian_impl.hpp"

namespace vibook::verify::typed_lagrangian_detail {
template void set_lagrangian_system<3>(MapStudy&, const verify::TypedDiscreteLagrangian&,
                                       const std::vector<double>&, const std::vector<double>&);
}  // namespace vibook::verify::typed_lagrangian_detail
