// The study of a typed discrete Lagrangian from C++ (ld_study.hpp): the report the command
// prints, from the library. One correct method that must pass and one deliberately wrong one
// (a sign slip in the potential term) that must fail consistency. The order is measured by the
// order study of every route (study_order): the walk of step sizes, not a list of its own.
#include "vibook/verify/ld_study.hpp"

#include <mutex>

#include <doctest/doctest.h>

#include "vibook/modified/series.hpp"

namespace {

using vibook::verify::LdSettings;
using vibook::verify::TypedDiscreteLagrangian;

std::unique_ptr<TypedDiscreteLagrangian> typed(const std::string& ld, const std::string& V) {
  std::lock_guard<std::recursive_mutex> lock(vibook::modified::ginac_mutex());
  return std::make_unique<TypedDiscreteLagrangian>(vibook::verify::TypedTexts{ld, V, "", "", 0});
}

LdSettings pendulum_settings(const std::string& ld) {
  LdSettings s;
  s.dim = 1;
  s.q0 = {1.0};
  s.p0 = {0.5};
  s.t_end = 5;  // no step sizes: the walk of every route
  s.expected = 2;
  s.order_tol = 0.2;
  s.h = 0.05;
  s.steps = 4096;
  s.modified_order = 2;
  s.adaptive_steps = 1024;
  s.ld_text = ld;
  s.potential_text = "-cos(x)";
  return s;
}

}  // namespace

TEST_CASE("ld_study: the trapezoidal L_d on the pendulum passes at order 2 from the library") {
  const std::string ld = "h*((q1-q0)^2/(2*h^2) - (V(q0)+V(q1))/2)";
  const auto dl = typed(ld, "-cos(x)");
  const auto st = vibook::verify::run_ld_study(*dl, pendulum_settings(ld));
  CHECK(st.status == vibook::verify::kLdOk);
  CHECK(st.error_line.empty());
  CHECK(st.js.at("verdict").at("passed").get<bool>());
  const double slope = st.js.at("order").at("fitted").get<double>();
  CHECK(std::abs(slope - 2) < 0.1);
  // the order study of every route: the walk into the window, its slopes settled
  CHECK(st.js.at("order").at("fitted_on") == "the window");
  CHECK(st.js.at("order").at("settled_h").is_array());
  CHECK(st.order_h.size() == st.order_error.size());
  CHECK(st.order_h.size() > 5);
  CHECK(st.js.at("symplecticity").at("passed").get<bool>());
  CHECK(st.text.find("verdict              PASS") != std::string::npos);
  CHECK(st.modified_terms.size() == 3);  // h^0, h^1, h^2
}

TEST_CASE("ld_study: a sign slip in the potential term fails consistency with status 5") {
  const std::string ld = "h*((q1-q0)^2/(2*h^2) + (V(q0)+V(q1))/2)";
  const auto dl = typed(ld, "-cos(x)");
  const auto st = vibook::verify::run_ld_study(*dl, pendulum_settings(ld));
  CHECK(st.status == vibook::verify::kLdVerdict);
  CHECK_FALSE(st.js.at("consistency").at("passed").get<bool>());
  REQUIRE_FALSE(st.failed_checks.empty());
  CHECK(st.failed_checks.front() == "consistency");
  CHECK(st.error_line.rfind("vibook: verify: FAIL (consistency", 0) == 0);
}
