/// \file typed_lagrangian_impl.hpp
/// \brief The templates behind set_typed_lagrangian (typed_lagrangian_study.cpp): the Legendre
/// map of a typed L(q, v) and the map study's reference, energy and initial state from it, for N
/// degrees of freedom. Included by typed_lagrangian_study.cpp (N = 1, 2) and
/// typed_lagrangian_3.cpp (N = 3), so that the dimensions compile in parallel (one unit took
/// about a minute on two busy cores).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <type_traits>

#include <fmt/format.h>

#include "vibook/core/errors.hpp"
#include "vibook/verify/typed_system.hpp"

namespace vibook::verify::typed_lagrangian_detail {

// The Legendre map of the typed L at (q, p) in T (double-double for the reference, double for
// the energy): v with ∂L/∂v(q, v) = p, and there L and ∂L/∂q. Newton's method from v = p on
// the Hessian ∂²L/∂v², all from one nested AutoDiff evaluation of L in (q, v) per iteration
// (one AutoDiff type per T: each type the tree is evaluated in is compiled anew); one
// correction when L is quadratic in v. It stops when the correction is below
// rel·max(1, |v|) (max norms; rel = 1e-30 in double-double, 1e-14 in double, where H's error
// is of second order in v's since ∂H/∂v = p − ∂L/∂v = 0), keeping the point it was computed
// at; nullopt when that does not happen in 60 iterations or a number leaves the finite ones
// (L not regular there).
template <int N, class T>
struct LegendrePoint {
  Vec<T, N> v, dLdq;
  T L;
};

template <int N, class T>
std::optional<LegendrePoint<N, T>> legendre(const verify::TypedDiscreteLagrangian& sys,
                                            const Vec<T, N>& q, const Vec<T, N>& p,
                                            const T& time = T(0.0)) {
  const double rel = std::is_same_v<T, double> ? 1e-14 : 1e-30;
  Vec<T, 2 * N> w;
  w << q, p;
  for (int it = 0; it < 60; ++it) {
    T value;
    Vec<T, 2 * N> g;
    Mat<T, 2 * N> H;
    lagrangian_derivatives<N, T>(sys, w, value, g, H, time);
    const Mat<T, N> M = H.template bottomRightCorner<N, N>();
    const Vec<T, N> dv = M.partialPivLu().solve(Vec<T, N>(g.template tail<N>() - p));
    double nd = 0, nv = 1;
    bool finite = std::isfinite(to_double(value));
    for (int i = 0; i < N; ++i) {
      const double d = to_double(dv(i)), x = to_double(w(N + i));
      finite = finite && std::isfinite(d) && std::isfinite(x);
      nd = std::max(nd, std::abs(d));
      nv = std::max(nv, std::abs(x));
    }
    if (!finite) return std::nullopt;
    if (nd <= rel * nv)
      return LegendrePoint<N, T>{w.template tail<N>(), g.template head<N>(), value};
    w.template tail<N>() -= dv;
  }
  return std::nullopt;
}

template <int N, class T>
LegendrePoint<N, T> legendre_or_throw(const verify::TypedDiscreteLagrangian& sys,
                                      const Vec<T, N>& q, const Vec<T, N>& p,
                                      const T& time = T(0.0)) {
  if (auto r = legendre<N, T>(sys, q, p, time)) return *r;
  std::vector<double> qd, pd;
  for (int i = 0; i < N; ++i) {
    qd.push_back(to_double(q(i)));
    pd.push_back(to_double(p(i)));
  }
  throw NumericalError(
      "the Legendre map dL/dv(q, v) = p has no solution near v = p at q = " + vec_text(qd) +
      ", p = " + vec_text(pd) + ": the Lagrangian is not regular there");
}

// A time-dependent L(q, v, t): the state carries the clock, z = (q, p, t) from t = 0, and the
// reference solves the Euler–Lagrange equations in (q, v, t), M a = ∂L/∂q − B v − ∂²L/∂v∂t,
// t' = 1, with the derivatives in the 2N + 1 variables (lagrangian_derivatives_timed).
// The reference's end state (q, v, ...) in r turned to (q, p, ...), p = ∂L/∂v(q, v, t).
template <int N>
void momenta_at_end(const verify::TypedDiscreteLagrangian& sys, verify::Reference<dd_real>& r,
                    const dd_real& t) {
  Vec<dd_real, 2 * N> w;
  for (int i = 0; i < 2 * N; ++i) w(i) = r.y[static_cast<std::size_t>(i)];
  dd_real value;
  Vec<dd_real, 2 * N> g;
  Mat<dd_real, 2 * N> H;
  lagrangian_derivatives<N, dd_real>(sys, w, value, g, H, t);
  for (int i = 0; i < N; ++i) r.y[static_cast<std::size_t>(N + i)] = g(N + i);
}

template <int N>
void set_timed_lagrangian_system(MapStudy& s, const verify::TypedDiscreteLagrangian& sys) {
  s.timed = true;
  s.z0.conservativeResize(2 * N + 1);
  s.z0(2 * N) = 0;
  s.reference = [&sys](const std::vector<dd_real>& z0d, double t, bool action) {
    Vec<dd_real, N> qq, pp;
    for (int i = 0; i < N; ++i) {
      qq(i) = z0d[static_cast<std::size_t>(i)];
      pp(i) = z0d[static_cast<std::size_t>(N + i)];
    }
    const dd_real t0 = z0d[2 * N];
    const verify::Field<dd_real> f = [&](const std::vector<dd_real>& y) {
      Vec<dd_real, 2 * N + 1> w;
      for (int i = 0; i < 2 * N + 1; ++i) w(i) = y[static_cast<std::size_t>(i)];
      dd_real value;
      Vec<dd_real, 2 * N + 1> g;
      Mat<dd_real, 2 * N + 1> H;
      lagrangian_derivatives_timed<N, dd_real>(sys, w, value, g, H);
      const Mat<dd_real, N> M = H.template block<N, N>(N, N);
      const Mat<dd_real, N> B = H.template block<N, N>(N, 0);
      const Vec<dd_real, N> v = w.template segment<N>(N), vt = H.template block<N, 1>(N, 2 * N);
      const Vec<dd_real, N> bv = B * v;
      Vec<dd_real, N> rhs;
      for (int i = 0; i < N; ++i) rhs(i) = g(i) - bv(i) - vt(i);
      const Vec<dd_real, N> acc = M.partialPivLu().solve(rhs);
      std::vector<dd_real> r(y.size());
      for (int i = 0; i < N; ++i) {
        r[static_cast<std::size_t>(i)] = w(N + i);
        r[static_cast<std::size_t>(N + i)] = acc(i);
      }
      r[2 * N] = dd_real(1.0);
      if (action) r.back() = value;
      return r;
    };
    const LegendrePoint<N, dd_real> start = legendre_or_throw<N, dd_real>(sys, qq, pp, t0);
    std::vector<dd_real> y0(2 * N + 1);
    for (int i = 0; i < N; ++i) {
      y0[static_cast<std::size_t>(i)] = qq(i);
      y0[static_cast<std::size_t>(N + i)] = start.v(i);
    }
    y0[2 * N] = t0;
    if (action) y0.emplace_back(0.0);
    verify::Reference<dd_real> r = verify::reference_solution<dd_real>(f, y0, t);
    momenta_at_end<N>(sys, r, r.y[2 * N]);
    return r;
  };
  s.equations =
      "the Euler-Lagrange equations of L(q, v, t) in (q, v, t) (v from dL/dv = p by Newton at "
      "the start, p = dL/dv at the end)";
  s.H = [&sys](const Eigen::VectorXd& z) {
    const Vec<double, N> qq = z.head<N>(), pp = z.segment<N>(N);
    const LegendrePoint<N, double> r = legendre_or_throw<N, double>(sys, qq, pp, z(2 * N));
    return pp.dot(r.v) - r.L;
  };
}

template <int N>
void set_lagrangian_system(MapStudy& s, const verify::TypedDiscreteLagrangian& sys,
                           const std::vector<double>& q0, const std::vector<double>& p0) {
  Eigen::VectorXd z0(2 * N);
  Vec<double, N> q, p;
  for (int i = 0; i < N; ++i) {
    z0(i) = q0[static_cast<std::size_t>(i)];
    z0(N + i) = p0[static_cast<std::size_t>(i)];
    q(i) = z0(i);
    p(i) = z0(N + i);
  }
  if (!legendre<N, double>(sys, q, p))
    throw ArgumentError("--lagrangian",
                        "is not regular at the initial state: dL/dv(q0, v) = p0 has no solution "
                        "near v = p0 (q0 = " +
                            vec_text(q0) + ", p0 = " + vec_text(p0) + ")");
  s.z0 = z0;
  if (sys.time_dependent()) return set_timed_lagrangian_system<N>(s, sys);
  // The reference (MapStudy::reference; `field` is not used): the Euler–Lagrange equations in
  // (q, v), M a = ∂L/∂q − B v with the Hessian blocks M = ∂²L/∂v², B = ∂²L/∂v∂q (nested
  // AutoDiff in double-double), from v of the Legendre map at z0; p = ∂L/∂v formed at the end;
  // L itself as one more component for the action. No Newton iteration inside the field.
  s.reference = [&sys](const std::vector<dd_real>& z0d, double t, bool action) {
    Vec<dd_real, N> qq, pp;
    for (int i = 0; i < N; ++i) {
      qq(i) = z0d[static_cast<std::size_t>(i)];
      pp(i) = z0d[static_cast<std::size_t>(N + i)];
    }
    const verify::Field<dd_real> f = [&](const std::vector<dd_real>& y) {
      Vec<dd_real, 2 * N> w;
      for (int i = 0; i < 2 * N; ++i) w(i) = y[static_cast<std::size_t>(i)];
      dd_real value;
      Vec<dd_real, 2 * N> g;
      Mat<dd_real, 2 * N> H;
      lagrangian_derivatives<N, dd_real>(sys, w, value, g, H);
      const Vec<dd_real, N> acc =
          euler_lagrange_acceleration<N, dd_real>(g, H, Vec<dd_real, N>(w.template tail<N>()));
      std::vector<dd_real> r(y.size());
      for (int i = 0; i < N; ++i) {
        r[static_cast<std::size_t>(i)] = w(N + i);
        r[static_cast<std::size_t>(N + i)] = acc(i);
      }
      if (action) r.back() = value;
      return r;
    };
    const LegendrePoint<N, dd_real> start = legendre_or_throw<N, dd_real>(sys, qq, pp);
    std::vector<dd_real> y0(2 * N);
    for (int i = 0; i < N; ++i) {
      y0[static_cast<std::size_t>(i)] = qq(i);
      y0[static_cast<std::size_t>(N + i)] = start.v(i);
    }
    if (action) y0.emplace_back(0.0);
    verify::Reference<dd_real> r = verify::reference_solution<dd_real>(f, y0, t);
    momenta_at_end<N>(sys, r, dd_real(0.0));  // p = ∂L/∂v
    return r;
  };
  s.equations =
      "the Euler-Lagrange equations of L in (q, v) (v from dL/dv = p by Newton at "
      "the start, p = dL/dv at the end)";
  // H = p·v − L in double
  s.H = [&sys](const Eigen::VectorXd& z) {
    const Vec<double, N> qq = z.head<N>(), pp = z.tail<N>();
    const LegendrePoint<N, double> r = legendre_or_throw<N, double>(sys, qq, pp);
    return pp.dot(r.v) - r.L;
  };
}

}  // namespace vibook::verify::typed_lagrangian_detail
