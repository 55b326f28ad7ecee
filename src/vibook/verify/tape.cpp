// The compiled typed discrete Lagrangian (tape.hpp): a graph of shared subexpressions recorded
// from the expression tree, differentiated symbolically (Vermeeren 2017 §2, (4)–(5) need
// D1 L_d, D2 L_d and the Newton matrix D2 D1 L_d), and flattened into instruction tapes.
#include "vibook/verify/tape.hpp"

#include <bit>
#include <cstring>
#include <sstream>
#include <unordered_map>
#include <utility>

namespace vibook::verify {

namespace {

using Op = Tape::Op;

// ---------------------------------------------------------------------------------------------
// The graph: nodes in creation order, which is an order where operands come first.
// ---------------------------------------------------------------------------------------------

enum class Kind : std::uint8_t { input, constant, operation };

struct Node {
  Kind kind;
  Op op = Op::add;  // operation
  int a = -1;       // input: its slot; constant: its index; operation: first operand
  int b = -1;       // operation: second operand (binary operations)
};

struct Const {
  GiNaC::numeric exact;  // when `is_exact`
  bool is_exact = false;
  double value = 0;
};

bool binary(Op op) { return op == Op::add || op == Op::sub || op == Op::mul || op == Op::div; }

struct Key {
  int kind, op, a, b;
  bool operator==(const Key&) const = default;
};
struct KeyHash {
  std::size_t operator()(const Key& k) const {
    std::size_t h = std::size_t(k.kind) * 0x9E3779B97F4A7C15ull;
    h ^= std::size_t(k.op) + 0x9E3779B9u + (h << 6) + (h >> 2);
    h ^= std::size_t(std::uint32_t(k.a)) + 0x9E3779B9u + (h << 6) + (h >> 2);
    h ^= std::size_t(std::uint32_t(k.b)) + 0x9E3779B9u + (h << 6) + (h >> 2);
    return h;
  }
};

class Graph {
 public:
  static constexpr int kZeroDerivative = -1;

  int size() const { return int(nodes_.size()); }
  const Node& node(int i) const { return nodes_[i]; }
  const Const& constant_of(int i) const { return consts_[nodes_[i].a]; }

  int input(int slot) { return intern({Kind::input, Op::add, slot, -1}); }

  int constant(const GiNaC::numeric& q) {
    std::ostringstream os;  // an exact rational prints exactly
    os << q;
    const std::string key = os.str();
    if (auto it = exact_index_.find(key); it != exact_index_.end()) return it->second;
    Const c;
    c.exact = q;
    c.is_exact = true;
    c.value = q.to_double();
    consts_.push_back(c);
    const int id = add({Kind::constant, Op::add, int(consts_.size()) - 1, -1});
    exact_index_.emplace(key, id);
    return id;
  }

  // A double is the rational m·2^e it denotes; a non-finite one stays a double.
  int constant(double x) {
    if (std::isfinite(x)) {
      int e = 0;
      const double m = std::frexp(x, &e);  // x = m·2^e, 0.5 <= |m| < 1
      const auto mantissa = static_cast<long long>(std::ldexp(m, 53));
      return constant(GiNaC::numeric(mantissa) * GiNaC::numeric(2).power(GiNaC::numeric(e - 53)));
    }
    const auto bits = std::bit_cast<std::uint64_t>(x);
    if (auto it = inexact_index_.find(bits); it != inexact_index_.end()) return it->second;
    Const c;
    c.value = x;
    consts_.push_back(c);
    const int id = add({Kind::constant, Op::add, int(consts_.size()) - 1, -1});
    inexact_index_.emplace(bits, id);
    return id;
  }

  int zero() { return constant(GiNaC::numeric(0)); }
  int one() { return constant(GiNaC::numeric(1)); }

