/// \file helmholtz.hpp
/// \brief The inverse problem of the calculus of variations for second-order systems
///   d/dt (M(x, ẋ) ẋ) = f(t, x, ẋ),   M symmetric,
/// Shen & Sun 2025, Theorems 2–4, (2.2a)–(2.2c): the system is the Euler–Lagrange equation of
/// some Lagrangian iff the three families of identities hold for all i, j. They are identities
/// in the curve x(t) (the Fréchet derivative of N(x) = d/dt(Mẋ) − f is compared with its
/// adjoint for arbitrary x), so d/dt is the total derivative ∂_t + ẋ·∂_x + ẍ·∂_ẋ with ẍ free.
///
/// helmholtz_check evaluates the three residuals at random points (t, x, ẋ, ẍ), every first
/// and second derivative of M and f from one nested-AutoDiff evaluation, and calls the system
/// variational when every residual is at round-off relative to the size of its terms.
///
/// Chapter: \ref chapter-kepler-lrl.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>

#include "vibook/core/autodiff.hpp"
#include "vibook/core/errors.hpp"
#include "vibook/core/types.hpp"

namespace vibook {

/// Outcome of helmholtz_check: the largest relative residual of each condition over the
/// sampled points, and the verdict.
struct HelmholtzReport {
  double residual_a = 0;  ///< (2.2a), relative
  double residual_b = 0;  ///< (2.2b), relative
  double residual_c = 0;  ///< (2.2c), relative
  int samples = 0;
  double tolerance = 0;  ///< the relative tolerance used for the verdict
  bool variational = false;
};

struct HelmholtzOptions {
  int samples = 200;
  double box = 1.0;  ///< t, x, ẋ, ẍ drawn uniformly from [−box, box] (x shifted, below)
  Vec<double, 3> x_shift = Vec<double, 3>::Zero();  ///< added to x (first min(n, 3) components)
  double tolerance = 1e3 * std::numeric_limits<double>::epsilon();
  std::uint64_t seed = 20250202;
};

namespace helmholtz_detail {

/// Value, gradient and Hessian of every scalar output of g(z) (z ∈ R^D), from one nested
/// AutoDiff evaluation. g returns an Eigen matrix or vector of the scalar it is given.
template <int D>
struct Jet {
  double value = 0;
  Vec<double, D> grad;
  Mat<double, D> hess;
};

template <int D, class G>
auto jets(G&& g, const Vec<double, D>& z) {
  using In = ad::Dual<D>;
  using Out = ad::Dual2<D>;
  Vec<Out, D> Z;
  for (int i = 0; i < D; ++i) {
    Z(i) = Out(In(z(i), D, i));
    Z(i).derivatives().setZero();
    Z(i).derivatives()(i) = In(1.0);
    for (int j = 0; j < D; ++j) Z(i).derivatives()(j).derivatives().setZero();
  }
  const auto r = g(Z);
  using R = std::remove_cvref_t<decltype(r)>;
  static_assert(std::is_same_v<typename R::Scalar, Out>,
                "helmholtz_check: M and f must return matrices of their scalar type");
  std::array<Jet<D>, R::RowsAtCompileTime * R::ColsAtCompileTime> out;
  for (int c = 0; c < r.cols(); ++c) {
    for (int rr = 0; rr < r.rows(); ++rr) {
      Jet<D>& J = out[std::size_t(c * r.rows() + rr)];
      const Out& s = r(rr, c);
      J.value = s.value().value();
      J.grad = s.value().derivatives();
      for (int j = 0; j < D; ++j) J.hess.col(j) = s.derivatives()(j).derivatives();
    }
  }
  return out;
}

}  // namespace helmholtz_detail

/// Check the Helmholtz conditions (2.2a)–(2.2c) of Shen & Sun for
///   d/dt (M(x, v) v) = f(t, x, v),   x, v ∈ R^n,
/// with `M(x, v)` returning a symmetric n×n Eigen matrix and `f(t, x, v)` an n-vector, both
/// generic in their scalar (generic lambdas; return `Mat<S, n>` / `Vec<S, n>` with S the
/// scalar of x, and write literals as `constant<S>(…)`).
template <int n, class MFun, class FFun>
HelmholtzReport helmholtz_check(MFun&& M, FFun&& f, const HelmholtzOptions& opt = {}) {
  constexpr int D = 1 + 2 * n;  // z = (t, x, v)
  auto X = [](int j) { return 1 + j; };
  auto V = [](int j) { return 1 + n + j; };
  std::mt19937_64 rng(opt.seed);
  std::uniform_real_distribution<double> U(-opt.box, opt.box);
  HelmholtzReport rep;
  rep.tolerance = opt.tolerance;
  rep.samples = opt.samples;
  for (int s = 0; s < opt.samples; ++s) {
    Vec<double, D> z;
    for (int i = 0; i < D; ++i) z(i) = U(rng);
    for (int j = 0; j < std::min(n, 3); ++j) z(X(j)) += opt.x_shift(j);
    Vec<double, n> a;  // ẍ, free
    for (int i = 0; i < n; ++i) a(i) = U(rng);
    Vec<double, D> zdot;  // (1, ẋ, ẍ)
    zdot << 1.0, z.template tail<n>(), a;
    const auto Mj = helmholtz_detail::jets<D>(
        [&](const auto& Z) {
          using S = scalar_t<decltype(Z)>;
          const Vec<S, n> x = Z.template segment<n>(1), v = Z.template tail<n>();
          return Mat<S, n>(M(x, v));
        },
        z);
    const auto fj = helmholtz_detail::jets<D>(
        [&](const auto& Z) {
          using S = scalar_t<decltype(Z)>;
          const Vec<S, n> x = Z.template segment<n>(1), v = Z.template tail<n>();
          return Vec<S, n>(f(Z(0), x, v));
        },
        z);
    auto m = [&](int i, int k) -> const helmholtz_detail::Jet<D>& {
      return Mj[std::size_t(k * n + i)];  // column-major
    };
    const Vec<double, n> v = z.template tail<n>();
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        // (2.2a)
        double lhs = 0, rhs = 0, scale_a = 0;
        for (int k = 0; k < n; ++k) {
          lhs += m(i, k).grad(V(j)) * v(k);
          rhs += m(j, k).grad(V(i)) * v(k);
          scale_a += std::abs(m(i, k).grad(V(j)) * v(k)) + std::abs(m(j, k).grad(V(i)) * v(k));
        }
        rep.residual_a = std::max(rep.residual_a, std::abs(lhs - rhs) / std::max(scale_a, 1e-300));
        // (2.2b)
        double b = 0, scale_b = 0;
        for (int k = 0; k < n; ++k) {
          const double t = (m(i, k).grad(X(j)) + m(j, k).grad(X(i))) * v(k);
          b += t;
          scale_b += std::abs(t);
        }
        b -= fj[std::size_t(i)].grad(V(j)) + fj[std::size_t(j)].grad(V(i));
        scale_b +=
            std::abs(fj[std::size_t(i)].grad(V(j))) + std::abs(fj[std::size_t(j)].grad(V(i)));
        rep.residual_b = std::max(rep.residual_b, std::abs(b) / std::max(scale_b, 1e-300));
        // (2.2c): d/dt Σ_k ∂M_ik/∂x_j v_k − ∂f_i/∂x_j + ∂f_j/∂x_i − d/dt ∂f_j/∂v_i
        Vec<double, D> grad_G = Vec<double, D>::Zero();  // ∇_z Σ_k ∂M_ik/∂x_j v_k
        for (int k = 0; k < n; ++k) {
          grad_G += m(i, k).hess.col(X(j)) * v(k);
          grad_G(V(k)) += m(i, k).grad(X(j));
        }
        const double dG = grad_G.dot(zdot);
        const double dF = fj[std::size_t(j)].hess.col(V(i)).dot(zdot);
        const double fx = fj[std::size_t(i)].grad(X(j)), fxT = fj[std::size_t(j)].grad(X(i));
        const double c = dG - fx + fxT - dF;
        const double scale_c = (grad_G.cwiseAbs().dot(zdot.cwiseAbs())) + std::abs(fx) +
                               std::abs(fxT) +
                               fj[std::size_t(j)].hess.col(V(i)).cwiseAbs().dot(zdot.cwiseAbs());
        rep.residual_c = std::max(rep.residual_c, std::abs(c) / std::max(scale_c, 1e-300));
      }
    }
  }
  rep.variational = rep.residual_a <= opt.tolerance && rep.residual_b <= opt.tolerance &&
                    rep.residual_c <= opt.tolerance;
  return rep;
}

}  // namespace vibook
