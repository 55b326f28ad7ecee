/// \file expression.hpp
/// \brief A discrete Lagrangian and the system it is meant for, typed as text, for `vibook
/// verify`: parsed once into a tree that keeps the structure of the text, then evaluated on
/// any scalar — double, double-double and nested AutoDiff for the integrators and the
/// reference solution, GiNaC symbols for the modified-equation engine — so that the same
/// integrator and the same engine run it as run a C++ template.
///
/// Why not GiNaC's own parser: it returns GiNaC's simplified form, whose shape (the order of
/// terms, and which sign of (q1 − q0) is kept under a square) follows hash values that change
/// from run to run; evaluated in floating point it gave different last bits in every run. The
/// tree here is the text's own: `a - b` is computed as a − b, left to right, as C++ would, and
/// two runs give the same bits.
///
/// The language (`^` is a power, binding tighter than unary minus: -x^2 = −(x²)):
/// - the discrete Lagrangian (`--ld`) in vibook's scaling L_d ≈ h·L, in the vectors `q0`,
///   `q1`, the step `h` and the step's start time `t` (L_d(t, q0, q1, h));
/// - the intended Lagrangian (`--lagrangian`) in the vectors `q` and `v`, or the intended
///   Hamiltonian (`--hamiltonian`) in `q` and `p`; by default L = |v|²/2 − V(q);
/// - the potential (`--potential`) in the coordinates `x`, `y`, `z`, or in the vector `q`;
/// - a component of a vector variable: `q0[1]`, `v[2]` (counted from 1); a vector written out:
///   `[-q[2], q[1]]`; the potential and its gradient at a vector: `V(q0)`, `grad(V)(q)`;
/// - vectors add and subtract, scale by scalars, and `u^2` is |u|² (`u^4` is |u|⁴); a product
///   of two vector factors is their dot product;
/// - functions `sin cos exp log sqrt` of scalars; `u^(1/2)`-type half-integer powers of
///   scalars;
/// - the time `t` in any of them (a time-dependent system, chapter "Verify your own
///   integrator", section "Time-dependent systems");
/// - numbers are exact: `1/6` is 1/6, and a decimal such as `0.1` is the fraction 1/10 it
///   denotes (not the binary64 number nearest to it).
///
/// The dimension is the largest of: the last of x, y, z the potential uses, the largest
/// component index, the length of a written vector, and `--dim`; at most kMaxDim.
///
/// Example (Simpson's rule on Hénon–Heiles):
/// \code
///   TypedDiscreteLagrangian dl("h*((q1-q0)^2/(2*h^2) - (V(q0)+4*V((q0+q1)/2)+V(q1))/6)",
///                              "x^2/2+y^2/2+x^2*y-y^3/3");
///   // dl.dim() == 2; dl.bind<2>() is a callable L_d(q0, q1, h) for DelIntegrator and
///   // modified::symbolic_dl.
/// \endcode
/// Every error in the text (syntax, an unknown symbol or function, a vector where a scalar is
/// needed, a dimension that does not fit) is an ArgumentError naming `--ld`, `--lagrangian`,
/// `--hamiltonian`, `--potential` or `--dim`, with one line saying what is wrong.
///
/// Chapter: \ref chapter-verify.
#pragma once

#include <ginac/ginac.h>
#include "vibook/core/autodiff.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "vibook/core/errors.hpp"
#include "vibook/core/types.hpp"
#include "vibook/mechanics/discrete_lagrangian.hpp"
#include "vibook/modified/ginac_lock.hpp"

