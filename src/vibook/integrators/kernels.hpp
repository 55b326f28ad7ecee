/// \file kernels.hpp
/// \brief Fast kernels for separable mechanical problems H = ½|p|² + U(q): the symplectic
/// Euler pair, Störmer–Verlet (velocity form) and the implicit midpoint rule. Each is the
/// one-step map of a discrete Lagrangian of Vermeeren 2017, Example 1, and a doctest checks
/// it against the generic DelIntegrator on that discrete Lagrangian (claim V-EX1).
///
/// Interface (shared with DelIntegrator): `SolveReport step(q, p, h)` advances (q, p) in
/// place. Explicit kernels report zero residual and zero iterations.
///
/// Chapter: \ref chapter-vi.
#pragma once

#include "vibook/core/autodiff.hpp"
#include "vibook/core/newton.hpp"
#include "vibook/core/types.hpp"

namespace vibook {

/// Symplectic Euler `se` — discrete Lagrangian h·L(q1, (q1 − q0)/h), Vermeeren Ex. 1(d),
/// Shen & Sun (4.16): q1 = q0 + h p0, p1 = p0 − h ∇U(q1).
template <class Problem>
class SymplecticEuler {
 public:
  static constexpr int N = Problem::N;
  explicit SymplecticEuler(Problem P = {}) : P_(P) {}
  SolveReport step(Vec<double, N>& q, Vec<double, N>& p, double h) const {
    q += h * p;
    p -= h * P_.gradient(q);
    return {0.0, 0, true};
  }

 private:
  Problem P_;
};

/// Adjoint symplectic Euler `se-adjoint` — discrete Lagrangian h·L(q0, (q1 − q0)/h),
/// Vermeeren Ex. 1(c): p1 = p0 − h ∇U(q0), q1 = q0 + h p1.
template <class Problem>
class SymplecticEulerAdjoint {
 public:
  static constexpr int N = Problem::N;
  explicit SymplecticEulerAdjoint(Problem P = {}) : P_(P) {}
  SolveReport step(Vec<double, N>& q, Vec<double, N>& p, double h) const {
    p -= h * P_.gradient(q);
    q += h * p;
    return {0.0, 0, true};
  }

 private:
  Problem P_;
};

/// Störmer–Verlet, velocity form — discrete Lagrangian h·(½L(q0, v) + ½L(q1, v)),
/// Vermeeren Ex. 1(b): p½ = p0 − (h/2)∇U(q0), q1 = q0 + h p½, p1 = p½ − (h/2)∇U(q1).
/// One force evaluation per step: the force at the end of a step is kept for the next one
/// (it is reused only if the next step starts from the same q, bit for bit).
template <class Problem>
class StormerVerlet {
 public:
  static constexpr int N = Problem::N;
  explicit StormerVerlet(Problem P = {}) : P_(P) {}
  SolveReport step(Vec<double, N>& q, Vec<double, N>& p, double h) {
    if (!cached_ || q != q_cached_) g_ = P_.gradient(q);
    const double hh = 0.5 * h;
    p -= hh * g_;
    q += h * p;
    g_ = P_.gradient(q);
    p -= hh * g_;
    q_cached_ = q;
    cached_ = true;
    return {0.0, 0, true};
  }

 private:
  Problem P_;
  Vec<double, N> g_ = Vec<double, N>::Zero();
  Vec<double, N> q_cached_ = Vec<double, N>::Zero();
  bool cached_ = false;
};

/// Implicit midpoint rule — discrete Lagrangian h·L((q0 + q1)/2, (q1 − q0)/h), Vermeeren
/// Ex. 1(a). For H = ½|p|² + U the midpoint m = (q0 + q1)/2 solves
///   m − q0 − (h/2) p0 + (h²/4) ∇U(m) = 0,
/// by Newton's method with the Hessian ∇²U from AutoDiff of the problem's gradient; then
/// q1 = 2m − q0 and p1 = p0 − h ∇U(m).
template <class Problem>
class ImplicitMidpoint {
 public:
  static constexpr int N = Problem::N;
  explicit ImplicitMidpoint(Problem P = {}, NewtonOptions options = {})
      : P_(P), options_(options) {}
  SolveReport step(Vec<double, N>& q, Vec<double, N>& p, double h) const {
    const double c = 0.25 * h * h;
    Vec<double, N> m = q + 0.5 * h * p;
    const Vec<double, N> base = m;
    auto fj = [&](const Vec<double, N>& x, Vec<double, N>& F, Mat<double, N>& J) {
      F = x - base + c * P_.gradient(x);
      J = Mat<double, N>::Identity() +
          c * ad::jacobian<N>([&](const auto& y) { return P_.gradient(y); }, x);
    };
    const SolveReport rep = newton_solve<N>(m, fj, options_, "implicit midpoint step", &q);
    p -= h * P_.gradient(m);
    q = 2.0 * m - q;
    return rep;
  }

 private:
  Problem P_;
  NewtonOptions options_;
};

}  // namespace vibook
