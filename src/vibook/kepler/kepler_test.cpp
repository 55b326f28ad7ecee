// Doctests of kepler/: the exact solution against a 50-digit reference, and the invariants.
#include <cmath>
#include <numbers>
#include <random>

#include <doctest/doctest.h>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include "vibook/core/autodiff.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/problems/problems.hpp"

using namespace vibook;
using Big = boost::multiprecision::cpp_bin_float_50;

namespace {

// Reference perihelion orbit (a = 1, μ = 1) at time t, in 50 significant digits: Kepler's
// equation by Newton's method in Big, started from the double solution.
std::array<Big, 4> reference_state(double t, double e) {
  const Big pi = boost::math::constants::pi<Big>();
  const Big E_ = Big(e);
  Big M = fmod(Big(t), 2 * pi);
  if (M > pi) M -= 2 * pi;
  if (M < -pi) M += 2 * pi;
  Big E = Big(solve_kepler_equation(t, e));
  for (int i = 0; i < 8; ++i) E -= (E - E_ * sin(E) - M) / (1 - E_ * cos(E));
  const Big b = sqrt(1 - E_ * E_), rho = 1 - E_ * cos(E);
  return {cos(E) - E_, b * sin(E), -sin(E) / rho, b * cos(E) / rho};
}

}  // namespace

TEST_CASE("Kepler exact solution: within one ulp for 0 <= e <= 0.99 and |t| up to 1e12") {
  std::mt19937_64 rng(20261121);
  std::uniform_real_distribution<double> ecc(0.0, 0.99), logt(-3.0, 12.0);
  double worst_q = 0, worst_p = 0;
  for (int i = 0; i < 4000; ++i) {
    const double e = i < 200 ? 0.99 : (i < 400 ? 0.0 : ecc(rng));
    const double t = (i % 2 ? 1.0 : -1.0) * std::pow(10.0, logt(rng));
    const State<2> s = KeplerOrbit::perihelion(e).at(t);
    const auto ref = reference_state(t, e);
    const double r = std::hypot(double(ref[0]), double(ref[1]));
    const double v = std::hypot(double(ref[2]), double(ref[3]));
    // Error in ulps of the size of the vector (position: r, momentum: |p|).
    worst_q = std::max(worst_q,
                       double(abs(Big(s.q(0)) - ref[0]) + abs(Big(s.q(1)) - ref[1])) / (kEps * r));
    worst_p = std::max(worst_p,
                       double(abs(Big(s.p(0)) - ref[2]) + abs(Big(s.p(1)) - ref[3])) / (kEps * v));
  }
  MESSAGE("worst position error ", worst_q, " ulp, momentum ", worst_p, " ulp");
  CHECK(worst_q <= 1.0);
  CHECK(worst_p <= 1.0);
}

TEST_CASE("Kepler exact solution conserves H, L and the LRL vector over time and closes after 2π") {
  const double e = 0.7;
  const auto orbit = KeplerOrbit::perihelion(e);
  const auto k0 = kepler_invariants(orbit.at(0).q, orbit.at(0).p);
  // H = ½|p|² − 1/r is a difference of terms of size 1/r = 1/(1 − e): round-off is relative
  // to that size, not to |H|.
  const double term = 1.0 / (1.0 - e);
  CHECK(std::abs(k0.H + 0.5) <= 4 * kEps * term);
  CHECK(std::abs(k0.ecc - e) <= 4 * kEps);
  CHECK(std::abs(k0.omega) <= 4 * kEps);
  for (double t : {0.3, 1.0, 2.5, 100.0, 12345.6}) {
    const State<2> s = orbit.at(t);
    const auto k = kepler_invariants(s.q, s.p);
    CHECK(std::abs(k.H - k0.H) <= 16 * kEps * term);
    CHECK(std::abs(k.L - k0.L) <= 16 * kEps);
    CHECK(std::abs(k.ecc - k0.ecc) <= 16 * kEps);
  }
  const State<2> s = orbit.at(2 * std::numbers::pi);
  CHECK((s.q - orbit.at(0).q).norm() <= 8 * kEps);
}

TEST_CASE("KeplerOrbit::from_state reproduces the orbit through any bound state") {
  const auto per = KeplerOrbit::perihelion(0.6);
  const State<2> s0 = per.at(1.234);
  const auto orbit = KeplerOrbit::from_state(s0.q, s0.p);
  CHECK(std::abs(orbit.period() - 2 * std::numbers::pi) <= 64 * kEps);
  for (double t : {0.0, 0.5, 3.0, 10.0}) {
    const State<2> a = orbit.at(t), b = per.at(1.234 + t);
    CHECK((a.q - b.q).norm() <= 1e-13);
    CHECK((a.p - b.p).norm() <= 1e-13);
  }
  // Clockwise motion: mirror image.
  const auto cw =
      KeplerOrbit::from_state(Vec<double, 2>(s0.q(0), -s0.q(1)), Vec<double, 2>(s0.p(0), -s0.p(1)));
  const State<2> m = cw.at(2.0), b = per.at(3.234);
  CHECK(std::abs(m.q(1) + b.q(1)) <= 1e-13);
  CHECK_THROWS_AS(KeplerOrbit::from_state(Vec<double, 2>(1, 0), Vec<double, 2>(0, 2)),
                  ArgumentError);
  CHECK_THROWS_AS(KeplerOrbit::perihelion(1.0), ArgumentError);
}

TEST_CASE("problem gradients agree with AutoDiff of their potentials") {
  const Vec<double, 2> q(0.4, -0.9);
  const Vec<double, 2> g = ad::gradient<2>([](const auto& x) { return Kepler{}.potential(x); }, q);
  CHECK((g - Kepler{}.gradient(q)).norm() <= 4 * kEps * g.norm());
  const Vec<double, 1> x(0.7);
  const auto gp = ad::gradient<1>([](const auto& y) { return Pendulum{}.potential(y); }, x);
  CHECK(std::abs(gp(0) - Pendulum{}.gradient(x)(0)) <= 2 * kEps);
  const auto gh =
      ad::gradient<1>([](const auto& y) { return HarmonicOscillator{}.potential(y); }, x);
  CHECK(std::abs(gh(0) - HarmonicOscillator{}.gradient(x)(0)) <= 2 * kEps);
}

TEST_CASE("Kepler's written-out Hessian agrees with AutoDiff of its gradient") {
  // The closed-form EpAVI uses Kepler::hessian instead of AutoDiff when a problem has one.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int n = 0; n < 200; ++n) {
    const Vec<double, 2> q(u(rng), u(rng));
    if (q.norm() < 0.05) continue;
    using D = ad::Dual<2, double>;
    const Vec<D, 2> y(D(q(0), 2, 0), D(q(1), 2, 1));
    const Vec<D, 2> g = Kepler{}.gradient(y);
    Eigen::Matrix2d H;
    for (int i = 0; i < 2; ++i) H.row(i) = g(i).derivatives().transpose();
    const Eigen::Matrix2d Hk = Kepler{}.hessian(q);
    INFO("q = (" << q(0) << ", " << q(1) << ")");
    CHECK((H - Hk).lpNorm<Eigen::Infinity>() <= 16 * kEps * H.lpNorm<Eigen::Infinity>());
    CHECK(Hk(0, 1) == Hk(1, 0));
  }
}
