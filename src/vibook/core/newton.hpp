/// \file newton.hpp
/// \brief Newton's method for fixed-size nonlinear systems, with a report of residual and
/// iterations and a typed failure. Never loops forever, never returns a silent NaN.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <type_traits>

#include "vibook/core/errors.hpp"
#include "vibook/core/format.hpp"
#include "vibook/core/scalar.hpp"
#include "vibook/core/tolerance.hpp"
#include "vibook/core/types.hpp"

namespace vibook {

/// Stopping rule, componentwise: every component of the Newton update satisfies
///   |dx_i| <= step_rel · max(|x_i|, |ref_i|, |x − ref|_inf) + step_abs,
/// where `ref` is the reference point passed to newton_solve (the previous state of a time
/// step; by default the initial guess). Each component is judged at its own size, so a large
/// component (a clock t ≈ 40 beside positions ≈ 0.4) does not loosen the small ones, while
/// the displacement |x − ref| bounds the attainable accuracy of components passing through 0.
/// The residual criterion |F|_inf <= residual_abs also stops. At most max_iterations.
/// Stagnation also stops, as converged: two successive updates both within
/// step_rel · max(|x|_inf, |ref|_inf) (normwise, at the size of the largest component), the
/// second not 16 times smaller than the first. A component that stays at zero (a particle at
/// rest) cannot meet the componentwise rule: the round-off of the equation's own terms, of the
/// size of the largest component, is the floor of its updates, and Newton's iteration, which
/// would otherwise contract quadratically, has stopped contracting (chapter "Verify your own
/// integrator", section "The criteria of every route").
/// For a wider scalar type set step_rel to a few units of *its* round-off (unit_roundoff<T>),
/// or to the tolerance asked for.
struct NewtonOptions {
  double step_rel = 4 * kEps;
  double step_abs = 1e-300;
  double residual_abs = 0.0;
  int max_iterations = 50;
};

namespace newton_detail {
// The stopping rule of NewtonOptions, for an update dx just applied to x (dx scaled by
// `factor` >= 1 when the iteration converges only linearly). Always inlined: it is on the
// critical path of every iteration of a compiled discrete Lagrangian's cheap steps.
template <int N, class T>
[[gnu::always_inline]] inline bool update_is_small(const Vec<T, N>& x, const Vec<T, N>& dx,
                                                   const Vec<T, N>& ref, const T& step_rel,
                                                   const T& step_abs, const T& factor = T(1)) {
  const T displacement = (x - ref).template lpNorm<Eigen::Infinity>();
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    using std::abs;
    const T size = std::max(std::max(T(abs(x(i))), T(abs(ref(i)))), displacement);
    if (!(factor * abs(dx(i)) <= step_rel * size + step_abs)) return false;
  }
  return true;
}

// The stagnation test of NewtonOptions: called after each update that failed the componentwise
// rule; true when this update and the one before are both at the round-off of the largest
// component (normwise) and this one is not 16 times smaller than the one before.
template <int N, class T>
class Stagnation {
 public:
  bool operator()(const Vec<T, N>& x, const Vec<T, N>& dx, const Vec<T, N>& ref,
                  const T& step_rel) {
    using std::max;
    const T size =
        max(T(x.template lpNorm<Eigen::Infinity>()), T(ref.template lpNorm<Eigen::Infinity>()));
    const T d = dx.template lpNorm<Eigen::Infinity>();
    const bool small = d <= step_rel * size;
    const bool stagnated = small && last_small_ && T(16) * d > last_;
    last_small_ = small;
    last_ = d;
    return stagnated;
  }

 private:
  T last_ = T(0);
  bool last_small_ = false;
};

// How a Newton step solves J dx = F: the default factors J by LU with partial pivoting.
struct PivotedLu {
  template <class M>
  static auto factor(const M& J) {
    return J.partialPivLu();
  }
};
}  // namespace newton_detail

