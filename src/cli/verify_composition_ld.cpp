// `vibook verify --composition ld --ld EXPR --coefficients NAME|LIST`: a composition built on
// the user's own typed discrete Lagrangian. The base stage is the discrete Euler–Lagrange step
// of L_d (through the compiled tape); the adjoint stage is that of the adjoint discrete
// Lagrangian L_d*(q0, q1, h) = −L_d(q1, q0, −h) (nested AutoDiff on the expression tree),
// so a '*' in the coefficients applies the true adjoint of the user's method. Whether the base
// is symmetric (L_d* = L_d), which decides the order conditions, is computed from the
// expression: symbolically by the engine, else at random points. The system is the one typed
// (--potential or --hamiltonian, the reference Hamilton's equations in double-double; or
// --lagrangian, the reference its Euler–Lagrange equations and the energy its Legendre
// transform, set_typed_lagrangian).
#include <array>
#include <cmath>
#include <memory>
#include <mutex>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <ginac/ginac.h>

#include "args.hpp"
#include "cli.hpp"
#include "verify_composition.hpp"
#include "verify_map.hpp"
#include "vibook/core/output_file.hpp"
#include "vibook/core/precision.hpp"
#include "vibook/integrators/composition.hpp"
#include "vibook/mechanics/del_solver.hpp"
#include "vibook/modified/engine.hpp"
#include "vibook/modified/series.hpp"
#include "vibook/verify/composition_study.hpp"
#include "vibook/verify/expression.hpp"
#include "vibook/verify/method_symbolic.hpp"
#include "vibook/verify/tape.hpp"

