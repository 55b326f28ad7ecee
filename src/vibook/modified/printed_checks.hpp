/// \file printed_checks.hpp
/// \brief Internal to the checks of modified/: the printed displays of the three papers read
/// from their LaTeX (printed/) and compared with the engine. Each function returns the claims
/// it measured, with their comparisons attached, and appends the errata it found.
///
/// Chapter: \ref formulas.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "vibook/claims/ledger.hpp"
#include "vibook/modified/engine.hpp"
#include "vibook/printed/compare.hpp"

namespace vibook::checks::printed_detail {

using modified::ex;
using printed::Case;
using printed::JetNotation;
using printed::Paper;
using printed::Spec;
using printed::Target;
using printed::Value;

/// Σ c[k] h^k.
ex series_sum(const std::vector<ex>& c, const GiNaC::symbol& h, int through = -1);

/// The `source` of every claim these checks write (the check `vibook claims --check` names).
inline constexpr const char* kCheck = "check-modified";

/// A claim of these checks, `reproduced` until a comparison finds otherwise.
claims::ClaimResult claim(const std::string& id, const std::string& note);

/// Appends `text` to the note of the erratum `id` among `errata`, when the comparisons found
/// it (the independent evidence of a misprint, named where the erratum is written).
void add_evidence(std::vector<claims::ClaimResult>& errata, const std::string& id,
                  const std::string& text);

/// The Taylor coefficients of a curve shifted by `step` times the step size:
/// c[k] = step^k / k! · x^{(k)} of degree of freedom `dof`, for k = 0 … K (x(t + step·h) =
/// Σ c[k] h^k). The displays that expand x(t ± h) or x(a ± Δa/2) are compared with these.
std::vector<ex> shifted_taylor(const modified::JetSpace& J, int dof, const GiNaC::numeric& step,
                               int K);

/// The comparisons of one check, collected as they are made.
struct Compared {
  std::string check;
  std::vector<claims::FormulaComparison> list;
  /// Compare `quote` (verbatim from paper p) with the target, read with notation n.
  void operator()(Paper p, const std::string& quote, const std::string& part,
                  const std::string& against, const JetNotation& n, const Target& t,
                  std::vector<std::size_t> members = {}, bool equation = false,
                  const std::string& role = {});
  /// The same with a fully specified Spec (check and paper filled in here).
  void spec(Spec s, const std::vector<Case>& cases);
  /// Move the collected comparisons out.
  std::vector<claims::FormulaComparison> take();
};

/// On solutions of the modified equation: ẍ (of the degrees of freedom `dofs`) and its
/// derivatives replaced by Σ_{k≤K} h^k f_k and its total derivatives, truncated after h^K.
std::function<ex(const ex&)> on_shell(const modified::JetSpace& J, std::vector<int> dofs,
                                      const std::vector<std::vector<ex>>& f, int K);

/// A notation over an engine's jet space of one curve `x` (all degrees of freedom), with
/// the engine's Lagrangians as callables: `\\mathcal{L}_{\\text{disc}}([x],h)` (and `mesh`,
/// `mod,k`) stand for the engine's L_disc, L_mesh and L_mod,k (Vermeeren's names).
JetNotation engine_notation(modified::Engine& E, const std::string& curve = "x");

// Vermeeren 2017, Example 1 and the Legendre maps (5) (printed_vermeeren.cpp): the
// comparisons for the claim V-EX1 (check-v-ex1 concludes it). Call with ginac_mutex() held.
std::vector<claims::FormulaComparison> vermeeren_example1(const std::string& check);
// Vermeeren 2017 (printed_vermeeren.cpp).
std::vector<claims::ClaimResult> vermeeren_prints(std::vector<claims::ClaimResult>& errata);
// Shen & Sun 2025, §4 and Appendix A (printed_shen_sun.cpp).
std::vector<claims::ClaimResult> shen_sun_prints(std::vector<claims::ClaimResult>& errata);
/// Shen & Sun's (4.24), read from the paper (with A_1, A_2 read from the display after it), for
/// the Kepler potential U = −1/|x| split as φ^[1] = αU, φ^[2] = (1 − α)U, over the jet space J:
/// the coefficients f[k][i] of h⁰…h² (printed_shen_sun.cpp). ReadError if it cannot be read.
std::vector<std::vector<ex>> shen_sun_424_kepler(std::shared_ptr<const modified::JetSpace> J,
                                                 const ex& alpha);
/// Shen & Sun's relativistic Kepler (printed_shen_sun.cpp): the Lagrangian stated below (2.7)
/// and (2.7) itself, against the Lagrangian whose Euler–Lagrange equation is (2.7); the
/// two-step equations of Theorem 8 against the discrete Euler–Lagrange equations of the
/// library's discrete_lagrangian_320 (c = 5 and c = 3). With `trajectory` ((t, x₁, x₂) of
/// consecutive steps at speed of light `c`, step `h`), `route` receives the largest residual
/// of each Theorem 8 equation as printed and, where corrected, as corrected, evaluated along it in
/// binary64, in units of 4ε·max|y|/h² (the rounding of the row's variable y = t or x_i in a second
/// difference). Call with ginac_mutex() held.
std::vector<claims::FormulaComparison> shen_sun_relativistic_prints(
    const std::string& check, const std::vector<std::array<double, 3>>* trajectory = nullptr,
    double c = 5, double h = 0.05, std::vector<std::pair<std::string, double>>* route = nullptr);
// Sharma et al. 2022, §4.3–4.4 (printed_sharma.cpp).
std::vector<claims::ClaimResult> sharma_prints(std::vector<claims::ClaimResult>& errata);
/// Sharma et al. 2022's displays in discrete variables, read from the paper and compared with
/// the library's own templates evaluated on GiNaC symbols (printed_sharma.cpp): `group` is
/// "del" ((13)–(18), against the extended midpoint L_d and vibook's sign convention; check
/// `check`), "eq39" ((24), (25), (39)–(41)) or "monitors" ((26), (27), against AVI's
/// monitor functions). Call with ginac_mutex() held. For "eq39", `numeric` (when given)
/// receives a second route: each of (39)–(41) as the comparison left it (corrected where it was
/// corrected) evaluated in binary64 at 1000 random points against the AutoDiff derivatives the
/// extended integrator steps with (maximum relative deviations).
std::vector<claims::FormulaComparison> sharma_discrete_prints(
    const std::string& group, const std::string& check,
    std::vector<std::pair<std::string, double>>* numeric = nullptr);

}  // namespace vibook::checks::printed_detail
