// A black-box stepper behind the C ABI (black_box.hpp, stepper_abi.h).
#include "vibook/verify/black_box.hpp"

#include <dlfcn.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <memory>
#include <vector>

#include <fmt/format.h>

#include "vibook/core/errors.hpp"
#include "vibook/verify/stepper_abi.h"

namespace vibook::verify {

StepperLibrary::StepperLibrary(const std::string& path, const std::string& arg, int dof) {
  // A bare name would be searched on the library path; the user means the file.
  const std::string file = path.find('/') == std::string::npos ? "./" + path : path;
  struct stat st {};
  if (::stat(file.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
    throw ArgumentError("--stepper-lib", "'" + path + "' is not a file");
  handle_ = ::dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle_) {
    const char* e = ::dlerror();
    throw ArgumentError("--stepper-lib",
                        "cannot be loaded: " + std::string(e ? e : "dlopen failed"));
  }
  auto need = [&](const char* name) {
    void* s = ::dlsym(handle_, name);
    if (!s)
      throw ArgumentError("--stepper-lib", fmt::format("'{}' does not export {} (the vibook "
                                                       "stepper ABI: vibook/verify/stepper_abi.h)",
                                                       path, name));
    return s;
  };
  auto version = reinterpret_cast<int (*)()>(need("vibook_stepper_abi_version"));
  version_ = version();
  if (version_ != 1 && version_ != 2)
    throw ArgumentError("--stepper-lib", fmt::format("'{}' implements stepper ABI version {}; "
                                                     "this vibook speaks versions 1 and {}",
                                                     path, version_, VIBOOK_STEPPER_ABI_VERSION));
  auto create = reinterpret_cast<void* (*)(int, const char*)>(need("vibook_stepper_create"));
  if (version_ == 1)
    step_ = reinterpret_cast<int (*)(void*, double, double*, double*)>(need("vibook_stepper_step"));
  else
    step_t_ = reinterpret_cast<int (*)(void*, double, double, double*, double*)>(
        need("vibook_stepper_step_t"));
  destroy_ = reinterpret_cast<void (*)(void*)>(need("vibook_stepper_destroy"));
  message_ = reinterpret_cast<const char* (*)(void*)>(::dlsym(handle_, "vibook_stepper_message"));
  context_ = create(dof, arg.c_str());
  if (!context_)
    throw ArgumentError("--stepper-lib",
                        fmt::format("vibook_stepper_create({}, \"{}\") returned NULL{}", dof, arg,
                                    reason(nullptr)));
}

StepperLibrary::~StepperLibrary() {
  if (context_) destroy_(context_);
  if (handle_) ::dlclose(handle_);
}

void StepperLibrary::run(double h, long long n, double* q, double* p) {
  for (long long k = 0; k < n; ++k) {
    if (step_t_) {  // version 2: the step's start time, t_ + k h
      if (const int status = step_t_(context_, t_ + double(k) * h, h, q, p); status != 0)
        throw NumericalError(
            fmt::format("vibook_stepper_step_t returned {}{}", status, reason(context_)));
      continue;
    }
    if (const int status = step_(context_, h, q, p); status != 0)
      throw NumericalError(
          fmt::format("vibook_stepper_step returned {}{}", status, reason(context_)));
  }
}

std::string StepperLibrary::reason(void* context) const {
  const char* m = message_ ? message_(context) : nullptr;
  return m && *m ? std::string(": ") + m : std::string();
}

namespace {

bool write_fd(int fd, const std::string& s) {
  std::size_t done = 0;
  while (done < s.size()) {
    const ssize_t w = ::write(fd, s.data() + done, s.size() - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    done += static_cast<std::size_t>(w);
  }
  return true;
}

}  // namespace

int serve_stepper_library(const std::string& path, const std::string& arg, int dof) {
  // The protocol's answers on a descriptor of their own; the library's prints to standard
  // output go where its standard error goes (captured by vibook), never into an answer.
  const int answers = ::dup(1);
  ::dup2(2, 1);
  // A library that aborts ends this child with a status vibook reports; no core file is left.
  const rlimit no_core{0, 0};
  ::setrlimit(RLIMIT_CORE, &no_core);
  std::unique_ptr<StepperLibrary> lib;
  try {
    lib = std::make_unique<StepperLibrary>(path, arg, dof);
  } catch (const ArgumentError& e) {
    std::string why = e.what();
    const std::string prefix = e.argument() + ": ";
    if (why.rfind(prefix, 0) == 0) why.erase(0, prefix.size());
    write_fd(answers, "error " + why + "\n");
    return 2;
  }
  if (!write_fd(answers, fmt::format("ready abi {}\n", lib->abi_version()))) return 0;
  std::string buf;
  std::vector<double> q(static_cast<std::size_t>(dof)), p(static_cast<std::size_t>(dof));
  char chunk[4096];
  while (true) {
    const auto nl = buf.find('\n');
    if (nl == std::string::npos) {
      const ssize_t got = ::read(0, chunk, sizeof chunk);
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) return 0;  // end of input: vibook is done
      buf.append(chunk, static_cast<std::size_t>(got));
      continue;
    }
    const std::string line = buf.substr(0, nl);
    buf.erase(0, nl + 1);
    // "h n q_1 … q_d p_1 … p_d", as vibook writes it; "every h n …": the state after each
    // of the n steps, one line each, ending at an "error" line if a step fails
    const bool every = line.rfind("every ", 0) == 0;
    const char* s = line.c_str() + (every ? 6 : 0);
    char* end = nullptr;
    double t0 = 0;
    if (lib->takes_time()) {  // protocol 2: the start time first
      t0 = std::strtod(s, &end);
      lib->set_time(t0);
      s = end;
    }
    const double h = std::strtod(s, &end);
    s = end;
    const long long n = std::strtoll(s, &end, 10);
    s = end;
    for (int i = 0; i < 2 * dof; ++i) {
      (i < dof ? q[static_cast<std::size_t>(i)] : p[static_cast<std::size_t>(i - dof)]) =
          std::strtod(s, &end);
      s = end;
    }
    std::string answer;
    auto state = [&] {
      for (int i = 0; i < dof; ++i)
        answer += fmt::format("{}{:.17g}", i ? " " : "", q[static_cast<std::size_t>(i)]);
      for (int i = 0; i < dof; ++i)
        answer += fmt::format(" {:.17g}", p[static_cast<std::size_t>(i)]);
      answer += '\n';
    };
    auto failed = [&](const std::exception& e) {
      std::string why = std::string("error ") + e.what();
      for (char& c : why)
        if (c == '\n' || c == '\r') c = ' ';
      answer += why + "\n";
    };
    if (!every) {
      try {
        lib->run(h, n, q.data(), p.data());
        state();
      } catch (const std::exception& e) {
        failed(e);
      }
      if (!write_fd(answers, answer)) return 0;
      continue;
    }
    // The lines go out in blocks of up to 32 kB, and at least every 50 ms, so that vibook's
    // timeout on each line holds for a slow library too.
    auto sent = std::chrono::steady_clock::now();
    for (long long k = 0; k < n; ++k) {
      bool ok = true;
      try {
        lib->set_time(t0 + double(k) * h);
        lib->run(h, 1, q.data(), p.data());
        state();
      } catch (const std::exception& e) {
        failed(e);
        ok = false;
      }
      const auto now = std::chrono::steady_clock::now();
      if (!ok || k + 1 == n || answer.size() > 32768 ||
          now - sent > std::chrono::milliseconds(50)) {
        if (!write_fd(answers, answer)) return 0;
        answer.clear();
        sent = now;
      }
      if (!ok) break;
    }
  }
}

}  // namespace vibook::verify
