/// \file tableau_typed_impl.hpp
/// \brief measure_tableau_typed for N degrees of freedom (tableau_typed.cpp dispatches on the
/// dimension; typed_n.cpp.in instantiates each N in one unit per dimension). Internal: not
/// installed.
#pragma once

#include "vibook/verify/tableau_study_impl.hpp"
#include "vibook/verify/typed_potential.hpp"

namespace vibook::verify::tableau_detail {

template <int N>
void measure_typed_dim(const TableauSpec& spec, const TypedDiscreteLagrangian& sys,
                       const StudySystem& system, const MapStudy& study, bool symmetric_claimed,
                       bool general_h, MapMeasurement& rep) {
  if (general_h)
    measure(spec, N, system, study, symmetric_claimed, rep,
            hamiltonian_steps_for(TypedHamiltonian<N>{&sys}, spec.tableau), true);
  else
    measure(spec, N, system, study, symmetric_claimed, rep,
            steps_for(TypedPotential<N>{&sys}, spec.tableau));
}

extern template void measure_typed_dim<1>(const TableauSpec&, const TypedDiscreteLagrangian&,
                                          const StudySystem&, const MapStudy&, bool, bool,
                                          MapMeasurement&);
extern template void measure_typed_dim<2>(const TableauSpec&, const TypedDiscreteLagrangian&,
                                          const StudySystem&, const MapStudy&, bool, bool,
                                          MapMeasurement&);
extern template void measure_typed_dim<3>(const TableauSpec&, const TypedDiscreteLagrangian&,
                                          const StudySystem&, const MapStudy&, bool, bool,
                                          MapMeasurement&);

}  // namespace vibook::verify::tableau_detail
