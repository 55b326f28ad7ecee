/// \file precession.hpp
/// \brief Measured perihelion advance of a planar orbit from its sampled positions,
/// streaming (O(1) memory): perihelia are the local minima of r, located between samples by
/// a parabola through three radii, their polar angle interpolated to the same point.
///
/// Chapter: \ref chapter-relativistic.
#pragma once

#include <cmath>
#include <numbers>
#include <optional>

#include "vibook/core/angle.hpp"
#include "vibook/core/types.hpp"

namespace vibook::relativistic {

class PerihelionTracker {
 public:
  /// Feed the next position (equally spaced in the orbit's parameter).
  void add(const Vec<double, 2>& x) {
    const double r = x.norm();
    const double psi = angle_(std::atan2(x(1), x(0)));
    if (count_ > 0) {
      psi_[2] = psi_[1];
      psi_[1] = psi_[0];
      psi_[0] = psi;
    } else {
      psi_[0] = psi_[1] = psi_[2] = psi;
    }
    r_[2] = r_[1];
    r_[1] = r_[0];
    r_[0] = r;
    ++count_;
    if (count_ >= 3 && r_[1] < r_[0] && r_[1] <= r_[2]) {
      // samples at offsets −1 (r_[2]), 0 (r_[1]), +1 (r_[0]); vertex of the parabola:
      const double denom = r_[2] - 2 * r_[1] + r_[0];
      const double delta = denom > 0 ? 0.5 * (r_[2] - r_[0]) / denom : 0.0;
      const double angle = psi_[1] + delta * 0.5 * (psi_[0] - psi_[2]);
      if (first_) {
        sense_ = psi_[0] >= psi_[2] ? 1.0 : -1.0;
        first_angle_ = angle;
        first_ = false;
      }
      last_angle_ = angle;
      ++perihelia_;
    }
  }
  /// Number of perihelion passages seen.
  int perihelia() const { return perihelia_; }
  /// Mean perihelion advance per revolution in the direction of motion (needs two passages).
  std::optional<double> advance_per_revolution() const {
    if (perihelia_ < 2) return std::nullopt;
    return sense_ * (last_angle_ - first_angle_) / (perihelia_ - 1) - 2 * std::numbers::pi;
  }

 private:
  double r_[3] = {0, 0, 0}, psi_[3] = {0, 0, 0};
  AngleUnwrapper angle_;
  double first_angle_ = 0, last_angle_ = 0, sense_ = 1;
  long count_ = 0;
  int perihelia_ = 0;
  bool first_ = true;
};

}  // namespace vibook::relativistic
