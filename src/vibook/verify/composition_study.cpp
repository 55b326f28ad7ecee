// A composition method measured on a test problem (composition_study.hpp): the order
// conditions of the composition at 120 digits, weight by weight; the measured order on a
// nonlinear problem against the continuous equations integrated in double-double (never against
// the method itself); symplecticity and reversibility of the one-step map; the energy's
// long-time behaviour. `vibook verify --composition` prints it, the field audit records it.
#include "vibook/verify/composition_study.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <boost/multiprecision/cpp_int.hpp>

#include "vibook/integrators/kernels.hpp"
#include "vibook/integrators/splitting.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/mechanics/discrete_lagrangian.hpp"
#include "vibook/problems/problems.hpp"

namespace vibook::verify {

const std::vector<CompositionBase>& composition_bases() {
  static const std::vector<CompositionBase> b = {
      {"sv", true, "Störmer-Verlet (velocity form), symmetric, order 2"},
      {"midpoint", true, "the implicit midpoint rule, symmetric, order 2"},
      {"se", false,
       "symplectic Euler q1 = q0 + h p0, p1 = p0 - h grad U(q1) (drift, then kick), order 1; its "
       "adjoint kicks, then drifts"},
      {"se-adjoint", false,
       "adjoint symplectic Euler p1 = p0 - h grad U(q0), q1 = q0 + h p1 (kick, then drift), "
       "order 1; its adjoint is se"},
      {"vi1", false,
       "Shen & Sun's VI-1 (3.3): symplectic-Euler sub-steps of H_i = p_i^2/2 + phi^[i], one per "
       "coordinate, the potential split phi^[1] = phi^[2] = phi/2, order 1; its adjoint is "
       "vi1-adjoint"},
      {"vi1-adjoint", false,
       "the adjoint of Shen & Sun's VI-1, the sub-steps reversed and each adjoint, order 1; its "
       "adjoint is vi1"},
      {"vi2", true,
       "Shen & Sun's VI-2 (3.15), VI-1 after its adjoint at half steps, the potential split in "
       "halves, symmetric, order 2"}};
  return b;
}

const CompositionBase* find_composition_base(const std::string& name) {
  for (const auto& b : composition_bases())
    if (b.name == name) return &b;
  return nullptr;
}

namespace {

using nlohmann::json;
namespace comp = vibook::composition;

// The order conditions are evaluated at this many decimal digits.
// "Satisfied" for the verdict: coefficients rounded to double already leave residuals of
// 1e-15–1e-13 (Yoshida's 15-digit values 5e-14); a coefficient off in its eleventh digit leaves
// 1e-11 or more.
constexpr double kConditionTol = 1e-12;
// "Visible": a residual above this shows in an order study in double; the expected order of a
// typed list is the order the conditions give at this tolerance.
constexpr double kVisibleTol = 1e-8;

// A stage that also returns its discrete Lagrangian: the kernel's step from q0 to q1, then
// L_d(q0, q1, h) of the discrete Lagrangian that generates the kernel (mechanics/, splitting.hpp).
template <int N, class Kernel, class Ld>
auto generating_stage(Kernel kernel, Ld ld) {
  auto k = std::make_shared<Kernel>(std::move(kernel));
  return [k, ld](Vec<double, N>& q, Vec<double, N>& p, double h) {
    const Vec<double, N> q0 = q;
    k->step(q, p, h);
    return double(ld(q0, q, h));
  };
}

// The composed step with the composed discrete Lagrangian: the sum of the stages' L_d at the
// positions the stages pass through. Those are the interior points at which the sum is
// stationary for the two ends (the discrete Euler–Lagrange equations at an interior point are
// the continuity of the momentum), so the sum is the composition's L_d(q0, q1, h).
template <int N, class Base, class Adjoint>
GeneratingStep composed_generating(Base base, Adjoint adjoint, const std::vector<double>& c,
                                   const std::vector<bool>& adj) {
  return [base, adjoint, c, adj](Eigen::VectorXd& z, double h) mutable {
    Vec<double, N> q = z.head<N>(), p = z.tail<N>();
    double Ld = 0;
    for (std::size_t i = 0; i < c.size(); ++i)
      if (c[i] != 0) Ld += adj[i] ? adjoint(q, p, c[i] * h) : base(q, p, c[i] * h);
    z << q, p;
    return Ld;
  };
}

template <class P>
GeneratingStep generating_composition(const std::string& b, const P& prob,
                                      const std::vector<double>& c, const std::vector<bool>& adj) {
  constexpr int N = P::N;
  const auto L = mechanical_lagrangian(prob);
  if (b == "sv") {
    auto g = generating_stage<N>(StormerVerlet<P>(prob), stormer_verlet_dl(L));
    return composed_generating<N>(g, g, c, adj);
  }
  if (b == "midpoint") {
    auto g = generating_stage<N>(ImplicitMidpoint<P>(prob), midpoint_dl(L));
    return composed_generating<N>(g, g, c, adj);
  }
  auto se = generating_stage<N>(SymplecticEuler<P>(prob), symplectic_euler_dl(L));
  auto se_adj =
      generating_stage<N>(SymplecticEulerAdjoint<P>(prob), symplectic_euler_adjoint_dl(L));
  if (b == "se") return composed_generating<N>(se, se_adj, c, adj);
  if (b == "se-adjoint") return composed_generating<N>(se_adj, se, c, adj);
  // Shen & Sun 2025: VI-1 is generated by (3.3), its adjoint by L_d*(x0, x1, h) =
  // −L_d(x1, x0, −h); VI-2 (3.8) is the adjoint at h/2 followed by VI-1 at h/2.
  using Kernel = SplittingKernel<WeightedSplit<P>>;
  const auto split = WeightedSplit<P>::alpha(0.5, prob);
  auto vi1 = generating_stage<N>(Kernel(split, SplittingMethod::vi1), splitting_dl(split));
  auto vi1_adj =
      generating_stage<N>(Kernel(split, SplittingMethod::vi1_adjoint), splitting_dl_adjoint(split));
  if (b == "vi1") return composed_generating<N>(vi1, vi1_adj, c, adj);
  if (b == "vi1-adjoint") return composed_generating<N>(vi1_adj, vi1, c, adj);
  auto vi2 = [vi1, vi1_adj](Vec<double, N>& q, Vec<double, N>& p, double h) mutable {
    const double a = vi1_adj(q, p, 0.5 * h);
    return a + vi1(q, p, 0.5 * h);
  };
  return composed_generating<N>(vi2, vi2, c, adj);
}

// --- splittings (splitting_sequence.hpp) -----------------------------------------------------

// A coefficient typed as an exact ratio of decimals ("7/24", "-0.25", "3"), as a rational; none
// for anything else (an expression, an exponent).
std::optional<boost::multiprecision::cpp_rational> exact_ratio(std::string t) {
  using boost::multiprecision::cpp_int;
  using boost::multiprecision::cpp_rational;
  t.erase(0, t.find_first_not_of(" \t"));
  t.erase(t.find_last_not_of(" \t") + 1);
  auto decimal = [](const std::string& d) -> std::optional<cpp_rational> {
    std::size_t i = 0;
    bool minus = false;
    if (i < d.size() && (d[i] == '-' || d[i] == '+')) minus = d[i++] == '-';
    std::string digits;
    int scale = -1;
    for (; i < d.size(); ++i) {
      if (d[i] == '.' && scale < 0) {
        scale = 0;
      } else if (std::isdigit(static_cast<unsigned char>(d[i]))) {
        digits += d[i];
        if (scale >= 0) ++scale;
      } else {
        return std::nullopt;
      }
    }
    if (digits.empty() || digits.size() > 200) return std::nullopt;
    // no leading zeros: Boost reads "0193" as octal
    digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size() - 1));
    cpp_rational r(cpp_int(digits), pow(cpp_int(10), std::max(scale, 0)));
    return minus ? cpp_rational(-r) : r;
  };
  const auto slash = t.find('/');
  const auto a = decimal(t.substr(0, slash));
  if (!a) return std::nullopt;
  if (slash == std::string::npos) return a;
  const auto b = decimal(t.substr(slash + 1));
  if (!b || *b == 0) return std::nullopt;
  return *a / *b;
}

}  // namespace

