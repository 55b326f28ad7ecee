// Doctests of the vector notation (vector_notation.hpp): Shen & Sun's grouping of (4.14),
// (4.15), (4.21) and (4.22) found in the engine's component form, and every printed form read
// back by the papers' LaTeX reader as the engine's expression.
#include <doctest/doctest.h>

#include <string>

#include "vibook/modified/engine.hpp"
#include "vibook/modified/printed_checks.hpp"
#include "vibook/modified/vector_notation.hpp"
#include "vibook/printed/compare.hpp"
#include "vibook/printed/latex.hpp"
#include "vibook/printed/notation.hpp"

namespace {

using namespace vibook::modified;
using GiNaC::numeric;

// The coefficient of an invariant in a grouping (0 if it is not used).
numeric coeff(const VectorNotation::Grouped& g, const std::string& tex) {
  for (const auto& [t, c] : g.terms)
    if (t == tex) return GiNaC::ex_to<numeric>(c);
  return 0;
}

// Shen & Sun's notation over the engine's jets: φ the sum of the pieces phi1, phi2 (families 1
// and 2 of a generic engine), φ^[1] the first, U the unsplit potential (family 0).
vibook::printed::JetNotation notation(Engine& E, bool pieces) {
  auto n = vibook::checks::printed_detail::engine_notation(E);
  if (pieces) {
    n.field("phi", "", n.abstract_field({{1, 1}, {2, 1}}), "x");
    n.field("phi", "[1]", n.abstract_field({{1, 1}}), "x");
  } else {
    n.field("U", "", n.abstract_field({{0, 1}}), "x");
  }
  return n;
}

// The printed form, read back, minus the engine's series: zero when the print is right.
ex read_back_difference(const std::string& latex, const vibook::printed::JetNotation& n,
                        const std::vector<ex>& series, const GiNaC::symbol& h) {
  const auto r = vibook::printed::read(latex, n);
  REQUIRE(r.members.size() == 1);
  const ex read = vibook::printed::at_jet_point(r.members[0].as_scalar("the series"), n.jets());
  return GiNaC::expand(read - vibook::checks::printed_detail::series_sum(series, h));
}

}  // namespace

TEST_CASE("vector notation: the L_mod of VI-1 groups as Shen & Sun (4.21) and reads back") {
  std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
  Engine E(make_discrete_lagrangian(Method::vi1, Potential::generic, 2), 2);
  const auto L = E.l_mod();
  const auto v = VectorNotation::of(E.jets(), L);
  REQUIRE(v.has_value());
  // (4.21): −h/2 (∇φ·ẋ − 2 ∂φ^[1]/∂x₂ ẋ₂) + h²/24 (|∇φ|² − 2 φ_xx⟨ẋ, ẋ⟩ + 12 φ^[1]_12 ẋ₁ẋ₂)
  const auto g0 = v->group({L[0]}, false), g1 = v->group({L[1]}, false),
             g2 = v->group({L[2]}, false);
  CHECK(coeff(g0, "|\\dot{x}|^{2}") == numeric(1, 2));
  CHECK(coeff(g1, "\\nabla \\phi\\cdot \\dot{x}") == numeric(-1, 2));
  CHECK(coeff(g2, "|\\nabla \\phi|^{2}") == numeric(1, 24));
  CHECK(coeff(g2, "\\phi_{xx}\\langle \\dot{x},\\dot{x}\\rangle") == numeric(-1, 12));
  const JetSpace& J = E.jets();
  const ex phi1_2 = J.derivative(1, {1}), phi1_12 = J.derivative(1, {0, 1});
  CHECK(GiNaC::expand(g1.rest[0] - phi1_2 * J.x(1, 1)).is_zero());
  CHECK(GiNaC::expand(g2.rest[0] - phi1_12 * J.x(1, 0) * J.x(1, 1) / 2).is_zero());
  const std::string s = v->scalar_series(L);
  CHECK(s.find("\\frac{h^{2}}{24}\\Bigl(|\\nabla \\phi|^{2} - 2 \\phi_{xx}\\langle \\dot{x},"
               "\\dot{x}\\rangle + 12 ") != std::string::npos);
  CHECK(s.find("- \\frac{h}{2}\\Bigl(\\nabla \\phi\\cdot \\dot{x} - 2 ") != std::string::npos);
  const auto n = notation(E, true);
  CHECK(read_back_difference(s, n, L, J.h()).is_zero());
  // a wrong print must not read back: the paper's 1/24 made 1/12
  std::string wrong = s;
  wrong.replace(wrong.find("{24}"), 4, "{12}");
  CHECK_FALSE(read_back_difference(wrong, n, L, J.h()).is_zero());
}

