// Work–precision against wall-clock time (Shen & Sun §5 methods): Kepler e = 0.6 from perihelion,
// 10 periods with h = T/n, n = 10·2^j (j = the benchmark argument); each iteration integrates
// the whole span. Counter angle_error = |Δω| of the LRL vector at the end (the same in every
// iteration). bench_table.py turns the medians into a table and the CSV of the diagram.
#include <cmath>
#include <numbers>

#include <benchmark/benchmark.h>

#include "vibook/integrators/kernels.hpp"
#include "vibook/integrators/splitting.hpp"
#include "vibook/kepler/kepler.hpp"

namespace {

template <class Kernel>
void run_wp(benchmark::State& state, Kernel kernel) {
  const auto s0 = vibook::kepler_perihelion_state(0.6);
  const auto k0 = vibook::kepler_invariants(s0.q, s0.p);
  const long n = 10L << state.range(0);
  const double h = 10 * 2 * std::numbers::pi / double(n);
  double err = 0;
  for (auto _ : state) {
    vibook::Vec<double, 2> q = s0.q, p = s0.p;
    for (long k = 0; k < n; ++k) kernel.step(q, p, h);
    benchmark::DoNotOptimize(q);
    const auto k1 = vibook::kepler_invariants(q, p);
    double dw = k1.omega - k0.omega;
    dw -= 2 * std::numbers::pi * std::nearbyint(dw / (2 * std::numbers::pi));
    err = std::abs(dw);
  }
  state.counters["angle_error"] = err;
  state.counters["steps"] = double(n);
}

using Split = vibook::WeightedSplit<vibook::Kepler>;

void BM_wp_se(benchmark::State& s) { run_wp(s, vibook::SymplecticEuler<vibook::Kepler>{}); }
void BM_wp_sv(benchmark::State& s) { run_wp(s, vibook::StormerVerlet<vibook::Kepler>{}); }
void BM_wp_vi1(benchmark::State& s) {
  run_wp(s, vibook::SplittingKernel<Split>(Split::alpha(0.5), vibook::SplittingMethod::vi1));
}
void BM_wp_vi2(benchmark::State& s) {
  run_wp(s, vibook::SplittingKernel<Split>(Split::alpha(0.5), vibook::SplittingMethod::vi2));
}

}  // namespace

BENCHMARK(BM_wp_se)->DenseRange(6, 13)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_wp_sv)->DenseRange(6, 13)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_wp_vi1)->DenseRange(6, 13)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_wp_vi2)->DenseRange(6, 13)->Unit(benchmark::kMicrosecond);
