/// \file tolerance.hpp
/// \brief One tolerance policy: explicit absolute and relative parts, never implicit.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace vibook {

/// Unit round-off of binary64.
inline constexpr double kEps = std::numeric_limits<double>::epsilon();

/// |a - b| <= abs + rel * max(|a|, |b|). Both parts are stated at every call site.
struct Tolerance {
  double abs = 0.0;
  double rel = 0.0;
  bool accepts(double a, double b) const {
    return std::abs(a - b) <= abs + rel * std::max(std::abs(a), std::abs(b));
  }
};

/// Convenience for tests: close(a, b, {abs, rel}).
inline bool close(double a, double b, Tolerance tol) { return tol.accepts(a, b); }

}  // namespace vibook
