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
#include "vibook/verify/reference.hpp"

namespace vibook::verify {

namespace {

// --- the problems: V(q) and g(q) templated on the scalar (double, double-double, AutoDiff) ----

// The spherical pendulum: a unit mass on a rod of unit length, gravity along −q₃.
struct SphericalPendulum {
  static constexpr int N = 3, M = 1;
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
  static constexpr int N = 4, M = 2;
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

// ∇V and G = ∂g/∂q at q, by one forward AutoDiff pass in T.
template <class P, class T>
void first_derivatives(const P& prob, const Vec<T, P::N>& q, Vec<T, P::N>& gradV,
                       Eigen::Matrix<T, P::M, P::N>& G, Vec<T, P::M>* g = nullptr) {
  constexpr int N = P::N, M = P::M;
  using D = ad::Dual<N, T>;
  Vec<D, N> x;
  for (int i = 0; i < N; ++i) x(i) = D(q(i), N, i);
  gradV = prob.template potential<D>(x).derivatives();
  const Vec<D, M> c = prob.template constraint<D>(x);
  for (int i = 0; i < M; ++i) {
    G.row(i) = c(i).derivatives().transpose();
    if (g) (*g)(i) = c(i).value();
  }
}

// ∇²g_i(q), the Hessian of constraint i, by nested AutoDiff in T.
template <class P, class T>
Mat<T, P::N> constraint_hessian(const P& prob, const Vec<T, P::N>& q, int i) {
  constexpr int N = P::N;
  T value;
  Vec<T, N> grad;
  Mat<T, N> H;
  value_gradient_hessian<N, T>(
      [&](const auto& x) {
        using S = scalar_t<decltype(x)>;
        return S(prob.template constraint<S>(Vec<S, N>(x))(i));
      },
      q, value, grad, H);
  return H;
}

// pᵀ ∇²g_i(q) p for each constraint i (the hidden constraint's time derivative's curvature term).
template <class P, class T>
Vec<T, P::M> curvature(const P& prob, const Vec<T, P::N>& q, const Vec<T, P::N>& p) {
  constexpr int N = P::N, M = P::M;
  Vec<T, M> r;
  for (int i = 0; i < M; ++i) {
    const Vec<T, N> Hp = constraint_hessian<P, T>(prob, q, i) * p;
    T s = p(0) * Hp(0);
    for (int k = 1; k < N; ++k) s = s + p(k) * Hp(k);
    r(i) = s;
  }
  return r;
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
  const Vec<double, N> q0 = z.head<N>(), p0 = z.tail<N>();
  Vec<double, N> gradV;
  Eigen::Matrix<double, M, N> G0;
  first_derivatives<P, double>(prob, q0, gradV, G0);
  const Vec<double, N> pm = p0 - 0.5 * h * gradV;
  Vec<double, M> lambda = Vec<double, M>::Zero();
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
  if (project) {
    const Mat<double, M> A = G1 * G1.transpose();
    const Vec<double, M> mu = A.partialPivLu().solve(Vec<double, M>(G1 * p1));
    p1 -= G1.transpose() * mu;
  }
  if (!q1.allFinite() || !p1.allFinite()) throw SolveError("RATTLE step: non-finite state", r);
  z.head<N>() = q1;
  z.tail<N>() = p1;
}

// The index-1 equations in T (double-double for the reference): q' = p,
// p' = −∇V − Gᵀλ with G Gᵀ λ = curvature − G ∇V (the hidden constraint differentiated once
// more), on y = (q, p).
template <class P, class T>
std::vector<T> index1_field(const P& prob, const std::vector<T>& y) {
  constexpr int N = P::N, M = P::M;
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
  Vec<T, M> rhs;
  for (int i = 0; i < M; ++i) rhs(i) = c(i) - Ggv(i);
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

template <class P>
void measure_problem(const P& prob, const ConstrainedProblem& problem, bool project,
                     const std::vector<double>& q0, const std::vector<double>& p0, MapStudy s,
                     MapMeasurement& rep) {
  constexpr int N = P::N, M = P::M;
  if (q0.size() != std::size_t(N) || p0.size() != std::size_t(N))
    throw std::invalid_argument("measure_constrained: the state has the wrong size");
  Eigen::VectorXd z0(2 * N);
  for (int i = 0; i < N; ++i) {
    z0(i) = q0[static_cast<std::size_t>(i)];
    z0(N + i) = p0[static_cast<std::size_t>(i)];
  }
  auto residuals = [prob](const Eigen::VectorXd& z) {
    const Vec<double, N> q = z.head<N>(), p = z.tail<N>();
    Vec<double, N> gv;
    Eigen::Matrix<double, M, N> G;
    Vec<double, M> g;
    first_derivatives<P, double>(prob, q, gv, G, &g);
    return std::pair{g.template lpNorm<Eigen::Infinity>(),
                     Vec<double, M>(G * p).template lpNorm<Eigen::Infinity>()};
  };
  const auto [g0, hidden0] = residuals(z0);
  if (g0 > 1e-10)
    throw ArgumentError("--q0", fmt::format("is not on the constraint manifold of {}: |g(q0)| = "
                                            "{:.1e} (at most 1e-10)",
                                            problem.name, g0));
  if (hidden0 > 1e-10)
    throw ArgumentError("--p0", fmt::format("is not tangent to the constraint manifold of {}: "
                                            "|G(q0) p0| = {:.1e} (at most 1e-10)",
                                            problem.name, hidden0));
  s.z0 = z0;
  s.step = naming_failures(
      [prob, project](Eigen::VectorXd& z, double h) { rattle_step(prob, project, z, h); }, N);
  s.field = [prob](const std::vector<dd_real>& y) { return index1_field<P, dd_real>(prob, y); };
  s.equations =
      "the index-1 equations q' = p, p' = -grad V - G^T lambda (G G^T lambda from the hidden "
      "constraint differentiated once more)";
  s.H = [prob](const Eigen::VectorXd& z) {
    const Vec<double, N> q = z.head<N>(), p = z.tail<N>();
    return 0.5 * p.squaredNorm() + prob.template potential<double>(q);
  };
  s.position_residual = [residuals](const Eigen::VectorXd& z) { return residuals(z).first; };
  s.hidden_residual = [residuals](const Eigen::VectorXd& z) { return residuals(z).second; };
  // The tangent space of T*Q ⊂ R^2N at z: the kernel of the constraints' Jacobian, rows
  // (G, 0) and (∂(G p)/∂q, G), an orthonormal basis by QR of the kernel the LU gives.
  s.tangent = [prob](const Eigen::VectorXd& z) {
    const Vec<double, N> q = z.head<N>(), p = z.tail<N>();
    Vec<double, N> gv;
    Eigen::Matrix<double, M, N> G;
    first_derivatives<P, double>(prob, q, gv, G);
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(2 * M, 2 * N);
    C.topLeftCorner(M, N) = G;
    C.bottomRightCorner(M, N) = G;
    for (int i = 0; i < M; ++i)
      C.block(M + i, 0, 1, N) = (constraint_hessian<P, double>(prob, q, i) * p).transpose();
    const Eigen::MatrixXd K = Eigen::FullPivLU<Eigen::MatrixXd>(C).kernel();
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(K);
    return Eigen::MatrixXd(qr.householderQ() * Eigen::MatrixXd::Identity(2 * N, K.cols()));
  };
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
