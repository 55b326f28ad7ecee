// Numerical evaluation of the engine's expressions (for Vermeeren 2017, Theorem 16).
#include "vibook/modified/compiled.hpp"

#include "vibook/modified/canonical.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace vibook::modified {

namespace {
using Fn = std::function<long double(const long double*)>;

// A rational p/q as the long double nearest to it (p, q below 2^53, as in every coefficient
// the engine produces; larger ones lose their last bits, which is reported nowhere).
long double to_ld(const GiNaC::numeric& n) {
  if (n.is_rational()) {
    return static_cast<long double>(n.numer().to_double()) /
           static_cast<long double>(n.denom().to_double());
  }
  return static_cast<long double>(n.to_double());
}

Fn compile(const ex& e, const std::vector<GiNaC::symbol>& vars) {
  if (GiNaC::is_a<GiNaC::numeric>(e)) {
    const long double c = to_ld(GiNaC::ex_to<GiNaC::numeric>(e));
    return [c](const long double*) { return c; };
  }
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    for (std::size_t i = 0; i < vars.size(); ++i)
      if (e.is_equal(vars[i])) return [i](const long double* a) { return a[i]; };
    std::ostringstream os;
    os << e;
    throw std::invalid_argument("compiled expression: unbound symbol " + os.str());
  }
  if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
    // Canonical order (canonical.hpp): GiNaC's own order changes from run to run, and with
    // it the rounding of the sum.
    std::vector<Fn> ops;
    for (const ex& x : canonical_operands(e)) ops.push_back(compile(x, vars));
    if (GiNaC::is_a<GiNaC::add>(e))
      return [ops](const long double* a) {
        long double s = 0;
        for (const auto& f : ops) s += f(a);
        return s;
      };
    return [ops](const long double* a) {
      long double s = 1;
      for (const auto& f : ops) s *= f(a);
      return s;
    };
  }
  if (GiNaC::is_a<GiNaC::power>(e)) {
    const Fn base = compile(e.op(0), vars);
    const GiNaC::ex expo = e.op(1);
    if (GiNaC::is_a<GiNaC::numeric>(expo) && GiNaC::ex_to<GiNaC::numeric>(expo).is_integer()) {
      const long n = GiNaC::ex_to<GiNaC::numeric>(expo).to_long();
      return [base, n](const long double* a) {
        long double b = base(a), r = 1;
        for (long k = std::labs(n); k > 0; k >>= 1) {
          if (k & 1) r *= b;
          b *= b;
        }
        return n < 0 ? 1 / r : r;
      };
    }
    const Fn ex_fn = compile(expo, vars);
    return [base, ex_fn](const long double* a) { return std::pow(base(a), ex_fn(a)); };
  }
  if (GiNaC::is_a<GiNaC::function>(e) && e.nops() == 1) {
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    const Fn arg = compile(e.op(0), vars);
    if (name == "sin") return [arg](const long double* a) { return std::sin(arg(a)); };
    if (name == "cos") return [arg](const long double* a) { return std::cos(arg(a)); };
    if (name == "exp") return [arg](const long double* a) { return std::exp(arg(a)); };
    if (name == "log") return [arg](const long double* a) { return std::log(arg(a)); };
  }
  std::ostringstream os;
  os << e;
  throw std::invalid_argument("compiled expression: unsupported " + os.str());
}
}  // namespace

// Expanded first: the engine may return the same value in differently grouped forms from one
// run to the next (its intermediate maps are ordered by GiNaC's run-dependent hashes), and the
// expanded sum of monomials, in canonical order, is one form only.
Compiled::Compiled(const ex& e, const std::vector<GiNaC::symbol>& vars)
    : f_(compile(GiNaC::expand(e), vars)) {}

ModifiedFlow::ModifiedFlow(const JetSpace& J, const std::vector<std::vector<ex>>& f, int k,
                           long double h)
    : n_(J.dofs()), h_(h) {
  std::vector<GiNaC::symbol> vars;
  for (int i = 0; i < n_; ++i) vars.push_back(J.x(0, i));
  for (int i = 0; i < n_; ++i) vars.push_back(J.x(1, i));
  vars.push_back(J.h());
  for (int i = 0; i < n_; ++i) {
    ex acc = 0;
    for (int m = 0; m <= k; ++m) acc += GiNaC::pow(J.h(), m) * f.at(m).at(i);
    F_.emplace_back(acc, vars);
  }
}

std::vector<long double> ModifiedFlow::rhs(const std::vector<long double>& y) const {
  std::vector<long double> a(y.begin(), y.end());
  a.push_back(h_);
  std::vector<long double> d(2 * n_);
  for (int i = 0; i < n_; ++i) {
    d[i] = y[n_ + i];
    d[n_ + i] = F_[i](a);
  }
  return d;
}

void ModifiedFlow::rk4_step(std::vector<long double>& y, long double dt) const {
  auto add = [](const std::vector<long double>& a, const std::vector<long double>& b,
                long double c) {
    std::vector<long double> r(a);
    for (std::size_t i = 0; i < r.size(); ++i) r[i] += c * b[i];
    return r;
  };
  const auto k1 = rhs(y), k2 = rhs(add(y, k1, dt / 2)), k3 = rhs(add(y, k2, dt / 2)),
             k4 = rhs(add(y, k3, dt));
  for (std::size_t i = 0; i < y.size(); ++i)
    y[i] += dt / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
}

}  // namespace vibook::modified
