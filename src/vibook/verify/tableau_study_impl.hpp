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

template <int S, class P>
std::pair<Step, GeneratingStep> prk_steps(const P& prob, const PrkTableau& t) {
  constexpr int N = P::N;
  using Method = PartitionedRkMethod<S, P>;
  auto method = std::make_shared<Method>(prob, t);
  auto generating = std::make_shared<Method>(prob, t);
  return {naming_failures([method](Eigen::VectorXd& z, double h) { step_qp<N>(*method, z, h); }, N),
          [generating](Eigen::VectorXd& z, double h) {
            step_qp<N>(*generating, z, h);
            return generating->action();
          }};
}

template <class P>
std::pair<Step, GeneratingStep> steps_for(const P& prob, const PrkTableau& t) {
  switch (t.stages()) {
    case 1:
      return prk_steps<1>(prob, t);
    case 2:
      return prk_steps<2>(prob, t);
    case 3:
      return prk_steps<3>(prob, t);
    case 4:
      return prk_steps<4>(prob, t);
    case 5:
      return prk_steps<5>(prob, t);
    case 6:
      return prk_steps<6>(prob, t);
    default:
      throw std::invalid_argument("measure_tableau: 1 to 6 stages");
  }
}

// The tableau's lines, then the measurement of map_study.hpp on `system`; N degrees of freedom.
void measure(const TableauSpec& spec, int N, const StudySystem& system, const MapStudy& study,
             bool require_reversible, MapMeasurement& rep, std::pair<Step, GeneratingStep> steps);

}  // namespace vibook::verify::tableau_detail
