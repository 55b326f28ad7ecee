// `vibook run` (run.hpp): what the integration loops of run.cpp and adaptive.cpp share (the
// step plan, the progress line, the messages of a failed step). Internal to the library.
#pragma once

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "vibook/core/errors.hpp"
#include "vibook/core/precision.hpp"
#include "vibook/core/tolerance.hpp"
#include "vibook/problems/problems.hpp"

#include "vibook/run/run.hpp"

namespace vibook::run::detail {

// At most this many steps in one run (a plan of more is a typing error, or a study for the
// benchmarks, not for `vibook run`).
constexpr double kMaxSteps = 1e12;

// Number of steps and the last step's size for a run to t_end with step h: round(T/h) steps
// when T/h is within rounding of an integer (h = T/n ends exactly at T); otherwise ceil(T/h)
// steps, the last one shortened so that the run ends at T. `arg` is named when the plan has no
// step or more than kMaxSteps.
inline std::pair<long long, double> step_plan(double T, double h, const std::string& arg) {
  require_argument(
      h <= T * (1 + 64 * kEps), arg,
      fmt::format("the step {:.6g} is longer than the whole run (to {:.6g}): no step to take", h,
                  T));
  const double ratio = T / h;
  require_argument(
      ratio <= kMaxSteps, arg,
      fmt::format("step {:.3g} up to {:.3g} makes {:.3g} steps, more than the 1e12 a run may "
                  "take",
                  h, T, ratio));
  const double n = std::nearbyint(ratio);
  if (std::abs(ratio - n) <= 64 * kEps * std::max(1.0, ratio)) {
    return {static_cast<long long>(n), h};
  }
  const double full = std::floor(ratio);
  return {static_cast<long long>(full) + 1, T - full * h};
}

inline std::string state_text(const double* q, const double* p, int n) {
  std::string s = "q = (";
  for (int i = 0; i < n; ++i) s += fmt::format("{}{:.17g}", i ? ", " : "", q[i]);
  s += "), p = (";
  for (int i = 0; i < n; ++i) s += fmt::format("{}{:.17g}", i ? ", " : "", p[i]);
  return s + ")";
}

// A computed output value that is not finite ends the run as a numerical failure.
template <class Row>
void require_finite_row(const Row& row, const std::vector<std::string>& cols) {
  for (std::size_t i = 0; i < cols.size(); ++i)
    if (!std::isfinite(row[i]))
      throw NumericalError(fmt::format("the output column {} is not finite ({})", cols[i], row[i]));
}

// A signal the caller records during an integration (Hooks; the command defers SIGINT,
// SIGTERM and SIGHUP to the step loop) is seen at the next step (Progress::update), which stops
// like a failed step, keeping the rows written so far in FILE.partial.

// A failure of the step loop, rethrown with its place and what was kept: an interruption stays
// an interruption (exit 128 + signal), anything else is a numerical failure (exit 3).
[[noreturn]] inline void rethrow_with(const NumericalError& e, const std::string& message) {
  if (const auto* i = dynamic_cast<const Interrupted*>(&e)) throw Interrupted(i->signal(), message);
  throw NumericalError(message);
}

class Progress {
 public:
  Progress(long long total, double max_seconds, const Hooks& hooks)
      : total_(total),
        max_seconds_(max_seconds),
        tty_(::isatty(STDERR_FILENO) != 0),
        hooks_(hooks) {}
  void update(long long k) {
    if (const int s = hooks_.pending_signal(); s != 0)
      throw Interrupted(s, fmt::format("interrupted by {}", hooks_.signal_name(s)));
    if ((k & 0x3ff) != 0 || (!tty_ && max_seconds_ == 0)) return;
    const auto now = std::chrono::steady_clock::now();
    // --max-seconds: the run stops like a failed step (status 3, rows kept in FILE.partial).
    if (max_seconds_ > 0 && std::chrono::duration<double>(now - start_).count() >= max_seconds_)
      throw NumericalError(fmt::format("stopped by --max-seconds {:g}", max_seconds_));
    if (!tty_ || (k & 0x3fff) != 0) return;
    if (now - start_ < std::chrono::seconds(2) || now - last_ < std::chrono::milliseconds(500))
      return;
    last_ = now;
    std::fprintf(stderr, "\rvibook run: step %lld of %lld (%.0f%%)", k, total_,
                 100.0 * double(k) / double(total_));
    shown_ = true;
  }
  ~Progress() {
    if (shown_) std::fprintf(stderr, "\n");
  }

 private:
  long long total_;
  double max_seconds_;
  bool tty_, shown_ = false;
  const Hooks& hooks_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), last_ = start_;
};

template <int N>
Vec<double, N> vector_arg(const std::vector<double>& v, const char* name) {
  require_argument(v.size() == N, name,
                   fmt::format("expects {} comma-separated number(s) for this problem", N));
  Vec<double, N> out;
  for (int i = 0; i < N; ++i) {
    require_argument(std::isfinite(v[i]), name, "values must be finite");
    out(i) = v[i];
  }
  return out;
}

/// Adaptive methods on Kepler (adaptive.cpp): EpAVI in the precision of --precision, AVI1
/// and AVI2 in double.
void integrate_adaptive_kepler(const Settings& o, const Hooks& hooks);

}  // namespace vibook::run::detail
