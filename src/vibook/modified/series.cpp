// Truncated power series in h with GiNaC coefficients: the arithmetic behind the expansion
// (13) of Vermeeren 2017 and every later step of the modified-equation engine.
#include "vibook/modified/series.hpp"

#include "vibook/modified/ginac_eigen.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace vibook::modified {

using GiNaC::numeric;

namespace {

// The truncation used where an exact series would otherwise be infinite (1/(1 + h), …).
thread_local int g_cap = 16;

int clamp_prec(long long p) { return static_cast<int>(std::min<long long>(p, Series::exact)); }

// Drop stored terms at or beyond prec, and zero terms at the low end.
Series& normalise(Series& s) {
  const long long len = static_cast<long long>(s.prec) - s.low;
  if (len < static_cast<long long>(s.c.size())) s.c.resize(std::max<long long>(len, 0));
  std::size_t z = 0;
  while (z < s.c.size() && s.c[z].is_zero()) ++z;
  if (z > 0) {
    s.c.erase(s.c.begin(), s.c.begin() + static_cast<std::ptrdiff_t>(z));
    s.low += static_cast<int>(z);
  }
  if (s.c.empty()) s.low = 0;
  return s;
}

// Σ_m d(m)/m! δ^m with δ = a − a0: the Taylor series of a function about the constant term.
Series compose(const Series& a, const std::function<ex(int)>& d) {
  if (a.valuation() < 0) throw std::domain_error("function of a series with negative powers of h");
  Series delta = a;
  if (delta.low == 0 && !delta.c.empty()) delta.c[0] = 0;
  normalise(delta);
  if (delta.c.empty() && a.prec == Series::exact) return Series::constant(d(0));
  const int top = std::min(a.prec, g_cap);
  Series out = Series::constant(d(0)).truncated(top);
  Series power = Series::constant(1);
  numeric factorial = 1;
  for (int m = 1; m < top; ++m) {
    power = (power * delta).truncated(top);
    factorial *= m;
    if (power.valuation() >= top) break;
    out = out + Series::constant(d(m) / factorial) * power;
  }
  return out.truncated(top);
}

}  // namespace

Series Series::constant(const ex& value) {
  Series s;
  s.c = {value};
  return normalise(s);
}

Series Series::h() {
  Series s;
  s.c = {ex(1)};
  s.low = 1;
  return s;
}

ex Series::coeff(int k) const {
  if (k >= prec)
    throw std::logic_error("series coefficient h^" + std::to_string(k) + " beyond O(h^" +
                           std::to_string(prec) + ")");
  const long long idx = static_cast<long long>(k) - low;
  return idx >= 0 && idx < static_cast<long long>(c.size()) ? c[idx] : ex(0);
}

int Series::valuation() const {
  for (std::size_t k = 0; k < c.size(); ++k)
    if (!c[k].is_zero() && low + static_cast<int>(k) < prec) return low + static_cast<int>(k);
  return prec;
}

Series Series::truncated(int p) const {
  Series s = *this;
  s.prec = std::min(prec, p);
  return normalise(s);
}

Series operator+(const Series& a, const Series& b) {
  Series s;
  s.prec = std::min(a.prec, b.prec);
  if (a.c.empty()) {
    s.c = b.c;
    s.low = b.low;
  } else if (b.c.empty()) {
    s.c = a.c;
    s.low = a.low;
  } else {
    s.low = std::min(a.low, b.low);
    const int hi =
        std::max(a.low + static_cast<int>(a.c.size()), b.low + static_cast<int>(b.c.size()));
    const int top = std::min(hi, s.prec);
    for (int k = s.low; k < top; ++k) {
      const long long ia = static_cast<long long>(k) - a.low,
                      ib = static_cast<long long>(k) - b.low;
      ex x = 0;
      if (ia >= 0 && ia < static_cast<long long>(a.c.size())) x += a.c[ia];
      if (ib >= 0 && ib < static_cast<long long>(b.c.size())) x += b.c[ib];
      s.c.push_back(x);
    }
  }
  return normalise(s);
}

