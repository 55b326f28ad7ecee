// The parts of LdKernelN (ld_kernel_impl.hpp) that a study runs once: the reference in
// double-double, the symbolic discrete Lagrangian, EpAVI and the classical steppers of the
// work-precision table. Included only by the generated ld_kernel_N.cpp, which instantiates them
// for one dimension beside the kernel's step.
#pragma once

#include "vibook/modified/series.hpp"
#include "vibook/verify/ld_kernel_impl.hpp"
#include "vibook/verify/reference.hpp"

namespace vibook::verify {

// The continuous equations in double-double: Hamilton's of H, or the Euler–Lagrange
// equations of L in (q, v) with v from dL/dv(q0, v) = p0 and p = dL/dv at the end.
template <int N>
LdReference LdKernelN<N>::reference(const LdSettings& s) const {
  using T = dd_real;
  LdReference out;
  Field<T> f;
  std::vector<T> y0(2 * N);
  auto starts = [&] {
    if (!s.adaptive_epavi) return;
    for (int j = 0; j < 2; ++j) {
      const auto r = reference_solution<T>(f, y0, j == 0 ? s.h : s.h / 2);
      out.q_start[static_cast<std::size_t>(j)].resize(N);
      for (int i = 0; i < N; ++i)
        out.q_start[static_cast<std::size_t>(j)](i) = to_double(r.y[static_cast<std::size_t>(i)]);
    }
  };
  if (dl_.has_hamiltonian()) {
    f = typed_hamilton_field<N>(dl_);
    for (int i = 0; i < N; ++i) {
      y0[static_cast<std::size_t>(i)] = T(s.q0[static_cast<std::size_t>(i)]);
      y0[static_cast<std::size_t>(N + i)] = T(s.p0[static_cast<std::size_t>(i)]);
    }
    const auto r = reference_solution<T>(f, y0, s.t_end);
    out.z.resize(2 * N);
    for (int i = 0; i < 2 * N; ++i) out.z(i) = to_double(r.y[static_cast<std::size_t>(i)]);
    out.error = r.error;
    out.macro_steps = r.macro_steps;
    out.evaluations = r.evaluations;
    starts();
    return out;
  }
  auto derivatives = [&](const Vec<T, N>& q, const Vec<T, N>& v, Vec<T, 2 * N>& g,
                         Mat<T, 2 * N>& H) {
    Vec<T, 2 * N> w;
    w << q, v;
    T value;
    lagrangian_derivatives<N, T>(dl_, w, value, g, H);
  };
  f = [&](const std::vector<T>& y) {
    Vec<T, N> q, v;
    for (int i = 0; i < N; ++i) {
      q(i) = y[static_cast<std::size_t>(i)];
      v(i) = y[static_cast<std::size_t>(N + i)];
    }
    Vec<T, 2 * N> g;
    Mat<T, 2 * N> H;
    derivatives(q, v, g, H);
    const Vec<T, N> a = euler_lagrange_acceleration<N, T>(g, H, v);
    std::vector<T> r(2 * N);
    for (int i = 0; i < N; ++i) {
      r[static_cast<std::size_t>(i)] = v(i);
      r[static_cast<std::size_t>(N + i)] = a(i);
    }
    return r;
  };
  // the initial velocity: dL/dv(q0, v) = p0, by Newton from v = p0
  Vec<T, N> q, v;
  for (int i = 0; i < N; ++i) {
    q(i) = T(s.q0[static_cast<std::size_t>(i)]);
    v(i) = T(s.p0[static_cast<std::size_t>(i)]);
  }
  bool done = false;
  for (int it = 0; it < 60 && !done; ++it) {
    Vec<T, 2 * N> g;
    Mat<T, 2 * N> H;
    derivatives(q, v, g, H);
    Vec<T, N> F;
    for (int i = 0; i < N; ++i) F(i) = g(N + i) - T(s.p0[static_cast<std::size_t>(i)]);
    const Mat<T, N> M = H.template bottomRightCorner<N, N>();
    const Vec<T, N> dv = M.partialPivLu().solve(F);
    v -= dv;
    double nd = 0, nv = 1;
    for (int i = 0; i < N; ++i) {
      nd = std::max(nd, std::abs(to_double(dv(i))));
      nv = std::max(nv, std::abs(to_double(v(i))));
    }
    if (!std::isfinite(nd)) break;
    done = nd <= 1e-28 * nv;
  }
  if (!done)
    throw NumericalError(fmt::format(
        "the Legendre map dL/dv(q0, v) = p0 has no solution near v = p0 (q0 = {}, p0 = {}): "
        "the intended Lagrangian is not regular there",
        fmt::join(s.q0, ", "), fmt::join(s.p0, ", ")));
  for (int i = 0; i < N; ++i) {
    y0[static_cast<std::size_t>(i)] = q(i);
    y0[static_cast<std::size_t>(N + i)] = v(i);
  }
  // the state at T in (q, p): p = dL/dv at the end
  const auto r = reference_solution<T>(f, y0, s.t_end);
  Vec<T, N> qe, ve;
  for (int i = 0; i < N; ++i) {
    qe(i) = r.y[static_cast<std::size_t>(i)];
    ve(i) = r.y[static_cast<std::size_t>(N + i)];
  }
  Vec<T, 2 * N> g;
  Mat<T, 2 * N> H;
  derivatives(qe, ve, g, H);
  out.z.resize(2 * N);
  for (int i = 0; i < N; ++i) {
    out.z(i) = to_double(qe(i));
    out.z(N + i) = to_double(g(N + i));
  }
  out.error = r.error;
  out.macro_steps = r.macro_steps;
  out.evaluations = r.evaluations;
  starts();
  return out;
}

// The study runs the engine for at most 3 dimensions (its reports say so): not compiled
// above that.
template <int N>
modified::SymbolicDL LdKernelN<N>::symbolic(std::shared_ptr<modified::JetSpace> jets) const {
  if constexpr (N > 3)
    throw std::logic_error("the symbolic engine is run for at most 3 dimensions");
  else
    return modified::symbolic_dl<N>(Ld_, std::move(jets), "typed discrete Lagrangian");
}

template <int N>
AdaptiveStudy LdKernelN<N>::epavi(const Eigen::VectorXd& z0, const Eigen::VectorXd& q1, double h0,
                                  long long steps) const {
  const Observable H = [this](const Eigen::VectorXd& z) { return energy(z); };
  return epavi_study<N>(Ld_, H, z0, Vec<double, N>(q1), h0, steps);
}

template <int N>
std::vector<NamedStep> LdKernelN<N>::classical_steppers() {
  auto L = [this](const auto& q, const auto& v) -> scalar_t<decltype(q)> {
    using S = scalar_t<decltype(q)>;
    return dl_.lagrangian<N, S>(Vec<S, N>(q), Vec<S, N>(v));
  };
  auto sv =
      std::make_shared<DelIntegrator<N, decltype(stormer_verlet_dl(L))>>(stormer_verlet_dl(L));
  auto mid = std::make_shared<DelIntegrator<N, decltype(midpoint_dl(L))>>(midpoint_dl(L));
  return {{"stormer_verlet",
           [sv](Eigen::VectorXd& z, double h) {
             sv->reset();
             step_qp<N>(*sv, z, h);
           }},
          {"midpoint", [mid](Eigen::VectorXd& z, double h) {
             mid->reset();
             step_qp<N>(*mid, z, h);
           }}};
}

}  // namespace vibook::verify
