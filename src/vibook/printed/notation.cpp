// The papers' notation over the engine's jet space (notation.hpp).
#include "vibook/printed/notation.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace vibook::printed {

using GiNaC::numeric;

JetNotation::JetNotation(std::shared_ptr<const modified::JetSpace> J, std::vector<int> field_dofs)
    : J_(std::move(J)), field_dofs_(std::move(field_dofs)) {
  if (field_dofs_.empty())
    for (int i = 0; i < J_->dofs(); ++i) field_dofs_.push_back(i);
  for (std::size_t i = 0; i < field_dofs_.size(); ++i)
    point_.emplace_back("y" + std::to_string(i + 1));
}

JetNotation& JetNotation::curve(const std::string& letter, std::vector<int> dofs) {
  curves_.push_back({letter, std::move(dofs)});
  return *this;
}
JetNotation& JetNotation::primes_for_curves(bool on) {
  primes_ = on;
  return *this;
}
JetNotation& JetNotation::discrete_index(char letter) {
  discrete_ = letter;
  return *this;
}
JetNotation& JetNotation::field(const std::string& name, const std::string& sup, const ex& function,
                                const std::string& letter) {
  fields_.push_back({name, sup, function, letter});
  return *this;
}
JetNotation& JetNotation::constant(const std::string& text, const Value& value) {
  constants_[text] = value;
  return *this;
}
JetNotation& JetNotation::callable(const std::string& base,
                                   std::function<Value(const Atom&, const std::vector<Value>&)> f) {
  callables_[base] = std::move(f);
  return *this;
}
JetNotation& JetNotation::step_name(const std::string& name) {
  step_name_ = name;
  return *this;
}
JetNotation& JetNotation::time_name(const std::string& name) {
  time_name_ = name;
  time_ = GiNaC::symbol(name);
  return *this;
}

JetNotation& JetNotation::discrete(const std::string& letter, char index,
                                   std::function<Value(int, const Atom&, bool&)> value) {
  discrete_vars_.push_back({letter, index, std::move(value)});
  return *this;
}

JetNotation& JetNotation::subscripted(const std::string& text,
                                      std::function<Value(const Atom&, const Reader&)> f) {
  subscripted_[text] = std::move(f);
  return *this;
}

JetNotation& JetNotation::index_range(char letter, int from, int to) {
  ranges_[letter] = {from, to};
  return *this;
}
std::optional<std::pair<int, int>> JetNotation::index_range(char letter) const {
  if (auto it = ranges_.find(letter); it != ranges_.end()) return it->second;
  return std::nullopt;
}

JetNotation& JetNotation::slot_derivative(const std::string& base) {
  slot_derivatives_.push_back(base);
  return *this;
}

JetNotation& JetNotation::indexed(const std::string& base, std::function<Value(const ex&)> f) {
  indexed_[base] = std::move(f);
  return *this;
}

JetNotation& JetNotation::time_alias(const std::string& name, const ex& factor) {
  time_alias_[name] = factor;
  return *this;
}
JetNotation& JetNotation::jet_offset(const ex& offset) {
  jet_offset_ = offset;
  return *this;
}
JetNotation& JetNotation::anywhere(bool on) {
  anywhere_ = on;
  return *this;
}
JetNotation& JetNotation::parameter(const GiNaC::symbol& s) {
  params_.push_back(s);
  return *this;
}
JetNotation& JetNotation::pm_sign(int sign) {
  pm_ = sign;
  return *this;
}
std::vector<GiNaC::symbol> JetNotation::parameters() const {
  std::vector<GiNaC::symbol> p = params_;
  p.push_back(J_->h());
  return p;
}

std::vector<ex> JetNotation::expansion_point() const {
  std::vector<ex> x;
  for (int d : field_dofs_) x.push_back(J_->x(0, d));
  return x;
}

ex JetNotation::abstract_field(const std::vector<std::pair<int, ex>>& families) const {
  ex f = 0;
  for (const auto& [family, coef] : families) {
    std::vector<ex> args;
    for (int k = 0; k < J_->family_arity(family); ++k) {
      const int dof = J_->family_dof(family, k);
      std::size_t pos = 0;
      while (pos < field_dofs_.size() && field_dofs_[pos] != dof) ++pos;
      if (pos == field_dofs_.size())
        throw std::logic_error("a field family over a degree of freedom the notation lacks");
      args.push_back(point_[pos]);
    }
    f += coef * modified::abstract_call(family, args);
  }
  return f;
}

namespace {
bool all_digits(const std::string& s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}
// "(3)" -> 3, else -1
int paren_order(const std::string& s) {
  if (s.size() >= 3 && s.front() == '(' && s.back() == ')' && all_digits(s.substr(1, s.size() - 2)))
    return std::stoi(s.substr(1, s.size() - 2));
  return -1;
}
}  // namespace