  // An operation, simplified and shared. The simplifications are exact in real arithmetic and
  // change floating-point results only in the sign of a zero or where an operand is not
  // finite (x·0 is 0 here).
  //
  // Negations are moved outward and absorbed into sums, x + x is 2·x, and two scalings by
  // powers of two are one: each of these rewrites gives the same floating-point number
  // (IEEE rounding is symmetric, and a power-of-two scaling is exact away from overflow), so
  // the value of L_d stays the tree evaluator's to the bit while the derivatives, where the
  // chain rule makes many such patterns, lose instructions.
  int op(Op o, int a, int b = -1) {
    const Const* ca = exact(a);
    const Const* cb = binary(o) ? exact(b) : nullptr;
    const int na = negated(a), nb = binary(o) ? negated(b) : -1;
    switch (o) {
      case Op::add:
        if (ca && cb) return constant(ca->exact + cb->exact);
        if (ca && ca->exact.is_zero()) return b;
        if (cb && cb->exact.is_zero()) return a;
        if (na >= 0 && nb >= 0) return op(Op::neg, op(Op::add, na, nb));  // −x + −y = −(x + y)
        if (nb >= 0) return op(Op::sub, a, nb);                           // x + −y = x − y
        if (na >= 0) return op(Op::sub, b, na);                           // −x + y = y − x
        if (a == b) return op(Op::mul, constant(GiNaC::numeric(2)), a);   // x + x = 2x
        if (b < a) std::swap(a, b);                                       // a + b == b + a exactly
        break;
      case Op::sub:
        if (ca && cb) return constant(ca->exact - cb->exact);
        if (cb && cb->exact.is_zero()) return a;
        if (ca && ca->exact.is_zero()) return op(Op::neg, b);
        if (nb >= 0) return op(Op::add, a, nb);               // x − −y = x + y
        if (na >= 0) return op(Op::neg, op(Op::add, na, b));  // −x − y = −(x + y)
        break;
      case Op::mul:
        if (ca && cb) return constant(ca->exact * cb->exact);
        if ((ca && ca->exact.is_zero()) || (cb && cb->exact.is_zero())) return zero();
        if (ca && is(ca, 1)) return b;
        if (cb && is(cb, 1)) return a;
        if (ca && is(ca, -1)) return op(Op::neg, b);
        if (cb && is(cb, -1)) return op(Op::neg, a);
        if (na >= 0) return op(Op::neg, op(Op::mul, na, b));  // (−x)·y = −(x·y)
        if (nb >= 0) return op(Op::neg, op(Op::mul, a, nb));
        if (cb && !ca) {  // the constant first
          std::swap(a, b);
          std::swap(ca, cb);
        }
        if (ca && power_of_two(ca->exact) && nodes_[b].kind == Kind::operation &&
            nodes_[b].op == Op::mul) {  // 2^i·(2^j·y) = 2^(i+j)·y
          const Const* inner = exact(nodes_[b].a);
          if (inner && power_of_two(inner->exact))
            return op(Op::mul, constant(ca->exact * inner->exact), nodes_[b].b);
        }
        if (b < a && !(ca || cb)) std::swap(a, b);
        break;
      case Op::div:
        if (ca && cb && !cb->exact.is_zero()) return constant(ca->exact / cb->exact);
        if (ca && ca->exact.is_zero()) return zero();
        if (cb && is(cb, 1)) return a;
        if (na >= 0) return op(Op::neg, op(Op::div, na, b));  // (−x)/y = −(x/y)
        if (nb >= 0) return op(Op::neg, op(Op::div, a, nb));
        // x/2^k = 2^−k·x: both are x·2^−k correctly rounded, the same number, and a product
        // costs a fraction of a quotient (the chain rule of √ and of quotients makes many).
        if (cb && power_of_two(cb->exact) && representable(cb->exact))
          return op(Op::mul, constant(1 / cb->exact), a);
        {  // (c·x)/(c·y) = x/y for a power of two |c| >= 1: c·x and c·y are exact
          const Const* cx = scaling(a);
          const Const* cy = scaling(b);
          if (cx && cy && cx->exact.is_equal(cy->exact) && GiNaC::abs(cx->exact) >= 1)
            return op(Op::div, nodes_[a].b, nodes_[b].b);
        }
        break;
      case Op::neg:
        if (ca) return constant(-ca->exact);
        if (na >= 0) return na;
        if (nodes_[a].kind == Kind::operation && nodes_[a].op == Op::sub)  // −(x − y) = y − x
          return op(Op::sub, nodes_[a].b, nodes_[a].a);
        break;
      default:
        break;
    }
    return intern({Kind::operation, o, a, binary(o) ? b : -1});
  }

