/// \file constrained_typed.cpp
/// \brief Constraints typed after --constraint on a typed potential, stepped by RATTLE or by
/// the constrained discrete Euler–Lagrange equations of a typed --ld, measured by the map study
/// (constrained.hpp; chapter "Verify your own integrator", section "Constrained systems").
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "vibook/modified/engine.hpp"
#include "vibook/verify/composition_study.hpp"
#include "vibook/verify/constrained.hpp"
#include "vibook/verify/constrained_impl.hpp"
#include "vibook/verify/tape.hpp"
#include "vibook/verify/typed_system.hpp"

namespace vibook::verify {

namespace {

using namespace constrained_detail;

// A function f(q) of the positions typed as text, compiled into a tape through the discrete
// Lagrangian L_d(q0, q1, h) = V((q0 + q1)/2) with V = f (tape.hpp): at q0 = q1 = q its D1 is
// ∇f(q)/2 and its D2 D1 is ∇²f(q)/4, exactly (scalings by powers of 2, and (q + q)/2 = q), in
// any scalar. The tape differentiates the text once, symbolically; the expression tree on nested
// AutoDiff in double-double would cost the compiler half a minute per dimension.
template <int N>
class PointTape {
 public:
  explicit PointTape(const std::string& text) {
    TypedTexts t;
    t.ld = "V((q0+q1)/2)";
    t.potential = text;
    t.dim = N;
    const TypedDiscreteLagrangian dl(t);
    tape_ = std::make_shared<const CompiledDiscreteLagrangian<N>>(dl, false);
  }
  template <class T>
  void at(const Vec<T, N>& q, T& value, Vec<T, N>& gradient, Mat<T, N>* hessian) const {
    const ad::TwoPoint<N, T> r = tape_->template evaluate<T>(q, q, T(1.0));
    value = r.value;
    for (int i = 0; i < N; ++i) gradient(i) = T(2.0) * r.D1(i);
    if (hessian)
      for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j) (*hessian)(i, j) = T(4.0) * r.D12(i, j);
  }

 private:
  std::shared_ptr<const CompiledDiscreteLagrangian<N>> tape_;
};

// The typed system as a constrained problem: V from --potential (0 when none) and the m
// constraints of --constraint, each a PointTape (made with modified::ginac_mutex() held).
template <int N_>
struct TypedConstrained {
  static constexpr int N = N_, M = Eigen::Dynamic;
  std::shared_ptr<const PointTape<N>> potential;  ///< null: V = 0
  std::vector<std::shared_ptr<const PointTape<N>>> constraints;

