/// \file types.hpp
/// \brief Fixed-size Eigen vector and matrix aliases used throughout vibook.
#pragma once

#ifdef __FAST_MATH__
#error "vibook must not be compiled with -ffast-math: its tests measure round-off."
#endif

#include <Eigen/Dense>

namespace vibook {

/// Column vector of fixed dimension N over scalar S (S = double, an AutoDiff type, ...).
template <class S, int N>
using Vec = Eigen::Matrix<S, N, 1>;

/// N-by-N matrix over scalar S.
template <class S, int N>
using Mat = Eigen::Matrix<S, N, N>;

/// Phase-space state (q, p) of a system with N degrees of freedom.
template <int N>
struct State {
  Vec<double, N> q = Vec<double, N>::Zero();
  Vec<double, N> p = Vec<double, N>::Zero();
};

}  // namespace vibook