  // ∂/∂(input `slot`) of each target, by one forward sweep over the nodes the targets need.
  std::vector<int> diff(const std::vector<int>& targets, int slot) {
    const std::vector<char> need = ancestors(targets);
    const int m = int(need.size());
    std::vector<int> d(m, kZeroDerivative);
    for (int i = 0; i < m; ++i) {
      if (!need[i]) continue;
      const Node n = nodes_[i];  // a copy: op() may grow nodes_
      if (n.kind == Kind::input) {
        if (n.a == slot) d[i] = one();
        continue;
      }
      if (n.kind == Kind::constant) continue;
      const int da = d[n.a], db = binary(n.op) ? d[n.b] : kZeroDerivative;
      if (da == kZeroDerivative && db == kZeroDerivative) continue;
      switch (n.op) {
        case Op::add:
          d[i] = da == kZeroDerivative ? db : db == kZeroDerivative ? da : op(Op::add, da, db);
          break;
        case Op::sub:
          d[i] = db == kZeroDerivative   ? da
                 : da == kZeroDerivative ? op(Op::neg, db)
                                         : op(Op::sub, da, db);
          break;
        case Op::mul: {
          const int t1 = da == kZeroDerivative ? kZeroDerivative : op(Op::mul, da, n.b);
          const int t2 = db == kZeroDerivative ? kZeroDerivative : op(Op::mul, n.a, db);
          d[i] = t1 == kZeroDerivative ? t2 : t2 == kZeroDerivative ? t1 : op(Op::add, t1, t2);
          break;
        }
        case Op::div: {  // (a/b)' = (a' − (a/b)·b')/b
          if (db == kZeroDerivative) {
            d[i] = op(Op::div, da, n.b);
          } else {
            const int t = op(Op::mul, i, db);
            const int num = da == kZeroDerivative ? op(Op::neg, t) : op(Op::sub, da, t);
            d[i] = op(Op::div, num, n.b);
          }
          break;
        }
        case Op::neg:
          d[i] = op(Op::neg, da);
          break;
        case Op::sin:
          d[i] = op(Op::mul, op(Op::cos, n.a), da);
          break;
        case Op::cos:
          d[i] = op(Op::neg, op(Op::mul, op(Op::sin, n.a), da));
          break;
        case Op::exp:
          d[i] = op(Op::mul, i, da);
          break;
        case Op::log:
          d[i] = op(Op::div, da, n.a);
          break;
        case Op::sqrt:  // (√a)' = a'/(2√a)
          d[i] = op(Op::div, da, op(Op::mul, constant(GiNaC::numeric(2)), i));
          break;
      }
    }
    std::vector<int> out;
    for (int t : targets) out.push_back(d[t] == kZeroDerivative ? zero() : d[t]);
    return out;
  }

  // The targets with each input slot s in `with` replaced by the node with[s] (−1: kept).
  std::vector<int> substitute(const std::vector<int>& targets, const std::vector<int>& with) {
    const std::vector<char> need = ancestors(targets);
    const int m = int(need.size());
    std::vector<int> r(m, -1);
    for (int i = 0; i < m; ++i) {
      if (!need[i]) continue;
      const Node n = nodes_[i];
      if (n.kind == Kind::input)
        r[i] = n.a < int(with.size()) && with[n.a] >= 0 ? with[n.a] : i;
      else if (n.kind == Kind::constant)
        r[i] = i;
      else
        r[i] = op(n.op, r[n.a], binary(n.op) ? r[n.b] : -1);
    }
    std::vector<int> out;
    for (int t : targets) out.push_back(r[t]);
    return out;
  }

