// Engine expressions in vector notation (Shen & Sun 2025, §4): see vector_notation.hpp.
#include "vibook/modified/vector_notation.hpp"

#include <functional>
#include <set>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "vibook/modified/canonical.hpp"

namespace vibook::modified {

namespace {

using GiNaC::numeric;
using Terms = std::map<ex, numeric, GiNaC::ex_is_less>;  // monomial → its number

// An expanded polynomial as monomial → coefficient (the monomial: every factor that is not a
// number).
Terms terms(const ex& expanded) {
  Terms out;
  auto add_term = [&out](const ex& t) {
    numeric c = 1;
    ex m = 1;
    if (GiNaC::is_a<numeric>(t)) {
      c = GiNaC::ex_to<numeric>(t);
    } else if (GiNaC::is_a<GiNaC::mul>(t)) {
      for (std::size_t k = 0; k < t.nops(); ++k) {
        if (GiNaC::is_a<numeric>(t.op(k)))
          c *= GiNaC::ex_to<numeric>(t.op(k));
        else
          m *= t.op(k);
      }
    } else {
      m = t;
    }
    out[m] += c;
  };
  if (GiNaC::is_a<GiNaC::add>(expanded)) {
    for (std::size_t k = 0; k < expanded.nops(); ++k) add_term(expanded.op(k));
  } else if (!expanded.is_zero()) {
    add_term(expanded);
  }
  for (auto it = out.begin(); it != out.end();) it = it->second.is_zero() ? out.erase(it) : ++it;
  return out;
}

ex sum(const Terms& t) {
  ex s = 0;
  for (const auto& [m, c] : t) s += c * m;
  return s;
}

// The first term of "a + b" joined after others: " + b" or " - b".
void append(std::string& s, const std::string& term) {
  if (s.empty())
    s = term;
  else if (!term.empty() && term.front() == '-')
    s += " - " + term.substr(1);
  else
    s += " + " + term;
}

std::string h_power(int k) {
  if (k <= 0) return "";
  return k == 1 ? std::string("h") : "h^{" + std::to_string(k) + "}";
}

// "h^{k}" times the factor g, written before a parenthesis: \frac{h^{2}}{24}, -\frac{h}{2},
// \frac{7 h^{2}}{96}, 3 h (a leading "-" for a negative g).
std::string prefix(const numeric& g, const std::string& hk) {
  const std::string sign = g.is_negative() ? "-" : "";
  const numeric a = abs(g.numer()), b = g.denom();
  auto text = [](const numeric& x) {
    std::ostringstream os;
    os << x;
    return os.str();
  };
  const std::string top = a == 1 ? (hk.empty() ? "1" : hk) : text(a) + (hk.empty() ? "" : " " + hk);
  if (b == 1) return sign + (a == 1 ? hk : top);
  return sign + "\\frac{" + top + "}{" + text(b) + "}";
}

}  // namespace

std::optional<VectorNotation> VectorNotation::of(const JetSpace& J, const std::vector<ex>& exprs) {
  const int n = J.dofs();
  if (n < 2) return std::nullopt;
  std::set<int> families;
  bool p_occurs = false;
  std::set<int> orders;  // the derivatives of x that occur: ẋ 1, ẍ 2, x⃛ 3 (Theorem 11), …
  for (const ex& e : exprs)
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
      int f = 0;
      std::vector<int> index;
      if (J.derivative_of(*it, f, index)) families.insert(f);
      if (GiNaC::is_a<GiNaC::function>(*it)) return std::nullopt;  // an abstract call left
      for (int i = 0; i < n; ++i) {
        p_occurs = p_occurs || it->is_equal(J.p(i));
        for (int k = 1; k <= J.created_order(); ++k)
          if (it->is_equal(J.x(k, i))) orders.insert(k);
      }
    }
  if (families.empty()) return std::nullopt;
  for (int f : families)
    if (J.family_arity(f) != n) return std::nullopt;
  VectorNotation v;
  v.J_ = &J;
  v.n_ = n;
  if (families.size() == 1) {
    v.whole_ = *families.begin();
    v.whole_tex_ = J.family_tex(v.whole_);
  } else {
    for (int f : families)
      if (J.family_name(f).rfind("phi", 0) != 0) return std::nullopt;  // not pieces of one φ
    v.pieces_.assign(families.begin(), families.end());
    v.whole_tex_ = "\\phi";
  }
  // ẋ and ẍ (the meshed Lagrangians' ẍ: Shen & Sun (4.18), (4.25)), then p, then the higher
  // derivatives: the invariants of ẋ, ẍ and p keep their order
  auto add = [&](std::string tex, const std::function<ex(int)>& component) {
    v.velocity_tex_.push_back(std::move(tex));
    v.velocity_.emplace_back();
    for (int i = 0; i < n; ++i) v.velocity_.back().push_back(component(i));
  };
  for (int k : orders)
    if (k <= 2) add(k == 1 ? "\\dot{x}" : "\\ddot{x}", [&](int i) { return J.x(k, i); });
  if (p_occurs) add("p", [&](int i) { return J.p(i); });
  for (int k : orders)
    if (k > 2)
      add(k == 3 ? std::string("\\dddot{x}") : fmt::format("x^{{({})}}", k),
          [&](int i) { return J.x(k, i); });
  return v;
}

