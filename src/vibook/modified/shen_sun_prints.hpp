/// \file shen_sun_prints.hpp
/// \brief Printed formulas of Shen & Sun 2025 used by more than one check, typed once.
///
/// Chapter: \ref chapter-modified.
#pragma once

#include <algorithm>
#include <array>
#include <functional>
#include <vector>

#include "vibook/modified/jets.hpp"

namespace vibook::checks {

/// The h² coefficient of (4.24) (VI-2's modified equation as printed), component by component,
/// for given partial derivatives φ_I (the whole potential) and φ^[1]_I (the first piece),
/// I a sorted 0-based multi-index.
inline std::array<modified::ex, 2> shen_sun_424_h2(
    const std::function<modified::ex(std::vector<int>)>& phi,
    const std::function<modified::ex(std::vector<int>)>& p1, const modified::ex& v1,
    const modified::ex& v2) {
  using modified::ex;
  const ex V[2] = {v1, v2};
  const ex A[2] = {
      6 * p1({0, 0, 0}) * v1 * v1 + 12 * p1({0, 0, 1}) * v1 * v2 - 12 * p1({0, 0}) * phi({0}) -
          6 * p1({0, 1}) * phi({1}) - 6 * phi({0, 1}) * p1({1}),
      -6 * p1({0, 0, 1}) * v1 * v1 - 6 * p1({1, 1}) * phi({1}) - 6 * phi({1, 1}) * p1({1})};
  std::array<ex, 2> out;
  for (int i = 0; i < 2; ++i) {
    ex t3 = 0, t3_1 = 0, hg = 0, h1g = 0;
    for (int j = 0; j < 2; ++j) {
      std::vector<int> ij = {std::min(i, j), std::max(i, j)};
      hg += phi(ij) * phi({j});
      h1g += p1(ij) * phi({j});
      for (int k = 0; k < 2; ++k) {
        std::vector<int> ijk = {i, j, k};
        std::sort(ijk.begin(), ijk.end());
        t3 += phi(ijk) * V[j] * V[k];
        t3_1 += p1(ijk) * V[j] * V[k];
      }
    }
    out[i] = GiNaC::numeric(1, 48) * (4 * t3 - hg - 6 * t3_1 + 12 * h1g + A[i]);
  }
  return out;
}

}  // namespace vibook::checks
