/// \file composition.hpp
/// \brief Composition methods Ψ_h = Φ^{(s)}_{c_s h} ∘ … ∘ Φ^{(1)}_{c_1 h} of a one-step method
/// Φ and its adjoint Φ* (Hairer, Lubich & Wanner, *Geometric Numerical Integration*, §II.4 and
/// §III.3; McLachlan 1995): the stages, a catalogue of published coefficients with their sources,
/// the order conditions evaluated in any precision (MPFR through vibook::precision), and the
/// composed step.
///
/// **Order conditions, by the Baker–Campbell–Hausdorff formula in a free algebra.** A base method
/// of order ≥ 1 is the exact flow of a modified vector field, Φ_h = exp(h X₁ + h² X₂ + h³ X₃ + …),
/// X₁ the vector field itself. Its adjoint Φ*_h = Φ_{−h}^{−1} has the signs (−1)^{k+1} on X_k,
/// and a symmetric base (Φ* = Φ: Störmer–Verlet, the implicit midpoint rule) has X_k = 0 for
/// even k. Treating the X_k as free letters of weight k, the composition's logarithm
/// log Ψ_h = Σ_words coefficient(word)·word is computed in the free associative algebra truncated
/// at a weight W (exponentials, products and the logarithm as truncated series). The composition
/// has order p for *every* base method of that kind if and only if log Ψ_h = h X₁ up to weight
/// p: every word coefficient of weight 2…p vanishes and that of X₁ is 1. The residual of weight k
/// is the largest deviation over the words of weight k. Evaluated at 120 digits from
/// coefficients given exactly (decimal or rational text, or closed forms), a coefficient off
/// in its eleventh digit leaves a residual near 1e-11 that no measured order can see.
///
/// The conditions are those of a generic base method: on a particular base (a splitting, say) a
/// composition can reach a higher order than they predict, never a lower one.
///
/// Chapter: \ref chapter-verify (section "Compositions").
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "vibook/core/errors.hpp"
#include "vibook/core/newton.hpp"
#include "vibook/core/types.hpp"

namespace vibook::composition {

/// One stage: the base method (or, with `adjoint`, its adjoint) with step c·h.
template <class Real>
struct Stage {
  Real c;
  bool adjoint = false;
};

/// A composition method: its stages in the order they are applied to the state.
template <class Real>
using Stages = std::vector<Stage<Real>>;

/// The adjoint composition Ψ*_h = Ψ_{−h}^{−1}: the stages reversed, each replaced by its adjoint.
template <class Real>
Stages<Real> adjoint(const Stages<Real>& s) {
  Stages<Real> a(s.rbegin(), s.rend());
  for (auto& st : a) st.adjoint = !st.adjoint;
  return a;
}

/// Whether the composition is its own adjoint (a symmetric method), for a symmetric base
/// (stages compared by coefficient only) or a general one (coefficient and kind), to `tol`.
template <class Real>
bool is_symmetric(const Stages<Real>& s, bool symmetric_base, double tol = 0) {
  const Stages<Real> a = adjoint(s);
  for (std::size_t i = 0; i < s.size(); ++i) {
    using std::abs;
    if (abs(Real(s[i].c - a[i].c)) > tol) return false;
    if (!symmetric_base && s[i].adjoint != a[i].adjoint && s[i].c != Real(0)) return false;
  }
  return true;
}

// -------------------------------------------------------------------------------------------
// The free associative algebra in the letters X_k (weight k), truncated at a weight W
// -------------------------------------------------------------------------------------------

/// Words in the letters X_1 … X_W (only odd k for a symmetric base), up to total weight W; word 0
/// is the empty word. `products()` lists every pair (i, j) whose concatenation k stays within W.
class WordAlgebra {
 public:
  struct Product {
    int i, j, k;
  };

