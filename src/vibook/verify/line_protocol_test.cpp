// Doctests of verify/line_protocol.hpp: a child that serves the line protocol, here a small
// stepper written in the test (q advances by h a step, p stays), whose answers to `every` can
// be made to hold a state the caller refuses.
#include "vibook/verify/line_protocol.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include <doctest/doctest.h>
#include <fmt/format.h>

#include "vibook/core/errors.hpp"

namespace {

// The child's side for one degree of freedom: "h n q p" is answered with q + n h and p;
// "every h n q p" with n lines, the state after each step, the third one "inf p" when
// `poison` is set.
int serve(bool poison) {
  std::string buf;
  char chunk[4096];
  auto send = [](const std::string& s) {
    return ::write(1, s.data(), s.size()) == ssize_t(s.size());
  };
  while (true) {
    const auto nl = buf.find('\n');
    if (nl == std::string::npos) {
      const ssize_t got = ::read(0, chunk, sizeof chunk);
      if (got <= 0) return 0;
      buf.append(chunk, static_cast<std::size_t>(got));
      continue;
    }
    std::string line = buf.substr(0, nl);
    buf.erase(0, nl + 1);
    const bool every = line.rfind("every ", 0) == 0;
    char* s = line.data() + (every ? 6 : 0);
    const double h = std::strtod(s, &s);
    const long long n = std::strtoll(s, &s, 10);
    double q = std::strtod(s, &s);
    const double p = std::strtod(s, &s);
    std::string out;
    if (!every) {
      out = fmt::format("{:.17g} {:.17g}\n", q + double(n) * h, p);
    } else {
      for (long long k = 0; k < n; ++k) {
        q += h;
        out += poison && k == 2 ? fmt::format("inf {:.17g}\n", p)
                                : fmt::format("{:.17g} {:.17g}\n", q, p);
      }
    }
    if (!send(out)) return 0;
  }
}

}  // namespace

TEST_CASE("line protocol: a library's host answers every state of a run in one request") {
  vibook::verify::LineProtocolStepper s([] { return serve(false); }, 1, 10.0);
  double q = 0, p = 1;
  std::vector<double> seen;
  s.every(0.5, 4, &q, &p, [&] { seen.push_back(q); });
  CHECK(seen == std::vector<double>{0.5, 1.0, 1.5, 2.0});
  CHECK(p == 1.0);
}

TEST_CASE("line protocol: a state the caller refuses mid-run leaves the next request clean") {
  // The caller stops at the third state (not finite); the rest of that answer is read and
  // dropped, so the next request gets its own answer, not a line left over from the run.
  vibook::verify::LineProtocolStepper s([] { return serve(true); }, 1, 10.0);
  double q = 0, p = 1;
  int taken = 0;
  CHECK_THROWS_AS(s.every(0.5, 6, &q, &p,
                          [&] {
                            if (!std::isfinite(q)) throw vibook::NumericalError("not finite");
                            ++taken;
                          }),
                  vibook::NumericalError);
  CHECK(taken == 2);
  q = 1;
  s.run(0.25, 2, &q, &p);
  CHECK(q == 1.5);
  CHECK(p == 1.0);
}
