// The command's side of the measurements of a one-step map (verify_map.hpp).
#include "verify_map.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <mutex>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "args.hpp"
#include "vibook/core/output_file.hpp"
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

double checked_t_end(const std::string& text) {
  const double t = parse_number("--t-end", text);
  if (!(t > 0) || t > kMaxTEnd) throw ArgumentError("--t-end", "must lie in (0, 1e4]");
  return t;
}

double checked_order_tol(const std::string& text) {
  const double tol = parse_number("--order-tol", text);
  if (!(tol > 0 && tol <= 1)) throw ArgumentError("--order-tol", "must lie in (0, 1]");
  return tol;
}

double checked_floor(const std::string& text) {
  const double f = parse_number("--floor", text);
  if (!(f >= 0) || !std::isfinite(f))
    throw ArgumentError("--floor", "must be a finite number >= 0");
  return f;
}

void check_energy_run(const VerifyOptions& o, double& h, long long& steps) {
  h = parse_number("--h", o.h);
  steps = parse_integer("--steps", o.steps);
  if (steps < 1024 || steps > 100000000) throw ArgumentError("--steps", "must lie in [1024, 1e8]");
  if (!(h > 0) || !std::isfinite(h) || h * double(steps) > kMaxRunTime)
    throw ArgumentError("--h", "must be a positive finite step (h·steps at most 1e9)");
}

void check_study_options(const VerifyOptions& o, MapStudy& s) {
  if (o.has("--order-tol")) s.order_tol = checked_order_tol(o.order_tol);
  if (o.has("--h-list")) s.hs = parse_step_list("--h-list", o.h_list, s.t_end, kMaxStepsLog10);
  if (!o.floor.empty()) s.floor = checked_floor(o.floor);
  check_energy_run(o, s.h, s.steps);
  s.symmetric_claimed = o.symmetric;
  if (o.json_given) check_output_path(o.json_out, "--json-out", true);
}

void check_t_end(const VerifyOptions& o, MapStudy& s) {
  if (o.has("--t-end")) s.t_end = checked_t_end(o.t_end);
}

void check_initial_state(const VerifyOptions& o, const TestProblem& problem,
                         std::vector<double>& q0, std::vector<double>& p0, MapStudy& s) {
  const std::string why =
      fmt::format("{} has {} degrees of freedom", problem.name, problem.q0.size());
  q0 = parse_state("--q0", o.q0, problem.q0, why);
  p0 = parse_state("--p0", o.p0, problem.p0, why);
  if (problem.name == "kepler" && std::hypot(q0[0], q0[1]) < 1e-3)
    throw ArgumentError("--q0", "lies at (or within 1e-3 of) the Kepler singularity q = 0");
  check_t_end(o, s);
}

double check_expected_order(const std::string& text) {
  const double e = parse_number("--expected-order", text);
  if (!(e > 0 && e <= verify::kMaxOrder))
    throw ArgumentError("--expected-order",
                        fmt::format("must lie in (0, {:g}]", verify::kMaxOrder));
  return e;
}

void check_typed_initial_state(const VerifyOptions& o, int n, std::vector<double>& q0,
                               std::vector<double>& p0, MapStudy& s) {
  const std::vector<double> dflt(static_cast<std::size_t>(n), 0.1);
  const std::string why = fmt::format("the expressions are {}-dimensional", n);
  q0 = parse_state("--q0", o.q0, dflt, why);
  p0 = parse_state("--p0", o.p0, dflt, why);
  check_t_end(o, s);
}

int check_dim(const VerifyOptions& o, int max, const std::string& with) {
  if (o.dim.empty()) return 0;
  const int dim = static_cast<int>(parse_integer("--dim", o.dim));
  if (dim < 1 || dim > max)
    throw ArgumentError("--dim", fmt::format("must lie in 1..{}{}", max, with));
  return dim;
}

std::unique_ptr<verify::TypedDiscreteLagrangian> check_typed_system(
    const VerifyOptions& o, const std::string& option, const char* route, std::vector<double>& q0,
    std::vector<double>& p0, MapStudy& s, bool allow_time) {
  const std::string& text = option == "--potential"    ? o.potential
                            : option == "--lagrangian" ? o.lagrangian
                                                       : o.hamiltonian;
  if (text.empty()) throw ArgumentError(option, "is empty");
  if (!o.problem.empty())
    throw ArgumentError(option,
                        "gives the system; --problem names a test problem: give one of them");
  if (o.has("--potential") && o.potential.empty()) throw ArgumentError("--potential", "is empty");
  const int dim = check_dim(o, 3, fmt::format(" with {}", route));
  std::unique_ptr<verify::TypedDiscreteLagrangian> sys;
  {
    verify::TypedTexts texts{"", o.potential, option == "--lagrangian" ? o.lagrangian : "",
                             option == "--lagrangian"    ? ""
                             : option == "--hamiltonian" ? o.hamiltonian
                                                         : "p^2/2 + V(q)",
                             dim};
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

int MapReport::finish(const VerifyOptions& o) {
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
