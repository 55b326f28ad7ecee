/// \file series.hpp
/// \brief Truncated power series in the step size h with GiNaC coefficients, and the
/// evaluation of an arbitrary expression on series arguments. This is how the engine expands
/// a discrete Lagrangian along a smooth curve (Vermeeren 2017, (13)) without ever forming a
/// term beyond the requested order.
///
/// Chapter: \ref chapter-modified.
#pragma once

#include <limits>
#include <map>
#include <string>
#include <vector>

#include "vibook/modified/jets.hpp"

namespace vibook::modified {

/// Σ_k c[k] h^{low+k} + O(h^prec): a truncated Laurent series (low < 0 arises inside a
/// difference quotient such as h·(x1 − x0)/h²). Entries beyond c's size are zero; prec may
/// be Series::exact (no truncation). Coefficients are kept expanded.
struct Series {
  static constexpr int exact = std::numeric_limits<int>::max() / 4;
  std::vector<ex> c;
  int low = 0;
  int prec = exact;

  Series() = default;
  /// A constant (exact).
  static Series constant(const ex& value);
  /// The series of h itself (exact).
  static Series h();
  /// Coefficient of h^k (0 outside the stored terms); throws if k ≥ prec.
  ex coeff(int k) const;
  /// The power of the first coefficient that is not (syntactically) zero; prec if none.
  int valuation() const;
  /// Drop everything from h^p on.
  Series truncated(int p) const;
};

Series operator+(const Series& a, const Series& b);
Series operator-(const Series& a, const Series& b);
Series operator-(const Series& a);
Series operator*(const Series& a, const Series& b);
/// Division (the divisor's leading coefficient is tested for zero with vanishes()).
Series operator/(const Series& a, const Series& b);
/// a^r for a numeric exponent r (integer or rational).
Series pow(const Series& a, const GiNaC::numeric& r);
/// x(t + s·h) = Σ (s h)^k / k! x^{(k)}, to precision p, for degree of freedom i.
Series shifted_jet(const JetSpace& J, int i, const ex& s, int p);

/// True if e is zero: its expansion, or failing that its normal form, is zero.
bool vanishes(const ex& e);
/// Replace every floating-point number in e by the rational it exactly represents
/// (C++ literals such as 0.5 in the integrators' code are binary fractions). With `inexact`,
/// each number whose exact value needs a denominator above 2^32 (0.1, 1/6.0: almost surely a
/// decimal or a quotient that binary64 only approximates) is also described there, once.
ex exact_rationals(const ex& e, std::vector<std::string>* inexact = nullptr);

/// Evaluate e with the symbols in `subs` replaced by series (everything else is constant),
/// truncated at `cap` terms. Abstract functions are expanded by their multivariate Taylor
/// series around the arguments' constant terms, which must be the jet point x.
class SeriesEvaluator {
 public:
  SeriesEvaluator(const JetSpace& J, std::map<ex, Series, GiNaC::ex_is_less> subs, int cap);
  Series operator()(const ex& e);

 private:
  const JetSpace& J_;
  std::map<ex, Series, GiNaC::ex_is_less> subs_;
  int cap_;
  std::map<ex, Series, GiNaC::ex_is_less> memo_;
  bool symbol_keys_ = true;  // every key of subs_ a symbol: depends() in one walk
  bool depends(const ex& e) const;
  Series eval(const ex& e);
  Series unary(const ex& e, const Series& arg);
  Series abstract(int family, const std::vector<ex>& args, const std::vector<int>& index);
};

}  // namespace vibook::modified
