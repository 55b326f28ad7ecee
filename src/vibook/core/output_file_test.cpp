// A report directory (output_file.hpp): which names check_report_directory accepts.
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "vibook/core/errors.hpp"
#include "vibook/core/output_file.hpp"

namespace fs = std::filesystem;

TEST_CASE("check_report_directory: a new name, an empty directory or an earlier report") {
  char templ[] = "/tmp/vibook-report-test-XXXXXX";
  REQUIRE(::mkdtemp(templ) != nullptr);
  const fs::path base(templ);
  const auto check = [](const fs::path& p) {
    vibook::check_report_directory(p.string(), "--report");
  };
  CHECK_NOTHROW(check(base / "new"));  // a new name
  CHECK(vibook::report_directory((base / "new/").string()) == base / "new");
  fs::create_directory(base / "empty");
  CHECK_NOTHROW(check(base / "empty"));  // an empty directory
  fs::create_directory(base / "earlier");
  std::ofstream(base / "earlier" / "index.html") << "x";
  std::ofstream(base / "earlier" / "verify.json") << "{}";
  CHECK_NOTHROW(check(base / "earlier"));  // an earlier report
  // refused: a directory holding anything else, a file, a symbolic link, "..", a missing parent
  fs::create_directory(base / "other");
  std::ofstream(base / "other" / "notes.txt") << "mine";
  CHECK_THROWS_AS(check(base / "other"), vibook::ArgumentError);
  std::ofstream(base / "file") << "x";
  CHECK_THROWS_AS(check(base / "file"), vibook::ArgumentError);
  fs::create_directory_symlink(base / "empty", base / "link");
  CHECK_THROWS_AS(check(base / "link"), vibook::ArgumentError);
  CHECK_THROWS_AS(check(base / ".."), vibook::ArgumentError);
  CHECK_THROWS_AS(check(base / "missing" / "report"), vibook::ArgumentError);
  CHECK_THROWS_AS(vibook::check_report_directory("", "--report"), vibook::ArgumentError);
  fs::remove_all(base);
}
