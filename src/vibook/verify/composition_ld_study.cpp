/// \file composition_ld_study.cpp
/// \brief A composition built on the user's own typed discrete Lagrangian (`vibook verify
/// --composition ld --ld EXPR`), measured by the composition study (composition_study.hpp).
/// The base stage is the discrete Euler–Lagrange step of L_d (through the compiled tape); the
/// adjoint stage is that of the adjoint discrete Lagrangian L_d*(q0, q1, h) = −L_d(q1, q0, −h)
/// (nested AutoDiff on the expression tree), so a '*' in the coefficients applies the true
/// adjoint of the user's method. Whether the base is symmetric (L_d* = L_d), which decides the
/// order conditions, is computed from the expression: symbolically by the engine, else at random
/// points. The system is the one typed (--potential or --hamiltonian, the reference Hamilton's
/// equations in double-double; or --lagrangian, the reference its Euler–Lagrange equations and
/// the energy its Legendre transform, set_typed_lagrangian).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <ginac/ginac.h>

#include "vibook/core/precision.hpp"
#include "vibook/integrators/composition.hpp"
#include "vibook/mechanics/del_solver.hpp"
#include "vibook/modified/engine.hpp"
#include "vibook/modified/series.hpp"
#include "vibook/verify/composition_ld_study.hpp"
#include "vibook/verify/expression.hpp"
#include "vibook/verify/method_symbolic.hpp"
#include "vibook/verify/tape.hpp"
#include "vibook/verify/typed_system.hpp"