// The verdict line of order conditions (a composition's, a splitting's or an RKN tableau's): the
// order they give against the expected one, the first weight that fails, and whether a residual
// below 1e-8 points to inexact coefficients rather than a lower order; the same in the JSON
// (order_conditions, the caller adds what describes its algebra). True when they reach it.
bool conditions_verdict(const comp::OrderConditions& oc, const comp::OrderConditions& visible,
                        double expected, const std::string& expected_from, MapMeasurement& rep,
                        const char* weight, const char* word) {
  const bool ok = oc.order >= int(std::floor(expected + 1e-9));
  std::string text = fmt::format(
      "order {} by the conditions (each {}'s residual <= {:.0e}); expected {:g} ({}): {}", oc.order,
      weight, kConditionTol, expected, expected_from, ok ? "yes" : "NO");
  if (!ok && oc.order < oc.max_weight)
    text += fmt::format(" -- {} {} fails by {:.2e} at the {} {}", weight, oc.order + 1,
                        oc.residual[static_cast<std::size_t>(oc.order)], word,
                        oc.worst_word[static_cast<std::size_t>(oc.order)]);
  if (!ok && visible.order >= int(std::floor(expected + 1e-9)))
    text += " (a residual below 1e-8: inexact coefficients rather than a lower order)";
  rep.line("", text);
  rep.js["order_conditions"] = {{"digits", kCompositionDigits},
                                {"residual_by_weight", oc.residual},
                                {"worst_word", oc.worst_word},
                                {"tolerance", kConditionTol},
                                {"order", oc.order},
                                {"visible_tolerance", kVisibleTol},
                                {"visible_order", visible.order},
                                {"expected", expected},
                                {"expected_from", expected_from},
                                {"passed", ok}};
  return ok;
}

