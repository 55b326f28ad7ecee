// Doctests of canonical printing (canonical.hpp): the printed form depends on the expression
// only, not on the order in which GiNaC happened to store its operands, and it reads back.
#include <doctest/doctest.h>

#include <ginac/parser.h>

#include "vibook/modified/canonical.hpp"

using namespace vibook::modified;

TEST_CASE("canonical: the same expression prints the same whatever the symbol creation order") {
  // Two sets of symbols with the same names, created in opposite orders: GiNaC orders the
  // terms by serial numbers and hashes, canonical_string by the printed monomials.
  GiNaC::symbol b1("b"), a1("a"), c1("c");
  GiNaC::symbol c2("c"), a2("a"), b2("b");
  const ex e1 = GiNaC::numeric(-1, 12) * a1 * b1 * b1 + 3 * c1 * a1 + GiNaC::pow(b1 + c1, -2) +
                GiNaC::cos(a1) / 7 - 2;
  const ex e2 = GiNaC::numeric(-1, 12) * a2 * b2 * b2 + 3 * c2 * a2 + GiNaC::pow(b2 + c2, -2) +
                GiNaC::cos(a2) / 7 - 2;
  for (const Format f : {Format::text, Format::latex, Format::python})
    CHECK(canonical_string(e1, f) == canonical_string(e2, f));
  // Ordered by the monomial's text (ASCII), the constant first.
  CHECK(canonical_string(e1) == "-2+(b+c)^(-2)-1/12*a*b^2+3*a*c+1/7*cos(a)");
  CHECK(canonical_string(e1, Format::python) ==
        "-2+(b+c)**(-2)+Rational(-1, 12)*a*b**2+3*a*c+Rational(1, 7)*cos(a)");
  // The text form is GiNaC syntax: parsed back, it is the same expression.
  GiNaC::symtab table{{"a", a1}, {"b", b1}, {"c", c1}};
  GiNaC::parser reader(table);
  CHECK((reader(canonical_string(e1)) - e1).expand().is_zero());
  // Sums and products are evaluated in the printed order (compiled.hpp).
  const auto ops = canonical_operands(e1);
  REQUIRE(ops.size() == 5);
  CHECK(ops[0].is_equal(-2));
}

TEST_CASE("canonical: LaTeX puts negative powers below the fraction bar") {
  GiNaC::symbol x("x"), r("r", "|x|");
  CHECK(canonical_string(-x / (12 * GiNaC::pow(r, 3)), Format::latex) == "-\\frac{x}{12 |x|^{3}}");
  CHECK(canonical_string(GiNaC::pow(x, GiNaC::numeric(1, 2)), Format::latex) == "\\sqrt{x}");
}

TEST_CASE("canonical: LaTeX of symbols made without a TeX name, never their internal names") {
  auto tex = [](const char* name) { return canonical_string(GiNaC::symbol(name), Format::latex); };
  CHECK(tex("q0") == "q_{0}");
  CHECK(tex("q_k1") == "q_{k+1}");
  CHECK(tex("qm") == "q_{m}");
  CHECK(tex("qm_1") == "q_{m,1}");
  CHECK(tex("q0_1") == "q_{0,1}");  // the first point's first component (was printed q0_1)
  CHECK(tex("q1_2") == "q_{1,2}");
  CHECK(tex("bbar") == "\\bar{b}");
  CHECK(tex("a11") == "a_{11}");
}
