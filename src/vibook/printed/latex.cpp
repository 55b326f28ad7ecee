// The reader of the papers' LaTeX (latex.hpp): a tokenizer, tensor arithmetic, and a
// recursive-descent parser that evaluates as it reads, asking a Notation what each symbol
// means.
#include "vibook/printed/latex.hpp"

#include <algorithm>
#include <cctype>
#include <set>

namespace vibook::printed {

using GiNaC::numeric;

// --- tokens ------------------------------------------------------------------------------------

std::vector<Token> tokenize(std::string_view s) {
  std::vector<Token> out;
  bool space = false;
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (std::isspace(c)) {
      space = true;
      ++i;
      continue;
    }
    Token t;
    t.begin = i;
    t.space_before = space;
    space = false;
    if (c == '\\') {
      std::size_t j = i + 1;
      if (j < s.size() && std::isalpha(static_cast<unsigned char>(s[j]))) {
        while (j < s.size() && std::isalpha(static_cast<unsigned char>(s[j]))) ++j;
        t.kind = Token::Kind::command;
        t.text = std::string(s.substr(i + 1, j - i - 1));
      } else if (j < s.size()) {
        t.kind = Token::Kind::command;
        t.text = std::string(1, s[j]);
        ++j;
      } else {
        throw ReadError("a lone backslash at the end");
      }
      t.end = j;
      i = j;
    } else if (std::isdigit(c)) {
      std::size_t j = i;
      while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) ++j;
      if (j + 1 < s.size() && s[j] == '.' && std::isdigit(static_cast<unsigned char>(s[j + 1]))) {
        ++j;
        while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) ++j;
      }
      t.kind = Token::Kind::number;
      t.text = std::string(s.substr(i, j - i));
      t.end = j;
      i = j;
    } else if (std::isalpha(c)) {
      t.kind = Token::Kind::letter;
      t.text = std::string(1, s[i]);
      t.end = ++i;
    } else if (c >= 0x21 && c <= 0x7e) {
      t.kind = Token::Kind::symbol;
      t.text = std::string(1, s[i]);
      t.end = ++i;
    } else {
      throw ReadError("character " + std::to_string(i + 1) + " is not printable ASCII");
    }
    out.push_back(std::move(t));
  }
  return out;
}

std::string print(const std::vector<Token>& tokens) {
  std::string out;
  for (std::size_t k = 0; k < tokens.size(); ++k) {
    const Token& t = tokens[k];
    if (k > 0 && t.space_before) out += ' ';
    if (t.kind == Token::Kind::command) {
      // A command followed directly by a letter needs a space to stay the same command.
      out += '\\' + t.text;
      if (k + 1 < tokens.size() && !tokens[k + 1].space_before &&
          std::isalpha(static_cast<unsigned char>(t.text.back())) &&
          tokens[k + 1].kind == Token::Kind::letter)
        out += ' ';
    } else {
      out += t.text;
    }
  }
  return out;
}

// --- values ------------------------------------------------------------------------------------

Value Value::scalar(const ex& e) {
  Value v;
  v.c = {e};
  return v;
}

Value Value::vector(const std::vector<ex>& c) {
  Value v;
  v.rank = c.size() == 1 ? 0 : 1;
  v.n = static_cast<int>(c.size());
  if (v.rank == 0) v.n = 1;
  v.c = c;
  return v;
}

Value Value::zeros(int rank, int n) {
  Value v;
  v.rank = rank;
  v.n = n;
  std::size_t size = 1;
  for (int k = 0; k < rank; ++k) size *= static_cast<std::size_t>(n);
  v.c.assign(size, ex(0));
  return v;
}

const ex& Value::as_scalar(std::string_view what) const {
  if (tuple || rank != 0) throw IllFormed(std::string(what) + " is not a scalar");
  return c[0];
}

std::string Atom::text() const {
  std::string s = base;
  if (base.size() > 1 && base.find('{') == std::string::npos && base.find(' ') == std::string::npos)
    s = "\\" + base;
  for (auto it = accents.rbegin(); it != accents.rend(); ++it) s = "\\" + *it + "{" + s + "}";
  s += std::string(static_cast<std::size_t>(primes), '\'');
  if (sub) s += "_{" + print(*sub) + "}";
  if (sup) s += "^{" + print(*sup) + "}";
  return s;
}

bool Atom::has_accent(std::string_view a) const {
  return std::find(accents.begin(), accents.end(), a) != accents.end();
}

namespace {
// The sub- or superscript as plain text: "xx", "1", "ij", "disc", "mod,3", "[1]", "(3)"
// (braces and font commands such as \text, \mathrm, \rm dropped).
std::string texts(const std::optional<std::vector<Token>>& t) {
  std::string s;
  if (!t) return s;
  for (const auto& k : *t) {
    if (k.sym("{") || k.sym("}")) continue;
    if (k.kind == Token::Kind::command &&
        (k.text == "text" || k.text == "mathrm" || k.text == "rm" || k.text == "mathit"))
      continue;
    s += k.kind == Token::Kind::command && k.text.size() > 1 ? "\\" + k.text : k.text;
  }
  return s;
}
}  // namespace

std::string Atom::sub_text() const { return texts(sub); }
std::string Atom::sup_text() const { return texts(sup); }

Value Notation::shift(int, int, const ex&) const {
  throw ReadError("this notation has no curves to evaluate at another time");
}
GiNaC::symbol Notation::time_symbol() const {
  static const GiNaC::symbol t("t");
  return t;
}
Value Notation::time_derivative(const Value&, const std::string& variable, int) const {
  throw ReadError("this notation has no time derivative d/d" + variable);
}
Value Notation::partial(const Value&, const Atom& wrt) const {
  throw ReadError("this notation has no partial derivative with respect to " + wrt.text());
}

// --- tensor arithmetic -------------------------------------------------------------------------

namespace {
std::string shape(const Value& v) {
  if (v.tuple) return "a list of " + std::to_string(v.items.size());
  switch (v.rank) {
    case 0:
      return "a scalar";
    case 1:
      return "a vector of " + std::to_string(v.n);
    case 2:
      return "a " + std::to_string(v.n) + "x" + std::to_string(v.n) + " matrix";
    default:
      return "a tensor of rank " + std::to_string(v.rank);
  }
}
// Propagate the derivative-tensor slots of a scalar factor (1-D: U'' is a scalar taking two).
Value plain(Value v) {
  v.slots = 0;
  v.transposed = false;
  return v;
}
}  // namespace

Value map(const Value& v, const std::function<ex(const ex&)>& f) {
  if (v.tuple) {
    Value r = v;
    for (auto& it : r.items) it = map(it, f);
    return r;
  }
  Value r = v;
  for (auto& x : r.c) x = f(x);
  return r;
}