CompositionSpec splitting_spec(const std::string& arg, const std::string& seq) {
  CompositionSpec spec;
  spec.base = find_composition_base("se");
  spec.splitting = comp::find_splitting(seq);
  const std::string flows_text = spec.splitting ? spec.splitting->flows : seq;
  spec.flows_typed = flows_text;
  if (!spec.splitting && flows_text.find(':') == std::string::npos) {
    std::vector<std::string> names;
    for (const auto& e : comp::splitting_catalogue()) names.push_back(e.name);
    throw ArgumentError(arg, fmt::format("no catalogue splitting '{}' ({}), and not a sequence "
                                         "of flows drift:COEFFICIENT,kick:COEFFICIENT,...",
                                         seq, fmt::join(names, ", ")));
  }
  const MpfrDigits digits(kCompositionDigits);
  spec.flows = comp::parse_sequence<mpfr_real>(arg, flows_text);
  if (spec.flows.size() > 128) throw ArgumentError(arg, "has more than 128 flows");
  for (std::size_t i = 0; i < spec.flows.size(); ++i)
    if (!(abs(spec.flows[i].c) <= mpfr_real(1e3)))
      throw ArgumentError(arg, fmt::format("flow {} lies beyond 1e3 in size", i + 1));
  // Equal totals to within the order conditions' tolerance, 1e-12: published digits leave
  // their rounding (McLachlan and Atela's fifth-order drifts sum to 1 - 1e-19), which the
  // conditions of weight 1 report; the composition's last stage then covers the last flow to
  // that rounding. Without equal totals there is no equivalent composition: the method is not
  // consistent, and its order conditions of weight 1 say so (measure_composition fails it).
  spec.typed = comp::as_symplectic_euler_composition(spec.flows, kConditionTol);
  if (spec.typed.empty()) {
    spec.not_exact = "not derived: the method is not consistent";
    return spec;
  }
  // The same stages exactly, when every flow is a ratio of decimals: the symbolic engine's
  // variational order needs the coefficients exact.
  std::vector<boost::multiprecision::cpp_rational> exact;
  {
    std::vector<std::pair<bool, boost::multiprecision::cpp_rational>> flows;
    std::size_t from = 0;
    while (from <= flows_text.size() && spec.not_exact.empty()) {
      const auto comma = std::min(flows_text.find(',', from), flows_text.size());
      const std::string item = flows_text.substr(from, comma - from);
      const auto colon = item.find(':');
      const auto r = exact_ratio(item.substr(colon + 1));
      if (!r)
        spec.not_exact = "not derived: the coefficient '" + item.substr(colon + 1) +
                         "' is an expression, and the engine's zero test needs the "
                         "coefficients as exact ratios";
      else if (*r != 0) {
        const bool kick = item.find("kick") != std::string::npos;
        if (!flows.empty() && flows.back().first == kick) {
          flows.back().second += *r;
          if (flows.back().second == 0) flows.pop_back();
        } else {
          flows.push_back({kick, *r});
        }
      }
      from = comma + 1;
    }
    if (spec.not_exact.empty() && flows.size() >= 2) {
      boost::multiprecision::cpp_rational g = 0;
      for (std::size_t j = 0; j + 1 < flows.size(); ++j) {
        g = flows[j].second - g;
        exact.push_back(g);
      }
    }
  }
  std::vector<std::string> items;
  for (std::size_t j = 0; j < spec.typed.size(); ++j) {
    const auto& st = spec.typed[j];
    items.push_back((exact.size() == spec.typed.size() ? exact[j].str()
                                                       : st.c.str(40, std::ios_base::fmtflags{})) +
                    (st.adjoint ? "*" : ""));
  }
  spec.coefficients = fmt::format("{}", fmt::join(items, ","));
  if (exact.size() != spec.typed.size() && spec.not_exact.empty())
    spec.not_exact = "not derived: the coefficients are not exact ratios";
  return spec;
}

