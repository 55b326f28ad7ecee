// LdKernel for dimension N (ld_study.hpp): the dimension-dependent operations of a typed
// discrete Lagrangian. Included only by the generated ld_kernel_N.cpp, one per dimension.
#pragma once

#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "vibook/mechanics/del_solver.hpp"
#include "vibook/mechanics/discrete_lagrangian.hpp"
#include "vibook/modified/series.hpp"
#include "vibook/verify/adaptive.hpp"
#include "vibook/verify/ld_study.hpp"
#include "vibook/verify/map_study.hpp"
#include "vibook/verify/reference.hpp"
#include "vibook/verify/tape.hpp"
#include "vibook/verify/typed_system.hpp"

namespace vibook::verify {

template <int N>
class LdKernelN final : public LdKernel {
 public:
  LdKernelN(const TypedDiscreteLagrangian& dl, bool reference_evaluation)
      : dl_(dl), Ld_(dl.bind<N>()), tree_(Ld_) {
    // The method is stepped through the compiled tape (tape.hpp: D1 L_d, D2 L_d and D2 D1 L_d
    // as straight-line code), or with --reference through nested AutoDiff on the expression
    // tree, the path the tape is checked against.
    if (!reference_evaluation) {
      std::lock_guard<std::mutex> lock(modified::ginac_mutex());
      tape_.emplace(CompiledDiscreteLagrangian<N>(dl));
    }
  }

  int dim() const override { return N; }

  std::string evaluation() const override {
    if (!tape_) return "nested forward AutoDiff on the expression tree (--reference)";
    const auto& c = tape_->lagrangian();
    const auto st = c.stats();
    return fmt::format(
        "compiled tape, {}: {} instructions per Newton iteration and {} once a step{}, {} for "
        "the momentum{} (--reference: nested AutoDiff)",
        c.native() ? std::string("run as native code")
                   : "interpreted (no native code: " + c.native_reason() + ")",
        st.newton_instructions - st.newton_prefix, st.newton_prefix,
        st.carried > 0 ? fmt::format(" ({} with the {} values the last momentum carries over)",
                                     st.newton_prefix_carried, st.carried)
                       : std::string(),
        st.momentum_instructions,
        c.jacobian_constant() ? "; D2 D1 L_d is free of q1, so Newton factors its matrix once"
                              : "");
  }

  std::string evaluation_kind() const override {
    return !tape_ ? "autodiff" : tape_->lagrangian().native() ? "native" : "tape";
  }

  SolveReport step(Eigen::VectorXd& z, double h) override {
    Vec<double, N> q = z.head<N>(), p = z.tail<N>();
    const SolveReport rep = tape_ ? tape_->step(q, p, h) : tree_.step(q, p, h);
    z.head<N>() = q;
    z.tail<N>() = p;
    return rep;
  }

  void reset() override {
    tree_.reset();
    if (tape_) tape_->reset();
  }

  double largest_frequency(const std::vector<double>& q0) const override {
    if (!dl_.has_potential()) return 0;
    try {
      Vec<double, N> q;
      for (int i = 0; i < N; ++i) q(i) = q0[static_cast<std::size_t>(i)];
      double value = 0;
      Vec<double, N> g;
      Mat<double, N> H;
      value_gradient_hessian<N, double>([&](const auto& x) { return dl_.potential<N>(x); }, q,
                                        value, g, H);
      // (1 x 1 directly: GCC 12 warns, falsely, of bounds in the copy of a 1 x 1 matrix)
      double lmax = H(0, 0);
      if constexpr (N > 1) lmax = largest_symmetric_eigenvalue(H);
      return lmax > 0 ? std::sqrt(lmax) : 0;
    } catch (const std::exception&) {
      return 0;
    }
  }

  TwoPoint two_point(const Eigen::VectorXd& qa, const Eigen::VectorXd& qb,
                     double h) const override {
    const auto d = ad::two_point<N>(Ld_, Vec<double, N>(qa), Vec<double, N>(qb), h);
    return {d.value, d.D1, d.D2, d.D12, d.D12.determinant()};
  }

  modified::ex ld_symbolic(const std::vector<modified::ex>& x, const std::vector<modified::ex>& xh,
                           const modified::ex& h) const override {
    return dl_.evaluate<N, modified::ex>(vec(x), vec(xh), h);
  }

  modified::ex lagrangian_symbolic(const std::vector<modified::ex>& x,
                                   const std::vector<modified::ex>& v) const override {
    return dl_.lagrangian<N, modified::ex>(vec(x), vec(v));
  }

