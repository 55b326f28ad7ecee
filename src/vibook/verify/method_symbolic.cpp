// The variational order of a Galerkin method from the symbolic engine (method_symbolic.hpp):
// Marsden & West 2001, §2.3.1 (the variational order) and §2.6 (the Galerkin discrete
// Lagrangian), the interior control points eliminated order by order in h.
#include "vibook/verify/method_symbolic.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "vibook/core/errors.hpp"
#include "vibook/core/precision.hpp"
#include "vibook/integrators/composition.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/modified/canonical.hpp"
#include "vibook/modified/ginac_eigen.hpp"
#include "vibook/problems/problems.hpp"
#include "vibook/verify/tableau_study.hpp"

namespace vibook::verify {

using nlohmann::json;

SymbolicUse parse_symbolic_use(const std::string& s) {
  if (s == "auto") return SymbolicUse::automatic;
  if (s == "always") return SymbolicUse::always;
  if (s == "never") return SymbolicUse::never;
  throw ArgumentError("--symbolic", "'" + s + "': auto, always or never");
}

namespace {

template <class Problem>
modified::SymbolicLagrangian mechanical() {
  return [](const std::vector<modified::ex>& q, const std::vector<modified::ex>& v) {
    constexpr int N = Problem::N;
    Vec<modified::ex, N> x;
    modified::ex kinetic = 0;
    for (int i = 0; i < N; ++i) {
      x(i) = q[static_cast<std::size_t>(i)];
      kinetic += v[static_cast<std::size_t>(i)] * v[static_cast<std::size_t>(i)] / 2;
    }
    return modified::exact_rationals(kinetic - Problem{}.potential(x));
  };
}

}  // namespace

modified::SymbolicLagrangian test_problem_lagrangian(const std::string& problem) {
  if (problem == "pendulum") return mechanical<Pendulum>();
  if (problem == "henon-heiles") return mechanical<HenonHeiles>();
  if (problem == "kepler") return mechanical<Kepler>();
  throw std::invalid_argument("test_problem_lagrangian: no Lagrangian for '" + problem + "'");
}

namespace {

// What the engine is given: the discrete Lagrangian (built on the jets it is handed), the
// intended L, and why it is not derived when it is not.
struct Derivation {
  int dim = 1;
  std::function<modified::SymbolicDL(std::shared_ptr<modified::JetSpace>)> make_dl;
  modified::SymbolicLagrangian L;
  std::string source;  ///< for the JSON
  std::string skip;    ///< when set: not derived, and why
  /// Coefficients known to finite precision (a catalogue entry's, computed at 120 digits): a
  /// term of L_d − L_d^E all of whose numbers are below this counts as zero, and `precision`
  /// says so in the report. Unset: the zero test is exact.
  std::optional<GiNaC::numeric> zero_below;
  std::string precision;
  /// A Galerkin rule cut to finite precision (cut_quadrature): by default derived in one
  /// degree of freedom only.
  bool cut_rule = false;
  /// The coefficients are a catalogue entry's 120-digit values (long numbers: the derivation
  /// is skipped by default where it would take minutes).
  bool long_digits = false;
  int stages = 0;      ///< a composition's stages (the cost grows quickly with them)
  bool typed = false;  ///< stages of a typed L_d (--composition ld)
  /// A tableau's longest entry, in digits (typed decimals: long numbers beyond 20).
  std::size_t entry_digits = 0;
};

// The number of one term of an expanded polynomial (a numeric, or a product's numeric factors).
GiNaC::numeric term_number(const modified::ex& t) {
  GiNaC::numeric c = 1;
  if (GiNaC::is_a<GiNaC::numeric>(t)) {
    c = GiNaC::ex_to<GiNaC::numeric>(t);
  } else if (GiNaC::is_a<GiNaC::mul>(t)) {
    for (std::size_t k = 0; k < t.nops(); ++k)
      if (GiNaC::is_a<GiNaC::numeric>(t.op(k))) c *= GiNaC::ex_to<GiNaC::numeric>(t.op(k));
  }
  return c;
}

// The largest number in an expanded polynomial's terms (its coefficients), in absolute value.
GiNaC::numeric largest_coefficient(const modified::ex& e) {
  GiNaC::numeric top = 0;
  auto term = [&top](const modified::ex& t) {
    const GiNaC::numeric c = term_number(t);
    if (abs(c) > top) top = abs(c);
  };
  const modified::ex x = GiNaC::expand(e);
  if (GiNaC::is_a<GiNaC::add>(x))
    for (std::size_t k = 0; k < x.nops(); ++k) term(x.op(k));
  else if (!x.is_zero())
    term(x);
  return top;
}

// The fraction with the smallest denominator among the continued-fraction convergents of x
// that lie within tol of it.
GiNaC::numeric simplest_within(GiNaC::numeric x, const GiNaC::numeric& tol) {
  using GiNaC::numeric;
  const bool negative = x < 0;
  if (negative) x = -x;
  numeric n = x.numer(), d = x.denom(), h2 = 0, h1 = 1, k2 = 1, k1 = 0;
  for (int it = 0; it < 1000 && !d.is_zero(); ++it) {
    const numeric a = GiNaC::iquo(n, d), h = a * h1 + h2, k = a * k1 + k2;
    if (abs(x - h / k) <= tol) return negative ? -h / k : h / k;
    h2 = h1;
    h1 = h;
    k2 = k1;
    k1 = k;
    const numeric r = n - a * d;
    n = d;
    d = r;
  }
  return negative ? -x : x;
}

// A term of L_d − L_d^E derived from coefficients cut to finite precision, as the report shows
// it: the terms whose number is below `below` left out, and each other number the simplest
// fraction within 1e-20 of it relative. The cut moves a number by about 1e-34 at most, which is
// 1e-25 relative to the smallest true one met (Gauss 4's 1/1778112000), and two fractions with
// denominators up to 1e10 differ by more than 1e-20 relative: the Galerkin methods' true
// coefficients, rationals with small denominators, come back exactly.
modified::ex shown_term(const modified::ex& e, const GiNaC::numeric& below) {
  using GiNaC::numeric;
  const modified::ex x = GiNaC::expand(e);
  const numeric rel = numeric(1) / numeric(10).power(20);
  modified::ex kept = 0;
  auto one = [&](const modified::ex& t) {
    const numeric c = term_number(t);
    if (abs(c) < below) return;
    kept += t / c * simplest_within(c, abs(c) * rel);
  };
  if (GiNaC::is_a<GiNaC::add>(x))
    for (std::size_t k = 0; k < x.nops(); ++k) one(x.op(k));
  else
    one(x);
  return kept;
}

// Is L polynomial in q and v? (Then the engine is quick in any dimension.)
bool polynomial_lagrangian(const modified::SymbolicLagrangian& L, int dim) {
  std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
  modified::JetSpace J(dim);
  std::vector<modified::ex> x, v;
  GiNaC::lst vars;
  for (int i = 0; i < dim; ++i) {
    x.push_back(J.x(0, i));
    v.push_back(J.x(1, i));
    vars.append(x.back());
    vars.append(v.back());
  }
  return L(x, v).is_polynomial(vars);
}

// The first k whose term has a number at or above `zero_below`; −1 if none.
int order_above(const std::vector<modified::ex>& defect, const GiNaC::numeric& zero_below) {
  for (std::size_t k = 0; k < defect.size(); ++k)
    if (largest_coefficient(defect[k]) >= zero_below) return static_cast<int>(k);
  return -1;
}

// Set study.derive_variational_order: the engine's L_d − L_d^E to h^{K+1}, K the study's
// expected order (s.expected, known when the hook runs), printed on the line "  derived" and
// kept in the JSON under variational_order.engine; part of the verdict when the expected order
// is an integer up to the engine's maximum.
//
// The hook outlives this call and may run, be copied and be destroyed on another thread (the
// rows of a field audit run in parallel): it keeps the Derivation, whose GiNaC objects are
// not thread-safe, through modified::ginac_shared.
void install(Derivation derivation, SymbolicUse use, MapStudy& study) {
  const std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
  const bool quick = !derivation.skip.empty() || derivation.dim == 1 ||
                     polynomial_lagrangian(derivation.L, derivation.dim);
  if (use == SymbolicUse::never) derivation.skip = "not derived (--symbolic never)";
  study.derive_variational_order = [shared = modified::ginac_shared(std::move(derivation)), use,
                                    quick](const MapStudy& s, MapMeasurement& rep) {
    const Derivation& d = *shared;
    json& jv = rep.js["variational_order"];
    const bool judged = s.expected == std::floor(s.expected) && s.expected <= modified::max_order;
    const int K = static_cast<int>(std::min<double>(std::ceil(s.expected), modified::max_order));
    std::string skip = d.skip;
    if (skip.empty() && use == SymbolicUse::automatic && !quick && K > 4)
      skip = fmt::format(
          "not derived by default: to h^{} in {} dimensions, with a Lagrangian that is not "
          "polynomial, the engine takes minutes (gauss:3 on Kepler: about 2 minutes on 2 "
          "cores); --symbolic always runs it",
          K + 1, d.dim);
    // Coefficients cut to 30 digits make every number long: by default only the short
    // compositions on a polynomial Lagrangian (yoshida4 and suzuki4 on Hénon–Heiles)
    if (skip.empty() && use == SymbolicUse::automatic && d.long_digits && d.typed)
      skip =
          "not derived by default: the stages of a typed L_d with coefficients cut to 30 digits "
          "can take the engine many minutes (yoshida4 on a typed midpoint rule with a "
          "position-dependent mass: over 10 minutes at 120 digits); --symbolic always runs it";
    else if (skip.empty() && use == SymbolicUse::automatic && d.long_digits &&
             (d.stages > 5 || !quick))
      skip = fmt::format(
          "not derived by default: {} stages with coefficients cut to 30 digits{} take the "
          "engine a minute or more (yoshida6 on Hénon–Heiles: about 16 s, suzuki4 on Kepler: "
          "about 30 s, yoshida6 on Kepler: unfinished after 11 minutes at 40 digits, on one "
          "core); --symbolic always runs it",
          d.stages, quick ? "" : ", on a Lagrangian that is not polynomial,");
    // A tableau typed to many digits (the Gauss files, 45): by default only to h^5
    if (skip.empty() && use == SymbolicUse::automatic && d.entry_digits > 20 && K > 4)
      skip = fmt::format(
          "not derived by default: entries of up to {} digits make every number long, and to "
          "h^{} the engine takes a minute or more (the four-stage Gauss file: about 13 s on the "
          "pendulum and 75 s on Henon-Heiles, on one core); --symbolic always runs it",
          d.entry_digits, K + 1);
    if (skip.empty() && use == SymbolicUse::automatic && d.cut_rule && d.dim > 1)
      skip = fmt::format(
          "not derived by default: with the nodes cut to 30 digits the engine takes minutes in "
          "{} dimensions (gauss:4 on Henon-Heiles: about 2 minutes on one core, on the "
          "pendulum about 15 s); --symbolic always runs it",
          d.dim);
    if (!skip.empty()) {
      rep.line("  derived", skip);
      jv["engine"] = {{"derived", false}, {"reason", skip}};
      return;
    }
    json je;
    je["source"] = d.source;
    je["checked_to"] = fmt::format("h^{}", K + 1);
    je["expected"] = s.expected;
    int r = -1;
    std::string first_term;
    try {
      const std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
      auto J = std::make_shared<modified::JetSpace>(d.dim);
      modified::Engine engine(d.make_dl(J), K);
      std::vector<modified::ex> x, v;
      for (int i = 0; i < d.dim; ++i) {
        x.push_back(J->x(0, i));
        v.push_back(J->x(1, i));
      }
      const auto vo = engine.variational_order(modified::exact_rationals(d.L(x, v)));
      json terms = json::array();
      for (const auto& t : vo.defect)
        terms.push_back(modified::canonical_string(t, modified::Format::text));
      je["defect"] = terms;  // [k]: the coefficient of h^{k+1} in L_d − L_d^E
      r = vo.order;
      if (d.zero_below) {
        // finite precision: the first coefficient with a number at or above the threshold
        r = order_above(vo.defect, *d.zero_below);
        json sizes = json::array();
        for (const auto& t : vo.defect) {
          const GiNaC::numeric top = largest_coefficient(t);
          sizes.push_back(top.is_zero() ? 0.0 : top.to_double());
        }
        je["largest_coefficient"] = sizes;  // [k]: the largest number in the h^{k+1} term
        je["zero_below"] = d.zero_below->to_double();
        je["precision"] = d.precision;
      }
      if (r >= 0) first_term = terms[static_cast<std::size_t>(r)].get<std::string>();
      if (r >= 0 && d.zero_below) {
        // the first term as shown_term gives it (the JSON keeps it whole under "defect")
        first_term = modified::canonical_string(
            shown_term(vo.defect[static_cast<std::size_t>(r)], *d.zero_below),
            modified::Format::text);
        je["first_term_shown"] = first_term;
      }
    } catch (const std::exception& e) {
      // The engine could not reach the answer (interior points that have no series solution, a
      // Lagrangian it cannot expand): reported, and the verdict does not count on it.
      const std::string why = std::string("not derived (engine): ") + e.what();
      rep.line("  derived", why);
      jv["engine"] = {{"derived", false}, {"reason", why}};
      return;
    }
    je["derived"] = true;
    je["order"] = r >= 0 ? json(r) : json(nullptr);
    const bool agrees_expected = r >= 0 && r == s.expected;
    if (judged) je["passed"] = agrees_expected;
    std::string measured;
    if (jv.contains("order") && jv["order"].is_number()) {
      const double slope = jv["order"].get<double>();
      const bool agrees = r >= 0 && std::abs(slope - r) < s.order_tol;
      // A measurement whose local slopes did not settle is not compared (map_study.cpp).
      if (jv.value("settled", true)) {
        je["agrees_with_measured"] = agrees;
        measured = fmt::format("; measured {:.2f}: {}", slope,
                               agrees ? "agrees" : "DISAGREES (a finding)");
      } else {
        measured =
            fmt::format("; measured {:.2f}: not compared (its local slopes did not settle)", slope);
      }
    }
    const std::string term =
        first_term.size() <= 100
            ? first_term
            : fmt::format("a {}-character expression, in the JSON", first_term.size());
    const std::string by =
        d.zero_below ? fmt::format("by the engine ({})", d.precision) : "by the engine";
    const std::string value =
        r >= 0 ? fmt::format("{} {}: L_d - L_d^E = h^{} ({}) + O(h^{})", r, by, r + 1, term, r + 2)
               : fmt::format(
                     "more than {} {}: every term of L_d - L_d^E through "
                     "h^{} vanishes",
                     K, by, K + 1);
    rep.line("  derived",
             value +
                 (judged ? fmt::format("; expected {:g}: {} (part of the verdict)", s.expected,
                                       agrees_expected ? "yes" : "NO")
                         : fmt::format("; expected {:g}: not judged (not an integer up to {})",
                                       s.expected, modified::max_order)) +
                 measured);
    jv["engine"] = je;
    if (judged) {
      rep.required.push_back("variational order");
      if (!agrees_expected) rep.failed.push_back("variational order");
    }
  };
}

// A decimal or a ratio of decimals, exactly ("-25/24", "0.125"); nullopt for anything else.
std::optional<GiNaC::numeric> exact_number(const std::string& t) {
  auto decimal = [](const std::string& s) -> std::optional<GiNaC::numeric> {
    std::size_t i = 0;
    bool negative = false;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) negative = s[i++] == '-';
    GiNaC::numeric value = 0, scale = 1;
    bool digits = false, point = false;
    for (; i < s.size(); ++i) {
      if (s[i] == '.' && !point) {
        point = true;
      } else if (std::isdigit(static_cast<unsigned char>(s[i]))) {
        digits = true;
        value = value * 10 + (s[i] - '0');
        if (point) scale *= 10;
      } else {
        return std::nullopt;
      }
    }
    if (!digits) return std::nullopt;
    return (negative ? -value : value) / scale;
  };
  const auto slash = t.find('/');
  if (slash == std::string::npos) return decimal(t);
  const auto a = decimal(t.substr(0, slash)), b = decimal(t.substr(slash + 1));
  if (!a || !b || b->is_zero()) return std::nullopt;
  return *a / *b;
}

// An mpfr value as the rational its decimal digits (`digits` of them) spell.
GiNaC::numeric rational_of(const mpfr_real& x, int digits) {
  const std::string t = x.str(digits, std::ios_base::scientific);  // "-1.2345...e-02"
  const auto e = t.find('e');
  const auto mantissa = exact_number(t.substr(0, e));
  if (!mantissa) throw std::logic_error("rational_of: cannot read " + t);
  const int exponent = e == std::string::npos ? 0 : std::stoi(t.substr(e + 1));
  return *mantissa * GiNaC::numeric(10).power(exponent);
}

// Coefficients the engine cannot have exactly: a catalogue composition's (cube roots, or known
// only numerically: Newton on the order conditions, or published digits) and the nodes of
// Gauss 4 (nested radicals). They are computed at kCompositionDigits digits and the engine
// takes each as the rational of its first kEngineDigits; a term of L_d − L_d^E whose every
// number is below kZeroBelow then counts as zero. The threshold sits between two scales. The
// cut leaves terms near 1e-30 (times the Lagrangian's own numbers), and the least precise
// catalogue entry, Kahan & Li's as published, has 26 digits, which leaves terms near 1e-27. A
// composition coefficient off in its eleventh digit leaves terms near 1e-12 (the field audit's
// A-WRONG-DIGIT), and the first true term of Gauss 4 (order 8, at h^9) has numbers from its
// error constant (4!)^4/(9 (8!)^3) = 1/1778112000, about 5.6e-10, up (the pendulum's
// cos(x) v^8 coefficient is exactly minus that constant). The engine's cost grows
// with the numbers' length: Yoshida's sixth-order composition on Hénon–Heiles took 77 s at
// 120 digits, 23 s at 40 and 16 s at 30, with the same derived order and the same h^7 term.
constexpr int kEngineDigits = 30;
const GiNaC::numeric kZeroBelow = GiNaC::numeric(1) / GiNaC::numeric(10).power(20);

// A Galerkin rule without a closed form, as rationals: its nodes computed at kCompositionDigits
// digits (Newton on their defining equation in MPFR, quadrature_in) and cut to their first
// kEngineDigits, placed symmetrically about 1/2 (c and 1 − c from one cut), and the weights
// those nodes' interpolatory ones, b_i = ∫_0^1 ℓ_i(τ) dτ, in exact arithmetic. The rule is then
// exactly symmetric and exact on the polynomials of degree below s (up to s for odd s), and
// only the higher moments that give Gauss its order carry the cut. Symmetry halves the terms
// the cut leaves (the even powers of h vanish exactly, as for a symmetric method), and the engine's
// cost grows with their number: gauss:4 on the pendulum took 103 s with independently cut nodes and
// weights (at 40 digits), and takes 22 s so (15 s at 30 digits).

}  // namespace