std::optional<JetNotation::CurveRef> JetNotation::curve_ref(const Atom& a, const Reader* r) const {
  int which = -1;
  for (std::size_t k = 0; k < curves_.size(); ++k)
    if (curves_[k].letter == a.base) which = static_cast<int>(k);
  if (which < 0) return std::nullopt;
  CurveRef c;
  c.curve = which;
  int order = 0;
  for (const auto& acc : a.accents) {
    if (acc == "dot")
      order += 1;
    else if (acc == "ddot")
      order += 2;
    else if (acc == "dddot")
      order += 3;
    else if (acc == "mathbf" || acc == "boldsymbol" || acc == "bm")
      continue;
    else
      return std::nullopt;  // \bar{x}, \tilde{x}: not this curve
  }
  if (a.primes > 0) {
    if (!primes_) return std::nullopt;
    order += a.primes;
  }
  if (a.sup) {
    const int k = paren_order(a.sup_text());
    if (k >= 0) {
      order += k;
      c.consumed_sup = true;
    }
  }
  c.order = order;
  if (a.sub) {
    const std::string s = a.sub_text();
    if (all_digits(s) && curves_[which].dofs.size() > 1) {
      const int comp = std::stoi(s) - 1;
      if (comp < 0 || comp >= static_cast<int>(curves_[which].dofs.size()))
        throw IllFormed("component " + s + " of a " + std::to_string(curves_[which].dofs.size()) +
                        "-vector");
      c.component = comp;
    } else if (discrete_ && !s.empty() && s[0] == discrete_) {
      // x_j, x_{j+1}, x_{j-1}, x_{j\pm 1}: the offset after the index letter
      if (!r) return std::nullopt;
      std::vector<Token> rest(a.sub->begin() + 1, a.sub->end());
      ex off = 0;
      if (!rest.empty()) off = r->evaluate(rest).as_scalar("a step offset");
      c.offset = off;
    } else {
      return std::nullopt;
    }
  }
  return c;
}

Value JetNotation::jet(const CurveRef& c) const {
  const auto& dofs = curves_[c.curve].dofs;
  if (c.offset && !(GiNaC::ex(*c.offset) - jet_offset_).is_zero())
    return shift(c.component >= 0 ? (c.curve + 1) * 1000 + c.component + 1 : c.curve, c.order,
                 time_ + *c.offset * J_->h());
  if (c.component >= 0) return Value::scalar(J_->x(c.order, dofs[c.component]));
  std::vector<ex> v;
  for (int d : dofs) v.push_back(J_->x(c.order, d));
  return Value::vector(v);
}

Value JetNotation::shift(int curve, int derivative, const ex& time) const {
  // (curve + 1) * 1000 + (component + 1) encodes a component (jet() above); plain curves are
  // below 1000
  const int which = curve >= 1000 ? curve / 1000 - 1 : curve;
  const int component = curve >= 1000 ? curve % 1000 - 1 : -1;
  const ex s = GiNaC::expand((time - time_) / J_->h() - jet_offset_);
  if (s.has(time_) || s.has(J_->h()))
    throw ReadError("a curve evaluated at a time that is not t + (number)·h");
  const auto& dofs = curves_.at(which).dofs;
  std::vector<ex> v;
  for (std::size_t k = 0; k < dofs.size(); ++k) {
    if (component >= 0 && static_cast<int>(k) != component) continue;
    ex acc = 0;
    numeric fact = 1;
    for (int m = 0; m < cap_; ++m) {
      if (m > 0) fact *= m;
      const ex step = m == 0 ? ex(1) : GiNaC::pow(s * J_->h(), m);
      acc += step / fact * J_->x(derivative + m, dofs[k]);
    }
    v.push_back(acc);
  }
  return Value::vector(v);
}

