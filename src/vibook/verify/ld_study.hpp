// The study of a typed discrete Lagrangian (`vibook verify --ld`), in the library: consistency
// of its leading term, order against an independent reference (the continuous equations by GBS
// extrapolation in double-double), the variational order from the engine, symplecticity,
// symmetry and reversibility judged by scaling (phases.hpp, the criteria of every route), the
// energy of the intended system, the adaptive EpAVI run, work-precision and the modified
// equation, Lagrangian and Hamiltonian. One report model (text, JSON, the HTML page), the same
// the command prints; a C++ user gets it from run_ld_study.
//
// The study itself is compiled once. What depends on the dimension (the DEL solver on the tape
// or the expression tree, the reference's field in double-double, the symbolic L_d, the EpAVI
// steps) sits behind LdKernel, instantiated once per dimension 1..kMaxDim (ld_kernel_N.cpp).
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "vibook/core/errors.hpp"
#include "vibook/modified/canonical.hpp"
#include "vibook/modified/engine.hpp"
#include "vibook/verify/adaptive.hpp"
#include "vibook/verify/expression.hpp"
#include "vibook/verify/phases.hpp"
#include "vibook/verify/verify.hpp"

namespace vibook::verify {

/// The exit statuses of `vibook verify` (README): 0 passed, 1 another failure (e.g. gnuplot
/// missing), 2 bad argument, 3 numerical failure, 4 an output not written, 5 a verdict failed.
enum LdStatus : int {
  kLdOk = 0,
  kLdFailure = 1,
  kLdBadArgument = 2,
  kLdNumerical = 3,
  kLdIo = 4,
  kLdVerdict = 5
};

/// What the study measures, checked by the caller (the command checks its options into it).
struct LdSettings {
  int dim = 0;
  std::vector<double> q0, p0;  ///< the initial state (p0 the canonical momentum)
  /// The order study's step sizes (--h-list); empty, the walk of every route (study_order)
  std::vector<double> hs;
  double t_end = 0;             ///< T of the order study
  double expected = 0;          ///< the expected order
  double order_tol = 0;         ///< |fitted − expected| < order_tol
  double h = 0;                 ///< the step of the energy run and the scaling tests
  std::optional<double> floor;  ///< the order fit's error floor (default from the reference)
  long long steps = 0;          ///< steps of the energy run
  int modified_order = 0;       ///< terms of the modified equation
  modified::Format format = modified::Format::text;
  bool adaptive_epavi = false;  ///< run L_d as an EpAVI too
  long long adaptive_steps = 0;
  bool symmetric = false;       ///< the method is claimed symmetric (part of the verdict)
  bool work_precision = false;  ///< run beside Störmer–Verlet and the midpoint rule (the page)
  bool reference_evaluation = false;  ///< step by nested AutoDiff, not the compiled tape
  bool timings = false;  ///< each phase's seconds in the text and the page (not reproducible)
  /// The texts the report names the inputs by.
  std::string ld_text, potential_text, lagrangian_text, hamiltonian_text;
};

/// One part of the study: its status and, when it failed, why.
struct LdPhase {
  std::string name;
  std::string status = "not run";  ///< "ok", "failed", "skipped", "not run"
  std::string reason;
  int exit = kLdOk;  ///< the exit status its failure asks for
  double seconds = 0;
};

/// The step sizes of the work-precision runs when no --h-list is given.
inline const std::vector<double> kWorkPrecisionSteps = {0.2, 0.1, 0.05, 0.025, 0.0125};

/// The result of the reference phase the kernel computes.
struct LdReference {
  Eigen::VectorXd z;  ///< (q, p) at T
  double error = 0;   ///< its estimated error
  long long macro_steps = 0, evaluations = 0;
  /// --adaptive epavi: the positions q(h) and q(h/2), the adaptive runs' start-up steps
  std::array<Eigen::VectorXd, 2> q_start;
};

/// The dimension-dependent operations of one typed discrete Lagrangian.
class LdKernel {
 public:
  virtual ~LdKernel() = default;
  virtual int dim() const = 0;
  /// How the method is evaluated: the report's line and the JSON's word.
  virtual std::string evaluation() const = 0;
  virtual std::string evaluation_kind() const = 0;
  /// One step of the DEL map on z = (q, p), warm-started from the last step.
  virtual SolveReport step(Eigen::VectorXd& z, double h) = 0;
  virtual void reset() = 0;
  /// The largest frequency of V at q (unit mass), 0 when there is none or it fails.
  virtual double largest_frequency(const std::vector<double>& q) const = 0;
  /// L_d at (qa, qb, h): value, D1, D2 and the mixed derivative D1 D2.
  struct TwoPoint {
    double value = 0;
    Eigen::VectorXd D1, D2;
    Eigen::MatrixXd D12;
    double det = 0;  ///< det D1 D2 L_d (in the dimension's own arithmetic)
  };
  virtual TwoPoint two_point(const Eigen::VectorXd& qa, const Eigen::VectorXd& qb,
                             double h) const = 0;
  /// L_d(x, x + h v, h) and L(x, v) on GiNaC expressions.
  virtual modified::ex ld_symbolic(const std::vector<modified::ex>& x,
                                   const std::vector<modified::ex>& xh,
                                   const modified::ex& h) const = 0;
  virtual modified::ex lagrangian_symbolic(const std::vector<modified::ex>& x,
                                           const std::vector<modified::ex>& v) const = 0;
  /// H at y = (q, p) with its gradient.
  virtual double hamiltonian_gradient(const Eigen::VectorXd& y, Eigen::VectorXd& g) const = 0;
  virtual double hamiltonian(const Eigen::VectorXd& q, const Eigen::VectorXd& p) const = 0;
  virtual double lagrangian(const Eigen::VectorXd& q, const Eigen::VectorXd& v) const = 0;
  /// The intended energy at z = (q, p): H as typed, |p|²/2 + V, or L's Legendre transform.
  virtual double energy(const Eigen::VectorXd& z) const = 0;
  /// The continuous equations of the intended system in double-double from (q0, p0) to T.
  virtual LdReference reference(const LdSettings& s) const = 0;
  /// The engine's discrete Lagrangian on jets.
  virtual modified::SymbolicDL symbolic(std::shared_ptr<modified::JetSpace> jets) const = 0;
  /// L_d as an EpAVI from z0 with the first step to q1 (Sharma et al. 2022 §2.2).
  virtual AdaptiveStudy epavi(const Eigen::VectorXd& z0, const Eigen::VectorXd& q1, double h0,
                              long long steps) const = 0;
  /// Störmer–Verlet and the midpoint rule of the intended L, for work-precision.
  virtual std::vector<NamedStep> classical_steppers() = 0;
};

/// The kernel of `dl` in its dimension (1..kMaxDim); `dl` must outlive it.
std::unique_ptr<LdKernel> make_ld_kernel(const TypedDiscreteLagrangian& dl,
                                         bool reference_evaluation);

namespace detail {
/// LdKernel for dimension N, one translation unit per dimension (ld_kernel_N.cpp).
template <int N>
std::unique_ptr<LdKernel> make_ld_kernel_n(const TypedDiscreteLagrangian& dl,
                                           bool reference_evaluation);
#define VIBOOK_LD_KERNEL(N)                                                                     \
  extern template std::unique_ptr<LdKernel> make_ld_kernel_n<N>(const TypedDiscreteLagrangian&, \
                                                                bool);
VIBOOK_LD_KERNEL(1)
VIBOOK_LD_KERNEL(2)
VIBOOK_LD_KERNEL(3)
VIBOOK_LD_KERNEL(4)
VIBOOK_LD_KERNEL(5)
VIBOOK_LD_KERNEL(6)
#undef VIBOOK_LD_KERNEL
static_assert(kMaxDim == 6, "make_ld_kernel_n is instantiated for the dimensions 1..kMaxDim");
}  // namespace detail

/// The report model of one study.
struct LdStudy {
  std::string text;   ///< the text report, as `vibook verify` prints it
  nlohmann::json js;  ///< every number (the schema of --json-out)
  std::vector<LdPhase> phases;
  int status = kLdOk;      ///< the exit status: 0, 1, 2, 3 or 5
  std::string error_line;  ///< the one line for stderr when it did not pass ("" if none)
  std::vector<std::string> failed_checks;
  // For the page: the data behind its figure and tables.
  std::vector<double> order_error, order_h;  ///< the order study's errors at its step sizes
  PlateauFit fit;
  bool order_passed = false;
  double ref_error = 0;
  bool consistent = false, system_reversible = true;
  int var_k = 0;  ///< the variational order was checked through h^(var_k + 1)
  EnergyBehaviour energy;
  EnergyVerdict energy_verdict;
  AdaptiveStudy adaptive;
  EnergyVerdict adaptive_verdict;
  long long newton_steps = 0, newton_iterations = 0;
  int newton_max_iterations = 0;
  double newton_max_residual = 0;
  bool have_work_precision = false;
  WorkPrecision wp;
  std::vector<std::vector<std::string>> modified_terms;
  std::vector<std::string> modified_lagrangian, modified_hamiltonian;
  std::string lagrangian_error, hamiltonian_error;
};

/// Run every phase on the typed discrete Lagrangian `dl` under the checked settings `s`.
/// Failures are recorded in the phases, with their statuses, never thrown.
LdStudy run_ld_study(const TypedDiscreteLagrangian& dl, const LdSettings& s);

/// The report page: index.html (the book's stylesheet), verify.json, the figure and its data,
/// filled beside `final_dir` and renamed onto it. `command_line` is shown on the page. Returns
/// "" or why the figure was not drawn; throws IoError/ArgumentError on a failed write.
std::string write_ld_report(const LdStudy& study, const LdSettings& s,
                            const std::string& command_line,
                            const std::filesystem::path& final_dir);

}  // namespace vibook::verify
