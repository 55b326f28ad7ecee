/// \file problems.hpp
/// \brief Mechanical test problems H = ½|p|² + U(q) with unit mass. A problem knows its
/// potential (templated, so AutoDiff can differentiate it) and its gradient (written out,
/// for the fast kernels); it never knows an integrator.
#pragma once

#include <cmath>

#include "vibook/core/types.hpp"

namespace vibook {

/// Harmonic oscillator, one degree of freedom: U(q) = ½ q², H = ½ p² + ½ q².
struct HarmonicOscillator {
  static constexpr int N = 1;
  static constexpr const char* name = "harmonic";
  template <class S>
  S potential(const Vec<S, 1>& q) const {
    return constant<S>(0.5) * q(0) * q(0);
  }
  template <class S>
  Vec<S, 1> gradient(const Vec<S, 1>& q) const {
    return q;
  }
};

/// Mathematical pendulum, one degree of freedom: U(q) = −cos q (stable equilibrium at q = 0).
/// Shen & Sun's Fig. 1 writes the potential as φ = cos x, the same system shifted by π.
struct Pendulum {
  static constexpr int N = 1;
  static constexpr const char* name = "pendulum";
  template <class S>
  S potential(const Vec<S, 1>& q) const {
    using std::cos;
    return -cos(q(0));
  }
  template <class S>
  Vec<S, 1> gradient(const Vec<S, 1>& q) const {
    using std::sin;
    return Vec<S, 1>(sin(q(0)));
  }
};

/// Hénon–Heiles, two degrees of freedom: U(x, y) = ½(x² + y²) + x²y − y³/3 (Hénon & Heiles 1964),
/// bounded motion for energies below 1/6.
struct HenonHeiles {
  static constexpr int N = 2;
  static constexpr const char* name = "henon-heiles";
  template <class S>
  S potential(const Vec<S, 2>& q) const {
    const S x = q(0), y = q(1);
    return constant<S>(0.5) * (x * x + y * y) + x * x * y - y * y * y / constant<S>(3);
  }
  template <class S>
  Vec<S, 2> gradient(const Vec<S, 2>& q) const {
    const S x = q(0), y = q(1);
    Vec<S, 2> g;
    g(0) = x + constant<S>(2) * x * y;
    g(1) = y + x * x - y * y;
    return g;
  }
};

/// Energy H(q, p) = ½|p|² + U(q) of a mechanical problem.
template <class Problem>
double energy(const Problem& P, const Vec<double, Problem::N>& q,
              const Vec<double, Problem::N>& p) {
  return 0.5 * p.squaredNorm() + P.potential(q);
}

}  // namespace vibook
