// Doctests of the printed-formula reader (papers.hpp, latex.hpp, notation.hpp, compare.hpp):
// the papers' text is the specification's, every numbered display is found, a quote must occur
// in the paper, the reader evaluates what the papers write, and a wrong formula or a wrong
// target is reported as differing (never as agreeing).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include <doctest/doctest.h>

#include "vibook/modified/engine.hpp"
#include "vibook/modified/series.hpp"
#include "vibook/printed/compare.hpp"

using namespace vibook;
using namespace vibook::printed;
using modified::ex;

namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

// A notation over two point symbols (x_1, x_2) with one curve x and a field V = 1/|x|.
struct Plane {
  std::shared_ptr<modified::JetSpace> J = std::make_shared<modified::JetSpace>(2);
  JetNotation n{J};
  Plane() {
    n.curve("x", {0, 1});
    const auto& y = n.point();
    n.field("V", "", 1 / GiNaC::sqrt(y[0] * y[0] + y[1] * y[1]), "x");
    n.constant("\\mathbf{q}", Value::vector({J->x(0, 0), J->x(0, 1)}));
  }
  ex x(int i) const { return J->x(0, i); }
  ex v(int i) const { return J->x(1, i); }
};

bool same(const ex& a, const ex& b) { return modified::vanishes(a - b); }

}  // namespace

TEST_CASE("papers: the embedded text is papers/*.md, and the specification's where present") {
  const std::filesystem::path here = std::filesystem::path(__FILE__).parent_path();
  const std::filesystem::path repo = here / ".." / ".." / "..";
  for (Paper p : {Paper::S, Paper::V, Paper::SS}) {
    const std::string ours = slurp(repo / "papers" / std::string(file_name(p)));
    INFO(file_name(p));
    REQUIRE(!ours.empty());
    CHECK(ours == std::string(text(p)));
    // The specification beside the repository (../shared/papers), when this checkout has it.
    const auto spec = repo / ".." / "shared" / "papers" / std::string(file_name(p));
    if (std::filesystem::exists(spec)) CHECK(slurp(spec) == ours);
  }
}

TEST_CASE("papers: every numbered display is found, in sequence, once") {
  auto numbers = [](Paper p) {
    std::vector<std::string> out;
    for (const auto& d : displays(p))
      if (!d.number.empty()) out.push_back(d.number);
    return out;
  };
  // Sharma: (1)–(66) with no gap; Vermeeren: (1)–(25).
  for (auto [p, last] : {std::pair{Paper::S, 66}, std::pair{Paper::V, 25}}) {
    const auto ns = numbers(p);
    REQUIRE(ns.size() == static_cast<std::size_t>(last));
    for (int k = 1; k <= last; ++k) CHECK(ns[static_cast<std::size_t>(k - 1)] == std::to_string(k));
  }
  // Shen & Sun: numbered by section, unique, and the ones the checks quote are there.
  const auto ss = numbers(Paper::SS);
  CHECK(std::set<std::string>(ss.begin(), ss.end()).size() == ss.size());
  for (const char* n : {"2.7", "3.19", "3.20", "3.22", "4.8b", "4.13", "4.25", "4.30", "A5"})
    CHECK(std::find(ss.begin(), ss.end(), n) != ss.end());
  // Vermeeren's (5) carries its second map, printed as inline math on the line of the number.
  CHECK(display(Paper::V, "(5)").latex.find("p_{j+1} = D_2 L_{\\text{disc}}") != std::string::npos);
}

