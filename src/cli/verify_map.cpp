// The command's side of the measurements of a one-step map (verify_map.hpp).
#include "verify_map.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <mutex>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "verify_typed.hpp"
#include "vibook/core/output_file.hpp"
#include "vibook/modified/engine.hpp"
#include "vibook/verify/constrained.hpp"
#include "vibook/verify/report_page.hpp"

namespace vibook::cli {

const TestProblem& find_test_problem(const std::string& name) {
  if (const TestProblem* p = verify::find_problem(name)) return *p;
  if (verify::find_constrained_problem(name))
    throw ArgumentError("--problem", "'" + name +
                                         "' has constraints: --method rattle steps it (the other "
                                         "methods and routes are not constrained)");
  throw ArgumentError("--problem", "unknown problem '" +
                                       (name.empty() ? std::string("kepler") : name) +
                                       "' (kepler, pendulum or henon-heiles)");
}

namespace {

// The typed system of a catalogue route, checked before any work. `option` names the text that
// gives the system (`text`: a potential, a Lagrangian or a Hamiltonian) in the messages; the
// system parsed is L (`lagrangian`) or H (`hamiltonian`), either of which may call the V of
// --potential. 1 to 3 degrees of freedom; then --q0, --p0 and --t-end.
std::unique_ptr<verify::TypedDiscreteLagrangian> check_typed_system(
    const char* option, const std::string& text, const std::string& lagrangian,
    const std::string& hamiltonian, const TypedPotentialOptions& t, const StudyOptions& o,
    const char* route, std::vector<double>& q0, std::vector<double>& p0, MapStudy& s,
    bool allow_time) {
  if (text.empty()) throw ArgumentError(option, "is empty");
  if (!o.problem.empty())
    throw ArgumentError(option,
                        "gives the system; --problem names a test problem: give one of them");
  if (t.potential_given && t.potential.empty()) throw ArgumentError("--potential", "is empty");
  int dim = 0;
  if (!t.dim.empty()) {
    dim = static_cast<int>(parse_integer("--dim", t.dim));
    if (dim < 1 || dim > 3)
      throw ArgumentError("--dim", fmt::format("must lie in 1..3 with {}", route));
  }
  std::unique_ptr<verify::TypedDiscreteLagrangian> sys;
  {
    std::lock_guard<std::mutex> lock(modified::ginac_mutex());
    verify::TypedTexts texts{"", t.potential, lagrangian, hamiltonian, dim};
    texts.system_only = true;
    texts.allow_time = allow_time;
    sys = std::make_unique<verify::TypedDiscreteLagrangian>(texts);
  }
  if (sys->dim() > 3)
    throw ArgumentError(
        option, fmt::format("is {}-dimensional; {} runs in 1 to 3 dimensions", sys->dim(), route));
  check_typed_initial_state(o, sys->dim(), q0, p0, s);
  return sys;
}

}  // namespace

std::unique_ptr<verify::TypedDiscreteLagrangian> check_typed_potential(
    const TypedPotentialOptions& t, const StudyOptions& o, const char* route,
    std::vector<double>& q0, std::vector<double>& p0, MapStudy& s, bool allow_time) {
  return check_typed_system("--potential", t.potential, "", "p^2/2 + V(q)", t, o, route, q0, p0, s,
                            allow_time);
}

std::unique_ptr<verify::TypedDiscreteLagrangian> check_typed_lagrangian(
    const TypedPotentialOptions& t, const StudyOptions& o, const char* route,
    std::vector<double>& q0, std::vector<double>& p0, MapStudy& s, bool allow_time) {
  return check_typed_system("--lagrangian", t.lagrangian, t.lagrangian, "", t, o, route, q0, p0, s,
                            allow_time);
}

std::unique_ptr<verify::TypedDiscreteLagrangian> check_typed_hamiltonian(
    const TypedPotentialOptions& t, const std::string& hamiltonian, const StudyOptions& o,
    const char* route, std::vector<double>& q0, std::vector<double>& p0, MapStudy& s,
    bool allow_time) {
  return check_typed_system("--hamiltonian", hamiltonian, "", hamiltonian, t, o, route, q0, p0, s,
                            allow_time);
}

void MapReport::variational_order_not_derived(const std::string& reason) {
  line("variational order", "not derived: " + reason);
  js["variational_order"] = {{"derived", false}, {"reason", reason}};
}

int MapReport::finish(const StudyOptions& o) {
  js["verdict"] = {{"passed", failed.empty()}, {"failed", failed}, {"required", required}};
  // The full text of the first numerical failure (its line on stderr may be cut to 300).
  if (numerical_failure) js["error"] = first_error;
  line("verdict", fmt::format("{} ({})", failed.empty() ? "PASS" : "FAIL",
                              fmt::join(failed.empty() ? required : failed, ", ")));
  std::cout << out.str();
  std::cout.flush();
  const int rc = numerical_failure ? kNumerical : failed.empty() ? kOk : kVerdict;
  if (rc == kVerdict)
    eprint(fmt::format("vibook: verify: FAIL ({}); the report above says why\n",
                       fmt::join(failed, ", ")));
  if (rc == kNumerical) eprint("vibook: error: verify: " + first_error + "\n");
  if (o.json_given) write_output_file(o.json_out, js.dump(2) + "\n", "--json-out");
  if (o.report_given) {
    const std::filesystem::path dir = report_directory(o.report);
    verify::write_map_report(*this, command_line(), dir);
    std::cout << "report: " << (dir / "index.html").string() << '\n';
  }
  return rc;
}

}  // namespace vibook::cli