  TypedConstrained(const TypedDiscreteLagrangian& s, const std::string& potential_text) {
    std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
    if (!potential_text.empty()) potential = std::make_shared<const PointTape<N>>(potential_text);
    for (int i = 0; i < s.constraint_count(); ++i)
      constraints.push_back(std::make_shared<const PointTape<N>>(s.constraint_text(i)));
  }
  int m() const { return static_cast<int>(constraints.size()); }
  double energy_potential(const Vec<double, N>& q) const {
    if (!potential) return 0.0;
    double value = 0;
    Vec<double, N> gradient;
    potential->template at<double>(q, value, gradient, nullptr);  // V((q + q)/2) = V(q)
    return value;
  }
  template <class T>
  void derivatives(const Vec<T, N>& q, Vec<T, N>& gradV, Eigen::Matrix<T, M, N>& G,
                   Vec<T, M>* g = nullptr) const {
    T value;
    if (potential)
      potential->template at<T>(q, value, gradV, nullptr);
    else
      gradV.setZero();
    G.resize(m(), N);
    if (g) g->resize(m());
    for (int i = 0; i < m(); ++i) {
      Vec<T, N> row;
      constraints[static_cast<std::size_t>(i)]->template at<T>(q, value, row, nullptr);
      G.row(i) = row.transpose();
      if (g) (*g)(i) = value;
    }
  }
  template <class T>
  Mat<T, N> hessian(const Vec<T, N>& q, int i) const {
    T value;
    Vec<T, N> gradient;
    Mat<T, N> H;
    constraints[static_cast<std::size_t>(i)]->template at<T>(q, value, gradient, &H);
    return H;
  }
};

template <int N>
Step rattle_map(const TypedConstrained<N>& prob, bool project) {
  return naming_failures(
      [prob, project](Eigen::VectorXd& z, double h) { rattle_step(prob, project, z, h); }, N);
}

std::string constraints_text(const TypedDiscreteLagrangian& sys) {
  std::string s;
  for (int i = 0; i < sys.constraint_count(); ++i)
    s += fmt::format("{}g{} = {}", i ? ", " : "", i + 1, sys.constraint_text(i));
  return s;
}

// The report's "system" line and the JSON's "system" of a typed constrained system; `given`
// says where V and the constraints came from.
std::string system_line(const TypedDiscreteLagrangian& sys, const std::string& potential,
                        const std::vector<double>& q0, const std::vector<double>& p0,
                        const std::string& given = "--potential") {
  return fmt::format(
      "H = |p|^2/2 + V(q), V = {} ({}), constraints {}; {} positions; q0 = {}, p0 = {}",
      potential.empty() ? "0" : potential, given, constraints_text(sys), sys.dim(), vec_text(q0),
      vec_text(p0));
}
nlohmann::json system_json(const TypedDiscreteLagrangian& sys, const std::string& potential,
                           const std::vector<double>& q0, const std::vector<double>& p0) {
  std::vector<std::string> gs;
  for (int i = 0; i < sys.constraint_count(); ++i) gs.push_back(sys.constraint_text(i));
  return {{"potential", potential}, {"constraints", gs}, {"q0", q0}, {"p0", p0}};
}

template <int N>
void measure_n(const TypedDiscreteLagrangian& sys, const ConstrainedTexts& texts,
               ConstrainedStep kind, const std::vector<double>& q0, const std::vector<double>& p0,
               MapStudy s, MapMeasurement& rep) {
  const TypedConstrained<N> prob(sys, texts.potential);
  set_constrained_system(prob, "of the --constraint equations", q0, p0, s);
  const char* name = kind == ConstrainedStep::rattle  ? "rattle"
                     : kind == ConstrainedStep::shake ? "shake"
                                                      : "constrained DEL of --ld";
  if (kind == ConstrainedStep::del) {
    // L_d's derivatives from its compiled tape, interpreted (tape.hpp): the tape keeps the
    // last q0 and h, so each step has its own copy.
    // L_d's derivatives from its compiled tape, interpreted (tape.hpp); one tape for the study's
    // steps, which run one after another (it keeps the last q0 and h, and recomputes what
    // depends on them when they change).
    std::shared_ptr<CompiledDiscreteLagrangian<N>> ld;
    {
      std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
      ld = std::make_shared<CompiledDiscreteLagrangian<N>>(sys, false);
    }
    s.step = naming_failures(
        [prob, ld](Eigen::VectorXd& z, double h) { constrained_del_step(prob, *ld, z, h); }, N);
    rep.line("discrete Lagrangian", fmt::format("L_d(q0, q1, h) = {} (--ld)", texts.ld));
    rep.line(
        "",
        "stepped by its constrained discrete Euler-Lagrange equations (Marsden & West "
        "3.5): p0 + D1 L_d + G(q0)^T lambda = 0, g(q1) = 0, p1 = D2 L_d - G(q1)^T mu "
        "with G(q1) p1 = 0; Newton on (q1, h lambda), L_d's derivatives from its compiled tape");
  } else {
    const bool project = kind == ConstrainedStep::rattle;
    s.step = rattle_map(prob, project);
    s.symmetric_claimed = true;
    s.symmetric_note = "";
    rep.line("method", project ? "rattle: RATTLE (Andersen 1983; HLW VII.1.4), symplectic, "
                                 "symmetric, order 2"
                               : "shake: RATTLE without the velocity projection (deliberately "
                                 "wrong); documented as RATTLE, order 2");
  }
  rep.line("expected order", fmt::format("{:g}", s.expected));
  rep.line("system", system_line(sys, texts.potential, q0, p0));
  rep.js["method"] = {{"name", name}, {"expected", s.expected}};
  rep.js["system"] = system_json(sys, texts.potential, q0, p0);
  if (kind == ConstrainedStep::del) rep.js["system"]["ld"] = texts.ld;
  measure_map(s, rep);
  rep.line("variational order",
           "not measured: the constrained discrete Lagrangian's exact side is not implemented");
}

// The counts and the time, checked before any work (ArgumentErrors).
void check_constrained(const TypedDiscreteLagrangian& sys) {
  const int n = sys.dim(), m = sys.constraint_count();
  if (m < 1) throw ArgumentError("--constraint", "is required: no constraint was given");
  if (n < 2 || m >= n || n > kMaxConstrainedDim)
    throw ArgumentError(
        "--constraint",
        fmt::format("{} constraint{} on {} position{}: a constrained system takes "
                    "2 to {} positions and fewer constraints than positions",
                    m, m == 1 ? "" : "s", n, n == 1 ? "" : "s", kMaxConstrainedDim));
  if (sys.ld_uses_t())
    throw ArgumentError("--ld",
                        "uses the time t: constrained time-dependent systems are not "
                        "implemented");
  if (sys.time_dependent())
    throw ArgumentError("--potential",
                        "uses the time t: constrained time-dependent systems are "
                        "not implemented");
}

}  // namespace

