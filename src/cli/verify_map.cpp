// The command's side of the measurements of a one-step map (verify_map.hpp).
#include "verify_map.hpp"

#include <iostream>
#include <mutex>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "vibook/core/output_file.hpp"
#include "vibook/modified/engine.hpp"

namespace vibook::cli {

const TestProblem& find_test_problem(const std::string& name) {
  if (const TestProblem* p = verify::find_problem(name)) return *p;
  throw ArgumentError("--problem", "unknown problem '" +
                                       (name.empty() ? std::string("kepler") : name) +
                                       "' (kepler, pendulum or henon-heiles)");
}

std::unique_ptr<verify::TypedDiscreteLagrangian> check_typed_potential(
    const TypedPotentialOptions& t, const StudyOptions& o, const char* route,
    std::vector<double>& q0, std::vector<double>& p0, MapStudy& s) {
  if (t.potential.empty()) throw ArgumentError("--potential", "is empty");
  if (!o.problem.empty())
    throw ArgumentError("--potential",
                        "gives the system; --problem names a test problem: give one of them");
  int dim = 0;
  if (!t.dim.empty()) {
    dim = static_cast<int>(parse_integer("--dim", t.dim));
    if (dim < 1 || dim > 3)
      throw ArgumentError("--dim", fmt::format("must lie in 1..3 with {}", route));
  }
  std::unique_ptr<verify::TypedDiscreteLagrangian> sys;
  {
    std::lock_guard<std::mutex> lock(modified::ginac_mutex());
    verify::TypedTexts texts{"", t.potential, "", "p^2/2 + V(q)", dim};
    texts.system_only = true;
    sys = std::make_unique<verify::TypedDiscreteLagrangian>(texts);
  }
  if (sys->dim() > 3)
    throw ArgumentError("--potential", fmt::format("is {}-dimensional; {} runs in 1 to 3 "
                                                   "dimensions",
                                                   sys->dim(), route));
  check_typed_initial_state(o, sys->dim(), q0, p0, s);
  return sys;
}

namespace {

template <int N>
void set_potential_system(MapStudy& s, const verify::TypedDiscreteLagrangian& sys,
                          const std::vector<double>& q0, const std::vector<double>& p0) {
  Eigen::VectorXd z0(2 * N);
  for (int i = 0; i < N; ++i) {
    z0(i) = q0[static_cast<std::size_t>(i)];
    z0(N + i) = p0[static_cast<std::size_t>(i)];
  }
  set_typed_system<N>(s, sys, z0);
}

}  // namespace

std::string set_typed_potential(MapStudy& s, const verify::TypedDiscreteLagrangian& sys,
                                const std::string& potential, const std::vector<double>& q0,
                                const std::vector<double>& p0) {
  const int n = sys.dim();
  if (n == 1) set_potential_system<1>(s, sys, q0, p0);
  if (n == 2) set_potential_system<2>(s, sys, q0, p0);
  if (n == 3) set_potential_system<3>(s, sys, q0, p0);
  return fmt::format(
      "H = |p|^2/2 + V(q), V = {} (--potential), {} degree{} of freedom; q0 = {}, "
      "p0 = {}",
      potential, n, n == 1 ? "" : "s", vec_text(q0), vec_text(p0));
}

void MapReport::variational_order_not_derived(const std::string& reason) {
  line("variational order", "not derived: " + reason);
  js["variational_order"] = {{"derived", false}, {"reason", reason}};
}

int MapReport::finish(bool json_given, const std::string& json_out) {
  js["verdict"] = {{"passed", failed.empty()}, {"failed", failed}, {"required", required}};
  line("verdict", fmt::format("{} ({})", failed.empty() ? "PASS" : "FAIL",
                              fmt::join(failed.empty() ? required : failed, ", ")));
  std::cout << out.str();
  std::cout.flush();
  const int rc = numerical_failure ? kNumerical : failed.empty() ? kOk : kVerdict;
  if (rc == kVerdict)
    eprint(fmt::format("vibook: verify: FAIL ({}); the report above says why\n",
                       fmt::join(failed, ", ")));
  if (rc == kNumerical) eprint("vibook: error: verify: " + first_error + "\n");
  if (json_given) write_output_file(json_out, js.dump(2) + "\n", "--json-out");
  return rc;
}

double largest_symmetric_eigenvalue(const Eigen::MatrixXd& H) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(H, Eigen::EigenvaluesOnly)
      .eigenvalues()
      .maxCoeff();
}

}  // namespace vibook::cli