Value scale(const ex& s, const Value& v) {
  return map(v, [&](const ex& x) { return s * x; });
}

Value add(const Value& a, const Value& b) {
  if (a.tuple || b.tuple) throw IllFormed("cannot add " + shape(a) + " and " + shape(b));
  if (a.rank != b.rank || (a.rank > 0 && a.n != b.n))
    throw IllFormed("cannot add " + shape(a) + " and " + shape(b));
  Value r = plain(a);
  for (std::size_t k = 0; k < r.c.size(); ++k) r.c[k] = a.c[k] + b.c[k];
  return r;
}

Value dot(const Value& a, const Value& b) {
  if (a.tuple || b.tuple) throw IllFormed("cannot multiply " + shape(a) + " and " + shape(b));
  if (a.rank == 0) return scale(a.c[0], plain(b));
  if (b.rank == 0) return scale(b.c[0], plain(a));
  if (a.n != b.n) throw IllFormed("cannot contract " + shape(a) + " with " + shape(b));
  const int n = a.n;
  const int rank = a.rank + b.rank - 2;
  Value r = Value::zeros(rank, n);
  const std::size_t inner_b = b.c.size() / static_cast<std::size_t>(n);
  const std::size_t outer_a = a.c.size() / static_cast<std::size_t>(n);
  for (std::size_t i = 0; i < outer_a; ++i)
    for (std::size_t j = 0; j < inner_b; ++j) {
      ex acc = 0;
      for (int k = 0; k < n; ++k) acc += a.c[i * n + k] * b.c[k * inner_b + j];
      r.c[i * inner_b + j] = acc;
    }
  return r;
}

Value contract(const Value& t, const std::vector<Value>& args) {
  if (t.slots == 0)
    throw IllFormed(shape(t) + " is not a derivative tensor and takes no arguments");
  if (static_cast<int>(args.size()) > t.slots)
    throw IllFormed("a derivative of order " + std::to_string(t.slots) + " applied to " +
                    std::to_string(args.size()) + " arguments");
  Value r = t;
  if (r.rank == 0) {  // one dimension: the tensor is a scalar, the arguments multiply
    for (const auto& a : args) r = scale(a.as_scalar("an argument of a derivative"), r);
    r.slots = t.slots - static_cast<int>(args.size());
    return r;
  }
  // N dimensions: contract the first index with each argument in turn.
  for (const auto& a : args) {
    if (a.tuple || a.rank != 1 || a.n != r.n)
      throw IllFormed("the argument of a derivative tensor must be a vector, not " + shape(a));
    Value v = a;
    v.transposed = false;
    Value rr = Value::zeros(r.rank - 1, r.n);
    const std::size_t inner = r.c.size() / static_cast<std::size_t>(r.n);
    for (int k = 0; k < r.n; ++k)
      for (std::size_t j = 0; j < inner; ++j) rr.c[j] += v.c[k] * r.c[k * inner + j];
    r = rr;
  }
  r.slots = t.slots - static_cast<int>(args.size());
  return r;
}

Value multiply(const Value& a, const Value& b) {
  if (b.tuple && !a.tuple) {
    if (a.slots > 0) return contract(a, b.items);
    if (b.angle && b.items.size() == 2 && a.rank == 0)
      return scale(a.c[0], dot(b.items[0], b.items[1]));
    throw IllFormed("an argument list after " + shape(a) + ", which takes no arguments");
  }
  if (a.tuple) {
    if (a.angle && a.items.size() == 2) return multiply(dot(a.items[0], a.items[1]), b);
    throw IllFormed("an argument list where a factor is expected");
  }
  if (a.rank == 0) {
    Value r = scale(a.c[0], b);
    r.slots = a.slots == 0 ? b.slots : 0;  // a coefficient keeps a tensor applicable
    r.transposed = b.transposed;
    return r;
  }
  if (b.rank == 0) return scale(b.c[0], plain(a));
  // A vector (or covector) times a vector: their contraction; a matrix times a vector or a
  // matrix: the product.
  return dot(a, b);
}

// --- the parser --------------------------------------------------------------------------------