std::optional<Entity> JetNotation::resolve(const Atom& a, const Reader& r) const {
  const std::string text = a.text();
  if (auto it = constants_.find(text); it != constants_.end()) {
    Entity e;
    e.value = it->second;
    e.consumed_sup = a.sup.has_value();
    return e;
  }
  // the atom without its superscript, for constants whose power is written on them
  if (a.sup) {
    Atom b = a;
    b.sup.reset();
    if (auto it = constants_.find(b.text()); it != constants_.end()) {
      Entity e;
      e.value = it->second;
      return e;
    }
  }
  if (a.sub && !subscripted_.empty()) {
    Atom bare = a;
    bare.sub.reset();
    bare.sup.reset();
    if (auto it = subscripted_.find(bare.text()); it != subscripted_.end()) {
      Entity e;
      e.value = it->second(a, r);
      return e;  // a superscript on it is a power
    }
  }
  for (const auto& base : slot_derivatives_) {
    if (a.base != base || !a.sub || !all_digits(a.sub_text()) || a.primes != 0 || a.sup) continue;
    bool plain = true;
    for (const auto& acc : a.accents) plain = plain && (acc == "mathbf" || acc == "boldsymbol");
    if (!plain) continue;
    Entity e;
    e.kind = Entity::Kind::op;
    e.slot = std::stoi(a.sub_text());
    e.apply = [](const Value&) -> Value { throw ReadError("D_i must be followed by a function"); };
    return e;
  }
  if (auto it = indexed_.find(a.base); it != indexed_.end() && a.sub && a.accents.empty()) {
    Entity e;
    e.value = it->second(r.evaluate(*a.sub).as_scalar("a subscript"));
    return e;
  }
  for (const auto& d : discrete_vars_) {
    if (a.base != d.letter || !a.sub || a.sub->empty() || a.primes != 0) continue;
    const auto& sub = *a.sub;
    if (sub[0].kind != Token::Kind::letter || sub[0].text[0] != d.index) continue;
    int offset = 0;
    if (sub.size() > 1) {
      const ex o =
          r.evaluate(std::vector<Token>(sub.begin() + 1, sub.end())).as_scalar("a step offset");
      if (!GiNaC::is_a<numeric>(o) || !GiNaC::ex_to<numeric>(o).is_integer())
        throw ReadError("the step offset of " + a.text() + " is not an integer");
      offset = GiNaC::ex_to<numeric>(o).to_int();
    }
    bool consumed = false;
    Entity e;
    e.value = d.value(offset, a, consumed);
    e.consumed_sup = consumed;
    return e;
  }
  const bool dotted = a.has_accent("dot") || a.has_accent("ddot") || a.has_accent("dddot");
  if (auto it = callables_.find(a.base); it != callables_.end() && !dotted) {
    Entity e;
    e.kind = Entity::Kind::callable;
    const auto f = it->second;
    // index letters bound by a sum are passed on as their values (x^i → x^2)
    Atom bound = a;
    auto is_text = [](const std::vector<Token>& ts) {
      return std::any_of(ts.begin(), ts.end(), [](const Token& t) {
        return t.cmd("text") || t.cmd("mathrm") || t.cmd("textrm") || t.cmd("operatorname");
      });
    };
    for (auto* part : {&bound.sub, &bound.sup})
      if (*part && !is_text(**part))  // a word (\text{disc}) is not an index
        for (auto& t : **part)
          if (t.kind == Token::Kind::letter)
            if (auto v = r.bound(t.text[0])) {
              t.kind = Token::Kind::number;
              t.text = std::to_string(*v);
            }
    e.call = [f, bound](const std::vector<Value>& args) { return f(bound, args); };
    e.consumed_sup = true;
    return e;
  }
  if (a.base == step_name_ && a.accents.empty() && a.primes == 0 && !a.sub) {
    Entity e;
    e.value = Value::scalar(J_->h());
    return e;
  }
  if (a.base == time_name_ && a.accents.empty() && a.primes == 0 && !a.sub) {
    Entity e;
    e.value = Value::scalar(time_);
    return e;
  }
  if (auto c = curve_ref(a, &r)) {
    Entity e;
    e.kind = Entity::Kind::curve;
    e.curve = c->component >= 0 ? (c->curve + 1) * 1000 + c->component + 1 : c->curve;
    e.derivative = c->order;
    e.value = jet(*c);
    e.consumed_sup = c->consumed_sup;
    if (c->offset) e.kind = Entity::Kind::value;  // x_{j+1} is a value, not a curve
    return e;
  }
  for (const auto& f : fields_) {
    if (f.name != a.base || !a.accents.empty()) continue;
    std::string sup = a.sup ? a.sup_text() : "";
    bool consumed = false;
    int order = a.primes;
    if (!f.sup.empty()) {
      // φ^{[1]} (and φ^{[1]}_{xx}); the superscript may also carry a derivative order after
      if (sup != f.sup) continue;
      consumed = true;
    } else if (!sup.empty()) {
      const int k = paren_order(sup);
      if (k >= 0) {
        order += k;
        consumed = true;
      } else if (sup.front() == '[') {
        continue;  // φ^{[1]} is another field
      }
    }
    if (a.sub) {
      const std::string s = a.sub_text();
      // φ_{12}, φ^{[1]}_{12}: digits name the coordinates of a partial derivative (the
      // engine's and vector_notation's way of writing what no invariant accounts for)
      if (!f.letter.empty() && dim() > 1 && a.primes == 0 && !s.empty() &&
          s.find_first_not_of("123456789") == std::string::npos &&
          std::all_of(s.begin(), s.end(), [this](char c) { return c - '0' <= dim(); })) {
        std::vector<ex> at = expansion_point();
        GiNaC::exmap here;
        for (std::size_t k = 0; k < point_.size(); ++k) here[point_[k]] = at[k];
        ex d = f.function;
        for (char c : s) d = d.diff(point_[static_cast<std::size_t>(c - '1')]);
        Entity e;
        e.kind = Entity::Kind::value;
        e.value = Value::scalar(d.subs(here));
        e.consumed_sup = consumed;
        return e;
      }
      if (f.letter.empty() || s.find_first_not_of(f.letter) != std::string::npos) continue;
      order += static_cast<int>(s.size() / f.letter.size());
    }
    Entity e;
    e.kind = Entity::Kind::field;
    e.field = f.function;
    e.order = order;
    e.value = field_tensor(f.function, order, *this);
    e.consumed_sup = consumed;
    return e;
  }
  return std::nullopt;
}

