// EpAVI (closed form, epavi/mechanical.hpp, and the generic nested-AutoDiff path, in five
// precisions), AVI1, AVI2, the implicit midpoint rule (the implicit baseline) and
// Störmer–Verlet on Kepler e = 0.7, h0 = h = 1e-3, from perihelion: nanoseconds per step and
// solver iterations per step (evaluations of the energy equation for EpAVI, Newton iterations
// for AVI and midpoint). Each iteration runs kSteps steps from the start. The ratios (each /
// SV step, each precision / double EpAVI) are computed by bench_table.py.
#include <benchmark/benchmark.h>

#include "vibook/avi/avi.hpp"
#include "vibook/core/precision.hpp"
#include "vibook/epavi/epavi.hpp"
#include "vibook/epavi/mechanical.hpp"
#include "vibook/integrators/kernels.hpp"
#include "vibook/kepler/kepler.hpp"

namespace {

constexpr int kSteps = 300;
constexpr double kE = 0.7, kH0 = 1e-3;

void counters(benchmark::State& state, double iterations) {
  state.counters["ns_per_step"] =
      benchmark::Counter(double(kSteps) * double(state.iterations()) * 1e-9,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["iterations_per_step"] =
      iterations / (double(kSteps) * double(state.iterations()));
}

template <class T, template <class, class> class Stepper = vibook::EpAVI>
void BM_epavi(benchmark::State& state) {
  std::optional<vibook::MpfrDigits> digits;
  if constexpr (std::is_same_v<T, vibook::mpfr_real>) digits.emplace(18);
  const auto orbit = vibook::KeplerOrbit::perihelion(kE);
  const auto s0 = vibook::kepler_perihelion_state(kE);
  const auto q1 = orbit.at(kH0).q;
  double its = 0;
  for (auto _ : state) {
    Stepper<vibook::Kepler, T> m{vibook::Kepler{}};
    auto s = m.start(T(0), vibook::Vec<T, 2>(T(s0.q(0)), T(s0.q(1))), T(kH0),
                     vibook::Vec<T, 2>(T(q1(0)), T(q1(1))));
    for (int k = 0; k < kSteps; ++k) its += m.step(s).root_iterations;
    benchmark::DoNotOptimize(s);
  }
  counters(state, its);
}

template <class Monitor>
void BM_avi(benchmark::State& state) {
  const auto s0 = vibook::kepler_perihelion_state(kE);
  const double H0 = vibook::energy(vibook::Kepler{}, s0.q, s0.p);
  Monitor g = [&] {
    if constexpr (std::is_same_v<Monitor, vibook::MonitorArclength>)
      return vibook::MonitorArclength{H0};
    else
      return vibook::MonitorQuadratic{};
  }();
  vibook::AdaptiveMidpoint<vibook::Kepler, Monitor> m(vibook::Kepler{}, g);
  const vibook::TimedState<2> start{0.0, s0.q, s0.p};
  const double da = m.step_for_first_step(start, kH0);
  double its = 0;
  for (auto _ : state) {
    vibook::TimedState<2> s = start;
    for (int k = 0; k < kSteps; ++k) its += m.step(s, da).iterations;
    benchmark::DoNotOptimize(s);
  }
  counters(state, its);
}

void BM_sv_e07(benchmark::State& state) {
  const auto s0 = vibook::kepler_perihelion_state(kE);
  for (auto _ : state) {
    vibook::StormerVerlet<vibook::Kepler> sv;
    vibook::Vec<double, 2> q = s0.q, p = s0.p;
    for (int k = 0; k < kSteps; ++k) sv.step(q, p, kH0);
    benchmark::DoNotOptimize(q);
    benchmark::DoNotOptimize(p);
  }
  counters(state, 0);
}

void BM_midpoint_e07(benchmark::State& state) {
  const auto s0 = vibook::kepler_perihelion_state(kE);
  double its = 0;
  for (auto _ : state) {
    vibook::ImplicitMidpoint<vibook::Kepler> mp;
    vibook::Vec<double, 2> q = s0.q, p = s0.p;
    for (int k = 0; k < kSteps; ++k) its += mp.step(q, p, kH0).iterations;
    benchmark::DoNotOptimize(q);
    benchmark::DoNotOptimize(p);
  }
  counters(state, its);
}

}  // namespace

BENCHMARK(BM_sv_e07);
BENCHMARK(BM_midpoint_e07);
BENCHMARK(BM_epavi<double, vibook::MechanicalEpAVI>)->Name("BM_epavi_fast_double");
BENCHMARK(BM_epavi<long double, vibook::MechanicalEpAVI>)->Name("BM_epavi_fast_long_double");
BENCHMARK(BM_epavi<dd_real, vibook::MechanicalEpAVI>)->Name("BM_epavi_fast_double_double");
BENCHMARK(BM_epavi<vibook::quad, vibook::MechanicalEpAVI>)->Name("BM_epavi_fast_quad");
BENCHMARK(BM_epavi<double>)->Name("BM_epavi_double");
BENCHMARK(BM_epavi<long double>)->Name("BM_epavi_long_double");
BENCHMARK(BM_epavi<dd_real>)->Name("BM_epavi_double_double");
BENCHMARK(BM_epavi<vibook::quad>)->Name("BM_epavi_quad");
BENCHMARK(BM_epavi<vibook::mpfr_real>)->Name("BM_epavi_mpfr18")->Iterations(1);
BENCHMARK(BM_avi<vibook::MonitorArclength>)->Name("BM_avi1");
BENCHMARK(BM_avi<vibook::MonitorQuadratic>)->Name("BM_avi2");