modified::ExactQuadrature cut_quadrature(const Quadrature& rule) {
  using GiNaC::numeric;
  const std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
  const MpfrDigits digits(kCompositionDigits);
  const QuadratureT<mpfr_real> r = quadrature_in<mpfr_real>(rule);
  const std::size_t s = r.c.size();
  std::vector<numeric> c(s);
  for (std::size_t i = 0; i < (s + 1) / 2; ++i) {
    c[i] = 2 * i + 1 == s ? numeric(1, 2) : rational_of(r.c[i], kEngineDigits);
    c[s - 1 - i] = 1 - c[i];
  }
  const GiNaC::symbol tau("tau");
  modified::ExactQuadrature q;
  for (std::size_t i = 0; i < s; ++i) {
    modified::ex ell = 1;
    for (std::size_t j = 0; j < s; ++j)
      if (j != i) ell *= (tau - c[j]) / (c[i] - c[j]);
    const modified::ex primitive = GiNaC::integral(tau, 0, 1, GiNaC::expand(ell)).eval_integ();
    q.c.push_back(c[i]);
    q.b.push_back(primitive);
  }
  return q;
}

void derive_galerkin_variational_order(const MethodSpec& spec, int dim,
                                       modified::SymbolicLagrangian L, SymbolicUse use,
                                       MapStudy& study) {
  const std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
  const std::optional<modified::ExactQuadrature> rule =
      modified::exact_quadrature(spec.rule.name, spec.stages);
  Derivation d;
  d.dim = dim;
  d.L = L;
  d.source =
      "engine: the Galerkin L_d (quadrature action of the degree-S polynomial, exact nodes and "
      "weights), its interior control points eliminated as series in h; L_d - L_d^E along the "
      "solutions of the intended L, expanded about the step's midpoint (Marsden & West 2001, "
      "Sec. 2.3.1 and 2.6)";
  modified::ExactQuadrature q;
  if (rule) {
    q = *rule;
  } else {
    // Gauss with four nodes: no closed form over the rationals and their square roots (nested
    // radicals). The rule cut to kEngineDigits (cut_quadrature); a term of L_d − L_d^E whose
    // every number is below kZeroBelow counts as zero.
    q = cut_quadrature(spec.rule);
    d.cut_rule = true;
    d.zero_below = kZeroBelow;
    d.precision = fmt::format(
        "the nodes and weights of {} to {} digits, a term with every number below 1e-20 "
        "counted as zero",
        spec.name, kEngineDigits);
  }
  d.make_dl = [q, L, name = spec.name](std::shared_ptr<modified::JetSpace> J) {
    return modified::galerkin_dl(q, L, std::move(J), name);
  };
  install(std::move(d), use, study);
}

