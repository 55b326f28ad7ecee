#include "vibook/plot/gnuplot.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

extern char** environ;

namespace vibook::plot {

std::filesystem::path find_on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return {};
  std::stringstream ss(path);
  std::string dir;
  while (std::getline(ss, dir, ':')) {
    if (dir.empty()) continue;
    const std::filesystem::path p = std::filesystem::path(dir) / program;
    if (::access(p.c_str(), X_OK) == 0) return p;
  }
  return {};
}

std::filesystem::path installed_path(const std::string& relative) {
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec || relative.empty()) return {};
  const auto candidate = exe.parent_path().parent_path() / relative;
  return std::filesystem::exists(candidate, ec) ? candidate : std::filesystem::path();
}

std::filesystem::path scripts_dir() {
  if (const char* env = std::getenv("VIBOOK_FIGURES_DIR"); env && *env) return env;
#ifdef VIBOOK_INSTALL_FIGURES_REL
  if (auto p = installed_path(VIBOOK_INSTALL_FIGURES_REL); !p.empty()) return p;
#endif
  return VIBOOK_FIGURES_DIR;
}

double gnuplot_timeout_seconds() {
  if (const char* env = std::getenv("VIBOOK_GNUPLOT_TIMEOUT"); env && *env) {
    char* end = nullptr;
    const double t = std::strtod(env, &end);
    if (end != env && *end == '\0' && std::isfinite(t) && t > 0) return t;
    throw PlotError(std::string("VIBOOK_GNUPLOT_TIMEOUT='") + env +
                    "' is not a positive number of seconds");
  }
  return 120;
}

void render(const std::string& id, const std::filesystem::path& data_dir) {
  const auto gnuplot = find_on_path("gnuplot");
  if (gnuplot.empty()) {
    throw PlotError("gnuplot not found on PATH; the CSV data are in " + data_dir.string() +
                    " (install the Debian package gnuplot-nox to render " + id + ")");
  }
  const auto script = scripts_dir() / (id + ".gp");
  if (!std::filesystem::exists(script)) {
    throw PlotError("figure script " + script.string() + " does not exist");
  }
  const auto base = data_dir / id;
  const auto log = data_dir / "gnuplot.log";
  std::vector<std::string> args = {gnuplot.string(), "-c", script.string(), data_dir.string(),
                                   base.string()};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_adddup2(&fa, STDOUT_FILENO, STDERR_FILENO);
  posix_spawn_file_actions_addopen(&fa, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  // gnuplot starts with no signal blocked and SIGPIPE at its default action, whatever the
  // command line set for itself (it blocks SIGINT/SIGTERM/SIGHUP for its signal thread and
  // ignores SIGPIPE; both would otherwise be inherited through exec).
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t none, pipe;
  sigemptyset(&none);
  sigemptyset(&pipe);
  sigaddset(&pipe, SIGPIPE);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setsigdefault(&attr, &pipe);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, gnuplot.c_str(), &fa, &attr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  posix_spawnattr_destroy(&attr);
  if (rc != 0) throw PlotError("could not start gnuplot for " + id);
  // A gnuplot that never returns must not hang the command: it is killed after the timeout.
  const double timeout = gnuplot_timeout_seconds();
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout);
  int status = 0;
  pid_t done = 0;
  while ((done = waitpid(pid, &status, WNOHANG)) == 0) {
    if (std::chrono::steady_clock::now() >= deadline) {
      ::kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      throw PlotError("gnuplot did not finish " + script.string() + " within " +
                      std::to_string(static_cast<long>(timeout)) +
                      " s and was stopped (VIBOOK_GNUPLOT_TIMEOUT sets the limit in seconds)");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (done < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::ifstream in(log);
    std::stringstream msg;
    msg << in.rdbuf();
    throw PlotError("gnuplot failed on " + script.string() + ":\n" + msg.str());
  }
  for (const char* ext : {".svg", ".png"}) {
    auto f = base;
    f += ext;
    if (!std::filesystem::exists(f) || std::filesystem::file_size(f) == 0) {
      throw PlotError("gnuplot did not write " + f.string());
    }
  }
}

}  // namespace vibook::plot