/// The Newton linear solve for small fixed-size systems, where Eigen's general LU costs more
/// than the rest of a compiled discrete Lagrangian's or a Lobatto tableau's step (benchmarks
/// in tests/bench):
/// - n = 1…4: Eigen's closed-form inverse (cofactors), J⁻¹F a matrix–vector product. Its error
///   grows with the condition number of J as an LU's does, but it is not backward stable;
///   Newton's iteration corrects either (an inexact inverse only slows the contraction).
/// - n = 5…8: LU with partial pivoting (the pivot the largest entry of its column, rows
///   interchanged), the algorithm of Eigen's PartialPivLU written out for the fixed n so that
///   the compiler unrolls it, without Eigen's blocked and stride-generic machinery. Each pivot
///   is inverted once and multiplied by (a quotient is the slow operation on the step's
///   critical path), so the round-off differs from Eigen's by that and by the order of a few
///   sums.
/// - other sizes and Eigen::Dynamic: Eigen's PartialPivLU.
/// A singular J gives a non-finite update, reported as a singular Jacobian as for Eigen's LU.
struct SmallSystemSolve {
  template <class M>
  struct Inverse {
    M inverse;
    template <class V>
    V solve(const V& F) const {
      return inverse * F;
    }
  };
  template <class M>
  class Lu {
   public:
    static constexpr int n = M::RowsAtCompileTime;
    explicit Lu(const M& J) : lu_(J) {
      using std::abs;
      using T = typename M::Scalar;
      for (int k = 0; k < n; ++k) {
        int p = k;
        T largest = abs(lu_(k, k));
        for (int i = k + 1; i < n; ++i)
          if (abs(lu_(i, k)) > largest) {
            largest = abs(lu_(i, k));
            p = i;
          }
        perm_[k] = p;
        if (p != k)
          for (int j = 0; j < n; ++j) std::swap(lu_(k, j), lu_(p, j));
        const T inverse = T(1) / lu_(k, k);
        inverse_pivot_[k] = inverse;
        for (int i = k + 1; i < n; ++i) {
          const T l = lu_(i, k) * inverse;
          lu_(i, k) = l;
          for (int j = k + 1; j < n; ++j) lu_(i, j) -= l * lu_(k, j);
        }
      }
    }
    template <class V>
    V solve(const V& F) const {
      V x = F;
      for (int k = 0; k < n; ++k)
        if (perm_[k] != k) std::swap(x(k), x(perm_[k]));
      for (int i = 1; i < n; ++i)
        for (int j = 0; j < i; ++j) x(i) -= lu_(i, j) * x(j);
      for (int i = n - 1; i >= 0; --i) {
        for (int j = i + 1; j < n; ++j) x(i) -= lu_(i, j) * x(j);
        x(i) *= inverse_pivot_[i];
      }
      return x;
    }

   private:
    M lu_;
    std::array<typename M::Scalar, std::size_t(n)> inverse_pivot_{};
    std::array<int, std::size_t(n)> perm_{};
  };
  template <class M>
  static auto factor(const M& J) {
    if constexpr (M::RowsAtCompileTime >= 1 && M::RowsAtCompileTime <= 4)
      return Inverse<M>{M(J.inverse())};
    else if constexpr (M::RowsAtCompileTime >= 5 && M::RowsAtCompileTime <= 8)
      return Lu<M>(J);
    else
      return J.partialPivLu();
  }
};

namespace newton_detail {
[[gnu::noinline, gnu::cold]] inline SolveError singular_jacobian(const char* what,
                                                                 const SolveReport& rep) {
  return SolveError(std::string(what) + ": singular Jacobian (residual " +
                        text::e(rep.residual, 3) + " after " + std::to_string(rep.iterations) +
                        " iterations)",
                    rep);
}

[[gnu::noinline, gnu::cold]] inline SolveError no_convergence(const char* what, SolveReport rep,
                                                              int max_iterations) {
  if (rep.iterations > max_iterations) rep.iterations = max_iterations;
  return SolveError(std::string(what) + ": no convergence (residual " + text::e(rep.residual, 3) +
                        " after " + std::to_string(rep.iterations) + " iterations" +
                        (std::isfinite(rep.residual) ? "" : ", non-finite") + ")",
                    rep);
}
}  // namespace newton_detail

