/// \file line_protocol.hpp
/// \brief A black-box stepper behind the line protocol: a child process (`sh -c CMD`) that
/// reads requests `H N q_1 … q_d p_1 … p_d` on its standard input and answers one line
/// `q_1 … q_d p_1 … p_d` (or `error REASON`) on its standard output (`vibook verify
/// --stepper-cmd`, chapter "Verify your own integrator", "Any stepper as a black box").
///
/// The child is held at arm's length: it runs in a process group of its own, which is ended
/// (SIGKILL to the group, so also anything it forked) on every way out, the destructor's and
/// vibook's exits through end_child_groups() (core/children.hpp). Requests are written without
/// blocking and answers read with bounds, all within the timeout: an answer longer than 1 MiB,
/// a line it was not asked for, or a stepper that stops reading its input is an error, never a
/// hang. Its standard error is captured, not passed through; its last line is added to the
/// message of any failure.
#pragma once

#include <sys/types.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "vibook/core/errors.hpp"
#include "vibook/verify/black_box.hpp"

namespace vibook::verify {

/// The stepper's process was killed by a signal (an abort(), a segmentation fault, a bus
/// error): a numerical failure of the method's code, status 3 even at its first step.
class StepperKilled : public NumericalError {
 public:
  using NumericalError::NumericalError;
};

class LineProtocolStepper final : public BlackBox {
 public:
  /// Start `sh -c cmd`; `dof` degrees of freedom; `timeout` seconds for each answer; `protocol`
  /// 1 (requests `H N q p`) or 2 (requests `T H N q p`, T the time the first of the N steps
  /// starts at: a time-dependent system).
  LineProtocolStepper(const std::string& cmd, int dof, double timeout, int protocol = 1);
  /// Start a child that runs `serve` (forked, not executed) and exits with its value: the
  /// child's standard input and output carry the protocol, its standard error is captured.
  /// `serve` runs in the child only.
  LineProtocolStepper(const std::function<int()>& serve, int dof, double timeout);

  /// The first line of a child that announces itself (`ready`, or `error REASON`), within the
  /// timeout: "" for ready, else why not: its reason, or (`ended` set) how it ended, e.g. killed
  /// by SIGBUS while loading. Never throws for what the child did.
  std::string handshake(bool& ended);
  /// The ABI version of a library's host, from its handshake (`ready abi V`); 0 otherwise.
  int abi_version() const { return abi_version_; }
  ~LineProtocolStepper() override;
  LineProtocolStepper(const LineProtocolStepper&) = delete;
  LineProtocolStepper& operator=(const LineProtocolStepper&) = delete;

  void run(double h, long long n, double* q, double* p) override;
  bool takes_time() const override { return protocol_ == 2; }
  void set_time(double t) override { t_ = t; }
  /// A child started with `serve` (a library's host) answers all n states in one request
  /// (`every h n q p`, one line a state; the library takes the same calls as n single steps);
  /// a command, n single steps (line protocol 1 has no such request).
  void every(double h, long long n, double* q, double* p,
             const std::function<void()>& each) override;

  /// The largest answer line read (bytes).
  static constexpr std::size_t kMaxLine = std::size_t(1) << 20;

 private:
  void start(const std::function<void()>& child);
  [[noreturn]] void fail(const std::string& why);
  std::string exited();
  void pump(int timeout_ms);  // read what is there on stdout and stderr, waiting up to timeout
  void write_all(const std::string& s, double deadline_s);
  std::string read_line(double deadline_s, bool more_may_follow = false);
  void request(const std::string& head, double h, long long n, const double* q, const double* p,
               double deadline_s);
  // An answer line: its state into q, p, or its reason when it is "error ..." (returned, not
  // thrown); any other line is a protocol error (thrown).
  std::optional<std::string> parse_answer(const std::string& answer, double* q, double* p);
  void end();

  int dof_;
  double timeout_;
  int protocol_ = 1;
  int abi_version_ = 0;
  double t_ = 0;  ///< protocol 2: the start time of the next request
  pid_t pid_ = -1;
  int to_ = -1, from_ = -1, err_ = -1;
  std::string buf_, err_tail_;
  bool reaped_ = false;
  bool killed_ = false;        // it ended by a signal (exited() found out)
  bool serves_every_ = false;  // a library's host: `every` is one request
};

}  // namespace vibook::verify
