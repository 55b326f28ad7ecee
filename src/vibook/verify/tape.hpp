/// \file tape.hpp
/// \brief A typed discrete Lagrangian compiled once: its derivatives D1 L_d, D2 L_d and
/// D2 D1 L_d taken symbolically on a graph of shared subexpressions, simplified, and flattened
/// into a straight-line instruction tape that is evaluated in any scalar type (double,
/// long double, double-double, quad, MPFR).
///
/// Why: the generic path evaluates the expression tree on nested forward AutoDiff numbers in
/// every Newton iteration (Vermeeren 2017 §2, (4)–(5): p_k = −D1 L_d(q_k, q_{k+1}, h) solved
/// for q_{k+1}, p_{k+1} = D2 L_d), carrying N + N² derivative components through every
/// operation, most of them zero. The tape computes only what is not zero, computes each
/// shared piece once, and computes the part that depends on q_k and h alone once per step
/// instead of once per iteration.
///
/// How the tape is made:
/// 1. **Recording.** The expression tree (expression.hpp) is evaluated once on a recording
///    scalar: every operation becomes a node of a graph, identical nodes are one node
///    (hash-consing: the same operation on the same operands, commutative operands ordered),
///    constants are exact rationals and are folded exactly, x + 0, x · 1, x · 0 and −(−x)
///    are simplified away. `grad(V)(u)` is V recorded at placeholders, differentiated, and
///    the placeholders replaced by u.
/// 2. **Differentiation.** d/dq0_i, d/dq1_j by the chain rule, one forward sweep over the
///    graph per variable; the second derivative d/dq1_j of D1 L_d is a sweep over the graph
///    that already holds D1. The new nodes go through the same simplification and sharing.
/// 3. **Flattening.** The nodes the outputs need, in an order where operands come first,
///    those that do not depend on q1 first; operands renumbered into one work array.
///
/// The value L_d is computed by the same operations in the same order as the tree
/// evaluator, so in double it is the same number bit for bit; the derivatives are computed by
/// other operations than AutoDiff's and agree to round-off (doctests in tape_test.cpp).
///
/// Chapter: \ref chapter-verify.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "vibook/core/autodiff.hpp"
#include "vibook/core/types.hpp"
#include "vibook/verify/expression.hpp"

namespace vibook::verify {

/// The instructions of a tape: straight-line code over one work array.
class Tape {
 public:
  enum class Op : std::uint8_t { add, sub, mul, div, neg, sin, cos, exp, log, sqrt };
  struct Instruction {
    Op op;
    std::int32_t a, b;  ///< operands: indices into the work array
  };
  /// A constant: the exact rational num/den when both are integers below 2^53 (lifted as
  /// S(num)/S(den), so that a wider type gets its own digits), else the nearest double.
  struct Constant {
    double value = 0, num = 0, den = 1;
    bool fraction = false;
  };

  Tape() = default;
  Tape(int inputs, std::vector<Constant> constants, std::vector<Instruction> code,
       std::vector<int> outputs, int prefix, int first_part)
      : inputs_(inputs),
        constants_(std::move(constants)),
        code_(std::move(code)),
        outputs_(std::move(outputs)),
        prefix_(prefix),
        first_part_(first_part) {}

  int inputs() const { return inputs_; }
  int size() const { return inputs_ + int(constants_.size()) + int(code_.size()); }
  int instructions() const { return int(code_.size()); }
  /// The first `prefix()` instructions depend on the inputs in `prefix_inputs` only.
  int prefix() const { return prefix_; }
  /// The instructions [0, first_part()) compute the first `first_outputs` outputs (flatten's
  /// argument): a caller that needs only those stops there.
  int first_part() const { return first_part_; }
  /// The prefix instructions still needed when the carried outputs (values another tape has
  /// computed, copied in) are in place: their indices, in order. Empty when nothing is
  /// carried.
  const std::vector<int>& carried_prefix() const { return carried_prefix_; }
  void set_carried_prefix(std::vector<int> k) { carried_prefix_ = std::move(k); }
  const std::vector<int>& outputs() const { return outputs_; }
  const std::vector<Instruction>& code() const { return code_; }
  /// Index in the work array of instruction k's result.
  int result_of(int k) const { return inputs_ + int(constants_.size()) + k; }

