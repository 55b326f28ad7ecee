// A printed display against vibook's side, and the correction search (compare.hpp).
#include "vibook/printed/compare.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "vibook/modified/canonical.hpp"
#include "vibook/modified/engine.hpp"
#include "vibook/modified/series.hpp"
#include "vibook/modified/vector_notation.hpp"

namespace vibook::printed {

using GiNaC::numeric;

Target Target::scalar_series(const std::vector<ex>& c, int through) {
  Target t;
  t.series = {c};
  t.through = through;
  return t;
}

Target Target::vector_series(const std::vector<std::vector<ex>>& f, int through) {
  Target t;
  const std::size_t n = f.empty() ? 0 : f[0].size();
  t.series.assign(n, {});
  for (const auto& fk : f)
    for (std::size_t i = 0; i < n; ++i) t.series[i].push_back(fk.at(i));
  t.through = through;
  return t;
}

Target Target::exactly(const std::vector<ex>& components) {
  Target t;
  t.exact = components;
  return t;
}

Target Target::exactly(const ex& scalar) { return exactly(std::vector<ex>{scalar}); }

Target& Target::shown_as(std::vector<ex> display, GiNaC::exmap abbreviations, std::string latex,
                         const ex& h) {
  const bool is_series = !series.empty();
  if (display.size() != (is_series ? series.size() : exact.size()))
    throw std::logic_error("Target::shown_as: one shown form per component");
  for (std::size_t i = 0; i < display.size(); ++i) {
    bool same = true;
    if (!is_series) {
      same = modified::vanishes(display[i].subs(abbreviations) - exact[i]);
    } else {
      const ex x = GiNaC::expand(display[i].subs(abbreviations));
      for (std::size_t k = 0; k < series[i].size() && same; ++k)
        if (through < 0 || static_cast<int>(k) <= through)
          same = modified::vanishes(x.coeff(h, static_cast<int>(k)) - series[i][k]);
    }
    if (!same)
      throw std::logic_error("Target::shown_as: component " + std::to_string(i + 1) +
                             " shown is not the target once its abbreviations are substituted");
  }
  shown_h = h;
  shown = std::move(display);
  where = std::move(abbreviations);
  where_latex = std::move(latex);
  return *this;
}

Target& Target::shown_read(std::string latex, const Notation& notation) {
  const Reading r = read(latex, notation);
  if (r.members.size() != 1)
    throw std::logic_error("Target::shown_read: one expression, not an equation: " + latex);
  const Value& v = r.members[0];
  const bool is_series = !series.empty();
  const std::size_t n = is_series ? series.size() : exact.size();
  if (v.c.size() != n)
    throw std::logic_error("Target::shown_read: " + std::to_string(v.c.size()) +
                           " components shown, the target has " + std::to_string(n));
  const ex h = notation.step();
  for (std::size_t i = 0; i < n; ++i) {
    bool same = true;
    if (!is_series) {
      same = modified::vanishes(v.c[i] - exact[i]);
    } else {
      const ex x = GiNaC::expand(v.c[i]);
      int compared = 0;
      for (std::size_t k = 0; k < series[i].size() && same; ++k)
        if (through < 0 || static_cast<int>(k) <= through) {
          same = modified::vanishes(x.coeff(h, static_cast<int>(k)) - series[i][k]);
          compared = static_cast<int>(k) + 1;
        }
      // nothing shown beyond the powers compared
      same = same && (!x.has(h) || (x.is_polynomial(h) && x.degree(h) < compared));
    }
    if (!same)
      throw std::logic_error("Target::shown_read: component " + std::to_string(i + 1) +
                             " of the LaTeX shown is not the target: " + latex);
  }
  shown_latex = std::move(latex);
  return *this;
}

namespace {

// Abstract calls compare equal only with their arguments in one form: expand them.
ex expand_arguments(const ex& e) {
  struct Map : GiNaC::map_function {
    ex operator()(const ex& x) override {
      if (GiNaC::is_a<GiNaC::function>(x) || GiNaC::is_a<GiNaC::fderivative>(x)) {
        ex y = x;
        for (std::size_t k = 0; k < x.nops(); ++k)
          y = y.subs(x.op(k) == GiNaC::expand(x.op(k).map(*this)));
        return y;
      }
      return x.map(*this);
    }
  } m;
  return m(e);
}

std::string str(const numeric& n) {
  std::ostringstream os;
  os << n;
  return os.str();
}

std::string latex(const ex& e) { return modified::canonical_string(e, modified::Format::latex); }

// Our side of a comparison, for the reader: the expanded expression with its terms grouped by
// their non-polynomial part (a power of a sum with an exponent that is not a positive integer,
// a function), each group printed as that part times the sum of its polynomial cofactors,
// factored over the rationals where that prints shorter. The groups are keyed by their
// canonical text and every sum and product prints in canonical order, and a factorization is
// unique up to the signs the printer fixes, so the text is the same in every run. Kept only
// when it is shorter than the expanded form.
std::string readable_latex(const ex& e) {
  const ex x = GiNaC::expand(e);
  const std::string expanded = latex(x);
  if (!GiNaC::is_a<GiNaC::add>(x) || x.nops() > 400) return expanded;
  auto polynomial_factor = [](const ex& f) {
    if (GiNaC::is_a<GiNaC::numeric>(f) || GiNaC::is_a<GiNaC::symbol>(f)) return true;
    return GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::symbol>(f.op(0)) &&
           GiNaC::is_a<GiNaC::numeric>(f.op(1)) &&
           GiNaC::ex_to<GiNaC::numeric>(f.op(1)).is_pos_integer();
  };
  std::map<std::string, std::pair<ex, ex>> groups;  // key -> (non-polynomial part, cofactor)
  for (std::size_t k = 0; k < x.nops(); ++k) {
    const ex t = x.op(k);
    ex poly = 1, rest = 1;
    if (GiNaC::is_a<GiNaC::mul>(t)) {
      for (std::size_t j = 0; j < t.nops(); ++j)
        (polynomial_factor(t.op(j)) ? poly : rest) *= t.op(j);
    } else {
      (polynomial_factor(t) ? poly : rest) = t;
    }
    auto& g = groups[latex(rest)];
    g.first = rest;
    g.second += poly;
  }
  if (groups.size() == x.nops()) return expanded;  // nothing shared
  ex grouped = 0;
  for (const auto& [key, g] : groups) {
    ex cofactor = g.second;
    if (GiNaC::is_a<GiNaC::add>(cofactor) && cofactor.nops() <= 100) {
      try {
        // GiNaC returns each factor in a recursive form that follows the order the symbols were
        // made in; expanded, each irreducible factor is one canonical polynomial.
        auto expanded_factor = [](const ex& y) {
          return GiNaC::is_a<GiNaC::power>(y) ? GiNaC::pow(GiNaC::expand(y.op(0)), y.op(1))
                                              : GiNaC::expand(y);
        };
        const ex raw = GiNaC::factor(cofactor);
        ex f = 1;
        if (GiNaC::is_a<GiNaC::mul>(raw)) {
          for (std::size_t j = 0; j < raw.nops(); ++j) f *= expanded_factor(raw.op(j));
        } else {
          f = expanded_factor(raw);
        }
        if (latex(f).size() < latex(cofactor).size()) cofactor = f;
      } catch (const std::exception&) {
        // not a polynomial GiNaC factors: the sum as it is
      }
    }
    grouped += g.first * cofactor;
  }
  const std::string text = latex(grouped);
  return text.size() < expanded.size() ? text : expanded;
}

// Σ_k c[k] h^k, each power that does not vanish with its coefficient by readable_latex in
// \Bigl(…\Bigr), as format_series prints a series; "0" when every coefficient vanishes.
std::string by_powers_of_h(const std::vector<ex>& c) {
  std::string text;
  for (std::size_t k = 0; k < c.size(); ++k) {
    if (c[k].is_zero()) continue;
    if (!text.empty()) text += " + ";
    if (k > 0) text += k == 1 ? std::string("h") : fmt::format("h^{{{}}}", k);
    text += "\\Bigl(" + readable_latex(c[k]) + "\\Bigr)";
  }
  return text.empty() ? std::string("0") : text;
}

// Where printed and ours differ, in a form a reader can take in: both sides when they are
// short; else their difference when that is short; else both evaluated at one point (every
// symbol a distinct small rational) when they are numbers there; else only their sizes.
// A scalar of an abstract potential in 2-3 dimensions (J set) is written in vector notation.
std::string describe_difference(const ex& printed, const ex& ours,
                                const modified::JetSpace* J = nullptr) {
  const ex p = GiNaC::expand(printed), o = GiNaC::expand(ours);
  std::optional<modified::VectorNotation> vn;
  if (J) vn = modified::VectorNotation::of(*J, {p, o});
  auto tex = [&](const ex& e) { return vn ? vn->scalar(e) : latex(e); };
  const std::string a = tex(p), b = tex(o);
  if (a.size() + b.size() <= 600) {
    std::string both = fmt::format("printed \\({}\\), ours \\({}\\)", a, b);
    // grouped, both sides are short more often: their difference shows what differs
    if (vn) {
      const std::string d = tex(GiNaC::expand(p - o));
      if (d.size() <= 400) both += fmt::format("; printed − ours = \\({}\\)", d);
    }
    return both;
  }
  const ex d = vn ? GiNaC::expand(p - o) : GiNaC::normal(printed - ours);
  const std::string dl = tex(d);
  if (dl.size() <= 400) return fmt::format("printed − ours = \\({}\\)", dl);
  GiNaC::exset syms;
  struct Collect : GiNaC::visitor, GiNaC::symbol::visitor {
    GiNaC::exset* out;
    void visit(const GiNaC::symbol& x) override { out->insert(x); }
  } c;
  c.out = &syms;
  (printed - ours).traverse(c);
  // by name, not by GiNaC's order (which follows creation order, and so the checks run before)
  std::map<std::string, ex> by_name;
  for (const ex& x : syms) by_name[GiNaC::ex_to<GiNaC::symbol>(x).get_name()] = x;
  GiNaC::exmap at;
  std::vector<std::string> shown;
  int k = 0;
  for (const auto& [name, x] : by_name) {
    const numeric v = numeric(2 * k + 3, 7 + k);
    at[x] = v;
    shown.push_back(fmt::format("{} = {}", latex(x), str(v)));
    ++k;
  }
  const ex pa = GiNaC::evalf(printed.subs(at)), pb = GiNaC::evalf(ours.subs(at));
  if (GiNaC::is_a<numeric>(pa) && GiNaC::is_a<numeric>(pb) && GiNaC::ex_to<numeric>(pa).is_real() &&
      GiNaC::ex_to<numeric>(pb).is_real())
    return fmt::format("at \\({}\\): printed {:.12g}, ours {:.12g}", fmt::join(shown, ",\\ "),
                       GiNaC::ex_to<numeric>(pa).to_double(),
                       GiNaC::ex_to<numeric>(pb).to_double());
  return fmt::format("printed and ours differ (expressions of {} and {} characters)", a.size(),
                     b.size());
}

// The differences printed − ours of one reading, over every case, component and power; the
// first non-vanishing one described in `first`.
struct Differences {
  std::vector<ex> d;
  std::string first;
  int through = -1;  // highest power compared (series), −1 for exact
  bool failed = false;
};

// With `stop`, the first difference that does not vanish ends the work (the search only
// needs to know whether a candidate fails); `out.failed` says so.
Differences differences(const std::vector<Token>& tokens, const std::map<std::size_t, ex>& factors,
                        const Spec& spec, const std::vector<Case>& cases, bool describe,
                        bool stop = false) {
  Differences out;
  // One difference: kept; with `stop`, a non-vanishing one ends the work (true); with
  // `describe`, the first non-vanishing one is described, `where` naming its place. Whether it
  // vanishes (a normal form, possibly of radicals) is decided once.
  const modified::JetSpace* scalar_jets = nullptr;  // a scalar series: vector notation
  auto record = [&](const ex& printed, const ex& ours, const auto& where) {
    const ex diff = printed - ours;
    out.d.push_back(diff);
    if (!stop && !(describe && out.first.empty())) return false;
    if (modified::vanishes(diff)) return false;
    if (stop) {
      out.failed = true;
      return true;
    }
    out.first = where() + describe_difference(printed, ours, scalar_jets);
    return false;
  };
  for (const Case& c : cases) {
    const Reading r = read(tokens, *c.notation, factors);
    std::vector<std::size_t> members = spec.members;
    if (members.empty()) members.push_back(Spec::kLast);
    if (spec.equation) members = {0};
    for (std::size_t m : members) {
      if (m == Spec::kLast) m = r.members.size() - 1;
      if (m >= r.members.size() || (spec.equation && r.members.size() != 2))
        throw ReadError(fmt::format("the quote has {} members, not {}", r.members.size(),
                                    spec.equation ? 2 : m + 1));
      Value v = r.members[m];
      if (spec.equation) v = add(v, scale(-1, r.members[1]));
      if (v.tuple) throw IllFormed("the compared member is an argument list");
      const std::string where_m =
          members.size() > 1 ? fmt::format("member {}: ", m + 1) : std::string();
      const std::size_t comps =
          c.target.series.empty() ? c.target.exact.size() : c.target.series.size();
      if (v.c.size() != comps)
        throw IllFormed(
            fmt::format("the printed member has {} components, ours {}", v.c.size(), comps));
      const std::string where = (cases.size() > 1 ? c.name + ": " : std::string()) + where_m;
      if (c.target.series.empty()) {
        for (std::size_t i = 0; i < comps; ++i) {
          const auto& J = c.notation->jets();
          ex printed = at_jet_point(expand_arguments(v.c[i]), J);
          ex ours = at_jet_point(expand_arguments(c.target.exact[i]), J);
          if (c.target.reduce) {
            printed = c.target.reduce(printed);
            ours = c.target.reduce(ours);
          }
          if (record(printed, ours, [&] {
                return where + (comps > 1 ? fmt::format("component {}: ", i + 1) : "");
              }))
            return out;
        }
        continue;
      }
      int K = c.target.through;
      if (K < 0)
        for (const auto& s : c.target.series) K = std::max(K, static_cast<int>(s.size()) - 1);
      std::optional<int> rem = r.remainder[m];
      if (spec.equation && r.remainder[1])
        rem = rem ? std::min(*rem, *r.remainder[1]) : r.remainder[1];
      if (rem) K = std::min(K, *rem - 1);
      if (K < 0) throw ReadError("the display's remainder leaves no power of the step to compare");
      out.through = std::max(out.through, K);
      const auto& J = c.notation->jets();
      scalar_jets = comps == 1 ? &J : nullptr;
      std::map<ex, modified::Series, GiNaC::ex_is_less> subs;
      subs[J.h()] = modified::Series::h();
      // Extra terms for quotients by powers of h (2/h · arcsin(h/2)); the result must still
      // reach h^K, or the comparison stops with a reader error rather than read missing terms
      // as zeros.
      modified::SeriesEvaluator se(J, subs, K + 8);
      for (std::size_t i = 0; i < comps; ++i) {
        modified::Series s;
        try {
          s = se(v.c[i]);
        } catch (const std::domain_error& e) {
          throw ReadError(std::string("cannot expand the printed member in the step: ") + e.what());
        }
        if (s.prec <= K)
          throw ReadError(
              fmt::format("the expansion of the printed member reaches only h^{}", s.prec - 1));
        const int low = std::min(0, s.low);
        for (int k = low; k <= K; ++k) {
          const ex printed = at_jet_point(k < s.prec ? s.coeff(k) : ex(0), J);
          const auto& tc = c.target.series[i];
          const ex ours =
              k >= 0 && k < static_cast<int>(tc.size()) ? tc[static_cast<std::size_t>(k)] : ex(0);
          if (record(printed, ours, [&] {
                return fmt::format("{}\\(h^{{{}}}\\){}: ", where, k,
                                   comps > 1 ? fmt::format(" of component {}", i + 1) : "");
              }))
            return out;
        }
      }
    }
  }
  return out;
}

// A rational times powers of the parameters (h, c^-2, 8h): a factor a correction may have.
bool monomial_in(const ex& l, const std::vector<GiNaC::symbol>& params) {
  ex rest = l;
  for (const auto& p : params) {
    if (!rest.has(p)) continue;
    const ex e = GiNaC::expand(rest);
    if (GiNaC::is_a<GiNaC::add>(e)) return false;
    // divide out p^k
    int k = 0;
    for (; k < 12 && rest.has(p); ++k) rest = GiNaC::normal(rest / p);
    if (rest.has(p)) {
      rest = l;
      for (int j = 0; j < 12 && rest.has(p); ++j) rest = GiNaC::normal(rest * p);
      if (rest.has(p)) return false;
    }
  }
  return GiNaC::is_a<numeric>(rest) && GiNaC::ex_to<numeric>(rest).is_rational();
}

bool all_vanish(const std::vector<ex>& d) {
  return std::all_of(d.begin(), d.end(), [](const ex& e) { return modified::vanishes(e); });
}

// --- the correction search -------------------------------------------------------------------

struct Candidate {
  std::vector<Token> tokens;
  std::map<std::size_t, ex> scale;
  std::string edit;
};

Token make(Token::Kind k, const std::string& text, bool space = false) {
  Token t;
  t.kind = k;
  t.text = text;
  t.space_before = space;
  return t;
}

bool sizing(const Token& x) {
  static const std::set<std::string> k = {"left", "bigl", "Bigl", "biggl", "Biggl",
                                          "big",  "Big",  "bigg", "Bigg"};
  return x.kind == Token::Kind::command && k.count(x.text);
}

// The term's first token including a sizing command before it (\left| …).
std::size_t with_sizing(const std::vector<Token>& t, std::size_t first) {
  while (first > 0 && sizing(t[first - 1])) --first;
  return first;
}

std::string term_text(const std::vector<Token>& t, std::size_t b, std::size_t e) {
  return print(std::vector<Token>(t.begin() + static_cast<std::ptrdiff_t>(b),
                                  t.begin() + static_cast<std::ptrdiff_t>(std::min(e, t.size()))));
}

// The sign token before a term (skipping \left and similar), or npos.
std::size_t sign_before(const std::vector<Token>& t, std::size_t first) {
  std::size_t k = first;
  while (k > 0) {
    --k;
    const Token& x = t[k];
    if (x.sym("+") || x.sym("-")) return k;
    if (x.cmd("left") || x.cmd("bigl") || x.cmd("Bigl") || x.cmd("big") || x.cmd("Big") ||
        x.cmd("quad") || x.sym("&") || x.cmd("\\"))
      continue;
    return std::string::npos;
  }
  return std::string::npos;
}

// The tokens with the term [first, end) multiplied by λ (a rational), as a reader would
// write the correction.
std::vector<Token> scaled_tokens(const std::vector<Token>& t, std::size_t first, std::size_t end,
                                 const ex& factor) {
  // split the factor into its rational part and the rest (h, c^{-2}), printed as LaTeX
  numeric lambda = 1;
  ex rest = 1;
  if (GiNaC::is_a<numeric>(factor)) {
    lambda = GiNaC::ex_to<numeric>(factor);
  } else {
    const ex f = GiNaC::expand(factor);
    const ex c = GiNaC::is_a<GiNaC::mul>(f) ? f.op(f.nops() - 1) : ex(1);
    if (GiNaC::is_a<numeric>(c)) {
      lambda = GiNaC::ex_to<numeric>(c);
      rest = f / c;
    } else {
      rest = f;
    }
  }
  if (rest != 1) {
    std::vector<Token> out = scaled_tokens(t, first, end, lambda);
    const std::size_t at =
        with_sizing(out, first + (out.size() > t.size() ? out.size() - t.size() : 0));
    std::vector<Token> ins = tokenize(latex(rest));
    if (!ins.empty()) ins.front().space_before = true;
    out[at].space_before = true;
    out.insert(out.begin() + static_cast<std::ptrdiff_t>(at), ins.begin(), ins.end());
    return out;
  }
  first = with_sizing(t, first);
  std::vector<Token> out = t;
  const std::size_t s = sign_before(t, first);
  (void)end;
  if (lambda.is_zero()) {
    const std::size_t b = s == std::string::npos ? first : s;
    out.erase(out.begin() + static_cast<std::ptrdiff_t>(b),
              out.begin() + static_cast<std::ptrdiff_t>(std::min(end, out.size())));
    return out;
  }
  numeric mag = lambda;
  if (lambda.is_negative()) {
    mag = -lambda;
    if (s != std::string::npos) {
      out[s].text = out[s].sym("+") ? "-" : "+";
    } else {
      out.insert(out.begin() + static_cast<std::ptrdiff_t>(first),
                 make(Token::Kind::symbol, "-", t[first].space_before));
    }
  }
  if (mag == 1) return out;
  const std::size_t at = first + (lambda.is_negative() && s == std::string::npos ? 1 : 0);
  // a leading integer coefficient: multiply it
  if (out[at].kind == Token::Kind::number && out[at].text.find('.') == std::string::npos) {
    const numeric v = numeric(out[at].text.c_str()) * mag;
    if (v.is_integer()) {
      out[at].text = str(v);
      return out;
    }
  }
  std::vector<Token> ins;
  if (mag.is_integer()) {
    ins.push_back(make(Token::Kind::number, str(mag), out[at].space_before));
  } else {
    ins = {make(Token::Kind::command, "frac", out[at].space_before),
           make(Token::Kind::symbol, "{"),
           make(Token::Kind::number, str(mag.numer())),
           make(Token::Kind::symbol, "}"),
           make(Token::Kind::symbol, "{"),
           make(Token::Kind::number, str(mag.denom())),
           make(Token::Kind::symbol, "}")};
  }
  out[at].space_before = true;
  out.insert(out.begin() + static_cast<std::ptrdiff_t>(at), ins.begin(), ins.end());
  return out;
}

// Positions of the digits written as subscripts (x_1, \dot{x}_{2}), with the text of the
// symbol before the underscore (its base and accents) and its digit.
struct SubDigit {
  std::size_t pos;
  std::string symbol;
};
std::vector<SubDigit> subscript_digits(const std::vector<Token>& t) {
  std::vector<SubDigit> out;
  for (std::size_t k = 0; k + 1 < t.size(); ++k) {
    if (!t[k].sym("_")) continue;
    // the symbol: back to the start of \dot{x} or x
    std::string sym;
    if (k > 0) {
      std::size_t b = k - 1;
      if (t[b].sym("}")) {
        int depth = 0;
        for (std::size_t j = b + 1; j-- > 0;) {
          if (t[j].sym("}")) ++depth;
          if (t[j].sym("{") && --depth == 0) {
            b = j > 0 ? j - 1 : j;
            break;
          }
        }
      }
      sym = term_text(t, b, k);
    }
    if (t[k + 1].kind == Token::Kind::number && t[k + 1].text.size() == 1) {
      out.push_back({k + 1, sym});
    } else if (t[k + 1].sym("{")) {
      for (std::size_t j = k + 2; j < t.size() && !t[j].sym("}"); ++j)
        if (t[j].kind == Token::Kind::number && t[j].text.size() == 1) out.push_back({j, sym});
    }
  }
  return out;
}

// Where a token stands, in terms a reader of the printed display can count (our transcription's
// character positions mean nothing to the paper's author): "" when what it shows occurs once in
// the display, else " (the 2nd from the left)". key(j) is what position j shows, "" where it
// shows nothing of the kind; k is the position described.
std::string which(std::size_t n, std::size_t k,
                  const std::function<std::string(std::size_t)>& key) {
  const std::string mine = key(k);
  std::size_t before = 0, all = 0;
  for (std::size_t j = 0; j < n; ++j)
    if (const std::string kj = key(j); !kj.empty() && kj == mine) {
      ++all;
      if (j < k) ++before;
    }
  if (all <= 1) return "";
  const std::size_t i = before + 1;
  const char* suffix = (i % 100 >= 11 && i % 100 <= 13) ? "th"
                       : i % 10 == 1                    ? "st"
                       : i % 10 == 2                    ? "nd"
                       : i % 10 == 3                    ? "rd"
                                                        : "th";
  return fmt::format(" (the {}{} from the left)", i, suffix);
}

// Positions of integers in superscripts (h^2, x^{(3)}).
std::vector<std::size_t> superscript_integers(const std::vector<Token>& t) {
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k + 1 < t.size(); ++k) {
    if (!t[k].sym("^")) continue;
    if (t[k + 1].kind == Token::Kind::number) {
      out.push_back(k + 1);
    } else if (t[k + 1].sym("{")) {
      int depth = 0;
      for (std::size_t j = k + 1; j < t.size(); ++j) {
        if (t[j].sym("{")) ++depth;
        if (t[j].sym("}") && --depth == 0) break;
        if (t[j].kind == Token::Kind::number && t[j].text.find('.') == std::string::npos)
          out.push_back(j);
      }
    }
  }
  return out;
}

// Argument lists: for each comma at depth 1 of a (…) or ⟨…⟩, the item after it (for deletion),
// and for lists of two, both items (for a swap).
struct ListItem {
  std::size_t open, comma, close;  // the comma before the item, and where the item ends
};
std::vector<std::pair<std::size_t, std::size_t>> list_items(const std::vector<Token>& t) {
  // returns [begin, end) token ranges to delete: ", item"
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (!t[k].sym(",")) continue;
    int depth = 0;
    std::size_t j = k + 1;
    for (; j < t.size(); ++j) {
      const Token& x = t[j];
      if (x.sym("(") || x.sym("[") || x.sym("{") || x.cmd("langle")) ++depth;
      if (x.sym(")") || x.sym("]") || x.sym("}") || x.cmd("rangle")) {
        if (depth == 0) break;
        --depth;
      }
      if (x.sym(",") && depth == 0) break;
    }
    std::size_t end = j;
    while (end > k + 1 &&
           (t[end - 1].cmd("right") || t[end - 1].cmd("bigr") || t[end - 1].cmd("Bigr")))
      --end;
    out.emplace_back(k, end);
  }
  return out;
}

}  // namespace

