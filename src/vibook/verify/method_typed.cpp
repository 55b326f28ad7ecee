// A Galerkin variational integrator measured on the user's own system (method_study.hpp,
// measure_method_typed): the integrator of integrators/galerkin.hpp for the Lagrangian typed
// after --lagrangian, or for L = |v|²/2 − V(q) with V typed after --potential, evaluated on its
// tree in the nested AutoDiff numbers the integrator's Newton method asks for. The work for each
// dimension (1 to 3, each with 1 to 5 stages) is instantiated in one unit per
// dimension (typed_n.cpp.in).
#include <stdexcept>
#include <string>
#include <vector>

#include "vibook/verify/method_typed_impl.hpp"
#include "vibook/verify/typed_study_system.hpp"

namespace vibook::verify {

void measure_method_typed(const MethodSpec& spec, const TypedDiscreteLagrangian& sys,
                          const std::vector<double>& q0, const std::vector<double>& p0,
                          const MapStudy& study, const std::string& system_line,
                          MapMeasurement& rep) {
  using method_detail::measure_typed_dim;
  const StudySystem system = typed_study_system(system_line, q0, p0);
  switch (sys.dim()) {
    case 1:
      return measure_typed_dim<1>(spec, sys, system, study, rep);
    case 2:
      return measure_typed_dim<2>(spec, sys, system, study, rep);
    case 3:
      return measure_typed_dim<3>(spec, sys, system, study, rep);
    default:
      throw std::invalid_argument("measure_method_typed: 1 to 3 degrees of freedom");
  }
}

}  // namespace vibook::verify
