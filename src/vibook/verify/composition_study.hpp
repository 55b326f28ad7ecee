/// \file composition_study.hpp
/// \brief A composition of a base method (integrators/composition.hpp) measured on a test
/// problem of map_study.hpp: its order conditions at 120 digits, weight by weight (a
/// coefficient off in its eleventh digit shows), then the one-step map's measured order,
/// symplecticity, reversibility and energy. `vibook verify --composition` prints the
/// measurement; the field audit (field_audit.cpp) records it in the ledger.
///
/// Chapter: \ref chapter-verify (section "Compositions").
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "vibook/core/precision.hpp"
#include "vibook/integrators/composition.hpp"
#include "vibook/integrators/splitting_sequence.hpp"
#include "vibook/verify/map_study.hpp"
#include "vibook/verify/reference.hpp"

namespace vibook::verify {

/// The order conditions are evaluated at this many decimal digits.
constexpr int kCompositionDigits = 120;

/// A base method a composition can be built on.
struct CompositionBase {
  std::string name;
  bool symmetric;
  std::string description;
};
/// sv, midpoint, se, se-adjoint, vi1, vi1-adjoint, vi2.
const std::vector<CompositionBase>& composition_bases();
/// The base of that name, or nullptr.
const CompositionBase* find_composition_base(const std::string& name);

/// What is composed: a base and either a catalogue entry or stages typed exactly (parsed at
/// kCompositionDigits digits).
struct CompositionSpec {
  const CompositionBase* base = nullptr;
  const composition::CatalogueEntry* entry = nullptr;
  composition::Stages<mpfr_real> typed;  ///< used when `entry` is null
  std::string coefficients;              ///< as given: the catalogue name or the typed list
  /// The order the composition is held to; without it, the documented order (a catalogue entry
  /// on its documented base) or the order its conditions give at 1e-8.
  std::optional<double> expected;
  std::string expected_from = "--expected-order";  ///< where `expected` came from
  /// A splitting (`vibook verify --splitting`, splitting_sequence.hpp): its flows; `typed` then
  /// holds its equivalent composition of se and se-adjoint, and the order conditions are those
  /// of two flows.
  composition::Sequence<mpfr_real> flows;
  std::string flows_typed;  ///< the flows as text (the catalogue's, or as typed)
  const composition::SplittingEntry* splitting = nullptr;  ///< its catalogue entry, if any
  /// Why the coefficients cannot be given to the symbolic engine exactly (empty when they can).
  std::string not_exact;
};

/// A splitting's flows as one step in double-double on the system whose Hamilton equations are
/// `field` (in double-double, (q, p) stacked, `n` degrees of freedom, T = |p|²/2): a drift moves
/// q by c h p, a kick p by c h times the field's p-part; the coefficients are rounded from their
/// 120 digits (to_dd). For the order study where double cannot reach the asymptotic range.
StepDD splitting_step_dd(const composition::Sequence<mpfr_real>& flows, Field<dd_real> field,
                         int n);

/// The spec of a splitting: `seq` is a catalogue name or flows "drift:c1,kick:d1,…"; the base
/// is se and the stages its equivalent composition (exact ratios in `coefficients` when every
/// flow is a ratio or a decimal). ArgumentError naming `arg` when the text is not a sequence or
/// the sequence has no equivalent composition (its drifts and kicks sum to different totals).
CompositionSpec splitting_spec(const std::string& arg, const std::string& seq);

/// The verdict line of exact order conditions (a composition's, a splitting's, an RKN
/// tableau's): the order they give at 1e-12 against `expected`, the first weight (order) that
/// fails and at which word (tree), and whether the conditions hold at 1e-8 (`visible`: inexact
/// coefficients rather than a lower order); the same in rep.js["order_conditions"]. True when
/// they reach the expected order.
/// `weight` and `word` name the grading and the condition in the failure text ("order" and
/// "tree" for an RKN tableau).
bool conditions_verdict(const composition::OrderConditions& oc,
                        const composition::OrderConditions& visible, double expected,
                        const std::string& expected_from, MapMeasurement& rep,
                        const char* weight = "weight", const char* word = "word");

/// Measure the composition on `problem` from (q0, p0) with the settings of `study` (its step,
/// state, field, energy, expected order and reversibility are set here); appended to `rep`.
void measure_composition(const CompositionSpec& spec, const TestProblem& problem,
                         const std::vector<double>& q0, const std::vector<double>& p0,
                         const MapStudy& study, MapMeasurement& rep);

/// One stage of a composition on a method the caller builds (e.g. a typed discrete
/// Lagrangian): advances z = (q, p) by a step h of either sign, in place, and returns the
/// stage's discrete Lagrangian L_d(q0, q1, h) along it.
using CompositionStage = std::function<double(Eigen::VectorXd& z, double h)>;

/// Measure the composition of `base` (with its adjoint `adjoint`; spec.base names it and says
/// whether it is symmetric) on the system `study` is set up for by the caller (z0, field,
/// equations, H); `system_line` describes that system in the report. Appended to `rep`. With
/// `variational` false the stages' values are not a discrete Lagrangian the study can measure
/// (a constrained system's): the variational order is not measured.
void measure_composition(const CompositionSpec& spec, const CompositionStage& base,
                         const CompositionStage& adjoint, const std::string& system_line,
                         MapStudy study, MapMeasurement& rep, bool variational = true);

}  // namespace vibook::verify
