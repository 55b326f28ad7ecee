// LdKernel for dimension N (ld_study.hpp): the dimension-dependent operations of a typed
// discrete Lagrangian. Included only by the generated ld_kernel_N.cpp, one per dimension; the
// parts a study runs once (the reference, the symbolic L_d, EpAVI, the classical steppers) are
// defined in ld_kernel_cold_impl.hpp and compiled in the same unit.
#pragma once

#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "vibook/mechanics/del_solver.hpp"
#include "vibook/mechanics/discrete_lagrangian.hpp"
#include "vibook/verify/adaptive.hpp"
#include "vibook/verify/ld_study.hpp"
#include "vibook/verify/map_study.hpp"
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
      std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
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

  // The continuous equations in double-double (ld_kernel_cold_impl.hpp, with the other parts
  // that run once a study).
  LdReference reference(const LdSettings& s) const override;

  modified::SymbolicDL symbolic(std::shared_ptr<modified::JetSpace> jets) const override;

  AdaptiveStudy epavi(const Eigen::VectorXd& z0, const Eigen::VectorXd& q1, double h0,
                      long long steps) const override;

  std::vector<NamedStep> classical_steppers() override;

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
