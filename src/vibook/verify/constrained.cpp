/// \file constrained.cpp
/// \brief RATTLE on the constrained test problems, measured by the map study (constrained.hpp).
#include "vibook/verify/constrained.hpp"

#include <cmath>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "vibook/modified/engine.hpp"

namespace vibook::verify {

namespace {

// The two problems are given in the expression language (make_problems) and measured as typed
// constrained systems are (constrained_typed.cpp): their derivatives from compiled tapes, the
// same code that measures a user's --constraint.
void measure_problem(const ConstrainedProblem& problem, bool project, const std::vector<double>& q0,
                     const std::vector<double>& p0, MapStudy s, MapMeasurement& rep) {
  std::unique_ptr<TypedDiscreteLagrangian> sys;
  {
    std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
    TypedTexts t{"", problem.potential, "", "p^2/2 + V(q)", static_cast<int>(problem.q0.size())};
    t.system_only = true;
    t.constraints = problem.constraint_texts;
    sys = std::make_unique<TypedDiscreteLagrangian>(t);
  }
  if (q0.size() != problem.q0.size() || p0.size() != problem.q0.size())
    throw std::invalid_argument("measure_constrained: the state has the wrong size");
  set_constrained_typed_system(s, *sys, problem.potential, q0, p0, "of " + problem.name);
  s.step = typed_rattle_step(*sys, problem.potential, project);
  s.symmetric_claimed = true;
  s.symmetric_note = "";
  rep.line("method",
           project ? "rattle: RATTLE (Andersen 1983; HLW VII.1.4), the positions of SHAKE with the "
                     "momentum projected onto the hidden constraint G(q) p = 0; symplectic, "
                     "symmetric, order 2"
                   : "shake: RATTLE without the velocity projection (deliberately wrong: the "
                     "momentum leaves the hidden constraint G(q) p = 0); documented as RATTLE, "
                     "order 2");
  rep.line("expected order", fmt::format("{:g}", s.expected));
  rep.line("problem",
           fmt::format("{}: {}, constraints {}; q0 = {}, p0 = {}", problem.name,
                       problem.hamiltonian, problem.constraints, vec_text(q0), vec_text(p0)));
  rep.js["method"] = {{"name", project ? "rattle" : "shake"}, {"expected", s.expected}};
  rep.js["system"] = {{"name", problem.name},
                      {"hamiltonian", problem.hamiltonian},
                      {"constraints", problem.constraints},
                      {"q0", q0},
                      {"p0", p0}};
  measure_map(s, rep);
  rep.line("variational order",
           "not measured: the constrained discrete Lagrangian's exact side is not implemented");
}

std::vector<ConstrainedProblem> make_problems() {
  std::vector<ConstrainedProblem> v;
  // The spherical pendulum from 1 rad off the vertical, pushed sideways.
  const double a = 1.0;
  v.push_back({"spherical-pendulum",
               "H = |p|^2/2 + q3",
               "g = (|q|^2 - 1)/2",
               {std::sin(a), 0.0, -std::cos(a)},
               {0.0, 0.8, 0.0},
               "z",
               {"(x^2+y^2+z^2-1)/2"}});
  // The double pendulum at angles 0.5 and 1 rad from the downward vertical, the second rod
  // turning at 0.5 rad per unit time.
  const double t1 = 0.5, t2 = 1.0, w2 = 0.5;
  const double x1 = std::sin(t1), y1 = -std::cos(t1);
  const double x2 = x1 + std::sin(t2), y2 = y1 - std::cos(t2);
  v.push_back({"double-pendulum",
               "H = |p|^2/2 + y1 + y2",
               "g1 = (x1^2 + y1^2 - 1)/2, g2 = ((x2-x1)^2 + (y2-y1)^2 - 1)/2",
               {x1, y1, x2, y2},
               {0.0, 0.0, w2 * std::cos(t2), w2 * std::sin(t2)},
               "q[2]+q[4]",
               {"(q[1]^2+q[2]^2-1)/2", "((q[3]-q[1])^2+(q[4]-q[2])^2-1)/2"}});
  return v;
}

}  // namespace

const std::vector<ConstrainedProblem>& constrained_problems() {
  static const std::vector<ConstrainedProblem> problems = make_problems();
  return problems;
}

const ConstrainedProblem* find_constrained_problem(const std::string& name) {
  for (const auto& p : constrained_problems())
    if (p.name == name) return &p;
  return nullptr;
}

void measure_constrained(const ConstrainedProblem& problem, bool project_velocity,
                         const std::vector<double>& q0, const std::vector<double>& p0,
                         MapStudy study, MapMeasurement& rep) {
  measure_problem(problem, project_velocity, q0, p0, std::move(study), rep);
}

}  // namespace vibook::verify
