// A Galerkin variational integrator measured on a test problem (method_study.hpp): the
// integrator of integrators/galerkin.hpp with S stages (a polynomial of degree S through the
// step, the S-node Gauss–Legendre or Gauss–Lobatto quadrature of the action, the interior
// control points eliminated by Newton's method with the new position) on L = |v|²/2 − V(q);
// symmetric, so reversibility is part of the verdict. The measurements are those of
// map_study.hpp, against Hamilton's equations in double-double. `vibook verify --method` prints
// it; the field audit records it.
#include "vibook/verify/method_study.hpp"

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "vibook/kepler/kepler.hpp"
#include "vibook/problems/problems.hpp"
#include "vibook/verify/method_study_impl.hpp"

namespace vibook::verify {

namespace method_detail {

void measure(const MethodSpec& p, int N, const StudySystem& system, MapStudy s, MapMeasurement& rep,
             std::pair<Step, GeneratingStep> steps) {
  const int S = p.stages;
  s.step = std::move(steps.first);
  s.generating = std::move(steps.second);
  s.generating_from = fmt::format(
      "the {}-node quadrature action of the degree-{} polynomial through (q0, q1), its interior "
      "control points solved",
      S, S);
  system.set(s);
  s.expected = p.expected;
  // A Galerkin step costs a nested-AutoDiff Hessian per Newton iteration: the walk of step
  // counts stops at 2e5 stage evaluations a run (compositions: 1e6).
  s.substeps = S;
  s.max_substeps = 2e5;
  s.symmetric_claimed = true;  // Gauss and Lobatto IIIA-IIIB are symmetric

  const bool gauss = p.rule.name == "gauss";
  auto list = [](const std::vector<double>& v) {
    std::vector<std::string> t;
    for (double x : v) t.push_back(fmt::format("{:.12g}", x));
    return fmt::format("{}", fmt::join(t, ", "));
  };
  rep.line(
      "method",
      fmt::format("{}:{}, the Galerkin variational integrator: the action of a polynomial of "
                  "degree {} by {}-node {} quadrature; the {}-stage {} (HLW VI.6.4), "
                  "symmetric, order {}",
                  p.rule.name, S, S, S, gauss ? "Gauss-Legendre" : "Gauss-Lobatto", S,
                  gauss ? "Gauss collocation method" : "Lobatto IIIA-IIIB pair", p.rule.order));
  rep.line("  nodes", "c = " + list(p.rule.c));
  rep.line("  weights", "b = " + list(p.rule.b));
  rep.line("  solved by",
           fmt::format("Newton's method on the {} interior control points and q1 together "
                       "({} unknowns), derivatives by nested AutoDiff",
                       S - 1, S * N));
  rep.line("expected order", fmt::format("{:g} ({})", p.expected, p.expected_from));
  rep.line("problem", system.line);
  rep.js["method"] = {{"name", p.name},
                      {"family", p.rule.name},
                      {"stages", S},
                      {"nodes", p.rule.c},
                      {"weights", p.rule.b},
                      {"documented_order", p.rule.order},
                      {"expected", p.expected},
                      {"expected_from", p.expected_from}};
  rep.js["problem"] = system.js;
  measure_map(s, rep);
}

}  // namespace method_detail

void measure_method(const MethodSpec& spec, const TestProblem& problem,
                    const std::vector<double>& q0, const std::vector<double>& p0,
                    const MapStudy& study, MapMeasurement& rep) {
  using method_detail::galerkin_step;
  const StudySystem system = test_problem_system(problem, q0, p0);
  const int N = static_cast<int>(q0.size());
  const char* who = "measure_method";
  // The same method in double-double, for the order study and the variational order from
  // order 6 on (map_study.hpp, kExtendedOrder).
  MapStudy s = study;
  const method_detail::GalerkinDD dd = method_detail::galerkin_dd(problem.name, spec.rule);
  s.step_dd = dd.step;
  s.generating_dd = dd.generating;
  if (problem.name == "pendulum")
    return method_detail::measure(spec, N, system, s, rep,
                                  galerkin_step(Pendulum{}, spec.rule, who));
  if (problem.name == "henon-heiles")
    return method_detail::measure(spec, N, system, s, rep,
                                  galerkin_step(HenonHeiles{}, spec.rule, who));
  return method_detail::measure(spec, N, system, s, rep, galerkin_step(Kepler{}, spec.rule, who));
}

}  // namespace vibook::verify
