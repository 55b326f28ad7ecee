// `vibook verify --method gauss:S|lobatto:S` (issue #25): the arguments checked before any work,
// then the measurement of vibook/verify/method_study.hpp (the Galerkin variational integrator
// with S stages on a nonlinear test problem, on the user's L(q, v) typed after --lagrangian, or
// on L = |v|²/2 − V(q) with the user's V typed after --potential; documented order 2S for
// Gauss, 2S − 2 for Lobatto) printed.
#include "verify_method.hpp"

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
Plan check_constrained(const MethodOptions& o) {
  Plan p;
  p.project_velocity = o.method == "rattle";
  if (o.lagrangian_given || o.potential_given || !o.dim.empty())
    throw ArgumentError(o.lagrangian_given  ? "--lagrangian"
                        : o.potential_given ? "--potential"
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
  const std::size_t n = p.constrained->q0.size();
  auto vector_or = [&](const std::string& arg, const std::string& text,
                       const std::vector<double>& dflt) {
    std::vector<double> v = text.empty() ? dflt : parse_list(arg, text);
    if (v.size() != n)
      throw ArgumentError(
          arg, fmt::format("has {} components; {} has {} coordinates", v.size(), name, n));
    for (double x : v)
      if (!std::isfinite(x)) throw ArgumentError(arg, "must be finite");
    return v;
  };
  p.q0 = vector_or("--q0", o.q0, p.constrained->q0);
  p.p0 = vector_or("--p0", o.p0, p.constrained->p0);
  if (o.t_end_given) {
    p.study.t_end = parse_number("--t-end", o.t_end);
    if (!(p.study.t_end > 0) || p.study.t_end > 1e4)
      throw ArgumentError("--t-end", "must lie in (0, 1e4]");
  }
  p.study.expected = 2;
  if (o.expected_given) p.study.expected = check_expected_order(o.expected);
  check_study_options(o, p.study);
  if (o.json_given) check_output_path(o.json_out, "--json-out", true);
  return p;
}

Plan check(const MethodOptions& o) {
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
  if (o.lagrangian_given) {
    p.sys = check_typed_lagrangian(o, o, "--method", p.q0, p.p0, p.study, true);
  } else if (o.potential_given) {
    p.sys = check_typed_potential(o, o, "--method", p.q0, p.p0, p.study, true);
  } else {
    if (!o.dim.empty())
      throw ArgumentError("--dim", "applies to --method with --potential or --lagrangian only");
    p.problem = &find_test_problem(o.problem);
    check_initial_state(o, *p.problem, p.q0, p.p0, p.study);
  }
  p.spec.expected = p.spec.rule.order;
  p.spec.expected_from = "documented";
  if (o.expected_given) {
    p.spec.expected = check_expected_order(o.expected);
    p.spec.expected_from = "--expected-order";
  }
  p.symbolic = verify::parse_symbolic_use(o.symbolic);
  check_study_options(o, p.study);
  if (o.json_given) check_output_path(o.json_out, "--json-out", true);
  return p;
}

}  // namespace

int run_method(const MethodOptions& o) {
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
  const std::string system = o.lagrangian_given
                                 ? set_typed_lagrangian(p.study, *p.sys, o.lagrangian, p.q0, p.p0)
                                 : set_typed_potential(p.study, *p.sys, o.potential, p.q0, p.p0);
  verify::measure_method_typed(p.spec, *p.sys, p.q0, p.p0, p.study, system, rep);
  return rep.finish(o);
}

}  // namespace vibook::cli
