/// \file field_audit.hpp
/// \brief The field audit: every published composition of the catalogue
/// (integrators/composition.hpp) measured as `vibook verify --composition` measures it
/// (composition_study.hpp) on two nonlinear problems, Kepler (eccentricity 0.5) and Hénon–Heiles,
/// each row a claim of the ledger with the method's source as its "paper" (key `A`). Beside
/// them, compositions that are wrong on purpose, whose claim is that the audit flags them: an
/// audit that passes a known defect, or fails a correct method, certifies nothing.
///
/// Chapter: \ref chapter-verify (section "The audit").
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "vibook/claims/ledger.hpp"

namespace vibook::verify {

/// One row of the audit.
struct AuditEntry {
  claims::ClaimInfo info;    ///< ID `A-…`, paper "A", where = the source, title
  std::string statement;     ///< what the source documents (or what a correct audit must do)
  std::string method;        ///< a Galerkin method "gauss:S" or "lobatto:S" (then base is empty)
  std::string base;          ///< a composition's base method (composition_bases())
  std::string coefficients;  ///< a catalogue name or an exact list, as `--coefficients` takes it
  /// A splitting (`--splitting`): a catalogue name or its flows "drift:c1,kick:d1,...", or
  /// empty. Then base and coefficients are empty.
  std::string splitting;
  /// A Boost.Odeint stepper of examples/black_box/odeint_steppers.cpp, reached through the C
  /// ABI (its METHOD; the module gets METHOD/PROBLEM), or empty.
  std::string stepper;
  bool symmetric_claimed = false;  ///< for a stepper: its documentation says symmetric
  /// For a stepper row whose claimed order is what a header's Doxygen brief says: the header
  /// (under the Boost include directory) and the class; the order is read from the brief's
  /// ordinal ("of sixth order") when the check runs.
  std::string brief_header, brief_class;
  std::optional<double> expected;  ///< the order a wrong row claims (catalogue rows: documented)
  /// Empty for a published method; for a wrong one, the parts its verdict must fail on every
  /// problem ("order conditions", "order").
  std::vector<std::string> must_flag;
  /// The problems it is measured on; empty: audit_problems() (Kepler and Hénon–Heiles).
  std::vector<std::string> problems;
  /// A constrained method ("rattle", or the wrong "shake") on the constrained test problems
  /// (constrained.hpp), or empty.
  std::string constrained;
  /// A row on the forced systems (forced_problems(), section "Time-dependent systems"): with
  /// `method` a Galerkin method on the typed L(q, v, t), with `tableau_json` a tableau on
  /// V(q, t), with `stepper` a C library of ABI version 2, with `splitting` a splitting of
  /// V(q, t); otherwise the midpoint rule as a typed L_d(t, q0, q1, h) with the forcing at the
  /// time `forced_time` ("t+h/2", or the wrong "t").
  bool forced = false;
  /// A forced row's partitioned Runge–Kutta tableau, as the JSON of a `--tableau` file (the audit
  /// reads no files), or empty.
  std::string tableau_json;
  std::string forced_time;
};

/// The two forced systems of the audit: the forced oscillator L = v²/2 − q²/2 + q cos t and the
/// forced pendulum L = v²/2 + cos q + q cos(t)/2, from q0 = 0.5, p0 = 0.
const std::vector<std::string>& forced_problems();

/// The rows, in the book's order: the catalogue's compositions, the wrong ones, Boost.Odeint's
/// steppers through the C ABI (with two wrong ones), the splittings of the catalogue (with three
/// wrong ones), then the Galerkin methods (measured by the long study field-audit-galerkin),
/// then the new kinds of system (long study field-audit-systems): RATTLE and its wrong variant
/// on the constrained problems, and methods of two families on the forced systems.
const std::vector<AuditEntry>& audit_entries();

/// The two problems of the audit.
const std::vector<std::string>& audit_problems();

/// Measure one row on both problems and judge it by the criterion fixed in the chapter: a
/// published method is `reproduced` when every part of the command's verdict passes on both
/// problems; a wrong one is `reproduced` (flagged) when its verdict fails every part of
/// `must_flag` on both. Otherwise `not-reproduced`, with a headline naming what failed or what
/// was missed, and the cause `pre-asymptotic` when only the order failed and on each problem
/// where it did the local slope between the two smallest fitted step sizes lies within the
/// tolerance of the documented order (the fit's window is still above the asymptotic range),
/// `does-not-hold` otherwise.
claims::ClaimResult judge_audit_entry(const AuditEntry& a);

}  // namespace vibook::verify
