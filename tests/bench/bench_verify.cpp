// `vibook verify` on the README's example (#28: the whole report, orders, defects, the 1e5-step
// energy test and the modified equation to h², within 2 s wall): the command is read from
// README.md, so the benchmark times the example a reader runs, not a copy of it, and the
// `vibook` binary is run as a process, start-up included. Wall time, one run per iteration.
#include <benchmark/benchmark.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace {

// The words of a command line as the README writes it: blanks separate words, '...' quotes
// (no other quoting is used there, and anything else is refused rather than guessed at).
std::vector<std::string> shell_words(const std::string& line) {
  std::vector<std::string> words;
  std::string word;
  bool in_word = false, quoted = false;
  for (char c : line) {
    if (quoted) {
      if (c == '\'')
        quoted = false;
      else
        word += c;
    } else if (c == '\'') {
      quoted = in_word = true;
    } else if (c == ' ' || c == '\t') {
      if (in_word) words.push_back(word);
      word.clear();
      in_word = false;
    } else if (c == '"' || c == '\\' || c == '$' || c == '`') {
      throw std::runtime_error(std::string("README example: unsupported shell character '") + c +
                               "'");
    } else {
      word += c;
      in_word = true;
    }
  }
  if (quoted) throw std::runtime_error("README example: unterminated quote");
  if (in_word) words.push_back(word);
  return words;
}

// The first `vibook verify --ld` command after the README's heading line for a typed discrete
// Lagrangian, continuation lines ("\" at the end) joined.
std::vector<std::string> readme_example() {
  std::ifstream in(VIBOOK_README);
  if (!in) throw std::runtime_error("cannot read " + std::string(VIBOOK_README));
  std::string line, command;
  bool after_heading = false, in_command = false;
  while (std::getline(in, line)) {
    if (line.starts_with("Your own discrete Lagrangian, typed as an expression"))
      after_heading = true;
    if (!after_heading) continue;
    if (!in_command) {
      const auto at = line.find("vibook verify --ld");
      if (at == std::string::npos) continue;
      in_command = true;
      line = line.substr(at);
    }
    const bool more = !line.empty() && line.back() == '\\';
    command += more ? line.substr(0, line.size() - 1) : line;
    if (!more) break;
  }
  if (command.empty()) throw std::runtime_error("no `vibook verify --ld` example in the README");
  auto words = shell_words(command);
  words[0] = VIBOOK_CLI;
  return words;
}

void BM_verify_readme_example(benchmark::State& state) {
  std::vector<std::string> words;
  try {
    words = readme_example();
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t quiet;
  posix_spawn_file_actions_init(&quiet);
  posix_spawn_file_actions_addopen(&quiet, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&quiet, 2, "/dev/null", O_WRONLY, 0);
  for (auto _ : state) {
    pid_t pid = 0;
    int status = 0;
    if (posix_spawn(&pid, argv[0], &quiet, nullptr, argv.data(), environ) != 0 ||
        waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
      state.SkipWithError("the README example did not run to a PASS (exit status 0)");
      break;
    }
  }
  posix_spawn_file_actions_destroy(&quiet);
}
BENCHMARK(BM_verify_readme_example)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace
