/// \file splitting_sequence.hpp
/// \brief Splitting methods as the field publishes them: a sequence of the two flows of
/// H = T(p) + V(q), the drift φ^T_{a h} (q += a h ∇T(p)) and the kick φ^V_{b h}
/// (p −= b h ∇V(q)), in the order they act on the state, each with its coefficient
/// (Hairer, Lubich & Wanner, *Geometric Numerical Integration*, §II.5 and §III.3; McLachlan &
/// Quispel 2002, Acta Numerica 11, 341). The sequence is parsed from text with exact
/// coefficients (ratios, decimals, or expressions with radicals, evaluated in any precision),
/// and a catalogue holds published methods with their sources.
///
/// **Order conditions for two non-commuting flows.** The flows are exp(a h A) and exp(b h B),
/// A and B the Lie derivatives of the two vector fields. In the free associative algebra on the
/// letters A and B (each of weight 1), truncated at a weight W, the logarithm of the product of
/// the flows is computed as for compositions (composition.hpp): the method has order p for every
/// pair of vector fields if and only if that logarithm equals h(A + B) up to weight p, that is
/// Σa = Σb = 1 and every word of weight 2…p has coefficient 0. These are the conditions for a
/// generic splitting; a method designed for T quadratic in p (Runge–Kutta–Nyström splittings,
/// where [B,[B,[B,A]]] = 0) can reach a higher order on such systems than they give, never a
/// lower one. For T = |p|²/2 the sequence is a Runge–Kutta–Nyström method (as_rkn_tableau),
/// and the conditions of its Nyström trees (rkn.hpp) give its exact order there.
///
/// **The equivalent composition.** A consistent sequence (Σa = Σb) is a composition of
/// symplectic Euler Φ_c = φ^V_c ∘ φ^T_c (drift, then kick) and its adjoint Φ*_c (kick, then
/// drift): consecutive flows of one kind are merged, and with the flows f₁, f₂, … alternating
/// in kind, stage j covers the rest of f_j and the start of f_{j+1}, γ_j = a_j − γ_{j−1}
/// (γ₀ = 0), its kind that of f_j (a drift first: Φ; a kick first: Φ*); the last flow is covered
/// exactly when the drifts and the kicks sum to the same total. Through it every measured phase
/// of a composition (composition_study.hpp) applies to a splitting unchanged.
///
/// Chapter: \ref chapter-verify (section "Splittings").
#pragma once

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "vibook/core/errors.hpp"
#include "vibook/integrators/composition.hpp"
#include "vibook/integrators/rkn.hpp"