Value JetNotation::time_derivative(const Value& v, const std::string& variable, int times) const {
  ex factor = 1;
  if (variable != time_name_) {
    const auto it = time_alias_.find(variable);
    if (it == time_alias_.end())
      throw ReadError("d/d" + variable + " in a notation whose time is " + time_name_);
    factor = it->second;
  }
  return map(v, [&](const ex& e) {
    ex r = e;
    for (int k = 0; k < times; ++k) r = factor * J_->total(r);
    return r;
  });
}

namespace {
// ∂/∂(argument `slot`) of every abstract function call in e, at its own arguments (the
// printed ∂/∂x_1 φ(x_n^1, x_{n-1}^2) of a display in discrete variables).
ex slot_partial(const ex& e, int slot) {
  struct Map : GiNaC::map_function {
    int slot;
    explicit Map(int s) : slot(s) {}
    ex operator()(const ex& x) override {
      int family = 0;
      std::vector<ex> args;
      std::vector<int> index;
      if (modified::match_abstract(x, family, args, index)) {
        if (slot >= static_cast<int>(args.size())) return ex(0);
        std::vector<GiNaC::symbol> s;
        for (std::size_t k = 0; k < args.size(); ++k)
          s.emplace_back("vibook_arg" + std::to_string(k));
        ex f = modified::abstract_call(family, std::vector<ex>(s.begin(), s.end()));
        for (int i : index) f = f.diff(s[static_cast<std::size_t>(i)]);
        f = f.diff(s[static_cast<std::size_t>(slot)]);
        GiNaC::exmap back;
        for (std::size_t k = 0; k < args.size(); ++k) back[s[k]] = args[k];
        return f.subs(back);
      }
      if (GiNaC::is_a<GiNaC::add>(x)) return x.map(*this);
      if (GiNaC::is_a<GiNaC::mul>(x)) {  // product rule
        ex acc = 0;
        for (std::size_t k = 0; k < x.nops(); ++k) {
          ex term = 1;
          for (std::size_t j = 0; j < x.nops(); ++j) term *= j == k ? (*this)(x.op(j)) : x.op(j);
          acc += term;
        }
        return acc;
      }
      if (GiNaC::is_a<GiNaC::numeric>(x) || GiNaC::is_a<GiNaC::symbol>(x)) return ex(0);
      throw ReadError("∂/∂x_i of something other than sums and products of functions");
    }
  } m(slot);
  return m(e);
}
}  // namespace

Value JetNotation::partial(const Value& v, const Atom& wrt) const {
  if (anywhere_ && wrt.sub && all_digits(wrt.sub_text()) && wrt.accents.empty() &&
      wrt.primes == 0) {
    const int slot = std::stoi(wrt.sub_text()) - 1;
    return map(v, [&](const ex& e) { return slot_partial(e, slot); });
  }
  const auto c = curve_ref(wrt, nullptr);
  if (!c || c->offset) throw ReadError("∂/∂" + wrt.text() + ": not a variable of the jet space");
  const auto& dofs = curves_[c->curve].dofs;
  auto d = [&](const ex& e, int dof) { return J_->partial(e, c->order, dof); };
  if (c->component >= 0 || dofs.size() == 1) {
    const int dof = dofs[c->component >= 0 ? c->component : 0];
    return map(v, [&](const ex& e) { return d(e, dof); });
  }
  // ∂/∂ẋ of a scalar: the vector of partials
  const ex s = v.as_scalar("the numerator of ∂/∂(a vector)");
  std::vector<ex> out;
  for (int dof : dofs) out.push_back(d(s, dof));
  return Value::vector(out);
}

}  // namespace vibook::printed
