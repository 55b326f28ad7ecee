// A discrete Lagrangian typed as text (expression.hpp): a recursive-descent parser that keeps
// the text's structure, checking as it goes what is a vector and what a scalar, into the small
// tree that expression.hpp evaluates on any scalar.
#include "vibook/verify/expression.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <set>
#include <string_view>
#include <utility>

namespace vibook::verify {

GiNaC::numeric parse_rational(const std::string& s, const std::string& argument) {
  const auto bad = [&] {
    return ArgumentError(argument, "'" + s + "' is not a number (write 1/2, 0.25, 3 or 2.5e-1)");
  };
  const auto digits = [](const std::string& t) {
    return !t.empty() && t.size() <= 18 &&
           std::all_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; });
  };
  std::string t = s;
  bool negative = false;
  if (!t.empty() && (t[0] == '+' || t[0] == '-')) {
    negative = t[0] == '-';
    t.erase(0, 1);
  }
  GiNaC::numeric value;
  if (const auto slash = t.find('/'); slash != std::string::npos) {
    const std::string p = t.substr(0, slash), q = t.substr(slash + 1);
    if (!digits(p) || !digits(q)) throw bad();
    if (std::stoll(q) == 0) throw ArgumentError(argument, "'" + s + "' has a zero denominator");
    value = GiNaC::numeric(std::stoll(p)) / GiNaC::numeric(std::stoll(q));
  } else {
    long exponent = 0;
    if (const auto e = t.find_first_of("eE"); e != std::string::npos) {
      std::string x = t.substr(e + 1);
      t.erase(e);
      bool xneg = false;
      if (!x.empty() && (x[0] == '+' || x[0] == '-')) {
        xneg = x[0] == '-';
        x.erase(0, 1);
      }
      if (!digits(x) || x.size() > 3) throw bad();
      exponent = xneg ? -std::stol(x) : std::stol(x);
    }
    std::string whole = t, frac;
    if (const auto dot = t.find('.'); dot != std::string::npos) {
      whole = t.substr(0, dot);
      frac = t.substr(dot + 1);
    }
    if ((whole.empty() && frac.empty()) || (!whole.empty() && !digits(whole)) ||
        (!frac.empty() && !digits(frac)))
      throw bad();
    const std::string mantissa = whole + frac;
    if (!digits(mantissa)) throw bad();
    value = GiNaC::numeric(std::stoll(mantissa)) *
            GiNaC::pow(GiNaC::numeric(10), GiNaC::numeric(exponent - long(frac.size())));
  }
  return negative ? -value : value;
}

// expr   := term (('+' | '-') term)*
// term   := unary (('*' | '/') unary)*
// unary  := ('+' | '-') unary | power
// power  := primary ('^' unary)?
// primary:= number | name | name '[' integer ']' | name '(' expr ')' | 'grad(V)(' expr ')'
//         | '[' expr (',' expr)* ']' | '(' expr ')'
class TypedDiscreteLagrangian::Parser {
 public:
  enum class Kind { potential, ld, lagrangian, hamiltonian, constraint };

  /// The language's functions of one scalar, by name (also the words --param may not use).
  static constexpr std::array<std::pair<std::string_view, TypedDiscreteLagrangian::Fn>, 5>
      kFunctions{{{"sin", TypedDiscreteLagrangian::Fn::sin},
                  {"cos", TypedDiscreteLagrangian::Fn::cos},
                  {"exp", TypedDiscreteLagrangian::Fn::exp},
                  {"log", TypedDiscreteLagrangian::Fn::log},
                  {"sqrt", TypedDiscreteLagrangian::Fn::sqrt}}};
  static const std::pair<std::string_view, TypedDiscreteLagrangian::Fn>* function_named(
      std::string_view id) {
    for (const auto& f : kFunctions)
      if (f.first == id) return &f;
    return nullptr;
  }

  /// `scalar_vars`: every vector variable is its first component (the one-dimensional reading,
  /// in which `q*cos(t)` is a number).
  Parser(TypedDiscreteLagrangian& owner, const std::string& text, std::string argument, Kind kind,
         bool have_potential, bool scalar_vars = false)
      : o_(owner),
        text_(text),
        arg_(std::move(argument)),
        kind_(kind),
        have_potential_(have_potential),
        scalar_vars_(scalar_vars) {}

