// `vibook verify --tableau FILE` (issue #25): the file and the other arguments checked before
// any work, then the measurement of vibook/verify/tableau_study.hpp printed, on a test problem,
// on the user's own potential (--potential) or on any Hamiltonian typed (--hamiltonian).
#include "verify_tableau.hpp"

#include <memory>
#include <string>
#include <vector>

#include "args.hpp"
#include "verify_map.hpp"
#include "vibook/core/output_file.hpp"
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
};

Plan check(const TableauOptions& o) {
  Plan p;
  p.spec = verify::read_tableau(o.file);
  if (p.spec.rkn && (o.hamiltonian_given || o.potential_given))
    throw ArgumentError(o.hamiltonian_given ? "--hamiltonian" : "--potential",
                        "a Runge-Kutta-Nystrom tableau (abar, bbar) runs on the test problems "
                        "(--problem) only, for now");
  if (o.hamiltonian_given) {
    // (a time-dependent system too: each stage at t + c_i h, prk.hpp)
    p.sys = check_typed_hamiltonian(o, o.hamiltonian, o, "--tableau", p.q0, p.p0, p.study, true);
  } else if (o.potential_given) {
    p.sys = check_typed_potential(o, o, "--tableau", p.q0, p.p0, p.study, true);
  } else {
    if (!o.dim.empty())
      throw ArgumentError("--dim", "applies to --tableau with --potential or --hamiltonian only");
    p.problem = &find_test_problem(o.problem);
    check_initial_state(o, *p.problem, p.q0, p.p0, p.study);
  }
  if (o.expected_given) {
    p.spec.expected = check_expected_order(o.expected);
    p.spec.expected_from = "--expected-order";
  } else if (!p.spec.documented_order) {
    throw ArgumentError("--expected-order",
                        "is required: the tableau file '" + o.file + "' has no 'order'");
  }
  check_study_options(o, p.study);
  if (o.json_given) check_output_path(o.json_out, "--json-out", true);
  return p;
}

}  // namespace

int run_tableau(const TableauOptions& o) {
  Plan p = check(o);
  MapReport rep;
  if (!p.sys) {
    verify::measure_tableau(p.spec, *p.problem, p.q0, p.p0, p.study, o.symmetric, rep);
    return rep.finish(o);
  }
  const std::string system = o.hamiltonian_given
                                 ? set_typed_hamiltonian(p.study, *p.sys, o.hamiltonian, p.q0, p.p0)
                                 : set_typed_potential(p.study, *p.sys, o.potential, p.q0, p.p0);
  verify::measure_tableau_typed(p.spec, *p.sys, p.q0, p.p0, p.study, system, o.symmetric,
                                o.hamiltonian_given, rep);
  return rep.finish(o);
}

}  // namespace vibook::cli