// --- compositions -----------------------------------------------------------------------------

namespace {

using ExactStages = std::vector<std::pair<modified::ex, bool>>;  // coefficient, adjoint

// Coefficients typed as decimals are the rationals they spell, and the order conditions hold
// them to 1e-12 (composition_study.cpp, kConditionTol: decimals rounded to double leave
// 1e-15 to 1e-13, a wrong eleventh digit 1e-11). The engine takes the same tolerance: Forest
// and Ruth's coefficients typed to 18 digits leave an h^3 term of about 1e-19 in L_d − L_d^E,
// which an exact zero test would read as variational order 2.
const GiNaC::numeric kTypedZeroBelow = GiNaC::numeric(1) / GiNaC::numeric(10).power(12);

// Does the text type a decimal (a point between digits, or an exponent)?
bool types_a_decimal(const std::string& t) {
  for (std::size_t i = 1; i < t.size(); ++i)
    if (std::isdigit(static_cast<unsigned char>(t[i - 1])) &&
        (t[i] == '.' || t[i] == 'e' || t[i] == 'E'))
      return true;
  return false;
}

// The stages as exact rationals: a typed list of exact decimals or ratios, or a catalogue
// entry (Ruth's exactly; the others at kEngineDigits digits, `zero_below` and `precision`
// then set). nullopt, with the reason, otherwise.
std::optional<ExactStages> exact_stages(const CompositionSpec& spec, std::string& why,
                                        std::optional<GiNaC::numeric>* zero_below = nullptr,
                                        std::string* precision = nullptr,
                                        bool* long_digits = nullptr) {
  ExactStages st;
  if (!spec.not_exact.empty()) {
    why = spec.not_exact;
    return std::nullopt;
  }
  if (spec.entry && spec.entry->name != "ruth3") {
    const std::string& n = spec.entry->name;
    if (!zero_below || !precision) {
      why = fmt::format(
          "not derived: the coefficients of {} are not rational ({}), and the engine's zero "
          "test needs them exactly",
          n, spec.entry->derivation);
      return std::nullopt;
    }
    for (const auto& [c, adjoint] : catalogue_rationals(n)) st.emplace_back(c, adjoint);
    *zero_below = kZeroBelow;
    if (long_digits) *long_digits = true;
    *precision = fmt::format(
        "the coefficients of {} to {} digits, a term with every number below 1e-20 counted as "
        "zero",
        n, kEngineDigits);
    return st;
  }
  const std::string list = spec.entry ? std::string(composition::kRuth3Stages) : spec.coefficients;
  std::size_t from = 0;
  while (from <= list.size()) {
    const auto comma = std::min(list.find(',', from), list.size());
    std::string t = list.substr(from, comma - from);
    t.erase(0, t.find_first_not_of(" \t"));
    t.erase(t.find_last_not_of(" \t") + 1);
    bool adjoint = false;
    if (!t.empty() && t.back() == '*') {
      adjoint = true;
      t.pop_back();
      t.erase(t.find_last_not_of(" \t") + 1);
    }
    const auto x = exact_number(t);
    if (!x) {
      why = "not derived: the coefficient '" + t +
            "' is not an exact decimal or ratio, and the engine's zero test needs it exactly";
      return std::nullopt;
    }
    st.emplace_back(*x, adjoint);
    from = comma + 1;
  }
  const std::string typed = spec.splitting             ? spec.splitting->flows
                            : spec.flows_typed.empty() ? spec.coefficients
                                                       : spec.flows_typed;
  if (zero_below && precision && !spec.entry && types_a_decimal(typed)) {
    *zero_below = kTypedZeroBelow;
    *precision =
        "the coefficients as the rationals their decimals spell, a term with every number "
        "below 1e-12 (the order conditions' tolerance) counted as zero";
  }
  return st;
}

// A stage's discrete Lagrangian on the engine's symbols, positions as vectors of expressions
// (the form the public API takes; on_vec/on_vectors convert to and from Vec<ex, N>).
using StageDl = SymbolicStageDl;

template <int N>
StageDl on_vectors(std::function<modified::ex(const Vec<modified::ex, N>&,
                                              const Vec<modified::ex, N>&, const modified::ex&)>
                       f) {
  return [f](const std::vector<modified::ex>& a, const std::vector<modified::ex>& b,
             const modified::ex& h) {
    Vec<modified::ex, N> x, y;
    for (int i = 0; i < N; ++i) {
      x(i) = a[static_cast<std::size_t>(i)];
      y(i) = b[static_cast<std::size_t>(i)];
    }
    return f(x, y, h);
  };
}

template <int N>
auto on_vec(const StageDl& f) {
  return [f](const Vec<modified::ex, N>& a, const Vec<modified::ex, N>& b, const modified::ex& h) {
    return f(std::vector<modified::ex>(a.data(), a.data() + N),
             std::vector<modified::ex>(b.data(), b.data() + N), h);
  };
}

// The composed discrete Lagrangian: the sum of the stages' L_d between consecutive interior
// points, the adjoint's L_d for a stage marked '*' (composition_study.cpp's construction, on
// symbols), zero stages dropped. Interior point i starts on the chord at the stages' partial
// sum (a rational close to it: only the start of Newton's method on series).
template <int N>
modified::SymbolicDL compose_dl(const StageDl& first_v, const StageDl& second_v,
                                const ExactStages& stages, std::shared_ptr<modified::JetSpace> J,
                                const std::string& description) {
  using V = Vec<modified::ex, N>;
  const auto first = on_vec<N>(first_v), second = on_vec<N>(second_v);
  ExactStages st;
  for (const auto& s : stages)
    if (!s.first.is_zero()) st.push_back(s);
  std::vector<GiNaC::numeric> at;
  double sum = 0;
  for (std::size_t i = 0; i + 1 < st.size(); ++i) {
    sum += GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(st[i].first)).to_double();
    at.emplace_back(static_cast<long>(std::lround(sum * 1024)), 1024);
  }
  const auto dl = [&](const V& q0, const std::vector<V>& Q, const V& q1, const modified::ex& h) {
    auto point = [&](std::size_t i) -> const V& {
      return i == 0 ? q0 : i == st.size() ? q1 : Q[i - 1];
    };
    modified::ex total = 0;
    for (std::size_t i = 0; i < st.size(); ++i)
      total += (st[i].second ? second : first)(point(i), point(i + 1), st[i].first * h);
    return total;
  };
  return modified::symbolic_dl_interior<N>(dl, std::move(J), description, at);
}