  // The tape of `outputs` over `inputs` input slots; the instructions that depend on no slot
  // outside `prefix_slots` come first (Tape::prefix()).
  // Of the late instructions, those the first `first_outputs` outputs need come first
  // (Tape::first_part()).
  // Outputs listed in `carried` can be copied in from elsewhere; Tape::carried_prefix() lists
  // the prefix instructions the other outputs need when they are.
  Tape flatten(const std::vector<int>& outputs, int inputs, const std::vector<char>& prefix_slots,
               std::size_t first_outputs = 0, const std::vector<int>& carried = {}) const {
    const std::vector<char> need = ancestors(outputs);
    std::vector<char> first = ancestors(std::vector<int>(
        outputs.begin(), outputs.begin() + std::min(first_outputs, outputs.size())));
    first.resize(need.size(), 0);
    const int m = int(need.size());
    std::vector<char> late =  // depends on a slot outside the prefix
        depends_on(
            [&](int slot) { return !(slot < int(prefix_slots.size()) && prefix_slots[slot]); });
    std::vector<char> is_carried(m, 0);
    for (int c : carried) is_carried[c] = 1;
    std::vector<char> through = ancestors(outputs, &is_carried);  // not behind a carried one
    through.resize(m, 0);
    std::vector<int> carried_prefix;
    std::vector<Tape::Constant> constants;
    std::vector<Tape::Instruction> code;
    int prefix = 0;
    std::vector<int> where(m, -1);
    for (int i = 0; i < m; ++i) {
      if (!need[i]) continue;
      const Node& n = nodes_[i];
      if (n.kind == Kind::input) {
        if (n.a >= inputs) throw std::logic_error("tape: an input slot was left unsubstituted");
        where[i] = n.a;
      } else if (n.kind == Kind::constant) {
        const Const& c = consts_[n.a];
        Tape::Constant k;
        k.value = c.value;
        if (c.is_exact) {
          const GiNaC::numeric num = c.exact.numer(), den = c.exact.denom();
          const GiNaC::numeric limit = GiNaC::numeric(2).power(GiNaC::numeric(53));
          if (GiNaC::abs(num) < limit && den < limit) {
            k.fraction = true;
            k.num = num.to_double();
            k.den = den.to_double();
          }
        }
        where[i] = inputs + int(constants.size());
        constants.push_back(k);
      }
    }
    const int base = inputs + int(constants.size());
    // Three passes, each in index order (operands first): the prefix, the late instructions
    // of the first outputs, the rest.
    int first_part = 0;
    for (int pass = 0; pass < 3; ++pass) {
      for (int i = 0; i < m; ++i) {
        const Node& n = nodes_[i];
        if (!need[i] || n.kind != Kind::operation) continue;
        const int group = !late[i] ? 0 : first[i] ? 1 : 2;
        if (group != pass) continue;
        where[i] = base + int(code.size());
        if (pass == 0 && !carried.empty() && through[i] && !is_carried[i])
          carried_prefix.push_back(int(code.size()));
        code.push_back({n.op, where[n.a], binary(n.op) ? where[n.b] : where[n.a]});
      }
      if (pass == 0) prefix = int(code.size());
      if (pass == 1) first_part = int(code.size());
    }
    std::vector<int> out;
    for (int o : outputs) out.push_back(where[o]);
    Tape t(inputs, std::move(constants), std::move(code), std::move(out), prefix, first_part);
    t.set_carried_prefix(std::move(carried_prefix));
    return t;
  }

  // Which nodes depend on an input slot s with in(s).
  template <class In>
  std::vector<char> depends_on(In&& in) const {
    const int m = size();
    std::vector<char> d(m, 0);
    for (int i = 0; i < m; ++i) {
      const Node& n = nodes_[i];
      if (n.kind == Kind::input)
        d[i] = in(n.a);
      else if (n.kind == Kind::operation)
        d[i] = d[n.a] || (binary(n.op) && d[n.b]);
    }
    return d;
  }

  // Which nodes the targets need (a node's operands have smaller indices); a node marked in
  // `stop` is needed but its operands are not needed through it.
  std::vector<char> ancestors(const std::vector<int>& targets,
                              const std::vector<char>* stop = nullptr) const {
    int top = -1;
    for (int t : targets) top = std::max(top, t);
    std::vector<char> need(top + 1, 0);
    for (int t : targets) need[t] = 1;
    for (int i = top; i >= 0; --i) {
      if (!need[i] || nodes_[i].kind != Kind::operation) continue;
      if (stop && i < int(stop->size()) && (*stop)[i]) continue;
      need[nodes_[i].a] = 1;
      if (binary(nodes_[i].op)) need[nodes_[i].b] = 1;
    }
    return need;
  }