  WordAlgebra(int max_weight, bool odd_letters_only) : max_weight_(max_weight) {
    if (max_weight < 1 || max_weight > 12)
      throw std::invalid_argument("WordAlgebra: weight must lie in 1..12");
    for (int k = 1; k <= max_weight; ++k)
      if (!odd_letters_only || k % 2 == 1) letters_.push_back(k);
    std::map<std::vector<int>, int> id;
    words_.push_back({});
    weights_.push_back(0);
    id[{}] = 0;
    // breadth first: words of each weight from shorter ones
    for (std::size_t w = 0; w < words_.size(); ++w)
      for (int l : letters_)
        if (weights_[w] + l <= max_weight) {
          std::vector<int> nw = words_[w];
          nw.push_back(l);
          if (id.count(nw)) continue;
          id[nw] = static_cast<int>(words_.size());
          words_.push_back(nw);
          weights_.push_back(weights_[w] + l);
        }
    for (int i = 0; i < size(); ++i)
      for (int j = 0; j < size(); ++j)
        if (weights_[static_cast<std::size_t>(i)] + weights_[static_cast<std::size_t>(j)] <=
            max_weight) {
          std::vector<int> c = words_[static_cast<std::size_t>(i)];
          const auto& b = words_[static_cast<std::size_t>(j)];
          c.insert(c.end(), b.begin(), b.end());
          products_.push_back({i, j, id.at(c)});
        }
    for (int l : letters_) letter_id_[l] = id.at({l});
  }

  int max_weight() const { return max_weight_; }
  int size() const { return static_cast<int>(words_.size()); }
  int weight(int w) const { return weights_[static_cast<std::size_t>(w)]; }
  const std::vector<int>& letters() const { return letters_; }
  /// The one-letter word X_k, or −1 when X_k is not a letter.
  int letter(int k) const {
    const auto it = letter_id_.find(k);
    return it == letter_id_.end() ? -1 : it->second;
  }
  const std::vector<Product>& products() const { return products_; }
  /// "X1 X3 X1"
  std::string name(int w) const {
    std::string s;
    for (int l : words_[static_cast<std::size_t>(w)])
      s += (s.empty() ? "X" : " X") + std::to_string(l);
    return s.empty() ? "1" : s;
  }

