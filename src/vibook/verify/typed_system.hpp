/// \file typed_system.hpp
/// \brief The intended system of a typed expression (`--lagrangian`, `--hamiltonian`,
/// `--potential`) as every typed route of `vibook verify` uses it: L's derivatives by nested
/// AutoDiff, the Euler–Lagrange acceleration, Hamilton's equations in double-double, the
/// system part of a map study. Internal: not installed.
#pragma once

#include <string>
#include <type_traits>
#include <vector>

#include <Eigen/Dense>

#include "vibook/core/precision.hpp"
#include "vibook/verify/expression.hpp"
#include "vibook/verify/map_study.hpp"
#include "vibook/verify/reference.hpp"

namespace vibook::verify {

/// f(std::integral_constant<int, N>{}) for N = n, 1 ≤ n ≤ kMaxDim (a larger n: kMaxDim): the
/// one dispatch from a run-time dimension to the code compiled for it.
template <class F>
decltype(auto) with_dim(int n, F&& f) {
  static_assert(kMaxDim == 6, "with_dim lists the dimensions 1..kMaxDim");
  switch (n) {
    case 1:
      return f(std::integral_constant<int, 1>{});
    case 2:
      return f(std::integral_constant<int, 2>{});
    case 3:
      return f(std::integral_constant<int, 3>{});
    case 4:
      return f(std::integral_constant<int, 4>{});
    case 5:
      return f(std::integral_constant<int, 5>{});
    default:
      return f(std::integral_constant<int, 6>{});
  }
}

/// The typed Lagrangian of `sys` (`--lagrangian`, in q and v) at w = (q, v): its value, gradient
/// and Hessian in the 2N variables, by nested forward AutoDiff in T on the expression tree.
/// A time-dependent L is evaluated at the time t (a constant here).
template <int N, class T>
void lagrangian_derivatives(const TypedDiscreteLagrangian& sys, const Vec<T, 2 * N>& w, T& value,
                            Vec<T, 2 * N>& g, Mat<T, 2 * N>& H, const T& t = T(0.0)) {
  value_gradient_hessian<2 * N, T>(
      [&](const auto& x) {
        using S = scalar_t<decltype(x)>;
        const Vec<S, N> qs = x.template head<N>(), vs = x.template tail<N>();
        return sys.lagrangian<N, S>(qs, vs, constant_of<S>(t));
      },
      w, value, g, H);
}

/// The same in the 2N + 1 variables (q, v, t) of a time-dependent L: its Euler–Lagrange
/// equations need ∂²L/∂v∂t besides.
template <int N, class T>
void lagrangian_derivatives_timed(const TypedDiscreteLagrangian& sys, const Vec<T, 2 * N + 1>& w,
                                  T& value, Vec<T, 2 * N + 1>& g, Mat<T, 2 * N + 1>& H) {
  value_gradient_hessian<2 * N + 1, T>(
      [&](const auto& x) {
        using S = scalar_t<decltype(x)>;
        const Vec<S, N> qs = x.template head<N>(), vs = x.template segment<N>(N);
        return sys.lagrangian<N, S>(qs, vs, x(2 * N));
      },
      w, value, g, H);
}

/// The acceleration the Euler–Lagrange equations give at (q, v), from L's gradient g and Hessian
/// H there (lagrangian_derivatives): M a = ∂L/∂q − B v, with M = ∂²L/∂v² and B = ∂²L/∂v∂q.
template <int N, class T>
Vec<T, N> euler_lagrange_acceleration(const Vec<T, 2 * N>& g, const Mat<T, 2 * N>& H,
                                      const Vec<T, N>& v) {
  const Mat<T, N> M = H.template bottomRightCorner<N, N>();
  const Mat<T, N> B = H.template bottomLeftCorner<N, N>();
  const Vec<T, N> rhs = g.template head<N>() - B * v;
  return M.partialPivLu().solve(rhs);
}

/// Hamilton's equations of the Hamiltonian of `sys` in double-double, (q, p) stacked: the field
/// every reference of a typed system solves. `sys` must outlive it. N = 1..kMaxDim,
/// instantiated once (typed_system.cpp).
template <int N>
Field<dd_real> typed_hamilton_field(const TypedDiscreteLagrangian& sys);

/// The system part of a study from a typed system with a Hamiltonian (`vibook verify
/// --hamiltonian`, or p^2/2 + V(q) from --potential): z0, the reference's field (Hamilton's
/// equations in double-double) and the energy. `sys` must outlive the study. N = 1..kMaxDim,
/// instantiated once (typed_system.cpp).
template <int N>
void set_typed_system(MapStudy& s, const TypedDiscreteLagrangian& sys, const Eigen::VectorXd& z0);

// X(1) … X(kMaxDim): explicit instantiations (here extern, in typed_system.cpp the definitions)
// for every dimension, from one list.
#define VIBOOK_FOR_EACH_DIM(X) X(1) X(2) X(3) X(4) X(5) X(6)
static_assert(kMaxDim == 6, "VIBOOK_FOR_EACH_DIM lists the dimensions 1..kMaxDim");
#define VIBOOK_TYPED_SYSTEM(N)                                                            \
  extern template Field<dd_real> typed_hamilton_field<N>(const TypedDiscreteLagrangian&); \
  extern template void set_typed_system<N>(MapStudy&, const TypedDiscreteLagrangian&,     \
                                           const Eigen::VectorXd&);
VIBOOK_FOR_EACH_DIM(VIBOOK_TYPED_SYSTEM)
#undef VIBOOK_TYPED_SYSTEM

/// set_typed_system<N> at z0 = (q0, p0), for the dimension of `sys` (1..kMaxDim).
void set_typed_system(MapStudy& s, const TypedDiscreteLagrangian& sys,
                      const std::vector<double>& q0, const std::vector<double>& p0);

/// The study's system from a typed Hamiltonian (Hamilton's equations of H in double-double,
/// the energy H, z0); returns the report's line naming it. `sys` must outlive the study.
std::string set_typed_hamiltonian(MapStudy& s, const TypedDiscreteLagrangian& sys,
                                  const std::string& hamiltonian, const std::vector<double>& q0,
                                  const std::vector<double>& p0);

/// The study's system from a typed Lagrangian: the reference (MapStudy::reference) solves its
/// Euler–Lagrange equations in (q, v) in double-double, v from ∂L/∂v(q0, v) = p0 by Newton's
/// method at the start and p = ∂L/∂v at the end; the energy is its Legendre transform
/// H(q, p) = p·v − L(q, v) in double, v by Newton's method at each evaluation. Returns the
/// report's line naming the system. An ArgumentError naming --lagrangian when the Legendre map
/// has no solution at (q0, p0) (L not regular there), before any work; later failures are
/// NumericalErrors. `sys` must outlive the study.
std::string set_typed_lagrangian(MapStudy& s, const TypedDiscreteLagrangian& sys,
                                 const std::string& lagrangian, const std::vector<double>& q0,
                                 const std::vector<double>& p0);

/// The study's system from a typed potential (Hamilton's equations of |p|²/2 + V, the energy,
/// z0); returns the report's line naming it. `sys` must outlive the study.
std::string set_typed_potential(MapStudy& s, const TypedDiscreteLagrangian& sys,
                                const std::string& potential, const std::vector<double>& q0,
                                const std::vector<double>& p0);

/// The largest eigenvalue of the symmetric matrix H (the stability hint's ω² from V's Hessian):
/// one instance for every dimension, compiled once.
double largest_symmetric_eigenvalue(const Eigen::MatrixXd& H);

}  // namespace vibook::verify
