/// \file kepler.hpp
/// \brief The planar Kepler problem with μ = 1: the problem, its invariants (energy, angular
/// momentum, Laplace–Runge–Lenz vector), and its exact solution through Kepler's equation.
#pragma once

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "vibook/core/errors.hpp"
#include "vibook/core/tolerance.hpp"
#include "vibook/core/types.hpp"

namespace vibook {

/// Kepler problem in the plane: U(q) = −1/|q|, H = ½|p|² − 1/|q|.
struct Kepler {
  static constexpr int N = 2;
  static constexpr const char* name = "kepler";
  template <class S>
  S potential(const Vec<S, 2>& q) const {
    using std::sqrt;
    return -1.0 / sqrt(q.squaredNorm());
  }
  template <class S>
  Vec<S, 2> gradient(const Vec<S, 2>& q) const {
    using std::sqrt;
    const S r2 = q.squaredNorm();
    const S inv_r3 = 1.0 / (r2 * sqrt(r2));
    return (q * inv_r3).eval();
  }
};

/// Invariants of the Kepler flow at one state.
struct KeplerInvariants {
  double H = 0;       ///< energy ½|p|² − 1/|q|
  double L = 0;       ///< angular momentum q1 p2 − q2 p1
  Vec<double, 2> A;   ///< Laplace–Runge–Lenz vector p × L e3 − q/|q|
  double ecc = 0;     ///< eccentricity |A|
  double omega = 0;   ///< perihelion angle atan2(A2, A1), in (−π, π]
};

/// Energy, angular momentum and the LRL vector (Shen & Sun 2025, Prop. 2).
inline KeplerInvariants kepler_invariants(const Vec<double, 2>& q, const Vec<double, 2>& p) {
  KeplerInvariants k;
  const double r = std::hypot(q(0), q(1));
  k.H = 0.5 * p.squaredNorm() - 1.0 / r;
  k.L = q(0) * p(1) - q(1) * p(0);
  k.A = Vec<double, 2>(p(1) * k.L - q(0) / r, -p(0) * k.L - q(1) / r);
  k.ecc = std::hypot(k.A(0), k.A(1));
  k.omega = std::atan2(k.A(1), k.A(0));
  return k;
}

/// Perihelion initial state of the orbit with semi-major axis 1 and eccentricity e, moving
/// counter-clockwise: q0 = (1 − e, 0), p0 = (0, √((1 + e)/(1 − e))). Period 2π.
inline State<2> kepler_perihelion_state(double e) {
  if (!(e >= 0.0 && e < 1.0)) throw ArgumentError("e", "eccentricity must lie in [0, 1)");
  State<2> s;
  s.q = Vec<double, 2>(1.0 - e, 0.0);
  s.p = Vec<double, 2>(0.0, std::sqrt((1.0 + e) / (1.0 - e)));
  return s;
}

namespace internal {
/// E − sin E, without cancellation for small |E| (series below |E| = 1).
inline double e_minus_sin(double E) {
  const double a = std::abs(E);
  if (a >= 1.0) return E - std::sin(E);
  // E³/3! − E⁵/5! + ... ; 12 terms reach binary64 round-off for |E| < 1.
  const double E2 = E * E;
  double term = E * E2 / 6.0;
  double sum = 0.0;
  for (int k = 1; k <= 12; ++k) {
    sum += term;
    term *= -E2 / ((2.0 * k + 2.0) * (2.0 * k + 3.0));
  }
  return sum;
}
}  // namespace internal

/// Reduce an angle to [−π, π] with a three-part 2π (Cody–Waite with FMA), accurate to about
/// one ulp of the result for |x| < 2^40.
inline double reduce_angle(double x) {
  constexpr double kTwoPi1 = 6.283185307179586;       // 2π rounded to binary64
  constexpr double kTwoPi2 = 2.4492935982947064e-16;  // 2π − kTwoPi1, rounded
  constexpr double kTwoPi3 = -5.989539619436679e-33;  // the next part
  const double k = std::nearbyint(x / kTwoPi1);
  double r = std::fma(-k, kTwoPi1, x);
  r = std::fma(-k, kTwoPi2, r);
  r = std::fma(-k, kTwoPi3, r);
  return r;
}

/// Solve Kepler's equation E − e sin E = M for the eccentric anomaly E, 0 ≤ e < 1.
/// M is reduced to [−π, π] and E returned in the same range (plus the removed multiple of 2π
/// is not added back). Method: safeguarded Newton on [0, π] after using the odd symmetry,
/// starting from E0 = M + 0.85 e (Danby), with the residual computed as
/// (1 − e)E + e(E − sin E) so that it has no cancellation near perihelion when e → 1.
/// Converges to within one ulp of the root or throws SolveError after 60 iterations.
inline double solve_kepler_equation(double M, double e) {
  if (!(e >= 0.0 && e < 1.0)) throw ArgumentError("e", "eccentricity must lie in [0, 1)");
  const double Mr = reduce_angle(M);
  const double sign = Mr < 0 ? -1.0 : 1.0;
  const double m = std::abs(Mr);
  if (m == 0.0) return 0.0;
  const double one_minus_e = 1.0 - e;
  double lo = 0.0, hi = std::numbers::pi;
  double E = std::min(m + 0.85 * e, std::numbers::pi);
  for (int it = 0; it < 60; ++it) {
    const double f = one_minus_e * E + e * internal::e_minus_sin(E) - m;
    if (f > 0) hi = std::min(hi, E); else lo = std::max(lo, E);
    const double s = std::sin(0.5 * E);
    const double fp = one_minus_e + 2.0 * e * s * s;  // 1 − e cos E without cancellation
    double En = E - f / fp;
    if (!(En > lo && En < hi)) En = 0.5 * (lo + hi);  // Newton left the bracket: bisect
    if (std::abs(En - E) <= kEps * std::abs(En) || En == E || hi - lo <= kEps * hi) {
      return sign * En;
    }
    E = En;
  }
  throw SolveError("Kepler's equation: no convergence", SolveReport{0.0, 60, false});
}

/// Exact (elliptic) Kepler motion with μ = 1 through Kepler's equation.
class KeplerOrbit {
 public:
  /// The orbit through the perihelion state of kepler_perihelion_state(e) at t = 0.
  static KeplerOrbit perihelion(double e) {
    KeplerOrbit o;
    if (!(e >= 0.0 && e < 1.0)) throw ArgumentError("e", "eccentricity must lie in [0, 1)");
    o.a_ = 1.0;
    o.e_ = e;
    o.n_ = 1.0;
    return o;
  }