namespace {

struct UnboundIndex {
  char index;
};

const std::set<std::string> kSizing = {"left",  "right", "big",   "Big",   "bigg",
                                       "Bigg",  "bigl",  "bigr",  "Bigl",  "Bigr",
                                       "biggl", "biggr", "Biggl", "Biggr", "middle"};
const std::set<std::string> kSpacing = {"quad", "qquad",        ",",        ";",     "!",     " ",
                                        ":",    "displaystyle", "nonumber", "notag", "limits"};
const std::set<std::string> kTransparentEnv = {"aligned",  "split",    "align",    "align*",
                                               "gathered", "equation", "equation*"};
const std::set<std::string> kMatrixEnv = {"bmatrix", "pmatrix", "matrix", "array", "cases"};
const std::set<std::string> kAccents = {"dot",      "ddot",      "dddot",  "bar",        "hat",
                                        "tilde",    "widetilde", "mathbf", "boldsymbol", "vec",
                                        "overline", "bm",        "widehat"};
const std::set<std::string> kLetterFonts = {"mathcal", "mathbb", "mathfrak", "mathscr"};
const std::set<std::string> kFunctions = {"sin",    "cos",    "tan",    "exp",  "log", "ln",
                                          "arcsin", "arccos", "arctan", "sinh", "cosh"};
const std::set<std::string> kGreek = {
    "alpha", "beta",    "gamma",  "delta",  "epsilon", "varepsilon", "zeta",  "eta",   "theta",
    "iota",  "kappa",   "lambda", "mu",     "nu",      "xi",         "pi",    "rho",   "sigma",
    "tau",   "upsilon", "phi",    "varphi", "chi",     "psi",        "omega", "Gamma", "Delta",
    "Theta", "Lambda",  "Xi",     "Pi",     "Sigma",   "Phi",        "Psi",   "Omega", "ell"};

std::string env_name(const std::vector<Token>& t, std::size_t open_brace, std::size_t* close) {
  std::string name;
  std::size_t j = open_brace + 1;
  while (j < t.size() && !t[j].sym("}")) name += t[j++].text;
  if (close) *close = j;
  return name;
}

class Parser : public Reader {
 public:
  Parser(const std::vector<Token>& t, const Notation& n, const std::map<std::size_t, ex>& scale,
         std::vector<std::pair<std::size_t, std::size_t>>* term_starts = nullptr)
      : t_(t), n_(n), scale_(scale), term_starts_(term_starts) {
    // The tokens the grammar sees: spacing, sizing, invisible delimiters, equation tags and
    // the alignment of `aligned` environments dropped; `&` and `\\` kept inside matrices only.
    int matrix_depth = 0;
    for (std::size_t k = 0; k < t.size(); ++k) {
      const Token& x = t[k];
      if (x.kind == Token::Kind::command && kSpacing.count(x.text)) continue;
      if (x.kind == Token::Kind::command && kSizing.count(x.text)) {
        if (k + 1 < t.size() && t[k + 1].sym(".")) ++k;  // \left. and \right.
        continue;
      }
      if ((x.cmd("begin") || x.cmd("end")) && k + 1 < t.size() && t[k + 1].sym("{")) {
        std::size_t close = k + 1;
        const std::string name = env_name(t, k + 1, &close);
        if (kTransparentEnv.count(name)) {
          k = close;
          continue;
        }
        if (kMatrixEnv.count(name)) matrix_depth += x.cmd("begin") ? 1 : -1;
      }
      if ((x.sym("&") || x.cmd("\\")) && matrix_depth == 0) continue;
      if (x.cmd("tag")) {  // \tag{...}
        int depth = 0;
        for (++k; k < t.size(); ++k) {
          if (t[k].sym("{")) ++depth;
          if (t[k].sym("}") && --depth == 0) break;
        }
        continue;
      }
      if ((x.cmd("mathrm") || x.cmd("operatorname") || x.cmd("rm")) && k + 1 < t.size() &&
          t[k + 1].sym("{")) {
        // \mathrm{d} is the letter d, \mathrm{disc} the letters of a word: keep the inside
        std::size_t j = k + 2;
        while (j < t.size() && !t[j].sym("}")) idx_.push_back(j++);
        k = j;
        continue;
      }
      if (x.cmd("rm")) continue;
      // \mathbf{0}: a bold number is the number (the zero vector of "= \mathbf{0}")
      if ((x.cmd("mathbf") || x.cmd("boldsymbol")) && k + 3 < t.size() && t[k + 1].sym("{") &&
          t[k + 2].kind == Token::Kind::number && t[k + 3].sym("}"))
        continue;
      idx_.push_back(k);
    }
    // A trailing full stop or comma, and a trailing equation tag "\quad (39)".
    auto strip = [&] {
      while (!idx_.empty() && (at(idx_.size() - 1).sym(".") || at(idx_.size() - 1).sym(",")))
        idx_.pop_back();
    };
    strip();
    if (idx_.size() >= 3 && at(idx_.size() - 1).sym(")") && at(idx_.size() - 3).sym("(") &&
        at(idx_.size() - 2).kind == Token::Kind::number) {
      const std::size_t open = idx_[idx_.size() - 3];
      if (open > 0 && (t[open - 1].cmd("quad") || t[open - 1].cmd("qquad"))) {
        idx_.resize(idx_.size() - 3);
        strip();
      }
    }
  }

  Reading read_all() {
    Reading r;
    relation();  // a quote of a continued display may begin with "= …"
    for (;;) {
      rem_.reset();
      dots_ = false;
      Value v = expr();
      r.members.push_back(v);
      r.remainder.push_back(rem_);
      r.dots.push_back(dots_);
      if (done()) break;
      if (relation()) continue;
      if (peek().sym(",")) {  // "A = B, C = D": a comma separates members too
        ++p_;
        continue;
      }
      throw ReadError("unexpected '" + peek().text + "' at " + where());
    }
    return r;
  }

  std::optional<int> bound(char index) const override {
    for (auto it = bound_.rbegin(); it != bound_.rend(); ++it)
      if (it->first == index) return it->second;
    return std::nullopt;
  }

  Value evaluate(const std::vector<Token>& tokens) const override {
    Parser p(tokens, n_, kNoScale);
    p.bound_ = bound_;
    Value v = p.expr();
    if (!p.done()) throw ReadError("cannot read " + print(tokens));
    return v;
  }

  static const std::map<std::size_t, ex> kNoScale;

 private:
  const std::vector<Token>& t_;
  const Notation& n_;
  const std::map<std::size_t, ex>& scale_;
  std::vector<std::pair<std::size_t, std::size_t>>* term_starts_;
  std::vector<std::size_t> idx_;
  std::size_t p_ = 0;
  std::size_t end_ = static_cast<std::size_t>(-1);  // a sub-parse stops here
  std::vector<std::pair<char, int>> bound_;
  std::vector<std::string> abs_;  // open | or \| (innermost last)
  std::optional<int> rem_;
  bool dots_ = false;

  const Token& at(std::size_t k) const { return t_[idx_[k]]; }
  std::size_t limit() const { return std::min(idx_.size(), end_); }
  bool done() const { return p_ >= limit(); }
  const Token& peek(std::size_t ahead = 0) const {
    static const Token end{Token::Kind::symbol, "", 0, 0, false};
    return p_ + ahead < limit() ? at(p_ + ahead) : end;
  }

  // A range [b, e) of the grammar's token positions: a braced group's inside.
  struct Range {
    std::size_t b = 0, e = 0;
  };
  // The inside of {…}, or a single token (\text{…} whole).
  Range braced_range() {
    if (peek().sym("{")) {
      ++p_;
      const std::size_t b = p_;
      int depth = 1;
      while (!done()) {
        const Token& k = next();
        if (k.sym("{")) ++depth;
        if (k.sym("}") && --depth == 0) return {b, p_ - 1};
      }
      throw ReadError("an unclosed '{'");
    }
    const std::size_t b = p_;
    if (peek().cmd("text")) {
      ++p_;
      braced_range();
      return {b, p_};
    }
    next();
    return {b, p_};
  }
  std::vector<Token> copy(Range r) const {
    std::vector<Token> out;
    for (std::size_t k = r.b; k < r.e; ++k) out.push_back(at(k));
    return out;
  }
  // Read the range as an expression, in this parser (so that its terms keep their token
  // positions for the correction search).
  Value sub(Range r) {
    const std::size_t saved_p = p_, saved_end = end_;
    auto saved_abs = std::move(abs_);
    abs_.clear();
    p_ = r.b;
    end_ = r.e;
    Value v = expr();
    if (!done()) throw ReadError("unexpected '" + peek().text + "' at " + where());
    p_ = saved_p;
    end_ = saved_end;
    abs_ = std::move(saved_abs);
    return v;
  }
  const Token& next() {
    if (done()) throw ReadError("the formula ends too early");
    return at(p_++);
  }
  std::string where() const {
    return done() ? "the end" : "character " + std::to_string(peek().begin + 1);
  }
  void expect(std::string_view sym) {
    if (!peek().sym(sym)) throw ReadError("expected '" + std::string(sym) + "' at " + where());
    ++p_;
  }