  int parse() {
    if (text_.find_first_not_of(" \t") == std::string::npos) throw ArgumentError(arg_, "is empty");
    if (text_.size() > 4096) throw ArgumentError(arg_, "is longer than 4096 characters");
    for (std::size_t i = 0; i < text_.size(); ++i) {
      const auto c = static_cast<unsigned char>(text_[i]);
      if (c < 0x20 || c > 0x7e)
        throw ArgumentError(arg_, "character " + std::to_string(i + 1) +
                                      " is not part of an expression (only printable ASCII)");
    }
    const int root = expr();
    skip();
    if (pos_ < text_.size()) fail("unexpected '" + std::string(1, text_[pos_]) + "'");
    return root;
  }
  /// The dimension the text needs (coordinates x, y, z; component indices), 0 if none.
  int needs() const { return needs_; }
  /// The lengths of the vectors written out.
  const std::vector<int>& literal_lengths() const { return literals_; }
  bool uses_slot(int slot) const { return slots_used_[static_cast<std::size_t>(slot)]; }
  /// The text uses the time t.
  bool uses_t() const { return uses_t_; }
  /// The text calls V(...) or grad(V)(...).
  bool calls_potential() const { return calls_potential_; }

 private:
  using Op = TypedDiscreteLagrangian::Op;
  using Fn = TypedDiscreteLagrangian::Fn;

