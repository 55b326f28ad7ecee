// A discrete Lagrangian typed as text (expression.hpp): a recursive-descent parser that keeps
// the text's structure, checking as it goes what is a vector and what a scalar, into the small
// tree that expression.hpp evaluates on any scalar.
#include "vibook/verify/expression.hpp"

#include <algorithm>
#include <cctype>

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
// primary:= number | name | name '(' expr ')' | '(' expr ')'
class TypedDiscreteLagrangian::Parser {
 public:
  Parser(TypedDiscreteLagrangian& owner, const std::string& text, std::string argument,
         bool potential)
      : o_(owner), text_(text), arg_(std::move(argument)), potential_(potential) {}

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
  int used_coordinates() const { return used_; }
  bool uses(TypedDiscreteLagrangian::Op op) const {
    return std::any_of(o_.nodes_.begin() + first_, o_.nodes_.end(),
                       [&](const Node& n) { return n.op == op; });
  }

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
  const Node& node(int i) const { return o_.nodes_[i]; }
  int make(Op op, int a, int b, bool vector) {
    Node n;
    n.op = op;
    n.a = a;
    n.b = b;
    n.vector = vector;
    return o_.add_node(n);
  }

  int expr() {
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
      const int a = unary();
      return make(Op::neg, a, -1, node(a).vector);
    }
    if (eat('+')) return unary();
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
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') return name();
    fail("unexpected '" + std::string(1, c) + "'");
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
    return o_.add_node(n);
  }

  int name() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() &&
           (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
      ++pos_;
    const std::string id = text_.substr(start, pos_ - start);
    const std::size_t after = pos_;
    if (eat('(')) {
      const bool known = id == "sin" || id == "cos" || id == "exp" || id == "log" || id == "sqrt" ||
                         (id == "V" && !potential_);
      if (!known) {
        pos_ = start;
        fail("unknown function '" + id + "' (" +
             (potential_ ? "sin cos exp log sqrt" : "V, sin cos exp log sqrt") + ")");
      }
      const int a = expr();
      if (!eat(')')) fail("expected ')' after the argument of " + id);
      if (id == "V") {
        if (!node(a).vector) {
          pos_ = start;
          fail("V takes a vector (q0, q1, (q0+q1)/2, …)");
        }
        return make(Op::potential_call, a, -1, false);
      }
      if (node(a).vector) {
        pos_ = start;
        fail(id + " of a vector");
      }
      Node n;
      n.op = Op::func;
      n.a = a;
      n.fn = id == "sin"   ? Fn::sin
             : id == "cos" ? Fn::cos
             : id == "exp" ? Fn::exp
             : id == "log" ? Fn::log
                           : Fn::sqrt;
      return o_.add_node(n);
    }
    pos_ = after;
    Node n;
    if (!potential_ && (id == "q0" || id == "q1")) {
      n.op = id == "q0" ? Op::q0 : Op::q1;
      n.vector = true;
    } else if (!potential_ && id == "h") {
      n.op = Op::h;
    } else if (potential_ && (id == "x" || id == "y" || id == "z")) {
      n.op = Op::coordinate;
      n.index = id == "x" ? 0 : id == "y" ? 1 : 2;
      used_ = std::max(used_, n.index + 1);
    } else {
      pos_ = start;
      fail("unknown symbol '" + id + "' (" +
           (potential_ ? "the potential is a function of x, y, z"
                       : "the discrete Lagrangian is a function of q0, q1, h and V(...)") +
           ")");
    }
    return o_.add_node(n);
  }

  TypedDiscreteLagrangian& o_;
  const std::string& text_;
  std::string arg_;
  bool potential_;
  std::size_t pos_ = 0;
  int used_ = 0;
  std::size_t first_ = o_.nodes_.size();
};

TypedDiscreteLagrangian::TypedDiscreteLagrangian(const std::string& ld,
                                                 const std::string& potential, int dim) {
  if (dim < 0 || dim > 3)
    throw ArgumentError("--dim", "must be 1, 2 or 3, got " + std::to_string(dim));
  Parser pp(*this, potential, "--potential", true);
  potential_root_ = pp.parse();
  const int used = std::max(1, pp.used_coordinates());
  if (dim == 0) dim = used;
  if (dim < used)
    throw ArgumentError("--dim", std::to_string(dim) + " is fewer than the potential's " +
                                     std::to_string(used) + " coordinates");
  dim_ = dim;
  Parser pl(*this, ld, "--ld", false);
  ld_root_ = pl.parse();
  if (nodes_[ld_root_].vector)
    throw ArgumentError("--ld", "is a vector, not a scalar (write u^2 for |u|^2)");
  if (!pl.uses(Op::q0) || !pl.uses(Op::q1))
    throw ArgumentError("--ld", "must depend on both q0 and q1");
}

}  // namespace vibook::verify
