// Native code from a tape (tape.hpp, load_native): C source, the system compiler, a cache, dlopen.
#include "vibook/verify/tape.hpp"

#include <dlfcn.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
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

// --- The cache is trusted only if it is ours (issue: the tape cache ran planted code) -------
// A directory or file is ours when lstat says: not a symbolic link, owned by the effective
// user, and writable by neither group nor others. Anyone else who could write there could put
// a shared object under the name we compute, and dlopen runs its constructors.
bool ours(const struct stat& st) {
  return st.st_uid == geteuid() && (st.st_mode & (S_IWGRP | S_IWOTH)) == 0;
}

// Create `dir` and its missing parents with mode 0700; then require it and its parent to be
// ours. Returns the reason it is not trusted (empty: trusted).
std::string trust_directory(const fs::path& dir) {
  auto check = [](const fs::path& d, bool must_exist) -> std::string {
    struct stat st {};
    if (::lstat(d.c_str(), &st) != 0) return must_exist ? "cannot read " + d.string() : "";
    if (!S_ISDIR(st.st_mode)) return d.string() + " is not a directory (a link is refused)";
    if (!ours(st))
      return d.string() + (st.st_uid != geteuid() ? " belongs to another user"
                                                  : " is writable by group or others");
    return {};
  };
  // What exists is judged before anything is created: nothing is made inside a directory that
  // is refused.
  for (const fs::path& d : {dir, dir.parent_path()})
    if (std::string why = check(d, false); !why.empty()) return why;
  std::vector<fs::path> missing;
  for (fs::path d = dir; !d.empty() && d != d.root_path(); d = d.parent_path()) {
    struct stat st {};
    if (::lstat(d.c_str(), &st) == 0) break;
    missing.push_back(d);
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it)
    if (::mkdir(it->c_str(), 0700) != 0 && errno != EEXIST) return "cannot create " + it->string();
  for (const fs::path& d : {dir, dir.parent_path()})
    if (std::string why = check(d, true); !why.empty()) return why;
  return {};
}

// The identity of a compiled object, as vibook records it beside the object right after it
// compiled it: device, inode, size and the kernel's change time. A file put there in any
// other way (planted, replaced, restored from a copy of the cache) has another inode or
// change time, which no user can set, and is compiled again instead of loaded.
std::string identity(const struct stat& st) {
  return std::to_string(st.st_dev) + " " + std::to_string(st.st_ino) + " " +
         std::to_string(st.st_size) + " " + std::to_string(st.st_ctim.tv_sec) + "." +
         std::to_string(st.st_ctim.tv_nsec) + "\n";
}

// Open `file` without following a link; its stat when it is a regular file that is ours.
int open_ours(const fs::path& file, struct stat& st) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return -1;
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || !ours(st)) {
    ::close(fd);
    return -1;
  }
  return fd;
}

// Is `so` the object vibook compiled, by the record `id` written when it did?
bool recorded(const fs::path& so, const fs::path& id) {
  struct stat st {
  }, rst{};
  const int fd = open_ours(so, st);
  if (fd < 0) return false;
  ::close(fd);
  const int rfd = open_ours(id, rst);
  if (rfd < 0) return false;
  char buf[256];
  const ssize_t n = ::read(rfd, buf, sizeof buf);
  ::close(rfd);
  return n > 0 && std::string(buf, std::size_t(n)) == identity(st);
}

// Write the record of `so` (just renamed into place) through a temporary and a rename.
bool record(const fs::path& so, const fs::path& id) {
  struct stat st {};
  const int fd = open_ours(so, st);
  if (fd < 0) return false;
  ::close(fd);
  const std::string text = identity(st);
  std::string tmp = id.string() + ".XXXXXX";
  const int tfd = mkstemp(tmp.data());
  if (tfd < 0) return false;
  const bool ok = ::write(tfd, text.data(), text.size()) == ssize_t(text.size());
  if (::close(tfd) != 0 || !ok) {
    ::unlink(tmp.c_str());
    return false;
  }
  if (::rename(tmp.c_str(), id.c_str()) != 0) {
    ::unlink(tmp.c_str());
    return false;
  }
  return true;
}

// A private directory of our own for a cache we do not trust: compiled, loaded, removed.
struct PrivateDir {
  fs::path path;
  PrivateDir() {
    const char* t = std::getenv("TMPDIR");
    std::string tmpl = (fs::path(t && *t ? t : "/tmp") / "vibook-tape.XXXXXX").string();
    if (mkdtemp(tmpl.data())) path = tmpl;
  }
  ~PrivateDir() {
    std::error_code ec;
    if (!path.empty()) fs::remove_all(path, ec);
  }
};

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
  fs::path dir = cache_dir();
  // An untrusted cache is refused with one line (once a process) and the object compiled in a
  // private temporary directory instead, loaded from there and removed.
  std::unique_ptr<PrivateDir> private_dir;
  const std::string distrust =
      dir.empty() ? std::string("no cache directory (set VIBOOK_CACHE_DIR)") : trust_directory(dir);
  if (!distrust.empty()) {
    static bool said = false;
    if (!said && !dir.empty())
      std::cerr << "vibook: the tape cache is not used: " << distrust
                << "; compiling in a private temporary directory\n";
    said = true;
    private_dir = std::make_unique<PrivateDir>();
    if (private_dir->path.empty()) {
      reason = distrust + ", and no private temporary directory";
      return n;
    }
    dir = private_dir->path;
  }
  std::error_code ec;
  const fs::path so = dir / (std::string(name) + ".so");
  const fs::path id = dir / (std::string(name) + ".id");
  if (!recorded(so, id)) {
    // Compile into temporaries and rename into place: a concurrent run sees either nothing or
    // a finished object, never a half-written one. Then record what was compiled.
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
        fs::permissions(so_tmp, fs::perms::owner_read | fs::perms::owner_write, ec);
        fs::rename(so_tmp, so, ec);
        if (ec || !record(so, id)) {
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
  // Load what was just verified; a concurrent run may have replaced it by its own compile of
  // the same source in between (same user, same directory), which is as good.
  struct stat before {};
  const int verified = open_ours(so, before);
  if (verified < 0) {
    reason = "cannot open " + so.string();
    return n;
  }
  ::close(verified);
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
