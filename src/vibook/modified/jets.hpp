/// \file jets.hpp
/// \brief Jet space of the modified-equation engine (Vermeeren 2017, §3–4): the derivatives
/// x, ẋ, ẍ, … of a curve as independent GiNaC symbols, abstract functions whose partial
/// derivatives at x are symbols, and the operators ∂/∂x^{(ℓ)} and the total time derivative
/// D = Σ x^{(ℓ+1)} ∂/∂x^{(ℓ)}.
///
/// Chapter: \ref chapter-modified.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <ginac/ginac.h>

namespace vibook::modified {

using GiNaC::ex;

/// An abstract function U(x_1, …, x_N) inside a discrete Lagrangian expression:
/// `abstract_fn(family, x_1, …, x_N)`. The engine never looks inside it; its partial
/// derivatives at the expansion point become symbols (JetSpace::derivative).
ex abstract_call(int family, const std::vector<ex>& args);
/// True if e is an abstract_call or a derivative of one; sets family, arguments and the
/// multi-index of the derivative (sorted, 0-based degrees of freedom).
bool match_abstract(const ex& e, int& family, std::vector<ex>& args, std::vector<int>& index);

/// Jets of an N-degree-of-freedom curve, and the derivative symbols of abstract functions.
class JetSpace {
 public:
  explicit JetSpace(int dofs);
  int dofs() const { return n_; }

  /// x_i^{(order)}: x1, v1 (ẋ1), x1_2 (ẍ1), x1_3, … (names valid in Python).
  GiNaC::symbol x(int order, int i) const;
  /// The momentum p_i of the Legendre transform.
  GiNaC::symbol p(int i) const;
  /// The step size h.
  const GiNaC::symbol& h() const { return h_; }

  /// Register an abstract function family ("U", "phi1", …); returns its id. Its arguments
  /// are the degrees of freedom `dofs` (all of them when empty), in that order.
  int add_family(const std::string& name, const std::string& tex, std::vector<int> dofs = {});
  /// The degree of freedom of argument `arg` of a family.
  int family_dof(int family, int arg) const { return families_.at(family).dofs.at(arg); }
  int family_arity(int family) const { return static_cast<int>(families_.at(family).dofs.size()); }
  int families() const { return static_cast<int>(families_.size()); }
  const std::string& family_name(int f) const { return families_.at(f).name; }
  const std::string& family_tex(int f) const { return families_.at(f).tex; }
  /// The symbol for ∂^{|I|} U_f / ∂x_{I} at x (I: argument positions, sorted; empty = the
  /// value).
  GiNaC::symbol derivative(int family, std::vector<int> index) const;
  /// The reverse of derivative(): true if s is a derivative symbol, with its family and
  /// index.
  bool derivative_of(const ex& s, int& family, std::vector<int>& index) const;

  /// ∂e/∂x_i^{(order)}; for order 0 the chain rule through the abstract derivatives.
  ex partial(const ex& e, int order, int i) const;
  /// The total time derivative D e, on the free jets (every x^{(ℓ)} independent).
  ex total(const ex& e) const;
  /// The total time derivative with x_d^{(ℓ)}, ℓ ≥ 1, held fixed for every d with
  /// frozen[d]: the part of D e that does not come from ẍ_d, x_d^{(3)}, … (the engine adds
  /// it along a modified equation that gives ẍ_d).
  ex total_except(const ex& e, const std::vector<bool>& frozen) const;
  /// Highest jet order that occurs in e (0 if none beyond x; −1 if e has no x at all).
  int max_order(const ex& e) const;
  /// The same for one degree of freedom.
  int max_order(const ex& e, int dof) const;
  /// The reference path: partial, total and total_except as the chain rule over every
  /// symbol of e with one GiNaC diff each (the engine's original algorithm, slow once the
  /// derivative symbols number in the hundreds) instead of the one-walk derivation. For
  /// checking the fast path (`vibook modified --reference`); the results are equal.
  void set_reference(bool on) const { reference_ = on; }
  bool reference() const { return reference_; }
  /// Highest jet order created so far.
  int created_order() const { return static_cast<int>(jets_.size()) - 1; }

 private:
  struct Family {
    std::string name, tex;
    std::vector<int> dofs;
  };
  int n_;
  GiNaC::symbol h_;
  mutable std::vector<std::vector<GiNaC::symbol>> jets_;
  mutable std::vector<GiNaC::symbol> p_;
  std::vector<Family> families_;
  struct Key {
    int family;
    std::vector<int> index;
    bool operator<(const Key& o) const {
      return family != o.family ? family < o.family : index < o.index;
    }
  };
  mutable std::map<Key, GiNaC::symbol> deriv_;
  // Reverse look-up of the jet and derivative symbols: (order, dof) and Key.
  mutable std::map<ex, std::pair<int, int>, GiNaC::ex_is_less> jet_index_;
  mutable std::map<ex, Key, GiNaC::ex_is_less> deriv_index_;
  mutable bool reference_ = false;
  void ensure_order(int order) const;
  /// A derivation δ of e (δ(a + b) = δa + δb, δ(ab) = a δb + b δa, δ(a^n) = n a^{n−1} δa,
  /// and the chain rule through GiNaC's diff for any other node) in one walk over the
  /// expression tree, with δ of each symbol from `rule` .
  /// One walk replaces one GiNaC diff per symbol, which dominated the engine's time once the
  /// derivative symbols number in the hundreds (dimension 3, order 6).
  template <class Rule>
  ex derive(const ex& e, const Rule& rule) const;
  /// δ of a jet or derivative symbol for the time derivative D (frozen: see total_except).
  ex time_rule(const ex& s, const std::vector<bool>* frozen) const;
  /// δ of a symbol for ∂/∂x_i (x_i → 1, U_I → Σ U_{I+a} over the arguments a of dof i).
  ex space_rule(const ex& s, int i) const;
};

}  // namespace vibook::modified