/// Solve F(x) = 0 for x in R^N, starting from x. `fj(x, F, J)` fills the residual F and its
/// Jacobian J at x (an `fj(x, F, J, bool with_jacobian)` is called with false where J is not
/// used: for the residual reported at the returned point).
/// Jacobian J at x. Returns the report; x holds the solution. Throws SolveError (with the
/// report) when the iteration does not converge within max_iterations, when the Jacobian is
/// singular, or when a non-finite value appears. `what` names the solve in the message.
/// N may be Eigen::Dynamic (F and J are then given x's size before fj fills them). `Linear`
/// solves J dx = F: Eigen's LU with partial pivoting by default, or SmallSystemSolve.
template <int N, class FJ, class T = double, class Linear = newton_detail::PivotedLu>
SolveReport newton_solve(Vec<T, N>& x, FJ&& fj, const NewtonOptions& opt,
                         const char* what = "Newton solve", const Vec<T, N>* reference = nullptr) {
  const Vec<T, N> ref = reference ? *reference : x;
  SolveReport rep;
  Vec<T, N> F;
  Mat<T, N> J;
  if constexpr (N == Eigen::Dynamic) {  // fj fills blocks of F and J: give them x's size
    F.resize(x.size());
    J.resize(x.size(), x.size());
  }
  const T step_rel(opt.step_rel), step_abs(opt.step_abs);
  newton_detail::Stagnation<N, T> stagnation;
  const auto evaluate = [&](bool with_jacobian) {
    if constexpr (std::is_invocable_v<FJ&, const Vec<T, N>&, Vec<T, N>&, Mat<T, N>&, bool>)
      fj(x, F, J, with_jacobian);
    else
      fj(x, F, J);
  };
  for (rep.iterations = 1; rep.iterations <= opt.max_iterations; ++rep.iterations) {
    evaluate(true);
    rep.residual = to_double(T(F.template lpNorm<Eigen::Infinity>()));
    if (!std::isfinite(rep.residual)) break;
    if (rep.residual <= opt.residual_abs) {
      rep.converged = true;
      return rep;
    }
    const auto lu = Linear::factor(J);
    const Vec<T, N> dx = lu.solve(F);
    if (!std::isfinite(to_double(T(dx.template lpNorm<Eigen::Infinity>()))))
      throw newton_detail::singular_jacobian(what, rep);
    x -= dx;
    if (newton_detail::update_is_small<N>(x, dx, ref, step_rel, step_abs) ||
        stagnation(x, dx, ref, step_rel)) {
      evaluate(false);  // the residual at the returned point: F alone, when fj can skip J
      rep.residual = to_double(T(F.template lpNorm<Eigen::Infinity>()));
      rep.converged = std::isfinite(rep.residual);
      if (rep.converged) return rep;
      break;
    }
  }
  throw newton_detail::no_convergence(what, rep, opt.max_iterations);
}

