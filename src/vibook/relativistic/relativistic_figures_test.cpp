// Doctests of the relativistic figures and checks: the same functions as `vibook figure
// shen-sun-fig7 relativistic-precession` and `vibook claims`.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <doctest/doctest.h>

#include "vibook/core/tolerance.hpp"
#include "vibook/figures/registry.hpp"
#include "vibook/relativistic/shen_sun_fig7.hpp"

using namespace vibook;

namespace {
const claims::ClaimResult& by_id(const std::vector<claims::ClaimResult>& rs,
                                 const std::string& id) {
  for (const auto& r : rs) {
    if (r.id == id) return r;
  }
  FAIL("no result for ", id);
  return rs.front();
}
}  // namespace

TEST_CASE("check-ss-t8: SS-T8 to round-off, and the four errata measured") {
  const auto rs = figures::find("check-ss-t8")->run({});
  const auto& t8 = by_id(rs, "SS-T8");
  CHECK(t8.status == claims::Status::erratum);
  CHECK(t8.cause == "misprint");
  // Theorem 8 read from the paper: the corrected t-equation and the printed x-equation hold
  // along the run to round-off, the printed t-equation does not.
  CHECK(t8.value("t_equation_corrected_max_residual_along_run_in_roundoff_units") <= 64);
  CHECK(t8.value("x_equation_printed_max_residual_along_run_in_roundoff_units") <= 64);
  CHECK(t8.value("t_equation_printed_max_residual_along_run_in_roundoff_units") > 1e6);
  CHECK(t8.value("vi322_vs_composition_one_step_max") <= t8.value("round_off_bound"));
  CHECK(t8.value("generic_320_vs_composition_one_step_max") <= t8.value("round_off_bound"));
  CHECK(t8.value("generic_max_newton_iterations") <= 4);
  const auto& e319 = by_id(rs, "SS-ERR-3.19");
  CHECK(e319.status == claims::Status::erratum);
  CHECK(e319.value("printed_composition_vs_322_one_step_max") > 1e-3);  // first order in h
  const auto& et8 = by_id(rs, "SS-ERR-T8");
  CHECK(et8.status == claims::Status::erratum);
  REQUIRE(et8.comparisons.size() == 1);
  CHECK(et8.comparisons[0].corrected.find("c^2 h") != std::string::npos);
  const auto& ephi = by_id(rs, "SS-ERR-PHI");
  CHECK(ephi.status == claims::Status::erratum);
  CHECK(ephi.value("radial_force_fig7_lagrangian") < 0);
  CHECK(ephi.value("radial_force_sec3_phi") > 0);
  const auto& e27 = by_id(rs, "SS-ERR-2.7");
  CHECK(e27.status == claims::Status::erratum);
  REQUIRE(e27.comparisons.size() == 1);
  CHECK(e27.comparisons[0].edit == "the sign of the term \\(\\phi(x)\\) reversed");
}

TEST_CASE("shen-sun-fig7: orbits against the exact precessing orbit, with the worldline") {
  const auto dir = std::filesystem::temp_directory_path() / "vibook-test-shen-sun-fig7";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto rs = figures::find("shen-sun-fig7")->run({dir});
  const auto& r = by_id(rs, "SS-F7");
  INFO(r.note);
  // Measured, and asserted as measured: at the paper's h = 0.05 the methods' own perihelion
  // drift is comparable to the relativistic precession at c = 5, so the 5% criterion fails.
  CHECK(r.status == claims::Status::not_reproduced);
  CHECK(r.value("vi2_orbit_rel_err_max") < r.value("vi_orbit_rel_err_max"));
  CHECK(r.value("vi_precession_per_rev") < r.value("exact_precession_per_rev"));
  // Energy c²γ + φ is conserved by the compositions to round-off; the shell is not.
  CHECK(r.value("vi_energy_drift_over_c2") <= 1e-13);
  CHECK(r.value("vi2_energy_drift_over_c2") <= 1e-13);
  CHECK(r.value("vi2_shell_drift") > 1e-6);
  for (const char* f : {"vi.csv", "vi2.csv", "exact.csv", "shen-sun-fig7-worldline.png"}) {
    CHECK(std::filesystem::file_size(dir / f) > 0);
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("relativistic-precession: measured advance against 2π(1/Γ − 1) over c") {
  const auto rs = figures::find("relativistic-precession")->run({});
  const auto& r = by_id(rs, "SS-F7");
  INFO(r.note);
  CHECK(r.status == claims::Status::reproduced);
  const double floor = r.value("vi2_own_precession_at_c1e4");
  CHECK(floor < 1e-5);
  for (double c : checks::kSweepSpeeds) {
    const std::string key = c == std::floor(c) ? std::to_string(long(c)) : std::to_string(c);
    const double ex = r.value("c" + key + "_exact"), m = r.value("c" + key + "_vi2_measured");
    CHECK(std::abs(m - ex) <= 0.01 * ex + floor);
  }
}
