/// \file vector_notation.hpp
/// \brief Engine expressions of an abstract potential in N ≥ 2 degrees of freedom, written
/// the way Shen & Sun (2025, §4, (4.14)–(4.24)) write theirs: in the invariants ∇φ·ẋ, |∇φ|²,
/// φ_xx⟨ẋ, ẋ⟩, φ_xx∇φ, φ_xxx⟨ẋ, ẋ⟩, …, with φ = φ^[1] + φ^[2] + … the whole potential when
/// it is split into pieces, and what no invariant accounts for left in components.
///
/// The engine's results are polynomials in the component symbols (φ^[1]_12 ẋ1 ẋ2, …); side by
/// side with a paper's display they cannot be compared by eye. The grouping is a change of
/// basis, made exactly:
///   1. the last piece is written as the whole minus the others (φ^[2]_I = φ_I − φ^[1]_I), so
///      the expression is a polynomial in the derivatives of φ, of φ^[1], …, φ^[N−1] and the
///      velocities;
///   2. each invariant of a fixed list (φ's first, then those that involve a piece) is taken
///      with the coefficient that most of its terms carry, if that is more than half of them,
///      and subtracted;
///   3. what is left is printed in components; the result is checked to add up to the input
///      (std::logic_error otherwise), and each coefficient of h^k ≥ 1 is written over the
///      common factor of its numbers, as the paper writes h²/24 (…).
///
/// Example (VI-1 (3.3), 2-D, through h²; Shen & Sun (4.21)):
/// \code
///   Engine E(make_discrete_lagrangian(Method::vi1, Potential::generic, 2), 2);
///   const auto L = E.l_mod();
///   auto v = VectorNotation::of(E.jets(), L);  // set: the pieces phi1, phi2
///   v->scalar_series(L);
///   // \frac{|\dot{x}|^{2}}{2} - {\phi} - \frac{h}{2}\Bigl(\nabla\phi\cdot\dot{x}
///   //   - 2 {\phi^{[1]}_{2}} \dot{x}_{2}\Bigr) + \frac{h^{2}}{24}\Bigl(|\nabla\phi|^{2}
///   //   - 2 \phi_{xx}\langle\dot{x},\dot{x}\rangle + 12 {\phi^{[1]}_{12}} \dot{x}_{1}
///   \dot{x}_{2}\Bigr) + …
/// \endcode
///
/// Chapter: \ref chapter-modified.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "vibook/modified/jets.hpp"

namespace vibook::modified {

class VectorNotation {
 public:
  /// The notation for the expressions `exprs` of J: set when J has N ≥ 2 degrees of freedom,
  /// the expressions hold derivatives of one abstract function of all N coordinates (U), or
  /// of two or more pieces phi1, phi2, … of all of them, and nothing else abstract.
  static std::optional<VectorNotation> of(const JetSpace& J, const std::vector<ex>& exprs);

  /// A scalar series c[k] (the coefficient of h^k) in LaTeX, as format_series writes it but
  /// for the parenthesis around h⁰'s terms, which the papers do not write.
  std::string scalar_series(const std::vector<ex>& c) const;
  /// A vector series field[k][i] (component i of the coefficient of h^k) in LaTeX.
  std::string vector_series(const std::vector<std::vector<ex>>& field) const;
  /// One scalar, or one vector, without powers of h.
  std::string scalar(const ex& e) const;
  std::string vector(const std::vector<ex>& v) const;

  /// One coefficient, grouped: the invariants used (LaTeX, coefficient) in the list's order,
  /// and the rest (one entry for a scalar, N for a vector) in the derivatives of the whole
  /// φ and of the pieces but the last.
  struct Grouped {
    std::vector<std::pair<std::string, ex>> terms;
    std::vector<ex> rest;
  };
  Grouped group(const std::vector<ex>& e, bool vector) const;

 private:
  struct Invariant {
    std::string tex;
    std::vector<ex> comp;  // one (scalar) or N (vector) expanded polynomials
  };
  const JetSpace* J_ = nullptr;
  int n_ = 0;
  std::vector<int> pieces_;  // the families of the pieces (empty: one function, whole_)
  int whole_ = -1;           // the one family, when there are no pieces
  std::string whole_tex_;    // "\phi" or the family's LaTeX
  std::vector<std::string> velocity_tex_;
  std::vector<std::vector<ex>> velocity_;
  mutable std::map<std::vector<int>, GiNaC::symbol> whole_symbols_;

  ex whole(std::vector<int> index) const;
  ex piece(std::size_t k, std::vector<int> index) const;  // k < pieces_.size() − 1
  ex to_internal(const ex& e) const;
  ex to_external(const ex& e) const;
  std::vector<Invariant> invariants(bool vector) const;
  std::string coefficient(const std::vector<ex>& e, bool vector, int k) const;
};

}  // namespace vibook::modified
