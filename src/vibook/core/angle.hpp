/// \file angle.hpp
/// \brief Unwrapping an angle sampled along a motion: each new value is taken within π of the
/// previous one (exact as long as the angle moves by less than π between samples).
#pragma once

#include <cmath>
#include <numbers>

namespace vibook {

class AngleUnwrapper {
 public:
  /// Feed an angle in any branch; returns the continuous (unwrapped) value.
  double operator()(double angle) {
    if (!started_) {
      started_ = true;
      unwrapped_ = angle;
    } else {
      double d = angle - last_;
      d -= 2 * std::numbers::pi * std::nearbyint(d / (2 * std::numbers::pi));
      unwrapped_ += d;
    }
    last_ = angle;
    return unwrapped_;
  }
  double value() const { return unwrapped_; }

 private:
  bool started_ = false;
  double last_ = 0, unwrapped_ = 0;
};

}  // namespace vibook
