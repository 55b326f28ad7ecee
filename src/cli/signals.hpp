// SIGINT, SIGTERM and SIGHUP for the whole `vibook` command (README: exit status 128 + N).
#pragma once

namespace vibook::cli {

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

}  // namespace vibook::cli