TEST_CASE("vector notation: the modified equations of VI-1 (4.22) and VI-2 read back") {
  std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
  for (Method m : {Method::vi1, Method::vi2}) {
    Engine E(make_discrete_lagrangian(m, Potential::generic, 2), 2);
    const auto f = E.modified_equation();
    std::vector<ex> flat;
    for (const auto& row : f) flat.insert(flat.end(), row.begin(), row.end());
    const auto v = VectorNotation::of(E.jets(), flat);
    REQUIRE(v.has_value());
    // h^0: −∇φ, nothing left over
    const auto g0 = v->group(f[0], true);
    CHECK(coeff(g0, "\\nabla \\phi") == -1);
    CHECK(g0.rest[0].is_zero());
    CHECK(g0.rest[1].is_zero());
    // h²: (4.22) has h²/12 (φ_xxx⟨ẋ, ẋ⟩ − φ_xx∇φ) besides its components
    const auto g2 = v->group(f[2], true);
    if (m == Method::vi1) {
      CHECK(coeff(g2, "\\phi_{xxx}\\langle \\dot{x},\\dot{x}\\rangle") == numeric(1, 12));
      CHECK(coeff(g2, "\\phi_{xx}\\nabla \\phi") == numeric(-1, 12));
    }
    const std::string s = "\\ddot{x} = " + v->vector_series(f);
    const auto n = notation(E, true);
    const auto r = vibook::printed::read(s, n);
    REQUIRE(r.members.size() == 2);
    const auto& got = r.members[1];
    REQUIRE(got.rank == 1);
    for (int i = 0; i < 2; ++i) {
      std::vector<ex> c;
      for (const auto& row : f) c.push_back(row[static_cast<std::size_t>(i)]);
      const ex read = vibook::printed::at_jet_point(got.c[static_cast<std::size_t>(i)], E.jets());
      CHECK(GiNaC::expand(read - vibook::checks::printed_detail::series_sum(c, E.jets().h()))
                .is_zero());
    }
  }
}

TEST_CASE("vector notation: Störmer-Verlet (4.14) and (4.15) have nothing left over") {
  std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
  Engine E(make_discrete_lagrangian(Method::sv, Potential::generic, 2), 2);
  const auto L = E.l_mod();
  const auto f = E.modified_equation();
  const auto v = VectorNotation::of(E.jets(), L);
  REQUIRE(v.has_value());
  const auto g = v->group({L[2]}, false);
  CHECK(coeff(g, "|\\nabla U|^{2}") == numeric(1, 24));
  CHECK(coeff(g, "U_{xx}\\langle \\dot{x},\\dot{x}\\rangle") == numeric(-1, 12));
  CHECK(g.rest[0].is_zero());
  const auto e2 = v->group(f[2], true);
  CHECK(coeff(e2, "U_{xxx}\\langle \\dot{x},\\dot{x}\\rangle") == numeric(1, 12));
  CHECK(coeff(e2, "U_{xx}\\nabla U") == numeric(-1, 12));
  CHECK(e2.rest[0].is_zero());
  CHECK(e2.rest[1].is_zero());
  CHECK(v->scalar_series(L).find("\\frac{h^{2}}{24}\\Bigl(|\\nabla U|^{2} - 2 U_{xx}\\langle "
                                 "\\dot{x},\\dot{x}\\rangle\\Bigr)") != std::string::npos);
  CHECK(read_back_difference(v->scalar_series(L), notation(E, false), L, E.jets().h()).is_zero());
}

