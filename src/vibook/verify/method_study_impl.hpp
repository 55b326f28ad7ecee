/// \file method_study_impl.hpp
/// \brief The parts of method_study.cpp that the typed route (method_typed.cpp) shares: the
/// Galerkin one-step map of any Lagrangian L(q, v), or of L = |v|²/2 − V(q) for a problem type
/// with `potential<T>(q)`, and the report around the measurement. Internal: not installed.
#pragma once

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include <nlohmann/json.hpp>

#include "vibook/integrators/galerkin.hpp"
#include "vibook/verify/map_study.hpp"
#include "vibook/verify/method_study.hpp"

namespace vibook::verify::method_detail {

// A test problem's L = |v|²/2 − V(q) as a callable L(q, v), its return type declared, as
// AutoDiff needs (autodiff.hpp). It declares itself of unit mass and gives V, so that the
// Galerkin step differentiates V alone (galerkin_detail::UnitMassMechanical).
template <class P>
struct MechanicalLagrangian {
  static constexpr bool unit_mass_mechanical = true;
  P prob;
  template <class Q, class V>
  auto operator()(const Q& q, const V& v) const -> std::remove_cvref_t<decltype(q(0))> {
    using T = std::remove_cvref_t<decltype(q(0))>;
    return constant<T>(0.5) * squared_norm(v) - prob.template potential<T>(q);
  }
  template <class T>
  T potential(const Vec<T, P::N>& q) const {
    return prob.template potential<T>(q);
  }
};

template <class P>
MechanicalLagrangian<P> mechanical_lagrangian_of(P prob) {
  return {prob};
}

// The one-step map of the Galerkin integrator of the Lagrangian `lagrangian(q, v)` (a callable
// templated on the scalar, its return type declared, as AutoDiff needs) with N degrees of
// freedom (one instance per Lagrangian: the number of stages is the rule's, at run time, as in
// GalerkinIntegrator<N, Eigen::Dynamic, L>); the rest of the report depends on the system only.
// With it, the step that also returns the step's discrete Lagrangian (the variational order).
// `who` names the caller in the message for a number of stages outside 1..5, the catalogue's
// range.
template <int N, class L>
std::pair<Step, GeneratingStep> galerkin_step_of(const L& lagrangian, const Quadrature& rule,
                                                 const char* who) {
  if (rule.c.empty() || rule.c.size() > 5)
    throw std::invalid_argument(std::string(who) + ": 1 to 5 stages");
  using Integrator = GalerkinIntegrator<N, Eigen::Dynamic, L>;
  auto integrator = std::make_shared<Integrator>(lagrangian, rule);
  auto generating = std::make_shared<Integrator>(lagrangian, rule);
  return {naming_failures(
              [integrator](Eigen::VectorXd& z, double h) { step_qp<N>(*integrator, z, h); }, N),
          [generating](Eigen::VectorXd& z, double h) {
            step_qp<N>(*generating, z, h);
            return generating->action();
          }};
}

// The same for L = |v|²/2 − V(q), V the problem type's `potential<T>(q)`.
template <class P>
std::pair<Step, GeneratingStep> galerkin_step(const P& prob, const Quadrature& rule,
                                              const char* who) {
  return galerkin_step_of<P::N>(mechanical_lagrangian_of(prob), rule, who);
}

// The Galerkin integrator of `rule` on the test problem `problem` in double-double: its step
// and its step with the discrete Lagrangian (method_study_dd.cpp).
struct GalerkinDD {
  StepDD step;
  GeneratingStepDD generating;
};
GalerkinDD galerkin_dd(const std::string& problem, const Quadrature& rule);

// The method's lines, then the measurement of map_study.hpp; N degrees of freedom.
void measure(const MethodSpec& p, int N, const StudySystem& system, MapStudy s, MapMeasurement& rep,
             std::pair<Step, GeneratingStep> steps);

}  // namespace vibook::verify::method_detail
