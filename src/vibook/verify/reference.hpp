/// \file reference.hpp
/// \brief An independent reference solution for `vibook verify`: the continuous equations of
/// the system the user meant — the Euler–Lagrange equations of a Lagrangian L(q, v), or
/// Hamilton's equations of H(q, p) — integrated by Gragg–Bulirsch–Stoer extrapolation (order
/// 2k in the macro-step, k = 8 by default) in a wide scalar type (double-double for the
/// command). Never the method under test: a wrong discrete Lagrangian converges to the wrong
/// solution, and its order against this reference shows it.
///
/// **Method.** One macro-step H is the modified midpoint rule with n_j = 2j substeps,
/// j = 1 … k, extrapolated to zero step by Aitken–Neville in (H/n_j)² (Hairer, Nørsett and
/// Wanner, *Solving ODEs I*, §II.9). The run is repeated with twice the macro-steps until two
/// runs agree to the requested tolerance; their difference is the reference's error estimate,
/// reported beside it (a convergence study must not read points below it).
///
/// **Equations.** For L(q, v), with the Hessian blocks M = ∂²L/∂v² and B = ∂²L/∂v∂q (by nested
/// forward AutoDiff in T), the acceleration solves M a = ∂L/∂q − B v; the state is (q, v), and
/// the canonical momentum p = ∂L/∂v is formed at the ends. For H(q, p): q' = ∂H/∂p,
/// p' = −∂H/∂q. The Legendre map from the initial (q, p) to v is solved by Newton in T.
///
/// Chapter: \ref chapter-verify.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "vibook/core/autodiff.hpp"
#include "vibook/core/errors.hpp"
#include "vibook/core/scalar.hpp"
#include "vibook/core/types.hpp"