Series operator-(const Series& a) {
  Series s = a;
  for (auto& x : s.c) x = -x;
  return s;
}

Series operator-(const Series& a, const Series& b) { return a + (-b); }

Series operator*(const Series& a, const Series& b) {
  Series s;
  if (a.c.empty() || b.c.empty()) {
    const int va = a.valuation(), vb = b.valuation();
    s.prec = clamp_prec(
        std::min(static_cast<long long>(a.prec) + vb, static_cast<long long>(b.prec) + va));
    return s;
  }
  const int va = a.low, vb = b.low;  // normalised: the first stored term is not zero
  s.prec = clamp_prec(
      std::min(static_cast<long long>(a.prec) + vb, static_cast<long long>(b.prec) + va));
  s.low = va + vb;
  const long long len = std::min<long long>(static_cast<long long>(a.c.size() + b.c.size()) - 1,
                                            static_cast<long long>(s.prec) - s.low);
  for (long long k = 0; k < len; ++k) {
    ex acc = 0;
    for (long long i = 0; i <= k && i < static_cast<long long>(a.c.size()); ++i) {
      const long long j = k - i;
      if (j >= static_cast<long long>(b.c.size()) || a.c[i].is_zero() || b.c[j].is_zero()) continue;
      acc += GiNaC::expand(a.c[i] * b.c[j]);
    }
    s.c.push_back(acc);
  }
  return normalise(s);
}

Series operator/(const Series& a, const Series& b) {
  Series den = b;
  // The leading coefficient must really be non-zero (not only syntactically).
  while (!den.c.empty() && vanishes(den.c.front())) {
    den.c.erase(den.c.begin());
    ++den.low;
  }
  if (den.c.empty() || den.low >= den.prec) throw std::domain_error("series division by O(h^p)");
  const int v = den.low;
  den.low = 0;
  if (den.prec != Series::exact) den.prec -= v;
  const ex d0 = den.c.front();
  const Series inv = compose(den, [&](int m) {
    // m-th derivative of 1/y at d0: (−1)^m m! / d0^{m+1}
    numeric f = 1;
    for (int j = 2; j <= m; ++j) f *= j;
    return ex((m % 2 ? -1 : 1) * f) * GiNaC::pow(d0, -(m + 1));
  });
  Series out = a * inv;
  out.low -= v;
  if (out.prec != Series::exact) out.prec -= v;
  return normalise(out);
}

Series pow(const Series& a, const numeric& r) {
  if (r.is_integer()) {
    const long n = r.to_long();
    if (n < 0) return Series::constant(1) / pow(a, numeric(-n));
    // a = a0 + δ with a0 ≠ 0: the binomial sum Σ_m C(n, m) a0^{n−m} δ^m multiplies the large
    // expanded a0^{n−m} only by the short powers of δ, where squaring multiplies the large
    // coefficients with each other ((x + y + z)^32 in 3-D: 55 s to h^2 by squaring).
    if (n >= 3 && a.low == 0 && !a.c.empty() && !a.c[0].is_zero() && a.prec <= g_cap) {
      const ex a0 = a.c[0];
      return compose(a, [&](int m) {
        if (m > n) return ex(0);
        numeric f = 1;
        for (int j = 0; j < m; ++j) f *= n - j;
        return f * GiNaC::pow(a0, n - m);
      });
    }
    Series out = Series::constant(1), base = a;
    for (long k = n; k > 0; k >>= 1) {
      if (k & 1) out = out * base;
      if (k > 1) base = base * base;
    }
    return out;
  }
  const ex a0 = a.coeff(0);
  if (vanishes(a0)) throw std::domain_error("non-integer power of a series without constant term");
  return compose(a, [&](int m) {
    ex f = 1;
    for (int j = 0; j < m; ++j) f *= (r - j);
    return f * GiNaC::pow(a0, r - m);
  });
}

