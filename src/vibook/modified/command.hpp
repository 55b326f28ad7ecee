/// \file command.hpp
/// \brief `vibook modified` as a library call: the modified equation, Lagrangian, Hamiltonian,
/// first-order vector field, meshed or discrete Lagrangian of a method (Vermeeren 2017 §3–5,
/// Shen & Sun 2025 §4), printed as the command prints it.
///
/// The command parses and checks its options into a Derivation and prints what derive()
/// returns; a C++ user gets the same document. Chapter: \ref chapter-modified.
#pragma once

#include <optional>
#include <string>

#include "vibook/modified/canonical.hpp"
#include "vibook/modified/engine.hpp"
#include "vibook/verify/expression.hpp"

namespace vibook::modified {

/// One derivation: a method of the library on a named potential, or a typed discrete
/// Lagrangian, or a method of the library on a typed continuous Lagrangian.
struct Derivation {
  Method method = Method::sv;
  Potential potential = Potential::generic;
  int dim = 1;    ///< degrees of freedom (1 to 3)
  int order = 2;  ///< the highest power of h, 0 to max_order
  /// equation, lagrangian, hamiltonian, vector-field, meshed or disc
  std::string what = "equation";
  Format format = Format::text;
  std::optional<GiNaC::numeric> alpha;  ///< the split φ^[1] = αU of vi1, vi1-adjoint, vi2
  bool cross_check = false;             ///< equation: the direct route must agree term by term
  bool reference = false;               ///< the engine's slow reference path
  bool components = false;              ///< latex: component by component, not in vector notation
  /// A typed discrete Lagrangian, or (typed_lagrangian) a typed continuous one that `method`
  /// discretizes; nullptr: the library's method on `potential`. Must outlive the call.
  const verify::TypedDiscreteLagrangian* typed = nullptr;
  bool typed_lagrangian = false;
  std::string description;  ///< what the typed text is, for the header line
};

/// The derivation, printed (the header comment, then each series by powers of h). A
/// disagreement of the cross-check is a NumericalError; an unknown `what` an ArgumentError
/// naming --what. Takes ginac_mutex() for its duration.
std::string derive(const Derivation& d);

}  // namespace vibook::modified