namespace vibook::verify {

/// The exact rational a number's text denotes: "1/2", "-3", "0.25", "2.5e-1" (a decimal is the
/// decimal fraction it is: 0.3 = 3/10). Anything else, trailing characters and the empty
/// string included, is an ArgumentError naming `argument`.
GiNaC::numeric parse_rational(const std::string& text, const std::string& argument);

/// The largest dimension the typed expressions take (the numerics are instantiated for each).
inline constexpr int kMaxDim = 6;

/// The texts of a verification: the discrete Lagrangian, the potential (may be empty when
/// nothing uses V), and at most one of the intended Lagrangian and Hamiltonian (both empty:
/// L = |v|²/2 − V(q)).
struct TypedTexts {
  std::string ld, potential, lagrangian, hamiltonian;
  int dim = 0;  ///< 0: from the texts
  /// Names of symbolic parameters (`vibook modified --param k`): constants the texts may use,
  /// which stay symbols in the symbolic engine's output. They have no numeric value, so an
  /// evaluation in a numeric type throws std::logic_error (`vibook verify` takes none).
  std::vector<std::string> params{};
  /// Only the intended system, no discrete Lagrangian (`ld` empty): a black-box stepper's
  /// Hamiltonian. evaluate() and bind() are then not available.
  bool system_only = false;
  /// The caller steps time-dependent systems (the time t in any text). Without it a text that
  /// uses t is an ArgumentError naming it: a route that has not been taught the time would
  /// otherwise evaluate every text at t = 0.
  bool allow_time = false;
  /// Holonomic constraints g_i(q) = 0 (`--constraint`, repeatable), each a scalar in the
  /// potential's variables (x, y, z or the vector q) without t (chapter "Verify your own
  /// integrator", section "Constrained systems").
  std::vector<std::string> constraints{};
};

namespace detail {

/// The parsed texts of a TypedDiscreteLagrangian: its expression tree (each constant keeps
/// its exact value, a GiNaC number) and the roots of each text. Copied and destroyed under
/// modified::ginac_mutex() (GinacGuarded), so that a typed system can be built, copied into a
/// kernel and dropped beside other threads' GiNaC work (the field audit's rows in parallel).
struct TypedStorage {
  enum class Op {
    constant,
    var,        ///< a vector variable (slot)
    component,  ///< one component of a vector variable (slot, index)
    h,
    t,        ///< the time (in --ld: the step's start time)
    literal,  ///< a vector written out, [a, b, …] (items)
    add,
    sub,
    mul,
    dot,
    div,
    neg,
    power,
    func,
    potential_call,
    gradient_call,  ///< ∇V at a vector: a vector
    param           ///< a symbolic parameter (index)
  };
  enum class Fn { sin, cos, exp, log, sqrt };
  struct Node {
    Op op = Op::constant;
    bool vector = false;      ///< the node's value is a vector (of dimension dim())
    double value = 0;         ///< constant: the nearest double
    double num = 0, den = 1;  ///< constant: numerator and denominator, when both are doubles
    bool fraction = false;    ///< num/den is the exact value
    GiNaC::numeric exact;     ///< constant: the exact value
    int slot = 0;             ///< var, component: which variable
    int index = 0;            ///< component: 0-based
    int twice_exponent = 0;   ///< power: 2 × the exponent (an integer)
    Fn fn = Fn::sin;
    int a = -1, b = -1;      ///< operands
    std::vector<int> items;  ///< literal: its entries
  };
  int dim_ = 0;
  std::vector<Node> nodes_;
  std::vector<GiNaC::symbol> params_;  ///< the symbolic parameters, in the order given
  int ld_root_ = -1, potential_root_ = -1, lagrangian_root_ = -1, hamiltonian_root_ = -1;
  std::vector<int> constraint_roots_;
  std::vector<std::string> constraint_texts_;
  bool system_uses_t_ = false, ld_uses_t_ = false;
};

}  // namespace detail

class TypedDiscreteLagrangian : private modified::GinacGuarded<detail::TypedStorage> {
 public:
  /// Parse and check both texts; `dim` 0 means: from the texts (see the file comment).
  TypedDiscreteLagrangian(const std::string& ld, const std::string& potential, int dim = 0);
  /// Parse and check every text of `t`.
  explicit TypedDiscreteLagrangian(const TypedTexts& t);