namespace {

// The stages of a composition, and the order it is held to.
struct Composed {
  std::vector<double> c;
  std::vector<bool> adj;
  std::vector<dd_real> c_dd;  ///< the coefficients rounded from their 120 digits (to_dd)
  bool symmetric = false;
  double expected = 0;
  double conditions_order = 0;  ///< the order the conditions give (below 1: not consistent)
};

// A splitting's flows and its order conditions for two flows at 120 digits, printed and written
// to rep; its equivalent composition shown beside them (and stepped).
Composed splitting_conditions(const CompositionSpec& p, MapMeasurement& rep) {
  json& js = rep.js;
  std::vector<double> c;
  std::vector<bool> adj;
  comp::OrderConditions oc, visible, as_composition, generic, generic_visible;
  bool palindrome = false, nystrom = false;
  std::vector<std::string> flow_text;
  json flows = json::array();
  {
    const MpfrDigits digits(kCompositionDigits);
    for (const auto& s : p.typed) {
      c.push_back(static_cast<double>(s.c));
      adj.push_back(s.adjoint);
    }
    for (const auto& f : p.flows) {
      flow_text.push_back(fmt::format("{} {:.16g}", f.kick ? "kick" : "drift", double(f.c)));
      flows.push_back({{"flow", f.kick ? "kick" : "drift"}, {"c", double(f.c)}});
    }
    const int W = std::min(
        10,
        std::max(4, int(std::ceil(p.expected.value_or(p.splitting ? p.splitting->order : 8))) + 1));
    generic = comp::splitting_order_conditions(p.flows, W, kConditionTol);
    generic_visible = comp::splitting_order_conditions(p.flows, W, kVisibleTol);
    oc = generic;
    visible = generic_visible;
    // Every system this route takes has T = |p|²/2 (a test problem, or --potential): there the
    // splitting is a Runge–Kutta–Nyström method, and its order conditions are those of the
    // Nyström trees, which a method designed for such systems meets beyond the generic ones.
    if (std::any_of(p.flows.begin(), p.flows.end(), [](const auto& f) { return f.kick; })) {
      nystrom = true;
      oc = comp::splitting_nystrom_conditions(p.flows, W, kConditionTol);
      visible = comp::splitting_nystrom_conditions(p.flows, W, kVisibleTol);
    }
    as_composition = comp::order_conditions(p.typed, false, W, kConditionTol);
    palindrome = comp::is_palindrome(p.flows, 1e-60);
  }
  double expected;
  std::string expected_from;
  if (p.expected) {
    expected = *p.expected;
    expected_from = p.expected_from;
  } else if (p.splitting) {
    expected = p.splitting->order;
    expected_from = "documented";
  } else {
    // the order its conditions give, and never below 1: a method is at least consistent
    expected = std::max(1, visible.order);
    expected_from =
        fmt::format("the order conditions at tolerance {:.0e}, at least 1", kVisibleTol);
  }
  const std::size_t kicks = static_cast<std::size_t>(
      std::count_if(p.flows.begin(), p.flows.end(), [](const auto& f) { return f.kick; }));
  rep.line("splitting", fmt::format("{} flows of H = T(p) + V(q) ({} drifts, {} kicks), {}",
                                    p.flows.size(), p.flows.size() - kicks, kicks,
                                    palindrome ? "a palindrome (symmetric: its own adjoint)"
                                               : "not a palindrome (not symmetric)"));
  rep.line("  flows", fmt::format("in the order they act: {}", fmt::join(flow_text, ", ")));
  rep.line("  source", p.splitting ? p.splitting->name + ": " + p.splitting->source
                                   : "as typed: " + p.flows_typed);
  if (c.empty()) {
    const auto [a, b] = [&] {
      const MpfrDigits digits(kCompositionDigits);
      const auto t = comp::totals(p.flows);
      return std::pair{static_cast<double>(t.first), static_cast<double>(t.second)};
    }();
    rep.line("  as a composition",
             fmt::format("none: the drifts sum to {:.17g} and the kicks to {:.17g} (a consistent "
                         "splitting of H = T + V has both equal to 1)",
                         a, b));
  } else {
    rep.line("  as a composition",
             fmt::format("of se (drift, then kick) and se* (kick, then drift), {} stages: {}",
                         c.size(), p.coefficients));
  }
  auto residuals = [](const comp::OrderConditions& o) {
    std::vector<std::string> parts;
    for (std::size_t k = 0; k < o.residual.size(); ++k)
      parts.push_back(fmt::format("{}: {:.1e}", k + 1, o.residual[k]));
    return fmt::format("{}", fmt::join(parts, ", "));
  };
  rep.line("order conditions",
           fmt::format("two flows, A (drift) and B (kick): residual by weight ({} digits) {}",
                       kCompositionDigits, residuals(generic)));
  if (nystrom) {
    rep.line("", fmt::format("order {} for two generic flows (any T(p) and V(q))", generic.order));
    rep.line("", fmt::format("for T = |p|^2/2 (q'' = f(q), the systems taken here) the splitting "
                             "is a Runge-Kutta-Nystrom method, one stage a kick: Nystrom trees, "
                             "residual by order {}",
                             residuals(oc)));
  }
  const bool conditions_ok =
      nystrom ? conditions_verdict(oc, visible, expected, expected_from, rep, "order", "tree")
              : conditions_verdict(oc, visible, expected, expected_from, rep);
  if (!c.empty())
    rep.line("", fmt::format("(as a composition of any first-order method and its adjoint: order "
                             "{}; the splitting's own conditions decide)",
                             as_composition.order));
  rep.required.push_back("order conditions");
  if (!conditions_ok) rep.failed.push_back("order conditions");
  js["splitting"] = {{"flows", flows},
                     {"typed", p.splitting ? p.splitting->flows : p.flows_typed},
                     {"source", p.splitting ? p.splitting->source : "typed"},
                     {"palindrome", palindrome},
                     {"composition", {{"base", "se"}, {"stages", c}, {"adjoint", adj}}},
                     {"composition_order", as_composition.order},
                     {"generic_order", generic.order},
                     {"generic_residual_by_weight", generic.residual}};
  js["order_conditions"]["flows"] = "two: A (drift), B (kick)";
  if (nystrom)
    js["order_conditions"]["trees"] =
        "Nystrom trees (T = |p|^2/2): the splitting as a Runge-Kutta-Nystrom method";
  return {c, adj, {}, palindrome, expected, double(oc.order)};
}

// The stages and their order conditions at 120 digits, printed and written to rep; the same
// whatever the base method is, given whether it is symmetric.
Composed conditions(const CompositionSpec& p, MapMeasurement& rep) {
  if (!p.flows.empty()) return splitting_conditions(p, rep);
  auto line = [&](const std::string& label, const std::string& text) { rep.line(label, text); };
  json& js = rep.js;
  std::vector<std::string>& failed = rep.failed;
  std::vector<std::string>& required = rep.required;

  // --- the stages and their order conditions, at 120 digits -------------------------------
  std::vector<double> c;
  std::vector<bool> adj;
  std::vector<dd_real> c_dd;
  comp::OrderConditions oc, visible;
  comp::Refinement rf;
  bool symmetric = false;
  {
    const MpfrDigits digits(kCompositionDigits);
    const comp::Stages<mpfr_real> st =
        p.entry ? comp::catalogue_stages<mpfr_real>(p.entry->name, kCompositionDigits, &rf)
                : p.typed;
    for (const auto& s : st) {
      c.push_back(static_cast<double>(s.c));
      c_dd.push_back(to_dd(s.c));
      adj.push_back(s.adjoint);
    }
    const int W = std::min(
        10, std::max(4, int(std::ceil(p.expected.value_or(p.entry ? p.entry->order : 8))) + 1));
    oc = comp::order_conditions(st, p.base->symmetric, W, kConditionTol);
    visible = comp::order_conditions(st, p.base->symmetric, W, kVisibleTol);
    symmetric = comp::is_symmetric(st, p.base->symmetric);
  }
  const bool documented_base =
      p.entry && (p.entry->base == "symmetric" ? p.base->symmetric : p.entry->base == p.base->name);
  double expected;
  std::string expected_from;
  if (p.expected) {
    expected = *p.expected;
    expected_from = p.expected_from;
  } else if (documented_base) {
    expected = p.entry->order;
    expected_from = "documented";
  } else {
    expected = visible.order;
    expected_from = fmt::format("the order conditions at tolerance {:.0e}", kVisibleTol);
  }

  line("composition",
       fmt::format("{} stages of {}{}", c.size(), p.base->name,
                   symmetric ? " (symmetric: its own adjoint)" : " (not symmetric)"));
  line("base method", p.base->description);
  if (p.entry) {
    line("coefficients", p.entry->name + ": " + p.entry->source);
    line("  obtained by",
         p.entry->derivation + (rf.iterations > 0
                                    ? fmt::format(" ({} Newton iterations at {} digits; largest "
                                                  "change from the published digits {:.1e})",
                                                  rf.iterations, kCompositionDigits, rf.max_change)
                                    : std::string()));
    if (!rf.published_residual.empty()) {
      const auto worst =
          std::max_element(rf.published_residual.begin(), rf.published_residual.end());
      line("  published digits",
           fmt::format("satisfy the order conditions to {:.1e} (largest at weight {}); the "
                       "solution of the conditions is used",
                       *worst, worst - rf.published_residual.begin() + 1));
    }
    if (!documented_base)
      line("  note", fmt::format("documented for {} (order {}); on {} the expected order comes "
                                 "from {}",
                                 p.entry->base == "symmetric" ? "a symmetric base" : p.entry->base,
                                 p.entry->order, p.base->name,
                                 p.expected ? p.expected_from : "the order conditions"));
  } else {
    line("coefficients", fmt::format("as typed: {}", p.coefficients));
  }
  {
    std::vector<std::string> parts;
    for (std::size_t k = 0; k < oc.residual.size(); ++k)
      if (!p.base->symmetric || k % 2 == 0 || oc.residual[k] > 0)
        parts.push_back(fmt::format("{}: {:.1e}", k + 1, oc.residual[k]));
    line("order conditions", fmt::format("residual by weight ({} base, {} digits) {}",
                                         p.base->symmetric ? "symmetric" : "general",
                                         kCompositionDigits, fmt::join(parts, ", ")));
  }
  const bool conditions_ok = conditions_verdict(oc, visible, expected, expected_from, rep);
  required.push_back("order conditions");
  if (!conditions_ok) failed.push_back("order conditions");
  js["composition"] = {{"base", p.base->name},
                       {"coefficients", p.coefficients},
                       {"stages", c},
                       {"adjoint", adj},
                       {"symmetric", symmetric},
                       {"source", p.entry ? p.entry->source : "typed"},
                       {"derivation", p.entry ? p.entry->derivation : "typed"}};
  if (rf.iterations > 0)
    js["composition"]["newton"] = {{"iterations", rf.iterations},
                                   {"max_change_from_published", rf.max_change},
                                   {"published_residual_by_weight", rf.published_residual},
                                   {"final_residual", rf.final_residual}};
  js["order_conditions"]["symmetric_base"] = p.base->symmetric;
  return {c, adj, c_dd, symmetric, expected, double(oc.order)};
}

// A composition of an explicit base (sv, se, se-adjoint; kernels.hpp) in double-double, with
// its discrete Lagrangian: the sum of the stages' L_d, as composed_generating sums them in
// double. A stage of size k = c h from q0 to q1 moves the positions by one drift, whose velocity
// v is (q1 − q0)/k, so that with L = |v|²/2 − U(q)
//   sv (kick k/2, drift k, kick k/2):  L_d = k |v|²/2 − k (U(q0) + U(q1))/2,
//   se (drift k, then kick k):         L_d = k |v|²/2 − k U(q1),
//   se-adjoint (kick k, then drift k): L_d = k |v|²/2 − k U(q0)
// (Vermeeren 2017, Example 1 (b)-(d)); the adjoint stage of se is se-adjoint and conversely.
// The step alone (first) and the step with its L_d (second); none for an implicit base, which
// is measured in double (and the report says so).
template <class P>
std::optional<std::pair<StepDD, GeneratingStepDD>> explicit_composition_dd(
    const std::string& base, const P& prob, const std::vector<dd_real>& c,
    const std::vector<bool>& adj) {
  constexpr int N = P::N;
  if (base != "sv" && base != "se" && base != "se-adjoint") return std::nullopt;
  enum class Kind { sv, drift_kick, kick_drift };
  std::vector<Kind> kind;
  for (std::size_t i = 0; i < c.size(); ++i)
    kind.push_back(base == "sv"                     ? Kind::sv
                   : (base == "se") != bool(adj[i]) ? Kind::drift_kick
                                                    : Kind::kick_drift);
  // One pass over the stages; the potential only when L_d is asked for. The gradient and the
  // potential at the current q are kept until the next drift moves it (the kick that ends a
  // stage and the one that starts the next one are at the same q), as StormerVerlet keeps its
  // force in double.
  auto run = [prob, c, kind](VecXdd& z, const dd_real& h, bool with_ld) {
    using V = Vec<dd_real, N>;
    V q = z.template head<N>(), p = z.template tail<N>();
    const dd_real half(0.5);
    dd_real Ld(0.0);
    std::optional<V> g;
    std::optional<dd_real> U;
    auto kick = [&](const dd_real& by) {
      if (!g) g = prob.template gradient<dd_real>(q);
      p -= by * *g;
    };
    auto potential = [&]() {
      if (!U) U = prob.template potential<dd_real>(q);
      return *U;
    };
    for (std::size_t i = 0; i < c.size(); ++i) {
      if (c[i] == 0) continue;
      const dd_real k = c[i] * h;
      const dd_real U0 = with_ld && kind[i] != Kind::drift_kick ? potential() : dd_real(0.0);
      if (kind[i] == Kind::sv) kick(k * half);
      if (kind[i] == Kind::kick_drift) kick(k);
      const V v = p;
      q += k * v;
      g.reset();
      U.reset();
      const dd_real U1 = with_ld && kind[i] != Kind::kick_drift ? potential() : dd_real(0.0);
      if (kind[i] == Kind::sv) kick(k * half);
      if (kind[i] == Kind::drift_kick) kick(k);
      if (with_ld) {
        const dd_real Us = kind[i] == Kind::sv           ? half * (U0 + U1)
                           : kind[i] == Kind::drift_kick ? U1
                                                         : U0;
        Ld += k * (half * v.squaredNorm() - Us);
      }
    }
    z << q, p;
    return Ld;
  };
  return std::pair<StepDD, GeneratingStepDD>{
      [run](VecXdd& z, const dd_real& h) { run(z, h, false); },
      [run](VecXdd& z, const dd_real& h) { return run(z, h, true); }};
}

template <class P>
void measure(const CompositionSpec& p, const std::vector<double>& q0, const std::vector<double>& p0,
             const TestProblem& problem, MapStudy study, MapMeasurement& rep, const P& prob) {
  constexpr int N = P::N;
  const Composed k = conditions(p, rep);
  if (k.c.empty()) {
    // A splitting whose drifts and kicks sum to different totals: no composition to step, and
    // its weight-1 conditions have already failed. An inconsistent method never passes.
    rep.line("measured", "nothing: an inconsistent method converges to no solution of H");
    rep.required.push_back("consistency");
    rep.failed.push_back("consistency");
    return;
  }
  const std::vector<double>& c = k.c;
  const std::vector<bool>& adj = k.adj;
  const bool symmetric = k.symmetric;

  // --- the integrator ----------------------------------------------------------------------
  auto make_step = [&]() -> Step {
    auto wrap = [](auto integrator) {
      auto shared = std::make_shared<decltype(integrator)>(std::move(integrator));
      // A failed solve names the step size and the state it started from.
      return naming_failures([shared](Eigen::VectorXd& z, double h) { step_qp<N>(*shared, z, h); },
                             N);
    };
    const std::string& b = p.base->name;
    if (b == "sv")
      return wrap(comp::Composed<StormerVerlet<P>, StormerVerlet<P>>(
          StormerVerlet<P>(prob), StormerVerlet<P>(prob), c, adj));
    if (b == "midpoint")
      return wrap(comp::Composed<ImplicitMidpoint<P>, ImplicitMidpoint<P>>(
          ImplicitMidpoint<P>(prob), ImplicitMidpoint<P>(prob), c, adj));
    if (b == "se")
      return wrap(comp::Composed<SymplecticEuler<P>, SymplecticEulerAdjoint<P>>(
          SymplecticEuler<P>(prob), SymplecticEulerAdjoint<P>(prob), c, adj));
    if (b == "se-adjoint")
      return wrap(comp::Composed<SymplecticEulerAdjoint<P>, SymplecticEuler<P>>(
          SymplecticEulerAdjoint<P>(prob), SymplecticEuler<P>(prob), c, adj));
    // Shen & Sun 2025 §3: the splitting methods, potential split α = 1/2 (splitting.hpp).
    using Kernel = SplittingKernel<WeightedSplit<P>>;
    const auto split = WeightedSplit<P>::alpha(0.5, prob);
    if (b == "vi1")
      return wrap(comp::Composed<Kernel, Kernel>(Kernel(split, SplittingMethod::vi1),
                                                 Kernel(split, SplittingMethod::vi1_adjoint), c,
                                                 adj));
    if (b == "vi1-adjoint")
      return wrap(comp::Composed<Kernel, Kernel>(Kernel(split, SplittingMethod::vi1_adjoint),
                                                 Kernel(split, SplittingMethod::vi1), c, adj));
    return wrap(comp::Composed<Kernel, Kernel>(Kernel(split, SplittingMethod::vi2),
                                               Kernel(split, SplittingMethod::vi2), c, adj));
  };
  const Step step = make_step();
  rep.line("problem", fmt::format("{}: {}, q0 = {}, p0 = {}", problem.name, problem.hamiltonian,
                                  vec_text(q0), vec_text(p0)));

  study.step = step;
  set_problem(study, problem, q0, p0);
  // A splitting is explicit: its flows in double-double too. So is a composition of
  // Störmer–Verlet or of symplectic Euler and its adjoint (explicit_composition_dd): from
  // order 6 on its order and variational order are measured where double's window would lie
  // in their pre-asymptotic range.
  if (!p.flows.empty()) {
    study.step_dd = splitting_step_dd(p.flows, study.field, N);
  } else if (auto dd = explicit_composition_dd(p.base->name, prob, k.c_dd, adj)) {
    study.step_dd = std::move(dd->first);
    study.generating_dd = std::move(dd->second);
  }
  study.expected = k.expected;
  study.substeps = double(c.size());
  study.symmetric_claimed = study.symmetric_claimed || symmetric;
  study.conditions_order = k.conditions_order;
  study.symmetric_note = " (reported only: the composition is not symmetric)";
  study.generating = generating_composition(p.base->name, prob, c, adj);
  study.generating_from = fmt::format(
      "the sum of the {} stages' discrete Lagrangians ({}) at the positions the stages pass "
      "through",
      c.size(), p.base->name);
  measure_map(study, rep);
}

}  // namespace