 private:
  // x when node i is −x (an operation), else −1.
  int negated(int i) const {
    if (i < 0 || nodes_[i].kind != Kind::operation || nodes_[i].op != Op::neg) return -1;
    return nodes_[i].a;
  }
  // ±2^k: a scaling by it is exact.
  static bool power_of_two(const GiNaC::numeric& c) {
    if (c.is_zero()) return false;
    const GiNaC::numeric m = GiNaC::abs(c);
    auto pow2 = [](GiNaC::numeric n) {  // a positive integer
      while (n.is_even()) n = n / 2;
      return n.is_equal(GiNaC::numeric(1));
    };
    return pow2(m.numer()) && pow2(m.denom());
  }
  // A power of two whose reciprocal is a normal double too.
  static bool representable(const GiNaC::numeric& c) {
    const GiNaC::numeric m = GiNaC::abs(c), big = GiNaC::numeric(2).power(1000);
    return m < big && m * big > 1;
  }
  // The constant c of a node c·y, c a power of two (the product keeps its constant first).
  const Const* scaling(int i) const {
    if (nodes_[i].kind != Kind::operation || nodes_[i].op != Op::mul) return nullptr;
    const Const* c = exact(nodes_[i].a);
    return c && power_of_two(c->exact) ? c : nullptr;
  }
  static bool is(const Const* c, int k) { return c->exact.is_equal(GiNaC::numeric(k)); }
  const Const* exact(int i) const {
    if (i < 0 || nodes_[i].kind != Kind::constant) return nullptr;
    const Const& c = consts_[nodes_[i].a];
    return c.is_exact ? &c : nullptr;
  }
  int add(const Node& n) {
    nodes_.push_back(n);
    return int(nodes_.size()) - 1;
  }
  int intern(const Node& n) {
    const Key k{int(n.kind), int(n.op), n.a, n.b};
    if (auto it = index_.find(k); it != index_.end()) return it->second;
    const int id = add(n);
    index_.emplace(k, id);
    return id;
  }
  std::vector<Node> nodes_;
  std::vector<Const> consts_;
  std::unordered_map<Key, int, KeyHash> index_;
  std::unordered_map<std::string, int> exact_index_;
  std::unordered_map<std::uint64_t, int> inexact_index_;
};

thread_local Graph* recording = nullptr;

}  // namespace

// ---------------------------------------------------------------------------------------------
// The recording scalar: the expression tree evaluated on it writes the graph.
// ---------------------------------------------------------------------------------------------

/// A scalar whose arithmetic records nodes in the graph being built (compile_tapes only).
struct TapeScalar {
  static constexpr bool records_a_tape = true;
  int id = -1;

  TapeScalar() = default;
  TapeScalar(double x) : id(recording->constant(x)) {}  // NOLINT: constants lift implicitly
  static TapeScalar node(int i) {
    TapeScalar s;
    s.id = i;
    return s;
  }

  friend TapeScalar operator+(const TapeScalar& a, const TapeScalar& b) {
    return node(recording->op(Op::add, a.id, b.id));
  }
  friend TapeScalar operator-(const TapeScalar& a, const TapeScalar& b) {
    return node(recording->op(Op::sub, a.id, b.id));
  }
  friend TapeScalar operator*(const TapeScalar& a, const TapeScalar& b) {
    return node(recording->op(Op::mul, a.id, b.id));
  }
  friend TapeScalar operator/(const TapeScalar& a, const TapeScalar& b) {
    return node(recording->op(Op::div, a.id, b.id));
  }
  friend TapeScalar operator-(const TapeScalar& a) { return node(recording->op(Op::neg, a.id)); }
  friend TapeScalar sin(const TapeScalar& a) { return node(recording->op(Op::sin, a.id)); }
  friend TapeScalar cos(const TapeScalar& a) { return node(recording->op(Op::cos, a.id)); }
  friend TapeScalar exp(const TapeScalar& a) { return node(recording->op(Op::exp, a.id)); }
  friend TapeScalar log(const TapeScalar& a) { return node(recording->op(Op::log, a.id)); }
  friend TapeScalar sqrt(const TapeScalar& a) { return node(recording->op(Op::sqrt, a.id)); }