  int dim() const { return dim_; }
  /// The index of a symbolic parameter (TypedTexts::params), or −1.
  int param_index(const std::string& name) const {
    for (std::size_t k = 0; k < params_.size(); ++k)
      if (params_[k].get_name() == name) return static_cast<int>(k);
    return -1;
  }
  /// The intended system is the default L = |v|²/2 − V(q).
  bool default_system() const { return lagrangian_root_ < 0 && hamiltonian_root_ < 0; }
  /// The intended system is given as a Hamiltonian (`--hamiltonian`).
  bool has_hamiltonian() const { return hamiltonian_root_ >= 0; }
  bool has_potential() const { return potential_root_ >= 0; }
  /// The intended system depends on the time t explicitly (its Lagrangian, Hamiltonian or
  /// potential uses t).
  bool time_dependent() const { return system_uses_t_; }
  /// The discrete Lagrangian uses the step's start time t.
  bool ld_uses_t() const { return ld_uses_t_; }
  /// The number of constraints typed (`--constraint`).
  int constraint_count() const { return static_cast<int>(constraint_roots_.size()); }
  /// The text of constraint i as typed.
  const std::string& constraint_text(int i) const {
    return constraint_texts_[static_cast<std::size_t>(i)];
  }
  /// Constraint i, g_i(q), on any scalar (0 <= i < constraint_count()).
  template <int N, class S>
  S constraint(int i, const Vec<S, N>& q) const {
    Inputs<S, N> in;
    for (int k = 0; k < N; ++k) in.var[kX][k] = q(k);
    return scalar<S, N, 0>(constraint_roots_[static_cast<std::size_t>(i)], in);
  }

  /// L_d(q0, q1, h) on scalars of type S (q0, q1 of dimension N == dim()).
  template <int N, class S>
  S evaluate(const Vec<S, N>& q0, const Vec<S, N>& q1, const S& h) const {
    return evaluate<N, S>(q0, q1, h, S(lift_integer<S>(0)));
  }
  /// L_d(t, q0, q1, h), t the step's start time.
  template <int N, class S>
  S evaluate(const Vec<S, N>& q0, const Vec<S, N>& q1, const S& h, const S& t) const {
    Inputs<S, N> in;
    in.t = t;
    for (int i = 0; i < N; ++i) {
      in.var[kQ0][i] = q0(i);
      in.var[kQ1][i] = q1(i);
    }
    in.h = h;
    return scalar<S, N, 0>(ld_root_, in);
  }
  /// V(q) on scalars of type S (0 when no potential was given).
  template <int N, class S>
  S potential(const Vec<S, N>& q) const {
    return potential<N, S>(q, S(lift_integer<S>(0)));
  }
  /// V(q, t).
  template <int N, class S>
  S potential(const Vec<S, N>& q, const S& t) const {
    if (potential_root_ < 0) return S(lift_integer<S>(0));
    Inputs<S, N> in;
    in.t = t;
    for (int i = 0; i < N; ++i) in.var[kX][i] = q(i);
    return scalar<S, N, 0>(potential_root_, in);
  }
  /// The intended Lagrangian L(q, v) (the default |v|²/2 − V(q) when none was typed). Not
  /// available when the system was given as a Hamiltonian (std::logic_error).
  template <int N, class S>
  S lagrangian(const Vec<S, N>& q, const Vec<S, N>& v) const {
    return lagrangian<N, S>(q, v, S(lift_integer<S>(0)));
  }
  /// L(q, v, t).
  template <int N, class S>
  S lagrangian(const Vec<S, N>& q, const Vec<S, N>& v, const S& t) const {
    if (hamiltonian_root_ >= 0)
      throw std::logic_error("TypedDiscreteLagrangian: the system is given as a Hamiltonian");
    if (lagrangian_root_ < 0) {
      S k = v(0) * v(0);
      for (int i = 1; i < N; ++i) k = k + v(i) * v(i);
      return S(k / lift_integer<S>(2) - potential<N, S>(q, t));
    }
    Inputs<S, N> in;
    in.t = t;
    for (int i = 0; i < N; ++i) {
      in.var[kQ][i] = q(i);
      in.var[kV][i] = v(i);
    }
    return scalar<S, N, 0>(lagrangian_root_, in);
  }
  /// The intended Hamiltonian H(q, p), when typed (std::logic_error otherwise).
  template <int N, class S>
  S hamiltonian(const Vec<S, N>& q, const Vec<S, N>& p) const {
    return hamiltonian<N, S>(q, p, S(lift_integer<S>(0)));
  }
  /// H(q, p, t).
  template <int N, class S>
  S hamiltonian(const Vec<S, N>& q, const Vec<S, N>& p, const S& t) const {
    if (hamiltonian_root_ < 0)
      throw std::logic_error("TypedDiscreteLagrangian: no Hamiltonian was typed");
    Inputs<S, N> in;
    in.t = t;
    for (int i = 0; i < N; ++i) {
      in.var[kQ][i] = q(i);
      in.var[kP][i] = p(i);
    }
    return scalar<S, N, 0>(hamiltonian_root_, in);
  }