  bool relation() {
    const Token& k = peek();
    // equalities, and inequalities: "h \leq 2/\sqrt{\lambda}" has two members too
    if (k.sym("=") || k.cmd("simeq") || k.cmd("approx") || k.cmd("equiv") || k.cmd("leq") ||
        k.cmd("geq") || k.cmd("le") || k.cmd("ge") || k.sym("<") || k.sym(">")) {
      ++p_;
      return true;
    }
    if (k.sym(":") && peek(1).sym("=")) {
      p_ += 2;
      return true;
    }
    return false;
  }

  bool closes_abs() const {
    if (abs_.empty()) return false;
    return (abs_.back() == "|" && peek().sym("|")) || (abs_.back() == "||" && peek().cmd("|"));
  }

  // The end of an expression: a relation, a closing delimiter, a comma, the end.
  bool expr_end() const {
    if (done()) return true;
    const Token& k = peek();
    if (k.sym("=") || k.sym(")") || k.sym("]") || k.sym("}") || k.sym(",") || k.sym("&") ||
        k.sym(";") || k.sym("<") || k.sym(">") || k.cmd("rangle") || k.cmd("simeq") ||
        k.cmd("approx") || k.cmd("equiv") || k.cmd("end") || k.cmd("\\") || k.cmd("leq") ||
        k.cmd("geq") || k.cmd("le") || k.cmd("ge") || k.cmd("neq") || k.cmd("to") ||
        k.cmd("rightarrow") || k.cmd("in") || k.cmd("Rightarrow"))
      return true;
    if (k.sym(":") && peek(1).sym("=")) return true;
    return closes_abs();
  }

  // --- expressions --------------------------------------------------------------------------
  struct SumScope {
    char index;
    int from, to;
  };

  Value expr() {
    std::optional<Value> acc;
    std::vector<SumScope> scopes;
    bool first = true;
    while (!expr_end()) {
      int sign = 1;
      if (peek().sym("+")) {
        ++p_;
      } else if (peek().sym("-")) {
        sign = -1;
        ++p_;
      } else if (peek().cmd("pm") || peek().cmd("mp")) {
        if (n_.pm() == 0) throw ReadError("± in a formula: read it once per sign (Notation::pm)");
        sign = peek().cmd("pm") ? n_.pm() : -n_.pm();
        ++p_;
      } else if (!first) {
        throw ReadError("expected '+' or '-' at " + where());
      }
      first = false;
      if (expr_end()) throw ReadError("a sign without a term at " + where());
      const std::size_t term_start = p_;
      const std::size_t term_token = idx_[p_];
      Value v;
      try {
        v = factor_chain(&scopes);
      } catch (const UnboundIndex& u) {
        // A later term of the same bracket using an index of an earlier sum: summed over it.
        auto it = std::find_if(scopes.begin(), scopes.end(),
                               [&](const SumScope& s) { return s.index == u.index; });
        if (it == scopes.end()) throw;
        v = summed(*it, term_start);
      }
      // a term ends before the next grammar token, or after the last one (not in the
      // trailing full stop and equation tag)
      if (term_starts_) term_starts_->emplace_back(term_token, done() ? idx_.back() + 1 : idx_[p_]);
      if (v.tuple && v.items.empty()) continue;  // \dots or O(…): nothing to add
      if (auto s = scale_.find(term_token); s != scale_.end()) v = scale(s->second, v);
      if (sign < 0) v = scale(-1, v);
      acc = acc ? add(*acc, v) : v;
    }
    if (!acc) {
      if (dots_ || rem_) return Value::scalar(0);
      throw ReadError("an empty expression at " + where());
    }
    return *acc;
  }

  Value summed(const SumScope& s, std::size_t start) {
    std::optional<Value> acc;
    std::size_t end = start;
    for (int i = s.from; i <= s.to; ++i) {
      p_ = start;
      bound_.emplace_back(s.index, i);
      Value v = factor_chain(nullptr);
      bound_.pop_back();
      end = p_;
      if (v.tuple && v.items.empty()) continue;
      acc = acc ? add(*acc, v) : v;
    }
    p_ = end;
    if (!acc) throw ReadError("an empty sum");
    return *acc;
  }

  bool starts_factor() const {
    if (expr_end()) return false;
    const Token& k = peek();
    if (k.kind == Token::Kind::number || k.kind == Token::Kind::letter) return true;
    if (k.kind == Token::Kind::command)
      return !(k.text == "cdot" || k.text == "times" || k.text == "pm" || k.text == "mp" ||
               k.text == "rangle" || k.text == "top");
    return k.sym("(") || k.sym("[") || k.sym("{") || k.sym("|");
  }

  static Value vanishing() {
    Value d;
    d.tuple = true;
    return d;
  }

  // term := factor ( factor | \cdot factor | / factor )*
  Value factor_chain(std::vector<SumScope>* scopes) {
    std::optional<Value> acc;
    for (;;) {
      if (peek().cmd("cdot")) {
        ++p_;
        if (!acc) throw ReadError("\\cdot without a left factor");
        acc = dot(finish(*acc), finish(single_factor(scopes, true)));
        continue;
      }
      if (peek().sym("/")) {
        ++p_;
        if (!acc) throw ReadError("'/' without a left factor");
        Value r = single_factor(scopes, true);
        const ex d = r.as_scalar("a divisor");
        acc = map(*acc, [&](const ex& x) { return x / d; });
        continue;
      }
      if (peek().cmd("times")) throw ReadError("\\times is not supported");
      if (!starts_factor()) break;
      Value f = single_factor(scopes, false);
      if (f.tuple && f.items.empty()) {  // \dots or O(…) as a factor: the term vanishes
        while (!expr_end() && !peek().sym("+") && !peek().sym("-")) ++p_;
        return vanishing();
      }
      acc = acc ? multiply(*acc, f) : f;
    }
    if (!acc) throw ReadError("a term without factors at " + where());
    return finish(*acc);
  }

  // A term that ends in an angle pair ⟨a, b⟩ that no tensor took: their inner product.
  static Value finish(const Value& v) {
    if (v.tuple && v.angle && v.items.size() == 2) return dot(v.items[0], v.items[1]);
    if (v.tuple && !v.items.empty()) throw IllFormed("an argument list that nothing takes");
    return v;
  }