// The stages' L_d of a built-in base on the intended L, composed.
template <int N>
modified::SymbolicDL composition_dl(const std::string& base, const ExactStages& stages,
                                    const modified::SymbolicLagrangian& lagrangian,
                                    std::shared_ptr<modified::JetSpace> J,
                                    const std::string& description) {
  using V = Vec<modified::ex, N>;
  using Dl = std::function<modified::ex(const V&, const V&, const modified::ex&)>;
  // The stages' discrete Lagrangians (mechanics/discrete_lagrangian.hpp; Vermeeren 2017,
  // Example 1) on the same L as the engine's exact side, written here with exact halves: the
  // templates' 0.5 would turn a rational such as Hénon–Heiles' 1/3 into a 17-digit float, and
  // its binary64 value would differ from 1/6 in the 17th digit, a defect at h^1.
  const auto L = [&lagrangian](const V& q, const V& v) {
    std::vector<modified::ex> x(q.data(), q.data() + N), u(v.data(), v.data() + N);
    return lagrangian(x, u);
  };
  const Dl trapezoid = [L](const V& a, const V& b, const modified::ex& h) {
    const V v = (b - a) / h;
    return h * (L(a, v) + L(b, v)) / 2;
  };
  const Dl midpoint = [L](const V& a, const V& b, const modified::ex& h) {
    return h * L(V((a + b) / 2), V((b - a) / h));
  };
  const Dl right = [L](const V& a, const V& b, const modified::ex& h) {  // se: L(q1, v)
    return h * L(b, V((b - a) / h));
  };
  const Dl left = [L](const V& a, const V& b, const modified::ex& h) {  // se-adjoint: L(q0, v)
    return h * L(a, V((b - a) / h));
  };
  Dl first, second;  // the base's L_d and its adjoint's
  if (base == "sv") {
    first = second = trapezoid;
  } else if (base == "midpoint") {
    first = second = midpoint;
  } else {
    first = base == "se" ? right : left;
    second = base == "se" ? left : right;
  }
  return compose_dl<N>(on_vectors<N>(first), on_vectors<N>(second), stages, std::move(J),
                       description);
}

}  // namespace