  [[noreturn]] void fail(const std::string& why) const {
    throw ArgumentError(arg_, "at character " + std::to_string(std::min(pos_, text_.size()) + 1) +
                                  " of '" + text_ + "': " + why);
  }
  void skip() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t')) ++pos_;
  }
  bool eat(char c) {
    skip();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  const Node& node(int i) const { return o_.nodes_[static_cast<std::size_t>(i)]; }
  int make(Op op, int a, int b, bool vector) {
    Node n;
    n.op = op;
    n.a = a;
    n.b = b;
    n.vector = vector;
    return o_.add_node(n);
  }

  // Nesting is bounded: a text of 4096 characters can nest about 800 calls (sin(sin(…))),
  // whose nested derivatives then take minutes to form. Each parenthesis, function argument,
  // bracket and leading sign is a level; 64 is far beyond what a Lagrangian needs.
  static constexpr int kMaxDepth = 64;
  struct Deeper {
    Parser& p;
    explicit Deeper(Parser& parser) : p(parser) {
      if (++p.depth_ > kMaxDepth)
        p.fail("nests deeper than " + std::to_string(kMaxDepth) +
               " levels of parentheses, functions or signs");
    }
    ~Deeper() { --p.depth_; }
    Deeper(const Deeper&) = delete;
    Deeper& operator=(const Deeper&) = delete;
  };

  int expr() {
    const Deeper deeper(*this);
    int left = term();
    for (;;) {
      const std::size_t at = pos_;
      if (eat('+') || eat('-')) {
        const Op op = text_[pos_ - 1] == '+' ? Op::add : Op::sub;
        const int right = term();
        if (node(left).vector != node(right).vector) {
          pos_ = at;
          fail(std::string(op == Op::add ? "adds" : "subtracts") + " a vector and a scalar");
        }
        left = make(op, left, right, node(left).vector);
      } else {
        return left;
      }
    }
  }

  int term() {
    int left = unary();
    for (;;) {
      const std::size_t at = pos_;
      if (eat('*')) {
        const int right = unary();
        const bool u = node(left).vector, w = node(right).vector;
        left = u && w ? make(Op::dot, left, right, false) : make(Op::mul, left, right, u || w);
      } else if (eat('/')) {
        const int right = unary();
        if (node(right).vector) {
          pos_ = at;
          fail("divides by a vector");
        }
        GiNaC::numeric k;
        if (constant_value(right, k) && k.is_zero()) {
          pos_ = at;
          fail("divides by zero");
        }
        left = make(Op::div, left, right, node(left).vector);
      } else {
        return left;
      }
    }
  }

  int unary() {
    if (eat('-')) {
      const Deeper deeper(*this);
      const int a = unary();
      return make(Op::neg, a, -1, node(a).vector);
    }
    if (eat('+')) {
      const Deeper deeper(*this);
      return unary();
    }
    return power();
  }

  int power() {
    const int base = primary();
    const std::size_t at = pos_;
    if (!eat('^')) return base;
    const std::size_t exponent_at = pos_;
    const int e = unary();
    GiNaC::numeric k;
    if (!constant_value(e, k) || !k.is_rational() || !(2 * k).is_integer() || abs(k) > 32 ||
        k.is_zero()) {
      pos_ = exponent_at;
      fail("the exponent must be a nonzero integer or half-integer constant up to 32");
    }
    GiNaC::numeric b;
    if (k < 0 && constant_value(base, b) && b.is_zero()) {
      pos_ = at;
      fail("divides by zero (zero to a negative power)");
    }
    Node n;
    n.op = Op::power;
    n.a = base;
    n.twice_exponent = (2 * k).to_int();
    if (node(base).vector && (n.twice_exponent <= 0 || n.twice_exponent % 4 != 0)) {
      pos_ = at;
      fail("a vector u has only even positive powers (u^2 = |u|^2)");
    }
    return o_.add_node(n);
  }

  // The exact value of a subtree made of constants only.
  bool constant_value(int i, GiNaC::numeric& v) const {
    const Node& n = node(i);
    GiNaC::numeric a, b;
    switch (n.op) {
      case Op::constant:
        v = n.exact;
        return true;
      case Op::neg:
        if (!constant_value(n.a, a)) return false;
        v = -a;
        return true;
      case Op::add:
      case Op::sub:
      case Op::mul:
      case Op::div:
        if (!constant_value(n.a, a) || !constant_value(n.b, b)) return false;
        if (n.op == Op::div && b.is_zero()) return false;
        v = n.op == Op::add ? a + b : n.op == Op::sub ? a - b : n.op == Op::mul ? a * b : a / b;
        return true;
      default:
        return false;
    }
  }

  int primary() {
    skip();
    if (pos_ >= text_.size()) fail("the expression ends too early");
    const char c = text_[pos_];
    if (c == '(') {
      ++pos_;
      const int inner = expr();
      if (!eat(')')) fail("expected ')'");
      return inner;
    }
    if (c == '[') return literal();
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') return name();
    fail("unexpected '" + std::string(1, c) + "'");
  }

  // [a, b, …]: a vector written out, one scalar per component.
  int literal() {
    const std::size_t start = pos_;
    ++pos_;
    Node n;
    n.op = Op::literal;
    n.vector = true;
    for (;;) {
      const int item = expr();
      if (node(item).vector) {
        pos_ = start;
        fail("a written vector [a, b, …] has scalar entries");
      }
      n.items.push_back(item);
      if (eat(',')) continue;
      if (eat(']')) break;
      fail("expected ',' or ']'");
    }
    if (static_cast<int>(n.items.size()) > kMaxDim) {
      pos_ = start;
      fail("a vector has at most " + std::to_string(kMaxDim) + " components");
    }
    literals_.push_back(static_cast<int>(n.items.size()));
    return o_.add_node(n);
  }

  int number() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() &&
           (std::isdigit(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '.'))
      ++pos_;
    if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      std::size_t k = pos_ + 1;
      if (k < text_.size() && (text_[k] == '+' || text_[k] == '-')) ++k;
      if (k < text_.size() && std::isdigit(static_cast<unsigned char>(text_[k]))) {
        while (k < text_.size() && std::isdigit(static_cast<unsigned char>(text_[k]))) ++k;
        pos_ = k;
      }
    }
    const std::string token = text_.substr(start, pos_ - start);
    if (pos_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[pos_])) ||
                                text_[pos_] == '_' || text_[pos_] == '.')) {
      pos_ = start;
      fail("'" + token + text_[pos_ + token.size()] + "…' is not a number");
    }
    Node n;
    n.op = Op::constant;
    try {
      n.exact = parse_rational(token, arg_);
    } catch (const ArgumentError&) {
      pos_ = start;
      fail("'" + token + "' is not a number");
    }
    n.value = n.exact.to_double();
    if (!std::isfinite(n.value)) {
      pos_ = start;
      fail("'" + token + "' is beyond the range of double");
    }
    // num/den when both are integers a double holds exactly (|·| < 2^53)
    const GiNaC::numeric limit("9007199254740992");  // 2^53
    if (n.exact.is_rational() && abs(n.exact.numer()) < limit && n.exact.denom() < limit) {
      n.fraction = true;
      n.num = n.exact.numer().to_double();
      n.den = n.exact.denom().to_double();
    }
    return o_.add_node(n);
  }

  // A text in the positions alone (the potential, a constraint): x, y, z, no V.
  bool positional() const { return kind_ == Kind::potential || kind_ == Kind::constraint; }

  // The vector variables of this text: name → slot.
  int slot_of(const std::string& id) const {
    switch (kind_) {
      case Kind::potential:
      case Kind::constraint:
        return id == "q" ? kX : -1;
      case Kind::ld:
        return id == "q0" ? kQ0 : id == "q1" ? kQ1 : -1;
      case Kind::lagrangian:
        return id == "q" ? kQ : id == "v" ? kV : -1;
      case Kind::hamiltonian:
        return id == "q" ? kQ : id == "p" ? kP : -1;
    }
    return -1;
  }
  std::string symbols() const {
    switch (kind_) {
      case Kind::potential:
        return "the potential is a function of x, y, z (or of the vector q, q[1], q[2], …) and "
               "of the time t";
      case Kind::ld:
        return "the discrete Lagrangian is a function of q0, q1 (and q0[1], …), h, the step's "
               "start time t, V(...) and grad(V)(...)";
      case Kind::lagrangian:
        return "the Lagrangian is a function of q, v (and q[1], v[1], …), t, V(...) and "
               "grad(V)(...)";
      case Kind::hamiltonian:
        return "the Hamiltonian is a function of q, p (and q[1], p[1], …), t, V(...) and "
               "grad(V)(...)";
      case Kind::constraint:
        return "a constraint g(q) = 0 is a function of x, y, z (or of the vector q, q[1], "
               "q[2], …)";
    }
    return {};
  }

  // The argument of V(...) or grad(V)(...): a vector.
  int vector_argument(const std::string& what, std::size_t start) {
    const int a = expr();
    if (!eat(')')) fail("expected ')' after the argument of " + what);
    if (!node(a).vector && scalar_vars_) {  // one dimension: the number is the vector [a]
      Node n;
      n.op = Op::literal;
      n.vector = true;
      n.items.push_back(a);
      literals_.push_back(1);
      return o_.add_node(n);
    }
    if (!node(a).vector) {
      pos_ = start;
      fail(what + " takes a vector (q0, q1, (q0+q1)/2, …)");
    }
    return a;
  }
  void need_potential(const std::string& what, std::size_t start) {
    if (positional()) {
      pos_ = start;
      fail("unknown function '" + what + "' (sin cos exp log sqrt)");
    }
    if (!have_potential_) {
      pos_ = start;
      fail(what + " is used but no --potential was given");
    }
  }

  int name() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() &&
           (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
      ++pos_;
    const std::string id = text_.substr(start, pos_ - start);
    const std::size_t after = pos_;
    // grad(V)(u)
    if (id == "grad") {
      skip();
      const bool form = eat('(') && eat('V') && eat(')') && eat('(');
      if (!form) {
        pos_ = start;
        fail("write the gradient of the potential as grad(V)(u)");
      }
      need_potential("grad(V)", start);
      const int a = vector_argument("grad(V)", start);
      calls_potential_ = true;
      return make(Op::gradient_call, a, -1, true);
    }
    if (eat('(')) {
      const auto* function = function_named(id);
      const bool known = function || (id == "V" && !positional());
      if (!known) {
        pos_ = start;
        fail("unknown function '" + id + "' (" +
             (positional() ? "sin cos exp log sqrt" : "V, grad(V), sin cos exp log sqrt") + ")");
      }
      if (id == "V") {
        need_potential("V", start);
        const int a = vector_argument("V", start);
        calls_potential_ = true;
        return make(Op::potential_call, a, -1, false);
      }
      const int a = expr();
      if (!eat(')')) fail("expected ')' after the argument of " + id);
      if (node(a).vector) {
        pos_ = start;
        fail(id + " of a vector");
      }
      Node n;
      n.op = Op::func;
      n.a = a;
      n.fn = function->second;
      return o_.add_node(n);
    }
    pos_ = after;
    Node n;
    if (const int slot = slot_of(id); slot >= 0) {
      slots_used_[static_cast<std::size_t>(slot)] = true;
      skip();
      if (pos_ < text_.size() && text_[pos_] == '[') {  // a component, counted from 1
        ++pos_;
        skip();
        const std::size_t digits = pos_;
        while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
        const std::string k = text_.substr(digits, pos_ - digits);
        if (k.empty() || k.size() > 2 || !eat(']')) {
          pos_ = digits;
          fail("a component is written " + id + "[1], " + id + "[2], …");
        }
        const int index = std::stoi(k);
        if (index < 1 || index > kMaxDim) {
          pos_ = digits;
          fail("component " + k + " of " + id + ": components are counted from 1 to at most " +
               std::to_string(kMaxDim));
        }
        n.op = Op::component;
        n.slot = slot;
        n.index = index - 1;
        needs_ = std::max(needs_, index);
      } else if (scalar_vars_) {
        pos_ = after;
        n.op = Op::component;
        n.slot = slot;
        n.index = 0;
        needs_ = std::max(needs_, 1);
      } else {
        pos_ = after;
        n.op = Op::var;
        n.slot = slot;
        n.vector = true;
      }
    } else if (kind_ == Kind::ld && id == "h") {
      n.op = Op::h;
    } else if (const int k = o_.param_index(id); k >= 0) {
      n.op = Op::param;
      n.index = k;
    } else if (positional() && (id == "x" || id == "y" || id == "z")) {
      slots_used_[kX] = true;
      n.op = Op::component;
      n.slot = kX;
      n.index = id == "x" ? 0 : id == "y" ? 1 : 2;
      needs_ = std::max(needs_, n.index + 1);
    } else if (id == "t" && kind_ == Kind::constraint) {
      pos_ = start;
      fail(
          "a constraint may not depend on the time t (time-dependent constraints are not "
          "implemented)");
    } else if (id == "t") {
      n.op = Op::t;
      uses_t_ = true;
    } else {
      pos_ = start;
      fail("unknown symbol '" + id + "' (" + symbols() + ")");
    }
    return o_.add_node(n);
  }

  TypedDiscreteLagrangian& o_;
  const std::string& text_;
  std::string arg_;
  Kind kind_;
  bool have_potential_;
  bool scalar_vars_ = false;
  std::size_t pos_ = 0;
  int depth_ = 0;  ///< the levels of nesting open (Deeper)
  int needs_ = 0;
  std::vector<int> literals_;
  std::array<bool, kVars> slots_used_{};
  bool uses_t_ = false, calls_potential_ = false;
};

