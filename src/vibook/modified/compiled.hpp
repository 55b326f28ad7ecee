/// \file compiled.hpp
/// \brief A GiNaC expression turned into a numerical function of chosen symbols, evaluated in
/// long double: the engine's modified equations and Hamiltonians integrated and measured
/// numerically (Vermeeren 2017, Theorem 16).
#pragma once

#include <functional>
#include <vector>

#include "vibook/modified/jets.hpp"

namespace vibook::modified {

class Compiled {
 public:
  /// `vars` fixes the order of the arguments; any other symbol in e is an error
  /// (std::invalid_argument naming it). Supported: +, ×, powers, sin, cos, exp, log.
  Compiled(const ex& e, const std::vector<GiNaC::symbol>& vars);
  long double operator()(const std::vector<long double>& args) const { return f_(args.data()); }

 private:
  std::function<long double(const long double*)> f_;
};

}  // namespace vibook::modified