  // One factor with its operator applications: an operator takes the rest of the term.
  Value single_factor(std::vector<SumScope>* scopes, bool only_one) {
    if (peek().cmd("sum")) return sum(scopes);
    if (peek().cmd("nabla")) {
      ++p_;
      Entity e = entity();
      if (e.kind != Entity::Kind::field)
        throw ReadError("\\nabla of something that is not a field");
      Entity g = e;
      g.order = e.order + 1;
      g.value = field_tensor(g.field, g.order, n_);
      return postfix_power(value_entity(postfix_entity(g))).value;
    }
    Entity e = primary();
    if (e.kind == Entity::Kind::op && e.slot > 0) {
      // D_i F(a_1, …, a_n): the derivative of F with respect to its i-th argument, there
      Entity f = entity();
      if (f.kind != Entity::Kind::callable || !(peek().sym("(")))
        throw ReadError("D_" + std::to_string(e.slot) +
                        " must be followed by a function and its arguments");
      Value args = group();
      std::vector<Value> list = args.tuple ? args.items : std::vector<Value>{args};
      return differentiate_call(f, list, e.slot);
    }
    if (e.kind == Entity::Kind::op) {
      // the product of the factors that follow
      std::optional<Value> rest;
      while (starts_factor()) {
        Value f = single_factor(scopes, false);
        rest = rest ? multiply(*rest, f) : f;
        if (only_one) break;
      }
      if (!rest) throw ReadError("an operator with nothing to act on at " + where());
      return e.apply(finish(*rest));
    }
    return e.value;
  }

  // D_slot F(args): F with its slot-th argument replaced by fresh symbols, differentiated,
  // evaluated back at the argument (a vector argument gives the gradient).
  static Value differentiate_call(const Entity& f, std::vector<Value> args, int slot) {
    if (slot < 1 || slot > static_cast<int>(args.size()))
      throw IllFormed("D_" + std::to_string(slot) + " of a function of " +
                      std::to_string(args.size()) + " arguments");
    Value& a = args[static_cast<std::size_t>(slot - 1)];
    const Value original = a;
    std::vector<GiNaC::symbol> s;
    for (std::size_t k = 0; k < a.c.size(); ++k) s.emplace_back("vibook_slot" + std::to_string(k));
    for (std::size_t k = 0; k < a.c.size(); ++k) a.c[k] = s[k];
    const ex F = f.call(args).as_scalar("a function differentiated by D_i");
    GiNaC::exmap back;
    for (std::size_t k = 0; k < s.size(); ++k) back[s[k]] = original.c[k];
    std::vector<ex> g;
    for (const auto& sk : s) g.push_back(F.diff(sk).subs(back));
    return Value::vector(g);
  }

  // After an entity: a field, a curve or a callable followed by '(' or ⟨ is applied.
  Value postfix_entity(const Entity& e) {
    if (e.kind == Entity::Kind::op) throw ReadError("an operator where a value is expected");
    if (e.kind == Entity::Kind::value) return e.value;
    const bool paren = peek().sym("(") || peek().cmd("langle");
    if (!paren) {
      if (e.kind == Entity::Kind::callable) return e.call({});
      return e.value;
    }
    const std::size_t before = p_;
    Value args = group();
    std::vector<Value> list = args.tuple ? args.items : std::vector<Value>{args};
    switch (e.kind) {
      case Entity::Kind::callable:
        return e.call(list);
      case Entity::Kind::curve: {
        // x(t + h) is the curve at another time; t' (…) without the time in it a product
        const bool at_time = list.size() == 1 && !list[0].tuple && list[0].rank == 0 &&
                             list[0].c[0].has(n_.time_symbol());
        if (at_time) return n_.shift(e.curve, e.derivative, list[0].c[0]);
        p_ = before;  // not a time: the group is the next factor (with its own power)
        return e.value;
      }
      case Entity::Kind::field:
        return apply_field(e, list, args.angle);
      default:
        break;
    }
    return e.value;
  }

  // A field applied to arguments: at a point (one argument whose value at step 0 is the
  // expansion point), or to directions (the derivative tensor contracted with them).
  Value apply_field(const Entity& e, const std::vector<Value>& args, bool angle) {
    const auto x = n_.expansion_point();
    const std::size_t n = x.size();
    auto is_point = [&](const Value& a) {
      if (a.tuple || a.c.size() != n) return false;
      for (std::size_t k = 0; k < n; ++k) {
        const ex at0 = GiNaC::expand(a.c[k]).subs(n_.step() == 0);
        if (!GiNaC::expand(at0 - x[k]).is_zero()) return false;
      }
      return true;
    };
    const bool anywhere =
        n_.points_anywhere() && args.size() == 1 && !args[0].tuple && args[0].c.size() == n;
    if (!angle && args.size() == 1 && (anywhere || is_point(args[0])))
      return field_tensor_at(e.field, e.order, n_, args[0].c);
    // φ(x_1(t), x_2(t + h/2)): the point given coordinate by coordinate
    if (!angle && n > 1 && args.size() == n &&
        std::all_of(args.begin(), args.end(), [](const Value& a) { return a.is_scalar(); })) {
      std::vector<ex> pt;
      for (const auto& a : args) pt.push_back(a.c[0]);
      return field_tensor_at(e.field, e.order, n_, pt);
    }
    return contract(e.value, args);
  }

  // --- sums ----------------------------------------------------------------------------------
  Value sum(std::vector<SumScope>* scopes) {
    ++p_;  // \sum
    if (!peek().sym("_")) throw ReadError("\\sum without a lower limit");
    ++p_;
    const Range lr = braced_range();
    const std::vector<Token> lower = copy(lr);
    if (lower.size() == 1 && lower[0].kind == Token::Kind::letter && !peek().sym("^")) {
      // \sum_j: over the range the notation gives the letter
      const char index = lower[0].text[0];
      const auto range = n_.index_range(index);
      if (!range)
        throw ReadError(std::string("\\sum_") + index + " without limits and no range for " +
                        index);
      SumScope s{index, range->first, range->second};
      if (scopes) scopes->push_back(s);
      return summed(s, p_);
    }
    if (lower.size() < 3 || lower[0].kind != Token::Kind::letter || !lower[1].sym("="))
      throw ReadError("a sum's lower limit must read i=…");
    const char index = lower[0].text[0];
    const Value from = sub(Range{lr.b + 2, lr.e});
    if (!peek().sym("^")) throw ReadError("\\sum without an upper limit");
    ++p_;
    const Range ur = braced_range();
    const std::vector<Token> upper = copy(ur);
    int to = 0;
    if (upper.size() == 1 && upper[0].cmd("infty")) {
      to = n_.cap();
    } else {
      const ex ue = sub(ur).as_scalar("a sum's upper limit");
      if (!GiNaC::is_a<numeric>(ue) || !GiNaC::ex_to<numeric>(ue).is_integer())
        throw ReadError("a sum's upper limit must be an integer, not " + print(upper));
      to = GiNaC::ex_to<numeric>(ue).to_int();
    }
    const ex fe = from.as_scalar("a sum's lower limit");
    if (!GiNaC::is_a<numeric>(fe)) throw ReadError("a sum's lower limit must be an integer");
    SumScope s{index, GiNaC::ex_to<numeric>(fe).to_int(), to};
    if (scopes) scopes->push_back(s);
    return summed(s, p_);
  }

