/// \file compare.hpp
/// \brief A printed display compared with what vibook computes, and, where they differ, the
/// smallest change of the printed LaTeX that makes them agree.
///
/// A check names the paper and quotes the LaTeX it compares, verbatim (the quote must occur in
/// one display of the paper file, or the comparison fails). The reader (latex.hpp) turns the
/// quote into expressions with the check's notation; each is expanded in the step size by the
/// engine's series arithmetic and compared coefficient by coefficient with the target (the
/// engine's result, or an exact expression), below the display's own remainder
/// `\\mathcal{O}(h^k)`. Several *cases* (the same display read under several settings, such as
/// Theorem 10 for four Nyström tableaux) must all agree.
///
/// **Correction search.** When the display does not agree (or means nothing as printed), the
/// search tries, in order of size, every edit of one of these kinds and keeps the first that
/// makes every case agree:
///  1. one term multiplied by a rational λ, λ solved for (a wrong sign, a wrong factor, a
///     missing weight; λ = 0: a term too many);
///  2. one subscript digit changed (x_1 → x_2), one accent changed (ẋ ↔ ẍ), one prime added or
///     removed, one integer in a superscript changed by ±1;
///  3. two subscript digits swapped throughout one symbol (every ẋ_1 ↔ ẋ_2);
///  4. one argument of an argument list deleted; the two entries of a pair swapped;
///  5. two accented forms of one letter exchanged throughout (b̂ ↔ b̄), or the variable of a
///     derivative changed (d/dt → d/da);
///  6. two edits together, when no single edit works: two sign reversals, a sign reversal and
///     a change of kind 2, or two changes of kind 2 (the same slip in two components); at
///     most 600 pairs in all.
/// A factor λ may contain the notation's parameters (h, c): a term multiplied by h or by
/// c^-2 is a correction of its kind. If nothing is found and the check states a correction of
/// its own (Spec::proposed), that one is read and compared in the same way.
/// The outcome says which edits were tried and how many candidates were read, so that "no
/// correction found" is a statement about a described search.
///
/// Chapter: \ref formulas.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "vibook/claims/ledger.hpp"
#include "vibook/printed/notation.hpp"
#include "vibook/printed/papers.hpp"

namespace vibook::printed {

/// What a display is compared with, component by component: coefficients of h^0, h^1, …
/// (a series), or exact expressions.
struct Target {
  std::vector<std::vector<ex>> series;  ///< series[i][k]: component i, coefficient of h^k
  std::vector<ex> exact;                ///< exact[i], when `series` is empty
  int through = -1;  ///< highest power of h compared (−1: every coefficient given)
  /// Applied to both sides before they are compared (an identity that holds on solutions:
  /// ẍ replaced by the equation of motion).
  std::function<ex(const ex&)> reduce;

  /// A scalar series Σ c[k] h^k.
  static Target scalar_series(const std::vector<ex>& c, int through = -1);
  /// The engine's vector series f[k][i] (h^k, component i).
  static Target vector_series(const std::vector<std::vector<ex>>& f, int through = -1);
  static Target exactly(const std::vector<ex>& components);
  static Target exactly(const ex& scalar);

  /// How our side is shown: `shown[i]` in abbreviations (a midpoint, a difference; the
  /// derivatives of an abstract field) that `where` maps back to the target's symbols, printed
  /// followed by `where_latex`. The comparison uses the target alone; the display is checked
  /// equal to it, and std::logic_error says which component is not: `exact[i]` once `where` is
  /// substituted, or for a series each coefficient of h^k compared (k up to `through`), the
  /// shown form then a polynomial in `h`, printed by powers of h.
  std::vector<ex> shown;
  GiNaC::exmap where;
  std::string where_latex;
  ex shown_h;  ///< the h of a shown series
  Target& shown_as(std::vector<ex> display, GiNaC::exmap abbreviations, std::string latex,
                   const ex& h = ex(0));