claims::FormulaComparison compare(const Spec& spec, const std::vector<Case>& cases) {
  // Our side's abstract functions print with the paper's letters (U, V, φ), never with the
  // engine's internal names.
  std::vector<std::string> family_names;
  if (!cases.empty() && cases[0].notation) {
    const auto& J = cases[0].notation->jets();
    for (int f = 0; f < J.families(); ++f) family_names.push_back(J.family_tex(f));
  }
  const modified::AbstractNames abstract_names(std::move(family_names));
  claims::FormulaComparison out;
  out.paper = std::string(key(spec.paper));
  out.quote = spec.quote;
  out.part = spec.part;
  out.against = spec.against;
  out.check = spec.check;
  out.role = spec.role;
  out.verified = spec.verified;
  try {
    const Display& d = spec.display.empty() ? display_quoting(spec.paper, spec.quote)
                                            : display(spec.paper, spec.display);
    if (!quotes(d, spec.quote))
      throw std::invalid_argument("the quote does not occur in display " + d.full_id());
    out.display = d.id();
    out.label = d.label();
  } catch (const std::invalid_argument& e) {
    out.outcome = "unreadable";
    out.detail = e.what();
    return out;
  }
  // Our side, as LaTeX (the first case's target), expanded: the unexpanded form's shape (which
  // products GiNaC multiplied out on the way) depends on the order the symbols were made in,
  // which differs between runs when checks run in parallel; the expanded form does not.
  if (!cases.empty()) {
    const Target& t = cases[0].target;
    std::vector<std::string> comps;
    if (t.series.empty()) {
      // an exact polynomial in h with two powers or more: collected by them (a screen of
      // expanded terms otherwise: Shen & Sun's (4.4b) on a test force)
      const ex h = cases[0].notation->jets().h();
      // shown in abbreviations (Target::shown_as, checked equal to the target)
      for (const auto& e : t.shown) comps.push_back(readable_latex(e));
      for (const auto& e : t.shown.empty() ? t.exact : std::vector<ex>{}) {
        const ex x = GiNaC::expand(e);
        std::vector<ex> c;
        if (x.has(h) && x.is_polynomial(h))
          for (int k = 0; k <= x.degree(h); ++k) c.push_back(x.coeff(h, k));
        const auto powers =
            std::count_if(c.begin(), c.end(), [](const ex& y) { return !y.is_zero(); });
        comps.push_back(powers < 2 ? readable_latex(e) : by_powers_of_h(c));
      }
      out.through = "exactly";
    } else {
      const auto& J = cases[0].notation->jets();
      std::vector<std::vector<ex>> series;  // series[i][k]
      std::vector<ex> all;
      for (const auto& s : t.series) {
        std::vector<ex> c = s;
        if (t.through >= 0 && static_cast<int>(c.size()) > t.through + 1)
          c.resize(static_cast<std::size_t>(t.through) + 1);
        for (auto& x : c) x = GiNaC::expand(x);
        all.insert(all.end(), c.begin(), c.end());
        series.push_back(std::move(c));
      }
      // an abstract potential in 2-3 dimensions: in the papers' vector notation
      // (vector_notation.hpp), so that the two sides can be compared by eye
      if (const auto vn = t.shown.empty() ? modified::VectorNotation::of(J, all) : std::nullopt) {
        if (series.size() == 1) {
          out.ours = vn->scalar_series(series[0]);
        } else {
          std::size_t K = 0;
          for (const auto& c : series) K = std::max(K, c.size());
          std::vector<std::vector<ex>> field(K, std::vector<ex>(series.size(), ex(0)));
          for (std::size_t i = 0; i < series.size(); ++i)
            for (std::size_t k = 0; k < series[i].size(); ++k) field[k][i] = series[i][k];
          out.ours = vn->vector_series(field);
        }
      }
      if (!t.shown.empty()) {
        // shown in the abstract field's derivatives (Target::shown_as, checked coefficient by
        // coefficient)
        for (std::size_t i = 0; i < t.shown.size(); ++i) {
          const ex x = GiNaC::expand(t.shown[i]);
          std::vector<ex> c;
          for (std::size_t k = 0; k < series[i].size(); ++k)
            c.push_back(x.coeff(t.shown_h, static_cast<int>(k)));
          comps.push_back(by_powers_of_h(c) + fmt::format(" + \\mathcal{{O}}(h^{{{}}})", c.size()));
        }
      } else {
        for (const auto& c : series)
          comps.push_back(by_powers_of_h(c) + fmt::format(" + \\mathcal{{O}}(h^{{{}}})", c.size()));
      }
    }
    if (!t.shown_latex.empty()) {
      // in the paper's notation (Target::shown_read, read back and checked equal to the target)
      out.ours = t.shown_latex;
      if (!t.series.empty()) {
        std::size_t K = 0;
        for (const auto& c : t.series) K = std::max(K, c.size());
        if (t.through >= 0) K = std::min(K, static_cast<std::size_t>(t.through) + 1);
        out.ours += fmt::format(" + \\mathcal{{O}}(h^{{{}}})", K);
      }
    }
    if (out.ours.empty())
      out.ours = comps.size() == 1
                     ? comps[0]
                     : "\\begin{bmatrix}" + fmt::format("{}", fmt::join(comps, " \\\\ ")) +
                           "\\end{bmatrix}";
    if (!t.shown.empty() && !t.where_latex.empty()) out.ours += ",\\quad " + t.where_latex;
  }
  std::vector<Token> tokens;
  try {
    tokens = tokenize(spec.quote);
  } catch (const ReadError& e) {
    out.outcome = "unreadable";
    out.detail = e.what();
    return out;
  }
  try {
    const Differences d = differences(tokens, {}, spec, cases, true);
    if (d.through >= 0) out.through = fmt::format("through h^{}", d.through);
    if (all_vanish(d.d)) {
      out.outcome = "agrees";
      return out;
    }
    out.outcome = "differs";
    out.detail = d.first;
  } catch (const IllFormed& e) {
    out.outcome = "ill-formed";
    out.detail = e.what();
  } catch (const ReadError& e) {
    out.outcome = "unreadable";
    out.detail = e.what();
    return out;
  }
  if (!spec.search) {
    out.search = "no correction searched for (this comparison is a cross-check)";
    return out;
  }
  // The check's own correction, read and compared like the print: first when the check knows the
  // natural reading of the slip (spec.prefer_proposed), otherwise when the search finds none.
  auto try_proposed = [&] {
    if (spec.proposed.empty()) return false;
    try {
      if (all_vanish(differences(tokenize(spec.proposed), {}, spec, cases, false).d)) {
        out.corrected = spec.proposed;
        out.edit = spec.proposed_edit.empty() ? "the check's correction" : spec.proposed_edit;
        out.edit += " (stated by the check, read and compared like the print)";
        return true;
      }
    } catch (const ReadError&) {
    } catch (const IllFormed&) {
    }
    return false;
  };
  if (spec.prefer_proposed && try_proposed()) {
    out.search = "not searched: the check's correction, read and compared like the print, agrees";
    return out;
  }

  // --- the correction search ---
  int tried = 0;
  auto works = [&](const std::vector<Token>& t, const std::map<std::size_t, ex>& scale) {
    ++tried;
    try {
      const Differences d = differences(t, scale, spec, cases, false, true);
      return !d.failed && all_vanish(d.d);
    } catch (const ReadError&) {
      return false;
    } catch (const IllFormed&) {
      return false;
    } catch (const std::exception&) {  // an edited text the notation cannot evaluate
      return false;
    }
  };
  auto found = [&](const std::vector<Token>& t, const std::string& edit) {
    out.corrected = print(t);
    out.edit = edit;
  };
  const Notation& n0 = *cases[0].notation;
  const auto terms = term_ranges(tokens, n0);
  // 1. one term times λ
  const GiNaC::symbol lambda("vibook_lambda");
  const std::vector<GiNaC::symbol> params = n0.parameters();
  for (const auto& [first, end] : terms) {
    ++tried;
    try {
      const Differences d = differences(tokens, {{first, lambda}}, spec, cases, false);
      std::optional<ex> sol;
      bool linear = true;
      for (const ex& e0 : d.d) {
        const ex e = GiNaC::expand(e0);
        if (!e.is_polynomial(lambda) || e.degree(lambda) > 1) {
          linear = false;
          break;
        }
        const ex B = e.coeff(lambda, 1), A = e.coeff(lambda, 0);
        if (modified::vanishes(B)) continue;
        const ex l = GiNaC::normal(-A / B);
        if (!monomial_in(l, params)) {
          linear = false;
          break;
        }
        sol = l;
        break;
      }
      if (!linear || !sol || *sol == 1) continue;
      std::vector<ex> subst;
      for (const ex& e : d.d) subst.push_back(e.subs(lambda == *sol));
      if (!all_vanish(subst)) continue;
      const std::string term = term_text(tokens, with_sizing(tokens, first), end);
      std::string edit;
      if (sol->is_zero())
        edit = "the term \\(" + term + "\\) removed";
      else if (*sol == -1)
        edit = "the sign of the term \\(" + term + "\\) reversed";
      else
        edit = "the term \\(" + term + "\\) multiplied by \\(" + latex(*sol) + "\\)";
      found(scaled_tokens(tokens, first, end, *sol), edit);
      break;
    } catch (const ReadError&) {
    } catch (const IllFormed&) {
    }
  }
  // 2. one token changed
  std::vector<Candidate> singles;
  if (out.edit.empty()) {
    const int dim = std::max(2, n0.dim());
    for (const auto& s : subscript_digits(tokens))
      for (int v = 1; v <= dim; ++v) {
        if (std::to_string(v) == tokens[s.pos].text) continue;
        Candidate c{tokens, {}, ""};
        c.tokens[s.pos].text = std::to_string(v);
        c.edit =
            fmt::format("the subscript {} of \\({}\\) read as {}", tokens[s.pos].text, s.symbol, v);
        singles.push_back(c);
      }
    for (std::size_t k = 0; k < tokens.size(); ++k) {
      if (tokens[k].cmd("dot") || tokens[k].cmd("ddot")) {
        Candidate c{tokens, {}, ""};
        c.tokens[k].text = tokens[k].text == "dot" ? "ddot" : "dot";
        // The accent with its argument (a bare \dot is a MathJax error): the next letter or
        // braced group, as printed.
        auto argument = [&tokens](std::size_t j) {
          std::size_t e = j + 1;
          if (e < tokens.size() && tokens[e].sym("{")) {
            for (int depth = 0; e < tokens.size(); ++e) {
              depth += tokens[e].sym("{") ? 1 : tokens[e].sym("}") ? -1 : 0;
              if (depth == 0) break;
            }
            e = std::min(e + 1, tokens.size());
          } else if (e < tokens.size()) {
            ++e;
          }
          return e > j + 1 ? term_text(tokens, j + 1, e) : std::string("{}");
        };
        const std::string arg = argument(k);
        c.edit = "\\(\\" + tokens[k].text + " " + arg + "\\) read as \\(\\" + c.tokens[k].text +
                 " " + arg + "\\)" + which(tokens.size(), k, [&](std::size_t j) {
                   return tokens[j].cmd(tokens[k].text) ? argument(j) : std::string();
                 });
        singles.push_back(c);
      }
      if ((tokens[k].kind == Token::Kind::letter ||
           (tokens[k].kind == Token::Kind::command && tokens[k].text.size() > 2 &&
            std::islower(static_cast<unsigned char>(tokens[k].text[0])) == 0 && false)) &&
          !(k + 1 < tokens.size() && tokens[k + 1].sym("'")) &&
          !(k > 0 && tokens[k - 1].sym("_")) &&
          !(k > 0 && tokens[k - 1].sym("{") && k > 1 &&
            tokens[k - 2].kind == Token::Kind::command)) {
        // a first prime on a letter (U → U')
        Candidate add{tokens, {}, ""};
        add.tokens.insert(add.tokens.begin() + static_cast<std::ptrdiff_t>(k) + 1,
                          make(Token::Kind::symbol, "'"));
        add.edit = "a prime added to \\(" + tokens[k].text + "\\)" +
                   which(tokens.size(), k, [&](std::size_t j) {
                     return tokens[j].kind == tokens[k].kind ? tokens[j].text : std::string();
                   });
        singles.push_back(add);
      }
      if (tokens[k].sym("'")) {
        // The primed symbol as printed (its letter and all its primes), counted among the
        // symbols printed the same way.
        auto primed = [&tokens](std::size_t j) {
          if (!tokens[j].sym("'")) return std::string();
          std::size_t b = j, e = j;
          while (b > 0 && tokens[b - 1].sym("'")) --b;
          while (e < tokens.size() && tokens[e].sym("'")) ++e;
          return b > 0 ? term_text(tokens, b - 1, e) : std::string();
        };
        auto first_prime = [&tokens, &primed](std::size_t j) {
          return j > 0 && tokens[j - 1].sym("'") ? std::string() : primed(j);
        };
        std::size_t run = k;
        while (run > 0 && tokens[run - 1].sym("'")) --run;
        const std::string where =
            "\\(" + primed(k) + "\\)" + which(tokens.size(), run, first_prime);
        Candidate add{tokens, {}, ""};
        add.tokens.insert(add.tokens.begin() + static_cast<std::ptrdiff_t>(k),
                          make(Token::Kind::symbol, "'"));
        add.edit = "one prime more on " + where;
        singles.push_back(add);
        Candidate del{tokens, {}, ""};
        del.tokens.erase(del.tokens.begin() + static_cast<std::ptrdiff_t>(k));
        del.edit = "one prime less on " + where;
        singles.push_back(del);
      }
    }
    const std::vector<std::size_t> exponents = superscript_integers(tokens);
    for (std::size_t pos : exponents)
      for (int dv : {-1, 1}) {
        const numeric v = numeric(tokens[pos].text.c_str()) + dv;
        if (v.is_negative()) continue;
        Candidate c{tokens, {}, ""};
        c.tokens[pos].text = str(v);
        c.edit = "the exponent " + tokens[pos].text +
                 which(tokens.size(), pos,
                       [&](std::size_t j) {
                         return std::find(exponents.begin(), exponents.end(), j) != exponents.end()
                                    ? tokens[j].text
                                    : std::string();
                       }) +
                 " read as " + str(v);
        singles.push_back(c);
      }
    for (const auto& c : singles)
      if (works(c.tokens, c.scale)) {
        found(c.tokens, c.edit);
        break;
      }
  }
  // 3. two subscript digits swapped throughout one symbol, in the whole quote or in one
  // member of it (the part between two top-level relations)
  std::vector<std::pair<std::size_t, std::size_t>> segments = {{0, tokens.size()}};
  {
    int depth = 0;
    std::size_t start = 0;
    std::vector<std::pair<std::size_t, std::size_t>> parts;
    for (std::size_t k = 0; k < tokens.size(); ++k) {
      const Token& x = tokens[k];
      if (x.sym("(") || x.sym("[") || x.sym("{") || x.cmd("langle")) ++depth;
      if (x.sym(")") || x.sym("]") || x.sym("}") || x.cmd("rangle")) --depth;
      if (depth == 0 && x.sym("=")) {
        parts.emplace_back(start, k);
        start = k + 1;
      }
    }
    parts.emplace_back(start, tokens.size());
    if (parts.size() > 1) segments.insert(segments.end(), parts.begin(), parts.end());
  }
  for (const auto& [seg_b, seg_e] : segments) {
    if (!out.edit.empty()) break;
    {
      std::map<std::string, std::vector<std::size_t>> by_symbol;
      for (const auto& s : subscript_digits(tokens))
        if (s.pos >= seg_b && s.pos < seg_e) by_symbol[s.symbol].push_back(s.pos);
      for (const auto& [sym, pos] : by_symbol) {
        std::set<std::string> digits;
        for (auto p : pos) digits.insert(tokens[p].text);
        if (digits.size() < 2) continue;
        const std::vector<std::string> ds(digits.begin(), digits.end());
        for (std::size_t a = 0; a < ds.size() && out.edit.empty(); ++a)
          for (std::size_t b = a + 1; b < ds.size() && out.edit.empty(); ++b) {
            std::vector<Token> t = tokens;
            for (auto p : pos) {
              if (t[p].text == ds[a])
                t[p].text = ds[b];
              else if (t[p].text == ds[b])
                t[p].text = ds[a];
            }
            if (works(t, {}))
              found(t, fmt::format("the subscripts {} and {} of \\({}\\) exchanged throughout{}",
                                   ds[a], ds[b], sym,
                                   seg_b == 0 && seg_e == tokens.size() ? "" : " the last member"));
          }
        if (!out.edit.empty()) break;
      }
    }
  }
  // 4. one argument deleted
  if (out.edit.empty()) {
    const auto items = list_items(tokens);
    for (const auto& [b, e] : items) {
      std::vector<Token> t = tokens;
      t.erase(t.begin() + static_cast<std::ptrdiff_t>(b),
              t.begin() + static_cast<std::ptrdiff_t>(e));
      if (works(t, {})) {
        found(t, "the argument \\(" + term_text(tokens, b + 1, e) + "\\)" +
                     which(tokens.size(), b,
                           [&](std::size_t j) {
                             for (const auto& [bj, ej] : items)
                               if (bj == j) return term_text(tokens, bj + 1, ej);
                             return std::string();
                           }) +
                     " removed");
        break;
      }
    }
  }
  // 5. two accented forms of one letter exchanged throughout; the variable of d/dX changed
  if (out.edit.empty()) {
    std::map<std::string, std::map<std::string, std::vector<std::size_t>>> accented;
    for (std::size_t k = 0; k + 3 < tokens.size(); ++k)
      if (tokens[k].kind == Token::Kind::command &&
          (tokens[k].text == "hat" || tokens[k].text == "bar" || tokens[k].text == "tilde" ||
           tokens[k].text == "dot" || tokens[k].text == "ddot") &&
          tokens[k + 1].sym("{") && tokens[k + 3].sym("}"))
        accented[tokens[k + 2].text][tokens[k].text].push_back(k);
    for (const auto& [letter, forms] : accented) {
      if (forms.size() < 2 || !out.edit.empty()) continue;
      for (auto a = forms.begin(); a != forms.end() && out.edit.empty(); ++a)
        for (auto b = std::next(a); b != forms.end() && out.edit.empty(); ++b) {
          std::vector<Token> t = tokens;
          for (auto k : a->second) t[k].text = b->first;
          for (auto k : b->second) t[k].text = a->first;
          if (works(t, {}))
            found(t, "\\(\\" + a->first + "{" + letter + "}\\) and \\(\\" + b->first + "{" +
                         letter + "}\\) exchanged throughout");
        }
    }
  }
  if (out.edit.empty()) {
    for (std::size_t k = 0; k + 1 < tokens.size() && out.edit.empty(); ++k) {
      // \frac{d…}{d X…}: X is the letter after a d that follows an opening brace
      if (!(tokens[k].is(Token::Kind::letter, "d") && k > 0 && tokens[k - 1].sym("{") &&
            tokens[k + 1].kind == Token::Kind::letter && k >= 2 && tokens[k - 2].sym("}")))
        continue;
      for (const char* v : {"t", "a", "s", "\\tau"}) {
        if (tokens[k + 1].text == v) continue;
        std::vector<Token> t = tokens;
        t[k + 1] = tokenize(v).front();
        if (works(t, {})) {
          found(t, "\\(d/d" + tokens[k + 1].text + "\\)" +
                       which(tokens.size(), k,
                             [&](std::size_t j) {
                               return j + 1 < tokens.size() &&
                                              tokens[j].is(Token::Kind::letter, "d") && j >= 2 &&
                                              tokens[j - 1].sym("{") && tokens[j - 2].sym("}") &&
                                              tokens[j + 1].kind == Token::Kind::letter
                                          ? tokens[j + 1].text
                                          : std::string();
                             }) +
                       " read as \\(d/d" + v + "\\)");
          break;
        }
      }
    }
  }
  // 6. two edits: two sign reversals, or a sign reversal and a token change
  if (out.edit.empty()) {
    std::vector<Candidate> flips;
    for (const auto& [first, end] : terms)
      flips.push_back({tokens,
                       {{first, ex(-1)}},
                       "the sign of \\(" + term_text(tokens, first, end) + "\\) reversed"});
    const std::size_t budget = 600;
    std::size_t spent = 0;
    for (std::size_t i = 0; i < flips.size() && out.edit.empty() && spent < budget; ++i)
      for (std::size_t j = i + 1; j < flips.size() && out.edit.empty() && spent < budget;
           ++j, ++spent) {
        std::map<std::size_t, ex> sc = flips[i].scale;
        sc.insert(flips[j].scale.begin(), flips[j].scale.end());
        if (works(tokens, sc)) {
          const std::vector<Token> t =
              scaled_tokens(tokens, terms[j].first, terms[j].second, numeric(-1));
          found(scaled_tokens(t, terms[i].first, terms[i].second, numeric(-1)),
                flips[i].edit + " and " + flips[j].edit);
        }
      }
    for (std::size_t i = 0; i < flips.size() && out.edit.empty() && spent < budget; ++i)
      for (std::size_t j = 0; j < singles.size() && out.edit.empty() && spent < budget;
           ++j, ++spent)
        if (singles[j].tokens.size() == tokens.size() && works(singles[j].tokens, flips[i].scale))
          found(scaled_tokens(singles[j].tokens, terms[i].first, terms[i].second, numeric(-1)),
                flips[i].edit + " and " + singles[j].edit);
    // two single changes in place (the same slip in two components: ẋ₁ and ẋ₂ for ẍ₁, ẍ₂)
    auto changed_at = [&](const Candidate& c) {
      std::size_t at = std::string::npos;
      if (c.tokens.size() != tokens.size()) return at;
      for (std::size_t k = 0; k < tokens.size(); ++k)
        if (c.tokens[k].text != tokens[k].text)
          return at == std::string::npos ? (at = k) : std::string::npos;
      return at;
    };
    for (std::size_t i = 0; i < singles.size() && out.edit.empty() && spent < budget; ++i) {
      const std::size_t a = changed_at(singles[i]);
      if (a == std::string::npos) continue;
      for (std::size_t j = i + 1; j < singles.size() && out.edit.empty() && spent < budget; ++j) {
        const std::size_t b = changed_at(singles[j]);
        if (b == std::string::npos || b == a) continue;
        ++spent;
        std::vector<Token> t = singles[i].tokens;
        t[b] = singles[j].tokens[b];
        if (works(t, {})) found(t, singles[i].edit + " and " + singles[j].edit);
      }
    }
  }
  if (out.edit.empty()) try_proposed();
  out.search = fmt::format(
      "searched: one term times a rational λ or a monomial in the parameters ({} terms), one "
      "subscript, accent, prime or exponent changed ({} candidates), subscript pairs exchanged "
      "throughout a symbol, one argument removed, two accents of a letter exchanged, the "
      "variable of a derivative changed, and pairs of sign reversals and single changes, or of "
      "two single changes (at most 600 pairs); {} readings in all",
      terms.size(), singles.size(), tried);
  return out;
}