  double hamiltonian_gradient(const Eigen::VectorXd& y, Eigen::VectorXd& grad) const override {
    double Hv = 0;
    Vec<double, 2 * N> g;
    Mat<double, 2 * N> Hm;
    value_gradient_hessian<2 * N, double>(
        [&](const auto& w) {
          using S = scalar_t<decltype(w)>;
          Vec<S, N> q = w.template head<N>(), pp = w.template tail<N>();
          return dl_.hamiltonian<N, S>(q, pp);
        },
        Vec<double, 2 * N>(y), Hv, g, Hm);
    grad = g;
    return Hv;
  }

  double hamiltonian(const Eigen::VectorXd& q, const Eigen::VectorXd& p) const override {
    return dl_.hamiltonian<N, double>(Vec<double, N>(q), Vec<double, N>(p));
  }

  double lagrangian(const Eigen::VectorXd& q, const Eigen::VectorXd& v) const override {
    return dl_.lagrangian<N, double>(Vec<double, N>(q), Vec<double, N>(v));
  }

  // H(q, p): typed, ½|p|² + V for the default system, else the Legendre transform of L (v
  // from dL/dv = p by Newton in double).
  double energy(const Eigen::VectorXd& z) const override {
    if (dl_.has_hamiltonian())
      return dl_.hamiltonian<N, double>(Vec<double, N>(z.head<N>()), Vec<double, N>(z.tail<N>()));
    if (dl_.default_system())
      return 0.5 * z.tail<N>().squaredNorm() +
             dl_.potential<N, double>(Vec<double, N>(z.head<N>()));
    const Vec<double, N> q = z.head<N>(), pk = z.tail<N>();
    Vec<double, N> v = pk;
    for (int it = 0; it < 50; ++it) {
      double value;
      Vec<double, N> g;
      Mat<double, N> H;
      value_gradient_hessian<N, double>(
          [&](const auto& w) {
            using S = scalar_t<decltype(w)>;
            return dl_.lagrangian<N, S>(q.template cast<S>(), w);
          },
          v, value, g, H);
      const Vec<double, N> dv = H.partialPivLu().solve(Vec<double, N>(g - pk));
      v -= dv;
      if (dv.template lpNorm<Eigen::Infinity>() <=
          1e-15 * std::max(1.0, v.template lpNorm<Eigen::Infinity>()))
        return pk.dot(v) - dl_.lagrangian<N, double>(q, v);
      if (!dv.allFinite()) break;
    }
    throw NumericalError("energy: the Legendre map dL/dv(q, v) = p has no solution at q = " +
                         state_text(q) + ", p = " + state_text(pk));
  }

  // The continuous equations in double-double: Hamilton's of H, or the Euler–Lagrange
  // equations of L in (q, v) with v from dL/dv(q0, v) = p0 and p = dL/dv at the end.
  LdReference reference(const LdSettings& s) const override {
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
  modified::SymbolicDL symbolic(std::shared_ptr<modified::JetSpace> jets) const override {
    if constexpr (N > 3)
      throw std::logic_error("the symbolic engine is run for at most 3 dimensions");
    else
      return modified::symbolic_dl<N>(Ld_, std::move(jets), "typed discrete Lagrangian");
  }

  AdaptiveStudy epavi(const Eigen::VectorXd& z0, const Eigen::VectorXd& q1, double h0,
                      long long steps) const override {
    const Observable H = [this](const Eigen::VectorXd& z) { return energy(z); };
    return epavi_study<N>(Ld_, H, z0, Vec<double, N>(q1), h0, steps);
  }

  std::vector<NamedStep> classical_steppers() override {
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

 private:
  static Vec<modified::ex, N> vec(const std::vector<modified::ex>& x) {
    Vec<modified::ex, N> out;
    for (int i = 0; i < N; ++i) out(i) = x[static_cast<std::size_t>(i)];
    return out;
  }
  static std::string state_text(const Vec<double, N>& v) {
    return vec_text(std::vector<double>(v.data(), v.data() + N));
  }

  const TypedDiscreteLagrangian& dl_;
  decltype(std::declval<const TypedDiscreteLagrangian&>().template bind<N>()) Ld_;
  DelIntegrator<N, decltype(Ld_)> tree_;
  std::optional<DelIntegrator<N, CompiledDiscreteLagrangian<N>>> tape_;
};

}  // namespace vibook::verify