void derive_composition_variational_order(const CompositionSpec& spec, const std::string& problem,
                                          SymbolicUse use, MapStudy& study) {
  const std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
  Derivation d;
  d.L = test_problem_lagrangian(problem);
  const TestProblem* tp = find_problem(problem);
  if (!tp)
    throw std::logic_error("derive_composition_variational_order: no test problem " + problem);
  d.dim = static_cast<int>(tp->q0.size());
  d.source =
      "engine: the composed L_d (the stages' discrete Lagrangians summed over the interior "
      "points, the coefficients exact), its interior points eliminated as series in h; L_d - "
      "L_d^E along the solutions of the intended L, expanded about the step's midpoint "
      "(Marsden & West 2001, Sec. 2.3.1)";
  const std::string base = spec.base->name;
  std::string why;
  const auto stages = exact_stages(spec, why, &d.zero_below, &d.precision, &d.long_digits);
  if (stages) d.stages = static_cast<int>(stages->size());
  if (base != "sv" && base != "midpoint" && base != "se" && base != "se-adjoint")
    d.skip = "not derived: the engine composes sv, midpoint, se and se-adjoint (not " + base + ")";
  else if (!stages)
    d.skip = why;
  else
    d.make_dl = [base, st = *stages, L = d.L, dim = d.dim,
                 name = spec.coefficients](std::shared_ptr<modified::JetSpace> J) {
      return dim == 1 ? composition_dl<1>(base, st, L, std::move(J), name)
                      : composition_dl<2>(base, st, L, std::move(J), name);
    };
  install(std::move(d), use, study);
}

