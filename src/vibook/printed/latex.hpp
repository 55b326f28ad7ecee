/// \file latex.hpp
/// \brief A reader for the LaTeX of the papers' displayed formulas: it turns a display, as
/// printed, into GiNaC expressions, so that no printed formula is ever retyped by hand.
///
/// The reader knows the grammar of the LaTeX subset the three papers use (`\\frac`, `\\left(`,
/// `\\sqrt`, sub- and superscripts, primes, dots, `\\langle a, b \\rangle`, `|x|`, `[a, b]^\\top`,
/// `\\begin{bmatrix}`, `\\sum_{i=1}^s`, `\\mathcal{O}(h^k)`, `\\frac{d}{dt}`, `\\frac{\\partial}{\\partial
/// x_i}`, chains `A = B = C`, `aligned` environments) and nothing of what the symbols mean. That
/// is a *notation* (notation.hpp): one per paper and setting, it says that `U''` is the Hessian
/// of the potential, `x^{(3)}` the third derivative of the curve, `V_{qq}` a second derivative,
/// and so on.
///
/// Values are tensors (scalars, vectors, matrices, three-tensors) with GiNaC components.
/// Juxtaposition multiplies: a scalar scales; a vector times a vector is their contraction
/// (Vermeeren's U'ẍ is ⟨∇U, ẍ⟩); a matrix times a vector is the product; a derivative tensor
/// followed by an argument list, `U''(\\dot{x}, \\dot{x})` or `\\phi_{xx}\\langle\\dot{x},\\dot{x}
/// \\rangle`, is applied to its arguments (contracted slot by slot).
///
/// Reading rules the papers need, stated once:
/// - An operator (`\\frac{d}{dt}`, `\\frac{\\partial}{\\partial x_1}`, `\\nabla`) applies to the
///   product of the factors that follow it in its term.
/// - `\\sum_{i=1}^{s}` sums the term that follows it; a later term of the same bracket that uses
///   the summation index is summed over it too (Shen & Sun's Theorem 10 writes one sum over two
///   lines).
/// - `\\mathcal{O}(h^k)` marks the display's remainder: it is zero, and the display is compared
///   below h^k only. `\\dots` in a sum is zero (the check says to which order it compares).
/// - A comma or full stop at the end, `\\quad` and the equation tag are not part of the formula.
///
/// Two kinds of failure are kept apart: ReadError (the reader cannot read the text: a
/// limitation of ours, reported as "not compared") and IllFormed (the text reads, but means
/// nothing: a tensor given the wrong number of arguments, a vector added to a scalar — the
/// printed formula is wrong, and a correction is searched for).
///
/// Chapter: \ref formulas.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <ginac/ginac.h>