  // A braced group's tokens ({…}) or a single token.
  std::vector<Token> braced() { return copy(braced_range()); }

  // --- groups: ( … ), [ … ], ⟨ … ⟩, { … } ---------------------------------------------------
  Value group() {
    const Token open = next();
    std::string close;
    bool angle = false;
    if (open.sym("(")) {
      close = ")";
    } else if (open.sym("[")) {
      close = "]";
    } else if (open.cmd("langle")) {
      angle = true;
    } else if (open.sym("{")) {
      close = "}";
    } else {
      throw ReadError("expected a group at " + where());
    }
    auto saved_abs = std::move(abs_);
    abs_.clear();
    std::vector<Value> items;
    for (;;) {
      items.push_back(expr());
      if (peek().sym(",")) {
        ++p_;
        continue;
      }
      break;
    }
    abs_ = std::move(saved_abs);
    if (angle) {
      if (!peek().cmd("rangle")) throw ReadError("expected \\rangle at " + where());
      ++p_;
    } else {
      expect(close);
    }
    if (items.size() == 1 && !angle) return items[0];
    if (open.sym("[")) {  // [a, b]: a vector
      std::vector<ex> c;
      for (const auto& it : items) c.push_back(it.as_scalar("an entry of a vector"));
      return Value::vector(c);
    }
    Value t;
    t.tuple = true;
    t.angle = angle;
    t.items = std::move(items);
    return t;
  }

  // \begin{bmatrix} … \end{bmatrix}, \begin{array}{c} … \end{array}: a vector or a matrix.
  Value matrix(const std::string& env) {
    std::vector<std::vector<Value>> rows(1);
    for (;;) {
      if (peek().cmd("end")) break;
      rows.back().push_back(expr());
      if (peek().sym("&")) {
        ++p_;
        continue;
      }
      if (peek().cmd("\\")) {
        ++p_;
        if (peek().cmd("end")) break;
        rows.emplace_back();
        continue;
      }
      if (peek().cmd("end")) break;
      throw ReadError("unexpected '" + peek().text + "' in a " + env);
    }
    ++p_;  // \end
    braced_range();
    const std::size_t cols = rows[0].size();
    for (const auto& r : rows)
      if (r.size() != cols) throw IllFormed("a " + env + " with rows of different lengths");
    if (cols == 1) {
      std::vector<ex> c;
      for (const auto& r : rows) c.push_back(r[0].as_scalar("an entry of a column"));
      return Value::vector(c);
    }
    if (rows.size() != cols) throw ReadError("a non-square matrix");
    Value m = Value::zeros(2, static_cast<int>(cols));
    for (std::size_t i = 0; i < cols; ++i)
      for (std::size_t j = 0; j < cols; ++j)
        m.c[i * cols + j] = rows[i][j].as_scalar("a matrix entry");
    return m;
  }

  // --- primaries -----------------------------------------------------------------------------
  static Entity value_entity(const Value& v) {
    Entity e;
    e.value = v;
    return e;
  }

  Entity primary() {
    const Token& k = peek();
    if (k.kind == Token::Kind::number) {
      ++p_;
      return postfix_power(value_entity(Value::scalar(number(k.text))));
    }
    if (k.sym("(") || k.sym("[") || k.cmd("langle") || k.sym("{")) {
      return postfix_power(value_entity(group()));
    }
    if (k.sym("|") || k.cmd("|")) {
      abs_.push_back(k.sym("|") ? "|" : "||");
      ++p_;
      Value v = expr();
      if (!closes_abs()) throw ReadError("an unclosed '|' at " + where());
      abs_.pop_back();
      ++p_;
      const ex s = (v.rank == 0 && !v.tuple) ? GiNaC::sqrt(v.c[0] * v.c[0])
                                             : GiNaC::sqrt(dot(v, v).as_scalar("a norm"));
      return postfix_power(value_entity(Value::scalar(s)));
    }
    if (k.cmd("frac") || k.cmd("dfrac") || k.cmd("tfrac")) return frac();
    if (k.cmd("sqrt")) {
      ++p_;
      const Value a = braced_value();
      return postfix_power(value_entity(map(a, [](const ex& e) { return GiNaC::sqrt(e); })));
    }
    if (k.cmd("begin")) {
      ++p_;
      std::vector<Token> env = braced();
      std::string name;
      for (const auto& t : env) name += t.text;
      if (!kMatrixEnv.count(name)) throw ReadError("the environment " + name + " is not supported");
      if (name == "array") braced_range();  // {c}
      return postfix_power(value_entity(matrix(name)));
    }
    if (k.cmd("mathcal") && peek(1).sym("{") && peek(2).is(Token::Kind::letter, "O") &&
        peek(3).sym("}") && peek(4).sym("(")) {
      p_ += 4;
      return remainder();
    }
    if (k.is(Token::Kind::letter, "O") && peek(1).sym("(")) {
      ++p_;
      return remainder();
    }
    if (k.cmd("dots") || k.cmd("ldots") || k.cmd("cdots") || k.cmd("vdots")) {
      ++p_;
      dots_ = true;
      return value_entity(vanishing());
    }
    if (k.kind == Token::Kind::command && kFunctions.count(k.text)) return function();
    if (k.cmd("infty")) throw ReadError("∞ outside a sum's limit");
    return atom_entity();
  }

  Entity remainder() {
    const Value arg = group();
    const ex e = GiNaC::expand(arg.as_scalar("the argument of O(…)"));
    const GiNaC::symbol h = n_.step();
    if (!(e.has(h) && e.is_polynomial(h)))
      throw ReadError("O(…) of something that is not a power of the step");
    const int k = e.ldegree(h);
    rem_ = rem_ ? std::min(*rem_, k) : k;
    return value_entity(vanishing());
  }

