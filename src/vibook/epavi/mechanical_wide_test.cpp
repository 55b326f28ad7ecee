// Doctests of epavi/mechanical.hpp in the wider types: the sign of the closed-form step's energy
// residuals in long double, double-double and quad, and MPFR beyond double's range (apart from
// mechanical_test.cpp so that neither unit takes a minute to compile).
#include <cmath>
#include <string>
#include <type_traits>

#include <doctest/doctest.h>

#include "vibook/core/precision.hpp"
#include "vibook/epavi/mechanical.hpp"
#include "vibook/kepler/kepler.hpp"

using namespace vibook;

namespace {

template <class T>
Vec<T, 2> widen(const Vec<double, 2>& v) {
  return Vec<T, 2>(T(v(0)), T(v(1)));
}

template <class T>
const char* label() {
  if constexpr (std::is_same_v<T, long double>)
    return "long double";
  else if constexpr (std::is_same_v<T, dd_real>)
    return "double-double";
  else
    return "quad";
}

}  // namespace

TEST_CASE_TEMPLATE("MechanicalEpAVI in the wider types: the discrete energy walks at random", T,
                   long double, dd_real, quad) {
  // e = 0.7, h0 = 1e-3, 1e5 steps (about 100 periods): no preferred sign of the per-step
  // changes, |z| < 4 for z = Σd/√(Σd²). These types are their own wide type: phase 2 runs
  // Newton on 2τ²g with its updates in double. Phase 2 once started double-double's Newton
  // from the closed-form zero of (16) in double-double (libqd's square root): the residuals
  // came out of one sign, z = 5.8 at 1e5 steps, 9.1 at 2e5.
  const double e = 0.7, h0 = 1e-3;
  const KeplerOrbit orbit = KeplerOrbit::perihelion(e);
  MechanicalEpAVI<Kepler, T> m{Kepler{}};
  auto s = m.start(T(0), widen<T>(orbit.at(0.0).q), T(h0), widen<T>(orbit.at(h0).q));
  double sum = 0, sum2 = 0;
  for (long k = 0; k < 100000; ++k) {
    const T E0 = s.E;
    m.step(s);
    const double d = to_double(T(s.E - E0));
    sum += d;
    sum2 += d * d;
  }
  const double z = sum / std::sqrt(sum2);
  MESSAGE(std::string(label<T>()), ", 1e5 steps: z = ", z, ", rms change ", std::sqrt(sum2 / 1e5),
          ", generic path ", m.fallbacks());
  CHECK(std::abs(z) < 4);
  CHECK(m.fallbacks() == 0);
}

TEST_CASE("MechanicalEpAVI in MPFR beyond double's range: every step by the generic path") {
  // The closed form takes its estimates (Newton matrices, bounds) in double, which needs the
  // unit round-off inside double's range. At 300 digits (u ≈ 1e-300) every step must go to
  // the generic path, and the discrete energy must hold to that precision, not to double's.
  const MpfrDigits digits(300);
  using T = mpfr_real;
  const double e = 0.7, h0 = 1e-3;
  const KeplerOrbit orbit = KeplerOrbit::perihelion(e);
  MechanicalEpAVI<Kepler, T> m{Kepler{}};
  auto s = m.start(T(0), widen<T>(orbit.at(0.0).q), T(h0), widen<T>(orbit.at(h0).q));
  const T E1 = s.E;
  for (int k = 0; k < 3; ++k) m.step(s);
  const double dE = std::abs(to_double(T(s.E - E1)));
  MESSAGE("MPFR 300 digits, 3 steps: generic path ", m.fallbacks(), ", |E_3 - E_1| = ", dE);
  CHECK(m.fallbacks() == 3);
  CHECK(dE <= 1e-250);
}