namespace vibook::printed {

using GiNaC::ex;

/// The reader cannot read this text (an unsupported construct or an unknown symbol).
class ReadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The text reads but is not a well-formed formula (wrong number of arguments for a tensor,
/// mismatched dimensions): the printed formula itself is at fault.
class IllFormed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Token {
  enum class Kind { command, letter, number, symbol };
  Kind kind = Kind::symbol;
  std::string text;       ///< command name without the backslash, or the character(s)
  std::size_t begin = 0;  ///< byte range in the source text
  std::size_t end = 0;
  bool space_before = false;  ///< whitespace precedes it in the source (for re-printing)
  bool is(Kind k, std::string_view t) const { return kind == k && text == t; }
  bool cmd(std::string_view t) const { return is(Kind::command, t); }
  bool sym(std::string_view t) const { return is(Kind::symbol, t); }
};

/// Tokens of a LaTeX math text (whitespace dropped, positions kept). ReadError on a
/// character outside printable ASCII.
std::vector<Token> tokenize(std::string_view latex);
/// The tokens printed back as LaTeX (spacing as in the source where it was known).
std::string print(const std::vector<Token>& tokens);

/// A tensor with GiNaC components, or a tuple of values (an argument list).
struct Value {
  int rank = 0;              ///< 0 scalar, 1 vector, 2 matrix, 3 three-tensor
  int n = 1;                 ///< dimension of each index
  std::vector<ex> c{ex(0)};  ///< n^rank components, row-major
  int slots = 0;             ///< a derivative tensor: the number of arguments it takes
  bool transposed = false;   ///< a vector written u^T
  bool tuple = false;        ///< an argument list (a, b, …) or ⟨a, b⟩
  bool angle = false;        ///< the tuple was written ⟨…⟩
  std::vector<Value> items;  ///< the tuple's entries

  static Value scalar(const ex& e);
  static Value vector(const std::vector<ex>& v);
  static Value zeros(int rank, int n);
  bool is_scalar() const { return !tuple && rank == 0; }
  /// The scalar, or component i of a vector; IllFormed otherwise.
  const ex& as_scalar(std::string_view what) const;
};

/// A symbol as written: base (a letter or a command such as `phi`, `mathcal{L}`), accents
/// (`dot`, `ddot`, `bar`, `hat`, `tilde`, `mathbf`, …, outermost first), primes, and the raw
/// tokens of its subscript and superscript.
struct Atom {
  std::string base;
  std::vector<std::string> accents;
  int primes = 0;
  std::optional<std::vector<Token>> sub, sup;
  /// The atom printed back, for messages ("\\dot{x}_1").
  std::string text() const;
  bool has_accent(std::string_view a) const;
  /// The subscript's tokens as one string of their texts ("xx", "1", "ij", "text{disc}").
  std::string sub_text() const;
  std::string sup_text() const;
};

class Reader;

/// What an atom stands for.
struct Entity {
  enum class Kind {
    value,     ///< a tensor (x, ẋ, h, m, a coefficient)
    field,     ///< a function of position with derivative tensors (U, φ, V, f, ∇φ, U'')
    curve,     ///< a curve of time: its value is the jet, application shifts it (x(t+h))
    callable,  ///< anything else applied to an argument list (EL(·), L_disc(x_j, x_{j+1}, h))
    op         ///< an operator on the factor that follows (d/dt as notation supplies it)
  };
  Kind kind = Kind::value;
  Value value;  ///< value, field (its tensor at the expansion point), curve (the jet)
  /// field: the scalar function as an expression in the point symbols (Notation::point),
  /// differentiated `order` times (the tensor has rank `order` in N dimensions).
  ex field;
  int order = 0;
  /// curve: the curve's index (the notation's meaning) and derivative order.
  int curve = 0, derivative = 0;
  std::function<Value(const std::vector<Value>&)> call;  ///< callable
  std::function<Value(const Value&)> apply;              ///< op
  /// op that differentiates a callable with respect to its slot-th argument (D_2 L_d(a, b)):
  /// the reader gives it the callable and the evaluated arguments.
  int slot = 0;
  bool consumed_sup = false;  ///< the superscript belonged to the symbol (U^{(3)}, φ^{[1]})
};

/// What the symbols of one paper mean in one setting. Checks build one over the engine's
/// jet space (notation.hpp); the reader asks it about every atom.
class Notation {
 public:
  virtual ~Notation() = default;
  /// The entity an atom denotes, or nullopt if the notation does not know it.
  virtual std::optional<Entity> resolve(const Atom& a, const Reader& r) const = 0;
  /// Number of dimensions of vectors (1: everything is a scalar).
  virtual int dim() const = 0;
  /// The point symbols y_1 … y_N in which a field is written.
  virtual const std::vector<GiNaC::symbol>& point() const = 0;
  /// The expansion point of fields: the jet x (its value at the curve).
  virtual std::vector<ex> expansion_point() const = 0;
  /// The step symbol whose powers `\\mathcal{O}(…)` counts (h, or Δa).
  virtual GiNaC::symbol step() const = 0;
  /// The curve `curve` at time `time` (an expression in time_symbol() and the step), with
  /// `derivative` derivatives; the reader applies a curve this way.
  virtual Value shift(int curve, int derivative, const ex& time) const;
  /// The symbol t (or a) that a curve's argument is written in.
  virtual GiNaC::symbol time_symbol() const;
  /// The total time derivative (d/dt) of a value, `times` times; ReadError by default.
  virtual Value time_derivative(const Value& v, const std::string& variable, int times) const;
  /// ∂v/∂(atom) for an atom of the denominator of `\\frac{\\partial …}{\\partial …}`.
  virtual Value partial(const Value& v, const Atom& wrt) const;
  /// How many terms of a Taylor expansion a point evaluation keeps (powers of the step), and
  /// the last index of a sum to ∞.
  virtual int cap() const { return 8; }
  /// The sign that `\\pm` stands for in this reading (+1 or −1; `\\mp` the other one). A display
  /// with ± is read once per sign.
  virtual int pm() const { return 0; }
  /// A field applied to one argument of its dimension is evaluated there, wherever that is
  /// (displays in discrete variables); otherwise only near the jet point.
  virtual bool points_anywhere() const { return false; }
  /// The range of a summation index written without limits (\\sum_j): nullopt if unknown.
  virtual std::optional<std::pair<int, int>> index_range(char) const { return std::nullopt; }
  /// Symbols that a correction's factor may contain besides numbers (the step h, the speed of
  /// light c): a term multiplied by c^-2 is a correction, one multiplied by x_1 is not.
  virtual std::vector<GiNaC::symbol> parameters() const { return {step()}; }
};

/// The reading of a display: its members (A = B = C gives three; a top-level comma separates
/// members too: "A = B, C = D" gives four), each with the power of the step in its remainder,
/// if it has one.
struct Reading {
  std::vector<Value> members;
  std::vector<std::optional<int>> remainder;  ///< O(h^k): k; nullopt: none printed
  std::vector<bool> dots;                     ///< the member has `\dots` terms
};

/// Read `latex` with `notation`. ReadError / IllFormed as above.
Reading read(std::string_view latex, const Notation& notation);
/// Read already tokenized text (the correction search edits tokens). `scale`, if given, maps
/// a token index (the first token of a term) to a factor by which that term is multiplied.
Reading read(const std::vector<Token>& tokens, const Notation& notation,
             const std::map<std::size_t, ex>& scale = {});

/// The terms of every sum in the text, as token ranges [first, end) (for the correction
/// search), as far as the text reads. `first` is the term's first token after its sign.
std::vector<std::pair<std::size_t, std::size_t>> term_ranges(const std::vector<Token>& tokens,
                                                             const Notation& notation);

/// The parser's view that a notation may consult: the integer bound to a summation index.
class Reader {
 public:
  virtual ~Reader() = default;
  /// The value of a bound summation index ('i' → 2), or nullopt.
  virtual std::optional<int> bound(char index) const = 0;
  /// Read a token sequence (a subscript, a superscript) as an expression.
  virtual Value evaluate(const std::vector<Token>& tokens) const = 0;
};

/// For notations: an index letter (i, j) that no enclosing sum binds. The reader catches it
/// and, where a sum over that letter came earlier in the same bracket, sums the term over it.
[[noreturn]] void unbound_index(char index);

/// The tensor of the order-th derivatives of a field (an expression in the notation's point
/// symbols) at the notation's expansion point; slots = order. In one dimension a scalar.
Value field_tensor(const ex& field, int order, const Notation& notation);
/// The same at another point (one expression per point symbol).
Value field_tensor_at(const ex& field, int order, const Notation& notation,
                      const std::vector<ex>& point);

// --- tensor arithmetic (used by the reader and by notations) ----------------------------------
Value add(const Value& a, const Value& b);
Value scale(const ex& s, const Value& v);
/// Juxtaposition a b as described above.
Value multiply(const Value& a, const Value& b);
/// a · b (contraction of the last index of a with the first of b; scalars multiply).
Value dot(const Value& a, const Value& b);
/// A derivative tensor applied to arguments, slot by slot.
Value contract(const Value& tensor, const std::vector<Value>& args);
/// Every component mapped by f.
Value map(const Value& v, const std::function<ex(const ex&)>& f);

}  // namespace vibook::printed
