/// \file splitting.hpp
/// \brief Splitting variational integrators, Shen & Sun 2025, §3, (3.3)–(3.8), Theorems 6–7,
/// for ẍ = −∇φ(x) with φ split into one piece per coordinate, φ = Σ_i φ^[i] (x ∈ R^N).
///
/// Two forms of each method, which Theorems 6–7 say are the same map:
///  - the Lagrangian form: the discrete Lagrangians (3.3), its adjoint, and the half-step
///    chains (3.7)/(3.8), solved by the generic discrete Euler–Lagrange solver;
///  - the composition form: Φ_h = Φ_{H_N} ∘ … ∘ Φ_{H_1}, Φ_{H_i} the symplectic-Euler sub-step
///    of H_i = ½p_i² + φ^[i] (x_i += h p_i, then p −= h ∇φ^[i](x)); its adjoint
///    Φ*_h = Φ*_{H_1} ∘ … ∘ Φ*_{H_N} (p −= h ∇φ^[i](x), then x_i += h p_i, i from N down).
///
/// Methods (command line names): vi1 = Φ_h (3.3); vi1-adjoint = Φ*_h; vi2 = Φ_{h/2} ∘ Φ*_{h/2}
/// (3.8), the paper's VI-2 (3.15); vi2-adjoint = Φ*_{h/2} ∘ Φ_{h/2} (3.7).
///
/// Chapter: \ref chapter-kepler-lrl.
#pragma once

#include <string_view>

#include "vibook/core/autodiff.hpp"
#include "vibook/core/errors.hpp"
#include "vibook/mechanics/del_solver.hpp"
#include "vibook/mechanics/discrete_lagrangian.hpp"

namespace vibook {

/// A problem's potential split into φ^[1] = αφ, φ^[2] = (1 − α)φ, … (weights summing to 1),
/// one piece per coordinate. The paper's Kepler experiments use α = ½.
template <class Problem>
struct WeightedSplit {
  static constexpr int N = Problem::N;
  Problem problem;
  Vec<double, N> weight;

  /// Two-piece split α, 1 − α (N = 2); for N = 1 the single piece is φ.
  static WeightedSplit alpha(double a, Problem P = {}) {
    if (!(a >= 0.0 && a <= 1.0)) throw ArgumentError("--alpha", "must lie in [0, 1]");
    WeightedSplit s{P, Vec<double, N>::Zero()};
    s.weight(0) = N == 1 ? 1.0 : a;
    if constexpr (N > 1) s.weight(1) = 1.0 - a;
    return s;
  }
  /// φ^[i](x), generic in the scalar.
  template <class S>
  S piece(int i, const Vec<S, N>& x) const {
    return constant<S>(weight(i)) * problem.potential(x);
  }
  /// ∇φ^[i](x).
  Vec<double, N> piece_gradient(int i, const Vec<double, N>& x) const {
    return weight(i) * problem.gradient(x);
  }
};

// Shen & Sun 2025, (3.3), in vibook's scaling L_d = h·𝕃:
//   L_d(x_n, x_{n+1}, h) = |x_{n+1} − x_n|²/(2h) − h Σ_i φ^[i](x̂^i),
//   x̂^i = x_n + Σ_{j ≤ i} (x_{n+1}^j − x_n^j) e_j.
/// First-order splitting discrete Lagrangian (3.3).
template <class Split>
auto splitting_dl(Split split) {
  return [sp = std::move(split)](const auto& x0, const auto& x1,
                                 const auto& h) -> scalar_t<decltype(h)> {
    using S = scalar_t<decltype(h)>;
    constexpr int N = Split::N;
    Vec<S, N> xhat = x0;
    S pot = constant<S>(0);
    for (int i = 0; i < N; ++i) {
      xhat(i) = x1(i);
      pot += sp.piece(i, xhat);
    }
    const Vec<S, N> d = x1 - x0;
    return S(squared_norm(d) / (constant<S>(2) * h) - h * pot);
  };
}

// The adjoint 𝕃*(x_n, x_{n+1}, h) = 𝕃(x_{n+1}, x_n, −h); scaled: L_d*(x0, x1, h) = −L_d(x1, x0,
// −h).
/// Adjoint of the first-order splitting discrete Lagrangian.
template <class Split>
auto splitting_dl_adjoint(Split split) {
  return [Ld = splitting_dl(std::move(split))](const auto& x0, const auto& x1,
                                               const auto& h) -> scalar_t<decltype(h)> {
    using S = scalar_t<decltype(h)>;
    const S mh = -h;
    return S(-Ld(x1, x0, mh));
  };
}

/// The composition form: explicit, one ∇φ^[i] per piece and sub-step.
template <class Split>
class SplittingComposition {
 public:
  static constexpr int N = Split::N;
  explicit SplittingComposition(Split s) : split_(std::move(s)) {}

