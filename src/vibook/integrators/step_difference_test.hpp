// Test helper (not installed): the largest one-step difference between two steppers of one
// method (galerkin_test.cpp, prk_test.cpp).
#pragma once

#include <algorithm>
#include <cmath>

#include "vibook/core/types.hpp"

namespace vibook::test {

struct StepDifference {
  double state = 0;       ///< max |Δq|, |Δp| (absolute)
  double action = 0;      ///< max |ΔL_d| of the step (absolute; both steppers have action())
  bool converged = true;  ///< every step of both reported convergence
};

// Along `steps` steps of h of `a` on Kepler (e = 0.5, from perihelion), `b` takes each step
// from a's state, so that nothing accumulates.
template <class A, class B>
StepDifference step_difference(A& a, B& b, int steps, double h) {
  Vec<double, 2> q(0.5, 0), p(0, std::sqrt(3.0));
  StepDifference d;
  for (int k = 0; k < steps; ++k) {
    Vec<double, 2> q2 = q, p2 = p;
    d.converged = a.step(q, p, h).converged && d.converged;
    d.converged = b.step(q2, p2, h).converged && d.converged;
    d.state = std::max({d.state, (q - q2).template lpNorm<Eigen::Infinity>(),
                        (p - p2).template lpNorm<Eigen::Infinity>()});
    d.action = std::max(d.action, std::abs(a.action() - b.action()));
  }
  return d;
}

}  // namespace vibook::test
