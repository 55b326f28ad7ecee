// Störmer–Verlet on Kepler (e = 0.5, h = 1e-3), nanoseconds per step, three ways in one run:
//   hand      — a plain loop on doubles, one force evaluation per step (the practical limit)
//   vibook    — vibook::StormerVerlet<vibook::Kepler> on Eigen fixed-size vectors
//   odeint    — boost::numeric::odeint::velocity_verlet on std::array, the same force
// Each iteration runs kSteps steps from the same initial state; the counter ns_per_step is
// the time of one step. The ratios are computed by tests/bench/bench_table.py.
#include <array>
#include <cmath>
#include <utility>

#include <benchmark/benchmark.h>
#include <boost/numeric/odeint/stepper/velocity_verlet.hpp>

#include "vibook/integrators/kernels.hpp"
#include "vibook/kepler/kepler.hpp"

namespace {

constexpr int kSteps = 10000;
constexpr double kH = 1e-3;

void set_counter(benchmark::State& state) {
  state.counters["ns_per_step"] =
      benchmark::Counter(double(kSteps) * double(state.iterations()) * 1e-9,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_hand_loop(benchmark::State& state) {
  const auto s0 = vibook::kepler_perihelion_state(0.5);
  for (auto _ : state) {
    double x = s0.q(0), y = s0.q(1), px = s0.p(0), py = s0.p(1);
    double r2 = x * x + y * y, ir3 = 1.0 / (r2 * std::sqrt(r2));
    double ax = -x * ir3, ay = -y * ir3;
    for (int k = 0; k < kSteps; ++k) {
      px += 0.5 * kH * ax;
      py += 0.5 * kH * ay;
      x += kH * px;
      y += kH * py;
      r2 = x * x + y * y;
      ir3 = 1.0 / (r2 * std::sqrt(r2));
      ax = -x * ir3;
      ay = -y * ir3;
      px += 0.5 * kH * ax;
      py += 0.5 * kH * ay;
    }
    benchmark::DoNotOptimize(x);
    benchmark::DoNotOptimize(y);
    benchmark::DoNotOptimize(px);
    benchmark::DoNotOptimize(py);
  }
  set_counter(state);
}

void BM_vibook(benchmark::State& state) {
  const auto s0 = vibook::kepler_perihelion_state(0.5);
  for (auto _ : state) {
    vibook::StormerVerlet<vibook::Kepler> sv;
    vibook::Vec<double, 2> q = s0.q, p = s0.p;
    for (int k = 0; k < kSteps; ++k) sv.step(q, p, kH);
    benchmark::DoNotOptimize(q);
    benchmark::DoNotOptimize(p);
  }
  set_counter(state);
}

void BM_odeint(benchmark::State& state) {
  using vec = std::array<double, 2>;
  const auto s0 = vibook::kepler_perihelion_state(0.5);
  auto force = [](const vec& x, const vec& /*v*/, vec& a, double /*t*/) {
    const double r2 = x[0] * x[0] + x[1] * x[1];
    const double ir3 = 1.0 / (r2 * std::sqrt(r2));
    a[0] = -x[0] * ir3;
    a[1] = -x[1] * ir3;
  };
  for (auto _ : state) {
    boost::numeric::odeint::velocity_verlet<vec> stepper;
    std::pair<vec, vec> xv{{s0.q(0), s0.q(1)}, {s0.p(0), s0.p(1)}};
    double t = 0;
    for (int k = 0; k < kSteps; ++k) {
      stepper.do_step(force, xv, t, kH);
      t += kH;
    }
    benchmark::DoNotOptimize(xv);
  }
  set_counter(state);
}

BENCHMARK(BM_hand_loop);
BENCHMARK(BM_vibook);
BENCHMARK(BM_odeint);

}  // namespace

BENCHMARK_MAIN();
