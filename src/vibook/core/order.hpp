/// \file order.hpp
/// \brief Measured convergence orders: least-squares slope of log(error) against log(h).
#pragma once

#include <cmath>
#include <stdexcept>
#include <vector>

namespace vibook {

struct OrderFit {
  double slope = 0.0;  ///< fitted order p in error ≈ C h^p
  int points = 0;      ///< number of (h, error) pairs used
};

/// Fit error ≈ C h^p over the pairs whose error lies above `floor` (the round-off plateau is
/// excluded, never fitted). Throws std::invalid_argument if fewer than `min_points` remain.
inline OrderFit fit_order(const std::vector<double>& h, const std::vector<double>& err,
                          double floor, int min_points = 4) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    if (!(err[i] > floor) || !(h[i] > 0)) continue;
    const double x = std::log(h[i]), y = std::log(err[i]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
    ++n;
  }
  if (n < min_points)
    throw std::invalid_argument("fit_order: too few points above the round-off floor");
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  return {slope, n};
}

}  // namespace vibook