Series shifted_jet(const JetSpace& J, int i, const ex& s, int p) {
  Series out;
  out.prec = p;
  numeric factorial = 1;
  for (int k = 0; k < p; ++k) {
    if (k > 0) factorial *= k;
    const ex sk = k == 0 ? ex(1) : GiNaC::pow(s, k);
    out.c.push_back(GiNaC::expand(sk / factorial * J.x(k, i)));
  }
  return out;
}

namespace {

// Zero on a normal form with radicals: every power b^(p/q) of a base b (expanded) becomes
// t_b^(p·Q/q), t_b a new symbol with t_b^Q = b (Q the common denominator of b's exponents);
// the numerator of the rational function is then reduced modulo t_b^Q − b, which leaves it
// of degree < Q in each t_b, and it is zero if and only if every coefficient is. This decides
// (x1² + x2²)^(-7/2)·(x1² + x2²) − (x1² + x2²)^(-5/2) = 0, which expand and normal alone do
// not (they treat each power of a radical as a separate symbol).
bool radical_zero(const ex& e) {
  std::map<ex, long, GiNaC::ex_is_less> denominators;  // base -> common denominator
  for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (!GiNaC::is_a<GiNaC::power>(*it)) continue;
    const ex ex_ = it->op(1);
    if (!GiNaC::is_a<numeric>(ex_)) continue;
    const numeric q = GiNaC::ex_to<numeric>(ex_);
    if (!q.is_rational() || q.is_integer()) continue;
    const ex base = GiNaC::expand(it->op(0));
    const long d = q.denom().to_long();
    auto [pos, fresh] = denominators.emplace(base, d);
    if (!fresh) pos->second = std::lcm(pos->second, d);
  }
  if (denominators.empty()) return false;
  std::vector<std::tuple<ex, GiNaC::symbol, long>> radicals;
  int k = 0;
  for (const auto& [base, d] : denominators)
    radicals.emplace_back(base, GiNaC::symbol("vibook_rad" + std::to_string(k++)), d);
  struct Map : GiNaC::map_function {
    const std::vector<std::tuple<ex, GiNaC::symbol, long>>& r;
    explicit Map(const std::vector<std::tuple<ex, GiNaC::symbol, long>>& rr) : r(rr) {}
    ex operator()(const ex& x) override {
      if (GiNaC::is_a<GiNaC::power>(x) && GiNaC::is_a<numeric>(x.op(1))) {
        const numeric q = GiNaC::ex_to<numeric>(x.op(1));
        if (q.is_rational() && !q.is_integer()) {
          const ex base = GiNaC::expand(x.op(0).map(*this));
          for (const auto& [b, t, d] : r)
            if (GiNaC::expand(base - b).is_zero()) return GiNaC::pow(t, q * d);
        }
      }
      return x.map(*this);
    }
  } m(radicals);
  const ex num = GiNaC::numer(GiNaC::normal(m(e)));
  // reduce modulo t^d − b, for each radical, then test every coefficient
  ex red = GiNaC::expand(num);
  for (const auto& [b, t, d] : radicals) {
    if (!red.is_polynomial(t)) return false;
    const int deg = red.degree(t);
    ex acc = 0;
    for (int j = 0; j <= deg; ++j)
      acc += red.coeff(t, j) * GiNaC::pow(b, j / d) * GiNaC::pow(t, j % d);
    red = GiNaC::expand(acc);
  }
  // what remains is of degree < d in each t: zero iff all its coefficients are
  std::vector<ex> parts = {red};
  for (const auto& rad : radicals) {
    const GiNaC::symbol& t = std::get<1>(rad);
    std::vector<ex> next;
    for (const ex& p : parts)
      for (int j = 0; j <= p.degree(t); ++j) next.push_back(p.coeff(t, j));
    parts = std::move(next);
  }
  return std::all_of(parts.begin(), parts.end(),
                     [](const ex& p) { return GiNaC::normal(GiNaC::expand(p)).is_zero(); });
}

}  // namespace

bool vanishes(const ex& e) {
  const ex x = GiNaC::expand(e);
  if (x.is_zero()) return true;
  if (GiNaC::normal(x).is_zero()) return true;
  return radical_zero(x);
}

