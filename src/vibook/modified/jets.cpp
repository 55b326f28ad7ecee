// Jet space of the modified-equation engine: Vermeeren 2017, §3.2 (derivatives of a curve as
// independent variables) and §4.2 (expansions around the midpoint).
#include "vibook/modified/jets.hpp"

#include <algorithm>
#include <stdexcept>

namespace vibook::modified {

// Abstract functions of 1, 2 and 3 degrees of freedom; the first argument is the family id.
DECLARE_FUNCTION_2P(vibook_abstract1)
DECLARE_FUNCTION_3P(vibook_abstract2)
DECLARE_FUNCTION_4P(vibook_abstract3)
REGISTER_FUNCTION(vibook_abstract1, dummy())
REGISTER_FUNCTION(vibook_abstract2, dummy())
REGISTER_FUNCTION(vibook_abstract3, dummy())

ex abstract_call(int family, const std::vector<ex>& args) {
  const ex f = family;
  switch (args.size()) {
    case 1:
      return vibook_abstract1(f, args[0]);
    case 2:
      return vibook_abstract2(f, args[0], args[1]);
    case 3:
      return vibook_abstract3(f, args[0], args[1], args[2]);
    default:
      throw std::invalid_argument("abstract functions support 1 to 3 degrees of freedom");
  }
}

bool match_abstract(const ex& e, int& family, std::vector<ex>& args, std::vector<int>& index) {
  if (!GiNaC::is_a<GiNaC::function>(e)) return false;
  const unsigned s = GiNaC::ex_to<GiNaC::function>(e).get_serial();
  if (s != vibook_abstract1_SERIAL::serial && s != vibook_abstract2_SERIAL::serial &&
      s != vibook_abstract3_SERIAL::serial)
    return false;
  family = GiNaC::ex_to<GiNaC::numeric>(e.op(0)).to_int();
  args.clear();
  for (std::size_t k = 1; k < e.nops(); ++k) args.push_back(e.op(k));
  index.clear();
  if (GiNaC::is_a<GiNaC::fderivative>(e)) {
    for (unsigned param : GiNaC::ex_to<GiNaC::fderivative>(e).derivatives()) {
      if (param == 0) throw std::logic_error("derivative with respect to a family id");
      index.push_back(static_cast<int>(param) - 1);
    }
  }
  std::sort(index.begin(), index.end());
  return true;
}

JetSpace::JetSpace(int dofs) : n_(dofs), h_("h", "h") {
  if (dofs < 1 || dofs > 3)
    throw std::invalid_argument(std::to_string(dofs) + " degrees of freedom: supported are 1 to 3");
  ensure_order(2);
  for (int i = 0; i < n_; ++i) {
    const std::string name = "p" + std::to_string(i + 1);
    const std::string tex = n_ == 1 ? "p" : "p_{" + std::to_string(i + 1) + "}";
    p_.emplace_back(name, tex);
  }
}

void JetSpace::ensure_order(int order) const {
  while (static_cast<int>(jets_.size()) <= order) {
    const int k = static_cast<int>(jets_.size());
    std::vector<GiNaC::symbol> row;
    for (int i = 0; i < n_; ++i) {
      const std::string sub = n_ == 1 ? "" : "_{" + std::to_string(i + 1) + "}";
      std::string name, tex;
      if (k == 0) {
        name = "x" + std::to_string(i + 1);
        tex = "x" + sub;
      } else if (k == 1) {
        name = "v" + std::to_string(i + 1);
        tex = "\\dot{x}" + sub;
      } else {
        name = "x" + std::to_string(i + 1) + "_" + std::to_string(k);
        tex = k == 2 ? "\\ddot{x}" + sub : "{x" + sub + "^{(" + std::to_string(k) + ")}}";
      }
      row.emplace_back(name, tex);
      jet_index_.emplace(row.back(), std::make_pair(k, i));
    }
    jets_.push_back(std::move(row));
  }
}

GiNaC::symbol JetSpace::x(int order, int i) const {
  ensure_order(order);
  return jets_.at(order).at(i);
}

GiNaC::symbol JetSpace::p(int i) const { return p_.at(i); }

int JetSpace::add_family(const std::string& name, const std::string& tex, std::vector<int> dofs) {
  if (dofs.empty())
    for (int i = 0; i < n_; ++i) dofs.push_back(i);
  for (int d : dofs)
    if (d < 0 || d >= n_) throw std::invalid_argument("abstract function of a missing dof");
  families_.push_back({name, tex, std::move(dofs)});
  return static_cast<int>(families_.size()) - 1;
}

GiNaC::symbol JetSpace::derivative(int family, std::vector<int> index) const {
  std::sort(index.begin(), index.end());
  const Key key{family, index};
  if (auto it = deriv_.find(key); it != deriv_.end()) return it->second;
  const Family& f = families_.at(family);
  std::string name = f.name, tex = f.tex;
  if (!index.empty()) {
    name += "_";
    for (int i : index) name += std::to_string(i + 1);
    if (f.dofs.size() == 1) {
      const auto m = index.size();
      tex += m <= 3 ? "^{" + std::string(m, '\'') + "}" : "^{(" + std::to_string(m) + ")}";
    } else {
      std::string sub;
      for (int i : index) sub += std::to_string(i + 1);
      tex += "_{" + sub + "}";
    }
  }
  GiNaC::symbol s(name, "{" + tex + "}");  // braced: safe under a power's superscript
  deriv_.emplace(key, s);
  deriv_index_.emplace(s, key);
  return s;
}

bool JetSpace::derivative_of(const ex& s, int& family, std::vector<int>& index) const {
  const auto d = deriv_index_.find(s);
  if (d == deriv_index_.end()) return false;
  family = d->second.family;
  index = d->second.index;
  return true;
}

namespace {
// δe = Σ_s ∂e/∂s · δs over the symbols s of e, one GiNaC diff each.
template <class Rule>
ex chain_rule(const ex& e, const Rule& rule) {
  GiNaC::exset symbols;
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
    if (GiNaC::is_a<GiNaC::symbol>(*it)) symbols.insert(*it);
  ex out = 0;
  for (const ex& s : symbols) {
    const ex d = rule(s);
    if (!d.is_zero()) out += e.diff(GiNaC::ex_to<GiNaC::symbol>(s)) * d;
  }
  return out;
}
}  // namespace

template <class Rule>
ex JetSpace::derive(const ex& top, const Rule& rule) const {
  if (reference_) return chain_rule(top, rule);
  // Powers and other non-polynomial nodes recur across the terms of a sum: memoized per call.
  std::map<ex, ex, GiNaC::ex_is_less> memo;
  const auto walk = [&](const auto& self, const ex& e) -> ex {
    if (GiNaC::is_a<GiNaC::numeric>(e)) return 0;
    if (GiNaC::is_a<GiNaC::symbol>(e)) return rule(e);
    if (GiNaC::is_a<GiNaC::add>(e)) {
      GiNaC::exvector terms;
      terms.reserve(e.nops());
      for (std::size_t k = 0; k < e.nops(); ++k) {
        ex d = self(self, e.op(k));
        if (!d.is_zero()) terms.push_back(std::move(d));
      }
      return GiNaC::add(terms);
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
      GiNaC::exvector factors;
      for (std::size_t k = 0; k < e.nops(); ++k) factors.push_back(e.op(k));
      GiNaC::exvector terms;
      for (std::size_t k = 0; k < factors.size(); ++k) {
        ex d = self(self, factors[k]);
        if (d.is_zero()) continue;
        GiNaC::exvector f = factors;
        f[k] = d;
        terms.push_back(GiNaC::mul(f));
      }
      return GiNaC::add(terms);
    }
    if (auto it = memo.find(e); it != memo.end()) return it->second;
    ex out = 0;
    if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1))) {
      const ex d = self(self, e.op(0));
      if (!d.is_zero()) out = e.op(1) * GiNaC::pow(e.op(0), e.op(1) - 1) * d;
    } else {
      // Any other node (functions, symbolic exponents): the chain rule over its symbols.
      out = chain_rule(e, rule);
    }
    memo.emplace(e, out);
    return out;
  };
  return walk(walk, top);
}

