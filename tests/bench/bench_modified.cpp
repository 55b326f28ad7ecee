// Derivation time of the modified-equation engine (Vermeeren 2017 §4–5): L_mod,K for
// Störmer–Verlet with a generic 1-DOF potential (K = 4, 6, 8) and for Kepler in 2-D (K = 4),
// from scratch each iteration. Peer in the same run: the expansion L_disc([x], h) done the
// straightforward way, GiNaC's series() on the substituted discrete Lagrangian.
#include <benchmark/benchmark.h>

#include "vibook/modified/engine.hpp"

namespace {

using namespace vibook::modified;

void BM_engine_sv_generic(benchmark::State& st) {
  const int K = static_cast<int>(st.range(0));
  for (auto _ : st) {
    Engine E(make_discrete_lagrangian(Method::sv, Potential::generic, 1), K);
    benchmark::DoNotOptimize(E.l_mod().size());
  }
  st.counters["order"] = K;
}

void BM_engine_sv_kepler(benchmark::State& st) {
  const int K = static_cast<int>(st.range(0));
  for (auto _ : st) {
    Engine E(make_discrete_lagrangian(Method::sv, Potential::kepler, 2), K);
    benchmark::DoNotOptimize(E.l_mod().size());
  }
  st.counters["order"] = K;
}

// Only the first step, L_disc([x], h), with the engine ...
void BM_ldisc_engine(benchmark::State& st) {
  const int K = static_cast<int>(st.range(0));
  for (auto _ : st) {
    Engine E(make_discrete_lagrangian(Method::sv, Potential::generic, 1), K);
    benchmark::DoNotOptimize(E.l_disc().size());
  }
  st.counters["order"] = K;
}

// ... and with GiNaC's series() on L_d(x − h/2 ẋ + …, x + h/2 ẋ + …, h)/h.
void BM_ldisc_ginac_series(benchmark::State& st) {
  const int K = static_cast<int>(st.range(0));
  for (auto _ : st) {
    const SymbolicDL dl = make_discrete_lagrangian(Method::sv, Potential::generic, 1);
    const JetSpace& J = *dl.jets;
    ex a = 0, b = 0;
    GiNaC::numeric fact = 1;
    for (int k = 0; k <= K + 3; ++k) {
      if (k > 0) fact *= k;
      a += GiNaC::pow(-J.h() / 2, k) / fact * J.x(k, 0);
      b += GiNaC::pow(J.h() / 2, k) / fact * J.x(k, 0);
    }
    const ex L = (dl.Ld / J.h()).subs(GiNaC::lst{dl.q0[0], dl.q1[0]}, GiNaC::lst{a, b});
    benchmark::DoNotOptimize(L.series(J.h() == 0, K + 1));
  }
  st.counters["order"] = K;
}

// #28: the engine's cost with dimension and order. L_mod,K of Störmer–Verlet for a generic
// potential of 1–3 degrees of freedom (the derivation the issue timed in SymPy).
void BM_engine_cost(benchmark::State& st) {
  const int dim = static_cast<int>(st.range(0)), K = static_cast<int>(st.range(1));
  for (auto _ : st) {
    Engine E(make_discrete_lagrangian(Method::sv, Potential::generic, dim), K);
    benchmark::DoNotOptimize(E.l_mod().size());
  }
  st.counters["dim"] = dim;
  st.counters["order"] = K;
}

// Every method to h^4 in 3-D: H_mod, which needs the modified equation and L_mod first.
void BM_engine_method_3d(benchmark::State& st) {
  const auto m = static_cast<Method>(st.range(0));
  for (auto _ : st) {
    Engine E(make_discrete_lagrangian(m, Potential::generic, 3), 4);
    benchmark::DoNotOptimize(E.h_mod().size());
  }
}

}  // namespace

BENCHMARK(BM_engine_cost)
    ->ArgsProduct({{1, 2}, {2, 4, 6, 8, 10}})
    ->ArgsProduct({{3}, {2, 4, 6, 8}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_engine_method_3d)
    ->DenseRange(static_cast<int>(Method::sv), static_cast<int>(Method::vi2))
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_engine_sv_kepler)->Arg(8)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_engine_sv_generic)->Arg(4)->Arg(6)->Arg(8)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_engine_sv_kepler)->Arg(4)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ldisc_engine)->Arg(4)->Arg(6)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ldisc_ginac_series)->Arg(4)->Arg(6)->Unit(benchmark::kMillisecond)->Iterations(1);