TEST_CASE("papers: a quote names exactly one display or inline formula") {
  CHECK(display_quoting(Paper::S, "g_2(\\mathbf{q}) = \\mathbf{q}^\\top \\mathbf{q}").id() ==
        "(27)");
  CHECK_THROWS_WITH_AS(
      display_quoting(Paper::S, "g_2(\\mathbf{q}) = 2\\mathbf{q}^\\top \\mathbf{q}"),
      doctest::Contains("does not occur"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(display_quoting(Paper::S, "L_d"), doctest::Contains("more than one"),
                       std::invalid_argument);
  // An inline formula of the text, when no display holds the quote.
  const Display& n = display_quoting(Paper::SS, "\\dot{x}_1 + \\frac{x_1}{|x|^3}");
  CHECK(n.inline_math);
  CHECK(n.id() == "I307");
  // Named as a reader of the paper finds it, not by our transcription's line.
  CHECK(n.label() ==
        "the formula after “Proof. Taking” in the text after (3.13), §3 Discrete Lagrangian "
        "Mechanics (Proof)");
}

TEST_CASE("reader: the constructs the papers use") {
  Plane P;
  // \frac, powers, square roots, |x|, (a, b)^T, \left( \right), a trailing tag and full stop
  CHECK(same(read("\\frac{1}{\\sqrt{x_1^2 + x_2^2}} \\quad (7).", P.n).members.at(0).c[0],
             1 / GiNaC::sqrt(P.x(0) * P.x(0) + P.x(1) * P.x(1))));
  CHECK(same(read("|x|^3", P.n).members.at(0).c[0],
             GiNaC::pow(P.x(0) * P.x(0) + P.x(1) * P.x(1), GiNaC::numeric(3, 2))));
  const Value col = read("\\left(\\dot{x}_1, \\dot{x}_2 + x_1\\right)^\\top", P.n).members.at(0);
  REQUIRE(col.rank == 1);
  CHECK(same(col.c[1], P.v(1) + P.x(0)));
  // ∇V and a quadratic form with a matrix constant
  Value I = Value::zeros(2, 2);
  I.c = {ex(1), ex(0), ex(0), ex(1)};
  P.n.constant("M^{-1}", I);
  const ex r2 = P.x(0) * P.x(0) + P.x(1) * P.x(1);
  CHECK(same(read("\\nabla V(\\mathbf{q})^T M^{-1} \\nabla V(\\mathbf{q})", P.n).members.at(0).c[0],
             1 / (r2 * r2)));
  // members split at relations; the remainder O(h^k) is read, not evaluated
  P.n.constant("a", Value::scalar(0));
  const Reading r = read("a = \\dot{x}_1 + \\mathcal{O}(h^3)", P.n);
  REQUIRE(r.members.size() == 2);
  CHECK(r.remainder[1] == 3);
  // a symbol the notation does not know is a reader error, never a zero
  CHECK_THROWS_AS(read("\\zeta_7 + 1", P.n), ReadError);
}

TEST_CASE("reader: a term ends before the trailing full stop and equation tag") {
  Plane P;
  const auto tokens = tokenize("x_1 - V(\\mathbf{q}). \\quad (14)");
  const auto terms = term_ranges(tokens, P.n);
  // the terms of every sum, nested ones included: find the one that starts at V
  const auto v = std::find_if(terms.begin(), terms.end(),
                              [&](const auto& t) { return tokens[t.first].text == "V"; });
  REQUIRE(v != terms.end());
  CHECK(print(std::vector<Token>(tokens.begin() + static_cast<std::ptrdiff_t>(v->first),
                                 tokens.begin() + static_cast<std::ptrdiff_t>(v->second))) ==
        "V(\\mathbf{q})");
}

TEST_CASE("compare: a printed display against the right and against a wrong target") {
  Plane P;
  Spec s;
  s.paper = Paper::S;
  s.quote = "= \\mathbf{q}^\\top \\mathbf{q}, \\quad (27)";  // Sharma (27), g_2
  s.part = "g_2";
  s.against = "q·q";
  s.check = "doctest";
  const ex qq = P.x(0) * P.x(0) + P.x(1) * P.x(1);
  CHECK(compare(s, {{&P.n, Target::exactly(qq), ""}}).outcome == "agrees");
  // A deliberately wrong target: the verdict must not be "agrees", and the search finds the
  // factor that would reconcile them (here ½, as if the print had a factor too many).
  const auto wrong = compare(s, {{&P.n, Target::exactly(qq / 2), ""}});
  CHECK(wrong.outcome == "differs");
  CHECK(wrong.edit.find("multiplied by \\(\\frac{1}{2}\\)") != std::string::npos);
  CHECK(wrong.corrected.find("\\frac{1}{2}") != std::string::npos);
  // Off by a term no small edit produces: differs, and the search is described, not silent.
  const auto far = compare(s, {{&P.n, Target::exactly(qq + P.x(0)), ""}});
  CHECK(far.outcome == "differs");
  CHECK(far.corrected.empty());
  CHECK(far.search.find("readings in all") != std::string::npos);
  // A check's preferred correction is used only when it reads equal: a right one is taken
  // without a search, a wrong one is passed over and the search finds the edit as before.
  Spec pr = s;
  pr.prefer_proposed = true;
  pr.proposed = "= \\frac{1}{2}\\mathbf{q}^\\top \\mathbf{q}, \\quad (27)";
  pr.proposed_edit = "the factor one half";
  const auto taken = compare(pr, {{&P.n, Target::exactly(qq / 2), ""}});
  CHECK(taken.edit.find("the factor one half (stated by the check") == 0);
  CHECK(taken.search.find("not searched") == 0);
  pr.proposed = "= \\frac{1}{3}\\mathbf{q}^\\top \\mathbf{q}, \\quad (27)";
  const auto passed_over = compare(pr, {{&P.n, Target::exactly(qq / 2), ""}});
  CHECK(passed_over.edit.find("multiplied by \\(\\frac{1}{2}\\)") != std::string::npos);
  CHECK(passed_over.search.find("readings in all") != std::string::npos);
  // A quote that is not in the paper is never compared, whatever the target.
  Spec t = s;
  t.quote = "= 2\\mathbf{q}^\\top \\mathbf{q}";
  const auto missing = compare(t, {{&P.n, Target::exactly(2 * qq), ""}});
  CHECK(missing.outcome == "unreadable");
  CHECK(missing.detail.find("does not occur") != std::string::npos);
}

TEST_CASE("compare: a mutated formula is read as what it says") {
  // The reader on a mutation of a printed display (not a comparison: the mutation is not in
  // the paper): what it reads differs from what the print reads.
  Plane P;
  const ex printed = read("\\frac{1}{2}|\\dot{x}|^2 - V(x)", P.n).members.at(0).c[0];
  for (const char* m : {"\\frac{1}{3}|\\dot{x}|^2 - V(x)", "\\frac{1}{2}|\\dot{x}|^2 + V(x)",
                        "\\frac{1}{2}|\\ddot{x}|^2 - V(x)", "\\frac{1}{2}|\\dot{x}|^3 - V(x)",
                        "\\frac{1}{2}|\\dot{x}|^2 - V'(x)"}) {
    INFO(m);
    ex other;
    try {
      other = read(m, P.n).members.at(0).c[0];
    } catch (const std::exception&) {
      continue;  // unreadable is not agreement either
    }
    CHECK_FALSE(same(printed, other));
  }
}

TEST_CASE("compare: a target shown in abbreviations must be the target once they are substituted") {
  // Target::shown_as: the midpoint m = (a + b)/2 and difference d = b - a of a step. A form
  // that is the target passes; one with a slip (m where 2m is meant, the sign of d) is refused.
  const GiNaC::symbol a("a"), b("b"), m("m"), d("d");
  const GiNaC::exmap back = {{m, (a + b) / 2}, {d, b - a}};
  const ex target = a * a + 2 * a * b + b * b + b - a;  // (a + b)^2 + (b - a)
  Target ok = Target::exactly(target);
  CHECK_NOTHROW(ok.shown_as({4 * m * m + d}, back, "m = (a + b)/2, d = b - a"));
  CHECK(ok.shown.size() == 1);
  Target slip = Target::exactly(target);
  CHECK_THROWS_AS(slip.shown_as({2 * m * m + d}, back, ""), std::logic_error);
  CHECK_THROWS_AS(slip.shown_as({4 * m * m - d}, back, ""), std::logic_error);
  CHECK(slip.shown.empty());
  // A series, compared through h^1: the shown form's coefficients of h^0 and h^1 are checked,
  // and a slip in one of them is refused (one beyond `through` is not compared).
  const GiNaC::symbol h("h"), g("g");
  const GiNaC::exmap at = {{g, a + b}};
  Target series = Target::scalar_series({a + b, 2 * (a + b)}, 1);
  CHECK_NOTHROW(series.shown_as({g + 2 * h * g + 7 * h * h}, at, "", h));
  Target wrong = Target::scalar_series({a + b, 2 * (a + b)}, 1);
  CHECK_THROWS_AS(wrong.shown_as({g + 3 * h * g}, at, "", h), std::logic_error);
}

TEST_CASE("compare: a target shown in the paper's notation is read back and must be the target") {
  // Target::shown_read: our side written as the paper writes it (a matrix times a vector), read
  // with the same notation as the paper's displays. The form that is the target passes; a
  // slip (a factor, a sign, the wrong matrix) or a power of h beyond those compared is refused.
  Plane P;
  const GiNaC::symbol m11("m11"), m12("m12"), m22("m22"), k("k");
  Value M = Value::zeros(2, 2), Jm = Value::zeros(2, 2);
  M.c = {m11, m12, m12, m22};
  Jm.c = {0, k, -k, 0};
  P.n.constant("M", M);
  P.n.constant("J_{-}", Jm);
  const ex h = P.J->h();
  // M ẋ + (h/2) J₋ ẋ, through h^1
  const std::vector<std::vector<ex>> target = {{m11 * P.v(0) + m12 * P.v(1), k * P.v(1) / 2},
                                               {m12 * P.v(0) + m22 * P.v(1), -k * P.v(0) / 2}};
  Target ok =
      Target::vector_series({{target[0][0], target[1][0]}, {target[0][1], target[1][1]}}, 1);
  CHECK_NOTHROW(ok.shown_read(R"(M \dot{x} + \frac{h}{2} J_{-} \dot{x})", P.n));
  CHECK(ok.shown_latex == R"(M \dot{x} + \frac{h}{2} J_{-} \dot{x})");
  for (const char* slip :
       {R"(M \dot{x} + h J_{-} \dot{x})", R"(M \dot{x} - \frac{h}{2} J_{-} \dot{x})",
        R"(J_{-} \dot{x} + \frac{h}{2} M \dot{x})",
        R"(M \dot{x} + \frac{h}{2} J_{-} \dot{x} + h^{2} M \dot{x})"}) {
    Target t =
        Target::vector_series({{target[0][0], target[1][0]}, {target[0][1], target[1][1]}}, 1);
    CHECK_THROWS_AS(t.shown_read(slip, P.n), std::logic_error);
    CHECK(t.shown_latex.empty());
  }
  // exact: the number of components must match
  Target scalar =
      Target::exactly(m11 * P.v(0) * P.v(0) + 2 * m12 * P.v(0) * P.v(1) + m22 * P.v(1) * P.v(1));
  CHECK_NOTHROW(scalar.shown_read(R"(\langle \dot{x}, M \dot{x} \rangle)", P.n));
  Target vector = Target::exactly(std::vector<ex>{P.v(0), P.v(1)});
  CHECK_THROWS_AS(vector.shown_read(R"(\langle \dot{x}, M \dot{x} \rangle)", P.n),
                  std::logic_error);
}