TypedDiscreteLagrangian::TypedDiscreteLagrangian(const std::string& ld,
                                                 const std::string& potential, int dim)
    : TypedDiscreteLagrangian(TypedTexts{ld, potential, "", "", dim}) {}

TypedDiscreteLagrangian::TypedDiscreteLagrangian(const TypedTexts& t) {
  const std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());  // the numbers
  finish(t);
}

void TypedDiscreteLagrangian::finish(const TypedTexts& t) {
  // A text that mixes a vector variable with numbers (`q*cos(t)` added to a scalar) is not
  // vector algebra, but in one dimension a vector is a number: read it again so, and keep that
  // reading when the system is then one-dimensional; otherwise the first error stands.
  try {
    finish_pass(t, false);
  } catch (const ArgumentError& first) {
    if (t.dim > 1) throw;
    nodes_.clear();
    params_.clear();
    ld_root_ = potential_root_ = lagrangian_root_ = hamiltonian_root_ = -1;
    constraint_roots_.clear();
    constraint_texts_.clear();
    system_uses_t_ = ld_uses_t_ = false;
    dim_ = 0;
    try {
      finish_pass(t, true);
    } catch (const ArgumentError&) {
      if (dim_ == 1) throw;  // read as one-dimensional, then refused for another reason
      throw first;
    }
    if (dim_ != 1) throw first;
  }
}