claims::ClaimResult erratum_for(const claims::FormulaComparison& c, const std::string& id,
                                const std::string& title, const std::string& context) {
  claims::ClaimResult r;
  r.id = id;
  r.source = c.check;
  r.info = claims::ClaimInfo{id, c.paper, c.label, title};
  const bool found = !c.corrected.empty();
  const bool replaced = !found && !c.verified.empty();
  r.status = found || replaced ? claims::Status::erratum : claims::Status::not_reproduced;
  r.cause = found ? "misprint" : "does-not-hold";
  r.values = {{"printed_agrees", 0.0}, {"small_correction_found", found ? 1.0 : 0.0}};
  // The corrected display as mathematics, without the paper's tag ("\\quad (39)") and the
  // punctuation that ends it in the paper.
  std::string corrected = c.corrected;
  if (const auto tag = corrected.rfind("\\quad");
      tag != std::string::npos &&
      corrected.find_first_not_of(" ()0123456789.abcdefghijklmnopqrstuvwxyz,", tag + 5) ==
          std::string::npos)
    corrected.erase(tag);
  while (!corrected.empty() &&
         (corrected.back() == ',' || corrected.back() == '.' || corrected.back() == ' '))
    corrected.pop_back();
  // A display the paper sets over two lines (\\ and an & alignment point) is one line here.
  for (std::size_t at; (at = corrected.find("\\\\")) != std::string::npos;)
    corrected.replace(at, 2, " ");
  std::erase(corrected, '&');
  if (!corrected.empty()) corrected = "\\(" + corrected + "\\)";
  r.note = fmt::format(
      "Printed {} ({}): {}. {}", c.label, c.part,
      c.outcome == "ill-formed" ? "ill-formed as printed, " + c.detail : "differs, " + c.detail,
      found ? "Corrected (" + c.edit + "): " + corrected + ", which agrees with " + c.against +
                  " " + c.through + "."
      : replaced
          ? "No small edit corrects it (" + c.search + "); the correct formula is " + c.against +
                ", shown beside the print, verified independently: " + c.verified + "."
          : "No correction found; " + c.search + ".");
  if (!context.empty()) r.note += " " + context;
  r.comparisons = {c};
  return r;
}

}  // namespace vibook::printed