ex exact_rationals(const ex& e, std::vector<std::string>* inexact) {
  struct Map : GiNaC::map_function {
    std::vector<std::string>* inexact = nullptr;
    ex operator()(const ex& x) override {
      if (GiNaC::is_a<numeric>(x)) {
        const numeric& n = GiNaC::ex_to<numeric>(x);
        if (n.is_rational() || !n.is_real()) return x;
        const double d = n.to_double();
        const numeric exact = GiNaC::ex_to<numeric>(vibook::constant<ex>(d));
        if (inexact && exact.denom() > numeric(4294967296L)) {
          std::ostringstream text;
          char buf[32];
          const auto r = std::to_chars(buf, buf + sizeof buf, d);  // shortest round trip
          text << "a floating-point literal made the coefficient " << std::string(buf, r.ptr)
               << ", taken as its binary64 value " << exact
               << " exactly; for an exact fraction divide the symbolic scalar by integers "
                  "(x / 6, not x / 6.0 or x * (1.0 / 6))";
          if (std::find(inexact->begin(), inexact->end(), text.str()) == inexact->end())
            inexact->push_back(text.str());
        }
        return exact;
      }
      return x.map(*this);
    }
  } map;
  map.inexact = inexact;
  return map(e);
}

SeriesEvaluator::SeriesEvaluator(const JetSpace& J, std::map<ex, Series, GiNaC::ex_is_less> subs,
                                 int cap)
    : J_(J), subs_(std::move(subs)), cap_(cap) {
  for (const auto& kv : subs_)
    if (!GiNaC::is_a<GiNaC::symbol>(kv.first)) symbol_keys_ = false;
}

Series SeriesEvaluator::operator()(const ex& e) {
  const int saved = g_cap;
  g_cap = cap_;
  try {
    Series s = eval(e);
    g_cap = saved;
    return s;
  } catch (...) {
    g_cap = saved;
    throw;
  }
}

bool SeriesEvaluator::depends(const ex& e) const {
  if (GiNaC::is_a<numeric>(e)) return false;
  if (!symbol_keys_)
    return std::any_of(subs_.begin(), subs_.end(), [&](const auto& kv) { return e.has(kv.first); });
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
    if (GiNaC::is_a<GiNaC::symbol>(*it) && subs_.count(*it)) return true;
  return false;
}

