/// \file checks.hpp
/// \brief The checks and figures of modified equations and modified Lagrangians
/// (Vermeeren 2017 §3–5, Sharma et al. 2022 §4.4, Shen & Sun 2025 §4 and App. A).
/// The registry (`figures/registry.hpp`) lists these in a fixed order; `vibook figure ID`
/// and the doctests beside them call the same functions.
///
/// Chapter: \ref chapter-modified.
#pragma once

#include "vibook/claims/check.hpp"

namespace vibook::checks {

using claims::Check;
using claims::Context;

Check vermeeren_fig1();  ///< vermeeren-fig1: V-EX3 (vermeeren_fig1.cpp)
Check check_modified();  ///< check-modified: every printed modified equation and Lagrangian
                         ///< (check_modified.cpp)
Check check_v_t16();     ///< check-v-t16: V-T16, V-SE, SS-ERR-4.24 (check_v_t16.cpp)
Check vermeeren_fig3();  ///< vermeeren-fig3: V-EX4 (vermeeren_fig3.cpp)
Check shen_sun_fig1();   ///< shen-sun-fig1: SS-F1 (shen_sun_fig1.cpp)

}  // namespace vibook::checks