void derive_composition_variational_order(const CompositionSpec& spec, int dim,
                                          const SymbolicStageDl& ld, modified::SymbolicLagrangian L,
                                          SymbolicUse use, MapStudy& study) {
  const std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
  Derivation d;
  d.L = std::move(L);
  d.dim = dim;
  d.source =
      "engine: the composed L_d (the typed L_d and its adjoint -L_d(q1, q0, -h) summed over the "
      "interior points, the coefficients exact), its interior points eliminated as series in h; "
      "L_d - L_d^E along the solutions of the intended L, expanded about the step's midpoint "
      "(Marsden & West 2001, Sec. 2.3.1)";
  std::string why;
  const auto stages = exact_stages(spec, why, &d.zero_below, &d.precision, &d.long_digits);
  if (stages) d.stages = static_cast<int>(stages->size());
  d.typed = true;
  if (!d.L)
    d.skip =
        "not derived: the system is typed as a Hamiltonian (--hamiltonian), and the engine "
        "expands L_d - L_d^E along the solutions of a Lagrangian (type --lagrangian, or "
        "--potential for |v|^2/2 - V)";
  else if (dim < 1 || dim > 3)
    d.skip = "not derived: the engine composes in 1 to 3 dimensions";
  else if (!stages)
    d.skip = why;
  else
    d.make_dl = [ld, st = *stages, dim,
                 name = spec.coefficients](std::shared_ptr<modified::JetSpace> J) {
      const StageDl adjoint = [ld](const std::vector<modified::ex>& a,
                                   const std::vector<modified::ex>& b,
                                   const modified::ex& h) { return -ld(b, a, -h); };
      return dim == 1   ? compose_dl<1>(ld, adjoint, st, std::move(J), name)
             : dim == 2 ? compose_dl<2>(ld, adjoint, st, std::move(J), name)
                        : compose_dl<3>(ld, adjoint, st, std::move(J), name);
    };
  install(std::move(d), use, study);
}

