// The variational order of a Galerkin method from the symbolic engine (method_symbolic.hpp):
// Marsden & West 2001, §2.3.1 (the variational order) and §2.6 (the Galerkin discrete
// Lagrangian), the interior control points eliminated order by order in h.
#include "vibook/verify/method_symbolic.hpp"

#include <cmath>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "vibook/core/errors.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/modified/canonical.hpp"
#include "vibook/modified/ginac_eigen.hpp"
#include "vibook/problems/problems.hpp"

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

void derive_galerkin_variational_order(const MethodSpec& spec, int dim,
                                       modified::SymbolicLagrangian L, SymbolicUse use,
                                       MapStudy& study) {
  const std::optional<modified::ExactQuadrature> rule =
      modified::exact_quadrature(spec.rule.name, spec.stages);
  const bool judged =
      spec.expected == std::floor(spec.expected) && spec.expected <= modified::max_order;
  const int K = static_cast<int>(std::min<double>(std::ceil(spec.expected), modified::max_order));
  // Is L polynomial in q and v? (Then the engine is quick in any dimension.)
  bool polynomial = false;
  {
    std::lock_guard<std::mutex> lock(modified::ginac_mutex());
    modified::JetSpace J(dim);
    std::vector<modified::ex> x, v;
    GiNaC::lst vars;
    for (int i = 0; i < dim; ++i) {
      x.push_back(J.x(0, i));
      v.push_back(J.x(1, i));
      vars.append(x.back());
      vars.append(v.back());
    }
    polynomial = L(x, v).is_polynomial(vars);
  }
  std::string skip;
  if (use == SymbolicUse::never)
    skip = "not derived (--symbolic never)";
  else if (!rule)
    skip = fmt::format(
        "not derived: the nodes of {} are nested radicals, and the engine's zero test is exact "
        "only over the rationals and their square roots",
        spec.name);
  else if (use == SymbolicUse::automatic && dim > 1 && K > 4 && !polynomial)
    skip = fmt::format(
        "not derived by default: to h^{} in {} dimensions, with a Lagrangian that is not "
        "polynomial, the engine takes minutes (gauss:3 on Kepler: about 2 minutes on 2 cores); "
        "--symbolic always runs it",
        K + 1, dim);
  const MethodSpec method = spec;
  study.derive_variational_order = [=](const MapStudy& s, MapMeasurement& rep) {
    json& jv = rep.js["variational_order"];
    if (!skip.empty()) {
      rep.line("  derived", skip);
      jv["engine"] = {{"derived", false}, {"reason", skip}};
      return;
    }
    json je;
    je["source"] =
        "engine: the Galerkin L_d (quadrature action of the degree-S polynomial, exact nodes "
        "and weights), its interior control points eliminated as series in h; L_d - L_d^E "
        "along the solutions of the intended L, expanded about the step's midpoint (Marsden & "
        "West 2001, Sec. 2.3.1 and 2.6)";
    je["checked_to"] = fmt::format("h^{}", K + 1);
    je["expected"] = method.expected;
    int r = -1;
    std::string first_term;
    try {
      std::lock_guard<std::mutex> lock(modified::ginac_mutex());
      auto J = std::make_shared<modified::JetSpace>(dim);
      modified::Engine engine(modified::galerkin_dl(*rule, L, J, method.name), K);
      std::vector<modified::ex> x, v;
      for (int i = 0; i < dim; ++i) {
        x.push_back(J->x(0, i));
        v.push_back(J->x(1, i));
      }
      const auto vo = engine.variational_order(modified::exact_rationals(L(x, v)));
      json terms = json::array();
      for (const auto& d : vo.defect)
        terms.push_back(modified::canonical_string(d, modified::Format::text));
      je["defect"] = terms;  // [k]: the coefficient of h^{k+1} in L_d − L_d^E
      r = vo.order;
      if (r >= 0) first_term = terms[static_cast<std::size_t>(r)].get<std::string>();
    } catch (const std::exception& e) {
      // The engine could not reach the answer (an interior point that has no series solution,
      // a Lagrangian it cannot expand): reported, and the verdict does not count on it.
      const std::string why = std::string("not derived (engine): ") + e.what();
      rep.line("  derived", why);
      jv["engine"] = {{"derived", false}, {"reason", why}};
      return;
    }
    je["derived"] = true;
    je["order"] = r >= 0 ? json(r) : json(nullptr);
    const bool agrees_expected = r >= 0 && r == method.expected;
    if (judged) je["passed"] = agrees_expected;
    std::string measured;
    if (jv.contains("order") && jv["order"].is_number()) {
      const double slope = jv["order"].get<double>();
      const bool agrees = r >= 0 && std::abs(slope - r) < s.order_tol;
      je["agrees_with_measured"] = agrees;
      measured =
          fmt::format("; measured {:.2f}: {}", slope, agrees ? "agrees" : "DISAGREES (a finding)");
    }
    const std::string term =
        first_term.size() <= 100
            ? first_term
            : fmt::format("a {}-character expression, in the JSON", first_term.size());
    const std::string value =
        r >= 0 ? fmt::format("{} by the engine: L_d - L_d^E = h^{} ({}) + O(h^{})", r, r + 1, term,
                             r + 2)
               : fmt::format(
                     "more than {} by the engine: every term of L_d - L_d^E through "
                     "h^{} vanishes",
                     K, K + 1);
    rep.line("  derived",
             value +
                 (judged ? fmt::format("; expected {:g}: {} (part of the verdict)", method.expected,
                                       agrees_expected ? "yes" : "NO")
                         : fmt::format("; expected {:g}: not judged (not an integer up to {})",
                                       method.expected, modified::max_order)) +
                 measured);
    jv["engine"] = je;
    if (judged) {
      rep.required.push_back("variational order");
      if (!agrees_expected) rep.failed.push_back("variational order");
    }
  };
}

}  // namespace vibook::verify
