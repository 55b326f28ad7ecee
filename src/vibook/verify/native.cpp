// Native code from a tape (tape.hpp, load_native): C source, the system compiler, a cache, dlopen.
#include "vibook/verify/tape.hpp"

#include <dlfcn.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>
#include <vector>

extern char** environ;

namespace vibook::verify {

namespace {

namespace fs = std::filesystem;

// The statements of the instructions `ks` of a tape, in that order.
void segment(std::string& out, const Tape& t, const char* name, const std::vector<int>& ks) {
  out += "void ";
  out += name;
  out += "(double* restrict w) {\n";
  static const char* const binary[] = {"+", "-", "*", "/"};
  for (int k : ks) {
    const Tape::Instruction& I = t.code()[k];
    const std::string a = "w[" + std::to_string(I.a) + "]", b = "w[" + std::to_string(I.b) + "]";
    out += "  w[" + std::to_string(t.result_of(k)) + "] = ";
    switch (I.op) {
      case Tape::Op::add:
      case Tape::Op::sub:
      case Tape::Op::mul:
      case Tape::Op::div:
        out += a + " " + binary[int(I.op)] + " " + b;
        break;
      case Tape::Op::neg:
        out += "-" + a;
        break;
      case Tape::Op::sin:
        out += "sin(" + a + ")";
        break;
      case Tape::Op::cos:
        out += "cos(" + a + ")";
        break;
      case Tape::Op::exp:
        out += "exp(" + a + ")";
        break;
      case Tape::Op::log:  // off the domain: NaN, as the interpreter
        out += "vb_log(" + a + ")";
        break;
      case Tape::Op::sqrt:
        out += "vb_sqrt(" + a + ")";
        break;
    }
    out += ";\n";
  }
  out += "}\n";
}

// Instructions [from, to) of a tape.
void segment(std::string& out, const Tape& t, const char* name, int from, int to) {
  std::vector<int> ks;
  for (int k = from; k < to; ++k) ks.push_back(k);
  segment(out, t, name, ks);
}

std::uint64_t fnv1a(const std::string& s) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

fs::path cache_dir() {
  if (const char* d = std::getenv("VIBOOK_CACHE_DIR"); d && *d) return fs::path(d) / "tapes";
  if (const char* d = std::getenv("XDG_CACHE_HOME"); d && *d)
    return fs::path(d) / "vibook" / "tapes";
  if (const char* d = std::getenv("HOME"); d && *d)
    return fs::path(d) / ".cache" / "vibook" / "tapes";
  return {};
}

// Run argv with stdout and stderr to /dev/null; true when it exits 0 within `seconds`.
bool run(const std::vector<std::string>& argv, double seconds, std::string& reason) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, args[0], &fa, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) {
    reason = "no C compiler '" + argv[0] + "' (set VIBOOK_CC)";
    return false;
  }
  const auto start = std::chrono::steady_clock::now();
  int status = 0;
  for (;;) {
    const pid_t r = waitpid(pid, &status, WNOHANG);
    if (r == pid) break;
    if (r < 0) {
      reason = "waiting for the C compiler failed";
      return false;
    }
    if (std::chrono::steady_clock::now() - start > std::chrono::duration<double>(seconds)) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      reason = "the C compiler did not finish in " + std::to_string(int(seconds)) + " s";
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    reason = "the C compiler '" + argv[0] + "' failed on the generated code";
    return false;
  }
  return true;
}

}  // namespace

std::string native_source(const Tape& newton, const Tape& momentum) {
  std::string s =
      "/* vibook: a compiled discrete Lagrangian (verify/native.hpp), generated */\n"
      "#include <math.h>\n"
      "static double vb_sqrt(double a) { return a >= 0 ? sqrt(a) : NAN; }\n"
      "static double vb_log(double a) { return a > 0 ? log(a) : NAN; }\n";
  segment(s, newton, "vibook_newton_prefix", 0, newton.prefix());
  segment(s, newton, "vibook_newton_prefix_carried", newton.carried_prefix());
  segment(s, newton, "vibook_newton_first", newton.prefix(), newton.first_part());
  segment(s, newton, "vibook_newton_rest", newton.first_part(), newton.instructions());
  segment(s, momentum, "vibook_momentum", 0, momentum.instructions());
  return s;
}