namespace vibook::composition {

/// One flow of a splitting: the drift (T) or the kick (V) over c·h.
template <class Real>
struct Flow {
  bool kick = false;
  Real c;
};

/// A splitting method: its flows in the order they act on the state.
template <class Real>
using Sequence = std::vector<Flow<Real>>;

/// Evaluate an exact coefficient typed as text: numbers (decimal, with an exponent), + − * /,
/// ^ (a power), parentheses, sqrt(…) and cbrt(…), in Real. "1/(2 - 2^(1/3))",
/// "1/2 - sqrt(3)/6", "0.1931833275037836". ArgumentError naming `arg` otherwise.
template <class Real>
Real evaluate_coefficient(const std::string& arg, const std::string& text) {
  std::size_t i = 0;
  auto fail = [&](const std::string& why) -> Real {
    throw ArgumentError(arg, "'" + text + "' " + why +
                                 " (a coefficient is a number, a ratio, or an expression with + "
                                 "- * / ^, parentheses, sqrt and cbrt)");
  };
  auto skip = [&] {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
  };
  int depth = 0;
  // Recursive descent: expr = term {(+|-) term}; term = unary {(*|/) unary};
  // unary = (+|-) unary | power; power = primary [^ unary]; primary = number | (expr) | f(expr).
  std::function<Real()> expr, term, unary, power, primary;
  primary = [&]() -> Real {
    skip();
    if (i >= text.size()) return fail("ends early");
    if (text[i] == '(') {
      if (++depth > 64) return fail("nests too deeply");
      ++i;
      const Real v = expr();
      skip();
      if (i >= text.size() || text[i] != ')') return fail("has a '(' without its ')'");
      ++i;
      --depth;
      return v;
    }
    for (const char* f : {"sqrt", "cbrt"}) {
      const std::string name(f);
      if (text.compare(i, name.size(), name) == 0) {
        i += name.size();
        skip();
        if (i >= text.size() || text[i] != '(') return fail("needs a '(' after " + name);
        const Real v = primary();
        if (name == "sqrt") {
          if (v < 0) return fail("takes the square root of a negative number");
          return sqrt(v);
        }
        return cbrt(v);
      }
    }
    const std::size_t start = i;
    bool digits = false, point = false;
    for (; i < text.size() && (std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '.');
         ++i) {
      if (text[i] == '.') {
        if (point) return fail("has a number with two decimal points");
        point = true;
      } else {
        digits = true;
      }
    }
    if (!digits) return fail("is not a coefficient");
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
      ++i;
      if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
      bool ed = false;
      for (; i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); ++i) ed = true;
      if (!ed) return fail("has an exponent without digits");
    }
    return Real(text.substr(start, i - start));
  };
  power = [&]() -> Real {
    const Real b = primary();
    skip();
    if (i < text.size() && text[i] == '^') {
      ++i;
      const Real e = unary();
      if (b < 0) return fail("raises a negative number to a power");
      return pow(b, e);
    }
    return b;
  };
  unary = [&]() -> Real {
    skip();
    if (i < text.size() && (text[i] == '-' || text[i] == '+')) {
      const bool minus = text[i] == '-';
      ++i;
      const Real v = unary();
      return minus ? Real(-v) : v;
    }
    return power();
  };
  term = [&]() -> Real {
    Real v = unary();
    for (;;) {
      skip();
      if (i >= text.size() || (text[i] != '*' && text[i] != '/')) return v;
      const char op = text[i++];
      const Real w = unary();
      if (op == '/') {
        if (w == 0) return fail("divides by zero");
        v /= w;
      } else {
        v *= w;
      }
    }
  };
  expr = [&]() -> Real {
    Real v = term();
    for (;;) {
      skip();
      if (i >= text.size() || (text[i] != '+' && text[i] != '-')) return v;
      const char op = text[i++];
      const Real w = term();
      v = op == '+' ? Real(v + w) : Real(v - w);
    }
  };
  const Real v = expr();
  skip();
  if (i != text.size()) return fail("has '" + text.substr(i, 20) + "' left over");
  using std::isfinite;
  if (!isfinite(static_cast<double>(v))) return fail("is not a finite number");
  return v;
}

/// Parse "drift:c1,kick:d1,drift:c2,…" (the flows in the order they act). Each coefficient is
/// an expression of evaluate_coefficient. ArgumentError naming `arg` for anything else.
template <class Real>
Sequence<Real> parse_sequence(const std::string& arg, const std::string& text) {
  Sequence<Real> s;
  std::size_t from = 0;
  while (from <= text.size()) {
    const auto comma = std::min(text.find(',', from), text.size());
    std::string item = text.substr(from, comma - from);
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    const auto colon = item.find(':');
    const std::string kind = item.substr(0, colon);
    if (colon == std::string::npos || (kind != "drift" && kind != "kick"))
      throw ArgumentError(arg, "flow " + std::to_string(s.size() + 1) + " ('" + item.substr(0, 40) +
                                   "') is not drift:COEFFICIENT or kick:COEFFICIENT");
    s.push_back({kind == "kick", evaluate_coefficient<Real>(arg, item.substr(colon + 1))});
    from = comma + 1;
  }
  return s;
}

/// Consecutive flows of one kind merged (their coefficients added), zero flows dropped.
template <class Real>
Sequence<Real> merged(const Sequence<Real>& s) {
  Sequence<Real> m;
  for (const auto& f : s) {
    if (f.c == 0) continue;
    if (!m.empty() && m.back().kick == f.kick) {
      m.back().c += f.c;
      if (m.back().c == 0) m.pop_back();
    } else {
      m.push_back(f);
    }
  }
  return m;
}

