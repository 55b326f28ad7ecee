// The line protocol's child process, held at arm's length (line_protocol.hpp).
#include "vibook/verify/line_protocol.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <vector>

#include <fmt/format.h>

#include "vibook/core/children.hpp"
#include "vibook/core/errors.hpp"

namespace vibook::verify {

namespace {

double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

int ms_until(double deadline_s) {
  const double left = deadline_s - now_s();
  return left <= 0 ? 0 : static_cast<int>(std::ceil(std::min(left, 1e6) * 1000));
}

// At most `n` characters of s on one line: control characters shown as spaces.
std::string one_line(std::string s, std::size_t n = 160) {
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  if (s.size() > n) s = s.substr(0, n) + "...";
  return s;
}

}  // namespace

LineProtocolStepper::LineProtocolStepper(const std::string& cmd, int dof, double timeout,
                                         int protocol)
    : dof_(dof), timeout_(timeout), protocol_(protocol) {
  start([&cmd] {
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  });
}

LineProtocolStepper::LineProtocolStepper(const std::function<int()>& serve, int dof, double timeout)
    : dof_(dof), timeout_(timeout) {
  start([&serve] { ::_exit(serve()); });
  serves_every_ = true;
}

std::string LineProtocolStepper::handshake(bool& ended) {
  ended = false;
  try {
    const std::string line = read_line(now_s() + timeout_);
    if (line == "ready") return {};
    if (line == "ready abi 1" ||
        line == "ready abi 2") {  // a library's host (serve_stepper_library)
      abi_version_ = line.back() - '0';
      protocol_ = abi_version_;  // a library of version 2 is asked with the time first
      return {};
    }
    if (line.rfind("error ", 0) == 0) return one_line(line.substr(6), 1000);
    return "it announced '" + one_line(line, 60) + "', not 'ready'";
  } catch (const NumericalError& e) {
    ended = true;
    return e.what();
  }
}

void LineProtocolStepper::start(const std::function<void()>& child) {
  int in[2], out[2], err[2];
  if (::pipe2(in, O_CLOEXEC) != 0) throw NumericalError("pipe: " + std::string(strerror(errno)));
  if (::pipe2(out, O_CLOEXEC) != 0 || ::pipe2(err, O_CLOEXEC) != 0) {
    ::close(in[0]);
    ::close(in[1]);
    throw NumericalError("pipe: " + std::string(strerror(errno)));
  }
  pid_ = ::fork();
  if (pid_ < 0) throw NumericalError("fork: " + std::string(strerror(errno)));
  if (pid_ == 0) {
    ::setpgid(0, 0);  // a group of its own: ended whole, with anything it forks
    ::dup2(in[0], 0);
    ::dup2(out[1], 1);
    ::dup2(err[1], 2);
    ::signal(SIGPIPE, SIG_DFL);  // vibook ignores it; the stepper gets the usual default
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);  // vibook blocks its handled signals
    child();
    ::_exit(127);
  }
  ::setpgid(pid_, pid_);  // also here: whichever runs first (EACCES after exec is harmless)
  register_child_group(pid_);
  ::close(in[0]);
  ::close(out[1]);
  ::close(err[1]);
  to_ = in[1];
  from_ = out[0];
  err_ = err[0];
  for (int fd : {to_, from_, err_}) ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
}

void LineProtocolStepper::end() {
  if (to_ >= 0) ::close(to_);  // end of input: the stepper should exit
  to_ = -1;
  if (pid_ > 0) {
    // Up to 2 s for the stepper to exit by itself, then the whole group is killed; the group
    // is killed even when it did exit, for anything it forked and left behind.
    for (int i = 0; i < 200 && !reaped_; ++i) {
      if (::waitpid(pid_, nullptr, WNOHANG) == pid_) reaped_ = true;
      if (!reaped_) {
        pump(0);  // keep its output pipes from filling while it winds down
        ::usleep(10000);
      }
    }
    ::kill(-pid_, SIGKILL);
    if (!reaped_) ::waitpid(pid_, nullptr, 0);
    reaped_ = true;
    unregister_child_group(pid_);
    pid_ = -1;
  }
  if (from_ >= 0) ::close(from_);
  if (err_ >= 0) ::close(err_);
  from_ = err_ = -1;
}

