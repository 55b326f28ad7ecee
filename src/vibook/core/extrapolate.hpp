/// \file extrapolate.hpp
/// \brief The start of an implicit step from the steps before it: the polynomial through the
/// last n values of a smooth sequence, evaluated one index further.
///
/// The closed-form steppers (avi/avi.hpp, epavi/mechanical.hpp) solve for a quantity that
/// changes smoothly from step to step: AVI's midpoints (equally spaced in the fictitious time
/// a), EpAVI's positions and steps (smooth in the step index). The polynomial of degree n − 1
/// through the last n values, taken at the next index, is Σ_j (−1)^(j+1) C(n, j) x_{k+1−j}
/// (the n-th difference set to zero). For Kepler at h0 = 1e-3 and n = 8 it misses the
/// converged value by about 1e-14 relative, where the rounding of the samples (amplified by
/// at most Σ C(8, j) = 255) takes over; a start this close leaves Newton one correction.
/// It is only a start: the solve decides the step.
#pragma once

#include <algorithm>
#include <array>

#include "vibook/core/types.hpp"

namespace vibook {

/// The last K values of a sequence (newest first) and their extrapolation to the next index.
/// V is a scalar or an Eigen vector over the scalar S.
template <class V, class S, int K>
class SampleHistory {
 public:
  static_assert(K >= 1 && K <= 12, "binomial weights are exact in double up to K = 12");

  /// Forget the values (a new trajectory).
  void clear() { count_ = 0; }
  /// How many values are held (at most K).
  int count() const { return count_; }
  /// The newest value; requires count() >= 1.
  const V& newest() const { return x_[top_]; }
  /// The j-th newest value (0: the newest); requires j < count().
  const V& value(int j) const { return x_[top_ + j]; }
  /// The weight of value(j) in next(n); requires 0 <= j < n <= K.
  static double weight(int n, int j) { return kWeights[n - 1][j]; }

  void push(const V& x) {
    if (top_ == 0) {  // the buffer's front is full: the K − 1 newest go back to its end
      for (int j = K - 2; j >= 0; --j) x_[K + 1 + j] = x_[j];
      top_ = K + 1;
    }
    x_[--top_] = x;
    count_ = std::min(count_ + 1, K);
  }

  /// The polynomial through the last min(count(), n) values at the next index; requires
  /// count() >= 1 (one value extrapolates as a constant).
  V next(int n = K) const { return weighted(x_[top_], x_.data() + top_ + 1, std::min(n, count_)); }

  /// What next(n) would return after push(x), without pushing: the same sum in the same
  /// order, so the two agree to the last bit (AVI computes the next step's start this way
  /// before it knows whether x is accepted).
  V next_after(const V& x, int n = K) const {
    return weighted(x, x_.data() + top_, std::min({n, count_ + 1, K}));
  }

 private:
  /// Σ_j w(n, j) x_j over x_0 = newest and x_1, x_2, … = older[0], older[1], …
  static V weighted(const V& newest, const V* older, int n) {
    V sum = newest * S(kWeights[n - 1][0]);
    for (int j = 1; j < n; ++j) sum += older[j - 1] * S(kWeights[n - 1][j]);
    return sum;
  }

  /// kWeights[n − 1][j − 1] = (−1)^(j+1) C(n, j): the weight of the j-th last of n values.
  static constexpr auto kWeights = [] {
    std::array<std::array<double, K>, K> w{};
    for (int n = 1; n <= K; ++n) {
      long long c = 1;
      for (int j = 1; j <= n; ++j) {
        c = c * (n - j + 1) / j;
        w[n - 1][j - 1] = j % 2 == 1 ? double(c) : -double(c);
      }
    }
    return w;
  }();

  /// The values newest first from x_[top_]: a push writes one place further down, so it
  /// copies nothing until the front is reached, and then the K − 1 it keeps once.
  std::array<V, 2 * K> x_{};
  int top_ = 2 * K;
  int count_ = 0;
};

}  // namespace vibook
