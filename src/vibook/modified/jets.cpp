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
  deriv_list_.emplace_back(s, key);
  return s;
}

ex JetSpace::partial(const ex& e, int order, int i) const {
  ex out = e.diff(x(order, i));
  if (order != 0) return out;
  // Chain rule: ∂/∂x_i U_I(x) = U_{I+i}(x). Iterate over a copy: derivative() may append.
  const auto list = deriv_list_;
  for (const auto& [s, key] : list) {
    if (!e.has(s)) continue;
    const auto& dofs = families_.at(key.family).dofs;
    for (std::size_t a = 0; a < dofs.size(); ++a) {
      if (dofs[a] != i) continue;
      std::vector<int> idx = key.index;
      idx.push_back(static_cast<int>(a));
      out += e.diff(s) * derivative(key.family, idx);
    }
  }
  return out;
}

ex JetSpace::total(const ex& e) const {
  const int top = std::max(max_order(e), 0);
  ex out = 0;
  for (int k = 0; k <= top; ++k)
    for (int i = 0; i < n_; ++i) {
      if (k == 0)
        out += partial(e, 0, i) * x(1, i);
      else
        out += e.diff(x(k, i)) * x(k + 1, i);
    }
  return out;
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
