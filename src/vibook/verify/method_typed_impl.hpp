/// \file method_typed_impl.hpp
/// \brief measure_method_typed for N degrees of freedom (method_typed.cpp dispatches on the
/// dimension; typed_n.cpp.in instantiates each N in one unit per dimension, so that the
/// three compile in parallel). Internal: not installed.
#pragma once

#include <stdexcept>
#include <type_traits>

#include "vibook/verify/expression.hpp"
#include "vibook/verify/method_study.hpp"
#include "vibook/verify/method_study_impl.hpp"
#include "vibook/verify/typed_potential.hpp"

namespace vibook::verify::method_detail {

template <int N>
void measure_typed_dim(const MethodSpec& spec, const TypedDiscreteLagrangian& sys,
                       const StudySystem& system, const MapStudy& study, MapMeasurement& rep) {
  // --potential gives the system as H = |p|²/2 + V(q) (check_typed_potential), --lagrangian as
  // L(q, v) typed: the Galerkin method of L = |v|²/2 − V(q) for the first.
  const bool typed_lagrangian = !sys.default_system() && !sys.has_hamiltonian();
  const TypedDiscreteLagrangian* s = &sys;
  if (sys.time_dependent()) {
    // L(q, v, t): the typed Lagrangian, or |v|²/2 − V(q, t); the Galerkin step evaluates it at
    // the nodes' times t + c_i h (study.timed: the state carries the clock).
    const auto lagrangian = [s, typed_lagrangian](
                                const auto& q, const auto& v,
                                const auto& t) -> std::remove_cvref_t<decltype(q(0))> {
      using T = std::remove_cvref_t<decltype(q(0))>;
      if (typed_lagrangian) return s->template lagrangian<N, T>(Vec<T, N>(q), Vec<T, N>(v), t);
      return T(constant<T>(0.5) * squared_norm(v) - s->template potential<N, T>(Vec<T, N>(q), t));
    };
    measure(spec, N, system, study, rep,
            galerkin_step_of<N>(lagrangian, spec.rule, "measure_method_typed"));
    return;
  }
  if (!typed_lagrangian) {
    const TypedPotential<N> prob{&sys};
    measure(spec, N, system, study, rep, galerkin_step(prob, spec.rule, "measure_method_typed"));
    return;
  }
  // L(q, v) typed after --lagrangian, on the tree in the integrator's nested AutoDiff numbers
  const auto lagrangian = [s](const auto& q, const auto& v) -> std::remove_cvref_t<decltype(q(0))> {
    using T = std::remove_cvref_t<decltype(q(0))>;
    return s->template lagrangian<N, T>(Vec<T, N>(q), Vec<T, N>(v));
  };
  measure(spec, N, system, study, rep,
          galerkin_step_of<N>(lagrangian, spec.rule, "measure_method_typed"));
}

extern template void measure_typed_dim<1>(const MethodSpec&, const TypedDiscreteLagrangian&,
                                          const StudySystem&, const MapStudy&, MapMeasurement&);
extern template void measure_typed_dim<2>(const MethodSpec&, const TypedDiscreteLagrangian&,
                                          const StudySystem&, const MapStudy&, MapMeasurement&);
extern template void measure_typed_dim<3>(const MethodSpec&, const TypedDiscreteLagrangian&,
                                          const StudySystem&, const MapStudy&, MapMeasurement&);

}  // namespace vibook::verify::method_detail