/// Whether the sequence reads the same from either end (a palindrome: the method is
/// symmetric), to `tol`.
template <class Real>
bool is_palindrome(const Sequence<Real>& s, double tol) {
  const Sequence<Real> m = merged(s);
  for (std::size_t i = 0, j = m.size(); i < j--; ++i) {
    using std::abs;
    if (m[i].kick != m[j].kick || abs(Real(m[i].c - m[j].c)) > tol) return false;
  }
  return true;
}

/// Σ of the drifts' and of the kicks' coefficients.
template <class Real>
std::pair<Real, Real> totals(const Sequence<Real>& s) {
  Real a = 0, b = 0;
  for (const auto& f : s) (f.kick ? b : a) += f.c;
  return {a, b};
}

/// The equivalent composition of symplectic Euler (drift, then kick) and its adjoint (kick,
/// then drift; `adjoint` set), or an empty list when there is none: a single kind of flow, or
/// drifts and kicks that do not sum to the same total (to `tol`).
template <class Real>
Stages<Real> as_symplectic_euler_composition(const Sequence<Real>& s, double tol) {
  const Sequence<Real> m = merged(s);
  Stages<Real> st;
  if (m.size() < 2) return st;
  Real gamma = 0;
  for (std::size_t j = 0; j + 1 < m.size(); ++j) {
    gamma = m[j].c - gamma;
    st.push_back({gamma, m[j].kick});
  }
  using std::abs;
  if (abs(Real(m.back().c - gamma)) > tol) return {};
  return st;
}

// -------------------------------------------------------------------------------------------
// The free associative algebra on two letters A (drift) and B (kick), truncated at weight W
// -------------------------------------------------------------------------------------------

/// Words over {A, B} of length ≤ W; word (n, bits) has length n, its letters the bits from the
/// highest (1 = B). Index: 2ⁿ − 1 + bits.
class TwoLetterAlgebra {
 public:
  explicit TwoLetterAlgebra(int max_weight) : w_(max_weight) {
    if (max_weight < 1 || max_weight > 12)
      throw std::invalid_argument("TwoLetterAlgebra: weight must lie in 1..12");
  }
  int max_weight() const { return w_; }
  int size() const { return (1 << (w_ + 1)) - 1; }
  static int index(int n, unsigned bits) { return (1 << n) - 1 + static_cast<int>(bits); }
  static int length(int i) {
    int n = 0;
    while (i >= (1 << (n + 1)) - 1) ++n;
    return n;
  }
  /// "A B A" for a word.
  static std::string name(int i) {
    const int n = length(i);
    const unsigned bits = static_cast<unsigned>(i - ((1 << n) - 1));
    std::string s;
    for (int k = n - 1; k >= 0; --k)
      s += std::string(s.empty() ? "" : " ") + ((bits >> k) & 1u ? "B" : "A");
    return s.empty() ? "1" : s;
  }

 private:
  int w_;
};