namespace vibook::verify {

namespace {

namespace comp = vibook::composition;

// Whether L_d is its own adjoint, and how that was decided.
struct Symmetry {
  bool symmetric = false;
  std::string how;
};

// max |x + y| / max(|x|, |y|) over 16 random points (q0 near 0.3, q1 within 0.05 of it, h in
// [0.05, 0.1], with `timed` a time t in [-2, 2]), where (x, y) = parts(q0, q1, h, t): an L_d and
// its mirror image, which sum to zero when L_d is symmetric.
template <int N, class Parts>
double random_asymmetry(Parts&& parts, std::uint64_t seed, bool timed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  double worst = 0;
  for (int k = 0; k < 16; ++k) {
    Vec<double, N> a, b;
    for (int i = 0; i < N; ++i) {
      a(i) = 0.3 + u(rng);
      b(i) = a(i) + 0.1 * u(rng);
    }
    const double h = 0.05 + 0.05 * (u(rng) + 0.5), t = timed ? 4 * u(rng) : 0.0;
    const auto [x, y] = parts(a, b, h, t);
    const double scale = std::max({std::abs(x), std::abs(y), 1e-300});
    worst = std::max(worst, std::abs(x + y) / scale);
  }
  return worst;
}

// L_d(q0, q1, h) + L_d(q1, q0, −h) ≡ 0: first on GiNaC symbols (the engine's zero test);
// where the engine cannot reduce it to zero, at 16 random points in double (relative 1e-13).
template <int N>
Symmetry decide_symmetry(const TypedDiscreteLagrangian& dl) {
  const auto Ld = dl.bind<N>();
  {
    std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
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
  const double worst = random_asymmetry<N>(
      [&Ld](const Vec<double, N>& a, const Vec<double, N>& b, double h, double) {
        return std::pair{double(Ld(a, b, h)), double(Ld(b, a, -h))};
      },
      20261127, false);
  if (worst <= 1e-13)
    return {true, fmt::format("symmetric: L_d(q0, q1, h) + L_d(q1, q0, -h) = 0 to {:.1e} "
                              "(relative) at 16 random points; the engine did not reduce it to "
                              "zero",
                              worst)};
  return {false, fmt::format("not symmetric: L_d(q0, q1, h) + L_d(q1, q0, -h) reaches {:.1e} "
                             "(relative) at random points; its adjoint is -L_d(q1, q0, -h)",
                             worst)};
}

// A typed L_d(t, q0, q1, h) at the clock's time, on whatever scalar the DEL solver asks for (the
// step sets the clock from the state before solving); with `adjoint`, the adjoint discrete
// Lagrangian of the time-dependent method, L_d*(t, q0, q1, h) = -L_d(t + h, q1, q0, -h): the
// adjoint map Φ*_{t,h} = (Φ_{t+h,-h})^{-1} of the extended system. One type for both, so that the
// DEL solver is compiled once per dimension.
template <int N>
struct TimedLd {
  const TypedDiscreteLagrangian* dl = nullptr;
  std::shared_ptr<double> clock;
  bool adjoint = false;
  template <class A, class B, class H>
  scalar_t<H> operator()(const A& a, const B& b, const H& h) const {
    using S = scalar_t<H>;
    const S t = constant_of<S>(*clock);
    if (adjoint) return -dl->evaluate<N, S>(Vec<S, N>(b), Vec<S, N>(a), S(-h), S(t + h));
    return dl->evaluate<N, S>(Vec<S, N>(a), Vec<S, N>(b), S(h), t);
  }
};

// The same test for L_d(t, q0, q1, h): L_d(t, q0, q1, h) + L_d(t + h, q1, q0, -h) at 16 random
// points (t among them), relative 1e-13; no symbolic attempt (the engine is autonomous).
template <int N>
Symmetry decide_timed_symmetry(const TypedDiscreteLagrangian& dl) {
  const double worst = random_asymmetry<N>(
      [&dl](const Vec<double, N>& a, const Vec<double, N>& b, double h, double t) {
        return std::pair{dl.evaluate<N, double>(a, b, h, t),
                         dl.evaluate<N, double>(b, a, -h, t + h)};
      },
      20261129, true);
  if (worst <= 1e-13)
    return {true, fmt::format("symmetric: L_d(t, q0, q1, h) + L_d(t + h, q1, q0, -h) = 0 to "
                              "{:.1e} (relative) at 16 random points",
                              worst)};
  return {false, fmt::format("not symmetric: L_d(t, q0, q1, h) + L_d(t + h, q1, q0, -h) reaches "
                             "{:.1e} (relative) at random points; its adjoint is -L_d(t + h, q1, "
                             "q0, -h)",
                             worst)};
}

template <int N>
void measure_n(const TypedLdSystem& o, const TypedDiscreteLagrangian& dl, CompositionSpec spec,
               MapStudy study, SymbolicUse symbolic, MapMeasurement& rep) {
  const std::vector<double>& q0 = o.q0;
  const std::vector<double>& p0 = o.p0;
  // A time-dependent system: a splitting on V(q, t), whose base is symplectic Euler (its drift
  // also advances the time), or a composition of a typed L_d(t, q0, q1, h), each stage starting
  // at the time the stages before it reached (the partial sums of the coefficients).
  const bool timed = dl.time_dependent();
  const bool splitting = !spec.flows.empty();
  const Symmetry sym = timed && splitting ? Symmetry{false, "not symmetric"}
                       : timed            ? decide_timed_symmetry<N>(dl)
                                          : decide_symmetry<N>(dl);
  const CompositionBase base{
      timed && splitting ? "se" : "ld", sym.symmetric,
      timed && splitting
          ? "symplectic Euler on the extended phase space: a drift (which also advances the "
            "time), then a kick at the time reached; its adjoint, a kick, then a drift"
          : (timed ? "the typed discrete Lagrangian L_d(t, q0, q1, h) = "
                   : "the typed discrete Lagrangian L_d = ") +
                o.ld + "; " + sym.how};
  spec.base = &base;
  // The base stage: the DEL step of L_d through the compiled tape; the adjoint stage: the DEL
  // step of -L_d(q1, q0, -h) by nested AutoDiff. Each stage starts Newton from q + h p (the
  // stages' steps differ in size and sign, so the last increment is no guess).
  const auto Ld = dl.bind<N>();
  std::shared_ptr<DelIntegrator<N, CompiledDiscreteLagrangian<N>>> tape;
  if (!timed) {  // (the tape's inputs are q0, q1 and h: an L_d in t is stepped on its tree)
    std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
    tape = std::make_shared<DelIntegrator<N, CompiledDiscreteLagrangian<N>>>(
        CompiledDiscreteLagrangian<N>(dl));
  }
  auto adjoint_ld = [Ld](const auto& a, const auto& b, const auto& h) -> scalar_t<decltype(h)> {
    using S = scalar_t<decltype(h)>;
    return -Ld(b, a, S(-h));
  };
  auto adj = std::make_shared<DelIntegrator<N, decltype(adjoint_ld)>>(adjoint_ld);
  auto stage = [](auto integrator, auto ld) -> CompositionStage {
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
    // L typed: the reference and the energy from its Legendre transform (typed_system.hpp)
    line = set_typed_lagrangian(study, dl, o.lagrangian, q0, p0);
  } else {
    set_typed_system<N>(study, dl, z0);
    const std::string system = o.hamiltonian.empty() ? (timed ? "H = |p|^2/2 + V(q, t), V = "
                                                              : "H = |p|^2/2 + V(q), V = ") +
                                                           o.potential + " (--potential)"
                                                     : "H = " + o.hamiltonian + " (--hamiltonian)";
    line = fmt::format("{}, {} degree{} of freedom; q0 = {}, p0 = {}", system, N, N == 1 ? "" : "s",
                       vec_text(q0), vec_text(p0));
  }
  // The variational order derived by the engine (method_symbolic.hpp): the typed L_d on its
  // symbols, composed, against the intended Lagrangian (none for a typed Hamiltonian).
  const SymbolicStageDl symbolic_ld = [Ld](const std::vector<modified::ex>& a,
                                           const std::vector<modified::ex>& b,
                                           const modified::ex& h) {
    Vec<modified::ex, N> x, y;
    for (int i = 0; i < N; ++i) {
      x(i) = a[static_cast<std::size_t>(i)];
      y(i) = b[static_cast<std::size_t>(i)];
    }
    return Ld(x, y, h);
  };
  // (Not for a time-dependent L_d: the engine is autonomous, and the map study says so.)
  if (!(timed && !splitting))
    derive_composition_variational_order(
        spec, N, symbolic_ld,
        o.hamiltonian.empty() ? typed_lagrangian<N>(&dl) : modified::SymbolicLagrangian{}, symbolic,
        study);
  if (timed && !splitting) {
    // L_d(t, q0, q1, h) and its adjoint, each stage's DEL step at the clock's time; the stage
    // advances the clock by its own step (negative for a negative coefficient).
    auto clock = std::make_shared<double>(0.0);
    auto base_del = std::make_shared<DelIntegrator<N, TimedLd<N>>>(TimedLd<N>{&dl, clock, false});
    auto adj_del = std::make_shared<DelIntegrator<N, TimedLd<N>>>(TimedLd<N>{&dl, clock, true});
    auto timed_stage = [clock](auto integrator) -> CompositionStage {
      return [integrator, clock](Eigen::VectorXd& z, double h) {
        Vec<double, N> q = z.head<N>(), p = z.segment<N>(N);
        *clock = z(2 * N);
        integrator->reset();
        integrator->step(q, p, h);
        z.head<N>() = q;
        z.segment<N>(N) = p;
        z(2 * N) += h;
        return 0.0;  // the stage's L_d: the variational order is not measured for t
      };
    };
    measure_composition(spec, timed_stage(base_del), timed_stage(adj_del), line, study, rep);
  } else if (splitting) {
    // A splitting on H = |p|^2/2 + V (--splitting with --potential): the flows are explicit, so
    // each stage is stepped as it is defined, with no Newton solve: symplectic Euler drifts
    // (q += c h p), then kicks (p -= c h grad V(q), from Hamilton's equations of the system);
    // its adjoint kicks, then drifts. Each stage's L_d is the typed one's (its value only).
    const Field<dd_real> field = study.field;
    // The same flows in double-double, for the order study where double's local slopes do
    // not settle (map_study.cpp).
    // (Not for a time-dependent system: the double-double flows are autonomous.)
    if (!timed) study.step_dd = splitting_step_dd(spec.flows, field, N);
    // With the clock in the state (z = (q, p, t)) the field reads the time, and the drift
    // advances it.
    auto kick = [field](Eigen::VectorXd& z, double c) {
      std::vector<dd_real> x(static_cast<std::size_t>(z.size()));
      for (Eigen::Index i = 0; i < z.size(); ++i) x[static_cast<std::size_t>(i)] = dd_real(z(i));
      const std::vector<dd_real> f = field(x);
      for (int i = 0; i < N; ++i) z(N + i) += c * to_double(f[static_cast<std::size_t>(N + i)]);
    };
    auto drift = [](Eigen::VectorXd& z, double c) {
      z.head<N>() += c * z.segment<N>(N);
      if (z.size() > 2 * N) z(2 * N) += c;
    };
    // The stage's L_d (the variational order's), not read for a time-dependent system.
    auto value = [](const auto& ld, const Eigen::VectorXd& from, const Eigen::VectorXd& z,
                    double h) {
      if (z.size() > 2 * N) return 0.0;
      const Vec<double, N> a = from.head<N>(), b = z.head<N>();
      return double(ld(a, b, h));
    };
    const CompositionStage se = [kick, drift, value, Ld](Eigen::VectorXd& z, double h) {
      const Eigen::VectorXd from = z;
      drift(z, h);
      kick(z, h);
      return value(Ld, from, z, h);
    };
    const CompositionStage se_adjoint = [kick, drift, value, adjoint_ld](Eigen::VectorXd& z,
                                                                         double h) {
      const Eigen::VectorXd from = z;
      kick(z, h);
      drift(z, h);
      return value(adjoint_ld, from, z, h);
    };
    measure_composition(spec, se, se_adjoint, line, study, rep);
  } else {
    measure_composition(spec, stage(tape, Ld), stage(adj, adjoint_ld), line, study, rep);
  }
  rep.js["system"] = {{"ld", o.ld},
                      {"potential", o.potential},
                      {"lagrangian", o.lagrangian},
                      {"hamiltonian", o.hamiltonian},
                      {"symmetric", sym.symmetric},
                      {"symmetry", sym.how},
                      {"q0", q0},
                      {"p0", p0}};
}

}  // namespace

namespace {

// The time-dependent --ld (measure_timed_ld) in N dimensions.
template <int N>
void measure_timed_ld_n(const TypedDiscreteLagrangian& dl, const TypedLdSystem& o, MapStudy study,
                        MapMeasurement& rep) {
  // L_d(t, q0, q1, h) at the clock's time, on whatever scalar the DEL solver asks for; the step
  // sets the clock from the state before solving.
  auto clock = std::make_shared<double>(0.0);
  auto del = std::make_shared<DelIntegrator<N, TimedLd<N>>>(TimedLd<N>{&dl, clock, false});
  study.step = naming_failures(
      [del, clock](Eigen::VectorXd& z, double h) {
        Vec<double, N> q = z.head<N>(), p = z.segment<N>(N);
        *clock = z(2 * N);
        del->reset();
        del->step(q, p, h);
        z.head<N>() = q;
        z.segment<N>(N) = p;
        z(2 * N) += h;
      },
      N);
  Eigen::VectorXd z0(2 * N);
  for (int i = 0; i < N; ++i) {
    z0(i) = o.q0[static_cast<std::size_t>(i)];
    z0(N + i) = o.p0[static_cast<std::size_t>(i)];
  }
  std::string line;
  if (!o.lagrangian.empty()) {
    line = set_typed_lagrangian(study, dl, o.lagrangian, o.q0, o.p0);
  } else {
    set_typed_system<N>(study, dl, z0);
    line = fmt::format("{}, {} degree{} of freedom; q0 = {}, p0 = {}",
                       o.hamiltonian.empty()
                           ? "H = |p|^2/2 + V(q, t), V = " + o.potential + " (--potential)"
                           : "H = " + o.hamiltonian + " (--hamiltonian)",
                       N, N == 1 ? "" : "s", vec_text(o.q0), vec_text(o.p0));
  }
  rep.line("discrete Lagrangian",
           fmt::format("L_d(t, q0, q1, h) = {} (--ld; t the step's start time)", o.ld));
  rep.line("", "stepped by its discrete Euler-Lagrange equations, Newton on nested AutoDiff");
  rep.line("system", line);
  rep.line("expected order", fmt::format("{:g}", study.expected));
  rep.js["system"] = {{"ld", o.ld},
                      {"potential", o.potential},
                      {"lagrangian", o.lagrangian},
                      {"hamiltonian", o.hamiltonian},
                      {"q0", o.q0},
                      {"p0", o.p0},
                      {"time_dependent", true}};
  measure_map(study, rep);
}

}  // namespace

void measure_timed_ld(const TypedDiscreteLagrangian& dl, const TypedLdSystem& system,
                      const MapStudy& study, MapMeasurement& rep) {
  if (!dl.time_dependent())
    throw ArgumentError("--ld",
                        "uses the time t, but the system (--potential, --lagrangian or "
                        "--hamiltonian) does not: give the system's own time dependence");
  switch (dl.dim()) {
    case 1:
      return measure_timed_ld_n<1>(dl, system, study, rep);
    case 2:
      return measure_timed_ld_n<2>(dl, system, study, rep);
    default:
      return measure_timed_ld_n<3>(dl, system, study, rep);
  }
}

std::string splitting_stage_ld(bool time_dependent) {
  return time_dependent ? "h*((q1-q0)^2/(2*h^2))" : "h*((q1-q0)^2/(2*h^2) - V(q1))";
}

void measure_ld_composition(CompositionSpec spec, const TypedDiscreteLagrangian& dl,
                            const TypedLdSystem& system, const MapStudy& study,
                            SymbolicUse symbolic, MapMeasurement& rep) {
  switch (dl.dim()) {
    case 1:
      return measure_n<1>(system, dl, std::move(spec), study, symbolic, rep);
    case 2:
      return measure_n<2>(system, dl, std::move(spec), study, symbolic, rep);
    default:
      return measure_n<3>(system, dl, std::move(spec), study, symbolic, rep);
  }
}

}  // namespace vibook::verify
