/// \file notation.hpp
/// \brief The papers' notation over the engine's jet space: what `x`, `\\dot{x}`, `x^{(3)}`,
/// `U''`, `\\phi_{xx}`, `\\phi^{[1]}`, `V_{qq}`, `q'`, `h` and `\\Delta a` mean, set up per paper
/// and setting by the check that compares a display.
///
/// A JetNotation is configured with
/// - *curves*: a letter and the degrees of freedom of the jet space it covers (`x` all of
///   them, as a vector; Sharma's `q` and `t` one each). Its derivatives are written with dots
///   (`\\dot{x}`, `\\ddot{x}`), primes (`q'''`), or `x^{(k)}`; a digit subscript picks a
///   component (`\\dot{x}_2`); a step subscript (`x_j`, `x_{j+1}`, with the letter given by
///   discrete_index) is the curve at t + (offset)·h; applied to a time, `x(t+h)` is the curve's
///   Taylor series there.
/// - *fields*: a name (`U`, `phi`, `V`, `f`), an optional superscript that selects it
///   (`[1]`), and the scalar function as an expression in the point symbols (an abstract
///   function of the engine, or a concrete potential). Derivatives are written with primes,
///   `^{(k)}`, `\\nabla`, or a subscript repeating the position letter (`\\phi_{xx}`, `V_{qq}`).
/// - *constants* and *callables* by the exact text of the atom (`m`, `\\alpha`, `\\lambda`,
///   `\\text{EL}`).
///
/// Chapter: \ref formulas.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "vibook/modified/jets.hpp"
#include "vibook/printed/latex.hpp"

namespace vibook::printed {

class JetNotation : public Notation {
 public:
  /// Fields are functions of the degrees of freedom `field_dofs` of J (all when empty).
  explicit JetNotation(std::shared_ptr<const modified::JetSpace> J,
                       std::vector<int> field_dofs = {});

  /// A curve named by a letter over the degrees of freedom `dofs` (several: a vector).
  JetNotation& curve(const std::string& letter, std::vector<int> dofs);
  /// Derivatives of curves written with primes (Sharma: q', q''), not dots.
  JetNotation& primes_for_curves(bool on = true);
  /// The letter of a step subscript (x_j, x_{j+1}): offset 0 at that letter.
  JetNotation& discrete_index(char letter);
  /// A field: `name` (a letter or a command name such as "phi"), selected by the superscript
  /// `sup` ("" for none, "[1]"), the scalar function in the point symbols, and the letter that
  /// repeated in a subscript counts derivatives ("x" for φ_xx, "q" for V_qq; "" for none).
  JetNotation& field(const std::string& name, const std::string& sup, const ex& function,
                     const std::string& derivative_letter = "");
  /// An atom written exactly as `text` (Atom::text()) stands for `value`.
  JetNotation& constant(const std::string& text, const Value& value);
  /// An atom with base `base` (any sub- or superscript, passed on) is applied like a function.
  JetNotation& callable(const std::string& base,
                        std::function<Value(const Atom&, const std::vector<Value>&)> f);
  /// The step's name: "h" (default) or "Delta a".
  JetNotation& step_name(const std::string& name);
  /// The time variable curves are written in: "t" (default) or "a".
  JetNotation& time_name(const std::string& name);