ex VectorNotation::whole(std::vector<int> index) const {
  std::sort(index.begin(), index.end());
  if (pieces_.empty()) return J_->derivative(whole_, index);
  auto it = whole_symbols_.find(index);
  if (it == whole_symbols_.end()) {
    std::string name = "phi", sub;
    for (int i : index) sub += std::to_string(i + 1);
    if (!sub.empty()) name += "_" + sub;
    const std::string tex = sub.empty() ? "{\\phi}" : "{\\phi_{" + sub + "}}";
    it = whole_symbols_.emplace(index, GiNaC::symbol(name, tex)).first;
  }
  return it->second;
}

ex VectorNotation::piece(std::size_t k, std::vector<int> index) const {
  return J_->derivative(pieces_.at(k), std::move(index));
}

ex VectorNotation::to_internal(const ex& e) const {
  if (pieces_.empty()) return GiNaC::expand(e);
  // φ^[m]_I = φ_I − Σ_{k<m} φ^[k]_I for the last piece m
  GiNaC::exmap last;
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    int f = 0;
    std::vector<int> index;
    if (!J_->derivative_of(*it, f, index) || f != pieces_.back()) continue;
    ex s = whole(index);
    for (std::size_t k = 0; k + 1 < pieces_.size(); ++k) s -= piece(k, index);
    last[*it] = s;
  }
  return GiNaC::expand(e.subs(last));
}

ex VectorNotation::to_external(const ex& e) const {
  if (pieces_.empty()) return GiNaC::expand(e);
  GiNaC::exmap back;
  for (const auto& [index, s] : whole_symbols_) {
    ex sum_of = 0;
    for (int f : pieces_) sum_of += J_->derivative(f, index);
    back[s] = sum_of;
  }
  return GiNaC::expand(e.subs(back));
}

