// `vibook verify --tableau FILE` (issue #25): the file and the other arguments checked before
// any work, then the measurement of vibook/verify/tableau_study.hpp printed, on a test problem,
// on the user's own potential (--potential) or on any Hamiltonian typed (--hamiltonian).
#include <memory>
#include <string>
#include <vector>

#include "args.hpp"
#include "verify_map.hpp"
#include "vibook/core/output_file.hpp"
#include "vibook/verify/method_symbolic.hpp"
#include "vibook/verify/tableau_study.hpp"

namespace vibook::cli {

namespace {

struct Plan {
  verify::TableauSpec spec;
  const TestProblem* problem = nullptr;
  // --potential or --hamiltonian: the typed system
  std::unique_ptr<verify::TypedDiscreteLagrangian> sys;
  std::vector<double> q0, p0;
  MapStudy study;  // the measurement settings
  verify::SymbolicUse symbolic = verify::SymbolicUse::automatic;
};

Plan check(const VerifyOptions& o) {
  Plan p;
  p.spec = verify::read_tableau(o.tableau);
  if (p.spec.rkn && (o.has("--hamiltonian") || o.has("--potential")))
    throw ArgumentError(o.has("--hamiltonian") ? "--hamiltonian" : "--potential",
                        "a Runge-Kutta-Nystrom tableau (abar, bbar) runs on the test problems "
                        "(--problem) only, for now");
  if (o.has("--hamiltonian") || o.has("--potential")) {
    // (a time-dependent system too: each stage at t + c_i h, prk.hpp)
    p.sys = check_typed_system(o, o.has("--hamiltonian") ? "--hamiltonian" : "--potential",
                               "--tableau", p.q0, p.p0, p.study, true);
  } else {
    if (!o.dim.empty())
      throw ArgumentError("--dim", "applies to --tableau with --potential or --hamiltonian only");
    p.problem = &find_test_problem(o.problem);
    check_initial_state(o, *p.problem, p.q0, p.p0, p.study);
  }
  if (o.has("--expected-order")) {
    p.spec.expected = check_expected_order(o.expected);
    p.spec.expected_from = "--expected-order";
  } else if (!p.spec.documented_order) {
    throw ArgumentError("--expected-order",
                        "is required: the tableau file '" + o.tableau + "' has no 'order'");
  }
  p.symbolic = verify::parse_symbolic_use(o.symbolic);
  check_study_options(o, p.study);
  return p;
}

}  // namespace

int run_tableau(const VerifyOptions& o) {
  Plan p = check(o);
  MapReport rep;
  // The variational order derived from a and b (a system typed as H has no symbolic L here).
  const int n = static_cast<int>(p.q0.size());
  const modified::SymbolicLagrangian L = !p.sys ? verify::test_problem_lagrangian(p.problem->name)
                                         : o.has("--hamiltonian") || n > 3
                                             ? modified::SymbolicLagrangian()
                                         : n == 1 ? verify::typed_lagrangian<1>(p.sys.get())
                                         : n == 2 ? verify::typed_lagrangian<2>(p.sys.get())
                                                  : verify::typed_lagrangian<3>(p.sys.get());
  verify::derive_tableau_variational_order(p.spec, n, L, p.symbolic, p.study);
  if (!p.sys) {
    verify::measure_tableau(p.spec, *p.problem, p.q0, p.p0, p.study, o.symmetric, rep);
    return rep.finish(o);
  }
  const std::string system = o.has("--hamiltonian")
                                 ? set_typed_hamiltonian(p.study, *p.sys, o.hamiltonian, p.q0, p.p0)
                                 : set_typed_potential(p.study, *p.sys, o.potential, p.q0, p.p0);
  verify::measure_tableau_typed(p.spec, *p.sys, p.q0, p.p0, p.study, system, o.symmetric,
                                o.has("--hamiltonian"), rep);
  return rep.finish(o);
}

}  // namespace vibook::cli
