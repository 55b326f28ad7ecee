// A library stepper (`vibook verify --stepper-lib`) three ways, nanoseconds per step, in one run
// (#50: the library runs in a child process of vibook's, which costs a round trip a request):
//   inprocess — StepperLibrary::run(h, 1) on the library loaded into this process (the limit)
//   host_step — the library's host (a forked child, the line protocol inside), one request a
//               step: what each single step of the order, symmetry and Jacobian phases costs
//   host_every — the same host answering all states of a run in one request (`every`): how the
//               energy phase's 1e5-step runs are taken
// The stepper is Boost.Odeint's McLachlan 4th-order method on Kepler (examples/black_box).
#include <cmath>
#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include "vibook/verify/black_box.hpp"
#include "vibook/verify/line_protocol.hpp"

namespace {

constexpr int kSteps = 4096;
constexpr double kH = 1e-3;
const std::string kArg = "mclachlan4/kepler";

void set_counter(benchmark::State& state) {
  state.counters["ns_per_step"] =
      benchmark::Counter(double(kSteps) * double(state.iterations()) * 1e-9,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

std::unique_ptr<vibook::verify::LineProtocolStepper> host(benchmark::State& state) {
  const std::string lib = VIBOOK_STEPPER_LIB;
  auto h = std::make_unique<vibook::verify::LineProtocolStepper>(
      [lib] { return vibook::verify::serve_stepper_library(lib, kArg, 2); }, 2, 10.0);
  bool ended = false;
  if (const std::string why = h->handshake(ended); !why.empty()) {
    state.SkipWithError(("the host did not start: " + why).c_str());
    return nullptr;
  }
  return h;
}

void BM_black_box_inprocess(benchmark::State& state) {
  vibook::verify::StepperLibrary lib(VIBOOK_STEPPER_LIB, kArg, 2);
  for (auto _ : state) {
    double q[2] = {0.5, 0}, p[2] = {0, std::sqrt(3.0)};
    for (int k = 0; k < kSteps; ++k) lib.run(kH, 1, q, p);
    benchmark::DoNotOptimize(q);
  }
  set_counter(state);
}

void BM_black_box_host_step(benchmark::State& state) {
  const auto h = host(state);
  if (!h) return;
  for (auto _ : state) {
    double q[2] = {0.5, 0}, p[2] = {0, std::sqrt(3.0)};
    for (int k = 0; k < kSteps; ++k) h->run(kH, 1, q, p);
    benchmark::DoNotOptimize(q);
  }
  set_counter(state);
}

void BM_black_box_host_every(benchmark::State& state) {
  const auto h = host(state);
  if (!h) return;
  for (auto _ : state) {
    double q[2] = {0.5, 0}, p[2] = {0, std::sqrt(3.0)};
    double sum = 0;
    h->every(kH, kSteps, q, p, [&] { sum += q[0]; });
    benchmark::DoNotOptimize(sum);
  }
  set_counter(state);
}

}  // namespace

// Wall time: the host's work is done in its child process.
BENCHMARK(BM_black_box_inprocess)->UseRealTime();
BENCHMARK(BM_black_box_host_step)->UseRealTime();
BENCHMARK(BM_black_box_host_every)->UseRealTime();
