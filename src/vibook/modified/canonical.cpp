// Canonical printing of engine expressions (see canonical.hpp for why GiNaC's order is not
// reproducible).
#include "vibook/modified/canonical.hpp"

#include <algorithm>
#include <regex>
#include <sstream>

namespace vibook::modified {

namespace {

using GiNaC::numeric;

std::string numeric_text(const numeric& x, Format f) {
  std::ostringstream os;
  if (f == Format::python && x.is_rational() && !x.is_integer()) {
    os << "Rational(" << x.numer() << ", " << x.denom() << ")";
  } else if (f == Format::latex && x.is_rational() && !x.is_integer()) {
    const numeric n = x.numer();
    os << (n.is_negative() ? "-" : "") << "\\frac{" << abs(n) << "}{" << x.denom() << "}";
  } else {
    os << GiNaC::dflt << x;
  }
  return os.str();
}

// A term split into its numerical coefficient and the rest (the monomial).
struct Term {
  numeric coeff = 1;
  std::vector<ex> factors;  // canonical order
};

Term split(const ex& e);
std::string print(const ex& e, Format f);
std::string print_factor(const ex& x, Format f);
bool flipped(const ex& sum);

// The sort key of a term: its monomial in text form, then its coefficient.
struct Keyed {
  std::string monomial, coeff;
  ex e;
};

std::string monomial_text(const Term& t) {
  std::string s;
  for (const auto& x : t.factors) s += (s.empty() ? "" : "*") + print_factor(x, Format::text);
  return s;
}

std::vector<ex> sorted(std::vector<Keyed> v) {
  std::stable_sort(v.begin(), v.end(), [](const Keyed& a, const Keyed& b) {
    return a.monomial != b.monomial ? a.monomial < b.monomial : a.coeff < b.coeff;
  });
  std::vector<ex> out;
  out.reserve(v.size());
  for (auto& k : v) out.push_back(k.e);
  return out;
}

// The sign of a sum inside a product is GiNaC's choice, made in the same hash order that
// changes from run to run: (t0 − t1)² in one run is (t1 − t0)² in the next, and GiNaC turns
// any power built with the other sign back into its own. So the sign is fixed when printing:
// a sum standing as a factor, or as the base of an integer power, is printed with the sign
// that makes its first term in canonical order positive (flipped()), and the term's
// coefficient takes the sign this costs: −1 for a sum, (−1)^n for a power n (factor_sign()).
bool int_power_of_sum(const ex& x) {
  return GiNaC::is_a<GiNaC::power>(x) && GiNaC::is_a<GiNaC::add>(x.op(0)) &&
         GiNaC::is_a<numeric>(x.op(1)) && GiNaC::ex_to<numeric>(x.op(1)).is_integer();
}

numeric factor_sign(const ex& x) {
  if (GiNaC::is_a<GiNaC::add>(x)) return flipped(x) ? -1 : 1;
  if (int_power_of_sum(x) && flipped(x.op(0)) && GiNaC::ex_to<numeric>(x.op(1)).is_odd()) return -1;
  return 1;
}

Term split(const ex& e) {
  Term t;
  if (GiNaC::is_a<numeric>(e)) {
    t.coeff = GiNaC::ex_to<numeric>(e);
    return t;
  }
  if (!GiNaC::is_a<GiNaC::mul>(e)) {
    if (!GiNaC::is_a<GiNaC::add>(e)) t.coeff *= factor_sign(e);
    t.factors.push_back(e);
    return t;
  }
  std::vector<Keyed> fs;
  for (std::size_t k = 0; k < e.nops(); ++k) {
    const ex x = e.op(k);
    if (GiNaC::is_a<numeric>(x)) {
      t.coeff *= GiNaC::ex_to<numeric>(x);
    } else {
      t.coeff *= factor_sign(x);
      fs.push_back({print_factor(x, Format::text), "", x});
    }
  }
  t.factors = sorted(std::move(fs));
  return t;
}

bool needs_parens_as_factor(const ex& x) {
  return GiNaC::is_a<GiNaC::add>(x) || GiNaC::is_a<GiNaC::mul>(x);
}

bool needs_parens_as_base(const ex& x) {
  if (GiNaC::is_a<numeric>(x)) {
    const numeric& n = GiNaC::ex_to<numeric>(x);
    return n.is_negative() || !n.is_integer();
  }
  return GiNaC::is_a<GiNaC::add>(x) || GiNaC::is_a<GiNaC::mul>(x) || GiNaC::is_a<GiNaC::power>(x);
}

std::string paren(const std::string& s, Format f) {
  return f == Format::latex ? "\\left(" + s + "\\right)" : "(" + s + ")";
}

// A product of factors (coefficient excluded), numerator part only in LaTeX.
std::string product(const std::vector<ex>& factors, Format f) {
  std::string s;
  for (const auto& x : factors) {
    std::string p = print_factor(x, f);
    if (needs_parens_as_factor(x)) p = paren(p, f);
    if (!s.empty()) s += f == Format::latex ? " " : "*";
    s += p;
  }
  return s;
}

std::string print_term(const Term& t, Format f) {
  if (t.factors.empty()) return numeric_text(t.coeff, f);
  if (f == Format::latex) {
    // Factors with a negative numerical exponent go below the fraction bar.
    std::vector<ex> num, den;
    for (const auto& x : t.factors) {
      if (GiNaC::is_a<GiNaC::power>(x) && GiNaC::is_a<numeric>(x.op(1)) &&
          GiNaC::ex_to<numeric>(x.op(1)).is_negative())
        den.push_back(GiNaC::pow(x.op(0), -x.op(1)));
      else
        num.push_back(x);
    }
    const numeric c = t.coeff;
    const std::string sign = c.is_negative() ? "-" : "";
    const numeric cn = abs(c.numer()), cd = c.denom();
    // A lone sum above the bar needs no parentheses.
    const bool lone_sum = num.size() == 1 && cn == 1 && GiNaC::is_a<GiNaC::add>(num[0]);
    std::string top = lone_sum ? print_factor(num[0], f) : product(num, f),
                bottom = product(den, f);
    if (cn != 1) top = numeric_text(cn, f) + (top.empty() ? "" : " " + top);
    if (cd != 1) bottom = numeric_text(cd, f) + (bottom.empty() ? "" : " " + bottom);
    if (top.empty()) top = "1";
    if (bottom.empty()) return sign + top;
    return sign + "\\frac{" + top + "}{" + bottom + "}";
  }
  const std::string body = product(t.factors, f);
  if (t.coeff == 1) return body;
  if (t.coeff == -1) return "-" + body;
  return numeric_text(t.coeff, f) + "*" + body;
}

thread_local const std::vector<std::string>* t_abstract_names = nullptr;

// A subscript as a reader writes it: "k1" and "kp1" are k+1 (q_k1 is q_{k+1}).
std::string subscript(const std::string& s) {
  static const std::regex next(R"(^([a-z])p?1$)");
  std::smatch m;
  if (std::regex_match(s, m, next)) return m[1].str() + "+1";
  return s;
}

// The LaTeX of a symbol made without a TeX name (GiNaC then prints its name as it is, and
// "q_k1" would read as q_k followed by 1): its letter, with its accent ("bbar" is b̄, "bhat" b̂)
// or its midpoint index ("qm" is q_m), then its subscript in braces ("q0", "a11", "q_k1" is
// q_{k+1}, "qm_1" is q_{m,1}, "q0_1" is q_{0,1}). Any other name is printed as it is.
std::string symbol_latex(const std::string& name) {
  static const std::regex digits(R"(^([A-Za-z]+?)([0-9]+)$)");
  static const std::regex letters(R"(^[A-Za-z]+$)");
  static const std::regex accent(R"(^([A-Za-z])(bar|hat|tilde|ddot|dot)$)");
  static const std::regex mid(R"(^([a-z])m$)");
  std::smatch m;
  std::string base = name, sub;
  if (const auto u = name.find('_'); u != std::string::npos && u > 0 && u + 1 < name.size() &&
                                     name.find('_', u + 1) == std::string::npos) {
    base = name.substr(0, u);
    sub = subscript(name.substr(u + 1));
  } else if (std::regex_match(name, m, digits)) {
    base = m[1].str();
    sub = m[2].str();
  }
  std::string head;
  if (!sub.empty() && std::regex_match(base, m, digits) && std::regex_match(m[1].str(), letters))
    return m[1].str() + "_{" + m[2].str() + "," + sub + "}";  // "q0_1": q_{0,1}
  if (std::regex_match(base, m, accent))
    head = "\\" + m[2].str() + "{" + m[1].str() + "}";
  else if (std::regex_match(base, m, mid))
    return m[1].str() + "_{m" + (sub.empty() ? "" : "," + sub) + "}";
  else if (std::regex_match(base, m, letters))
    head = base;
  else
    return name;
  if (sub.empty()) return head == name ? name : head;
  return head + "_{" + sub + "}";
}

std::string print(const ex& e, Format f) {
  if (GiNaC::is_a<numeric>(e)) return numeric_text(GiNaC::ex_to<numeric>(e), f);
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    const std::string name = GiNaC::ex_to<GiNaC::symbol>(e).get_name();
    if (f != Format::latex) return name;
    std::ostringstream os;
    os << GiNaC::latex << e;
    return os.str() == name ? symbol_latex(name) : os.str();
  }
  if (GiNaC::is_a<GiNaC::add>(e)) {
    std::string s;
    for (const auto& x : canonical_operands(e)) {
      const std::string p = print(x, f);
      if (s.empty())
        s = p;
      else if (p.front() == '-')
        s += f == Format::latex ? " - " + p.substr(1) : p;
      else
        s += (f == Format::latex ? " + " : "+") + p;
    }
    return s;
  }
  if (GiNaC::is_a<GiNaC::mul>(e)) return print_term(split(e), f);
  if (GiNaC::is_a<GiNaC::power>(e)) {
    const ex b = e.op(0), x = e.op(1);
    if (f == Format::latex && GiNaC::is_a<numeric>(x) && GiNaC::ex_to<numeric>(x).is_negative())
      return print_term(split(e), f);
    const std::string sign = factor_sign(e) == -1 ? "-" : "";
    return sign + print_factor(e, f);
  }
  if (GiNaC::is_a<GiNaC::function>(e)) {
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    std::string args;
    for (std::size_t k = 0; k < e.nops(); ++k) args += (k ? "," : "") + print(e.op(k), f);
    if (f == Format::latex && name.rfind("vibook_abstract", 0) == 0 && e.nops() >= 1 &&
        GiNaC::is_a<numeric>(e.op(0))) {
      // An abstract function: its family's name (AbstractNames), without the family id.
      const int family = GiNaC::ex_to<numeric>(e.op(0)).to_int();
      std::string inner;
      for (std::size_t k = 1; k < e.nops(); ++k) inner += (k > 1 ? "," : "") + print(e.op(k), f);
      const bool named = t_abstract_names && family >= 0 &&
                         family < static_cast<int>(t_abstract_names->size()) &&
                         !(*t_abstract_names)[static_cast<std::size_t>(family)].empty();
      const std::string fn = named ? (*t_abstract_names)[static_cast<std::size_t>(family)]
                                   : "F_{" + std::to_string(family) + "}";
      return fn + "\\left(" + inner + "\\right)";
    }
    if (f == Format::latex) {
      const bool known = name == "sin" || name == "cos" || name == "exp" || name == "log";
      return (known ? "\\" + name : "\\mathrm{" + name + "}") + "\\left(" + args + "\\right)";
    }
    return name + "(" + args + ")";
  }
  // Anything else (relations, lists): GiNaC's own printing; the engine produces none of these
  // in the expressions it prints.
  std::ostringstream os;
  if (f == Format::latex)
    os << GiNaC::latex << e;
  else if (f == Format::python)
    os << GiNaC::python << e;
  else
    os << GiNaC::dflt << e;
  return os.str();
}

}  // namespace

