// Progress line and time limit (watchdog.hpp).
#include "watchdog.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdlib>

#include <fmt/format.h>

#include "cli.hpp"
#include "vibook/core/children.hpp"
#include "vibook/core/output_file.hpp"
#include "vibook/core/progress.hpp"

namespace vibook::cli {

Watchdog::Watchdog(std::string command, double max_seconds, bool show_progress)
    : command_(std::move(command)),
      max_seconds_(max_seconds),
      tty_(::isatty(STDERR_FILENO) != 0),
      forced_(show_progress) {
  progress::set_stage("starting");
  thread_ = std::thread([this] { watch(); });
}

Watchdog::~Watchdog() {
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  cv_.notify_all();
  thread_.join();
  if (drawn_) eprint("\r\033[K");
}

void Watchdog::watch() {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto last_line = start;
  std::unique_lock lock(mutex_);
  for (;;) {
    if (cv_.wait_for(lock, std::chrono::milliseconds(100), [this] { return stop_; })) return;
    const auto now = Clock::now();
    const double elapsed = std::chrono::duration<double>(now - start).count();
    if (max_seconds_ > 0 && elapsed >= max_seconds_) {
      end_child_groups();
      remove_temporaries();
      eprint(fmt::format("{}vibook: numerical failure: {} stopped by --max-seconds {:g} in: {}\n",
                         drawn_ ? "\r\033[K" : "", command_, max_seconds_, progress::stage()));
      std::_Exit(kNumerical);
    }
    if (elapsed < 2) continue;
    if (tty_) {
      if (now - last_line < std::chrono::milliseconds(500)) continue;
      eprint(fmt::format("\r\033[Kvibook {}: {:.0f} s: {}", command_, elapsed, progress::stage()));
      drawn_ = true;
    } else if (forced_) {
      if (now - last_line < std::chrono::seconds(5)) continue;
      eprint(fmt::format("vibook {}: {:.0f} s: {}\n", command_, elapsed, progress::stage()));
    } else {
      continue;
    }
    last_line = now;
  }
}

}  // namespace vibook::cli