  /// The instructions as text, one per line ("w9 = w2 * w7"; inputs q0, q1, h are w0…w(2N),
  /// then the constants): what the tape computes, for a reader or a bug report.
  std::string listing() const {
    static const char* const names[] = {"+",   "-",   "*",   "/",   "neg",
                                        "sin", "cos", "exp", "log", "sqrt"};
    std::string s;
    for (std::size_t k = 0; k < constants_.size(); ++k)
      s += "w" + std::to_string(inputs_ + k) + " = " +
           (constants_[k].fraction
                ? std::to_string(constants_[k].num) + "/" + std::to_string(constants_[k].den)
                : std::to_string(constants_[k].value)) +
           "\n";
    const int base = inputs_ + int(constants_.size());
    for (std::size_t k = 0; k < code_.size(); ++k) {
      const Instruction& I = code_[k];
      const std::string a = "w" + std::to_string(I.a), b = "w" + std::to_string(I.b);
      const int o = int(I.op);
      s += "w" + std::to_string(base + k) + " = " +
           (o < 4 ? a + " " + names[o] + " " + b : std::string(names[o]) + "(" + a + ")") +
           (int(k) + 1 == prefix_ ? "    (end of the prefix)\n" : "\n");
    }
    s += "outputs:";
    for (int o : outputs_) s += " w" + std::to_string(o);
    return s + "\n";
  }

  /// Fill the constants of the work array `w` (size() entries) in the type S; once.
  template <class S>
  void load_constants(std::vector<S>& w) const {
    w.resize(size());
    for (std::size_t k = 0; k < constants_.size(); ++k) {
      const Constant& c = constants_[k];
      w[inputs_ + k] = c.fraction ? S(S(c.num) / S(c.den)) : S(c.value);
    }
  }
  /// Run instructions [from, to) on w (inputs and constants already in place).
  template <class S>
  void run(S* w, int from, int to) const {
    for (int k = from; k < to; ++k) execute(w, k);
  }
  /// Run the instructions listed in `k`, in that order.
  template <class S>
  void run_list(S* w, const std::vector<int>& k) const {
    for (int i : k) execute(w, i);
  }

 private:
  template <class S>
  void execute(S* w, int k) const {
    using std::cos;
    using std::exp;
    using std::log;
    using std::sin;
    using std::sqrt;
    const Instruction& I = code_[k];
    S& r = w[inputs_ + int(constants_.size()) + k];
    const S& a = w[I.a];
    switch (I.op) {
      case Op::add:
        r = a + w[I.b];
        break;
      case Op::sub:
        r = a - w[I.b];
        break;
      case Op::mul:
        r = a * w[I.b];
        break;
      case Op::div:
        r = a / w[I.b];
        break;
      case Op::neg:
        r = -a;
        break;
      case Op::sin:
        r = sin(a);
        break;
      case Op::cos:
        r = cos(a);
        break;
      case Op::exp:
        r = exp(a);
        break;
      case Op::log:  // off its domain: NaN, as the tree evaluator (no message from libqd)
        r = below_zero(a, true) ? not_a_number<S>() : S(log(a));
        break;
      case Op::sqrt:
        r = below_zero(a, false) ? not_a_number<S>() : S(sqrt(a));
        break;
    }
  }

  template <class S>
  static bool below_zero(const S& a, bool or_zero) {
    if constexpr (std::is_arithmetic_v<S>) {
      return or_zero ? !(a > 0) : !(a >= 0);
    } else {
      const double x = static_cast<double>(to_double_value(a));
      return or_zero ? !(x > 0) : !(x >= 0);
    }
  }
  template <class S>
  static double to_double_value(const S& a) {
    if constexpr (requires { to_double(a); })
      return to_double(a);
    else
      return static_cast<double>(a);
  }
  template <class S>
  static S not_a_number() {
    return S(std::numeric_limits<double>::quiet_NaN());
  }