/// log of the product of the flows in the two-letter algebra (letters stand for hA and hB).
template <class Real>
Series<Real> splitting_log(const TwoLetterAlgebra& T, const Sequence<Real>& s) {
  const int W = T.max_weight();
  const auto n_words = static_cast<std::size_t>(T.size());
  auto multiply = [&](const Series<Real>& x, const Series<Real>& y) {
    Series<Real> z(n_words, Real(0));
    for (int n = 0; n <= W; ++n)
      for (unsigned a = 0; a < (1u << n); ++a) {
        const Real& xa = x[static_cast<std::size_t>(TwoLetterAlgebra::index(n, a))];
        if (xa == 0) continue;
        for (int m = 0; n + m <= W; ++m)
          for (unsigned b = 0; b < (1u << m); ++b) {
            const Real& yb = y[static_cast<std::size_t>(TwoLetterAlgebra::index(m, b))];
            if (yb == 0) continue;
            z[static_cast<std::size_t>(TwoLetterAlgebra::index(n + m, (a << m) | b))] += xa * yb;
          }
      }
    return z;
  };
  Series<Real> Z(n_words, Real(0));
  Z[0] = Real(1);
  for (const auto& f : merged(s)) {
    // exp(c X) for one letter X: Σ cⁿ Xⁿ / n!, the word X…X of length n
    Series<Real> E(n_words, Real(0));
    Real term = Real(1);
    E[0] = term;
    for (int n = 1; n <= W; ++n) {
      term *= f.c;
      term /= n;
      E[static_cast<std::size_t>(TwoLetterAlgebra::index(n, f.kick ? (1u << n) - 1 : 0u))] = term;
    }
    Z = multiply(Z, E);
  }
  // log Z = Σ (−1)^{n+1} (Z − 1)ⁿ / n
  Series<Real> X = Z;
  X[0] = Real(0);
  Series<Real> L(n_words, Real(0)), P(n_words, Real(0));
  P[0] = Real(1);
  for (int n = 1; n <= W; ++n) {
    P = multiply(P, X);
    const Real c = Real(n % 2 == 1 ? 1 : -1) / Real(n);
    for (std::size_t i = 0; i < n_words; ++i) L[i] += c * P[i];
  }
  return L;
}

/// The order conditions of a splitting for two generic flows, weight by weight: the deviation
/// of its logarithm from h(A + B). Same meaning of the fields as for a composition.
template <class Real>
OrderConditions splitting_order_conditions(const Sequence<Real>& s, int max_weight,
                                           double tolerance = 1e-12) {
  const TwoLetterAlgebra T(max_weight);
  Series<Real> r = splitting_log(T, s);
  r[static_cast<std::size_t>(TwoLetterAlgebra::index(1, 0))] -= Real(1);
  r[static_cast<std::size_t>(TwoLetterAlgebra::index(1, 1))] -= Real(1);
  return conditions_from(r, max_weight, false, tolerance, &TwoLetterAlgebra::length,
                         &TwoLetterAlgebra::name);
}

/// The splitting as a Runge–Kutta–Nyström tableau (rkn.hpp), for H = |p|²/2 + V(q), i.e.
/// q'' = f(q): one stage per kick, at the drift total before it, c_k; a kick j before stage k
/// reaches it through the drifts between them, ā_kj = b_j (c_k − c_j); and b̄_j = b_j (D − c_j)
/// with D the drifts' total, returned in `drift_total`: the method is q1 = q0 + D h p0 + h² Σ
/// b̄_j f(Q_j), an RKN method when D = 1, and D − 1 is the residual of the positions' condition
/// of order 1 (published digits leave it at their rounding). Such a tableau is symplectic (both
/// conditions hold identically). Its Nyström conditions are the splitting's order conditions on
/// every system with kinetic energy |p|²/2, where [B, [B, [B, A]]] = 0 and a method can reach a
/// higher order than for two generic flows (McLachlan and Atela's and Blanes and Moan's RKN
/// splittings).
template <class Real>
RknTableauT<Real> as_rkn_tableau(const Sequence<Real>& s, Real* drift_total = nullptr) {
  RknTableauT<Real> t;
  Real drift(0);
  for (const auto& f : s) {
    if (!f.kick) {
      drift += f.c;
      continue;
    }
    t.c.push_back(drift);
    t.b.push_back(f.c);
  }
  const std::size_t n = t.b.size();
  t.abar.assign(n, std::vector<Real>(n, Real(0)));
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t j = 0; j < k; ++j) t.abar[k][j] = t.b[j] * (t.c[k] - t.c[j]);
  for (std::size_t j = 0; j < n; ++j) t.bbar.push_back(t.b[j] * (drift - t.c[j]));
  if (drift_total) *drift_total = drift;
  return t;
}