namespace vibook::printed {

// Abstract calls (and their derivatives) at the jet point x as the engine's derivative symbols
// U_1, phi1_12, …; calls elsewhere are left as they are.
ex at_jet_point(const ex& e, const modified::JetSpace& J) {
  struct Map : GiNaC::map_function {
    const modified::JetSpace& J;
    explicit Map(const modified::JetSpace& j) : J(j) {}
    ex operator()(const ex& x) override {
      int family = 0;
      std::vector<ex> args;
      std::vector<int> index;
      if (modified::match_abstract(x, family, args, index)) {
        bool at_x = static_cast<int>(args.size()) == J.family_arity(family);
        for (std::size_t k = 0; at_x && k < args.size(); ++k)
          at_x =
              GiNaC::expand(args[k] - J.x(0, J.family_dof(family, static_cast<int>(k)))).is_zero();
        if (at_x) return J.derivative(family, index);
        return x;
      }
      return x.map(*this);
    }
  } m(J);
  return m(e);
}

std::string erratum_id(const claims::FormulaComparison& c, const ErratumNames& names) {
  for (const auto& [display, id] : names)
    if (display == c.display) return id;
  const std::string d =
      c.display.front() == '(' ? c.display.substr(1, c.display.size() - 2) : c.display;
  return c.paper + "-ERR-" + d;
}

void conclude(claims::ClaimResult& claim, std::vector<claims::FormulaComparison> comparisons,
              std::vector<claims::ClaimResult>& errata, const ErratumNames& names) {
  int agree = 0, corrected = 0, replaced = 0, uncorrected = 0, unreadable = 0;
  std::string unread;
  std::vector<std::string> found_in;  // the errata of these comparisons (one per display)
  for (const auto& c : comparisons) {
    if (agrees(c) || c.role == "cross-check") {
      agree += agrees(c) ? 1 : 0;
      continue;
    }
    if (c.outcome == "unreadable") {
      ++unreadable;
      unread += (unread.empty() ? "" : "; ") + c.label + ": " + c.detail;
      continue;
    }
    const std::string id = erratum_id(c, names);
    const std::string title = c.part + (c.edit.empty() ? " does not agree" : ": " + c.edit);
    // one erratum per display: a second comparison of the same display joins the first
    auto it = std::find_if(errata.begin(), errata.end(),
                           [&](const claims::ClaimResult& e) { return e.id == id; });
    if (it == errata.end()) {
      errata.push_back(erratum_for(c, id, title));
    } else {
      it->comparisons.push_back(c);
      const claims::ClaimResult more = erratum_for(c, id, title);
      it->note += " | " + more.note;
      if (more.status == claims::Status::not_reproduced) it->status = more.status;
      if (it->cause.empty() || more.cause == "does-not-hold") it->cause = more.cause;
    }
    if (std::find(claim.errata.begin(), claim.errata.end(), id) == claim.errata.end())
      claim.errata.push_back(id);
    if (std::find(found_in.begin(), found_in.end(), id) == found_in.end()) found_in.push_back(id);
    if (!c.corrected.empty())
      corrected += 1;
    else if (!c.verified.empty())
      replaced += 1;
    else
      uncorrected += 1;
  }
  claim.values.push_back({"displays_compared", static_cast<double>(comparisons.size())});
  claim.values.push_back({"displays_agreeing", static_cast<double>(agree)});
  claim.comparisons.insert(claim.comparisons.end(), comparisons.begin(), comparisons.end());
  std::string summary =
      fmt::format(" Printed displays read from the paper and compared: {}, agreeing {}",
                  comparisons.size(), agree);
  // The errata of these comparisons only (a claim may list others, measured, not read); a
  // display compared in several parts is one erratum.
  const int wrong = corrected + replaced + uncorrected;
  if (wrong > 0)
    summary += wrong == static_cast<int>(found_in.size())
                   ? fmt::format(", found wrong {} ({})", wrong, fmt::join(found_in, ", "))
                   : fmt::format(", found wrong {} (in {} errat{}: {})", wrong, found_in.size(),
                                 found_in.size() == 1 ? "um" : "a", fmt::join(found_in, ", "));
  if (unreadable > 0) summary += fmt::format(", not read {} ({})", unreadable, unread);
  claim.note += summary + ".";
  // The headline: what is wrong, display by display (once per display).
  std::vector<std::string> heads;
  std::set<std::string> headed;
  for (const auto& c : comparisons) {
    if (agrees(c) || c.role == "cross-check" || !headed.insert(c.paper + c.display).second)
      continue;
    if (c.outcome == "unreadable")
      heads.push_back(c.label + " could not be read");
    else if (!c.corrected.empty())
      heads.push_back(c.label + " misprinted (" + erratum_id(c, names) + "): " + c.edit);
    else
      heads.push_back(c.label + " does not hold (" + c.part + ")");
  }
  if (!heads.empty()) {
    const std::string h = fmt::format("{}", fmt::join(heads, "; "));
    claim.headline = claim.headline.empty() ? h : claim.headline + "; " + h;
  }
  // [printed-verdict]
  // A display that cannot be read, or that differs with no small correction, makes the claim
  // not reproduced; displays that differ only by corrected misprints make it an erratum
  // (cause "misprint"), unless the check's own measurement already failed.
  if (unreadable > 0 || uncorrected > 0 || replaced > 0) {
    claim.status = claims::Status::not_reproduced;
    claim.cause = uncorrected + replaced > 0 ? "does-not-hold" : "";
    if (uncorrected + replaced == 0)
      claim.note += " A display the reader cannot read is not a comparison.";
  } else if (corrected > 0) {
    if (claim.status != claims::Status::not_reproduced) {
      claim.status = claims::Status::erratum;
      claim.cause = "misprint";
    }
  }
  // [printed-verdict]
}

}  // namespace vibook::printed