ex JetSpace::space_rule(const ex& s, int i) const {
  if (auto j = jet_index_.find(s); j != jet_index_.end())
    return j->second.first == 0 && j->second.second == i ? ex(1) : ex(0);
  const auto d = deriv_index_.find(s);
  if (d == deriv_index_.end()) return 0;
  const Key key = d->second;  // copied: derivative() may insert into the index
  const auto& dofs = families_.at(key.family).dofs;
  ex out = 0;
  for (std::size_t a = 0; a < dofs.size(); ++a) {
    if (dofs[a] != i) continue;
    std::vector<int> idx = key.index;
    idx.push_back(static_cast<int>(a));
    out += derivative(key.family, idx);
  }
  return out;
}

ex JetSpace::time_rule(const ex& s, const std::vector<bool>* frozen) const {
  if (auto j = jet_index_.find(s); j != jet_index_.end()) {
    const auto [k, i] = j->second;
    if (k >= 1 && frozen && (*frozen)[i]) return 0;
    return x(k + 1, i);
  }
  const auto d = deriv_index_.find(s);
  if (d == deriv_index_.end()) return 0;
  const Key key = d->second;
  const auto& dofs = families_.at(key.family).dofs;
  ex out = 0;
  for (std::size_t a = 0; a < dofs.size(); ++a) {
    std::vector<int> idx = key.index;
    idx.push_back(static_cast<int>(a));
    out += derivative(key.family, idx) * x(1, dofs[a]);
  }
  return out;
}

ex JetSpace::partial(const ex& e, int order, int i) const {
  if (order != 0) return e.diff(x(order, i));
  // Chain rule: ∂/∂x_i U_I(x) = U_{I+i}(x).
  return derive(e, [&](const ex& s) { return space_rule(s, i); });
}

ex JetSpace::total(const ex& e) const {
  return derive(e, [&](const ex& s) { return time_rule(s, nullptr); });
}

ex JetSpace::total_except(const ex& e, const std::vector<bool>& frozen) const {
  if (static_cast<int>(frozen.size()) != n_) throw std::invalid_argument("total_except: frozen");
  return derive(e, [&](const ex& s) { return time_rule(s, &frozen); });
}

int JetSpace::max_order(const ex& e, int dof) const {
  int top = -1;
  for (int k = 0; k < static_cast<int>(jets_.size()); ++k)
    if (e.has(jets_[k][dof])) top = k;
  return top;
}

int JetSpace::max_order(const ex& e) const {
  int top = -1;
  for (int k = 0; k < static_cast<int>(jets_.size()); ++k)
    for (int i = 0; i < n_; ++i)
      if (e.has(jets_[k][i])) top = k;
  return top;
}

}  // namespace vibook::modified
