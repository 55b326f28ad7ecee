/// \file checks.hpp
/// \brief The checks and figures of relativistic Kepler (Shen & Sun 2025 §2 (2.7), §3
/// (3.16)–(3.22), §5): Theorem 8, Fig. 7, the precession sweep.
/// The registry (`figures/registry.hpp`) lists these in a fixed order; `vibook figure ID`
/// and the doctests beside them call the same functions.
///
/// Chapter: \ref chapter-relativistic.
#pragma once

#include "vibook/claims/check.hpp"

namespace vibook::checks {

using claims::Check;
using claims::Context;

Check check_ss_t8();              ///< check-ss-t8: SS-T8 and its errata (shen_sun_fig7.cpp)
Check shen_sun_fig7();            ///< shen-sun-fig7: SS-F7 (shen_sun_fig7.cpp)
Check relativistic_precession();  ///< relativistic-precession: SS-F7 (shen_sun_fig7.cpp)

}  // namespace vibook::checks
