/// \file constrained.cpp
/// \brief RATTLE on the constrained test problems, measured by the map study (constrained.hpp).
#include "vibook/verify/constrained.hpp"

#include <cmath>
#include <memory>
#include <utility>

#include <fmt/format.h>

#include "vibook/core/autodiff.hpp"
#include "vibook/core/errors.hpp"
#include "vibook/core/newton.hpp"
#include "vibook/core/precision.hpp"
#include "vibook/mechanics/discrete_lagrangian.hpp"
#include "vibook/verify/constrained_impl.hpp"
#include "vibook/verify/reference.hpp"

namespace vibook::verify {

namespace {

// --- the problems: V(q) and g(q) templated on the scalar (double, double-double, AutoDiff) ----

// The spherical pendulum: a unit mass on a rod of unit length, gravity along −q₃.
struct SphericalPendulum {
  static constexpr bool autodiff = true;
  static constexpr int N = 3, M = 1;
  int m() const { return M; }
  double energy_potential(const Vec<double, N>& q) const { return potential<double>(q); }
  template <class S>
  S potential(const Vec<S, N>& q) const {
    return q(2);
  }
  template <class S>
  Vec<S, M> constraint(const Vec<S, N>& q) const {
    Vec<S, M> g;
    g(0) = constant<S>(0.5) * (q(0) * q(0) + q(1) * q(1) + q(2) * q(2) - constant<S>(1));
    return g;
  }
};

// The planar double pendulum in the Cartesian positions (x₁, y₁, x₂, y₂) of its bobs: unit
// masses and rods, gravity along −y.
struct DoublePendulum {
  static constexpr bool autodiff = true;
  static constexpr int N = 4, M = 2;
  int m() const { return M; }
  double energy_potential(const Vec<double, N>& q) const { return potential<double>(q); }
  template <class S>
  S potential(const Vec<S, N>& q) const {
    return q(1) + q(3);
  }
  template <class S>
  Vec<S, M> constraint(const Vec<S, N>& q) const {
    Vec<S, M> g;
    const S dx = q(2) - q(0), dy = q(3) - q(1);
    g(0) = constant<S>(0.5) * (q(0) * q(0) + q(1) * q(1) - constant<S>(1));
    g(1) = constant<S>(0.5) * (dx * dx + dy * dy - constant<S>(1));
    return g;
  }
};

using namespace constrained_detail;

template <class P>
void measure_problem(const P& prob, const ConstrainedProblem& problem, bool project,
                     const std::vector<double>& q0, const std::vector<double>& p0, MapStudy s,
                     MapMeasurement& rep) {
  set_constrained_system(prob, "of " + problem.name, q0, p0, s);
  s.step = naming_failures(
      [prob, project](Eigen::VectorXd& z, double h) { rattle_step(prob, project, z, h); }, P::N);
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
               {0.0, 0.8, 0.0}});
  // The double pendulum at angles 0.5 and 1 rad from the downward vertical, the second rod
  // turning at 0.5 rad per unit time.
  const double t1 = 0.5, t2 = 1.0, w2 = 0.5;
  const double x1 = std::sin(t1), y1 = -std::cos(t1);
  const double x2 = x1 + std::sin(t2), y2 = y1 - std::cos(t2);
  v.push_back({"double-pendulum",
               "H = |p|^2/2 + y1 + y2",
               "g1 = (x1^2 + y1^2 - 1)/2, g2 = ((x2-x1)^2 + (y2-y1)^2 - 1)/2",
               {x1, y1, x2, y2},
               {0.0, 0.0, w2 * std::cos(t2), w2 * std::sin(t2)}});
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
  if (problem.name == "spherical-pendulum")
    return measure_problem(SphericalPendulum{}, problem, project_velocity, q0, p0, std::move(study),
                           rep);
  if (problem.name == "double-pendulum")
    return measure_problem(DoublePendulum{}, problem, project_velocity, q0, p0, std::move(study),
                           rep);
  throw std::invalid_argument("measure_constrained: no constrained problem '" + problem.name + "'");
}

}  // namespace vibook::verify
