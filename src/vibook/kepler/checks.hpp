/// \file checks.hpp
/// \brief The checks and figures of the Kepler problem and its LRL vector (Shen & Sun 2025
/// §2–5): Helmholtz conditions, Noether characteristics, splitting VIs, Figs. 2–6.
/// The registry (`figures/registry.hpp`) lists these in a fixed order; `vibook figure ID`
/// and the doctests beside them call the same functions.
///
/// Chapter: \ref chapter-kepler-lrl.
#pragma once

#include "vibook/claims/check.hpp"

namespace vibook::checks {

using claims::Check;
using claims::Context;

Check check_ss_t2();              ///< check-ss-t2: SS-T2 (check_ss_t2_p4.cpp)
Check check_ss_p4();              ///< check-ss-p4: SS-P4 (check_ss_t2_p4.cpp)
Check check_ss_t6();              ///< check-ss-t6: SS-T6, SS-T7 (shen_sun_kepler.cpp)
Check shen_sun_fig2();            ///< shen-sun-fig2: SS-F2 (shen_sun_kepler.cpp)
Check shen_sun_fig345();          ///< shen-sun-fig345: SS-F3, SS-F4, SS-F5 (shen_sun_kepler.cpp)
Check shen_sun_fig6();            ///< shen-sun-fig6: SS-F6 (shen_sun_kepler.cpp)
Check shen_sun_work_precision();  ///< shen-sun-work-precision: no claim (figure only)
                                  ///< (shen_sun_kepler.cpp)
Check check_ss_t13();             ///< check-ss-t13: SS-T13 (shen_sun_kepler.cpp)

}  // namespace vibook::checks