  int inputs_ = 0;
  std::vector<Constant> constants_;
  std::vector<Instruction> code_;
  std::vector<int> outputs_;
  int prefix_ = 0, first_part_ = 0;
  std::vector<int> carried_prefix_;
};

// ---------------------------------------------------------------------------------------------
// Native code from a tape (native.cpp).
//
// A tape (tape.hpp) turned into native code: C source generated from its
// instructions, compiled once with the system's C compiler into a shared object, cached by
// the hash of the source, and loaded with dlopen. The tape stays the fallback.
//
// The generated code performs the tape's operations in the tape's order in binary64 with
// contraction of a·b + c into fused multiply–adds switched off, calling the same libm
// functions, so its results are the interpreter's to the bit (a doctest compares them).
//
// Where: `$VIBOOK_CACHE_DIR`, else `$XDG_CACHE_HOME/vibook`, else `~/.cache/vibook`, in a
// subdirectory `tapes/`. The compiler: `$VIBOOK_CC`, else `cc`. `VIBOOK_NATIVE=0` switches
// native code off. Any failure (no compiler, a cache that cannot be written, a compiler that
// does not finish in 60 s) leaves the tape in use and says why in `reason`.
// ---------------------------------------------------------------------------------------------

/// The compiled segments of the Newton tape (prefix, the prefix when values are carried over,
/// first part, rest) and of the momentum tape, each `void f(double* w)` on the tape's work
/// array.
struct NativeTapes {
  using Fn = void (*)(double*);
  Fn newton_prefix = nullptr, newton_prefix_carried = nullptr, newton_first = nullptr,
     newton_rest = nullptr, momentum = nullptr;
  std::shared_ptr<void> library;  ///< the dlopen handle (closed with the last copy)
  std::string path;               ///< the shared object
  bool loaded() const { return momentum != nullptr; }
};

/// The C source of the four segments (what is compiled; deterministic).
std::string native_source(const Tape& newton, const Tape& momentum);

/// Load the native code of the tapes, compiling it when it is not in the cache. On failure
/// the result is not loaded() and `reason` says why.
NativeTapes load_native(const Tape& newton, const Tape& momentum, std::string& reason);

/// Sizes of a compiled discrete Lagrangian, for a report.
struct CompiledStats {
  int nodes = 0;                  ///< graph nodes recorded (value and all derivatives)
  int newton_instructions = 0;    ///< instructions of the Newton tape
  int newton_prefix = 0;          ///< of which run once per step
  int newton_prefix_carried = 0;  ///< of those, still run when the carried values are copied in
  int carried = 0;                ///< values the momentum hands on to the next step's prefix
  int momentum_instructions = 0;
  int all_instructions = 0;  ///< the tape of value, D1, D2 and D2 D1 together
};

/// The three tapes of L_d (Newton part, momentum, everything) and the size of the graph they
/// came from.
///
/// Carried values: the Newton prefix of step k+1 is a function of q_(k+1) and h, and the
/// momentum tape of step k, D2 L_d(q_k, q_(k+1), h), often computes the same subexpressions of
/// q_(k+1) (for the trapezoidal rule, h/2 ∇V(q_(k+1)): the prefix needs h/2 ∇V(q_k) and the
/// momentum h/2 ∇V(q_(k+1))). Such a value is found on the graph: a prefix node with q0
/// replaced by q1 that is the same node (the same operations on the same operands, up to the
/// order of the operands of + and ·, which is exact) as one the momentum needs. The last
/// `carried` outputs of the Newton tape and of the momentum tape are these pairs; when the
/// momentum was last evaluated at (·, q0, h), the prefix copies them and runs only
/// `Tape::carried_prefix()`. The values are the same to the bit, so carrying them changes no
/// result.
struct CompiledTapes {
  Tape newton, momentum, all;
  int nodes = 0;
  int carried = 0;
};
/// Compile L_d of `dl` (call with modified::ginac_mutex() held). Throws ArgumentError("--dim")
/// outside 1…kMaxDim dimensions.
CompiledTapes compile_tapes(const TypedDiscreteLagrangian& dl);

/// A discrete Lagrangian of dimension N compiled into two tapes: the Newton part (D1 L_d and
/// D2 D1 L_d at (q0, q1, h), its q0- and h-only prefix run once per step) and the momentum
/// part (D2 L_d, once per step). Evaluated in double by DelIntegrator (which detects
/// `newton_parts`), and in any scalar S by `evaluate<S>`.
template <int N>
class CompiledDiscreteLagrangian {
 public:
  /// Compile `dl` (call with modified::ginac_mutex() held). With `native`, the Newton and
  /// momentum tapes also run as native code where a C compiler and the cache allow
  /// (load_native); `native_reason()` says why not otherwise.
  explicit CompiledDiscreteLagrangian(const TypedDiscreteLagrangian& dl, bool native = true)
      : t_(std::make_shared<const CompiledTapes>(compile_tapes(checked(dl)))) {
    t_->newton.load_constants(wn_);
    t_->momentum.load_constants(wm_);
    t_->all.load_constants(wa_);
    const Tape& T = t_->newton;
    for (int k = N; k < N + N * N; ++k) {  // is every output of D2 D1 L_d in the prefix?
      const int o = T.outputs()[k];
      if (o >= T.result_of(T.prefix()) || (o >= N && o < 2 * N)) jacobian_constant_ = false;
    }
    if (native)
      native_ = load_native(t_->newton, t_->momentum, native_reason_);
    else
      native_reason_ = "not asked for";
  }
  /// The native code is in use (else the tape is interpreted).
  bool native() const { return native_.loaded(); }
  /// D2 D1 L_d does not depend on q1: the DEL equation is affine in q_(k+1)
  /// (DelIntegrator then solves it by affine_newton_solve).
  bool jacobian_constant() const { return jacobian_constant_; }
  /// Carry values over from the last momentum to the next prefix (CompiledTapes; on by
  /// default). Off, the prefix is always computed in full: the results are the same to the
  /// bit (a doctest compares), only slower.
  void carry_over(bool on) { carry_ = on; }
  const std::string& native_reason() const { return native_reason_; }
  const std::string& native_path() const { return native_.path; }