  /// The orbit through (q0, p0) at t = 0. Throws ArgumentError if the motion is not a bound
  /// ellipse (energy ≥ 0, or zero angular momentum).
  static KeplerOrbit from_state(const Vec<double, 2>& q0, const Vec<double, 2>& p0) {
    const KeplerInvariants k = kepler_invariants(q0, p0);
    if (!(k.H < 0.0)) throw ArgumentError("initial state", "Kepler orbit is not bound (H >= 0)");
    if (k.L == 0.0) throw ArgumentError("initial state", "Kepler orbit is radial (L = 0)");
    KeplerOrbit o;
    o.a_ = -0.5 / k.H;
    o.n_ = 1.0 / (o.a_ * std::sqrt(o.a_));
    o.e_ = k.ecc;
    o.sense_ = k.L > 0 ? 1.0 : -1.0;
    const double r = q0.norm();
    if (o.e_ < 1e-13) {  // circular: measure anomalies from q0
      o.e_ = 0.0;
      o.omega_ = std::atan2(q0(1), q0(0));
      o.M0_ = 0.0;
    } else {
      o.omega_ = k.omega;
      const double ecosE = 1.0 - r / o.a_;
      const double esinE = q0.dot(p0) / std::sqrt(o.a_);
      const double E0 = std::atan2(esinE, ecosE);
      o.M0_ = E0 - o.e_ * std::sin(E0);
    }
    return o;
  }

  double semi_major_axis() const { return a_; }
  double eccentricity() const { return e_; }
  double period() const { return 2.0 * std::numbers::pi / n_; }

  /// State (q, p) at time t.
  State<2> at(double t) const {
    const double M = M0_ + n_ * t;
    const double E = solve_kepler_equation(M, e_);
    const double sE = std::sin(E), cE = std::cos(E), sh = std::sin(0.5 * E);
    const double one_minus_e = 1.0 - e_;
    const double b = std::sqrt(one_minus_e * (1.0 + e_));
    const double rho = one_minus_e + 2.0 * e_ * sh * sh;  // 1 − e cos E
    const double x = a_ * (one_minus_e - 2.0 * sh * sh);  // a (cos E − e)
    const double y = sense_ * a_ * b * sE;
    const double v = std::sqrt(1.0 / a_);
    const double vx = -v * sE / rho;
    const double vy = sense_ * v * b * cE / rho;
    State<2> s;
    if (omega_ == 0.0) {
      s.q = Vec<double, 2>(x, y);
      s.p = Vec<double, 2>(vx, vy);
    } else {
      const double c = std::cos(omega_), d = std::sin(omega_);
      s.q = Vec<double, 2>(c * x - d * y, d * x + c * y);
      s.p = Vec<double, 2>(c * vx - d * vy, d * vx + c * vy);
    }
    return s;
  }

 private:
  double a_ = 1, e_ = 0, n_ = 1, M0_ = 0, omega_ = 0, sense_ = 1;
};

}  // namespace vibook