std::vector<std::pair<GiNaC::numeric, bool>> catalogue_rationals(const std::string& name) {
  const std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
  std::vector<std::pair<GiNaC::numeric, bool>> out;
  const MpfrDigits digits(kCompositionDigits);
  for (const auto& stage : composition::catalogue_stages<mpfr_real>(name, kCompositionDigits))
    out.emplace_back(rational_of(stage.c, kEngineDigits), stage.adjoint);
  return out;
}

GiNaC::numeric composition_zero_below() {
  const std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
  return kZeroBelow;
}

namespace {

// The engine's variational order, through h^{K+1}, of the discrete Lagrangian `make_dl` builds
// on a test problem's jets, with L that problem's Lagrangian (the tests' route to the report's).
int test_problem_variational_order(
    const std::string& problem, int K, std::optional<GiNaC::numeric> zero_below,
    const std::function<modified::SymbolicDL(const modified::SymbolicLagrangian&, int,
                                             std::shared_ptr<modified::JetSpace>)>& make_dl) {
  const TestProblem* tp = find_problem(problem);
  if (!tp) throw std::invalid_argument("variational order: no test problem " + problem);
  const int dim = static_cast<int>(tp->q0.size());
  const std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
  const modified::SymbolicLagrangian L = test_problem_lagrangian(problem);
  auto J = std::make_shared<modified::JetSpace>(dim);
  modified::Engine engine(make_dl(L, dim, J), K);
  std::vector<modified::ex> x, v;
  for (int i = 0; i < dim; ++i) {
    x.push_back(J->x(0, i));
    v.push_back(J->x(1, i));
  }
  const auto vo = engine.variational_order(modified::exact_rationals(L(x, v)));
  return zero_below ? order_above(vo.defect, *zero_below) : vo.order;
}

}  // namespace

int galerkin_variational_order(const modified::ExactQuadrature& rule, const std::string& problem,
                               int K, std::optional<GiNaC::numeric> zero_below) {
  return test_problem_variational_order(
      problem, K, zero_below,
      [&rule](const modified::SymbolicLagrangian& L, int, std::shared_ptr<modified::JetSpace> J) {
        return modified::galerkin_dl(rule, L, std::move(J), "test");
      });
}

int composition_variational_order(const std::string& base,
                                  const std::vector<std::pair<GiNaC::numeric, bool>>& stages,
                                  const std::string& problem, int K,
                                  std::optional<GiNaC::numeric> zero_below) {
  const std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
  ExactStages st;
  for (const auto& [c, adjoint] : stages) st.emplace_back(c, adjoint);
  return test_problem_variational_order(
      problem, K, zero_below,
      [&](const modified::SymbolicLagrangian& L, int dim, std::shared_ptr<modified::JetSpace> J) {
        return dim == 1 ? composition_dl<1>(base, st, L, std::move(J), "test")
                        : composition_dl<2>(base, st, L, std::move(J), "test");
      });
}

// --- Shen & Sun 2025, Theorem 10, on an RKN tableau --------------------------------------------

NystromTheorem10 nystrom_theorem10(const std::vector<mpfr_real>& c,
                                   const std::vector<std::vector<mpfr_real>>& abar,
                                   const std::vector<mpfr_real>& bbar,
                                   const std::vector<mpfr_real>& b) {
  using GiNaC::numeric;
  std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
  const std::size_t s = b.size();
  modified::NystromTableau tab;
  for (std::size_t i = 0; i < s; ++i) {
    tab.c.push_back(rational_of(c[i], kCompositionDigits));
    tab.bbar.push_back(rational_of(bbar[i], kCompositionDigits));
    tab.bhat.push_back(rational_of(b[i], kCompositionDigits));
    tab.abar.emplace_back();
    for (std::size_t j = 0; j < s; ++j)
      tab.abar.back().push_back(rational_of(abar[i][j], kCompositionDigits));
  }
  auto num = [](const modified::ex& e) { return GiNaC::ex_to<numeric>(e); };
  numeric alpha = -1, sum1 = 1, sum2 = 1, bsum = 0;
  for (std::size_t i = 0; i < s; ++i) {
    const numeric ci = num(tab.c[i]), bi = num(tab.bhat[i]), bbi = num(tab.bbar[i]);
    alpha += bi * ci + bbi;
    sum1 += bi * ci * ci + 2 * (bbi - bi) * ci - bbi;
    sum2 += 2 * bbi * ci - bi * ci - bbi;
    for (std::size_t j = 0; j < s; ++j)
      sum2 += 2 * bi * (num(tab.abar[i][j]) - ci * num(tab.bbar[j]));
    bsum += bi;
  }
  const numeric beta1 = numeric(-1, 12) + sum1 / 2, beta2 = numeric(-1, 12) + sum2 / 2;
  auto J = std::make_shared<modified::JetSpace>(1);
  const int fam = J->add_family("f", "f");
  const auto E = modified::nystrom_modified_equation(J, tab, 2);
  const modified::ex xdot = J->x(1, 0), f = J->derivative(fam, {}), f1 = J->derivative(fam, {0}),
                     f11 = J->derivative(fam, {0, 0});
  NystromTheorem10 r;
  r.alpha = alpha.to_double();
  r.beta1 = beta1.to_double();
  r.beta2 = beta2.to_double();
  r.weights_residual = std::abs((bsum - 1).to_double());
  r.h1_difference = largest_coefficient(E[1][0] - alpha * f1 * xdot).to_double();
  r.h2_difference =
      largest_coefficient(E[2][0] - (beta1 * f11 * xdot * xdot + beta2 * f1 * f)).to_double();
  return r;
}

