// Boost.Odeint's symplectic steppers behind vibook's black-box stepper ABI
// (vibook/verify/stepper_abi.h), for `vibook verify --stepper-lib` in CI and in the book.
//
// --stepper-arg 'METHOD/SYSTEM':
//   METHOD  symplectic_euler       odeint::symplectic_euler (documented order 1)
//           velocity_verlet        odeint::velocity_verlet, reset before every step (order 2)
//           mclachlan4             odeint::symplectic_rkn_sb3a_mclachlan (documented order 4)
//           mclachlan4_m4          odeint::symplectic_rkn_sb3a_m4_mclachlan (documented order 4)
//   deliberately wrong, for the tests that must fail:
//           explicit_euler         q1 = q0 + h p0, p1 = p0 - h grad V(q0): not symplectic
//           velocity_verlet_cached odeint::velocity_verlet without reset: it reuses the
//                                  acceleration of the last state it returned, so the "map"
//                                  depends on the previous call, not only on (q, p)
//           rk4                    odeint::runge_kutta4 on (q, p): order 4, not symplectic
//           rk78                   odeint::runge_kutta_fehlberg78 on (q, p): order 8, not
//                                  symplectic; its defect at h = 0.05 is about 1e-12, which a
//                                  check at one small step size does not see
//   SYSTEM  pendulum (1 dof, V = -cos q), kepler (2 dof, V = -1/|q|), henon-heiles (2 dof)
#include <boost/numeric/odeint/stepper/runge_kutta4.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>
#include <boost/numeric/odeint/stepper/symplectic_euler.hpp>
#include <boost/numeric/odeint/stepper/symplectic_rkn_sb3a_m4_mclachlan.hpp>
#include <boost/numeric/odeint/stepper/symplectic_rkn_sb3a_mclachlan.hpp>
#include <boost/numeric/odeint/stepper/velocity_verlet.hpp>

#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "vibook/verify/stepper_abi.h"

namespace {

namespace odeint = boost::numeric::odeint;
using State = std::vector<double>;

// −∇V(q) for the named system.
using Force = std::function<void(const State& q, State& f)>;

bool make_force(const std::string& system, int dof, Force& f) {
  if (system == "pendulum" && dof == 1) {
    f = [](const State& q, State& out) { out[0] = -std::sin(q[0]); };
    return true;
  }
  if (system == "kepler" && dof == 2) {
    f = [](const State& q, State& out) {
      const double r2 = q[0] * q[0] + q[1] * q[1];
      const double ir3 = 1.0 / (r2 * std::sqrt(r2));
      out[0] = -q[0] * ir3;
      out[1] = -q[1] * ir3;
    };
    return true;
  }
  if (system == "henon-heiles" && dof == 2) {
    f = [](const State& q, State& out) {
      out[0] = -q[0] - 2 * q[0] * q[1];
      out[1] = -q[1] - q[0] * q[0] + q[1] * q[1];
    };
    return true;
  }
  return false;
}

struct Context {
  std::string method;
  Force force;
  odeint::symplectic_euler<State> euler;
  odeint::symplectic_rkn_sb3a_mclachlan<State> mclachlan;
  odeint::symplectic_rkn_sb3a_m4_mclachlan<State> mclachlan_m4;
  odeint::velocity_verlet<State> verlet;
  odeint::runge_kutta4<State> rk4;
  odeint::runge_kutta_fehlberg78<State> rk78;
  State f;
};

std::string g_message;

template <class Stepper>
void odeint_step(Stepper& s, const Force& force, double h, State& q, State& p) {
  auto coor = [](const State& pp, State& dqdt) { dqdt = pp; };
  auto momentum = [&force](const State& qq, State& dpdt) { force(qq, dpdt); };
  s.do_step(std::make_pair(coor, momentum), std::make_pair(std::ref(q), std::ref(p)), 0.0, h);
}

}  // namespace

extern "C" {

// Version 1: the systems here are autonomous, and version 2's time argument is not needed.
int vibook_stepper_abi_version(void) { return 1; }

void* vibook_stepper_create(int dof, const char* arg) {
  const std::string a = arg ? arg : "";
  const auto slash = a.find('/');
  if (slash == std::string::npos) {
    g_message = "--stepper-arg must be METHOD/SYSTEM, e.g. mclachlan4/kepler";
    return nullptr;
  }
  auto* c = new Context;
  c->method = a.substr(0, slash);
  const std::string system = a.substr(slash + 1);
  if (!make_force(system, dof, c->force)) {
    g_message = "no system '" + system + "' with " + std::to_string(dof) +
                " degrees of freedom (pendulum 1, kepler 2, henon-heiles 2)";
    delete c;
    return nullptr;
  }
  static const char* methods[] = {
      "symplectic_euler", "velocity_verlet",        "mclachlan4", "mclachlan4_m4",
      "explicit_euler",   "velocity_verlet_cached", "rk4",        "rk78"};
  bool known = false;
  for (const char* m : methods) known = known || c->method == m;
  if (!known) {
    g_message = "unknown method '" + c->method + "'";
    delete c;
    return nullptr;
  }
  c->f.resize(static_cast<std::size_t>(dof));
  return c;
}

int vibook_stepper_step(void* context, double h, double* q, double* p) {
  auto* c = static_cast<Context*>(context);
  const std::size_t n = c->f.size();
  State Q(q, q + n), P(p, p + n);
  if (c->method == "symplectic_euler") {
    odeint_step(c->euler, c->force, h, Q, P);
  } else if (c->method == "mclachlan4") {
    odeint_step(c->mclachlan, c->force, h, Q, P);
  } else if (c->method == "mclachlan4_m4") {
    odeint_step(c->mclachlan_m4, c->force, h, Q, P);
  } else if (c->method == "velocity_verlet" || c->method == "velocity_verlet_cached") {
    if (c->method == "velocity_verlet") c->verlet.reset();
    auto accel = [c](const State& x, const State& /*v*/, State& a, double /*t*/) {
      c->force(x, a);
    };
    std::pair<State, State> xv{Q, P};
    c->verlet.do_step(accel, xv, 0.0, h);
    Q = xv.first;
    P = xv.second;
  } else if (c->method == "rk4" || c->method == "rk78") {
    // z = (q, p), z' = (p, -grad V(q))
    const std::size_t d = n;
    auto rhs = [c, d](const State& z, State& dz, double /*t*/) {
      State q(z.begin(), z.begin() + static_cast<long>(d)), f(d);
      c->force(q, f);
      for (std::size_t i = 0; i < d; ++i) {
        dz[i] = z[d + i];
        dz[d + i] = f[i];
      }
    };
    State z(Q);
    z.insert(z.end(), P.begin(), P.end());
    if (c->method == "rk4")
      c->rk4.do_step(rhs, z, 0.0, h);
    else
      c->rk78.do_step(rhs, z, 0.0, h);
    Q.assign(z.begin(), z.begin() + static_cast<long>(d));
    P.assign(z.begin() + static_cast<long>(d), z.end());
  } else {  // explicit_euler
    c->force(Q, c->f);
    for (std::size_t i = 0; i < n; ++i) {
      const double q0 = Q[i];
      Q[i] = q0 + h * P[i];
      P[i] = P[i] + h * c->f[i];
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    q[i] = Q[i];
    p[i] = P[i];
  }
  return 0;
}

void vibook_stepper_destroy(void* context) { delete static_cast<Context*>(context); }

const char* vibook_stepper_message(void* context) { return context ? nullptr : g_message.c_str(); }

}  // extern "C"
