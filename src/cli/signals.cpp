// SIGINT, SIGTERM and SIGHUP for the whole command (signals.hpp).
#include "signals.hpp"

#include <pthread.h>
#include <signal.h>

#include <atomic>
#include <cstdlib>
#include <string>
#include <thread>

#include "cli.hpp"
#include "vibook/core/children.hpp"
#include "vibook/core/output_file.hpp"

namespace vibook::cli {

namespace {

std::atomic<int> g_pending{0};
std::atomic<int> g_deferred{0};

sigset_t handled_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  sigaddset(&set, SIGHUP);
  return set;
}

[[noreturn]] void wait_for_signals(sigset_t set) {
  for (;;) {
    int sig = 0;
    if (sigwait(&set, &sig) != 0) continue;
    if (g_deferred.load() > 0) {
      g_pending.store(sig);  // the step loop stops at its next step and keeps FILE.partial
      continue;
    }
    end_child_groups();
    remove_temporaries();
    eprint(std::string("vibook: interrupted by ") + signal_name(sig) +
           "; no output was left half-written (temporary files removed)\n");
    std::_Exit(128 + sig);
  }
}

}  // namespace

const char* signal_name(int signal) {
  switch (signal) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
    default:
      return "a signal";
  }
}

void start_signal_thread() {
  const sigset_t set = handled_signals();
  if (pthread_sigmask(SIG_BLOCK, &set, nullptr) != 0) return;  // the default action stays
  std::thread(wait_for_signals, set).detach();
}

int pending_signal() { return g_pending.load(); }

DeferSignals::DeferSignals() { g_deferred.fetch_add(1); }
DeferSignals::~DeferSignals() { g_deferred.fetch_sub(1); }

}  // namespace vibook::cli
