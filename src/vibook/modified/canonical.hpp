/// \file canonical.hpp
/// \brief Run-to-run reproducible printing and evaluation order of engine expressions.
///
/// GiNaC keeps the operands of a sum or a product sorted by hash values. Those hashes mix in
/// the addresses of type descriptors inside libginac (which move with address-space
/// randomisation) and the serial numbers of symbols (which follow the order in which threads
/// created them). Printed as GiNaC orders them, the same expression comes out with its terms
/// in a different order from one run to the next, and a numerical evaluation that sums the
/// terms in GiNaC's order gives results that differ in the last bits.
///
/// Here every sum and product is ordered by a key that depends only on the expression:
/// the printed monomial (without its numerical coefficient), then the coefficient. The same
/// expression prints the same way in every run, and `canonical_operands` gives the
/// evaluation order for compiled.hpp.
///
/// Chapter: \ref chapter-modified.
#pragma once

#include <string>
#include <vector>

#include "vibook/modified/jets.hpp"

namespace vibook::modified {

/// Output formats of `vibook modified` and of the engine's notes.
enum class Format { text, latex, python };

/// The expression in the given format with every sum and product in canonical order.
/// text: GiNaC's syntax (`-1/12*U_11*v1^2`), parsed back by GiNaC to the same expression;
/// python: SymPy source (`Rational(-1, 12)*U_11*v1**2`); latex: for MathJax, a symbol made
/// without a TeX name written with its subscript (`q0` as \f$q_{0}\f$, `q_k1` as
/// \f$q_{k+1}\f$, `qm_1` as \f$q_{m,1}\f$, `q0_1` as \f$q_{0,1}\f$).
std::string canonical_string(const ex& e, Format f = Format::text);

/// The names the abstract functions' families print with in LaTeX on this thread, while an
/// instance lives (a comparison with a paper sets the paper's letters: U, V, φ): an abstract call
/// then prints as `U\left(x\right)`; without a name, as `F_{k}\left(x\right)` (k its family),
/// never as the engine's internal function name.
class AbstractNames {
 public:
  explicit AbstractNames(std::vector<std::string> tex);
  ~AbstractNames();
  AbstractNames(const AbstractNames&) = delete;
  AbstractNames& operator=(const AbstractNames&) = delete;

 private:
  std::vector<std::string> tex_;
  const std::vector<std::string>* previous_;
};

/// The operands of a sum or product in canonical order (any other expression: its operands in
/// GiNaC's order, which for those is fixed by position).
std::vector<ex> canonical_operands(const ex& e);

}  // namespace vibook::modified
