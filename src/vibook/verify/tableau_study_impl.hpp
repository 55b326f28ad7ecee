/// \file tableau_study_impl.hpp
/// \brief The parts of tableau_study.cpp that the typed route (tableau_typed.cpp) shares: the
/// partitioned Runge–Kutta one-step map of a tableau for a problem type with `potential` and
/// `gradient`, and the report around the measurement. Internal: not installed.
#pragma once

#include <memory>
#include <stdexcept>
#include <utility>

#include "vibook/integrators/prk.hpp"
#include "vibook/verify/map_study.hpp"
#include "vibook/verify/tableau_study.hpp"

namespace vibook::verify::tableau_detail {

// The one-step map and the generating step of the tableau's method `Method` (constructed from
// `prob` and the tableau) on `prob`: one instance per problem, the number of stages the
// tableau's.
template <class Method, class P>
std::pair<Step, GeneratingStep> method_steps(const P& prob, const PrkTableau& t) {
  if (t.stages() < 1 || t.stages() > 6)
    throw std::invalid_argument("measure_tableau: 1 to 6 stages");
  constexpr int N = P::N;
  auto method = std::make_shared<Method>(prob, t);
  auto generating = std::make_shared<Method>(prob, t);
  return {naming_failures([method](Eigen::VectorXd& z, double h) { step_qp<N>(*method, z, h); }, N),
          [generating](Eigen::VectorXd& z, double h) {
            step_qp<N>(*generating, z, h);
            return generating->action();
          }};
}

// For a mechanical problem type (`potential`, `gradient` of U): PartitionedRkMethod.
template <class P>
std::pair<Step, GeneratingStep> steps_for(const P& prob, const PrkTableau& t) {
  return method_steps<PartitionedRkMethod<Eigen::Dynamic, P>>(prob, t);
}

// The same method in double-double, for the order study of a high-order tableau
// (MapStudy::step_dd), on a mechanical problem type; with it the step that also returns the
// step's discrete Lagrangian (MapStudy::generating_dd, the variational order beyond double).
template <class P>
std::pair<StepDD, GeneratingStepDD> steps_dd_for(const P& prob, const PrkTableauT<dd_real>& t) {
  using Method = PartitionedRkMethod<Eigen::Dynamic, P, dd_real>;
  return dd_steps<P::N>([&] { return std::make_shared<Method>(prob, t); });
}

// The Runge–Kutta–Nyström method of an RKN tableau (PartitionedRkMethod's RKN constructor) on
// a mechanical problem type: its step, and no step with a discrete Lagrangian.
template <class P>
std::pair<Step, GeneratingStep> rkn_steps_for(const P& prob, const RknTableauT<double>& t) {
  if (t.stages() < 1 || t.stages() > 6)
    throw std::invalid_argument("measure_tableau: 1 to 6 stages");
  constexpr int N = P::N;
  auto method = std::make_shared<PartitionedRkMethod<Eigen::Dynamic, P>>(prob, t);
  return {naming_failures([method](Eigen::VectorXd& z, double h) { step_qp<N>(*method, z, h); }, N),
          GeneratingStep{}};
}

// The same in double-double (MapStudy::step_dd).
template <class P>
std::pair<StepDD, GeneratingStepDD> rkn_steps_dd_for(const P& prob, const RknTableauT<dd_real>& t) {
  using Method = PartitionedRkMethod<Eigen::Dynamic, P, dd_real>;
  return dd_steps<P::N>([&] { return std::make_shared<Method>(prob, t); }, false);
}

// For a problem type with `hamiltonian` and `gradient` (∇H in (q, p)): the method of the
// tableau on any H (HamiltonianPrkMethod).
template <class P>
std::pair<Step, GeneratingStep> hamiltonian_steps_for(const P& prob, const PrkTableau& t) {
  return method_steps<HamiltonianPrkMethod<P>>(prob, t);
}

// The tableau's lines, then the measurement of map_study.hpp on `system`; N degrees of freedom.
// `general_h`: the steps are HamiltonianPrkMethod's (the report says how it is solved and what
// its discrete Lagrangian is).
void measure(const TableauSpec& spec, int N, const StudySystem& system, const MapStudy& study,
             bool symmetric_claimed, MapMeasurement& rep, std::pair<Step, GeneratingStep> steps,
             bool general_h = false);

}  // namespace vibook::verify::tableau_detail