void measure_composition(const CompositionSpec& spec, const CompositionStage& base,
                         const CompositionStage& adjoint, const std::string& system_line,
                         MapStudy study, MapMeasurement& rep, bool variational) {
  const Composed k = conditions(spec, rep);
  rep.line("system", system_line);
  // The composed step, stage by stage; the sum of the stages' L_d is the composed L_d.
  auto composed = [base, adjoint, c = k.c, adj = k.adj](Eigen::VectorXd& z, double h) {
    double Ld = 0;
    for (std::size_t i = 0; i < c.size(); ++i)
      if (c[i] != 0) Ld += adj[i] ? adjoint(z, c[i] * h) : base(z, c[i] * h);
    return Ld;
  };
  study.step = naming_failures([composed](Eigen::VectorXd& z, double h) { composed(z, h); },
                               int(study.z0.size() / 2));
  study.expected = k.expected;
  study.substeps = double(k.c.size());
  study.symmetric_claimed = study.symmetric_claimed || k.symmetric;
  study.conditions_order = k.conditions_order;
  study.symmetric_note = " (reported only: the composition is not symmetric)";
  if (variational) {
    study.generating = composed;
    study.generating_from = fmt::format(
        "the sum of the {} stages' discrete Lagrangians ({}) at the positions the stages pass "
        "through",
        k.c.size(), spec.base->name);
  }
  measure_map(study, rep);
}