std::vector<VectorNotation::Invariant> VectorNotation::invariants(bool vector) const {
  const int n = n_;
  // the potentials: the whole, then the pieces but the last (which the whole replaces)
  const std::size_t np = pieces_.empty() ? 1 : pieces_.size();
  auto pot = [&](std::size_t p, std::vector<int> index) {
    return p == 0 ? whole(std::move(index)) : piece(p - 1, std::move(index));
  };
  auto tex = [&](std::size_t p) { return p == 0 ? whole_tex_ : J_->family_tex(pieces_.at(p - 1)); };
  auto grad = [&](std::size_t p) {
    std::vector<ex> g;
    for (int i = 0; i < n; ++i) g.push_back(pot(p, {i}));
    return g;
  };
  auto dot = [n](const std::vector<ex>& a, const std::vector<ex>& b) {
    ex s = 0;
    for (int i = 0; i < n; ++i)
      s += a[static_cast<std::size_t>(i)] * b[static_cast<std::size_t>(i)];
    return GiNaC::expand(s);
  };
  // P_xx u (a vector), P_xxx⟨u, w⟩ (a vector)
  auto hess = [&](std::size_t p, const std::vector<ex>& u) {
    std::vector<ex> r;
    for (int i = 0; i < n; ++i) {
      ex s = 0;
      for (int j = 0; j < n; ++j) s += pot(p, {i, j}) * u[static_cast<std::size_t>(j)];
      r.push_back(GiNaC::expand(s));
    }
    return r;
  };
  auto third = [&](std::size_t p, const std::vector<ex>& u, const std::vector<ex>& w) {
    std::vector<ex> r;
    for (int i = 0; i < n; ++i) {
      ex s = 0;
      for (int j = 0; j < n; ++j)
        for (int k = 0; k < n; ++k)
          s += pot(p, {i, j, k}) * u[static_cast<std::size_t>(j)] * w[static_cast<std::size_t>(k)];
      r.push_back(GiNaC::expand(s));
    }
    return r;
  };
  const std::string nabla = "\\nabla ";
  std::vector<Invariant> out;
  auto scalar = [&](std::string t, const ex& e) { out.push_back({std::move(t), {e}}); };
  auto vec = [&](std::string t, std::vector<ex> e) { out.push_back({std::move(t), std::move(e)}); };
  const std::size_t nv = velocity_.size();
  if (!vector) {
    for (std::size_t v = 0; v < nv; ++v)
      scalar("|" + velocity_tex_[v] + "|^{2}", dot(velocity_[v], velocity_[v]));
    for (std::size_t p = 0; p < np; ++p)
      for (std::size_t v = 0; v < nv; ++v)
        scalar(nabla + tex(p) + "\\cdot " + velocity_tex_[v], dot(grad(p), velocity_[v]));
    for (std::size_t p = 0; p < np; ++p)
      for (std::size_t q = p; q < np; ++q)
        scalar(
            p == q ? "|" + nabla + tex(p) + "|^{2}" : nabla + tex(p) + "\\cdot " + nabla + tex(q),
            dot(grad(p), grad(q)));
    for (std::size_t p = 0; p < np; ++p)
      for (std::size_t v = 0; v < nv; ++v)
        scalar(tex(p) + "_{xx}\\langle " + velocity_tex_[v] + "," + velocity_tex_[v] + "\\rangle",
               dot(hess(p, velocity_[v]), velocity_[v]));
    for (std::size_t p = 0; p < np; ++p)
      for (std::size_t q = 0; q < np; ++q)
        for (std::size_t v = 0; v < nv; ++v)
          scalar(tex(p) + "_{xx}\\langle " + nabla + tex(q) + "," + velocity_tex_[v] + "\\rangle",
                 dot(hess(p, grad(q)), velocity_[v]));
    for (std::size_t p = 0; p < np; ++p)
      for (std::size_t q = 0; q < np; ++q)
        for (std::size_t r = q; r < np; ++r)
          scalar(tex(p) + "_{xx}\\langle " + nabla + tex(q) + "," + nabla + tex(r) + "\\rangle",
                 dot(hess(p, grad(q)), grad(r)));
    for (std::size_t p = 0; p < np; ++p)
      for (std::size_t v = 0; v < nv; ++v)
        scalar(tex(p) + "_{xxx}\\langle " + velocity_tex_[v] + "," + velocity_tex_[v] + "," +
                   velocity_tex_[v] + "\\rangle",
               dot(third(p, velocity_[v], velocity_[v]), velocity_[v]));
    // two different derivatives of x against each other (ẋ·x⃛ in Shen & Sun's (4.17) proof),
    // last: an expression without them is grouped as before
    for (std::size_t v = 0; v < nv; ++v)
      for (std::size_t w = v + 1; w < nv; ++w)
        scalar(velocity_tex_[v] + "\\cdot " + velocity_tex_[w], dot(velocity_[v], velocity_[w]));
  } else {
    // (4.15)'s order: φ_xxx⟨ẋ, ẋ⟩ before φ_xx∇φ
    for (std::size_t p = 0; p < np; ++p) vec(nabla + tex(p), grad(p));
    for (std::size_t p = 0; p < np; ++p)
      for (std::size_t v = 0; v < nv; ++v)
        vec(tex(p) + "_{xxx}\\langle " + velocity_tex_[v] + "," + velocity_tex_[v] + "\\rangle",
            third(p, velocity_[v], velocity_[v]));
    for (std::size_t p = 0; p < np; ++p)
      for (std::size_t v = 0; v < nv; ++v)
        vec(tex(p) + "_{xx}" + velocity_tex_[v], hess(p, velocity_[v]));
    for (std::size_t p = 0; p < np; ++p)
      for (std::size_t q = 0; q < np; ++q) vec(tex(p) + "_{xx}" + nabla + tex(q), hess(p, grad(q)));
  }
  return out;
}

VectorNotation::Grouped VectorNotation::group(const std::vector<ex>& e, bool vector) const {
  if (e.size() != (vector ? static_cast<std::size_t>(n_) : 1u))
    throw std::invalid_argument("VectorNotation::group: a vector has N components, a scalar one");
  std::vector<Terms> rest;
  for (const ex& x : e) rest.push_back(terms(to_internal(x)));
  Grouped g;
  std::vector<const Invariant*> used;  // the invariants of g.terms, in its order
  const std::vector<Invariant> invs = invariants(vector);
  for (const Invariant& inv : invs) {
    // the ratio rest/invariant on each of the invariant's terms; the majority decides
    std::vector<std::pair<numeric, int>> votes;
    int size = 0;
    std::vector<Terms> it;
    for (const ex& c : inv.comp) it.push_back(terms(c));
    for (std::size_t i = 0; i < it.size(); ++i)
      for (const auto& [m, a] : it[i]) {
        ++size;
        const auto f = rest[i].find(m);
        const numeric r = f == rest[i].end() ? numeric(0) : f->second / a;
        auto v =
            std::find_if(votes.begin(), votes.end(), [&](const auto& x) { return x.first == r; });
        if (v == votes.end())
          votes.emplace_back(r, 1);
        else
          ++v->second;
      }
    if (votes.empty()) continue;
    auto best = std::max_element(votes.begin(), votes.end(),
                                 [](const auto& a, const auto& b) { return a.second < b.second; });
    if (best->first.is_zero() || 2 * best->second <= size) continue;
    const numeric c = best->first;
    for (std::size_t i = 0; i < it.size(); ++i)
      for (const auto& [m, a] : it[i]) {
        numeric& r = rest[i][m];
        r -= c * a;
        if (r.is_zero()) rest[i].erase(m);
      }
    g.terms.emplace_back(inv.tex, c);
    used.push_back(&inv);
  }
  // the grouping is a change of basis: it must add up to the input exactly
  for (std::size_t i = 0; i < e.size(); ++i) {
    ex back = sum(rest[i]);
    for (std::size_t t = 0; t < used.size(); ++t) back += g.terms[t].second * used[t]->comp[i];
    if (!GiNaC::expand(to_external(back) - e[i]).is_zero())
      throw std::logic_error("vector notation: the grouped form does not add up to the input");
    g.rest.push_back(sum(rest[i]));
  }
  return g;
}