namespace vibook::cli {

namespace {

namespace comp = vibook::composition;

// Whether L_d is its own adjoint, and how that was decided.
struct Symmetry {
  bool symmetric = false;
  std::string how;
};

// L_d(q0, q1, h) + L_d(q1, q0, −h) ≡ 0: first on GiNaC symbols (the engine's zero test);
// where the engine cannot reduce it to zero, at 16 random points in double (relative 1e-13).
template <int N>
Symmetry decide_symmetry(const verify::TypedDiscreteLagrangian& dl) {
  const auto Ld = dl.bind<N>();
  {
    std::lock_guard<std::mutex> lock(modified::ginac_mutex());
    Vec<GiNaC::ex, N> a, b;
    for (int i = 0; i < N; ++i) {
      a(i) = GiNaC::symbol(fmt::format("a{}", i + 1));
      b(i) = GiNaC::symbol(fmt::format("b{}", i + 1));
    }
    const GiNaC::ex h = GiNaC::symbol("h");
    try {
      const GiNaC::ex d = Ld(a, b, h) + Ld(b, a, GiNaC::ex(-h));
      if (modified::vanishes(d))
        return {true, "symmetric: L_d(q0, q1, h) = -L_d(q1, q0, -h), shown by the engine"};
    } catch (const std::exception&) {
      // not decided symbolically (e.g. a function the engine does not expand); numerically below
    }
  }
  std::mt19937_64 rng(20261127);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  double worst = 0;
  for (int k = 0; k < 16; ++k) {
    Vec<double, N> a, b;
    for (int i = 0; i < N; ++i) {
      a(i) = 0.3 + u(rng);
      b(i) = a(i) + 0.1 * u(rng);
    }
    const double h = 0.05 + 0.05 * (u(rng) + 0.5);
    const double x = Ld(a, b, h), y = Ld(b, a, -h);
    const double scale = std::max({std::abs(x), std::abs(y), 1e-300});
    worst = std::max(worst, std::abs(x + y) / scale);
  }
  if (worst <= 1e-13)
    return {true, fmt::format("symmetric: L_d(q0, q1, h) + L_d(q1, q0, -h) = 0 to {:.1e} "
                              "(relative) at 16 random points; the engine did not reduce it to "
                              "zero",
                              worst)};
  return {false, fmt::format("not symmetric: L_d(q0, q1, h) + L_d(q1, q0, -h) reaches {:.1e} "
                             "(relative) at random points; its adjoint is -L_d(q1, q0, -h)",
                             worst)};
}

template <int N>
int run_n(const CompositionOptions& o, const verify::TypedDiscreteLagrangian& dl,
          verify::CompositionSpec spec, MapStudy study, const std::vector<double>& q0,
          const std::vector<double>& p0, verify::SymbolicUse symbolic) {
  const Symmetry sym = decide_symmetry<N>(dl);
  const verify::CompositionBase base{
      "ld", sym.symmetric, "the typed discrete Lagrangian L_d = " + o.ld + "; " + sym.how};
  spec.base = &base;
  // The base stage: the DEL step of L_d through the compiled tape; the adjoint stage: the DEL
  // step of -L_d(q1, q0, -h) by nested AutoDiff. Each stage starts Newton from q + h p (the
  // stages' steps differ in size and sign, so the last increment is no guess).
  const auto Ld = dl.bind<N>();
  std::shared_ptr<DelIntegrator<N, verify::CompiledDiscreteLagrangian<N>>> tape;
  {
    std::lock_guard<std::mutex> lock(modified::ginac_mutex());
    tape = std::make_shared<DelIntegrator<N, verify::CompiledDiscreteLagrangian<N>>>(
        verify::CompiledDiscreteLagrangian<N>(dl));
  }
  auto adjoint_ld = [Ld](const auto& a, const auto& b, const auto& h) -> scalar_t<decltype(h)> {
    using S = scalar_t<decltype(h)>;
    return -Ld(b, a, S(-h));
  };
  auto adj = std::make_shared<DelIntegrator<N, decltype(adjoint_ld)>>(adjoint_ld);
  auto stage = [](auto integrator, auto ld) -> verify::CompositionStage {
    return [integrator, ld](Eigen::VectorXd& z, double h) {
      Vec<double, N> q = z.head<N>(), p = z.tail<N>();
      const Vec<double, N> start = q;
      integrator->reset();
      integrator->step(q, p, h);
      z.head<N>() = q;
      z.tail<N>() = p;
      return double(ld(start, q, h));
    };
  };
  Eigen::VectorXd z0(2 * N);
  for (int i = 0; i < N; ++i) {
    z0(i) = q0[static_cast<std::size_t>(i)];
    z0(N + i) = p0[static_cast<std::size_t>(i)];
  }
  std::string line;
  if (!o.lagrangian.empty()) {
    // L typed: the reference and the energy from its Legendre transform (verify_map.hpp)
    line = set_typed_lagrangian(study, dl, o.lagrangian, q0, p0);
  } else {
    set_typed_system<N>(study, dl, z0);
    const std::string system = o.hamiltonian.empty()
                                   ? "H = |p|^2/2 + V(q), V = " + o.potential + " (--potential)"
                                   : "H = " + o.hamiltonian + " (--hamiltonian)";
    line = fmt::format("{}, {} degree{} of freedom; q0 = {}, p0 = {}", system, N, N == 1 ? "" : "s",
                       vec_text(q0), vec_text(p0));
  }
  // The variational order derived by the engine (method_symbolic.hpp): the typed L_d on its
  // symbols, composed, against the intended Lagrangian (none for a typed Hamiltonian).
  const verify::SymbolicStageDl symbolic_ld = [Ld](const std::vector<modified::ex>& a,
                                                   const std::vector<modified::ex>& b,
                                                   const modified::ex& h) {
    Vec<modified::ex, N> x, y;
    for (int i = 0; i < N; ++i) {
      x(i) = a[static_cast<std::size_t>(i)];
      y(i) = b[static_cast<std::size_t>(i)];
    }
    return Ld(x, y, h);
  };
  verify::derive_composition_variational_order(
      spec, N, symbolic_ld,
      o.hamiltonian.empty() ? verify::typed_lagrangian<N>(&dl) : modified::SymbolicLagrangian{},
      symbolic, study);
  MapReport rep;
  if (!spec.flows.empty()) {
    // A splitting on H = |p|^2/2 + V (--splitting with --potential): the flows are explicit, so
    // each stage is stepped as it is defined, with no Newton solve: symplectic Euler drifts
    // (q += c h p), then kicks (p -= c h grad V(q), from Hamilton's equations of the system);
    // its adjoint kicks, then drifts. Each stage's L_d is the typed one's (its value only).
    const verify::Field<dd_real> field = study.field;
    auto kick = [field](Eigen::VectorXd& z, double c) {
      std::vector<dd_real> x(2 * N);
      for (int i = 0; i < 2 * N; ++i) x[static_cast<std::size_t>(i)] = dd_real(z(i));
      const std::vector<dd_real> f = field(x);
      for (int i = 0; i < N; ++i) z(N + i) += c * to_double(f[static_cast<std::size_t>(N + i)]);
    };
    auto value = [](const auto& ld, const Eigen::VectorXd& from, const Eigen::VectorXd& z,
                    double h) {
      const Vec<double, N> a = from.head<N>(), b = z.head<N>();
      return double(ld(a, b, h));
    };
    const verify::CompositionStage se = [kick, value, Ld](Eigen::VectorXd& z, double h) {
      const Eigen::VectorXd from = z;
      z.head<N>() += h * z.tail<N>();
      kick(z, h);
      return value(Ld, from, z, h);
    };
    const verify::CompositionStage se_adjoint = [kick, value, adjoint_ld](Eigen::VectorXd& z,
                                                                          double h) {
      const Eigen::VectorXd from = z;
      kick(z, h);
      z.head<N>() += h * z.tail<N>();
      return value(adjoint_ld, from, z, h);
    };
    verify::measure_composition(spec, se, se_adjoint, line, study, rep);
  } else {
    verify::measure_composition(spec, stage(tape, Ld), stage(adj, adjoint_ld), line, study, rep);
  }
  rep.js["system"] = {{"ld", o.ld},
                      {"potential", o.potential},
                      {"lagrangian", o.lagrangian},
                      {"hamiltonian", o.hamiltonian},
                      {"symmetric", sym.symmetric},
                      {"symmetry", sym.how},
                      {"q0", q0},
                      {"p0", p0}};
  return rep.finish(o);
}

}  // namespace

int run_composition_ld(const CompositionOptions& t, verify::CompositionSpec spec) {
  const CompositionOptions& o = t;
  if (t.ld.empty()) throw ArgumentError("--ld", "is required with --composition ld");
  if (!t.lagrangian.empty() && !t.hamiltonian.empty())
    throw ArgumentError("--hamiltonian",
                        "give the system once: --lagrangian or --hamiltonian, not both");
  if (t.potential.empty() && t.hamiltonian.empty() && t.lagrangian.empty())
    throw ArgumentError("--potential",
                        "is required with --composition ld (or --lagrangian or --hamiltonian): "
                        "the system the composition is measured on");
  // The system: a Hamiltonian (typed, or p^2/2 + V), whose field is the reference's and H the
  // energy; or a typed Lagrangian, through its Legendre transform (set_typed_lagrangian).
  const std::string hamiltonian = !t.lagrangian.empty()   ? ""
                                  : t.hamiltonian.empty() ? "p^2/2 + V(q)"
                                                          : t.hamiltonian;
  int dim = 0;
  if (!t.dim.empty()) {
    dim = static_cast<int>(parse_integer("--dim", t.dim));
    if (dim < 1 || dim > 3) throw ArgumentError("--dim", "must lie in 1..3 with --composition ld");
  }
  std::unique_ptr<verify::TypedDiscreteLagrangian> dl;
  {
    std::lock_guard<std::mutex> lock(modified::ginac_mutex());
    dl = std::make_unique<verify::TypedDiscreteLagrangian>(
        verify::TypedTexts{t.ld, t.potential, t.lagrangian, hamiltonian, dim});
  }
  if (dl->dim() > 3)
    throw ArgumentError("--ld", fmt::format("is {}-dimensional; --composition ld runs in 1 to 3 "
                                            "dimensions",
                                            dl->dim()));
  const int n = dl->dim();
  const verify::SymbolicUse symbolic = verify::parse_symbolic_use(o.symbolic);
  std::vector<double> q0, p0;
  MapStudy study;
  check_typed_initial_state(o, n, q0, p0, study);
  check_study_options(o, study);
  if (o.json_given) check_output_path(o.json_out, "--json-out", true);
  switch (n) {
    case 1:
      return run_n<1>(o, *dl, std::move(spec), study, q0, p0, symbolic);
    case 2:
      return run_n<2>(o, *dl, std::move(spec), study, q0, p0, symbolic);
    default:
      return run_n<3>(o, *dl, std::move(spec), study, q0, p0, symbolic);
  }
}

}  // namespace vibook::cli
