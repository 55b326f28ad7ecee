/// \file checks.hpp
/// \brief The checks of extended discrete mechanics (Sharma et al. 2022 §2.2): claim S-DEL.
/// The registry (`figures/registry.hpp`) lists these in a fixed order; `vibook figure ID`
/// and the doctests beside them call the same functions.
///
/// Chapter: \ref chapter-extended.
#pragma once

#include "vibook/claims/check.hpp"

namespace vibook::checks {

using claims::Check;
using claims::Context;

Check check_s_del();  ///< check-s-del: S-DEL, S-ERR-14 (check_s_del.cpp)

}  // namespace vibook::checks