// --- a symplectic tableau (book chapter "Verify your own integrator", section "A method from
// its tableau": the variational order derived) --------------------------------------------------

// A tableau's decimal entries: up to kExactDecimalDigits significant digits they are the
// numbers meant (0.5, 0.125); beyond, the numbers they cut, which the derivation needs written
// to at least kCutDigitsNeeded digits (derive_tableau_variational_order says why).
constexpr std::size_t kExactDecimalDigits = 6, kCutDigitsNeeded = 25;

void derive_tableau_variational_order(const TableauSpec& spec, int dim,
                                      modified::SymbolicLagrangian L, SymbolicUse use,
                                      MapStudy& study) {
  // Without the conditions (or for an RKN tableau) the tableau route says itself why there is
  // no discrete Lagrangian to derive.
  if (spec.rkn || !spec.symplectic_conditions) return;
  const std::lock_guard<std::recursive_mutex> lock(modified::ginac_mutex());
  Derivation d;
  d.dim = dim;
  d.L = L;
  d.stages = static_cast<int>(spec.b_text.size());
  d.source =
      "engine: the tableau's L_d = ext h sum_i b_i L(q0 + h sum_j a_ij V_j, V_i) subject to q1 = "
      "q0 + h sum_j b_j V_j, the stage velocities eliminated as series in h; L_d - L_d^E along "
      "the solutions of the intended L, expanded about the step's midpoint (Suris; Marsden & "
      "West 2001; Hairer, Lubich & Wanner VI.6)";
  // The entries as the rationals they are written as.
  std::vector<std::vector<modified::ex>> a;
  std::vector<modified::ex> b;
  bool decimal = false;
  std::size_t longest = 0;  // digits of the longest entry
  std::size_t cut_at = 0;   // significant digits of the shortest cut decimal (0: none)
  auto read = [&](const std::string& t) -> std::optional<modified::ex> {
    const std::optional<GiNaC::numeric> x = exact_number(t);
    if (!x) return std::nullopt;
    const bool point = types_a_decimal(t);  // (exact_number reads no exponent)
    decimal = decimal || point;
    // digits from position `from` on (exact_number reads no exponent)
    auto digits_from = [&t](std::size_t from) -> std::size_t {
      return from == std::string::npos
                 ? 0
                 : std::count_if(
                       t.begin() + static_cast<std::ptrdiff_t>(from), t.end(),
                       [](char ch) { return std::isdigit(static_cast<unsigned char>(ch)); });
    };
    longest = std::max(longest, digits_from(0));
    const std::size_t significant = digits_from(t.find_first_of("123456789"));
    // a decimal of more than 6 significant digits stands for a number it cuts after its last
    // digit (0.5 or 0.125 is the number itself)
    if (point && significant > kExactDecimalDigits)
      cut_at = cut_at == 0 ? significant : std::min(cut_at, significant);
    return modified::ex(*x);
  };
  std::string unread;
  for (std::size_t i = 0; i < spec.b_text.size() && unread.empty(); ++i) {
    const auto bi = read(spec.b_text[i]);
    if (!bi)
      unread = fmt::format("b[{}] ('{}')", i, spec.b_text[i]);
    else
      b.push_back(*bi);
    a.emplace_back();
    for (std::size_t k = 0; k < spec.a_text[i].size() && unread.empty(); ++k) {
      const auto aik = read(spec.a_text[i][k]);
      if (!aik)
        unread = fmt::format("a[{}][{}] ('{}')", i, k, spec.a_text[i][k]);
      else
        a.back().push_back(*aik);
    }
  }
  if (!L) {
    d.skip =
        "not derived: the system is typed as a Hamiltonian, and vibook does not form its "
        "Lagrangian symbolically";
  } else if (!unread.empty()) {
    d.skip = "not derived: the entry " + unread +
             " is not a decimal or a ratio, which the engine needs to read exactly";
  } else if (std::any_of(b.begin(), b.end(), [](const modified::ex& x) { return x.is_zero(); })) {
    d.skip =
        "not derived: a weight b_i = 0 leaves its stage velocity undetermined in h sum_i b_i "
        "L(Q_i, V_i)";
  }
  if (decimal) d.entry_digits = longest;
  if (cut_at > 0 && d.skip.empty()) {
    // Entries cut to D significant digits leave terms of L_d − L_d^E near 10^-D (the 45-digit
    // Gauss files: at most 2e-46); the true first terms of tableaus up to six stages reach down
    // to Gauss 6's, near 2e-16 (Gauss 5: 4e-13, its error constant (5!)^4/(11 (10!)^3)). A
    // term with every number below 10^-(D-5) counts as zero, which separates the two only when
    // that threshold lies well below 2e-16: from D = 25 (10^-20) on. Fewer digits: not derived.
    if (cut_at < kCutDigitsNeeded) {
      d.skip = fmt::format(
          "not derived: entries typed to {} significant digits leave terms near 1e-{}, which the "
          "engine cannot tell from the true first terms of high-order methods (Gauss 6's: near "
          "2e-16); type them to {} digits or more, or as ratios",
          cut_at, cut_at, kCutDigitsNeeded);
    } else {
      d.zero_below = GiNaC::numeric(1) / GiNaC::numeric(10).power(static_cast<long>(cut_at) - 5);
      d.precision = fmt::format(
          "the entries as the decimals typed, to {} digits and more, a term with every number "
          "below 1e-{} counted as zero",
          cut_at, cut_at - 5);
    }
  }
  d.make_dl = [a, b, L, name = spec.name](std::shared_ptr<modified::JetSpace> J) {
    return modified::prk_dl(a, b, L, std::move(J), name);
  };
  install(std::move(d), use, study);
}

}  // namespace vibook::verify