  Entity function() {
    const std::string name = next().text;
    ex power = 1;
    if (peek().sym("^")) {
      ++p_;
      power = sub(braced_range()).as_scalar("a power");
    }
    Value arg;
    if (peek().sym("(") || peek().sym("{")) {
      arg = group();
    } else {
      arg = single_factor(nullptr, true);
    }
    const ex a = arg.as_scalar("the argument of \\" + name);
    ex r;
    if (name == "sin")
      r = GiNaC::sin(a);
    else if (name == "cos")
      r = GiNaC::cos(a);
    else if (name == "tan")
      r = GiNaC::tan(a);
    else if (name == "exp")
      r = GiNaC::exp(a);
    else if (name == "log" || name == "ln")
      r = GiNaC::log(a);
    else if (name == "arcsin")
      r = GiNaC::asin(a);
    else if (name == "arccos")
      r = GiNaC::acos(a);
    else if (name == "arctan")
      r = GiNaC::atan(a);
    else if (name == "sinh")
      r = GiNaC::sinh(a);
    else
      r = GiNaC::cosh(a);
    return postfix_power(value_entity(Value::scalar(GiNaC::pow(r, power))));
  }

  Value braced_value() {
    if (!peek().sym("{")) return single_factor(nullptr, true);
    return sub(braced_range());
  }

  static ex number(const std::string& s) {
    const auto dot = s.find('.');
    if (dot == std::string::npos) return numeric(s.c_str());
    const std::string whole = s.substr(0, dot), frac = s.substr(dot + 1);
    const numeric v(std::string(whole + frac).c_str());
    return v / GiNaC::pow(numeric(10), numeric(static_cast<long>(frac.size())));
  }

  // ^ and ! after a value: a power, a transpose, an inverse, a factorial.
  Entity postfix_power(Entity e) {
    while (peek().sym("^") || peek().sym("!")) {
      if (e.value.tuple && e.value.angle && e.value.items.size() == 2)  // ⟨a, b⟩^2
        e.value = dot(e.value.items[0], e.value.items[1]);
      if (peek().sym("!")) {
        ++p_;
        const ex v = e.value.as_scalar("a factorial");
        if (!GiNaC::is_a<numeric>(v)) throw ReadError("a factorial of a non-number");
        e.value = Value::scalar(GiNaC::factorial(GiNaC::ex_to<numeric>(v)));
        continue;
      }
      ++p_;
      const Range r = braced_range();
      const std::vector<Token> sup = copy(r);
      e.value =
          transpose(sup) ? power(e.value, sup) : raise(e.value, sub(r).as_scalar("an exponent"));
    }
    if (peek().sym("'")) throw ReadError("a prime after a group at " + where());
    return e;
  }

  static bool transpose(const std::vector<Token>& sup) {
    return sup.size() == 1 &&
           (sup[0].cmd("top") || sup[0].is(Token::Kind::letter, "T") || sup[0].cmd("intercal"));
  }

  // v^{sup} for a superscript read elsewhere (an atom's): a transpose or a power.
  Value power(const Value& v, const std::vector<Token>& sup) const {
    if (transpose(sup)) {
      if (v.tuple && !v.angle && !v.items.empty()) {
        // (a, b)^T: the row of scalars written as a column vector
        std::vector<ex> c;
        for (const Value& it : v.items) c.push_back(it.as_scalar("an entry of (a, b)^T"));
        return Value::vector(c);
      }
      Value r = v;
      if (r.rank == 2) {
        for (int i = 0; i < r.n; ++i)
          for (int j = i + 1; j < r.n; ++j) std::swap(r.c[i * r.n + j], r.c[j * r.n + i]);
      } else {
        r.transposed = !r.transposed;
      }
      return r;
    }
    return raise(v, evaluate(sup).as_scalar("an exponent"));
  }

  static Value raise(const Value& v, const ex& pe) {
    if (v.tuple) throw IllFormed("a power of an argument list");
    if (v.rank == 2) {
      if (pe != -1) throw IllFormed("a power of a matrix other than -1");
      GiNaC::matrix m(v.n, v.n);
      for (int i = 0; i < v.n; ++i)
        for (int j = 0; j < v.n; ++j) m(i, j) = v.c[i * v.n + j];
      const GiNaC::matrix inv = m.inverse();
      Value r = v;
      r.slots = 0;
      for (int i = 0; i < v.n; ++i)
        for (int j = 0; j < v.n; ++j) r.c[i * v.n + j] = inv(i, j);
      return r;
    }
    if (v.rank == 1) {  // a vector squared: its squared length
      if (pe != 2) throw IllFormed("a vector to a power other than 2");
      return Value::scalar(dot(v, v).as_scalar("a squared vector"));
    }
    return Value::scalar(GiNaC::pow(v.c[0], pe));
  }

  // \frac{A}{B}: a quotient, or a derivative operator (d/dt, ∂/∂x), or ∂A/∂B.
  Entity frac() {
    ++p_;
    const Range rn = braced_range(), rd = braced_range();
    const std::vector<Token> num = copy(rn), den = copy(rd);
    auto is_d = [](const Token& t) { return t.is(Token::Kind::letter, "d"); };
    // d/dt, d^k/dt^k, dA/dt
    if (!num.empty() && is_d(num[0]) && den.size() >= 2 && is_d(den[0]) &&
        den[1].kind == Token::Kind::letter) {
      int times = 1;
      std::size_t rest = 1;
      if (num.size() >= 3 && num[1].sym("^")) {
        // d^k or d^{2i} (an exponent in a bound index)
        std::size_t close = 3;
        if (num[2].sym("{")) {
          int depth = 0;
          for (close = 2; close < num.size(); ++close) {
            if (num[close].sym("{")) ++depth;
            if (num[close].sym("}") && --depth == 0) break;
          }
          ++close;
        }
        const ex k = sub(Range{rn.b + 2, rn.b + close}).as_scalar("the order of a derivative");
        if (!GiNaC::is_a<numeric>(k) || !GiNaC::ex_to<numeric>(k).is_nonneg_integer())
          throw ReadError("a derivative of order " +
                          print(std::vector<Token>(
                              num.begin() + 2, num.begin() + static_cast<std::ptrdiff_t>(close))));
        times = GiNaC::ex_to<numeric>(k).to_int();
        rest = close;
      }
      const std::string var = den[1].text;
      const Notation& n = n_;
      Entity op;
      op.kind = Entity::Kind::op;
      op.apply = [&n, var, times](const Value& v) { return n.time_derivative(v, var, times); };
      if (rest < num.size()) {  // dA/dt
        const Value a = sub(Range{rn.b + rest, rn.e});
        return postfix_power(value_entity(op.apply(a)));
      }
      return op;
    }
    if (!num.empty() && num[0].cmd("partial")) {
      std::size_t r = 1;
      int order = 1;
      if (num.size() > 2 && num[1].sym("^")) {
        if (num[2].kind != Token::Kind::number) throw ReadError("∂ of symbolic order");
        order = std::stoi(num[2].text);
        r = 3;
      }
      std::vector<std::pair<Atom, int>> wrt;
      {
        const std::size_t saved_p = p_, saved_end = end_;
        p_ = rd.b;
        end_ = rd.e;
        while (!done()) {
          if (!peek().cmd("partial")) throw ReadError("the denominator of ∂…/∂… must be ∂x ∂y …");
          ++p_;
          Atom a = atom();
          int times = 1;
          if (a.sup) {
            const ex tv = evaluate(*a.sup).as_scalar("a power of ∂");
            if (!GiNaC::is_a<numeric>(tv)) throw ReadError("a symbolic power of ∂");
            times = GiNaC::ex_to<numeric>(tv).to_int();
            a.sup.reset();
          }
          wrt.emplace_back(a, times);
        }
        p_ = saved_p;
        end_ = saved_end;
      }
      int total = 0;
      for (const auto& w : wrt) total += w.second;
      if (total != order)
        throw IllFormed("∂^" + std::to_string(order) + " over " + std::to_string(total) +
                        " variables");
      const Notation& n = n_;
      auto apply = [&n, wrt](Value v) {
        for (const auto& [a, times] : wrt)
          for (int k = 0; k < times; ++k) v = n.partial(v, a);
        return v;
      };
      if (r >= num.size()) {
        Entity op;
        op.kind = Entity::Kind::op;
        op.apply = apply;
        return op;
      }
      const Value a = sub(Range{rn.b + r, rn.e});
      return postfix_power(value_entity(apply(a)));
    }
    const Value a = sub(rn), b = sub(rd);
    const ex d = b.as_scalar("a denominator");
    return postfix_power(value_entity(map(a, [&](const ex& x) { return x / d; })));
  }