  /// D1 L_d and D2 D1 L_d (row i = ∂(D1 L_d)_i/∂q1) at (q0, q1, h): the Newton system of
  /// p0 = −D1 L_d(q0, q1, h). The q0/h part is recomputed only when q0 or h changed; with
  /// `with_jacobian` false only D1 is computed (D12 is left as it was).
  void newton_parts(const Vec<double, N>& q0, const Vec<double, N>& q1, double h,
                    Vec<double, N>& D1, Mat<double, N>& D12, bool with_jacobian = true) const {
    const Tape& T = t_->newton;
    bool same = have_prefix_ && bits(h) == bits(wn_[2 * N]);
    for (int i = 0; i < N && same; ++i) same = bits(q0(i)) == bits(wn_[i]);
    if (!same) {
      for (int i = 0; i < N; ++i) wn_[i] = q0(i);
      wn_[2 * N] = h;
      // The momentum last evaluated at (·, q0, h) holds the carried values (CompiledTapes).
      bool carry = carry_ && t_->carried > 0 && have_momentum_ && bits(wm_[2 * N]) == bits(h);
      for (int i = 0; i < N && carry; ++i) carry = bits(wm_[N + i]) == bits(q0(i));
      if (carry) {
        const auto &from = t_->momentum.outputs(), &to = T.outputs();
        for (int k = 0; k < t_->carried; ++k) wn_[to[N + N * N + k]] = wm_[from[N + k]];
        if (native_.loaded())
          native_.newton_prefix_carried(wn_.data());
        else
          T.run_list(wn_.data(), T.carried_prefix());
      } else if (native_.loaded()) {
        native_.newton_prefix(wn_.data());
      } else {
        T.run(wn_.data(), 0, T.prefix());
      }
    }
    Eigen::Map<Vec<double, N>>(wn_.data() + N) = q1;  // one vector store: see d2
    if (native_.loaded()) {
      native_.newton_first(wn_.data());
      if (with_jacobian) native_.newton_rest(wn_.data());
    } else {
      T.run(wn_.data(), T.prefix(), with_jacobian ? T.instructions() : T.first_part());
    }
    have_prefix_ = true;
    const auto& o = T.outputs();
    Vec<double, N> d1;  // gathered in registers and stored whole: the caller adds p0 to it
    for (int i = 0; i < N; ++i) d1(i) = wn_[o[i]];
    D1 = d1;
    if (with_jacobian)
      for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j) D12(i, j) = wn_[o[N + N * i + j]];
  }
  /// D2 L_d(q0, q1, h): the momentum p1 at the end of the step.
  Vec<double, N> d2(const Vec<double, N>& q0, const Vec<double, N>& q1, double h) const {
    const Tape& T = t_->momentum;
    // Whole-vector stores: the native code loads q0 and q1 as vectors, and a load that spans
    // two scalar stores waits for them to retire instead of being forwarded.
    Eigen::Map<Vec<double, N>>(wm_.data()) = q0;
    Eigen::Map<Vec<double, N>>(wm_.data() + N) = q1;
    wm_[2 * N] = h;
    if (native_.loaded())
      native_.momentum(wm_.data());
    else
      T.run(wm_.data(), 0, T.instructions());
    have_momentum_ = true;
    Vec<double, N> r;
    for (int i = 0; i < N; ++i) r(i) = wm_[T.outputs()[i]];
    return r;
  }
  /// Value and every derivative in the scalar type S (the tape of everything).
  template <class S>
  ad::TwoPoint<N, S> evaluate(const Vec<S, N>& q0, const Vec<S, N>& q1, const S& h) const {
    const Tape& T = t_->all;
    // In double, the work array starts as a copy of wa_ (the constants loaded once, the same
    // numbers) in storage each thread keeps: no allocation and no division per evaluation
    // (RATTLE on typed constraints evaluates a tape several times a step).
    std::vector<S> local;
    std::vector<S>& w = [&]() -> std::vector<S>& {
      if constexpr (std::is_same_v<S, double>) {
        thread_local std::vector<double> scratch;
        scratch.assign(wa_.begin(), wa_.end());
        return scratch;
      } else {
        T.load_constants(local);
        return local;
      }
    }();
    for (int i = 0; i < N; ++i) {
      w[i] = q0(i);
      w[N + i] = q1(i);
    }
    w[2 * N] = h;
    T.run(w.data(), 0, T.instructions());
    const auto& o = T.outputs();
    ad::TwoPoint<N, S> r;
    r.value = w[o[0]];
    for (int i = 0; i < N; ++i) {
      r.D1(i) = w[o[1 + i]];
      r.D2(i) = w[o[1 + N + i]];
    }
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) r.D12(i, j) = w[o[1 + 2 * N + N * i + j]];
    return r;
  }
  CompiledStats stats() const {
    return {t_->nodes,
            t_->newton.instructions(),
            t_->newton.prefix(),
            t_->carried > 0 ? int(t_->newton.carried_prefix().size()) : t_->newton.prefix(),
            t_->carried,
            t_->momentum.instructions(),
            t_->all.instructions()};
  }

 private:
  static const TypedDiscreteLagrangian& checked(const TypedDiscreteLagrangian& dl) {
    if (dl.dim() != N)
      throw ArgumentError("--dim", "the expressions are " + std::to_string(dl.dim()) +
                                       "-dimensional, not " + std::to_string(N));
    return dl;
  }

  static std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

  std::shared_ptr<const CompiledTapes> t_;
  // Work arrays: a copy of the object (one per integrator) has its own; the tapes are shared.
  mutable std::vector<double> wn_, wm_;
  std::vector<double> wa_;  ///< the tape of everything's work array, its constants loaded
  mutable bool have_prefix_ = false, have_momentum_ = false;
  bool jacobian_constant_ = true, carry_ = true;
  NativeTapes native_;
  std::string native_reason_;
};

}  // namespace vibook::verify
