/// \file checks.hpp
/// \brief The checks of the variational-integrator basics (Vermeeren 2017 §2, Example 1;
/// Proposition 1): claims V-EX1, V-P1.
/// The registry (`figures/registry.hpp`) lists these in a fixed order; `vibook figure ID`
/// and the doctests beside them call the same functions.
///
/// Chapter: \ref chapter-vi.
#pragma once

#include "vibook/claims/check.hpp"

namespace vibook::checks {

using claims::Check;
using claims::Context;

Check check_v_ex1();  ///< check-v-ex1: V-EX1, V-P1, V-ERR-5 (check_v_ex1.cpp)

}  // namespace vibook::checks
