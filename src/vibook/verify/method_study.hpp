/// \file method_study.hpp
/// \brief A Galerkin variational integrator (integrators/galerkin.hpp: Gauss or Lobatto, S
/// stages) measured on a test problem of map_study.hpp: measured order, symplecticity,
/// reversibility and energy of its one-step map. `vibook verify --method` prints the
/// measurement; the field audit (field_audit.cpp) records it in the ledger.
///
/// Chapter: \ref chapter-verify (section "Galerkin variational integrators").
#pragma once

#include <string>
#include <vector>

#include "vibook/integrators/galerkin.hpp"
#include "vibook/verify/map_study.hpp"

namespace vibook::verify {

/// Which Galerkin method, and the order it is held to.
struct MethodSpec {
  std::string name;  ///< as given: "gauss:3"
  Quadrature rule;   ///< quadrature_rule(family, stages)
  int stages = 0;    ///< 1 to 5
  double expected = 0;
  std::string expected_from = "documented";
};

/// Measure the method on `problem` from (q0, p0) with the settings of `study` (its step, state,
/// field, energy, expected order, cost limit and reversibility are set here); appended to
/// `rep`. std::invalid_argument for a number of stages outside 1..5.
void measure_method(const MethodSpec& spec, const TestProblem& problem,
                    const std::vector<double>& q0, const std::vector<double>& p0,
                    const MapStudy& study, MapMeasurement& rep);

class TypedDiscreteLagrangian;  // verify/expression.hpp

/// The same measurement on the user's own system: the Galerkin integrator of the Lagrangian
/// of `sys` (1 to 3 degrees of freedom, sys.dim()) — L(q, v) as typed (`vibook verify --method
/// NAME:S --lagrangian EXPR`), or L = |v|²/2 − V(q) with V typed (`--potential EXPR`) —
/// evaluated on its expression tree in nested AutoDiff. `study` carries the system already (its
/// reference field, H and z0, from the same expression); `system_line` names it in the report.
/// std::invalid_argument for a number of stages outside 1..5 or a dimension outside 1..3.
void measure_method_typed(const MethodSpec& spec, const TypedDiscreteLagrangian& sys,
                          const std::vector<double>& q0, const std::vector<double>& p0,
                          const MapStudy& study, const std::string& system_line,
                          MapMeasurement& rep);

}  // namespace vibook::verify
