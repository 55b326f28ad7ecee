// `vibook verify --method gauss:S|lobatto:S` (issue #25): the arguments checked before any work,
// then the measurement of vibook/verify/method_study.hpp (the Galerkin variational integrator
// with S stages on a nonlinear test problem, on the user's L(q, v) typed after --lagrangian, or
// on L = |v|²/2 − V(q) with the user's V typed after --potential; documented order 2S for
// Gauss, 2S − 2 for Lobatto) printed.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "args.hpp"
#include "verify_map.hpp"
#include "vibook/core/output_file.hpp"
#include "vibook/modified/ginac_eigen.hpp"
#include "vibook/verify/constrained.hpp"
#include "vibook/verify/expression.hpp"
#include "vibook/verify/method_study.hpp"
#include "vibook/verify/method_symbolic.hpp"

namespace vibook::cli {

namespace {

constexpr int kMaxGauss = 4, kMaxLobatto = 5;

struct Plan {
  verify::MethodSpec spec;
  const TestProblem* problem = nullptr;
  // --potential or --lagrangian: the typed system (H = |p|^2/2 + V, or L's Legendre transform,
  // for the reference and the energy)
  std::unique_ptr<verify::TypedDiscreteLagrangian> sys;
  std::vector<double> q0, p0;
  MapStudy study;  // the measurement settings
  verify::SymbolicUse symbolic = verify::SymbolicUse::automatic;
  // --method rattle|shake: the constrained problem, and whether the momentum is projected
  const verify::ConstrainedProblem* constrained = nullptr;
  bool project_velocity = true;
};

// --method rattle (or its deliberately wrong variant shake) on a constrained test problem.
Plan check_constrained(const VerifyOptions& o) {
  Plan p;
  p.project_velocity = o.method == "rattle";
  if (o.has("--lagrangian") || o.has("--potential") || !o.dim.empty())
    throw ArgumentError(o.has("--lagrangian")  ? "--lagrangian"
                        : o.has("--potential") ? "--potential"
                                               : "--dim",
                        "does not apply to --method " + o.method +
                            ": it runs on a constrained test problem (--problem "
                            "spherical-pendulum or double-pendulum), or on --potential with "
                            "--constraint");
  const std::string name = o.problem.empty() ? "spherical-pendulum" : o.problem;
  p.constrained = verify::find_constrained_problem(name);
  if (!p.constrained)
    throw ArgumentError("--problem", "'" + name + "' has no constraints; --method " + o.method +
                                         " runs on spherical-pendulum or double-pendulum");
  const std::string why = fmt::format("{} has {} coordinates", name, p.constrained->q0.size());
  p.q0 = parse_state("--q0", o.q0, p.constrained->q0, why);
  p.p0 = parse_state("--p0", o.p0, p.constrained->p0, why);
  check_t_end(o, p.study);
  p.study.expected = 2;
  if (o.has("--expected-order")) p.study.expected = check_expected_order(o.expected);
  check_study_options(o, p.study);
  return p;
}

Plan check(const VerifyOptions& o) {
  if (o.method == "rattle" || o.method == "shake") return check_constrained(o);
  Plan p;
  const auto colon = o.method.find(':');
  const std::string family = o.method.substr(0, colon);
  if (family != "gauss" && family != "lobatto")
    throw ArgumentError("--method", "unknown method '" + o.method + "' (gauss:S, S = 1.." +
                                        std::to_string(kMaxGauss) + ", or lobatto:S, S = 2.." +
                                        std::to_string(kMaxLobatto) +
                                        ": S stages; rattle on a constrained problem)");
  if (colon == std::string::npos)
    throw ArgumentError("--method",
                        "'" + o.method + "' needs the number of stages, e.g. " + family + ":3");
  const long long s = parse_integer("--method", o.method.substr(colon + 1));
  const int lo = family == "gauss" ? 1 : 2, hi = family == "gauss" ? kMaxGauss : kMaxLobatto;
  if (s < lo || s > hi)
    throw ArgumentError("--method",
                        fmt::format("{} takes {} to {} stages, not {}", family, lo, hi, s));
  p.spec.name = o.method;
  p.spec.stages = static_cast<int>(s);
  p.spec.rule = quadrature_rule(family, p.spec.stages);
  if (o.has("--lagrangian") || o.has("--potential")) {
    p.sys = check_typed_system(o, o.has("--lagrangian") ? "--lagrangian" : "--potential",
                               "--method", p.q0, p.p0, p.study, true);
  } else {
    if (!o.dim.empty())
      throw ArgumentError("--dim", "applies to --method with --potential or --lagrangian only");
    p.problem = &find_test_problem(o.problem);
    check_initial_state(o, *p.problem, p.q0, p.p0, p.study);
  }
  p.spec.expected = p.spec.rule.order;
  p.spec.expected_from = "documented";
  if (o.has("--expected-order")) {
    p.spec.expected = check_expected_order(o.expected);
    p.spec.expected_from = "--expected-order";
  }
  p.symbolic = verify::parse_symbolic_use(o.symbolic);
  check_study_options(o, p.study);
  return p;
}

}  // namespace

int run_method(const VerifyOptions& o) {
  Plan p = check(o);
  MapReport rep;
  if (p.constrained) {
    verify::measure_constrained(*p.constrained, p.project_velocity, p.q0, p.p0, p.study, rep);
    return rep.finish(o);
  }
  const int n = static_cast<int>(p.q0.size());
  const modified::SymbolicLagrangian L = !p.sys   ? verify::test_problem_lagrangian(p.problem->name)
                                         : n == 1 ? verify::typed_lagrangian<1>(p.sys.get())
                                         : n == 2 ? verify::typed_lagrangian<2>(p.sys.get())
                                                  : verify::typed_lagrangian<3>(p.sys.get());
  verify::derive_galerkin_variational_order(p.spec, n, L, p.symbolic, p.study);
  if (!p.sys) {
    verify::measure_method(p.spec, *p.problem, p.q0, p.p0, p.study, rep);
    return rep.finish(o);
  }
  const std::string system = o.has("--lagrangian")
                                 ? set_typed_lagrangian(p.study, *p.sys, o.lagrangian, p.q0, p.p0)
                                 : set_typed_potential(p.study, *p.sys, o.potential, p.q0, p.p0);
  verify::measure_method_typed(p.spec, *p.sys, p.q0, p.p0, p.study, system, rep);
  return rep.finish(o);
}

}  // namespace vibook::cli
