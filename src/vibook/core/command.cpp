// The process around a command (command.hpp): one-line messages, signals, the watchdog.
#include "vibook/core/command.hpp"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

#include <fmt/format.h>

#include "vibook/core/children.hpp"
#include "vibook/core/output_file.hpp"
#include "vibook/core/progress.hpp"

namespace vibook {

// --- one-line messages ----------------------------------------------------------------------

std::string one_line(const std::string& text) {
  // A progress line (carriage return, escape) is drawn as it is.
  if (text.empty() || text[0] == '\r' || text[0] == '\033') return text;
  const bool newline = text.back() == '\n';
  std::string body = text.substr(0, text.size() - (newline ? 1 : 0));
  for (char& c : body)
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  if (body.size() > kMaxMessage) {
    // The beginning (what failed, which argument) and the end (why) are kept, the middle (an
    // echoed argument, a state) is cut, at character boundaries (not inside a UTF-8
    // sequence), and the cut says so.
    std::size_t head = 150, tail = body.size() - 120;
    while (head > 0 && (static_cast<unsigned char>(body[head]) & 0xC0) == 0x80) --head;
    while (tail < body.size() && (static_cast<unsigned char>(body[tail]) & 0xC0) == 0x80) ++tail;
    body = body.substr(0, head) + fmt::format(" [... {} characters cut ...] ", tail - head) +
           body.substr(tail);
  }
  return newline ? body + '\n' : body;
}

void eprint(const std::string& message) {
  const std::string text = one_line(message);
  // fwrite on a closed descriptor sets the error flag and returns; nothing is thrown.
  (void)std::fwrite(text.data(), 1, text.size(), stderr);
  (void)std::fflush(stderr);
  std::clearerr(stderr);
}

// --- SIGINT, SIGTERM, SIGHUP ----------------------------------------------------------------

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

// --- the watchdog: a progress line and a time limit ----------------------------------------

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

}  // namespace vibook