/// Newton's method for an F that is affine in x: the Jacobian J does not depend on x (the
/// discrete Euler–Lagrange equation of a discrete Lagrangian whose D2 D1 L_d is free of
/// q_(k+1), the trapezoidal rule's among them). `fj(x, F, J, with_jacobian)` as for
/// newton_solve; J is asked for once and factored once, and every later evaluation is of F
/// alone. The iterates are newton_solve's to the bit for the same `Linear` (its Jacobian
/// would be the same matrix, factored the same way), with the same stopping rule and typed
/// failures; what is saved is the evaluation newton_solve spends after its last update to report
/// the residual there. Here, as in simplified_newton_solve, the residual reported is |F| at the
/// last evaluation, before the last update (an update that passed the stopping rule). For an affine
/// F the first update lands on the solution to round-off, so a step costs two evaluations of F and
/// one factorisation, where newton_solve needs three and two.
template <int N, class FJ, class T = double, class Linear = newton_detail::PivotedLu>
SolveReport affine_newton_solve(Vec<T, N>& x, FJ&& fj, const NewtonOptions& opt,
                                const char* what = "Newton solve",
                                const Vec<T, N>* reference = nullptr) {
  const Vec<T, N> ref = reference ? *reference : x;
  SolveReport rep;
  Vec<T, N> F;
  Mat<T, N> J;
  if constexpr (N == Eigen::Dynamic) {
    F.resize(x.size());
    J.resize(x.size(), x.size());
  }
  const T step_rel(opt.step_rel), step_abs(opt.step_abs);
  newton_detail::Stagnation<N, T> stagnation;
  fj(x, F, J, true);
  const auto lu = Linear::factor(J);
  for (rep.iterations = 1; rep.iterations <= opt.max_iterations; ++rep.iterations) {
    rep.residual = to_double(T(F.template lpNorm<Eigen::Infinity>()));
    if (!std::isfinite(rep.residual)) break;
    if (rep.residual <= opt.residual_abs) {
      rep.converged = true;
      return rep;
    }
    const Vec<T, N> dx = lu.solve(F);
    if (!std::isfinite(to_double(T(dx.template lpNorm<Eigen::Infinity>()))))
      throw newton_detail::singular_jacobian(what, rep);
    x -= dx;
    if (newton_detail::update_is_small<N>(x, dx, ref, step_rel, step_abs) ||
        stagnation(x, dx, ref, step_rel)) {
      rep.converged = true;
      return rep;
    }
    fj(x, F, J, false);
  }
  throw newton_detail::no_convergence(what, rep, opt.max_iterations);
}

/// Simplified Newton for small systems: the Jacobian `jac(x)` is evaluated at the start and
/// inverted once; `f(x)` alone is evaluated in the iterations. The Jacobian is evaluated again
/// only when an update fails to shrink eightfold (the contraction of a frozen Jacobian is then
/// too slow). For the implicit steps of small time steps the Jacobian changes by O(h) over a
/// step, so the iteration converges in as many iterations as Newton's and evaluates the
/// Jacobian once instead of in every iteration. Same stopping rule, report and typed failure
/// as newton_solve; the residual reported is |f| at the last evaluation (before the last,
/// negligible update).
template <int N, class Fn, class Jac, class T = double>
SolveReport simplified_newton_solve(Vec<T, N>& x, Fn&& f, Jac&& jac, const NewtonOptions& opt,
                                    const char* what = "Newton solve",
                                    const Vec<T, N>* reference = nullptr) {
  const Vec<T, N> ref = reference ? *reference : x;
  SolveReport rep;
  const T step_rel(opt.step_rel), step_abs(opt.step_abs);
  newton_detail::Stagnation<N, T> stagnation;
  Mat<T, N> Jinv = Mat<T, N>(jac(x)).inverse();
  T last = T(0);
  for (rep.iterations = 1; rep.iterations <= opt.max_iterations; ++rep.iterations) {
    const Vec<T, N> F = f(x);
    rep.residual = to_double(T(F.template lpNorm<Eigen::Infinity>()));
    if (!std::isfinite(rep.residual)) break;
    if (rep.residual <= opt.residual_abs) {
      rep.converged = true;
      return rep;
    }
    Vec<T, N> dx = Jinv * F;
    const T size_dx = dx.template lpNorm<Eigen::Infinity>();
    if (!std::isfinite(to_double(size_dx))) throw newton_detail::singular_jacobian(what, rep);
    // The error left after a linearly converging update is about ρ/(1 − ρ) times the update,
    // ρ the contraction seen: the stopping rule is applied to that.
    T factor(1);
    if (last > T(0) && size_dx > last * T(0.125)) {  // slow contraction: a fresh Jacobian
      Jinv = Mat<T, N>(jac(x)).inverse();
      dx = Jinv * F;
    } else if (last > T(0)) {
      const T rho = size_dx / last;
      factor = std::max(T(1), T(rho / (T(1) - rho)));
    }
    last = dx.template lpNorm<Eigen::Infinity>();
    x -= dx;
    if (newton_detail::update_is_small<N>(x, dx, ref, step_rel, step_abs, factor) ||
        stagnation(x, dx, ref, step_rel)) {
      rep.converged = true;
      return rep;
    }
  }
  throw newton_detail::no_convergence(what, rep, opt.max_iterations);
}

}  // namespace vibook