/// The order conditions of a splitting on T = |p|²/2: the Nyström trees' conditions of its RKN
/// tableau (as_rkn_tableau), with the drifts' total D − 1 joining the residual of order 1.
template <class Real>
OrderConditions splitting_nystrom_conditions(const Sequence<Real>& s, int max_order,
                                             double tolerance = 1e-12) {
  Real drift(0);
  const RknConditions<Real> rc = rkn_conditions(as_rkn_tableau(s, &drift), max_order);
  OrderConditions oc = conditions_from(
      rc.value, max_order, false, tolerance,
      [&rc](int w) { return rc.order[static_cast<std::size_t>(w)]; },
      [&rc](int w) { return rc.name[static_cast<std::size_t>(w)]; });
  using std::abs;
  const double d = static_cast<double>(abs(Real(drift - Real(1))));
  if (max_order >= 1 && d > oc.residual[0]) {
    oc.residual[0] = d;
    oc.worst_word[0] = "q: p (the drifts' total)";
  }
  oc.order = 0;
  while (oc.order < max_order && oc.residual[static_cast<std::size_t>(oc.order)] <= tolerance)
    ++oc.order;
  return oc;
}

// -------------------------------------------------------------------------------------------
// The catalogue
// -------------------------------------------------------------------------------------------

/// A published splitting method: its flows as text (exact where the source gives a closed form)
/// and its documented order, for two generic flows or, with `rkn`, for kinetic energy
/// |p|²/2 only (a Runge–Kutta–Nyström splitting: its generic order is lower, and the Nyström
/// trees' conditions of as_rkn_tableau give the documented one).
struct SplittingEntry {
  std::string name;
  std::string source;
  std::string flows;
  int order = 0;
  bool rkn = false;
};