NativeTapes load_native(const Tape& newton, const Tape& momentum, std::string& reason) {
  NativeTapes n;
  if (const char* e = std::getenv("VIBOOK_NATIVE"); e && std::string(e) == "0") {
    reason = "VIBOOK_NATIVE=0";
    return n;
  }
  const char* cc_env = std::getenv("VIBOOK_CC");
  const std::string cc = cc_env && *cc_env ? cc_env : "cc";
  const std::vector<std::string> flags = {
      "-O2",     "-fPIC", "-shared", "-fno-fast-math", "-ffp-contract=off", "-fno-math-errno",
      "-std=c99"};
  const std::string source = native_source(newton, momentum);
  std::string key = source + "\n" + cc;
  for (const auto& f : flags) key += " " + f;
  char name[17];
  std::snprintf(name, sizeof name, "%016llx", static_cast<unsigned long long>(fnv1a(key)));
  const fs::path dir = cache_dir();
  if (dir.empty()) {
    reason = "no cache directory (set VIBOOK_CACHE_DIR)";
    return n;
  }
  std::error_code ec;
  fs::create_directories(dir, ec);
  const fs::path so = dir / (std::string(name) + ".so");
  if (!fs::is_regular_file(so, ec)) {
    // Compile into temporaries and rename into place: a concurrent run sees either nothing or
    // a finished object, never a half-written one.
    const std::string cannot_write = "cannot write in the cache " + dir.string();
    std::string c_file = (dir / (std::string(name) + ".XXXXXX.c")).string();
    std::string so_tmp = so.string() + ".XXXXXX.tmp";
    const int fd = mkstemps(c_file.data(), 2);
    if (fd < 0) {
      reason = cannot_write;
      return n;
    }
    const bool written = ::write(fd, source.data(), source.size()) == ssize_t(source.size());
    const bool closed = ::close(fd) == 0;
    const int so_fd = written && closed ? mkstemps(so_tmp.data(), 4) : -1;
    bool ok = so_fd >= 0;
    if (ok) {
      ::close(so_fd);  // the compiler writes it
      std::vector<std::string> argv = {cc};
      argv.insert(argv.end(), flags.begin(), flags.end());
      argv.insert(argv.end(), {"-o", so_tmp, c_file, "-lm"});
      ok = run(argv, 60, reason);
      if (ok) {
        fs::rename(so_tmp, so, ec);
        if (ec) {
          ok = false;
          reason = cannot_write;
        }
      }
    } else {
      reason = cannot_write;
    }
    fs::remove(c_file, ec);
    if (!ok) {
      if (so_fd >= 0) fs::remove(so_tmp, ec);
      return n;
    }
  }
  void* h = dlopen(so.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!h) {
    reason = "cannot load " + so.string();
    return n;
  }
  n.library = std::shared_ptr<void>(h, [](void* p) { dlclose(p); });
  auto sym = [&](const char* s) {  // object pointer to function pointer, without a cast
    NativeTapes::Fn f = nullptr;
    void* p = dlsym(h, s);
    std::memcpy(&f, &p, sizeof f);
    return f;
  };
  n.newton_prefix = sym("vibook_newton_prefix");
  n.newton_prefix_carried = sym("vibook_newton_prefix_carried");
  n.newton_first = sym("vibook_newton_first");
  n.newton_rest = sym("vibook_newton_rest");
  n.momentum = sym("vibook_momentum");
  n.path = so.string();
  if (!n.newton_prefix || !n.newton_prefix_carried || !n.newton_first || !n.newton_rest ||
      !n.momentum) {
    reason = so.string() + " lacks the tape's functions";
    return NativeTapes{};
  }
  return n;
}

}  // namespace vibook::verify
