/// \file constrained_impl.hpp
/// \brief The templates behind constrained.hpp: a constrained system's derivatives, RATTLE, the
/// constrained discrete Euler–Lagrange step of a discrete Lagrangian, the index-1 reference and
/// the system part of a map study, for any problem P with
///   `static constexpr int N` (positions) and `M` (constraints, or Eigen::Dynamic),
///   `int m() const` (the number of constraints),
///   `double energy_potential(const Vec<double, N>&) const` (V in double),
///   `derivatives<T>(q, ∇V, G, &g)` and `hessian<T>(q, i)` (∇²g_i) in double and double-double.
/// Internal: included by constrained_typed.cpp, which measures the constraints typed after
/// --constraint and the test problems (given in the same language).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "vibook/core/errors.hpp"
#include "vibook/core/newton.hpp"
#include "vibook/core/precision.hpp"
#include "vibook/mechanics/discrete_lagrangian.hpp"
#include "vibook/verify/map_study.hpp"

namespace vibook::verify::constrained_detail {

// ∇V and G = ∂g/∂q at q in T (g too when asked): the problem's own (constrained_typed.cpp:
// compiled tapes, which cost the compiler far less than nested AutoDiff on the expression tree).
template <class P, class T>
void first_derivatives(const P& prob, const Vec<T, P::N>& q, Vec<T, P::N>& gradV,
                       Eigen::Matrix<T, P::M, P::N>& G, Vec<T, P::M>* g = nullptr) {
  prob.template derivatives<T>(q, gradV, G, g);
}

// ∇²g_i(q) in T.
template <class P, class T>
Mat<T, P::N> constraint_hessian(const P& prob, const Vec<T, P::N>& q, int i) {
  return prob.template hessian<T>(q, i);
}

// pᵀ ∇²g_i(q) p for each constraint i (the hidden constraint's time derivative's curvature term).
template <class P, class T>
Vec<T, P::M> curvature(const P& prob, const Vec<T, P::N>& q, const Vec<T, P::N>& p) {
  constexpr int N = P::N;
  const int m = prob.m();
  Vec<T, P::M> r(m);
  for (int i = 0; i < m; ++i) {
    const Vec<T, N> Hp = constraint_hessian<P, T>(prob, q, i) * p;
    T s = p(0) * Hp(0);
    for (int k = 1; k < N; ++k) s = s + p(k) * Hp(k);
    r(i) = s;
  }
  return r;
}

// The momentum projected onto the hidden constraint at q1: p1 − G(q1)ᵀμ with G(q1)(p1 − G(q1)ᵀμ)
// = 0 (one linear solve; μ = 0 when `project` is false).
template <class P>
Vec<double, P::N> project_momentum(const Eigen::Matrix<double, P::M, P::N>& G1,
                                   const Vec<double, P::N>& p1) {
  const Mat<double, P::M> A = G1 * G1.transpose();
  const Vec<double, P::M> mu = A.partialPivLu().solve(Vec<double, P::M>(G1 * p1));
  return p1 - G1.transpose() * mu;
}

// --- RATTLE (HLW §VII.1.4, (1.26)) ------------------------------------------------------------
//   p_{1/2} = p_0 − h/2 (∇V(q_0) + G(q_0)ᵀ λ),  q_1 = q_0 + h p_{1/2},  g(q_1) = 0,
//   p_1 = p_{1/2} − h/2 (∇V(q_1) + G(q_1)ᵀ μ),  G(q_1) p_1 = 0.
// λ by Newton's method on g(q_1(λ)) = 0 (its Jacobian −h²/2 G(q_1) G(q_0)ᵀ), μ by one linear
// solve. Without the projection (`project` false) μ = 0: the momentum leaves the hidden
// constraint.
template <class P>
void rattle_step(const P& prob, bool project, Eigen::VectorXd& z, double h) {
  constexpr int N = P::N, M = P::M;
  const int m = prob.m();
  const Vec<double, N> q0 = z.head<N>(), p0 = z.segment<N>(N);
  Vec<double, N> gradV;
  Eigen::Matrix<double, M, N> G0;
  first_derivatives<P, double>(prob, q0, gradV, G0);
  const Vec<double, N> pm = p0 - 0.5 * h * gradV;
  Vec<double, M> lambda = Vec<double, M>::Zero(m);
  auto q1_of = [&](const Vec<double, M>& l) {
    return Vec<double, N>(q0 + h * (pm - 0.5 * h * G0.transpose() * l));
  };
  auto fj = [&](const Vec<double, M>& l, Vec<double, M>& F, Mat<double, M>& J) {
    const Vec<double, N> q1 = q1_of(l);
    Vec<double, N> gv;
    Eigen::Matrix<double, M, N> G1;
    Vec<double, M> g;
    first_derivatives<P, double>(prob, q1, gv, G1, &g);
    F = g;
    J = -0.5 * h * h * G1 * G0.transpose();
  };
  // An update of λ moves q_1 by h²/2 G δλ: below 4u/h² it moves q_1 (of size about 1) by less
  // than the rounding of q_1 itself.
  // And a residual g(q_1) at the rounding of a quadratic constraint at q_1's size is as small
  // as it gets: the updates may then wander at round-off without settling.
  NewtonOptions opt;
  const double eps = std::numeric_limits<double>::epsilon();
  opt.step_abs = 4 * eps / std::max(h * h, 1e-300);
  const double size = std::max(1.0, q0.template lpNorm<Eigen::Infinity>());
  opt.residual_abs = 4 * eps * size * size;
  const SolveReport r = newton_solve<M>(lambda, fj, opt, "RATTLE's position constraint");
  if (!r.converged) throw SolveError("RATTLE's position constraint", r);
  const Vec<double, N> q1 = q1_of(lambda);
  Vec<double, N> gv1;
  Eigen::Matrix<double, M, N> G1;
  first_derivatives<P, double>(prob, q1, gv1, G1);
  Vec<double, N> p1 = pm - 0.5 * h * G0.transpose() * lambda - 0.5 * h * gv1;
  if (project) p1 = project_momentum<P>(G1, p1);
  if (!q1.allFinite() || !p1.allFinite()) throw SolveError("RATTLE step: non-finite state", r);
  z.head<N>() = q1;
  z.segment<N>(N) = p1;
}

// --- The constrained discrete Euler–Lagrange equations (Marsden & West 2001, §3.5) -----------
// In position–momentum form, with multipliers λ (the constraint force over the step) and μ (the
// projection of the momentum onto the hidden constraint, which makes the map one of T*Q; HLW
// §VII.5.3 writes RATTLE so, from the trapezoidal L_d):
//   p_0 + D1 L_d(q_0, q_1, h) + G(q_0)ᵀ λ = 0,   g(q_1) = 0,
//   p_1 = D2 L_d(q_0, q_1, h) − G(q_1)ᵀ μ,       G(q_1) p_1 = 0.
// (q_1, hλ) by Newton's method on the first two, the first times h (Jacobian
// [h D1D2 L_d, G(q_0)ᵀ; G(q_1), 0]), μ by
// one linear solve. The hidden constraint in this form is that of H = |p|²/2 + V (v = p). `ld`
// gives L_d's derivatives as CompiledDiscreteLagrangian<N> does: newton_parts(q0, q1, h, D1,
// D12) and d2(q0, q1, h).
template <class P, class Ld>
void constrained_del_step(const P& prob, const Ld& ld, Eigen::VectorXd& z, double h) {
  constexpr int N = P::N;
  const int m = prob.m();
  const Vec<double, N> q0 = z.head<N>(), p0 = z.segment<N>(N);
  Vec<double, N> gv0;
  Eigen::Matrix<double, P::M, N> G0;
  first_derivatives<P, double>(prob, q0, gv0, G0);
  Eigen::VectorXd x(N + m);
  x.head<N>() = q0 + h * p0;  // the free flight's guess (v = p)
  x.tail(m).setZero();
  auto fj = [&](const Eigen::VectorXd& y, Eigen::VectorXd& F, Eigen::MatrixXd& J) {
    const Vec<double, N> q1 = y.head<N>();
    Vec<double, N> d1;
    Mat<double, N> d12;
    ld.newton_parts(q0, q1, h, d1, d12);
    Vec<double, N> gv1;
    Eigen::Matrix<double, P::M, N> G1;
    Vec<double, P::M> c;
    first_derivatives<P, double>(prob, q1, gv1, G1, &c);
    F.head<N>() = h * (p0 + d1) + G0.transpose() * y.tail(m);
    F.tail(m) = c;
    J.setZero();
    J.topLeftCorner<N, N>() = h * d12;
    J.topRightCorner(N, m) = G0.transpose();
    J.bottomLeftCorner(m, N) = G1;
  };
  // Solved in position units, as RATTLE's λ: the first equation times h, the multiplier ν = hλ.
  // A residual at the rounding of the positions (and of a quadratic constraint at their size)
  // is as small as it gets; the updates of ν may then wander at round-off without settling.
  NewtonOptions opt;
  const double size = std::max(1.0, q0.template lpNorm<Eigen::Infinity>());
  opt.residual_abs = 4 * std::numeric_limits<double>::epsilon() * size * size;
  const SolveReport r =
      newton_solve<Eigen::Dynamic>(x, fj, opt, "the constrained discrete Euler-Lagrange equations");
  if (!r.converged) throw SolveError("the constrained discrete Euler-Lagrange equations", r);
  const Vec<double, N> q1 = x.head<N>();
  Vec<double, N> gv1;
  Eigen::Matrix<double, P::M, N> G1;
  first_derivatives<P, double>(prob, q1, gv1, G1);
  const Vec<double, N> p1 = project_momentum<P>(G1, ld.d2(q0, q1, h));
  if (!q1.allFinite() || !p1.allFinite())
    throw SolveError("the constrained discrete Euler-Lagrange step: non-finite state", r);
  z.head<N>() = q1;
  z.segment<N>(N) = p1;
}

// The index-1 equations in T (double-double for the reference): q' = p,
// p' = −∇V − Gᵀλ with G Gᵀ λ = curvature − G ∇V (the hidden constraint differentiated once
// more), on y = (q, p).
template <class P, class T>
std::vector<T> index1_field(const P& prob, const std::vector<T>& y) {
  constexpr int N = P::N, M = P::M;
  const int m = prob.m();
  Vec<T, N> q, p;
  for (int i = 0; i < N; ++i) {
    q(i) = y[static_cast<std::size_t>(i)];
    p(i) = y[static_cast<std::size_t>(N + i)];
  }
  Vec<T, N> gradV;
  Eigen::Matrix<T, M, N> G;
  first_derivatives<P, T>(prob, q, gradV, G);
  const Vec<T, M> c = curvature<P, T>(prob, q, p);
  const Vec<T, M> Ggv = G * gradV;
  Vec<T, M> rhs(m);
  for (int i = 0; i < m; ++i) rhs(i) = c(i) - Ggv(i);
  const Mat<T, M> A = G * G.transpose();
  const Vec<T, M> lambda = A.partialPivLu().solve(rhs);
  const Vec<T, N> force = G.transpose() * lambda;
  std::vector<T> f(2 * N);
  for (int i = 0; i < N; ++i) {
    f[static_cast<std::size_t>(i)] = p(i);
    f[static_cast<std::size_t>(N + i)] = -gradV(i) - force(i);
  }
  return f;
}

/// The system part of a study on the constrained system `prob` (H = |p|²/2 + V on T*Q) from
/// (q0, p0): z0, the index-1 reference in double-double, the energy, the position and hidden
/// constraint residuals and the tangent space of T*Q. `where` ends the messages of a state off
/// the manifold ("of spherical-pendulum"). `prob` is copied into the study's functions.
template <class P>
void set_constrained_system(const P& prob, const std::string& where, const std::vector<double>& q0,
                            const std::vector<double>& p0, MapStudy& s) {
  constexpr int N = P::N, M = P::M;
  if (q0.size() != std::size_t(N) || p0.size() != std::size_t(N))
    throw std::invalid_argument("set_constrained_system: the state has the wrong size");
  Eigen::VectorXd z0(2 * N);
  for (int i = 0; i < N; ++i) {
    z0(i) = q0[static_cast<std::size_t>(i)];
    z0(N + i) = p0[static_cast<std::size_t>(i)];
  }
  auto residuals = [prob](const Eigen::VectorXd& z) {
    const Vec<double, N> q = z.head<N>(), p = z.segment<N>(N);
    Vec<double, N> gv;
    Eigen::Matrix<double, M, N> G;
    Vec<double, M> g;
    first_derivatives<P, double>(prob, q, gv, G, &g);
    return std::pair{g.template lpNorm<Eigen::Infinity>(),
                     Vec<double, M>(G * p).template lpNorm<Eigen::Infinity>()};
  };
  const auto [g0, hidden0] = residuals(z0);
  if (!(g0 <= 1e-10))
    throw ArgumentError("--q0", fmt::format("is not on the constraint manifold {}: |g(q0)| = "
                                            "{:.1e} (at most 1e-10)",
                                            where, g0));
  if (!(hidden0 <= 1e-10))
    throw ArgumentError("--p0", fmt::format("is not tangent to the constraint manifold {}: "
                                            "|G(q0) p0| = {:.1e} (at most 1e-10)",
                                            where, hidden0));
  s.z0 = z0;
  s.field = [prob](const std::vector<dd_real>& y) { return index1_field<P, dd_real>(prob, y); };
  s.equations =
      "the index-1 equations q' = p, p' = -grad V - G^T lambda (G G^T lambda from the hidden "
      "constraint differentiated once more)";
  s.H = [prob](const Eigen::VectorXd& z) {
    const Vec<double, N> q = z.head<N>(), p = z.segment<N>(N);
    return 0.5 * p.squaredNorm() + prob.energy_potential(q);
  };
  s.position_residual = [residuals](const Eigen::VectorXd& z) { return residuals(z).first; };
  s.hidden_residual = [residuals](const Eigen::VectorXd& z) { return residuals(z).second; };
  // The tangent space of T*Q ⊂ R^2N at z: the kernel of the constraints' Jacobian, rows
  // (G, 0) and (∂(G p)/∂q, G), an orthonormal basis by QR of the kernel the LU gives.
  s.tangent = [prob](const Eigen::VectorXd& z) {
    const int m = prob.m();
    const Vec<double, N> q = z.head<N>(), p = z.segment<N>(N);
    Vec<double, N> gv;
    Eigen::Matrix<double, M, N> G;
    first_derivatives<P, double>(prob, q, gv, G);
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(2 * m, 2 * N);
    C.topLeftCorner(m, N) = G;
    C.bottomRightCorner(m, N) = G;
    for (int i = 0; i < m; ++i)
      C.block(m + i, 0, 1, N) = (constraint_hessian<P, double>(prob, q, i) * p).transpose();
    const Eigen::MatrixXd K = Eigen::FullPivLU<Eigen::MatrixXd>(C).kernel();
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(K);
    return Eigen::MatrixXd(qr.householderQ() * Eigen::MatrixXd::Identity(2 * N, K.cols()));
  };
}

}  // namespace vibook::verify::constrained_detail