  /// Hamilton's equations of the typed H at (q, p): (∂H/∂p, −∂H/∂q), the gradient by forward
  /// AutoDiff on scalars of type T (double-double for the reference solution).
  template <int N, class T>
  Vec<T, 2 * N> hamilton_field(const Vec<T, N>& q, const Vec<T, N>& p, const T& t = T(0.0)) const {
    using D = ad::Dual<2 * N, T>;
    Vec<D, N> Q, P;
    for (int i = 0; i < N; ++i) {
      Q(i) = D(q(i), 2 * N, i);
      P(i) = D(p(i), 2 * N, N + i);
    }
    const Vec<T, 2 * N> g = hamiltonian<N, D>(Q, P, D(t)).derivatives();
    Vec<T, 2 * N> r;
    for (int i = 0; i < N; ++i) {
      r(i) = g(N + i);
      r(N + i) = -g(i);
    }
    return r;
  }

  /// A callable `L_d(q0, q1, h)` for DelIntegrator<N> and modified::symbolic_dl<N>. The object
  /// must outlive it. Throws ArgumentError("--dim") if N != dim().
  template <int N>
  auto bind() const {
    if (ld_root_ < 0) throw std::logic_error("TypedDiscreteLagrangian: no --ld was given");
    if (N != dim_)
      throw ArgumentError("--dim", "the expressions are " + std::to_string(dim_) +
                                       "-dimensional, not " + std::to_string(N));
    return [this](const auto& q0, const auto& q1, const auto& h) -> scalar_t<decltype(h)> {
      using S = scalar_t<decltype(h)>;
      return this->evaluate<N, S>(Vec<S, N>(q0), Vec<S, N>(q1), S(h));
    };
  }

 private:
  // Vector variables: the slots of Inputs::var.
  static constexpr int kQ0 = 0, kQ1 = 1, kQ = 2, kV = 3, kP = 4, kX = 5, kVars = 6;
  template <class S, int N>
  struct Inputs {
    std::array<std::array<S, N>, kVars> var{};
    S h{};
    S t{};
  };
  class Parser;
  friend class Parser;

  int add_node(Node n) {
    nodes_.push_back(std::move(n));
    return static_cast<int>(nodes_.size()) - 1;
  }

  // A constant in the scalar type S: exact for GiNaC (also under AutoDiff), num/den in any
  // other type (the correctly rounded quotient in double, and more digits in double-double).
  template <class S>
  static S lift(const Node& n) {
    if constexpr (std::is_same_v<S, GiNaC::ex>) {
      return GiNaC::ex(n.exact);
    } else if constexpr (requires { typename S::DerType; }) {
      return S(lift<typename S::Scalar>(n));
    } else {
      if (n.fraction) return S(S(n.num) / S(n.den));
      return S(n.value);
    }
  }
  // A symbolic parameter: its GiNaC symbol (a constant under AutoDiff); no numeric value.
  template <class S>
  S param_value(int k) const {
    if constexpr (std::is_same_v<S, GiNaC::ex>) {
      return GiNaC::ex(params_[static_cast<std::size_t>(k)]);
    } else if constexpr (requires { typename S::DerType; }) {
      return S(param_value<typename S::Scalar>(k));
    } else {
      throw std::logic_error("TypedDiscreteLagrangian: the symbolic parameter " +
                             params_[static_cast<std::size_t>(k)].get_name() +
                             " has no numeric value");
    }
  }
  template <class S>
  static S lift_integer(int k) {
    if constexpr (std::is_same_v<S, GiNaC::ex>) {
      return GiNaC::ex(k);
    } else if constexpr (requires { typename S::DerType; }) {
      return S(lift_integer<typename S::Scalar>(k));
    } else {
      return S(double(k));
    }
  }