  std::optional<Entity> resolve(const Atom& a, const Reader& r) const override;
  int dim() const override { return static_cast<int>(point_.size()); }
  const std::vector<GiNaC::symbol>& point() const override { return point_; }
  std::vector<ex> expansion_point() const override;
  GiNaC::symbol step() const override { return J_->h(); }
  Value shift(int curve, int derivative, const ex& time) const override;
  GiNaC::symbol time_symbol() const override { return time_; }
  Value time_derivative(const Value& v, const std::string& variable, int times) const override;
  Value partial(const Value& v, const Atom& wrt) const override;
  int cap() const override { return cap_; }
  /// A discrete variable: `letter` with a step subscript (x_j, x_{j+1}, q_k^1) is the value
  /// `value(offset, atom)` gives (offset: the number after the index letter). The function may
  /// read the atom's superscript (a component) and then says so by returning consumed = true.
  JetNotation& discrete(const std::string& letter, char index,
                        std::function<Value(int offset, const Atom& a, bool& consumed)> value);
  /// `base_i` (D_1, \\mathbf{D}_3) is the derivative with respect to the i-th argument of the
  /// function that follows it (D_1 L_d(a, b)).
  JetNotation& slot_derivative(const std::string& base);
  /// An atom `base` with a subscript read as an expression (B_{2i} in a sum over i): the value
  /// f(subscript).
  JetNotation& indexed(const std::string& base, std::function<Value(const ex&)> f);
  /// An atom written `text` with any subscript (\\hat{b}_i, \\bar{a}_{ij}, c_i): the value
  /// f(atom, reader), which reads the subscript's index letters through Reader::bound.
  JetNotation& subscripted(const std::string& text,
                           std::function<Value(const Atom&, const Reader&)> f);
  /// d/d`name` stands for factor · d/d(time): Sharma writes d/dt for (1/t') d/da.
  JetNotation& time_alias(const std::string& name, const ex& factor);
  /// The jets are the curve's derivatives at t + offset·h (Shen & Sun take [x] at t + h/2).
  JetNotation& jet_offset(const ex& offset);
  /// A field applied to one argument is evaluated there, wherever that is (displays in
  /// discrete variables); by default only arguments near the jet point are points.
  JetNotation& anywhere(bool on = true);
  /// The range of an index letter summed without limits (\\sum_j).
  JetNotation& index_range(char letter, int from, int to);
  std::optional<std::pair<int, int>> index_range(char letter) const override;
  /// A symbol a correction's factor may contain (besides the step).
  JetNotation& parameter(const GiNaC::symbol& s);
  /// ± read as this sign (+1 or −1).
  JetNotation& pm_sign(int sign);
  bool points_anywhere() const override { return anywhere_; }
  int pm() const override { return pm_; }
  std::vector<GiNaC::symbol> parameters() const override;
  /// Taylor terms kept by point evaluations and shifted curves (default 8).
  JetNotation& set_cap(int cap) {
    cap_ = cap;
    return *this;
  }

  const modified::JetSpace& jets() const { return *J_; }
  /// An abstract field over the point symbols: Σ coef·F_family(y).
  ex abstract_field(const std::vector<std::pair<int, ex>>& families) const;

 private:
  struct Curve {
    std::string letter;
    std::vector<int> dofs;
  };
  struct Field {
    std::string name, sup;
    ex function;
    std::string letter;
  };
  std::shared_ptr<const modified::JetSpace> J_;
  std::vector<int> field_dofs_;
  std::vector<GiNaC::symbol> point_;
  std::vector<Curve> curves_;
  std::vector<Field> fields_;
  std::map<std::string, Value> constants_;
  std::map<std::string, std::function<Value(const Atom&, const std::vector<Value>&)>> callables_;
  bool primes_ = false;
  char discrete_ = 0;
  std::string step_name_ = "h", time_name_ = "t";
  GiNaC::symbol time_{"t"};
  int cap_ = 8;
  std::map<std::string, ex> time_alias_;
  struct Discrete {
    std::string letter;
    char index;
    std::function<Value(int, const Atom&, bool&)> value;
  };
  std::vector<Discrete> discrete_vars_;
  std::map<std::string, std::function<Value(const ex&)>> indexed_;
  std::vector<std::string> slot_derivatives_;
  std::map<char, std::pair<int, int>> ranges_;
  std::map<std::string, std::function<Value(const Atom&, const Reader&)>> subscripted_;
  ex jet_offset_ = 0;
  bool anywhere_ = false;
  int pm_ = 0;
  std::vector<GiNaC::symbol> params_;

  /// The curve atom's (curve, derivative order, component or -1, step offset or none).
  struct CurveRef {
    int curve = -1, order = 0, component = -1;
    std::optional<ex> offset;
    bool consumed_sup = false;
  };
  std::optional<CurveRef> curve_ref(const Atom& a, const Reader* r) const;
  Value jet(const CurveRef& c) const;
};

}  // namespace vibook::printed