/// The catalogue, in the order the book lists it.
inline const std::vector<SplittingEntry>& splitting_catalogue() {
  static const std::vector<SplittingEntry> entries = {
      {"leapfrog",
       "Strang 1968, SIAM J. Numer. Anal. 5, 506; Verlet 1967 (Störmer–Verlet, position form)",
       "drift:1/2,kick:1,drift:1/2", 2},
      {"forest-ruth",
       "Forest & Ruth 1990, Physica D 43, 105 (also Candy & Rozmus 1991, J. Comput. Phys. 92, "
       "230): theta = 1/(2 - 2^(1/3))",
       "drift:1/(2*(2-2^(1/3))),kick:1/(2-2^(1/3)),drift:(1-2^(1/3))/(2*(2-2^(1/3))),"
       "kick:-2^(1/3)/(2-2^(1/3)),drift:(1-2^(1/3))/(2*(2-2^(1/3))),kick:1/(2-2^(1/3)),"
       "drift:1/(2*(2-2^(1/3)))",
       4},
      {"omelyan-2",
       "Omelyan, Mryglod & Folk 2002, Comput. Phys. Commun. 146, 188: the second-order "
       "three-stage method whose leading error has the smallest norm, xi = 1/2 - "
       "(2 sqrt(326) + 36)^(1/3)/12 + 1/(6 (2 sqrt(326) + 36)^(1/3)) = 0.1931833275037836, "
       "here with the drifts outside",
       "drift:1/2-(2*sqrt(326)+36)^(1/3)/12+1/(6*(2*sqrt(326)+36)^(1/3)),kick:1/2,"
       "drift:2*((2*sqrt(326)+36)^(1/3)/12-1/(6*(2*sqrt(326)+36)^(1/3))),kick:1/2,"
       "drift:1/2-(2*sqrt(326)+36)^(1/3)/12+1/(6*(2*sqrt(326)+36)^(1/3))",
       2},
      {"saba-2",
       "Laskar & Robutel 2001, Celest. Mech. Dyn. Astron. 80, 39, SABA_2 (kicks at the Gauss "
       "nodes)",
       "drift:1/2-sqrt(3)/6,kick:1/2,drift:sqrt(3)/3,kick:1/2,drift:1/2-sqrt(3)/6", 2},
      {"saba-3",
       "Laskar & Robutel 2001, Celest. Mech. Dyn. Astron. 80, 39, SABA_3 (kicks at the Gauss "
       "nodes, the Gauss weights)",
       "drift:1/2-sqrt(15)/10,kick:5/18,drift:sqrt(15)/10,kick:4/9,drift:sqrt(15)/10,kick:5/18,"
       "drift:1/2-sqrt(15)/10",
       2},
      {"saba-4",
       "Laskar & Robutel 2001, Celest. Mech. Dyn. Astron. 80, 39, SABA_4 (kicks at the four "
       "Gauss nodes 1/2 -+ sqrt(525 +- 70 sqrt(30))/70, the Gauss weights (18 -+ sqrt(30))/72)",
       "drift:1/2-sqrt(525+70*sqrt(30))/70,kick:(18-sqrt(30))/72,"
       "drift:(sqrt(525+70*sqrt(30))-sqrt(525-70*sqrt(30)))/70,kick:(18+sqrt(30))/72,"
       "drift:sqrt(525-70*sqrt(30))/35,kick:(18+sqrt(30))/72,"
       "drift:(sqrt(525+70*sqrt(30))-sqrt(525-70*sqrt(30)))/70,kick:(18-sqrt(30))/72,"
       "drift:1/2-sqrt(525+70*sqrt(30))/70",
       2},
      {"sbab-2",
       "Laskar & Robutel 2001, Celest. Mech. Dyn. Astron. 80, 39, SBAB_2 (kicks at the Lobatto "
       "nodes, the Lobatto weights)",
       "kick:1/6,drift:1/2,kick:2/3,drift:1/2,kick:1/6", 2},
      {"sbab-3",
       "Laskar & Robutel 2001, Celest. Mech. Dyn. Astron. 80, 39, SBAB_3 (kicks at the four "
       "Lobatto nodes 0, 1/2 -+ sqrt(5)/10, 1, the Lobatto weights 1/12, 5/12)",
       "kick:1/12,drift:1/2-sqrt(5)/10,kick:5/12,drift:sqrt(5)/5,kick:5/12,drift:1/2-sqrt(5)/10,"
       "kick:1/12",
       2},
      {"ruth-3",
       "Ruth 1983, IEEE Trans. Nucl. Sci. 30, 2669: kick 7/24, drift 2/3, kick 3/4, drift -2/3, "
       "kick -1/24, drift 1",
       "kick:7/24,drift:2/3,kick:3/4,drift:-2/3,kick:-1/24,drift:1", 3},
      {"mclachlan-atela-4",
       "McLachlan & Atela 1992, Nonlinearity 5, 541, the optimal fourth-order RKN method with "
       "four kicks, kick first; the 19 digits as codes that cite the paper reproduce them (the "
       "paper itself was not at hand). "
       "Order 4 for T = |p|^2/2 (its Nystrom conditions hold to 6e-20), order 3 for two generic "
       "flows",
       "kick:0.1344961992774310892,drift:0.5153528374311229364,kick:-0.2248198030794208058,"
       "drift:-0.085782019412973646,kick:0.7563200005156682911,drift:0.4415830236164665242,"
       "kick:0.3340036032863214255,drift:0.1288461583653841854",
       4, true},
      {"mclachlan-atela-5",
       "McLachlan & Atela 1992, Nonlinearity 5, 541, the optimal fifth-order RKN method with six "
       "kicks, kick first; the digits as codes that cite the paper reproduce them (Principia's "
       "McLachlanAtela1992Order5Optimal; the paper itself was not at hand). Order 5 for T = "
       "|p|^2/2",
       "kick:0.1193900292875672758,drift:0.339839625839110000,kick:0.6989273703824752308,"
       "drift:-0.088601336903027329,kick:-0.1713123582716007754,drift:0.5858564768259621188,"
       "kick:0.4012695022513534480,drift:-0.603039356536491888,kick:0.0107050818482359840,"
       "drift:0.3235807965546976394,kick:-0.0589796254980311632,drift:0.4423637942197494587",
       5, true},
  };
  return entries;
}

/// The catalogue entry of that name, or nullptr.
inline const SplittingEntry* find_splitting(const std::string& name) {
  for (const auto& e : splitting_catalogue())
    if (e.name == name) return &e;
  return nullptr;
}

}  // namespace vibook::composition