void TypedDiscreteLagrangian::finish_pass(const TypedTexts& t, bool scalar_vars) {
  if (t.dim < 0 || t.dim > kMaxDim)
    throw ArgumentError(
        "--dim", "must lie in 1.." + std::to_string(kMaxDim) + ", got " + std::to_string(t.dim));
  if (!t.lagrangian.empty() && !t.hamiltonian.empty())
    throw ArgumentError("--hamiltonian",
                        "give the intended system once: --lagrangian or "
                        "--hamiltonian, not both");
  const bool have_potential = !t.potential.empty();
  // Symbolic parameters: names that are not the language's own (checked before any text).
  static const std::set<std::string> reserved = {"q0", "q1", "q", "v", "p", "h",
                                                 "x",  "y",  "z", "t", "V", "grad"};
  for (const auto& name : t.params) {
    const bool identifier = !name.empty() && std::isalpha(static_cast<unsigned char>(name[0])) &&
                            std::all_of(name.begin(), name.end(), [](char c) {
                              return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
                            });
    if (!identifier)
      throw ArgumentError("--param", "'" + name +
                                         "' is not a name (a letter, then letters, "
                                         "digits or _)");
    if (reserved.count(name) || Parser::function_named(name))
      throw ArgumentError("--param", "'" + name + "' is a name of the language itself");
    if (param_index(name) >= 0) throw ArgumentError("--param", "'" + name + "' given twice");
    params_.emplace_back(name);
  }
  if (!have_potential && t.lagrangian.empty() && t.hamiltonian.empty())
    throw ArgumentError("--potential",
                        "is required: the intended system is L = |v|^2/2 - V(q) unless "
                        "--lagrangian or --hamiltonian gives it");
  int needs = 0;
  std::vector<std::pair<std::string, int>> literals;  // argument, length
  auto parse = [&](const std::string& text, const char* arg, Parser::Kind kind) {
    Parser p(*this, text, arg, kind, have_potential, scalar_vars);
    const int root = p.parse();
    needs = std::max(needs, p.needs());
    for (int n : p.literal_lengths()) literals.emplace_back(arg, n);
    if (nodes_[static_cast<std::size_t>(root)].vector)
      throw ArgumentError(arg, "is a vector, not a scalar (write u^2 for |u|^2)");
    return std::pair{root, std::move(p)};
  };
  // The time: the system depends on t when its Lagrangian or Hamiltonian does, or the potential
  // does and the system uses it (the default L = |v|²/2 − V, or V(...) inside L or H).
  bool potential_t = false, system_calls_v = t.lagrangian.empty() && t.hamiltonian.empty();
  if (have_potential) {
    auto [root, p] = parse(t.potential, "--potential", Parser::Kind::potential);
    potential_root_ = root;
    potential_t = p.uses_t();
  }
  if (!(t.system_only && t.ld.empty())) {
    auto [root, p] = parse(t.ld, "--ld", Parser::Kind::ld);
    ld_root_ = root;
    if (!p.uses_slot(kQ0) || !p.uses_slot(kQ1))
      throw ArgumentError("--ld", "must depend on both q0 and q1");
    ld_uses_t_ = p.uses_t();
    if (t.allow_time && potential_t && p.calls_potential())
      throw ArgumentError("--ld",
                          "calls V(...) of a time-dependent --potential, and inside --ld V has no "
                          "time of its own: write the potential out in --ld with t (the step's "
                          "start time) and h where the rule evaluates it");
  }
  if (!t.lagrangian.empty()) {
    auto [root, p] = parse(t.lagrangian, "--lagrangian", Parser::Kind::lagrangian);
    lagrangian_root_ = root;
    if (!p.uses_slot(kV)) throw ArgumentError("--lagrangian", "must depend on the velocity v");
    system_uses_t_ = p.uses_t();
    system_calls_v = p.calls_potential();
  }
  if (!t.hamiltonian.empty()) {
    auto [root, p] = parse(t.hamiltonian, "--hamiltonian", Parser::Kind::hamiltonian);
    hamiltonian_root_ = root;
    if (!p.uses_slot(kP)) throw ArgumentError("--hamiltonian", "must depend on the momentum p");
    system_uses_t_ = p.uses_t();
    system_calls_v = p.calls_potential();
  }
  system_uses_t_ = system_uses_t_ || (potential_t && system_calls_v);
  for (const std::string& g : t.constraints) {
    auto [root, p] = parse(g, "--constraint", Parser::Kind::constraint);
    if (!p.uses_slot(kX))
      throw ArgumentError("--constraint", "'" + g + "' does not depend on the positions");
    constraint_roots_.push_back(root);
    constraint_texts_.push_back(g);
  }
  int dim = std::max(1, needs);
  for (const auto& [arg, n] : literals) dim = std::max(dim, n);
  if (t.dim != 0) {
    if (t.dim < dim)
      throw ArgumentError("--dim", std::to_string(t.dim) + " is fewer than the " +
                                       std::to_string(dim) + " the expressions use");
    dim = t.dim;
  }
  for (const auto& [arg, n] : literals)
    if (n != dim)
      throw ArgumentError(arg, "a written vector has " + std::to_string(n) +
                                   " components; the system is " + std::to_string(dim) +
                                   "-dimensional");
  dim_ = dim;
  if (!t.allow_time && (system_uses_t_ || ld_uses_t_ || potential_t)) {
    const char* arg = potential_t             ? "--potential"
                      : ld_uses_t_            ? "--ld"
                      : !t.lagrangian.empty() ? "--lagrangian"
                                              : "--hamiltonian";
    throw ArgumentError(
        arg,
        "uses the time t: this command does not step a time-dependent system "
        "(vibook verify does, with --method, --tableau, --ld, --composition ld, --splitting "
        "and a black-box stepper; see "
        "the chapter \"Verify your own integrator\", section \"Time-dependent "
        "systems\")");
  }
}

}  // namespace vibook::verify
