// A researcher's own discrete Lagrangian, typed as text (verify/expression.hpp), stepped by
// the generic variational integrator (DelIntegrator, Vermeeren 2017 (4)–(5)) through the
// compiled tape (verify/tape.hpp) run as native code and interpreted, and through the reference
// path (nested AutoDiff on the expression tree), on Kepler e = 0.7, h = 1e-3, 300 steps from
// perihelion: the same problem and step as BM_sv_e07 and BM_midpoint_e07 (bench_adaptive.cpp), so
// that bench_table.py divides by the hand-written kernels of the same run.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "vibook/integrators/galerkin.hpp"
#include "vibook/integrators/prk.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/mechanics/del_solver.hpp"
#include "vibook/modified/engine.hpp"
#include "vibook/verify/tape.hpp"

namespace {

constexpr int kSteps = 300;
constexpr double kE = 0.7, kH = 1e-3;
const char* kKepler = "-1/sqrt(x^2+y^2)";
const char* kMidpoint = "h*((q1-q0)^2/(2*h^2) - V((q0+q1)/2))";
const char* kTrapezoid = "(q1-q0)^2/(2*h) - h*(V(q0)+V(q1))/2";

const vibook::verify::TypedDiscreteLagrangian& typed(const char* ld) {
  std::lock_guard<std::recursive_mutex> lock(vibook::modified::ginac_mutex());
  static std::map<std::string, std::unique_ptr<vibook::verify::TypedDiscreteLagrangian>> cache;
  auto& p = cache[ld];
  if (!p) p = std::make_unique<vibook::verify::TypedDiscreteLagrangian>(ld, kKepler);
  return *p;
}

template <class Integrator>
void run(benchmark::State& state, Integrator& vi) {
  const auto s0 = vibook::kepler_perihelion_state(kE);
  double its = 0;
  for (auto _ : state) {
    vibook::Vec<double, 2> q = s0.q, p = s0.p;
    if constexpr (requires { vi.reset(); }) vi.reset();
    for (int k = 0; k < kSteps; ++k) its += vi.step(q, p, kH).iterations;
    benchmark::DoNotOptimize(q);
    benchmark::DoNotOptimize(p);
  }
  state.counters["ns_per_step"] =
      benchmark::Counter(double(kSteps) * double(state.iterations()) * 1e-9,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["iterations_per_step"] = its / (double(kSteps) * double(state.iterations()));
}

void tape(benchmark::State& state, const char* ld, bool native) {
  std::unique_lock<std::recursive_mutex> lock(vibook::modified::ginac_mutex(), std::defer_lock);
  const auto& dl = typed(ld);
  lock.lock();
  const vibook::verify::CompiledDiscreteLagrangian<2> c(dl, native);
  if (native && !c.native()) {
    state.SkipWithError(("no native code: " + c.native_reason()).c_str());
    return;
  }
  lock.unlock();
  vibook::DelIntegrator<2, vibook::verify::CompiledDiscreteLagrangian<2>> vi(c);
  run(state, vi);
}

void tree(benchmark::State& state, const char* ld) {
  const auto& dl = typed(ld);
  const auto Ld = dl.bind<2>();
  vibook::DelIntegrator<2, decltype(Ld)> vi(Ld);
  run(state, vi);
}

// The 3-stage Lobatto IIIA-IIIB method (#25, #28) on the same problem and step: from its
// tableau (integrators/prk.hpp, the route of `vibook verify --tableau`: Newton on the stages
// with the Hessian by AutoDiff of the problem's gradient), and as the Galerkin integrator
// (integrators/galerkin.hpp, `vibook verify --method lobatto:3`: nested AutoDiff of L).
void BM_vprk_lobatto3_tableau(benchmark::State& state) {
  const vibook::PartitionedRungeKutta<vibook::Kepler> coefficients(vibook::Kepler{},
                                                                   vibook::lobatto_rule(3));
  const vibook::PrkTableau t{coefficients.a(), coefficients.ahat(), vibook::lobatto_rule(3).b,
                             vibook::lobatto_rule(3).b};
  vibook::PartitionedRkMethod<3, vibook::Kepler> vi(vibook::Kepler{}, t);
  run(state, vi);
}
void BM_vprk_lobatto3_galerkin(benchmark::State& state) {
  auto L = [](const auto& q, const auto& v) -> std::remove_cvref_t<decltype(q(0))> {
    using T = std::remove_cvref_t<decltype(q(0))>;
    return vibook::constant<T>(0.5) * vibook::squared_norm(v) -
           vibook::Kepler{}.template potential<T>(q);
  };
  vibook::GalerkinIntegrator<2, 3, decltype(L)> vi(L, vibook::lobatto_rule(3));
  run(state, vi);
}

void BM_typed_midpoint_native(benchmark::State& s) { tape(s, kMidpoint, true); }
void BM_typed_midpoint_tape(benchmark::State& s) { tape(s, kMidpoint, false); }
void BM_typed_midpoint_autodiff(benchmark::State& s) { tree(s, kMidpoint); }
void BM_typed_trapezoid_native(benchmark::State& s) { tape(s, kTrapezoid, true); }
void BM_typed_trapezoid_tape(benchmark::State& s) { tape(s, kTrapezoid, false); }
void BM_typed_trapezoid_autodiff(benchmark::State& s) { tree(s, kTrapezoid); }

}  // namespace

BENCHMARK(BM_typed_midpoint_native);
BENCHMARK(BM_typed_midpoint_tape);
BENCHMARK(BM_typed_midpoint_autodiff);
BENCHMARK(BM_typed_trapezoid_native);
BENCHMARK(BM_typed_trapezoid_tape);
BENCHMARK(BM_typed_trapezoid_autodiff);
BENCHMARK(BM_vprk_lobatto3_tableau);
BENCHMARK(BM_vprk_lobatto3_galerkin);
