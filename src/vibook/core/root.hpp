/// \file root.hpp
/// \brief A bracketed scalar root finder generic in its floating-point type: Anderson–Björck
/// (a regula falsi that halves the stale end's function value when one end is kept twice),
/// safeguarded by bisection whenever the bracket fails to halve in two iterations.
///
/// Why not Boost.Math's TOMS 748: it assigns integer literals to T (`fa = 0`), which is
/// ambiguous for libqd's dd_real (int converts to both double and const char*). One solver for
/// every precision keeps the iteration counts comparable between precisions.
#pragma once

#include <cmath>
#include <cstdint>
#include <utility>

namespace vibook {

/// Result: the bracket end with the smaller |f| and the number of f evaluations used.
template <class T>
struct RootResult {
  T x;
  T fx;
  int evaluations = 0;
  bool converged = false;
};

/// Finds a root of f in [a, b] given fa = f(a), fb = f(b) of opposite signs. Stops when
/// |b − a| <= tol · min(|a|, |b|) (relative, for a bracket away from 0), when |f| <= f_tol at a
/// new point (f_tol = 0: only an exact zero), or after max_evaluations (converged = false).
template <class T, class F>
RootResult<T> bracketed_root(F&& f, T a, T b, T fa, T fb, const T& tol, int max_evaluations,
                             const T& f_tol = T(0)) {
  using std::abs;
  const T zero(0), half(0.5);
  RootResult<T> r{a, fa, 0, false};
  T true_fa = fa, true_fb = fb;  // fa, fb below may be Anderson–Björck-scaled
  int side = 0;                  // which end was kept last: −1 a, +1 b
  T width = abs(b - a);
  int since_halving = 0;
  while (r.evaluations < max_evaluations) {
    if (abs(b - a) <= tol * std::min(abs(a), abs(b))) {
      r.converged = true;
      break;
    }
    T c;
    if (since_halving >= 2) {  // safeguard: bisection
      c = half * (a + b);
      since_halving = 0;
      width = abs(b - a);
    } else {
      c = b - fb * (b - a) / (fb - fa);
      if (!(c > std::min(a, b) && c < std::max(a, b))) c = half * (a + b);
    }
    const T fc = f(c);
    ++r.evaluations;
    if (abs(fc) <= f_tol || fc == zero) {
      a = b = c;
      true_fa = true_fb = fc;
      r.converged = true;
      break;
    }
    if ((fc < zero) == (fb < zero)) {  // root in [a, c]: b moves, a kept
      if (side == -1) {                // a kept twice: Anderson–Björck scaling of fa
        const T m = T(1) - fc / fb;
        fa = fa * (m > zero ? m : half);
      }
      b = c;
      fb = true_fb = fc;
      side = -1;
    } else {  // root in [c, b]: a moves, b kept
      if (side == +1) {
        const T m = T(1) - fc / fa;
        fb = fb * (m > zero ? m : half);
      }
      a = c;
      fa = true_fa = fc;
      side = +1;
    }
    if (abs(b - a) <= half * width) {
      width = abs(b - a);
      since_halving = 0;
    } else {
      ++since_halving;
    }
  }
  if (abs(true_fa) <= abs(true_fb)) {
    r.x = a;
    r.fx = true_fa;
  } else {
    r.x = b;
    r.fx = true_fb;
  }
  return r;
}

}  // namespace vibook
