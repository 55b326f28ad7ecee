// `vibook modified` as a library call (command.hpp).
#include <doctest/doctest.h>

#include <string>

#include "vibook/core/errors.hpp"
#include "vibook/modified/command.hpp"

TEST_CASE("derive: Störmer–Verlet's modified equation, printed as the command prints it") {
  vibook::modified::Derivation d;  // sv on a generic potential, one degree of freedom
  d.order = 2;
  const std::string text = vibook::modified::derive(d);
  CHECK(text.rfind("# Störmer–Verlet, generic potential, 1 degree of freedom; order h^2\n", 0) ==
        0);
  CHECK(text.find("h^0: -U_1\n") != std::string::npos);
  CHECK(text.find("h^2: -1/12*U_1*U_11+1/12*U_111*v1^2\n") != std::string::npos);
  d.what = "nothing";
  CHECK_THROWS_AS(vibook::modified::derive(d), vibook::ArgumentError);
}