namespace vibook::verify {

/// Value, gradient and Hessian of f(Vec<S, M>) → S at x, by nested forward AutoDiff over T.
template <int M, class T, class F>
void value_gradient_hessian(F&& f, const Vec<T, M>& x, T& value, Vec<T, M>& g, Mat<T, M>& H) {
  using Out = ad::Dual2<M, T>;
  const Out r = f(ad::variables2<M, T>(x));
  value = r.value().value();
  g = r.value().derivatives();
  for (int j = 0; j < M; ++j) H.col(j) = r.derivatives()(j).derivatives();
}

/// The right-hand side y' = F(y) of a first-order system in T.
template <class T>
using Field = std::function<std::vector<T>(const std::vector<T>&)>;

/// One Gragg–Bulirsch–Stoer macro-step of size H with k columns (order 2k).
template <class T>
std::vector<T> gbs_step(const Field<T>& f, const std::vector<T>& y0, const T& H, int k) {
  const std::size_t n = y0.size();
  std::vector<std::vector<T>> table;  // table[j]: the extrapolated row j (Aitken–Neville)
  std::vector<int> steps;
  for (int j = 1; j <= k; ++j) {
    const int nj = 2 * j;
    steps.push_back(nj);
    const T h = H / T(double(nj));
    // modified midpoint: z0 = y0, z1 = y0 + h f(y0), z_{m+1} = z_{m-1} + 2h f(z_m)
    std::vector<T> zm = y0, z = y0;
    std::vector<T> fz = f(y0);
    for (std::size_t i = 0; i < n; ++i) z[i] = y0[i] + h * fz[i];
    for (int m = 1; m < nj; ++m) {
      fz = f(z);
      for (std::size_t i = 0; i < n; ++i) {
        const T next = zm[i] + T(2.0) * h * fz[i];
        zm[i] = z[i];
        z[i] = next;
      }
    }
    fz = f(z);
    std::vector<T> row(n);
    for (std::size_t i = 0; i < n; ++i) row[i] = (z[i] + zm[i] + h * fz[i]) / T(2.0);
    // Aitken–Neville in h²: T_{j,m} = T_{j,m−1} + (T_{j,m−1} − T_{j−1,m−1}) / ((n_j/n_{j−m})² − 1)
    std::vector<std::vector<T>> next{row};
    for (int m = 1; m < j; ++m) {
      // 1 / ((n_j/n)² − 1) = n² / (n_j² − n²), both integers: exact in T (a ratio such as
      // 16/6 rounded to double would leave an O(ε H²) term that no column removes)
      const int nm = steps[static_cast<std::size_t>(j - 1 - m)];
      const T num = T(double(nm * nm)), den = T(double(nj * nj - nm * nm));
      std::vector<T> e(n);
      for (std::size_t i = 0; i < n; ++i)
        e[i] = next.back()[i] +
               (next.back()[i] - table[static_cast<std::size_t>(m - 1)][i]) * num / den;
      next.push_back(e);
    }
    table = next;
  }
  return table.back();
}

/// Integrate y' = f(y) from y0 over [0, t_end] with `macro` macro-steps of k columns.
template <class T>
std::vector<T> gbs_integrate(const Field<T>& f, std::vector<T> y, double t_end, long macro,
                             int k = 8) {
  const T H = T(t_end) / T(double(macro));
  for (long s = 0; s < macro; ++s) y = gbs_step(f, y, H, k);
  return y;
}

/// A reference solution and its estimated error (max-norm, in the reported coordinates).
template <class T>
struct Reference {
  std::vector<T> y;      ///< the solution at t_end
  double error = 0;      ///< |run(M) − run(2M)|_max, the estimate of its error
  long macro_steps = 0;  ///< M of the accepted run
  long evaluations = 0;  ///< right-hand sides evaluated in all runs
};

/// Repeat gbs_integrate with twice the macro-steps until two runs agree to `tol` relative to
/// max(1, |y|); stop (and report the estimate reached) at `max_macro` macro-steps. A
/// non-finite value is a NumericalError naming the reference.
template <class T>
Reference<T> reference_solution(const Field<T>& f, const std::vector<T>& y0, double t_end,
                                double tol = 1e-26, long first_macro = 0, long max_macro = 1L << 16,
                                int k = 8) {
  long evaluations = 0;
  const Field<T> counted = [&](const std::vector<T>& y) {
    ++evaluations;
    return f(y);
  };
  long M = first_macro > 0 ? first_macro : std::max(1L, long(std::ceil(t_end / 0.25)));
  auto finite = [](const std::vector<T>& y) {
    return std::all_of(y.begin(), y.end(), [](const T& x) { return std::isfinite(to_double(x)); });
  };
  // A macro-step too long for the explicit midpoint rule inside (a stiff or fast system) gives
  // a non-finite result: halve it until the result is finite.
  std::vector<T> prev = gbs_integrate(counted, y0, t_end, M, k);
  while (!finite(prev) && 2 * M <= max_macro) {
    M *= 2;
    prev = gbs_integrate(counted, y0, t_end, M, k);
  }
  if (!finite(prev))
    throw NumericalError(
        "reference solution: no finite solution of the continuous equations up "
        "to t = " +
        std::to_string(t_end) + " with " + std::to_string(M) +
        " macro-steps (a singularity, or a blow-up of the system itself)");
  for (;;) {
    const long M2 = 2 * M;
    std::vector<T> next = gbs_integrate(counted, y0, t_end, M2, k);
    if (!finite(next))
      throw NumericalError("reference solution: not finite with " + std::to_string(M2) +
                           " macro-steps up to t = " + std::to_string(t_end));
    double diff = 0, scale = 1;
    for (std::size_t i = 0; i < next.size(); ++i) {
      diff = std::max(diff, std::abs(to_double(T(next[i] - prev[i]))));
      scale = std::max(scale, std::abs(to_double(next[i])));
    }
    if (M2 >= max_macro && diff > 1e-12 * scale)
      throw NumericalError("reference solution: the continuous equations' solution up to t = " +
                           std::to_string(t_end) + " did not settle: two estimates with " +
                           std::to_string(M) + " and " + std::to_string(M2) +
                           " macro-steps differ by " + std::to_string(diff) +
                           " (a singularity or a loss of smoothness on the way)");
    if (diff <= tol * scale || M2 >= max_macro) {
      Reference<T> r;
      r.y = next;
      r.error = diff;
      r.macro_steps = M2;
      r.evaluations = evaluations;
      return r;
    }
    prev = std::move(next);
    M = M2;
  }
}

}  // namespace vibook::verify