Series SeriesEvaluator::eval(const ex& e) {
  if (auto it = memo_.find(e); it != memo_.end()) return it->second;
  Series out;
  int family = 0;
  std::vector<ex> args;
  std::vector<int> index;
  if (match_abstract(e, family, args, index)) {
    out = abstract(family, args, index);
  } else if (!depends(e)) {
    out = Series::constant(e);
  } else if (GiNaC::is_a<GiNaC::symbol>(e)) {
    out = subs_.at(e);
  } else if (GiNaC::is_a<GiNaC::add>(e)) {
    // Terms c·D with the same dependent part D (the product of the factors that depend on the
    // substituted symbols) are gathered first: D is then expanded once, times Σ c. An
    // expanded L_mesh of a concrete polynomial potential has thousands of terms over a few
    // dozen distinct D.
    std::map<ex, ex, GiNaC::ex_is_less> groups;
    ex constant = 0;
    for (std::size_t k = 0; k < e.nops(); ++k) {
      const ex t = e.op(k);
      if (!depends(t)) {
        constant += t;
      } else if (GiNaC::is_a<GiNaC::mul>(t)) {
        GiNaC::exvector c, d;
        for (std::size_t j = 0; j < t.nops(); ++j) (depends(t.op(j)) ? d : c).push_back(t.op(j));
        auto [it, fresh] = groups.emplace(GiNaC::mul(d), GiNaC::mul(c));
        if (!fresh) it->second += GiNaC::mul(c);
      } else {
        auto [it, fresh] = groups.emplace(t, 1);
        if (!fresh) it->second += 1;
      }
    }
    out = Series::constant(constant);
    for (const auto& [d, c] : groups) out = out + Series::constant(c) * eval(d);
  } else if (GiNaC::is_a<GiNaC::mul>(e)) {
    // Factors with negative integer exponents (the 1/h of a difference quotient) divide the
    // product of the others, so that h^{-1}·(x1 − x0) cancels before it is formed.
    Series num = Series::constant(1), den = Series::constant(1);
    for (std::size_t k = 0; k < e.nops(); ++k) {
      const ex f = e.op(k);
      if (GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<numeric>(f.op(1)) &&
          GiNaC::ex_to<numeric>(f.op(1)).is_integer() &&
          GiNaC::ex_to<numeric>(f.op(1)).is_negative() && depends(f)) {
        den = (den * pow(eval(f.op(0)), -GiNaC::ex_to<numeric>(f.op(1)))).truncated(cap_ + 4);
      } else {
        num = (num * eval(f)).truncated(cap_ + 4);
      }
    }
    out = num / den;
  } else if (GiNaC::is_a<GiNaC::power>(e)) {
    const ex expo = e.op(1);
    if (!GiNaC::is_a<numeric>(expo))
      throw std::domain_error("series of a power with a non-numeric exponent");
    out = pow(eval(e.op(0)), GiNaC::ex_to<numeric>(expo));
  } else if (GiNaC::is_a<GiNaC::function>(e) && e.nops() == 1) {
    out = unary(e, eval(e.op(0)));
  } else {
    std::ostringstream os;
    os << e;
    throw std::domain_error("no series rule for " + os.str());
  }
  out = out.truncated(cap_);
  memo_.emplace(e, out);
  return out;
}

Series SeriesEvaluator::unary(const ex& e, const Series& arg) {
  const GiNaC::symbol y("y");
  const ex fy = e.subs(e.op(0) == y);
  const ex a0 = arg.coeff(0);
  return compose(arg, [&](int m) { return fy.diff(y, m).subs(y == a0); });
}

Series SeriesEvaluator::abstract(int family, const std::vector<ex>& args,
                                 const std::vector<int>& index) {
  const int n = static_cast<int>(args.size());
  if (n != J_.family_arity(family))
    throw std::logic_error("abstract function of the wrong dimension");
  std::vector<Series> delta(n);
  int top = cap_;
  for (int i = 0; i < n; ++i) {
    const GiNaC::symbol xi = J_.x(0, J_.family_dof(family, i));
    delta[i] = eval(args[i]);
    if (!vanishes(delta[i].coeff(0) - xi))
      throw std::domain_error("abstract potential expanded away from the jet point x");
    delta[i] = delta[i] - Series::constant(xi);
    top = std::min(top, delta[i].prec);
  }
  // powers[i][k] = δ_i^k / k!
  std::vector<std::vector<Series>> powers(n);
  for (int i = 0; i < n; ++i) {
    powers[i].push_back(Series::constant(1));
    for (int k = 1; k < top; ++k)
      powers[i].push_back((powers[i].back() * delta[i] / Series::constant(k)).truncated(top));
  }
  Series out = Series::constant(0).truncated(top);
  std::vector<int> alpha(n, 0);
  // Σ over multi-indices α with |α| < top of U_{index+α} Π δ_i^{α_i}/α_i!
  std::function<void(int, int)> rec = [&](int i, int left) {
    if (i == n) {
      std::vector<int> idx = index;
      Series term = Series::constant(1);
      for (int j = 0; j < n; ++j) {
        for (int r = 0; r < alpha[j]; ++r) idx.push_back(j);
        if (alpha[j] > 0) term = (term * powers[j][alpha[j]]).truncated(top);
      }
      out = out + Series::constant(J_.derivative(family, idx)) * term;
      return;
    }
    for (int a = 0; a <= left; ++a) {
      alpha[i] = a;
      rec(i + 1, left - a);
    }
    alpha[i] = 0;
  };
  rec(0, top - 1);
  return out.truncated(top);
}

}  // namespace vibook::modified