LineProtocolStepper::~LineProtocolStepper() { end(); }

void LineProtocolStepper::fail(const std::string& why) {
  std::string msg = why;
  pump(0);
  std::string tail = err_tail_;
  while (!tail.empty() && (tail.back() == '\n' || tail.back() == '\r' || tail.back() == ' '))
    tail.pop_back();
  if (const auto nl = tail.rfind('\n'); nl != std::string::npos) tail = tail.substr(nl + 1);
  if (!tail.empty()) msg += " (its last line on stderr: '" + one_line(tail) + "')";
  if (killed_) throw StepperKilled(msg);
  throw NumericalError(msg);
}

std::string LineProtocolStepper::exited() {
  int status = 0;
  for (int i = 0; i < 50 && !reaped_; ++i) {
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
      reaped_ = true;
      if (WIFEXITED(status))
        return fmt::format("the stepper exited with status {}", WEXITSTATUS(status));
      killed_ = WIFSIGNALED(status);
      if (WIFSIGNALED(status))
        return fmt::format("the stepper was killed by signal {}{}", WTERMSIG(status),
                           sigabbrev_np(WTERMSIG(status))
                               ? fmt::format(" (SIG{})", sigabbrev_np(WTERMSIG(status)))
                               : std::string());
    }
    ::usleep(10000);
  }
  return "the stepper closed its output";
}

void LineProtocolStepper::pump(int timeout_ms) {
  pollfd fds[2] = {{from_, POLLIN, 0}, {err_, POLLIN, 0}};
  const int r = ::poll(fds, 2, timeout_ms);
  if (r <= 0) return;
  char chunk[4096];
  if (err_ >= 0 && (fds[1].revents & (POLLIN | POLLHUP))) {
    const ssize_t got = ::read(err_, chunk, sizeof chunk);
    if (got > 0) {
      err_tail_.append(chunk, static_cast<std::size_t>(got));
      if (err_tail_.size() > 8192) err_tail_.erase(0, err_tail_.size() - 4096);
    } else if (got == 0) {
      ::close(err_);
      err_ = -1;
    }
  }
  if (from_ >= 0 && (fds[0].revents & (POLLIN | POLLHUP))) {
    const ssize_t got = ::read(from_, chunk, sizeof chunk);
    if (got > 0) {
      buf_.append(chunk, static_cast<std::size_t>(got));
    } else if (got == 0) {
      ::close(from_);
      from_ = -1;
    }
  }
}

void LineProtocolStepper::write_all(const std::string& s, double deadline_s) {
  std::size_t done = 0;
  while (done < s.size()) {
    const ssize_t w = ::write(to_, s.data() + done, s.size() - done);
    if (w > 0) {
      done += static_cast<std::size_t>(w);
      continue;
    }
    if (w < 0 && errno == EINTR) continue;
    if (w < 0 && errno != EAGAIN)
      fail(exited() + " (a request could not be written: " + strerror(errno) + ")");
    // Its input is full: it is not reading. Wait for room, reading its output meanwhile.
    if (ms_until(deadline_s) == 0)
      fail(fmt::format("the stepper did not read its request within {:g} s (--stepper-timeout)",
                       timeout_));
    pollfd pfd{to_, POLLOUT, 0};
    ::poll(&pfd, 1, std::min(ms_until(deadline_s), 50));
    pump(0);
    if (buf_.size() > kMaxLine) fail("the stepper writes more than it was asked for (1 MiB)");
  }
}

std::string LineProtocolStepper::read_line(double deadline_s, bool more_may_follow) {
  while (true) {
    if (const auto nl = buf_.find('\n'); nl != std::string::npos) {
      std::string line = buf_.substr(0, nl);
      buf_.erase(0, nl + 1);
      if (!buf_.empty() && !more_may_follow)
        fail(
            "the stepper answered more than one line to a request (line protocol 1: one "
            "line an answer)");
      return line;
    }
    if (buf_.size() > kMaxLine) fail("the stepper's answer exceeds 1 MiB without a newline");
    if (from_ < 0) fail(exited() + " before answering");
    const int ms = ms_until(deadline_s);
    if (ms == 0)
      fail(fmt::format("the stepper did not answer within {:g} s (--stepper-timeout)", timeout_));
    pump(ms);
  }
}

