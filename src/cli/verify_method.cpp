// `vibook verify --method gauss:S|lobatto:S` (issue #25): the Galerkin variational integrator of
// integrators/galerkin.hpp with S stages (a polynomial of degree S through the step, the
// S-node Gauss–Legendre or Gauss–Lobatto quadrature of the action, the interior control points
// eliminated by Newton's method with the new position), on one of the nonlinear test problems
// L = |v|²/2 − V(q). Documented order 2S (Gauss) or 2S − 2 (Lobatto); symmetric, so
// reversibility is part of the verdict. The measurements are those of verify_map.cpp, against
// Hamilton's equations in double-double.
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
#include "vibook/integrators/galerkin.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/problems/problems.hpp"

namespace vibook::cli {

namespace {

using nlohmann::json;

constexpr int kMaxGauss = 4, kMaxLobatto = 5;

struct Plan {
  Quadrature rule;
  int stages = 0;
  const TestProblem* problem = nullptr;
  std::vector<double> q0, p0;
  double expected = 0;
  std::string expected_from;
  MapStudy study;  // the measurement settings
};

Plan check(const MethodOptions& o) {
  Plan p;
  const auto colon = o.method.find(':');
  const std::string family = o.method.substr(0, colon);
  if (family != "gauss" && family != "lobatto")
    throw ArgumentError("--method", "unknown method '" + o.method + "' (gauss:S, S = 1.." +
                                        std::to_string(kMaxGauss) + ", or lobatto:S, S = 2.." +
                                        std::to_string(kMaxLobatto) + ": S stages)");
  if (colon == std::string::npos)
    throw ArgumentError("--method",
                        "'" + o.method + "' needs the number of stages, e.g. " + family + ":3");
  const long long s = parse_integer("--method", o.method.substr(colon + 1));
  const int lo = family == "gauss" ? 1 : 2, hi = family == "gauss" ? kMaxGauss : kMaxLobatto;
  if (s < lo || s > hi)
    throw ArgumentError("--method",
                        fmt::format("{} takes {} to {} stages, not {}", family, lo, hi, s));
  p.stages = static_cast<int>(s);
  p.rule = quadrature_rule(family, p.stages);
  p.problem = &find_test_problem(o.problem);
  check_initial_state(o, *p.problem, p.q0, p.p0, p.study);
  p.expected = p.rule.order;
  p.expected_from = "documented";
  if (o.expected_given) {
    p.expected = parse_number("--expected-order", o.expected);
    if (!(p.expected > 0 && p.expected <= 10))
      throw ArgumentError("--expected-order", "must lie in (0, 10]");
    p.expected_from = "--expected-order";
  }
  check_study_options(o, p.study);
  if (o.json_given) check_output_path(o.json_out, "--json-out", true);
  return p;
}

template <class P>
auto mechanical_lagrangian(P prob) {
  // L = |v|²/2 − V(q); the return type declared, as AutoDiff needs (autodiff.hpp)
  return [prob](const auto& q, const auto& v) -> std::remove_cvref_t<decltype(q(0))> {
    using T = std::remove_cvref_t<decltype(q(0))>;
    return constant<T>(0.5) * squared_norm(v) - prob.template potential<T>(q);
  };
}

// The one-step map (instantiated for each number of stages and problem); the rest of the
// report depends on the problem only.
template <int S, class P>
verify::Step galerkin_step(const P& prob, const Quadrature& rule) {
  constexpr int N = P::N;
  using Integrator = GalerkinIntegrator<N, S, decltype(mechanical_lagrangian(prob))>;
  auto integrator = std::make_shared<Integrator>(mechanical_lagrangian(prob), rule);
  return naming_failures(
      [integrator](Eigen::VectorXd& z, double h) { verify::step_qp<N>(*integrator, z, h); }, N);
}

template <class P>
int run_problem(const MethodOptions& o, const Plan& p, const P& prob, verify::Step step) {
  constexpr int N = P::N;
  const int S = p.stages;
  MapReport rep;
  Eigen::VectorXd z0(2 * N);
  for (int i = 0; i < N; ++i) {
    z0(i) = p.q0[static_cast<std::size_t>(i)];
    z0(N + i) = p.p0[static_cast<std::size_t>(i)];
  }
  MapStudy s = p.study;
  s.step = std::move(step);
  s.z0 = z0;
  s.field = [&prob](const std::vector<dd_real>& y) {
    Vec<dd_real, N> q;
    for (int i = 0; i < N; ++i) q(i) = y[static_cast<std::size_t>(i)];
    const Vec<dd_real, N> g = prob.template gradient<dd_real>(q);
    std::vector<dd_real> r(2 * N);
    for (int i = 0; i < N; ++i) {
      r[static_cast<std::size_t>(i)] = y[static_cast<std::size_t>(N + i)];
      r[static_cast<std::size_t>(N + i)] = -g(i);
    }
    return r;
  };
  s.H = [&prob](const Eigen::VectorXd& z) {
    return energy(prob, Vec<double, N>(z.head<N>()), Vec<double, N>(z.tail<N>()));
  };
  s.expected = p.expected;
  // A Galerkin step costs a nested-AutoDiff Hessian per Newton iteration: the walk of step
  // counts stops at 2e5 stage evaluations a run (compositions: 1e6).
  s.substeps = S;
  s.max_substeps = 2e5;
  s.require_reversible = true;  // Gauss and Lobatto IIIA-IIIB are symmetric

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
  rep.line("problem", fmt::format("{}: {}, q0 = {}, p0 = {}", p.problem->name,
                                  p.problem->hamiltonian, vec_text(p.q0), vec_text(p.p0)));
  rep.js["method"] = {{"name", o.method},
                      {"family", p.rule.name},
                      {"stages", S},
                      {"nodes", p.rule.c},
                      {"weights", p.rule.b},
                      {"documented_order", p.rule.order},
                      {"expected", p.expected},
                      {"expected_from", p.expected_from}};
  rep.js["problem"] = {{"name", p.problem->name}, {"q0", p.q0}, {"p0", p.p0}};
  measure_map(s, rep);
  return rep.finish(o.json_given, o.json_out);
}

template <int S>
int run_stages(const MethodOptions& o, const Plan& p) {
  if (p.problem->name == "pendulum")
    return run_problem(o, p, Pendulum{}, galerkin_step<S>(Pendulum{}, p.rule));
  if (p.problem->name == "henon-heiles")
    return run_problem(o, p, HenonHeiles{}, galerkin_step<S>(HenonHeiles{}, p.rule));
  return run_problem(o, p, Kepler{}, galerkin_step<S>(Kepler{}, p.rule));
}

}  // namespace

int run_method(const MethodOptions& o) {
  const Plan p = check(o);
  switch (p.stages) {
    case 1:
      return run_stages<1>(o, p);
    case 2:
      return run_stages<2>(o, p);
    case 3:
      return run_stages<3>(o, p);
    case 4:
      return run_stages<4>(o, p);
    default:
      return run_stages<5>(o, p);
  }
}

}  // namespace vibook::cli