void measure_composition(const CompositionSpec& spec, const TestProblem& problem,
                         const std::vector<double>& q0, const std::vector<double>& p0,
                         const MapStudy& study, MapMeasurement& rep) {
  if (problem.name == "pendulum") return measure(spec, q0, p0, problem, study, rep, Pendulum{});
  if (problem.name == "henon-heiles")
    return measure(spec, q0, p0, problem, study, rep, HenonHeiles{});
  return measure(spec, q0, p0, problem, study, rep, Kepler{});
}

StepDD splitting_step_dd(const composition::Sequence<mpfr_real>& flows, Field<dd_real> field,
                         int n) {
  std::vector<std::pair<bool, dd_real>> dd;
  for (const auto& f : flows) dd.emplace_back(f.kick, to_dd(f.c));
  return [field = std::move(field), dd, n](VecXdd& z, const dd_real& h) {
    for (const auto& [kick, c] : dd) {
      if (kick) {
        const std::vector<dd_real> f = field(std::vector<dd_real>(z.data(), z.data() + 2 * n));
        for (int i = 0; i < n; ++i) z(n + i) += c * h * f[static_cast<std::size_t>(n + i)];
      } else {
        for (int i = 0; i < n; ++i) z(i) += c * h * z(n + i);
      }
    }
  };
}

}  // namespace vibook::verify
