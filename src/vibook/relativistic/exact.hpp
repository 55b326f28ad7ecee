/// \file exact.hpp
/// \brief Exact bound motion of the relativistic Kepler problem in proper time: the
/// precessing orbit 1/r = B(1 + e cos Γ(ψ − ψ_p)) and its parametrization by proper time,
/// which reduces to Kepler's equation (derivation in the book's chapter "Relativistic
/// Kepler").
///
/// Chapter: \ref chapter-relativistic.
#pragma once

#include <cmath>
#include <numbers>

#include "vibook/core/errors.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/relativistic/relativistic.hpp"

namespace vibook::relativistic {

/// With s = 1/r, energy E = c²γ − s, angular momentum L = x × u (|L| = ℓ), and ψ the polar
/// angle measured in the direction of motion:
///   s(ψ) = B (1 + e cos θ),  θ = Γ(ψ − ψ_p),  Γ = √(1 − 1/(c²ℓ²)),  B = E/(c²ℓ²Γ²);
///   proper time  n τ = E_a − e sin E_a  (+ const),  n = ℓ B² Γ (1 − e²)^{3/2},
///   with the eccentric anomaly tan(E_a/2) = √((1−e)/(1+e)) tan(θ/2);
///   coordinate time  t = (E τ + (E_a − E_a0)/(ℓ B Γ √(1 − e²)))/c²;
///   γ = (E + s)/c².
/// The perihelion advances by 2π(1/Γ − 1) per radial period 2π/n.
class ExactOrbit {
 public:
  /// The orbit through x0 with relativistic momentum u0 at τ = t = 0. Throws ArgumentError
  /// when the motion is not a bound precessing ellipse (c ℓ ≤ 1: fall to the centre;
  /// E ≥ c²: unbound; ℓ = 0: radial).
  ExactOrbit(const Problem& P, const Vec<double, 2>& x0, const Vec<double, 2>& u0) : c_(P.c) {
    const RelState s0 = P.initial(x0, u0);
    const Invariants inv = invariants(P, s0);
    E_ = inv.energy;
    ell_ = std::abs(inv.L);
    sense_ = inv.L >= 0 ? 1.0 : -1.0;
    if (ell_ == 0.0) throw ArgumentError("initial state", "radial motion (x × u = 0) has no orbit");
    const double cl = c_ * ell_;
    if (!(cl > 1.0)) {
      throw ArgumentError("initial state", "c·|x × u| <= 1: the particle falls into the centre");
    }
    // Binding energy E − c² = c²(γ − 1) − 1/r, with γ − 1 = (|u|²/c²)/(γ + 1): no cancellation
    // even when c is large.
    const double g1 = (u0.squaredNorm() / (c_ * c_)) / (s0.gamma + 1.0);
    const double binding = c_ * c_ * g1 - 1.0 / x0.norm();
    if (!(binding < 0.0))
      throw ArgumentError("initial state", "energy >= c²: the orbit is not bound");
    Gamma_ = std::sqrt(1.0 - 1.0 / (cl * cl));
    B_ = E_ / (cl * cl * Gamma_ * Gamma_);
    const double r0 = x0.norm(), s = 1.0 / r0;
    const double ecos = s / B_ - 1.0;
    const double esin = (x0.dot(u0) / r0) / (ell_ * B_ * Gamma_);
    e_ = std::hypot(ecos, esin);
    if (!(B_ > 0.0 && e_ < 1.0)) throw ArgumentError("initial state", "the orbit is not bound");
    theta0_ = std::atan2(esin, ecos);
    psi_p_ = sense_ * std::atan2(x0(1), x0(0)) - theta0_ / Gamma_;
    Ea0_ = 2.0 * std::atan2(std::sqrt(1.0 - e_) * std::sin(0.5 * theta0_),
                            std::sqrt(1.0 + e_) * std::cos(0.5 * theta0_));
    n_ = ell_ * B_ * B_ * Gamma_ * std::pow(1.0 - e_ * e_, 1.5);
    M0_ = Ea0_ - e_ * std::sin(Ea0_);
  }

  double Gamma() const { return Gamma_; }
  double B() const { return B_; }
  double eccentricity() const { return e_; }
  double energy() const { return E_; }
  double angular_momentum() const { return sense_ * ell_; }
  /// Radial (perihelion-to-perihelion) period in proper time.
  double radial_period() const { return 2.0 * std::numbers::pi / n_; }
  /// Perihelion advance per radial period, in the direction of motion: 2π(1/Γ − 1).
  double precession_per_revolution() const { return 2.0 * std::numbers::pi * (1.0 / Gamma_ - 1.0); }

  /// Radius on the orbit at polar angle φ (unwrapped along the motion from the start).
  double radius_at_angle(double phi) const {
    return 1.0 / (B_ * (1.0 + e_ * std::cos(Gamma_ * (sense_ * phi - psi_p_))));
  }

  /// Exact state at proper time τ.
  RelState at(double tau) const {
    const double M = M0_ + n_ * tau;
    const double k = std::nearbyint(M / (2.0 * std::numbers::pi));  // as in reduce_angle
    const double Ea_red = solve_kepler_equation(M, e_);
    const double Ea = Ea_red + 2.0 * std::numbers::pi * k;
    const double theta = 2.0 * std::atan2(std::sqrt(1.0 + e_) * std::sin(0.5 * Ea_red),
                                          std::sqrt(1.0 - e_) * std::cos(0.5 * Ea_red)) +
                         2.0 * std::numbers::pi * k;
    const double s = B_ * (1.0 + e_ * std::cos(theta));
    const double psi = psi_p_ + theta / Gamma_;
    const double phi = sense_ * psi;
    const double r = 1.0 / s;
    const double vr = ell_ * B_ * e_ * Gamma_ * std::sin(theta);  // dr/dτ
    const double vt = sense_ * ell_ * s;                          // r dφ/dτ
    RelState out;
    out.x = Vec<double, 2>(r * std::cos(phi), r * std::sin(phi));
    out.u = Vec<double, 2>(vr * std::cos(phi) - vt * std::sin(phi),
                           vr * std::sin(phi) + vt * std::cos(phi));
    out.gamma = (E_ + s) / (c_ * c_);
    out.t = (E_ * tau + (Ea - Ea0_) / (ell_ * B_ * Gamma_ * std::sqrt(1.0 - e_ * e_))) / (c_ * c_);
    return out;
  }

 private:
  double c_, E_ = 0, ell_ = 0, sense_ = 1, Gamma_ = 1, B_ = 1, e_ = 0;
  double theta0_ = 0, psi_p_ = 0, Ea0_ = 0, n_ = 1, M0_ = 0;
};

}  // namespace vibook::relativistic
