/// \file expression.hpp
/// \brief A discrete Lagrangian typed as text, for `vibook verify`: parsed once into a tree
/// that keeps the structure of the text, then evaluated on any scalar — double and nested
/// AutoDiff for the generic solver, GiNaC symbols for the modified-equation engine — so that
/// the same integrator and the same engine run it as run a C++ template.
///
/// Why not GiNaC's own parser: it returns GiNaC's simplified form, whose shape (the order of
/// terms, and which sign of (q1 − q0) is kept under a square) follows hash values that change
/// from run to run; evaluated in floating point it gave different last bits in every run. The
/// tree here is the text's own: `a - b` is computed as a − b, left to right, as C++ would, and
/// two runs give the same bits.
///
/// The language (`^` is a power, binding tighter than unary minus: -x^2 = −(x²)):
/// - the discrete Lagrangian (`--ld`) in vibook's scaling L_d ≈ h·L, in the vectors `q0`,
///   `q1`, the step `h`, and the potential `V(·)` applied to a vector expression;
/// - the potential (`--potential`) in the coordinates `x`, `y`, `z` (dimension 1, 2, 3: the
///   last one used, or `--dim`);
/// - vectors add and subtract, scale by scalars, and `u^2` is |u|² (`u^4` is |u|⁴); a product
///   of two vector factors is their dot product;
/// - functions `sin cos exp log sqrt` of scalars; `u^(1/2)`-type half-integer powers of
///   scalars;
/// - numbers are exact: `1/6` is 1/6, and a decimal such as `0.1` is the fraction 1/10 it
///   denotes (not the binary64 number nearest to it).
///
/// Example (Simpson's rule on Hénon–Heiles):
/// \code
///   TypedDiscreteLagrangian dl("h*((q1-q0)^2/(2*h^2) - (V(q0)+4*V((q0+q1)/2)+V(q1))/6)",
///                              "x^2/2+y^2/2+x^2*y-y^3/3");
///   // dl.dim() == 2; dl.bind<2>() is a callable L_d(q0, q1, h) for DelIntegrator and
///   // modified::symbolic_dl.
/// \endcode
/// Every error in the text (syntax, an unknown symbol or function, a vector where a scalar is
/// needed, a dimension that does not fit) is an ArgumentError naming `--ld`, `--potential` or
/// `--dim`, with one line saying what is wrong.
///
/// Chapter: \ref chapter-verify.
#pragma once

#include <ginac/ginac.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "vibook/core/errors.hpp"
#include "vibook/core/types.hpp"
#include "vibook/mechanics/discrete_lagrangian.hpp"

namespace vibook::verify {

/// The exact rational a number's text denotes: "1/2", "-3", "0.25", "2.5e-1" (a decimal is the
/// decimal fraction it is: 0.3 = 3/10). Anything else, trailing characters and the empty
/// string included, is an ArgumentError naming `argument`.
GiNaC::numeric parse_rational(const std::string& text, const std::string& argument);

class TypedDiscreteLagrangian {
 public:
  /// Parse and check both texts; `dim` 0 means: the last of x, y, z the potential uses.
  TypedDiscreteLagrangian(const std::string& ld, const std::string& potential, int dim = 0);

  int dim() const { return dim_; }

  /// L_d(q0, q1, h) on scalars of type S (q0, q1 of dimension N == dim()).
  template <int N, class S>
  S evaluate(const Vec<S, N>& q0, const Vec<S, N>& q1, const S& h) const {
    Inputs<S, N> in;
    for (int i = 0; i < N; ++i) {
      in.q0[i] = q0(i);
      in.q1[i] = q1(i);
    }
    in.h = h;
    return scalar<S, N>(ld_root_, in);
  }

  /// V(q) on scalars of type S.
  template <int N, class S>
  S potential(const Vec<S, N>& q) const {
    Inputs<S, N> in;
    for (int i = 0; i < N; ++i) in.x[i] = q(i);
    return scalar<S, N>(potential_root_, in);
  }

  /// A callable `L_d(q0, q1, h)` for DelIntegrator<N> and modified::symbolic_dl<N>. The object
  /// must outlive it. Throws ArgumentError("--dim") if N != dim().
  template <int N>
  auto bind() const {
    if (N != dim_)
      throw ArgumentError("--dim", "the expressions are " + std::to_string(dim_) +
                                       "-dimensional, not " + std::to_string(N));
    return [this](const auto& q0, const auto& q1, const auto& h) -> scalar_t<decltype(h)> {
      using S = scalar_t<decltype(h)>;
      return this->evaluate<N, S>(Vec<S, N>(q0), Vec<S, N>(q1), S(h));
    };
  }

