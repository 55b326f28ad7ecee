// Numerical evaluation of the engine's expressions (for Vermeeren 2017, Theorem 16).
#include "vibook/modified/compiled.hpp"

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
    std::vector<Fn> ops;
    for (std::size_t k = 0; k < e.nops(); ++k) ops.push_back(compile(e.op(k), vars));
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

Compiled::Compiled(const ex& e, const std::vector<GiNaC::symbol>& vars) : f_(compile(e, vars)) {}

}  // namespace vibook::modified