 private:
  int max_weight_;
  std::vector<int> letters_;
  std::vector<std::vector<int>> words_;
  std::vector<int> weights_;
  std::vector<Product> products_;
  std::map<int, int> letter_id_;
};

/// Truncated series: one coefficient per word of the algebra.
template <class Real>
using Series = std::vector<Real>;

template <class Real>
Series<Real> multiply(const WordAlgebra& A, const Series<Real>& x, const Series<Real>& y) {
  Series<Real> z(static_cast<std::size_t>(A.size()), Real(0));
  for (const auto& pr : A.products()) {
    const Real& a = x[static_cast<std::size_t>(pr.i)];
    const Real& b = y[static_cast<std::size_t>(pr.j)];
    if (a != 0 && b != 0) z[static_cast<std::size_t>(pr.k)] += a * b;
  }
  return z;
}

/// exp(Y) for Y without constant term: Σ_n Yⁿ/n!, exact to the truncation weight.
template <class Real>
Series<Real> exp_series(const WordAlgebra& A, const Series<Real>& Y) {
  Series<Real> E(static_cast<std::size_t>(A.size()), Real(0)), P = E;
  E[0] = P[0] = Real(1);
  for (int n = 1; n <= A.max_weight(); ++n) {
    P = multiply(A, P, Y);
    for (auto& v : P) v /= n;
    for (std::size_t i = 0; i < E.size(); ++i) E[i] += P[i];
  }
  return E;
}

/// log(Z) for Z with constant term 1: Σ_n (−1)^{n+1} (Z − 1)ⁿ / n.
template <class Real>
Series<Real> log_series(const WordAlgebra& A, const Series<Real>& Z) {
  Series<Real> X = Z;
  X[0] = Real(0);
  Series<Real> L(static_cast<std::size_t>(A.size()), Real(0)), P = L;
  P[0] = Real(1);
  for (int n = 1; n <= A.max_weight(); ++n) {
    P = multiply(A, P, X);
    const Real f = Real(n % 2 == 1 ? 1 : -1) / Real(n);
    for (std::size_t i = 0; i < L.size(); ++i) L[i] += f * P[i];
  }
  return L;
}

/// log Ψ_h of the composition in the free algebra A (letters of weight k stand for h^k X_k).
template <class Real>
Series<Real> composition_log(const WordAlgebra& A, const Stages<Real>& stages) {
  Series<Real> Z(static_cast<std::size_t>(A.size()), Real(0));
  Z[0] = Real(1);
  for (const auto& st : stages) {
    if (st.c == Real(0)) continue;
    Series<Real> Y(static_cast<std::size_t>(A.size()), Real(0));
    Real ck = Real(1);
    for (int k = 1; k <= A.max_weight(); ++k) {
      ck *= st.c;
      const int w = A.letter(k);
      if (w < 0) continue;
      const bool flip = st.adjoint && k % 2 == 0;  // Φ*: (−1)^{k+1} on X_k
      Y[static_cast<std::size_t>(w)] = flip ? Real(-ck) : ck;
    }
    Z = multiply(A, Z, exp_series(A, Y));
  }
  return log_series(A, Z);
}

/// The deviation of log Ψ from h X₁, word by word (the order conditions' residual vector).
template <class Real>
Series<Real> condition_vector(const WordAlgebra& A, const Stages<Real>& stages) {
  Series<Real> L = composition_log(A, stages);
  L[static_cast<std::size_t>(A.letter(1))] -= Real(1);
  L[0] = Real(0);
  return L;
}

/// The order conditions of a composition, weight by weight.
struct OrderConditions {
  bool symmetric_base = true;
  int max_weight = 0;
  double tolerance = 0;                 ///< a weight is satisfied when its residual is ≤ this
  std::vector<double> residual;         ///< residual[k − 1]: the largest deviation at weight k
  std::vector<std::string> worst_word;  ///< the word where it occurs
  int order = 0;  ///< largest p with every weight 1…p satisfied (max_weight when all are)
};

/// Evaluate the order conditions in Real (mpfr_real at 120 digits for the command). `tolerance`
/// decides "satisfied": 1e-12 by default, above the 1e-15–1e-13 that rounding the coefficients
/// to double leaves and below the 1e-11 of a coefficient off in its eleventh digit.
/// The conditions from a residual vector over words 1 … n−1 (word 0 the empty one): the largest
/// deviation of each weight and its word, and the order they give at `tolerance`. `weight(w)`
/// and `name(w)` describe word w (composition and splitting algebras alike).
template <class Real, class Weight, class Name>
OrderConditions conditions_from(const Series<Real>& r, int max_weight, bool symmetric_base,
                                double tolerance, Weight weight, Name name) {
  OrderConditions oc;
  oc.symmetric_base = symmetric_base;
  oc.max_weight = max_weight;
  oc.tolerance = tolerance;
  oc.residual.assign(static_cast<std::size_t>(max_weight), 0.0);
  oc.worst_word.assign(static_cast<std::size_t>(max_weight), "");
  for (int w = 1; w < static_cast<int>(r.size()); ++w) {
    using std::abs;
    const double v = static_cast<double>(abs(r[static_cast<std::size_t>(w)]));
    const auto k = static_cast<std::size_t>(weight(w) - 1);
    if (v > oc.residual[k] || oc.worst_word[k].empty()) {  // residuals start at 0
      oc.residual[k] = v;
      oc.worst_word[k] = name(w);
    }
  }
  oc.order = 0;
  while (oc.order < max_weight && oc.residual[static_cast<std::size_t>(oc.order)] <= tolerance)
    ++oc.order;
  return oc;
}

template <class Real>
OrderConditions order_conditions(const Stages<Real>& stages, bool symmetric_base, int max_weight,
                                 double tolerance = 1e-12) {
  const WordAlgebra A(max_weight, symmetric_base);
  return conditions_from(
      condition_vector(A, stages), max_weight, symmetric_base, tolerance,
      [&A](int w) { return A.weight(w); }, [&A](int w) { return A.name(w); });
}

// -------------------------------------------------------------------------------------------
// Solving the order conditions: Gauss–Newton in Real from published digits
// -------------------------------------------------------------------------------------------

/// Result of refine_palindrome.
struct Refinement {
  int iterations = 0;
  double max_change = 0;      ///< largest |solved − published| over the coefficients
  double final_residual = 0;  ///< largest word residual of weights 1…W at the solution
  bool converged = false;
  /// The order conditions' residual by weight on the published digits themselves (filled by
  /// catalogue_stages): how far the printed values are from a solution.
  std::vector<double> published_residual;
};

/// The palindromic composition γ_1 … γ_{m−1} γ_m γ_{m−1} … γ_1 (γ_m in the middle) of a
/// symmetric base, from the outer-to-middle values.
template <class Real>
Stages<Real> palindrome(const std::vector<Real>& outer_to_middle) {
  Stages<Real> s;
  for (const auto& g : outer_to_middle) s.push_back({g, false});
  for (std::size_t i = outer_to_middle.size() - 1; i-- > 0;)
    s.push_back({outer_to_middle[i], false});
  return s;
}

/// Solve the order conditions up to weight W for the palindromic composition of a symmetric
/// base, starting from published values γ (outer to middle), by Gauss–Newton on every word
/// residual (Jacobian by central differences with step 10^{−digits/3}; normal equations by
/// Gaussian elimination with partial pivoting, all in Real). The system must determine γ
/// (as many independent conditions as unknowns): Yoshida's and McLachlan's are; Kahan–Li's
/// leave a free parameter and are not refined. γ is replaced by the solution.
template <class Real>
Refinement refine_palindrome(std::vector<Real>& gamma, int max_weight, int digits) {
  const WordAlgebra A(max_weight, true);
  const std::size_t m = gamma.size();
  auto residual = [&](const std::vector<Real>& g) { return condition_vector(A, palindrome(g)); };
  const std::vector<Real> published = gamma;
  const Real delta = pow(Real(10), -Real(digits) / 3);
  const Real stop = pow(Real(10), -Real(digits - 15));
  Refinement rf;
  for (int it = 0; it < 40; ++it) {
    const Series<Real> r = residual(gamma);
    const std::size_t n = r.size();
    std::vector<std::vector<Real>> J(m, std::vector<Real>(n));
    for (std::size_t j = 0; j < m; ++j) {
      std::vector<Real> gp = gamma, gm = gamma;
      gp[j] += delta;
      gm[j] -= delta;
      const Series<Real> rp = residual(gp), rm = residual(gm);
      for (std::size_t i = 0; i < n; ++i) J[j][i] = (rp[i] - rm[i]) / (2 * delta);
    }
    // normal equations (Jᵀ J) d = −Jᵀ r
    std::vector<std::vector<Real>> M(m, std::vector<Real>(m + 1, Real(0)));
    for (std::size_t a = 0; a < m; ++a) {
      for (std::size_t b = 0; b < m; ++b)
        for (std::size_t i = 0; i < n; ++i) M[a][b] += J[a][i] * J[b][i];
      for (std::size_t i = 0; i < n; ++i) M[a][m] -= J[a][i] * r[i];
    }
    for (std::size_t c = 0; c < m; ++c) {
      std::size_t piv = c;
      for (std::size_t a = c + 1; a < m; ++a)
        if (abs(M[a][c]) > abs(M[piv][c])) piv = a;
      std::swap(M[c], M[piv]);
      if (M[c][c] == 0) throw NumericalError("refine_palindrome: singular normal equations");
      for (std::size_t a = c + 1; a < m; ++a) {
        const Real f = M[a][c] / M[c][c];
        for (std::size_t b = c; b <= m; ++b) M[a][b] -= f * M[c][b];
      }
    }
    std::vector<Real> d(m);
    for (std::size_t c = m; c-- > 0;) {
      Real s = M[c][m];
      for (std::size_t b = c + 1; b < m; ++b) s -= M[c][b] * d[b];
      d[c] = s / M[c][c];
    }
    Real dmax = Real(0);
    for (std::size_t j = 0; j < m; ++j) {
      gamma[j] += d[j];
      dmax = std::max(dmax, Real(abs(d[j])));
    }
    rf.iterations = it + 1;
    if (dmax <= stop) {
      rf.converged = true;
      break;
    }
  }
  Real change = Real(0), res = Real(0);
  for (std::size_t j = 0; j < m; ++j) change = std::max(change, Real(abs(gamma[j] - published[j])));
  for (const auto& v : residual(gamma)) res = std::max(res, Real(abs(v)));
  rf.max_change = static_cast<double>(change);
  rf.final_residual = static_cast<double>(res);
  return rf;
}

// -------------------------------------------------------------------------------------------
// The catalogue
// -------------------------------------------------------------------------------------------

/// A published composition: where its coefficients come from and how vibook obtains them.
struct CatalogueEntry {
  std::string name;
  std::string source;      ///< the publication
  std::string derivation;  ///< closed form, refined by Newton, or as published
  std::string base;        ///< "symmetric" (any symmetric base of order 2) or a base's name
  int order = 0;           ///< the documented order on that base
  int stages = 0;
};

/// Ruth's third-order method as stages on symplectic Euler, exact rationals ('*' the adjoint):
/// the catalogue's entry, and the list the symbolic engine derives it from.
inline constexpr const char* kRuth3Stages = "7/24*,3/8,3/8*,-25/24,1*";

/// The catalogue, in the order the book's audit lists it.
inline const std::vector<CatalogueEntry>& catalogue() {
  static const std::vector<CatalogueEntry> entries = {
      {"yoshida4",
       "Yoshida 1990, Phys. Lett. A 150, 262, eq. (4.4) (the triple jump; also Creutz & Gocksch "
       "1989, Suzuki 1990)",
       "closed form: g1 = 1/(2 - 2^(1/3)), g2 = -2^(1/3)/(2 - 2^(1/3))", "symmetric", 4, 3},
      {"suzuki4", "Suzuki 1990, Phys. Lett. A 146, 319, eq. (3.11) (the fractal 5-stage method)",
       "closed form: p = 1/(4 - 4^(1/3)), stages p, p, 1 - 4p, p, p", "symmetric", 4, 5},
      {"yoshida6", "Yoshida 1990, Phys. Lett. A 150, 262, Table 1, solution A",
       "Newton on the order conditions to weight 6 from the published 15 digits", "symmetric", 6,
       7},
      {"yoshida8", "Yoshida 1990, Phys. Lett. A 150, 262, Table 2, solution A",
       "Newton on the order conditions to weight 8 from the published 15 digits", "symmetric", 8,
       15},
      {"mclachlan8", "McLachlan 1995, SIAM J. Sci. Comput. 16, 151, the 15-stage method of order 8",
       "Newton on the order conditions to weight 8 from the published 26 digits", "symmetric", 8,
       15},
      {"kahanli6", "Kahan & Li 1997, Math. Comp. 66, 1089, s9odr6a",
       "as published (26 digits; one free parameter, chosen by the authors, is not re-derived)",
       "symmetric", 6, 9},
      {"kahanli8", "Kahan & Li 1997, Math. Comp. 66, 1089, s17odr8a",
       "as published (26 digits; one free parameter, chosen by the authors, is not re-derived)",
       "symmetric", 8, 17},
      {"ruth3",
       "Ruth 1983, IEEE Trans. Nucl. Sci. 30, 2669 (kick 7/24, 3/4, -1/24; drift 2/3, -2/3, 1), "
       "written as symplectic Euler (se: drift, then kick) and its adjoint (kick, then drift)",
       "exact rationals from Ruth's coefficients: 7/24*, 3/8, 3/8*, -25/24, 1* (* the adjoint)",
       "se", 3, 5},
  };
  return entries;
}

/// The catalogue entry of that name, or nullptr.
inline const CatalogueEntry* find_entry(const std::string& name) {
  for (const auto& e : catalogue())
    if (e.name == name) return &e;
  return nullptr;
}

/// Parse one exact coefficient: a decimal number or a ratio of two, optionally followed by '*'
/// (the adjoint). ArgumentError naming `arg` otherwise.
template <class Real>
Stage<Real> parse_stage(const std::string& arg, std::string t) {
  auto trim = [](std::string s) {
    const auto a = s.find_first_not_of(" \t");
    const auto b = s.find_last_not_of(" \t");
    return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
  };
  t = trim(t);
  Stage<Real> st;
  if (!t.empty() && t.back() == '*') {
    st.adjoint = true;
    t = trim(t.substr(0, t.size() - 1));
  }
  auto number = [&](const std::string& s) {
    // digits, one point, an exponent: what both MPFR and a reader take as a decimal number
    std::size_t i = 0;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    bool digits = false, point = false;
    for (; i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.'); ++i) {
      if (s[i] == '.') {
        if (point) return false;
        point = true;
      } else {
        digits = true;
      }
    }
    if (!digits) return false;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
      ++i;
      if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
      bool ed = false;
      for (; i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])); ++i) ed = true;
      if (!ed) return false;
    }
    return i == s.size();
  };
  const auto slash = t.find('/');
  const std::string a = trim(t.substr(0, slash));
  const std::string b = slash == std::string::npos ? "" : trim(t.substr(slash + 1));
  if (!number(a) || (slash != std::string::npos && !number(b)))
    throw ArgumentError(arg, "'" + t +
                                 "' is not a coefficient (a decimal number or a ratio such as "
                                 "7/24, with '*' after it for the adjoint)");
  st.c = Real(a);
  if (slash != std::string::npos) {
    const Real d = Real(b);
    if (d == 0) throw ArgumentError(arg, "'" + t + "' divides by zero");
    st.c /= d;
  }
  return st;
}