void LineProtocolStepper::request(const std::string& head, double h, long long n, const double* q,
                                  const double* p, double deadline_s) {
  if (pid_ <= 0) fail("the stepper has ended");
  // Anything on its output before a request is a line it was not asked for.
  pump(0);
  if (!buf_.empty())
    fail("the stepper wrote '" + one_line(buf_, 60) + "' without a request (line protocol 1)");
  std::string req = head;
  if (protocol_ == 2) req += fmt::format("{:.17g} ", t_);
  req += fmt::format("{:.17g} {}", h, n);
  for (int i = 0; i < dof_; ++i) req += fmt::format(" {:.17g}", q[i]);
  for (int i = 0; i < dof_; ++i) req += fmt::format(" {:.17g}", p[i]);
  req += '\n';
  write_all(req, deadline_s);
}

std::optional<std::string> LineProtocolStepper::parse_answer(const std::string& answer, double* q,
                                                             double* p) {
  auto protocol = [&](const std::string& what) {
    fail("the stepper's answer " + what + " (line protocol 1: 'q_1 ... q_d p_1 ... p_d'): '" +
         one_line(answer, 120) + "'");
  };
  if (answer.find('\0') != std::string::npos) protocol("holds a NUL byte");
  if (answer.rfind("error", 0) == 0) {
    std::string why = answer.substr(5);
    why.erase(0, why.find_first_not_of(" :\t"));
    return why;
  }
  std::vector<double> v;
  const char* s = answer.c_str();
  while (true) {
    while (*s == ' ' || *s == '\t' || *s == '\r') ++s;
    if (!*s) break;
    char* end = nullptr;
    errno = 0;
    const double x = std::strtod(s, &end);
    if (end == s || (*end && *end != ' ' && *end != '\t' && *end != '\r'))
      protocol("is not a list of numbers");
    v.push_back(x);
    s = end;
  }
  if (v.size() != static_cast<std::size_t>(2 * dof_))
    protocol(fmt::format("has {} numbers, not 2 x {} (q then p)", v.size(), dof_));
  for (int i = 0; i < dof_; ++i) {
    q[i] = v[static_cast<std::size_t>(i)];
    p[i] = v[static_cast<std::size_t>(dof_ + i)];
  }
  return std::nullopt;
}

void LineProtocolStepper::run(double h, long long n, double* q, double* p) {
  const double deadline = now_s() + timeout_;
  request("", h, n, q, p, deadline);
  const std::string answer = read_line(deadline);
  if (const auto why = parse_answer(answer, q, p))
    fail("the stepper answered 'error'" + (why->empty() ? "" : ": " + one_line(*why)));
}

void LineProtocolStepper::every(double h, long long n, double* q, double* p,
                                const std::function<void()>& each) {
  if (!serves_every_) {
    BlackBox::every(h, n, q, p, each);
    return;
  }
  // One request; n lines, each within the timeout, an "error" line ending the answer early.
  request("every ", h, n, q, p, now_s() + timeout_);
  for (long long k = 0; k < n; ++k) {
    const std::string line = read_line(now_s() + timeout_, k + 1 < n);
    if (const auto why = parse_answer(line, q, p))
      fail("the stepper answered 'error'" + (why->empty() ? "" : ": " + one_line(*why)));
    try {
      each();
    } catch (...) {
      // The caller stops here (a state it refuses): the rest of this answer is read and
      // dropped, so that the next request starts clean.
      std::vector<double> rest(static_cast<std::size_t>(2 * dof_));
      for (long long j = k + 1; j < n; ++j)
        if (parse_answer(read_line(now_s() + timeout_, j + 1 < n), rest.data(), rest.data() + dof_))
          break;
      throw;
    }
  }
}

}  // namespace vibook::verify