  template <class S>
  static S int_power(const S& b, int k) {
    S r = b;
    for (int i = 1; i < k; ++i) r = r * b;
    return r;
  }

  // The number a scalar of any of the evaluation types stands for (the value under AutoDiff
  // layers), to keep sqrt and log off their domain's edge: double-double's own sqrt and log
  // print to stderr on a negative argument, so the evaluator returns NaN itself (a step that
  // meets it fails as non-finite, with its place).
  template <class S>
  static double probe(const S& x) {
    if constexpr (std::is_same_v<S, GiNaC::ex>)
      return 1;
    else if constexpr (std::is_arithmetic_v<S>)
      return static_cast<double>(x);
    else if constexpr (requires { x.value(); })
      return probe(x.value());
    else if constexpr (requires { to_double(x); })
      return to_double(x);
    else
      return 1;
  }
  template <class S>
  static S not_a_number(const S& a) {
    if constexpr (requires { typename S::DerType; })
      return S(not_a_number(a.value()));  // the value NaN, no derivatives
    else
      return S(std::numeric_limits<double>::quiet_NaN());
  }

  template <class S>
  static S apply(Fn fn, const S& a) {
    using std::cos;
    using std::exp;
    using std::log;
    using std::sin;
    using std::sqrt;
    switch (fn) {
      case Fn::sin:
        return sin(a);
      case Fn::cos:
        return cos(a);
      case Fn::exp:
        return exp(a);
      case Fn::log:
        if (!(probe(a) > 0)) return not_a_number(a);
        return log(a);
      case Fn::sqrt:
        if (!(probe(a) >= 0)) return not_a_number(a);
        return sqrt(a);
    }
    return a;
  }

  template <class S, int N>
  static S dot_product(const std::array<S, N>& u, const std::array<S, N>& w) {
    S d = u[0] * w[0];
    for (int j = 1; j < N; ++j) d = d + u[j] * w[j];
    return d;
  }

  // Depth counts the gradients being taken: ∇V is the potential evaluated on one more level of
  // forward AutoDiff, and the potential itself cannot contain V (so one level is enough).
  template <class S, int N, int Depth>
  S scalar(int i, const Inputs<S, N>& in) const {
    const Node& n = nodes_[i];
    switch (n.op) {
      case Op::constant:
        return lift<S>(n);
      case Op::h:
        return in.h;
      case Op::t:
        return in.t;
      case Op::param:
        return param_value<S>(n.index);
      case Op::component:
        return in.var[n.slot][n.index];
      case Op::add:
        return scalar<S, N, Depth>(n.a, in) + scalar<S, N, Depth>(n.b, in);
      case Op::sub:
        return scalar<S, N, Depth>(n.a, in) - scalar<S, N, Depth>(n.b, in);
      case Op::mul:
        return scalar<S, N, Depth>(n.a, in) * scalar<S, N, Depth>(n.b, in);
      case Op::dot:
        return dot_product<S, N>(vec<S, N, Depth>(n.a, in), vec<S, N, Depth>(n.b, in));
      case Op::div:
        return scalar<S, N, Depth>(n.a, in) / scalar<S, N, Depth>(n.b, in);
      case Op::neg:
        return -scalar<S, N, Depth>(n.a, in);
      case Op::power: {
        const int k2 = n.twice_exponent;
        if (nodes_[n.a].vector) {  // |u|^(k2/2), k2/2 even and positive
          const std::array<S, N> u = vec<S, N, Depth>(n.a, in);
          return int_power(dot_product<S, N>(u, u), k2 / 4);
        }
        const S b = scalar<S, N, Depth>(n.a, in);
        if constexpr (std::is_same_v<S, GiNaC::ex>) {
          return GiNaC::pow(b, GiNaC::numeric(k2, 2));
        } else {
          using std::sqrt;
          const int m = k2 < 0 ? -k2 : k2;
          // b^(m/2) = b^(m div 2) · sqrt(b)^(m mod 2)
          S r = m / 2 > 0 ? int_power(b, m / 2) : lift_integer<S>(1);
          if (m % 2 && !(probe(b) >= 0)) return not_a_number(b);
          if (m % 2) r = m / 2 > 0 ? S(r * sqrt(b)) : S(sqrt(b));
          return k2 < 0 ? S(lift_integer<S>(1) / r) : r;
        }
      }
      case Op::func:
        return apply<S>(n.fn, scalar<S, N, Depth>(n.a, in));
      case Op::potential_call: {
        Inputs<S, N> at;
        at.var[kX] = vec<S, N, Depth>(n.a, in);
        at.t = in.t;
        return scalar<S, N, Depth>(potential_root_, at);
      }
      default:
        break;
    }
    throw std::logic_error("TypedDiscreteLagrangian: vector node evaluated as a scalar");
  }