  /// Φ_h (Theorem 6): for i = 1..N, x_i += h p_i, then p −= h ∇φ^[i](x).
  void phi(Vec<double, N>& x, Vec<double, N>& p, double h) const {
    for (int i = 0; i < N; ++i) {
      x(i) += h * p(i);
      p -= h * split_.piece_gradient(i, x);
    }
  }
  /// Φ*_h, the adjoint: for i = N..1, p −= h ∇φ^[i](x), then x_i += h p_i.
  void phi_adjoint(Vec<double, N>& x, Vec<double, N>& p, double h) const {
    for (int i = N - 1; i >= 0; --i) {
      p -= h * split_.piece_gradient(i, x);
      x(i) += h * p(i);
    }
  }
  const Split& split() const { return split_; }

 private:
  Split split_;
};

/// The four splitting methods, by name.
enum class SplittingMethod { vi1, vi1_adjoint, vi2, vi2_adjoint };

inline SplittingMethod parse_splitting_method(std::string_view s) {
  if (s == "vi1") return SplittingMethod::vi1;
  if (s == "vi1-adjoint") return SplittingMethod::vi1_adjoint;
  if (s == "vi2") return SplittingMethod::vi2;
  if (s == "vi2-adjoint") return SplittingMethod::vi2_adjoint;
  throw ArgumentError("--method", "unknown splitting method '" + std::string(s) + "'");
}

/// Composition form of a splitting method: step(q, p, h).
template <class Split>
class SplittingKernel {
 public:
  static constexpr int N = Split::N;
  SplittingKernel(Split s, SplittingMethod m) : c_(std::move(s)), m_(m) {}
  /// Explicit: the report has residual 0 and no iterations (the kernels' interface).
  SolveReport step(Vec<double, N>& q, Vec<double, N>& p, double h) const {
    // [splitting-step]
    switch (m_) {
      case SplittingMethod::vi1:
        c_.phi(q, p, h);
        break;
      case SplittingMethod::vi1_adjoint:
        c_.phi_adjoint(q, p, h);
        break;
      case SplittingMethod::vi2:  // (3.8): Φ_{h/2} ∘ Φ*_{h/2}
        c_.phi_adjoint(q, p, 0.5 * h);
        c_.phi(q, p, 0.5 * h);
        break;
      case SplittingMethod::vi2_adjoint:  // (3.7): Φ*_{h/2} ∘ Φ_{h/2}
        c_.phi(q, p, 0.5 * h);
        c_.phi_adjoint(q, p, 0.5 * h);
        break;
    }
    // [splitting-step]
    return SolveReport{0.0, 0, true};
  }

 private:
  SplittingComposition<Split> c_;
  SplittingMethod m_;
};

/// Lagrangian form of a splitting method: the generic discrete Euler–Lagrange solver on (3.3),
/// its adjoint, or the half-step chains (3.7)/(3.8). step(q, p, h) returns the larger Newton
/// residual of its (half) steps.
template <class Split>
class SplittingVariational {
 public:
  static constexpr int N = Split::N;
  using L1 = decltype(splitting_dl(std::declval<Split>()));
  using LA = decltype(splitting_dl_adjoint(std::declval<Split>()));
  SplittingVariational(Split s, SplittingMethod m)
      : first_(splitting_dl(s)), adjoint_(splitting_dl_adjoint(s)), m_(m) {}

  SolveReport step(Vec<double, N>& q, Vec<double, N>& p, double h) {
    auto merge = [](SolveReport a, const SolveReport& b) {
      a.residual = std::max(a.residual, b.residual);
      a.iterations += b.iterations;
      return a;
    };
    switch (m_) {
      case SplittingMethod::vi1:
        return first_.step(q, p, h);
      case SplittingMethod::vi1_adjoint:
        return adjoint_.step(q, p, h);
      case SplittingMethod::vi2: {  // (3.8): L_d*(x_n, x_{n+1/2}) + L_d^1st(x_{n+1/2}, x_{n+1})
        const SolveReport a = adjoint_.step(q, p, 0.5 * h);
        return merge(a, first_.step(q, p, 0.5 * h));
      }
      case SplittingMethod::vi2_adjoint: {  // (3.7)
        const SolveReport a = first_.step(q, p, 0.5 * h);
        return merge(a, adjoint_.step(q, p, 0.5 * h));
      }
    }
    return {};
  }

 private:
  DelIntegrator<N, L1> first_;
  DelIntegrator<N, LA> adjoint_;
  SplittingMethod m_;
};

}  // namespace vibook
