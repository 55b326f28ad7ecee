// A partitioned Runge–Kutta method from a tableau measured on the user's own system
// (tableau_study.hpp, measure_tableau_typed): the method of integrators/prk.hpp on
// H = |p|²/2 + V(q), V the expression typed after --potential, its force by forward AutoDiff on
// the expression's tree (and the force's Jacobian, for the implicit stages, by AutoDiff on
// that); or HamiltonianPrkMethod on the H typed after --hamiltonian, ∇H and its Hessian the
// same way. The work for each dimension (1 to 3, each with 1 to 6 stages) is instantiated in
// one unit per dimension (typed_n.cpp.in).
#include <stdexcept>
#include <string>
#include <vector>

#include "vibook/verify/tableau_typed_impl.hpp"
#include "vibook/verify/typed_study_system.hpp"

namespace vibook::verify {

void measure_tableau_typed(const TableauSpec& spec, const TypedDiscreteLagrangian& sys,
                           const std::vector<double>& q0, const std::vector<double>& p0,
                           const MapStudy& study, const std::string& system_line,
                           bool symmetric_claimed, bool general_h, MapMeasurement& rep) {
  using tableau_detail::measure_typed_dim;
  if (spec.rkn)
    throw std::invalid_argument(
        "measure_tableau_typed: a Runge-Kutta-Nystrom tableau runs on the test problems only");
  const StudySystem system = typed_study_system(system_line, q0, p0);
  switch (sys.dim()) {
    case 1:
      return measure_typed_dim<1>(spec, sys, system, study, symmetric_claimed, general_h, rep);
    case 2:
      return measure_typed_dim<2>(spec, sys, system, study, symmetric_claimed, general_h, rep);
    case 3:
      return measure_typed_dim<3>(spec, sys, system, study, symmetric_claimed, general_h, rep);
    default:
      throw std::invalid_argument("measure_tableau_typed: 1 to 3 degrees of freedom");
  }
}

}  // namespace vibook::verify