 private:
  enum class Op {
    constant,
    q0,
    q1,
    h,
    coordinate,
    add,
    sub,
    mul,
    dot,
    div,
    neg,
    power,
    func,
    potential_call
  };
  enum class Fn { sin, cos, exp, log, sqrt };
  struct Node {
    Op op = Op::constant;
    bool vector = false;     ///< the node's value is a vector (of dimension dim())
    double value = 0;        ///< constant: the nearest double
    GiNaC::numeric exact;    ///< constant: the exact value
    int index = 0;           ///< coordinate: 0, 1, 2 for x, y, z
    int twice_exponent = 0;  ///< power: 2 × the exponent (an integer)
    Fn fn = Fn::sin;
    int a = -1, b = -1;  ///< operands
  };
  template <class S, int N>
  struct Inputs {
    std::array<S, N> q0{}, q1{}, x{};
    S h{};
  };
  class Parser;
  friend class Parser;
  int add_node(Node n) {
    nodes_.push_back(std::move(n));
    return static_cast<int>(nodes_.size()) - 1;
  }

  template <class S>
  static S from_constant(const Node& n) {
    if constexpr (std::is_same_v<S, GiNaC::ex>)
      return GiNaC::ex(n.exact);
    else
      return constant<S>(n.value);
  }

  template <class S>
  static S one() {
    if constexpr (std::is_same_v<S, GiNaC::ex>)
      return GiNaC::ex(1);
    else
      return constant<S>(1.0);
  }

  template <class S>
  static S int_power(const S& b, int k) {
    S r = b;
    for (int i = 1; i < k; ++i) r = r * b;
    return r;
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
        return log(a);
      case Fn::sqrt:
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

  template <class S, int N>
  S scalar(int i, const Inputs<S, N>& in) const {
    const Node& n = nodes_[i];
    switch (n.op) {
      case Op::constant:
        return from_constant<S>(n);
      case Op::h:
        return in.h;
      case Op::coordinate:
        return in.x[n.index];
      case Op::add:
        return scalar<S, N>(n.a, in) + scalar<S, N>(n.b, in);
      case Op::sub:
        return scalar<S, N>(n.a, in) - scalar<S, N>(n.b, in);
      case Op::mul:
        return scalar<S, N>(n.a, in) * scalar<S, N>(n.b, in);
      case Op::dot:
        return dot_product<S, N>(vec<S, N>(n.a, in), vec<S, N>(n.b, in));
      case Op::div:
        return scalar<S, N>(n.a, in) / scalar<S, N>(n.b, in);
      case Op::neg:
        return -scalar<S, N>(n.a, in);
      case Op::power: {
        const int k2 = n.twice_exponent;
        if (nodes_[n.a].vector) {  // |u|^(k2/2), k2/2 even and positive
          const std::array<S, N> u = vec<S, N>(n.a, in);
          return int_power(dot_product<S, N>(u, u), k2 / 4);
        }
        const S b = scalar<S, N>(n.a, in);
        if constexpr (std::is_same_v<S, GiNaC::ex>) {
          return GiNaC::pow(b, GiNaC::numeric(k2, 2));
        } else {
          using std::sqrt;
          const int m = k2 < 0 ? -k2 : k2;
          // b^(m/2) = b^(m div 2) · sqrt(b)^(m mod 2)
          S r = m / 2 > 0 ? int_power(b, m / 2) : one<S>();
          if (m % 2) r = m / 2 > 0 ? S(r * sqrt(b)) : S(sqrt(b));
          return k2 < 0 ? S(one<S>() / r) : r;
        }
      }
      case Op::func:
        return apply<S>(n.fn, scalar<S, N>(n.a, in));
      case Op::potential_call: {
        Inputs<S, N> at;
        at.x = vec<S, N>(n.a, in);
        return scalar<S, N>(potential_root_, at);
      }
      case Op::q0:
      case Op::q1:
        break;
    }
    throw std::logic_error("TypedDiscreteLagrangian: vector node evaluated as a scalar");
  }

  template <class S, int N>
  std::array<S, N> vec(int i, const Inputs<S, N>& in) const {
    const Node& n = nodes_[i];
    switch (n.op) {
      case Op::q0:
        return in.q0;
      case Op::q1:
        return in.q1;
      case Op::add:
      case Op::sub: {
        std::array<S, N> r = vec<S, N>(n.a, in);
        const std::array<S, N> w = vec<S, N>(n.b, in);
        for (int j = 0; j < N; ++j) r[j] = n.op == Op::add ? S(r[j] + w[j]) : S(r[j] - w[j]);
        return r;
      }
      case Op::mul: {  // one operand a vector, the other a scalar
        const bool left = nodes_[n.a].vector;
        std::array<S, N> r = vec<S, N>(left ? n.a : n.b, in);
        const S f = scalar<S, N>(left ? n.b : n.a, in);
        for (int j = 0; j < N; ++j) r[j] = left ? S(r[j] * f) : S(f * r[j]);
        return r;
      }
      case Op::div: {
        std::array<S, N> r = vec<S, N>(n.a, in);
        const S f = scalar<S, N>(n.b, in);
        for (int j = 0; j < N; ++j) r[j] = r[j] / f;
        return r;
      }
      case Op::neg: {
        std::array<S, N> r = vec<S, N>(n.a, in);
        for (int j = 0; j < N; ++j) r[j] = -r[j];
        return r;
      }
      default:
        break;
    }
    throw std::logic_error("TypedDiscreteLagrangian: scalar node evaluated as a vector");
  }

  int dim_ = 0;
  std::vector<Node> nodes_;
  int ld_root_ = -1, potential_root_ = -1;
};

}  // namespace vibook::verify