void measure_constrained_typed(const TypedDiscreteLagrangian& sys, const ConstrainedTexts& texts,
                               ConstrainedStep step, const std::vector<double>& q0,
                               const std::vector<double>& p0, MapStudy study, MapMeasurement& rep) {
  check_constrained(sys);
  with_dim(sys.dim(), [&](auto dim) {
    constexpr int N = decltype(dim)::value;
    if constexpr (N >= 2 && N <= kMaxConstrainedDim)
      measure_n<N>(sys, texts, step, q0, p0, std::move(study), rep);
  });
}

void set_constrained_typed_system(MapStudy& study, const TypedDiscreteLagrangian& sys,
                                  const std::string& potential, const std::vector<double>& q0,
                                  const std::vector<double>& p0, const std::string& where) {
  check_constrained(sys);
  with_dim(sys.dim(), [&](auto dim) {
    constexpr int N = decltype(dim)::value;
    if constexpr (N >= 2 && N <= kMaxConstrainedDim)
      set_constrained_system(TypedConstrained<N>(sys, potential), where, q0, p0, study);
  });
}

// --- compositions of RATTLE (book chapter "Verify your own integrator", section "Compositions of
// RATTLE"; Reich 1996) ----------------------------------------------------------------------------
void measure_constrained_composition(const CompositionSpec& spec,
                                     const TypedDiscreteLagrangian& sys,
                                     const std::string& potential, const std::vector<double>& q0,
                                     const std::vector<double>& p0, MapStudy study,
                                     MapMeasurement& rep, const std::string& given) {
  check_constrained(sys);
  with_dim(sys.dim(), [&](auto dim) {
    constexpr int N = decltype(dim)::value;
    if constexpr (N >= 2 && N <= kMaxConstrainedDim) {
      const TypedConstrained<N> prob(sys, potential);
      set_constrained_system(prob, "of the --constraint equations", q0, p0, study);
      static const CompositionBase base{
          "rattle", true,
          "RATTLE (Andersen 1983; HLW VII.1.4) on the typed constrained system: symmetric, so "
          "its own adjoint, order 2"};
      CompositionSpec composed = spec;
      composed.base = &base;
      // Each stage a whole RATTLE step of γ_i h: every stage ends on T*Q. The stages' values
      // are no discrete Lagrangian the study measures (variational = false).
      const CompositionStage stage = [prob](Eigen::VectorXd& z, double h) {
        rattle_step(prob, true, z, h);
        return std::numeric_limits<double>::quiet_NaN();
      };
      rep.js["system"] = system_json(sys, potential, q0, p0);
      measure_composition(composed, stage, stage, system_line(sys, potential, q0, p0, given),
                          std::move(study), rep, false);
      rep.line("variational order",
               "not measured: the constrained discrete Lagrangian's exact side is not "
               "implemented");
    }
  });
}

Step typed_rattle_step(const TypedDiscreteLagrangian& sys, const std::string& potential,
                       bool project) {
  check_constrained(sys);
  Step step;
  with_dim(sys.dim(), [&](auto dim) {
    constexpr int N = decltype(dim)::value;
    if constexpr (N >= 2 && N <= kMaxConstrainedDim)
      step = rattle_map(TypedConstrained<N>(sys, potential), project);
  });
  return step;
}

}  // namespace vibook::verify
