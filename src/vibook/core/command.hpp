/// \file command.hpp
/// \brief What a command-line program built on vibook shares with the `vibook` command: its exit
/// statuses, its one-line messages to standard error, its handling of SIGINT, SIGTERM and
/// SIGHUP (temporaries removed, status 128 + N) and the watchdog of its long commands (a
/// progress line, a time limit). The command (src/cli/) parses options and prints; this is the
/// process around it.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <string>
#include <thread>

namespace vibook {

/// Exit statuses, the same for every command (README): 0 success, 1 other failure (gnuplot
/// missing), 2 bad argument, 3 numerical failure, 4 an output could not be written, 5 `vibook
/// verify` ran to the end and a verdict failed (the report names which).
enum Exit : int { kOk = 0, kFailure = 1, kBadArgument = 2, kNumerical = 3, kIo = 4, kVerdict = 5 };

/// One message to standard error that never throws and never aborts: a closed or full stderr
/// loses the message but not the exit status (every error path of the command goes through it).
/// A message is one line: its newlines and tabs become spaces, and past kMaxMessage characters
/// it is cut, saying how long it was (an argument or a library's message echoed whole made
/// screen-wide "lines"; the JSON of --json-out keeps every reason whole).
void eprint(const std::string& text);
/// The message as eprint writes it.
std::string one_line(const std::string& text);
inline constexpr std::size_t kMaxMessage = 300;

/// Blocks SIGINT, SIGTERM and SIGHUP in the calling thread (and so in every thread it starts
/// later) and starts one thread that waits for them. Call once, first thing in main.
///
/// A signal then ends the process from that thread, whatever the others are doing: the
/// temporaries of output files and directories are removed (output_file.hpp), one line on
/// standard error names the signal, and the status is 128 + signal. Nothing hidden is left
/// behind, and no final name was ever half-written. While a DeferSignals object lives (the
/// step loop of `vibook run`), the signal is recorded instead, for the loop to see at its next
/// step (pending_signal) and to stop there keeping its rows in FILE.partial.
void start_signal_thread();

/// The signal recorded while deferred, or 0.
int pending_signal();

/// The name of a signal the thread handles ("SIGINT", "SIGTERM", "SIGHUP").
const char* signal_name(int signal);

/// Defers the signals to the step loop while it lives (see start_signal_thread).
class DeferSignals {
 public:
  DeferSignals();
  ~DeferSignals();
  DeferSignals(const DeferSignals&) = delete;
  DeferSignals& operator=(const DeferSignals&) = delete;
};

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

}  // namespace vibook