  // ∇V(u) for `grad(V)(u)` (the hook in expression.hpp): V recorded at placeholder inputs,
  // differentiated there, and the placeholders replaced by u.
  template <int N, class F>
  static std::array<TapeScalar, N> gradient(const std::array<TapeScalar, N>& u, F&& potential) {
    std::array<TapeScalar, N> x;
    std::vector<int> with(kPlaceholder + N, -1);
    for (int j = 0; j < N; ++j) {
      x[j] = node(recording->input(kPlaceholder + j));
      with[kPlaceholder + j] = u[j].id;
    }
    const int v = potential(x).id;
    std::vector<int> g;
    for (int j = 0; j < N; ++j) g.push_back(recording->diff({v}, kPlaceholder + j)[0]);
    g = recording->substitute(g, with);
    std::array<TapeScalar, N> r;
    for (int j = 0; j < N; ++j) r[j] = node(g[j]);
    return r;
  }
  // Input slots: q0 (0…N−1), q1 (N…2N−1), h (2N); placeholders of grad(V) from here.
  static constexpr int kPlaceholder = 2 * kMaxDim + 1;
};

namespace {

template <int N>
CompiledTapes compile(const TypedDiscreteLagrangian& dl) {
  Graph g;
  recording = &g;
  struct Reset {
    ~Reset() { recording = nullptr; }
  } reset;
  Vec<TapeScalar, N> q0, q1;
  for (int i = 0; i < N; ++i) {
    q0(i) = TapeScalar::node(g.input(i));
    q1(i) = TapeScalar::node(g.input(N + i));
  }
  const TapeScalar h = TapeScalar::node(g.input(2 * N));
  const int L = dl.evaluate<N, TapeScalar>(q0, q1, h).id;
  std::vector<int> D1, D2, D12(N * N);
  for (int i = 0; i < N; ++i) D1.push_back(g.diff({L}, i)[0]);
  for (int j = 0; j < N; ++j) D2.push_back(g.diff({L}, N + j)[0]);
  for (int j = 0; j < N; ++j) {
    const std::vector<int> col = g.diff(D1, N + j);
    for (int i = 0; i < N; ++i) D12[N * i + j] = col[i];
  }
  const int inputs = 2 * N + 1;
  std::vector<char> q0_and_h(inputs, 0), none(inputs, 0);
  for (int i = 0; i < N; ++i) q0_and_h[i] = 1;
  q0_and_h[2 * N] = 1;

  CompiledTapes t;
  t.nodes = g.size();
  std::vector<int> newton = D1;
  newton.insert(newton.end(), D12.begin(), D12.end());

  // Carried values (CompiledTapes): the prefix nodes that depend on q0 (and not on q1), their
  // twins with q0 replaced by q1, and those twins the momentum needs.
  const std::vector<char> on_q0 = g.depends_on([](int s) { return s < N; });
  const std::vector<char> on_q1 = g.depends_on([](int s) { return s >= N && s < 2 * N; });
  const std::vector<char> for_newton = g.ancestors(newton);
  std::vector<int> candidates;
  for (int i = 0; i < int(for_newton.size()); ++i)
    if (for_newton[i] && g.node(i).kind == Kind::operation && on_q0[i] && !on_q1[i])
      candidates.push_back(i);
  std::vector<int> shift(inputs, -1);
  for (int i = 0; i < N; ++i) shift[i] = g.input(N + i);
  const std::vector<int> twins = g.substitute(candidates, shift);  // may add nodes
  const std::vector<char> for_momentum = g.ancestors(D2);
  std::vector<char> twinned(g.size(), 0);
  std::vector<int> twin_of(g.size(), -1);
  for (std::size_t k = 0; k < candidates.size(); ++k)
    if (twins[k] < int(for_momentum.size()) && for_momentum[twins[k]]) {
      twinned[candidates[k]] = 1;
      twin_of[candidates[k]] = twins[k];
    }
  // Only the outermost of them: those the Newton outputs reach without passing another.
  const std::vector<char> reached = g.ancestors(newton, &twinned);
  std::vector<int> carried, momentum = D2;
  for (int i = 0; i < int(reached.size()); ++i)
    if (reached[i] && twinned[i]) {
      carried.push_back(i);
      momentum.push_back(twin_of[i]);
    }
  t.carried = int(carried.size());
  newton.insert(newton.end(), carried.begin(), carried.end());
  t.newton = g.flatten(newton, inputs, q0_and_h, D1.size(), carried);
  t.momentum = g.flatten(momentum, inputs, none);
  std::vector<int> all{L};
  all.insert(all.end(), D1.begin(), D1.end());
  all.insert(all.end(), D2.begin(), D2.end());
  all.insert(all.end(), D12.begin(), D12.end());
  t.all = g.flatten(all, inputs, none);
  return t;
}

}  // namespace

CompiledTapes compile_tapes(const TypedDiscreteLagrangian& dl) {
  CompiledTapes t;
  const bool done = [&]<int... K>(std::integer_sequence<int, K...>) {
    return ((dl.dim() == K + 1 && (t = compile<K + 1>(dl), true)) || ...);
  }
  (std::make_integer_sequence<int, kMaxDim>{});
  if (!done)
    throw ArgumentError("--dim", "a compiled discrete Lagrangian needs 1 to " +
                                     std::to_string(kMaxDim) + " dimensions");
  return t;
}

}  // namespace vibook::verify
