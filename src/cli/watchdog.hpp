// A progress line and a time limit for the long commands (`modified`, `verify`).
#pragma once

#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace vibook::cli {

/// While it lives, a thread watches the command:
/// - after 2 s, a progress line on standard error with the elapsed time and the current stage
///   (vibook/core/progress.hpp): redrawn in place every half second when standard error is a
///   terminal; when it is not, only if `show_progress` (`--progress`), one line every 5 s;
/// - after `max_seconds` (0: no limit), the command ends: temporaries removed, one line naming
///   the limit and the stage reached, exit status 3 (a numerical failure: the computation did
///   not finish in the time allowed).
class Watchdog {
 public:
  Watchdog(std::string command, double max_seconds, bool show_progress);
  ~Watchdog();
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

 private:
  void watch();

  std::string command_;
  double max_seconds_;
  bool tty_, forced_;
  std::mutex mutex_;
  std::condition_variable cv_;
  bool stop_ = false;
  bool drawn_ = false;  // a progress line is on the terminal (cleared at the end)
  std::thread thread_;
};

}  // namespace vibook::cli
