/// \file tableau_study.hpp
/// \brief A partitioned Runge–Kutta method read from a tableau file (integrators/prk.hpp),
/// measured on a test problem of map_study.hpp: its consistency and symplecticity conditions
/// evaluated at 120 digits from the entries as written, then the one-step map's measured
/// order, variational order (for a symplectic tableau), symplecticity, reversibility and energy.
/// `vibook verify --tableau FILE` prints the measurement.
///
/// **The file** is JSON (examples/tableaus/ has four):
///
///     { "name": "Lobatto IIIA-IIIB",
///       "source": "Hairer, Lubich & Wanner, Geometric Numerical Integration, Table II.2.2",
///       "order": 4, "symmetric": true,
///       "a":    [["0", "0", "0"], ["5/24", "1/3", "-1/24"], ["1/6", "2/3", "1/6"]],
///       "b":    ["1/6", "2/3", "1/6"],
///       "ahat": [["1/6", "-1/6", "0"], ["1/6", "1/3", "0"], ["1/6", "5/6", "0"]],
///       "bhat": ["1/6", "2/3", "1/6"] }
///
/// Entries are strings holding a decimal number or a ratio of two (read exactly), or JSON
/// numbers (read as the decimal they are printed as). `a` and `b` are required; `ahat`
/// defaults to `a` and `bhat` to `b` (a Runge–Kutta method); `c` is optional and checked
/// against the row sums of `a`; `order`, `symmetric`, `name` and `source` are optional.
///
/// **A Runge–Kutta–Nyström tableau** (integrators/rkn.hpp) has `c`, `abar`, `bbar` and `b`
/// instead of `a`, `ahat` and `bhat`: its order conditions by Nyström trees and its
/// symplecticity conditions are evaluated at 120 digits; it runs on the test problems.
///
/// Chapter: \ref chapter-verify (section "A method from its tableau").
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "vibook/integrators/composition.hpp"
#include "vibook/integrators/prk.hpp"
#include "vibook/integrators/rkn.hpp"
#include "vibook/verify/map_study.hpp"

namespace vibook::verify {

/// The largest tableau file read (1 MiB): room for about 8000 entries written to 120 digits (a
/// partitioned tableau of 60 stages); a larger file is refused, never read to its end.
constexpr std::size_t kMaxTableauBytes = std::size_t(1) << 20;

/// The largest number of stages a tableau may have.
constexpr int kMaxTableauStages = 6;

/// A tableau as read, with its conditions evaluated at 120 digits.
struct TableauSpec {
  std::string file, name, source;
  PrkTableau tableau;               ///< the entries rounded to double
  PrkTableauT<dd_real> tableau_dd;  ///< the entries rounded to double-double (the order study)
  std::optional<double> documented_order;
  bool symmetric_documented = false;
  // Residuals at 120 digits (the largest over the entries of each condition):
  double weights_residual = 0;         ///< |Σ b_i − 1| and |Σ b̂_i − 1|
  double row_sum_residual = -1;        ///< |Σ_j a_ij − c_i| where c is given (−1: not given)
  double bhat_residual = 0;            ///< |b_i − b̂_i|
  double symplectic_residual = 0;      ///< |b_i â_ij + b̂_j a_ji − b_i b̂_j|
  bool symplectic_conditions = false;  ///< both of the last two at most 1e-12
  double expected = 0;
  std::string expected_from;
  /// The entries of a and b as written in the file (a JSON number as it is printed): what the
  /// symbolic engine reads exactly (method_symbolic.hpp, derive_tableau_variational_order).
  std::vector<std::vector<std::string>> a_text;
  std::vector<std::string> b_text;
  // A Runge–Kutta–Nyström tableau (abar, bbar): then `tableau` is unused, and the residuals
  // above are those of the RKN conditions (weights: |Σ b_i − 1| and |Σ b̄_i − 1/2|; bhat:
  // |b̄_i − b_i(1 − c_i)|; symplectic: |b_i(b̄_j − ā_ij) − b_j(b̄_i − ā_ji)|).
  bool rkn = false;
  RknTableauT<double> rkn_tableau;
  RknTableauT<dd_real> rkn_tableau_dd;
  composition::OrderConditions rkn_conditions;  ///< by Nyström trees, at 1e-12
  composition::OrderConditions rkn_visible;     ///< the same at 1e-8
  RknTableauT<mpfr_real> rkn_exact;             ///< the entries at 120 digits (Theorem 10)
};

/// The orders up to which an RKN tableau's conditions are evaluated (trees of order up to 11).
constexpr int kRknConditionsOrder = 10;

/// Read and check a tableau file: ArgumentError naming --tableau for a file that cannot be
/// read, is not JSON, or whose entries are missing, of the wrong shape, not numbers, or more
/// than kMaxTableauStages stages. `expected` is set from the file's order when present.
TableauSpec read_tableau(const std::string& path);
/// The same from the file's text; `path` names it in the messages (and in TableauSpec::file).
TableauSpec parse_tableau(const std::string& content, const std::string& path);

/// Measure the method on `problem` from (q0, p0) with the settings of `study` (its step,
/// state, field, energy and expected order are set here; reversibility is required when
/// `symmetric_claimed` is set or the file says the method is symmetric); appended to `rep`.
void measure_tableau(const TableauSpec& spec, const TestProblem& problem,
                     const std::vector<double>& q0, const std::vector<double>& p0,
                     const MapStudy& study, bool symmetric_claimed, MapMeasurement& rep);

class TypedDiscreteLagrangian;  // verify/expression.hpp

/// The same measurement on the user's own system: with `general_h` false (`vibook verify
/// --tableau FILE --potential EXPR`) the method on H = |p|²/2 + V(q) with V the typed potential
/// of `sys`, the force by AutoDiff on the expression's tree; with `general_h` (`--hamiltonian
/// EXPR`) HamiltonianPrkMethod on the H typed in `sys`, any H(q, p), ∇H and its Hessian by
/// AutoDiff. 1 to 3 degrees of freedom (sys.dim()). `study` carries the system already (its
/// reference field, H and z0, from the same expression); `system_line` names it in the
/// report. std::invalid_argument for a dimension outside 1..3.
void measure_tableau_typed(const TableauSpec& spec, const TypedDiscreteLagrangian& sys,
                           const std::vector<double>& q0, const std::vector<double>& p0,
                           const MapStudy& study, const std::string& system_line,
                           bool symmetric_claimed, bool general_h, MapMeasurement& rep);

}  // namespace vibook::verify
