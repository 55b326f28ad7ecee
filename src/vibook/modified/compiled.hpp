/// \file compiled.hpp
/// \brief A GiNaC expression turned into a numerical function of chosen symbols, evaluated in
/// long double: the engine's modified equations and Hamiltonians integrated and measured
/// numerically (Vermeeren 2017, Theorem 16).
///
/// Chapter: \ref chapter-modified.
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

/// The modified equation truncated after h^k, ẍ = Σ_{m≤k} h^m f_m(x, ẋ) with f from
/// Engine::modified_equation(), compiled at a fixed step size h, and its classical RK4 step on
/// y = (x_1…x_N, ẋ_1…ẋ_N) in long double: how the checks integrate modified solutions.
class ModifiedFlow {
 public:
  ModifiedFlow(const JetSpace& J, const std::vector<std::vector<ex>>& f, int k, long double h);
  /// Advance y by dt (negative dt integrates backwards).
  void rk4_step(std::vector<long double>& y, long double dt) const;

 private:
  int n_;
  long double h_;
  std::vector<Compiled> F_;
  std::vector<long double> rhs(const std::vector<long double>& y) const;
};

}  // namespace vibook::modified
