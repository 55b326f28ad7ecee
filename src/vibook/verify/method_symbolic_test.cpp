// Doctests of the engine's variational order of compositions whose coefficients are known to
// finite precision (method_symbolic.hpp): the catalogue's 120-digit rationals and the
// threshold below which a term of L_d − L_d^E counts as zero.
#include <doctest/doctest.h>

#include <optional>

#include "vibook/verify/method_symbolic.hpp"

TEST_CASE(
    "derived variational order at 120 digits: yoshida4 is 4 and an eleventh-digit error is 2") {
  using namespace vibook::verify;
  const auto st = catalogue_rationals("yoshida4");
  REQUIRE(st.size() == 3);
  // the triple jump at 120 digits: order 4 once the rounding's terms (near 1e-120) count as zero
  CHECK(composition_variational_order("sv", st, "pendulum", 4, composition_zero_below()) == 4);
  // an exact zero test sees the rounding: the threshold is what makes the route work
  CHECK(composition_variational_order("sv", st, "pendulum", 4, std::nullopt) == 2);
  // the outer coefficient off in its eleventh digit, the middle one keeping the sum 1 and the
  // palindrome: the third-order conditions fail by 1e-11, and the threshold must not hide it
  auto wrong = st;
  const GiNaC::numeric delta = GiNaC::numeric(1) / GiNaC::numeric(10).power(11);
  wrong[0].first += delta;
  wrong[2].first += delta;
  wrong[1].first -= 2 * delta;
  CHECK(composition_variational_order("sv", wrong, "pendulum", 4, composition_zero_below()) == 2);
}
