/// \file newton.hpp
/// \brief Newton's method for fixed-size nonlinear systems, with a report of residual and
/// iterations and a typed failure. Never loops forever, never returns a silent NaN.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "vibook/core/errors.hpp"
#include "vibook/core/tolerance.hpp"
#include "vibook/core/types.hpp"

namespace vibook {

/// Stopping rule: the Newton update satisfies |dx|_inf <= step_rel*max(|x|_inf, scale) +
/// step_abs, or the residual satisfies |F|_inf <= residual_abs. At most max_iterations
/// iterations. `scale` is the size of x below which round-off is judged absolutely (pass the
/// size of the data, e.g. |q0|_inf, so that a solution passing through 0 still converges).
struct NewtonOptions {
  double step_rel = 4 * kEps;
  double scale = 0.0;
  double step_abs = 1e-300;
  double residual_abs = 0.0;
  int max_iterations = 50;
};

/// Solve F(x) = 0 for x in R^N, starting from x. `fj(x, F, J)` fills the residual F and its
/// Jacobian J at x. Returns the report; x holds the solution. Throws SolveError (with the
/// report) when the iteration does not converge within max_iterations, when the Jacobian is
/// singular, or when a non-finite value appears. `what` names the solve in the message.
template <int N, class FJ>
SolveReport newton_solve(Vec<double, N>& x, FJ&& fj, const NewtonOptions& opt,
                         const char* what = "Newton solve") {
  SolveReport rep;
  Vec<double, N> F;
  Mat<double, N> J;
  for (rep.iterations = 1; rep.iterations <= opt.max_iterations; ++rep.iterations) {
    fj(x, F, J);
    rep.residual = F.template lpNorm<Eigen::Infinity>();
    if (!std::isfinite(rep.residual)) break;
    if (rep.residual <= opt.residual_abs) {
      rep.converged = true;
      return rep;
    }
    const auto lu = J.partialPivLu();
    const Vec<double, N> dx = lu.solve(F);
    if (!dx.allFinite()) {
      throw SolveError(fmt::format("{}: singular Jacobian (residual {:.3e} after {} iterations)",
                                   what, rep.residual, rep.iterations),
                       rep);
    }
    x -= dx;
    const double step = dx.template lpNorm<Eigen::Infinity>();
    if (step <=
        opt.step_rel * std::max(x.template lpNorm<Eigen::Infinity>(), opt.scale) + opt.step_abs) {
      fj(x, F, J);  // report the residual at the returned point
      rep.residual = F.template lpNorm<Eigen::Infinity>();
      rep.converged = std::isfinite(rep.residual);
      if (rep.converged) return rep;
      break;
    }
  }
  if (rep.iterations > opt.max_iterations) rep.iterations = opt.max_iterations;
  throw SolveError(
      fmt::format("{}: no convergence (residual {:.3e} after {} iterations{})", what, rep.residual,
                  rep.iterations, std::isfinite(rep.residual) ? "" : ", non-finite"),
      rep);
}

}  // namespace vibook
