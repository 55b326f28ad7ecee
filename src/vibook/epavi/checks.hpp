/// \file checks.hpp
/// \brief The checks and figures of Sharma et al. 2022 (EpAVI against AVI): Figs. 1–5, (29),
/// (39)–(41), Lemma 1, and the long study of (29).
/// The registry (`figures/registry.hpp`) lists these in a fixed order; `vibook figure ID`
/// and the doctests beside them call the same functions.
///
/// Chapter: \ref chapter-epavi.
#pragma once

#include "vibook/claims/check.hpp"

namespace vibook::checks {

using claims::Check;
using claims::Context;

Check sharma_fig1();       ///< sharma-fig1: S-F1, S-F3 (sharma_fig12.cpp)
Check sharma_fig2();       ///< sharma-fig2: S-F2, S-F3 (sharma_fig12.cpp)
Check sharma_fig3();       ///< sharma-fig3: S-F3 (sharma_studies.cpp)
Check sharma_fig4();       ///< sharma-fig4: S-F4 (sharma_studies.cpp)
Check sharma_fig5();       ///< sharma-fig5: S-F5 (sharma_studies.cpp)
Check check_s_eq29();      ///< check-s-eq29: S-EQ29 (sharma_studies.cpp)
Check check_s_eq39();      ///< check-s-eq39: S-EQ39, S-ERR-39, S-ERR-40 (sharma_studies.cpp)
Check check_s_l1();        ///< check-s-l1: S-L1 (sharma_studies.cpp)
Check epavi_existence();   ///< epavi-existence: S-X-EXIST (sharma_studies.cpp)
Check sharma_eq29_long();  ///< sharma-eq29-long: S-EQ29 (long study) (sharma_eq29_long.cpp)
/// The long study at a fraction `scale` of its length (the doctest runs it small).
std::vector<claims::ClaimResult> run_eq29_long(const Context& ctx, double scale);

}  // namespace vibook::checks