std::string VectorNotation::coefficient(const std::vector<ex>& e, bool vector, int k) const {
  const Grouped g = group(e, vector);
  // the common factor of every number: gcd of the numerators over lcm of the denominators,
  // with the sign of the first term (none for h^0, where the paper writes ½|ẋ|² − φ)
  numeric factor = 1;
  if (k != 0) {
    std::vector<numeric> all;
    for (const auto& [t, c] : g.terms) all.push_back(GiNaC::ex_to<numeric>(c));
    for (const ex& r : g.rest)
      for (const auto& [m, c] : terms(GiNaC::expand(r))) all.push_back(c);
    if (!all.empty()) {
      numeric num = abs(all[0].numer()), den = all[0].denom();
      for (const numeric& c : all) {
        num = GiNaC::gcd(num, abs(c.numer()));
        den = GiNaC::lcm(den, c.denom());
      }
      factor = num / den;
      if (!g.terms.empty() && GiNaC::ex_to<numeric>(g.terms[0].second).is_negative())
        factor = -factor;
    }
  }
  std::string inner;
  for (const auto& [t, c] : g.terms)
    append(inner, canonical_string(c / factor * GiNaC::symbol("inv", t), Format::latex));
  if (vector) {
    bool any = false;
    std::string m;
    for (const ex& r : g.rest) {
      any = any || !r.is_zero();
      m += (m.empty() ? "" : " \\\\ ") + canonical_string(GiNaC::expand(r / factor), Format::latex);
    }
    if (any) append(inner, "\\begin{bmatrix}" + m + "\\end{bmatrix}");
    // a vector alone needs no parenthesis: h [a, b]ᵀ
    if (any && g.terms.empty() && factor == 1) return h_power(k) + inner;
  } else if (!g.rest[0].is_zero()) {
    append(inner, canonical_string(GiNaC::expand(g.rest[0] / factor), Format::latex));
  }
  if (inner.empty()) inner = "0";
  // one term needs no parenthesis: -\frac{h}{2}\nabla U\cdot\dot{x}
  std::size_t count = g.terms.size();
  if (!vector && !g.rest[0].is_zero()) count += terms(GiNaC::expand(g.rest[0])).size();
  const std::string hk = h_power(k);
  if (factor == 1) return hk + (hk.empty() || count == 1 ? inner : "\\Bigl(" + inner + "\\Bigr)");
  // \Bigl( \Bigr): MathJax breaks a long line only between delimiters of fixed size
  if (count == 1 && !hk.empty()) return prefix(factor, hk) + inner;
  return prefix(factor, hk) + "\\Bigl(" + inner + "\\Bigr)";
}

std::string VectorNotation::scalar_series(const std::vector<ex>& c) const {
  std::string s;
  for (std::size_t k = 0; k < c.size(); ++k)
    if (!c[k].is_zero()) {
      const std::string t = coefficient({c[k]}, false, static_cast<int>(k));
      append(s, t);
    }
  if (s.empty()) s = "0";
  return s + " + \\mathcal{O}(h^{" + std::to_string(c.size()) + "})";
}

std::string VectorNotation::vector_series(const std::vector<std::vector<ex>>& field) const {
  std::string s;
  for (std::size_t k = 0; k < field.size(); ++k) {
    bool zero = true;
    for (const ex& x : field[k]) zero = zero && x.is_zero();
    if (zero) continue;
    const std::string t = coefficient(field[k], true, static_cast<int>(k));
    append(s, t);
  }
  if (s.empty()) s = "0";
  return s + " + \\mathcal{O}(h^{" + std::to_string(field.size()) + "})";
}

std::string VectorNotation::scalar(const ex& e) const { return coefficient({e}, false, -1); }

std::string VectorNotation::vector(const std::vector<ex>& v) const {
  return coefficient(v, true, -1);
}

}  // namespace vibook::modified