TEST_CASE("vector notation: a term no invariant accounts for stays in components") {
  std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
  Engine E(make_discrete_lagrangian(Method::sv, Potential::generic, 2), 2);
  const JetSpace& J = E.jets();
  auto L = E.l_mod();
  // one of U_xx⟨ẋ, ẋ⟩'s three terms changed: the majority keeps −1/12, the change is left
  // over exactly
  const ex extra = J.derivative(0, {0, 0}) * J.x(1, 0) * J.x(1, 0) / 100;
  const auto v = VectorNotation::of(J, L);
  REQUIRE(v.has_value());
  const auto g = v->group({L[2] + extra}, false);
  CHECK(coeff(g, "|\\nabla U|^{2}") == numeric(1, 24));
  CHECK(coeff(g, "U_{xx}\\langle \\dot{x},\\dot{x}\\rangle") == numeric(-1, 12));
  CHECK(GiNaC::expand(g.rest[0] - extra).is_zero());
  // one dimension, an unsplit Kepler potential: no vector notation
  Engine E1(make_discrete_lagrangian(Method::sv, Potential::generic, 1), 2);
  CHECK_FALSE(VectorNotation::of(E1.jets(), E1.l_mod()).has_value());
  Engine K(make_discrete_lagrangian(Method::sv, Potential::kepler, 2), 2);
  CHECK_FALSE(VectorNotation::of(K.jets(), K.l_mod()).has_value());
}

TEST_CASE(
    "vector notation: meshed Lagrangians and the L_mod of VI-2 and of three dimensions read back") {
  std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
  struct Case {
    Method m;
    int dim;
    bool pieces, meshed;
  };
  for (const Case c : {Case{Method::vi2, 2, true, false}, Case{Method::vi2, 2, true, true},
                       Case{Method::se, 2, false, true}, Case{Method::sv, 3, false, false},
                       Case{Method::vi1, 3, true, false}}) {
    CAPTURE(c.dim);
    CAPTURE(c.meshed);
    Engine E(make_discrete_lagrangian(c.m, Potential::generic, c.dim), 2);
    const auto L = c.meshed ? E.l_mesh() : E.l_mod();
    const auto v = VectorNotation::of(E.jets(), L);
    REQUIRE(v.has_value());
    auto n = vibook::checks::printed_detail::engine_notation(E);
    if (c.pieces) {
      std::vector<std::pair<int, ex>> all;
      for (int k = 1; k <= c.dim; ++k) all.emplace_back(k, 1);
      n.field("phi", "", n.abstract_field(all), "x");
      for (int k = 1; k < c.dim; ++k)
        n.field("phi", "[" + std::to_string(k) + "]", n.abstract_field({{k, 1}}), "x");
    } else {
      n.field("U", "", n.abstract_field({{0, 1}}), "x");
    }
    const std::string s = v->scalar_series(L);
    CAPTURE(s);
    CHECK(read_back_difference(s, n, L, E.jets().h()).is_zero());
  }
}

TEST_CASE(
    "vector notation: two different derivatives of x group as a dot product (x-dot . x-dddot)") {
  std::lock_guard<std::recursive_mutex> lock(ginac_mutex());
  Engine E(make_discrete_lagrangian(Method::sv, Potential::generic, 2), 3);
  const JetSpace& J = E.jets();
  const auto L = E.l_mod();  // makes the jets through x''' the engine's expansion needs
  REQUIRE(J.created_order() >= 3);
  // −ẋ·x⃛ + 2 ∇U·x⃛ + ẋ₁ ẍ₁ / 100 (the last is half of ẋ·ẍ: no majority, left in components)
  const ex extra = J.x(1, 0) * J.x(2, 0) / 100;
  ex e = extra;
  for (int i = 0; i < 2; ++i) e += -J.x(1, i) * J.x(3, i) + 2 * J.derivative(0, {i}) * J.x(3, i);
  const auto v = VectorNotation::of(J, {e});
  REQUIRE(v.has_value());
  const auto g = v->group({e}, false);
  CHECK(coeff(g, "\\dot{x}\\cdot \\dddot{x}") == numeric(-1));
  CHECK(coeff(g, "\\nabla U\\cdot \\dddot{x}") == numeric(2));
  CHECK(GiNaC::expand(g.rest[0] - extra).is_zero());
}
