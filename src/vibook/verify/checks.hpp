/// \file checks.hpp
/// \brief The checks of the chapter "Verify your own integrator": the field audit of published
/// composition methods and Galerkin variational integrators (claims A-…, field_audit.hpp).
/// The registry (`figures/registry.hpp`) lists these in a fixed order; `vibook claims --check ID`
/// and the doctests beside them call the same functions.
///
/// Chapter: \ref chapter-verify.
#pragma once

#include "vibook/claims/check.hpp"

namespace vibook::checks {

using claims::Check;
using claims::Context;

Check field_audit();  ///< field-audit: A-YOSHIDA4 … A-RUTH3, A-WRONG-* (field_audit.cpp)
/// field-audit-odeint: A-ODEINT-*, A-WRONG-EXPLICIT-EULER, A-WRONG-CACHED (field_audit.cpp)
Check field_audit_odeint();
/// field-audit-splitting: A-SPLIT-*, A-WRONG-SPLIT-* (field_audit.cpp)
Check field_audit_splitting();
/// field-audit-galerkin: A-GAUSS1 … A-LOBATTO5 (long study, field_audit.cpp)
Check field_audit_galerkin();
/// field-audit-systems: A-RATTLE, A-WRONG-SHAKE, A-FORCED-* (long study, field_audit.cpp)
Check field_audit_systems();

}  // namespace vibook::checks
