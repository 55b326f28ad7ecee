// A stepper library of vibook's C ABI version 2 (vibook/verify/stepper_abi.h): one step from a
// given time, for a time-dependent system. `vibook verify --stepper-lib vibook_forced_steppers.so
// --stepper-arg METHOD --hamiltonian 'p^2/2 - cos(q) - q*cos(t)/2' --expected-order 2` measures
// it. The argument is METHOD or METHOD/SYSTEM; SYSTEM is forced-pendulum (the default),
// H = p²/2 − cos q − q cos(t)/2, or forced-oscillator, H = p²/2 + q²/2 − q cos t (one degree of
// freedom each; the field audit runs both).
//
// METHOD: sv        Störmer–Verlet with the time as a drifting variable: half a kick at t, a
//                   drift of h, half a kick at t + h; order 2, symplectic, symmetric.
//         sv_stale  deliberately wrong: the second half kick still at t (the time advanced by
//                   the drift with coefficient 0); Störmer–Verlet on an autonomous system,
//                   order 1 on this one.
#include <cmath>
#include <cstring>
#include <new>

#include "vibook/verify/stepper_abi.h"

namespace {

struct Stepper {
  bool stale = false;
  bool oscillator = false;
  double force(double q, double t) const {
    return oscillator ? -q + std::cos(t) : -std::sin(q) + 0.5 * std::cos(t);
  }
};

const char* last_message = nullptr;

}  // namespace

extern "C" {

int vibook_stepper_abi_version(void) { return 2; }

void* vibook_stepper_create(int dof, const char* arg) {
  if (dof != 1) {
    last_message = "the forced systems have one degree of freedom";
    return nullptr;
  }
  const char* slash = std::strchr(arg, '/');
  const std::size_t n = slash ? static_cast<std::size_t>(slash - arg) : std::strlen(arg);
  const bool stale = n == 8 && std::strncmp(arg, "sv_stale", n) == 0;
  if (!stale && !(n == 2 && std::strncmp(arg, "sv", n) == 0)) {
    last_message = "unknown method: sv or sv_stale (METHOD or METHOD/SYSTEM)";
    return nullptr;
  }
  const bool oscillator = slash && std::strcmp(slash + 1, "forced-oscillator") == 0;
  if (slash && !oscillator && std::strcmp(slash + 1, "forced-pendulum") != 0) {
    last_message = "unknown system: forced-pendulum or forced-oscillator";
    return nullptr;
  }
  return new (std::nothrow) Stepper{stale, oscillator};
}

int vibook_stepper_step_t(void* context, double t, double h, double* q, double* p) {
  const auto* s = static_cast<const Stepper*>(context);
  p[0] += 0.5 * h * s->force(q[0], t);
  q[0] += h * p[0];
  p[0] += 0.5 * h * s->force(q[0], s->stale ? t : t + h);
  return std::isfinite(q[0]) && std::isfinite(p[0]) ? 0 : 1;
}

void vibook_stepper_destroy(void* context) { delete static_cast<Stepper*>(context); }

const char* vibook_stepper_message(void* context) { return context ? nullptr : last_message; }

}  // extern "C"
