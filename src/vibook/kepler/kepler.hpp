/// \file kepler.hpp
/// \brief The planar Kepler problem with μ = 1: the problem, its invariants (energy, angular
/// momentum, Laplace–Runge–Lenz vector), and its exact solution through Kepler's equation.
///
/// Chapter: \ref chapter-kepler-lrl.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
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
    return -constant<S>(1) / sqrt(squared_norm(q));
  }
  template <class S>
  Vec<S, 2> gradient(const Vec<S, 2>& q) const {
    using std::sqrt;
    const S r2 = q.squaredNorm();
    const S inv_r3 = 1.0 / (r2 * sqrt(r2));
    return (q * inv_r3).eval();
  }
  /// ∇²V = I/r³ − 3 q qᵀ/r⁵, written out: the closed-form EpAVI (epavi/mechanical.hpp) uses a
  /// problem's own Hessian when it has one, and AutoDiff of the gradient otherwise.
  template <class S>
  Eigen::Matrix<S, 2, 2> hessian(const Vec<S, 2>& q) const {
    using std::sqrt;
    const S r2 = q.squaredNorm();
    const S inv_r3 = 1.0 / (r2 * sqrt(r2));
    const S c = S(3) * inv_r3 / r2;
    Eigen::Matrix<S, 2, 2> H;
    H(0, 0) = inv_r3 - c * q(0) * q(0);
    H(1, 1) = inv_r3 - c * q(1) * q(1);
    H(0, 1) = H(1, 0) = -c * q(0) * q(1);
    return H;
  }
};

/// Invariants of the Kepler flow at one state.
struct KeplerInvariants {
  double H = 0;      ///< energy ½|p|² − 1/|q|
  double L = 0;      ///< angular momentum q1 p2 − q2 p1
  Vec<double, 2> A;  ///< Laplace–Runge–Lenz vector p × L e3 − q/|q|
  double ecc = 0;    ///< eccentricity |A|
  double omega = 0;  ///< perihelion angle atan2(A2, A1), in (−π, π]
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
inline long double e_minus_sin(long double E) {
  if (std::abs(E) >= 1.0L) return E - std::sin(E);
  // E³/3! − E⁵/5! + ... ; 14 terms reach long-double round-off for |E| < 1.
  const long double E2 = E * E;
  long double term = E * E2 / 6.0L, sum = 0.0L;
  for (int k = 1; k <= 14; ++k) {
    sum += term;
    term *= -E2 / ((2.0L * k + 2.0L) * (2.0L * k + 3.0L));
  }
  return sum;
}

/// Reduce an angle to [−π, π]: Cody–Waite with a three-part 2π in long double and FMA.
inline long double reduce_angle_ld(long double x) {
  constexpr long double P1 = 0xc90fdaa22168c235p-61L;    // 2π rounded to 64 bits
  constexpr long double P2 = -0xece675d1fc8f8cbbp-127L;  // 2π − P1, rounded
  constexpr long double P3 = -0xb7ed8fbbacc19c60p-192L;  // the next part
  const long double k = std::nearbyint(x / P1);
  long double r = std::fma(-k, P1, x);
  r = std::fma(-k, P2, r);
  return std::fma(-k, P3, r);
}

/// Kepler's equation E − e sin E = M in long double (see solve_kepler_equation).
inline long double solve_kepler_ld(long double M, long double e) {
  const long double Mr = reduce_angle_ld(M);
  const long double sign = Mr < 0 ? -1.0L : 1.0L;
  const long double m = std::abs(Mr);
  if (m == 0.0L) return 0.0L;
  constexpr long double pi = 3.14159265358979323846264338327950288L;
  const long double one_minus_e = 1.0L - e;
  const long double eps = std::numeric_limits<long double>::epsilon();
  long double lo = 0.0L, hi = pi;
  long double E = std::min(m + 0.85L * e, pi);
  for (int it = 0; it < 80; ++it) {
    // Residual (1 − e)E + e(E − sin E) − m and derivative 1 − e cos E = (1 − e) + 2e sin²(E/2),
    // both free of cancellation near perihelion when e → 1.
    const long double f = one_minus_e * E + e * e_minus_sin(E) - m;
    if (f > 0)
      hi = std::min(hi, E);
    else
      lo = std::max(lo, E);
    const long double sh = std::sin(0.5L * E);
    const long double fp = one_minus_e + 2.0L * e * sh * sh;
    long double En = E - f / fp;
    if (!(En > lo && En < hi)) En = 0.5L * (lo + hi);  // Newton left the bracket: bisect
    if (std::abs(En - E) <= 2 * eps * std::abs(En) || hi - lo <= 2 * eps * hi) return sign * En;
    E = En;
  }
  throw SolveError("Kepler's equation: no convergence", SolveReport{0.0, 80, false});
}
}  // namespace internal

/// Reduce an angle to [−π, π] (three-part 2π in long double; about one ulp for |x| < 2^50).
inline double reduce_angle(double x) { return double(internal::reduce_angle_ld(x)); }

/// Solve Kepler's equation E − e sin E = M for the eccentric anomaly E ∈ [−π, π], 0 ≤ e < 1.
/// M is reduced to [−π, π] first (the removed multiple of 2π is not added back). Method:
/// safeguarded Newton on [0, π] after using the odd symmetry, from E0 = M + 0.85e (Danby),
/// in long double (64-bit mantissa) so that the result, rounded once to double, is within
/// about one ulp. Throws SolveError if 80 iterations do not converge (never seen).
inline double solve_kepler_equation(double M, double e) {
  if (!(e >= 0.0 && e < 1.0)) throw ArgumentError("e", "eccentricity must lie in [0, 1)");
  return double(internal::solve_kepler_ld(M, e));
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

  /// State (q, p) at time t. Computed in long double and rounded once: within a few ulps
  /// of the exact state for 0 ≤ e ≤ 0.99 and any t (measured in the doctests).
  State<2> at(double t) const {
    using LD = long double;
    const LD M = LD(M0_) + LD(n_) * LD(t);
    const LD e = e_, a = a_, sense = sense_;
    const LD E = internal::solve_kepler_ld(M, e);
    const LD sE = std::sin(E), cE = std::cos(E), sh = std::sin(0.5L * E);
    const LD one_minus_e = 1.0L - e;
    const LD b = std::sqrt(one_minus_e * (1.0L + e));
    const LD rho = one_minus_e + 2.0L * e * sh * sh;  // 1 − e cos E
    const LD x = a * (one_minus_e - 2.0L * sh * sh);  // a (cos E − e)
    const LD y = sense * a * b * sE;
    const LD v = std::sqrt(1.0L / a);
    const LD vx = -v * sE / rho;
    const LD vy = sense * v * b * cE / rho;
    State<2> s;
    if (omega_ == 0.0) {
      s.q = Vec<double, 2>(double(x), double(y));
      s.p = Vec<double, 2>(double(vx), double(vy));
    } else {
      const LD c = std::cos(LD(omega_)), d = std::sin(LD(omega_));
      s.q = Vec<double, 2>(double(c * x - d * y), double(d * x + c * y));
      s.p = Vec<double, 2>(double(c * vx - d * vy), double(d * vx + c * vy));
    }
    return s;
  }

 private:
  double a_ = 1, e_ = 0, n_ = 1, M0_ = 0, omega_ = 0, sense_ = 1;
};

}  // namespace vibook