  /// How our side is shown in the paper's own notation, as LaTeX (a vector equation in
  /// matrices, ẍ = M⁻¹(…)): the text is read with `notation`, as the paper's displays are, and
  /// must equal the target, component by component (for a series, each coefficient of h^k
  /// compared, and no power beyond them); std::logic_error says which component is not. The
  /// LaTeX is then our side as printed (a series followed by its O(h^k)).
  std::string shown_latex;
  Target& shown_read(std::string latex, const Notation& notation);
};

/// One setting in which the display is read and what it must equal there.
struct Case {
  const JetNotation* notation = nullptr;
  Target target;
  std::string name;  ///< "RKN4", when there are several
};

struct Spec {
  Paper paper = Paper::S;
  std::string quote;  ///< verbatim LaTeX from the paper
  /// The display's id ("L809", "(22)") when the quote occurs in several displays; empty: the
  /// one display that contains it.
  std::string display;
  static constexpr std::size_t kLast = std::numeric_limits<std::size_t>::max();
  /// Which members of A = B = C are compared with the target (each must agree); empty: the
  /// last. kLast stands for the last.
  std::vector<std::size_t> members;
  /// Compare the first two members' difference A − B with the target (an equation).
  bool equation = false;
  std::string part;     ///< "the right-hand side", "the h² term"
  std::string against;  ///< what the target is
  std::string check;    ///< the check's id
  bool search = true;   ///< search for a correction when it does not agree
  /// A correction derived by the check (LaTeX), tried when the search finds none: where the
  /// fix is larger than the search's edits, the check states it and the reader verifies it.
  std::string proposed;
  std::string proposed_edit;  ///< the proposed correction in words
  /// Try `proposed` before the search: the check knows the natural reading of the slip (two
  /// slips a referee would name, where the search's smallest edit is one factor that merges
  /// them). It must still read and compare equal, or the search runs as usual.
  bool prefer_proposed = false;
  /// "cross-check": shown beside the display's deciding comparison, decides nothing.
  std::string role;
  /// How our side is verified independently of this comparison (a measured order, a second
  /// route). When no small correction is found, our formula is then the correction.
  std::string verified;
};

/// Compare, and search for a correction when needed. Never throws for the display's sake:
/// a quote that is not in the paper is an "unreadable" outcome naming the problem.
claims::FormulaComparison compare(const Spec& spec, const std::vector<Case>& cases);

/// Abstract function calls (and their derivatives) at the jet point x replaced by the engine's
/// derivative symbols (U_1, phi1_12, …); calls anywhere else are left as they are.
ex at_jet_point(const ex& e, const modified::JetSpace& J);

/// True if the comparison's outcome is "agrees".
inline bool agrees(const claims::FormulaComparison& c) { return c.outcome == "agrees"; }

/// Erratum IDs for displays whose ID is older than the rule `<paper>-ERR-<number>` (or
/// `-L<line>` for an unnumbered display): display id → erratum id.
using ErratumNames = std::vector<std::pair<std::string, std::string>>;

/// The erratum ID of a display: "S-ERR-39", "SS-ERR-4.30", "V-ERR-L288", or its old name.
std::string erratum_id(const claims::FormulaComparison& c, const ErratumNames& names = {});

/// Conclude a claim from its comparisons (attached to it): every one agrees → the status the
/// check set stands; each one that does not agree becomes an erratum result (appended to
/// `errata`) and the claim gets cause "misprint" and status `erratum` when all of them have a
/// correction (or `not-reproduced`, cause "does-not-hold", when one has none); an unreadable
/// comparison makes the claim `not-reproduced` with the reader's message (that is our
/// limitation, and it must not pass as agreement).
void conclude(claims::ClaimResult& claim, std::vector<claims::FormulaComparison> comparisons,
              std::vector<claims::ClaimResult>& errata, const ErratumNames& names = {});

/// An erratum claim for a comparison that does not agree: status `erratum` when a correction
/// was found (the note gives the printed and the corrected LaTeX and the edit), `not-reproduced`
/// otherwise (the note describes the search). The comparison is attached to it.
claims::ClaimResult erratum_for(const claims::FormulaComparison& c, const std::string& id,
                                const std::string& title, const std::string& context = {});

}  // namespace vibook::printed