  // An atom: base, accents, primes, sub- and superscripts.
  Atom atom() {
    Atom a;
    std::vector<std::string> accents;
    while (peek().kind == Token::Kind::command && kAccents.count(peek().text)) {
      accents.push_back(next().text);
      if (peek().sym("{")) {  // \dot{x}: the braces hold the base, possibly decorated
        ++p_;
        Atom inner = atom();
        expect("}");
        inner.accents.insert(inner.accents.begin(), accents.begin(), accents.end());
        a = std::move(inner);
        decorate(a);
        return a;
      }
    }
    const Token& k = next();
    if (k.kind == Token::Kind::letter) {
      a.base = k.text;
    } else if (k.kind == Token::Kind::command && kLetterFonts.count(k.text)) {
      const std::vector<Token> inner = braced();
      a.base = k.text + "{" + print(inner) + "}";
    } else if (k.cmd("text")) {
      for (const auto& x : braced()) a.base += x.text;
    } else if (k.kind == Token::Kind::command && kGreek.count(k.text)) {
      a.base = k.text;
      if (k.text == "Delta" && peek().kind == Token::Kind::letter) a.base = "Delta " + next().text;
    } else {
      throw ReadError("unexpected '" + std::string(k.kind == Token::Kind::command ? "\\" : "") +
                      k.text + "' at character " + std::to_string(k.begin + 1));
    }
    a.accents = accents;
    decorate(a);
    return a;
  }

  void decorate(Atom& a) {
    for (;;) {
      if (peek().sym("'")) {
        ++p_;
        ++a.primes;
      } else if (peek().sym("_") && !a.sub) {
        ++p_;
        a.sub = braced();
      } else if (peek().sym("^") && !a.sup) {
        ++p_;
        a.sup = braced();
      } else {
        break;
      }
    }
  }

  Entity entity() {
    const Atom a = atom();
    std::optional<Entity> e;
    // a summation index used as a number (the k of \sum_{k=1}^\infty (k-1)! h^{2k})
    if (a.base.size() == 1 && a.accents.empty() && a.primes == 0 && !a.sub) {
      if (auto b = bound(a.base[0])) {
        e = Entity{};
        e->value = Value::scalar(*b);
      }
    }
    if (!e) e = n_.resolve(a, *this);
    if (!e) throw ReadError("the notation does not know " + a.text());
    if (a.sup && !e->consumed_sup) {
      // a power of a value, of a curve's value, or of a field's value at the jet point (f^3)
      if (e->kind != Entity::Kind::value && e->kind != Entity::Kind::curve &&
          e->kind != Entity::Kind::field)
        throw ReadError("a superscript on " + a.text() + " that the notation does not read");
      e->value = power(e->value, *a.sup);
      e->kind = Entity::Kind::value;
    }
    return *e;
  }

  Entity atom_entity() {
    Entity e = entity();
    if (e.kind == Entity::Kind::op) return e;
    return postfix_power(value_entity(postfix_entity(e)));
  }
};

const std::map<std::size_t, ex> Parser::kNoScale;

}  // namespace

void unbound_index(char index) { throw UnboundIndex{index}; }

Value field_tensor_at(const ex& f, int order, const Notation& n, const std::vector<ex>& point) {
  const auto& y = n.point();
  const std::size_t dim = y.size();
  Value v = Value::zeros(dim == 1 ? 0 : order, static_cast<int>(dim));
  if (dim == 1) v.n = 1;
  GiNaC::exmap at;
  for (std::size_t k = 0; k < dim; ++k) at[y[k]] = point.at(k);
  for (std::size_t flat = 0; flat < v.c.size(); ++flat) {
    std::size_t rest = flat;
    ex d = f;
    for (int s = 0; s < order; ++s) {
      const std::size_t i = dim == 1 ? 0 : rest % dim;
      if (dim > 1) rest /= dim;
      d = d.diff(y[i]);
    }
    v.c[flat] = d.subs(at);
  }
  v.slots = order;
  return v;
}

Value field_tensor(const ex& f, int order, const Notation& n) {
  return field_tensor_at(f, order, n, n.expansion_point());
}

Reading read(const std::vector<Token>& tokens, const Notation& notation,
             const std::map<std::size_t, ex>& scale) {
  try {
    Parser p(tokens, notation, scale);
    return p.read_all();
  } catch (const UnboundIndex& u) {
    throw ReadError(std::string("the index ") + u.index + " is not bound by a sum");
  }
}

Reading read(std::string_view latex, const Notation& notation) {
  return read(tokenize(latex), notation);
}

std::vector<std::pair<std::size_t, std::size_t>> term_ranges(const std::vector<Token>& tokens,
                                                             const Notation& notation) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  try {
    Parser p(tokens, notation, Parser::kNoScale, &out);
    p.read_all();
  } catch (...) {
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace vibook::printed