namespace {

bool flipped(const ex& sum) {
  const std::vector<ex> ops = canonical_operands(sum);
  return !ops.empty() && split(ops.front()).coeff.is_negative();
}

// A factor of a term: a sum, or the base of an integer power of a sum, with the sign
// flipped() chooses (the coefficient has taken its cost); anything else as print() has it.
std::string print_factor(const ex& e, Format f) {
  if (GiNaC::is_a<GiNaC::add>(e)) return print(flipped(e) ? ex(GiNaC::expand(-e)) : e, f);
  if (!GiNaC::is_a<GiNaC::power>(e)) return print(e, f);
  const ex x = e.op(1);
  const ex b = int_power_of_sum(e) && flipped(e.op(0)) ? ex(GiNaC::expand(-e.op(0))) : e.op(0);
  std::string base = print(b, f);
  if (needs_parens_as_base(b)) base = paren(base, f);
  if (f == Format::latex) {
    if (x.is_equal(GiNaC::numeric(1, 2))) return "\\sqrt{" + print(b, f) + "}";
    return base + "^{" + print(x, f) + "}";
  }
  std::string expo = print(x, f);
  const bool plain = GiNaC::is_a<numeric>(x) && GiNaC::ex_to<numeric>(x).is_pos_integer();
  if (!plain) expo = "(" + expo + ")";
  return base + (f == Format::python ? "**" : "^") + expo;
}

}  // namespace

std::vector<ex> canonical_operands(const ex& e) {
  std::vector<Keyed> v;
  if (GiNaC::is_a<GiNaC::add>(e)) {
    for (std::size_t k = 0; k < e.nops(); ++k) {
      const Term t = split(e.op(k));
      v.push_back({monomial_text(t), numeric_text(t.coeff, Format::text), e.op(k)});
    }
    return sorted(std::move(v));
  }
  if (GiNaC::is_a<GiNaC::mul>(e)) {
    const Term t = split(e);
    std::vector<ex> out = t.factors;
    if (t.coeff != 1) out.insert(out.begin(), t.coeff);
    return out;
  }
  std::vector<ex> out;
  for (std::size_t k = 0; k < e.nops(); ++k) out.push_back(e.op(k));
  return out;
}

std::string canonical_string(const ex& e, Format f) { return print(e, f); }

AbstractNames::AbstractNames(std::vector<std::string> tex)
    : tex_(std::move(tex)), previous_(t_abstract_names) {
  t_abstract_names = &tex_;
}

AbstractNames::~AbstractNames() { t_abstract_names = previous_; }

}  // namespace vibook::modified