  template <class S, int N, int Depth>
  std::array<S, N> vec(int i, const Inputs<S, N>& in) const {
    const Node& n = nodes_[i];
    switch (n.op) {
      case Op::var:
        return in.var[n.slot];
      case Op::literal: {
        std::array<S, N> r;
        for (int j = 0; j < N; ++j) r[j] = scalar<S, N, Depth>(n.items[j], in);
        return r;
      }
      case Op::add:
      case Op::sub: {
        std::array<S, N> r = vec<S, N, Depth>(n.a, in);
        const std::array<S, N> w = vec<S, N, Depth>(n.b, in);
        for (int j = 0; j < N; ++j) r[j] = n.op == Op::add ? S(r[j] + w[j]) : S(r[j] - w[j]);
        return r;
      }
      case Op::mul: {  // one operand a vector, the other a scalar
        const bool left = nodes_[n.a].vector;
        std::array<S, N> r = vec<S, N, Depth>(left ? n.a : n.b, in);
        const S f = scalar<S, N, Depth>(left ? n.b : n.a, in);
        for (int j = 0; j < N; ++j) r[j] = left ? S(r[j] * f) : S(f * r[j]);
        return r;
      }
      case Op::div: {
        std::array<S, N> r = vec<S, N, Depth>(n.a, in);
        const S f = scalar<S, N, Depth>(n.b, in);
        for (int j = 0; j < N; ++j) r[j] = r[j] / f;
        return r;
      }
      case Op::neg: {
        std::array<S, N> r = vec<S, N, Depth>(n.a, in);
        for (int j = 0; j < N; ++j) r[j] = -r[j];
        return r;
      }
      case Op::gradient_call:
        // A scalar that records a tape (tape.cpp) takes the gradient itself, symbolically.
        // One more level of AutoDiff over S needs S(1) from an int, which nested AutoDiff over
        // a class type (double-double) cannot give: ∇V is then not available in S.
        if constexpr (requires { S::records_a_tape; }) {
          const std::array<S, N> u = vec<S, N, Depth>(n.a, in);
          return S::template gradient<N>(u, [&](const std::array<S, N>& x) {
            Inputs<S, N> at;
            at.var[kX] = x;
            at.t = in.t;
            return scalar<S, N, 1>(potential_root_, at);
          });
        } else if constexpr (Depth == 0 && std::is_constructible_v<S, int>) {
          // ∇V(u): V on one level of forward AutoDiff over S, seeded at u.
          using A = Eigen::AutoDiffScalar<Eigen::Matrix<S, N, 1>>;
          const std::array<S, N> u = vec<S, N, Depth>(n.a, in);
          Inputs<A, N> at;
          at.t = A(in.t);
          for (int j = 0; j < N; ++j) {
            Eigen::Matrix<S, N, 1> seed;
            for (int k = 0; k < N; ++k) seed(k) = lift_integer<S>(k == j ? 1 : 0);
            at.var[kX][j] = A(u[j], seed);
          }
          const A value = scalar<A, N, 1>(potential_root_, at);
          std::array<S, N> g;
          for (int j = 0; j < N; ++j) g[j] = value.derivatives()(j);
          return g;
        } else {
          throw std::domain_error(
              "grad(V) cannot be evaluated in this scalar type (nested AutoDiff over "
              "double-double): write the gradient out");
        }
      default:
        break;
    }
    throw std::logic_error("TypedDiscreteLagrangian: scalar node evaluated as a vector");
  }

  void finish(const TypedTexts& t);
  void finish_pass(const TypedTexts& t, bool scalar_vars);
};

}  // namespace vibook::verify
