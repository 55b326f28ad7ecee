// `vibook run` as a library call (run.hpp): the file the command writes, from C++.
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "vibook/core/errors.hpp"
#include "vibook/run/run.hpp"

namespace {
std::string slurp(const std::filesystem::path& p) {
  std::ifstream f(p);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}
}  // namespace

TEST_CASE("run_trajectory: Störmer–Verlet on the pendulum, streamed to a CSV file") {
  char templ[] = "/tmp/vibook-run-test-XXXXXX";
  REQUIRE(::mkdtemp(templ) != nullptr);
  const std::filesystem::path dir(templ);
  vibook::run::Settings s;
  s.problem = "pendulum";
  s.method = "sv";
  s.h = 0.1;
  s.t_end = 1.0;
  s.q0 = {1.0};
  s.p0 = {0.0};
  s.every = 5;
  s.csv = (dir / "sv.csv").string();
  vibook::run::run_trajectory(s);
  const std::string text = slurp(dir / "sv.csv");
  std::istringstream lines(text);
  std::string header, row;
  std::getline(lines, header);
  CHECK(header == "step,t,q,p,H");
  int rows = 0;
  std::string last;
  while (std::getline(lines, row)) ++rows, last = row;
  CHECK(rows == 3);  // steps 0, 5 and 10 (every 5th, the last always)
  CHECK(last.rfind("10,1,", 0) == 0);
  // A setting that does not apply names the command's option, before any output.
  s.e = 0.5;
  s.csv = (dir / "bad.csv").string();
  CHECK_THROWS_AS(vibook::run::run_trajectory(s), vibook::ArgumentError);
  CHECK(!std::filesystem::exists(dir / "bad.csv"));
  std::filesystem::remove_all(dir);
}