/// The stages of a catalogue entry in Real, computed as its derivation says (closed form,
/// Newton from the published digits at `digits` decimal digits, or the published digits).
/// `refinement` receives Newton's account where there is one.
template <class Real>
Stages<Real> catalogue_stages(const std::string& name, int digits,
                              Refinement* refinement = nullptr) {
  auto R = [](const char* s) { return Real(s); };
  auto refined = [&](std::vector<Real> g, int weight) {
    const std::vector<double> before = order_conditions(palindrome(g), true, weight).residual;
    Refinement rf = refine_palindrome(g, weight, digits);
    rf.published_residual = before;
    if (refinement) *refinement = rf;
    if (!rf.converged)
      throw NumericalError("catalogue '" + name +
                           "': Newton on the order conditions did not converge from the "
                           "published values");
    return palindrome(g);
  };
  // Yoshida's tables give w_1 … w_m; w_0 = 1 − 2 Σ w_i is the middle stage.
  auto yoshida = [&](std::vector<Real> w) {
    Real w0 = Real(1);
    for (const auto& x : w) w0 -= 2 * x;
    std::vector<Real> g(w.rbegin(), w.rend());
    g.push_back(w0);
    return g;
  };
  if (name == "yoshida4") {
    const Real c = cbrt(Real(2));
    return palindrome(std::vector<Real>{Real(1) / (2 - c), -c / (2 - c)});
  }
  if (name == "suzuki4") {
    const Real p = Real(1) / (4 - cbrt(Real(4)));
    return palindrome(std::vector<Real>{p, p, 1 - 4 * p});
  }
  if (name == "yoshida6")
    return refined(
        yoshida({R("-1.17767998417887"), R("0.235573213359357"), R("0.784513610477560")}), 6);
  if (name == "yoshida8")
    return refined(yoshida({R("-1.61582374150097"), R("-2.44699182370524"),
                            R("-0.716989419708120e-2"), R("2.44002732616735"),
                            R("0.157739928123617"), R("1.82020630970714"), R("1.04242620869991")}),
                   8);
  if (name == "mclachlan8")
    return refined({R("0.74167036435061295344822780"), R("-0.40910082580003159399730010"),
                    R("0.19075471029623837995387626"), R("-0.57386247111608226665638773"),
                    R("0.29906418130365592384446354"), R("0.33462491824529818378495798"),
                    R("0.31529309239676659663205666"), R("-0.79688793935291635401978884")},
                   8);
  if (name == "kahanli6")
    return palindrome(
        std::vector<Real>{R("0.39216144400731413927925056"), R("0.33259913678935943859974864"),
                          R("-0.70624617255763935980996482"), R("0.08221359629355080023149045"),
                          R("0.79854399093482996339895035")});
  if (name == "kahanli8")
    return palindrome(
        std::vector<Real>{R("0.13020248308889008087881763"), R("0.56116298177510838456196441"),
                          R("-0.38947496264484728640807860"), R("0.15884190655515560089621075"),
                          R("-0.39590389413323757733623154"), R("0.18453964097831570709183254"),
                          R("0.25837438768632204729397911"), R("0.29501172360931029887096624"),
                          R("-0.60550853383003451169892108")});
  if (name == "ruth3") {
    Stages<Real> s;
    std::string item;
    for (const char* c = kRuth3Stages;; ++c) {
      if (*c == ',' || *c == '\0') {
        s.push_back(parse_stage<Real>("--coefficients", item));
        item.clear();
        if (*c == '\0') break;
      } else {
        item += *c;
      }
    }
    return s;
  }
  throw ArgumentError("--coefficients", "no catalogue entry '" + name + "'");
}

// -------------------------------------------------------------------------------------------
// The composed step
// -------------------------------------------------------------------------------------------

/// Ψ_h: the stages applied in order, each a step of the base (or adjoint) integrator with size
/// c·h. Base and Adjoint are anything with `SolveReport step(q, p, h)` (kernels.hpp,
/// DelIntegrator); for a symmetric base pass the same type twice. Zero stages are skipped. The
/// report is the worst residual and the total of Newton iterations over the stages.
template <class Base, class Adjoint>
class Composed {
 public:
  static constexpr int N = Base::N;
  Composed(Base base, Adjoint adjoint, std::vector<double> c, std::vector<bool> is_adjoint)
      : base_(std::move(base)),
        adjoint_(std::move(adjoint)),
        c_(std::move(c)),
        adj_(std::move(is_adjoint)) {
    if (c_.size() != adj_.size() || c_.empty())
      throw std::invalid_argument("Composed: one kind per coefficient, at least one stage");
  }
  SolveReport step(Vec<double, N>& q, Vec<double, N>& p, double h) {
    SolveReport total{0.0, 0, true};
    for (std::size_t i = 0; i < c_.size(); ++i) {
      if (c_[i] == 0) continue;
      const SolveReport r = adj_[i] ? adjoint_.step(q, p, c_[i] * h) : base_.step(q, p, c_[i] * h);
      total.residual = std::max(total.residual, r.residual);
      total.iterations += r.iterations;
      total.converged = total.converged && r.converged;
    }
    return total;
  }

 private:
  Base base_;
  Adjoint adjoint_;
  std::vector<double> c_;
  std::vector<bool> adj_;
};

}  // namespace vibook::composition
