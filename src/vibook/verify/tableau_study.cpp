// A partitioned Runge–Kutta method from a tableau file, measured on a test problem
// (tableau_study.hpp): the file read and checked, its conditions at 120 digits, the method of
// integrators/prk.hpp on the problem, and the measurements of map_study.hpp. `vibook verify
// --tableau` prints it.
#include "vibook/verify/tableau_study.hpp"
#include "vibook/verify/method_symbolic.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "vibook/core/errors.hpp"
#include "vibook/core/precision.hpp"
#include "vibook/integrators/composition.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/problems/problems.hpp"
#include "vibook/verify/composition_study.hpp"
#include "vibook/verify/tableau_study_impl.hpp"

namespace vibook::verify {

namespace {

using nlohmann::json;
constexpr int kDigits = 120;
// "Satisfied": entries typed as ratios leave 1e-120; decimals of 17 or more digits 1e-17.
constexpr double kConditionTol = 1e-12;

[[noreturn]] void bad(const std::string& path, const std::string& what) {
  throw ArgumentError("--tableau", "'" + path + "': " + what);
}

// One entry at 120 digits: a string with a decimal or a ratio, or a JSON number as printed.
mpfr_real entry(const std::string& path, const std::string& where, const json& j) {
  std::string text;
  if (j.is_string())
    text = j.get<std::string>();
  else if (j.is_number())
    text = j.dump();
  else
    bad(path, where + " is not a number or a string holding one");
  if (text.find('*') != std::string::npos) bad(path, where + " ('" + text + "') is not a number");
  try {
    return composition::parse_stage<mpfr_real>("--tableau", text).c;
  } catch (const ArgumentError&) {
    bad(path, where + " ('" + text + "') is not a decimal number or a ratio such as 5/24");
  }
}

std::vector<mpfr_real> row(const std::string& path, const json& j, const std::string& name,
                           std::size_t s) {
  if (!j.is_array() || j.size() != s)
    bad(path, fmt::format("'{}' must be a list of {} entries", name, s));
  std::vector<mpfr_real> r;
  for (std::size_t i = 0; i < s; ++i)
    r.push_back(entry(path, fmt::format("{}[{}]", name, i), j[i]));
  return r;
}

std::vector<std::vector<mpfr_real>> matrix(const std::string& path, const json& j,
                                           const std::string& name, std::size_t s) {
  if (!j.is_array() || j.size() != s)
    bad(path, fmt::format("'{}' must be a list of {} rows", name, s));
  std::vector<std::vector<mpfr_real>> m;
  for (std::size_t i = 0; i < s; ++i) {
    if (!j[i].is_array() || j[i].size() != s)
      bad(path, fmt::format("row {} of '{}' must have {} entries", i, name, s));
    std::vector<mpfr_real> r;
    for (std::size_t k = 0; k < s; ++k)
      r.push_back(entry(path, fmt::format("{}[{}][{}]", name, i, k), j[i][k]));
    m.push_back(r);
  }
  return m;
}

std::vector<dd_real> to_dds(const std::vector<mpfr_real>& v) {
  std::vector<dd_real> r;
  for (const auto& x : v) r.push_back(to_dd(x));
  return r;
}

std::vector<double> to_doubles(const std::vector<mpfr_real>& v) {
  std::vector<double> d;
  for (const auto& x : v) d.push_back(static_cast<double>(x));
  return d;
}

// A Runge–Kutta–Nyström tableau's entries and its conditions at 120 digits (rkn.hpp), into
// `t` (whose file, name, source, order and symmetry are read).
void read_rkn(const std::string& path, const json& j, std::size_t s, TableauSpec& t) {
  RknTableauT<mpfr_real> r;
  r.c = row(path, j["c"], "c", s);
  r.abar = matrix(path, j["abar"], "abar", s);
  r.bbar = row(path, j["bbar"], "bbar", s);
  r.b = row(path, j["b"], "b", s);
  auto absd = [](const mpfr_real& x) { return static_cast<double>(x < 0 ? mpfr_real(-x) : x); };
  mpfr_real sb = 0, sbb = 0;
  for (std::size_t i = 0; i < s; ++i) {
    sb += r.b[i];
    sbb += r.bbar[i];
  }
  t.rkn = true;
  t.weights_residual = std::max(absd(mpfr_real(sb - 1)), absd(mpfr_real(sbb - mpfr_real(0.5))));
  std::tie(t.bhat_residual, t.symplectic_residual) = rkn_symplectic_residuals(r, absd);
  t.symplectic_conditions =
      t.bhat_residual <= kConditionTol && t.symplectic_residual <= kConditionTol;
  const RknConditions<mpfr_real> rc = rkn_conditions(r, kRknConditionsOrder);
  auto oc = [&](double tol) {
    return composition::conditions_from(
        rc.value, kRknConditionsOrder, false, tol,
        [&rc](int w) { return rc.order[static_cast<std::size_t>(w)]; },
        [&rc](int w) { return rc.name[static_cast<std::size_t>(w)]; });
  };
  t.rkn_conditions = oc(kConditionTol);
  t.rkn_visible = oc(1e-8);
  t.rkn_exact = r;
  t.rkn_tableau.c = to_doubles(r.c);
  t.rkn_tableau.bbar = to_doubles(r.bbar);
  t.rkn_tableau.b = to_doubles(r.b);
  t.rkn_tableau_dd.c = to_dds(r.c);
  t.rkn_tableau_dd.bbar = to_dds(r.bbar);
  t.rkn_tableau_dd.b = to_dds(r.b);
  for (std::size_t i = 0; i < s; ++i) {
    t.rkn_tableau.abar.push_back(to_doubles(r.abar[i]));
    t.rkn_tableau_dd.abar.push_back(to_dds(r.abar[i]));
  }
  if (t.documented_order) {
    t.expected = *t.documented_order;
    t.expected_from = "the file's 'order'";
  }
}

}  // namespace

TableauSpec read_tableau(const std::string& path) {
  // Only a regular file, and at most kMaxTableauBytes: /dev/zero, /dev/urandom or a FIFO would
  // be read forever. The size is checked on the open file, and the read stops past the bound.
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) bad(path, "cannot be read");
  if (!std::filesystem::is_regular_file(status))
    bad(path, "is not a regular file (a device, FIFO or directory is refused)");
  std::ifstream in(path, std::ios::binary);
  if (!in) bad(path, "cannot be read");
  std::string content(kMaxTableauBytes + 1, '\0');
  in.read(content.data(), std::streamsize(content.size()));
  content.resize(static_cast<std::size_t>(in.gcount()));
  if (content.size() > kMaxTableauBytes)
    bad(path, fmt::format("is larger than {} bytes", kMaxTableauBytes));
  return parse_tableau(content, path);
}

TableauSpec parse_tableau(const std::string& content, const std::string& path) {
  json j;
  try {
    j = json::parse(content);
  } catch (const json::exception& e) {
    bad(path, std::string("is not JSON (") + e.what() + ")");
  }
  if (!j.is_object()) bad(path, "must hold a JSON object with 'a' and 'b'");
  for (const auto& [key, value] : j.items())
    if (key != "name" && key != "source" && key != "order" && key != "symmetric" && key != "a" &&
        key != "b" && key != "ahat" && key != "bhat" && key != "c" && key != "abar" &&
        key != "bbar")
      bad(path, "unknown key '" + key +
                    "' (name, source, order, symmetric, a, b, ahat, bhat, c; or for a "
                    "Runge-Kutta-Nystrom tableau c, abar, bbar, b)");
  if (!j.contains("b") || !j["b"].is_array() || j["b"].empty())
    bad(path, "needs 'b', the list of weights");
  const std::size_t s = j["b"].size();
  if (s > static_cast<std::size_t>(kMaxTableauStages))
    bad(path, fmt::format("has {} stages; at most {}", s, kMaxTableauStages));
  const bool rkn = j.contains("abar") || j.contains("bbar");
  if (rkn) {
    for (const char* k : {"a", "ahat", "bhat"})
      if (j.contains(k))
        bad(path, std::string("mixes '") + k +
                      "' with 'abar'/'bbar': a Runge-Kutta-Nystrom tableau has c, abar, bbar, b");
    for (const char* k : {"abar", "bbar", "c"})
      if (!j.contains(k))
        bad(path, std::string("needs '") + k +
                      "' (a Runge-Kutta-Nystrom tableau has c, abar, "
                      "bbar, b)");
  } else if (!j.contains("a")) {
    bad(path, "needs 'a', the s x s matrix of the positions' stages");
  }

  TableauSpec t;
  t.file = path;
  t.name = j.contains("name") && j["name"].is_string() ? j["name"].get<std::string>() : path;
  t.source = j.contains("source") && j["source"].is_string() ? j["source"].get<std::string>()
                                                             : "not given";
  if (j.contains("order")) {
    if (!j["order"].is_number() || !(j["order"].get<double>() > 0) ||
        j["order"].get<double>() > kMaxOrder)
      bad(path, fmt::format("'order' must be a number in (0, {:g}]", kMaxOrder));
    t.documented_order = j["order"].get<double>();
  }
  if (j.contains("symmetric")) {
    if (!j["symmetric"].is_boolean()) bad(path, "'symmetric' must be true or false");
    t.symmetric_documented = j["symmetric"].get<bool>();
  }

  const MpfrDigits digits(kDigits);
  if (rkn) {
    read_rkn(path, j, s, t);
    return t;
  }
  const auto b = row(path, j["b"], "b", s);
  const auto a = matrix(path, j["a"], "a", s);
  auto text = [](const json& e) { return e.is_string() ? e.get<std::string>() : e.dump(); };
  for (std::size_t i = 0; i < s; ++i) {
    t.b_text.push_back(text(j["b"][i]));
    t.a_text.emplace_back();
    for (std::size_t k = 0; k < s; ++k) t.a_text.back().push_back(text(j["a"][i][k]));
  }
  const auto bhat = j.contains("bhat") ? row(path, j["bhat"], "bhat", s) : b;
  const auto ahat = j.contains("ahat") ? matrix(path, j["ahat"], "ahat", s) : a;
  auto absd = [](const mpfr_real& x) { return static_cast<double>(x < 0 ? mpfr_real(-x) : x); };
  mpfr_real sb = 0, sbh = 0;
  for (std::size_t i = 0; i < s; ++i) {
    sb += b[i];
    sbh += bhat[i];
  }
  t.weights_residual = std::max(absd(mpfr_real(sb - 1)), absd(mpfr_real(sbh - 1)));
  if (j.contains("c")) {
    const auto c = row(path, j["c"], "c", s);
    t.row_sum_residual = 0;
    for (std::size_t i = 0; i < s; ++i) {
      mpfr_real r = 0;
      for (std::size_t k = 0; k < s; ++k) r += a[i][k];
      t.row_sum_residual = std::max(t.row_sum_residual, absd(mpfr_real(r - c[i])));
    }
  }
  for (std::size_t i = 0; i < s; ++i) {
    t.bhat_residual = std::max(t.bhat_residual, absd(mpfr_real(b[i] - bhat[i])));
    for (std::size_t k = 0; k < s; ++k)
      t.symplectic_residual =
          std::max(t.symplectic_residual,
                   absd(mpfr_real(b[i] * ahat[i][k] + bhat[k] * a[k][i] - b[i] * bhat[k])));
  }
  t.symplectic_conditions =
      t.bhat_residual <= kConditionTol && t.symplectic_residual <= kConditionTol;
  t.tableau.b = to_doubles(b);
  t.tableau.bhat = to_doubles(bhat);
  for (std::size_t i = 0; i < s; ++i) {
    t.tableau.a.push_back(to_doubles(a[i]));
    t.tableau.ahat.push_back(to_doubles(ahat[i]));
  }
  t.tableau_dd.b = to_dds(b);
  t.tableau_dd.bhat = to_dds(bhat);
  for (std::size_t i = 0; i < s; ++i) {
    t.tableau_dd.a.push_back(to_dds(a[i]));
    t.tableau_dd.ahat.push_back(to_dds(ahat[i]));
  }
  if (t.documented_order) {
    t.expected = *t.documented_order;
    t.expected_from = "the file's 'order'";
  }
  return t;
}

namespace {

std::string list(const std::vector<double>& v) {
  std::vector<std::string> t;
  for (double x : v) t.push_back(fmt::format("{:.12g}", x));
  return fmt::format("{}", fmt::join(t, ", "));
}

}  // namespace

namespace tableau_detail {

// The RKN tableau's lines (its entries, its conditions at 120 digits, the order its Nyström
// trees give), then the measurement; no variational order (the method has no momenta stages
// to form its discrete Lagrangian from).
void measure_rkn(const TableauSpec& spec, int N, const StudySystem& system, MapStudy& s,
                 MapMeasurement& rep, std::pair<Step, GeneratingStep> steps) {
  const RknTableauT<double>& t = spec.rkn_tableau;
  const int S = t.stages();
  s.exact_symplectic_from = fmt::format(
      "bbar_i = b_i (1 - c_i) and b_i (bbar_j - abar_ij) = b_j (bbar_i - abar_ji) at {} digits",
      kDigits);
  s.conditions_order = spec.rkn_conditions.order;
  rep.line("tableau",
           fmt::format("{} ({} stages, Runge-Kutta-Nystrom), from {}", spec.name, S, spec.file));
  rep.line("  source", spec.source);
  for (int i = 0; i < S; ++i)
    rep.line(i == 0 ? "  c | abar" : "",
             fmt::format("{:.12g} | ", t.c[static_cast<std::size_t>(i)]) +
                 list(t.abar[static_cast<std::size_t>(i)]));
  rep.line("  bbar | b", list(t.bbar) + " | " + list(t.b));
  rep.line("  solved by", fmt::format("Newton's method on the {} position stages ({} unknowns), "
                                      "the Hessian of the potential by AutoDiff",
                                      S, S * N));
  rep.line("conditions", fmt::format("at {} digits from the entries as written: b sums to 1 and "
                                     "bbar to 1/2 within {:.1e}",
                                     kDigits, spec.weights_residual));
  rep.line("", fmt::format("symplectic (bbar_i = b_i (1 - c_i) within {:.1e}; b_i (bbar_j - "
                           "abar_ij) = b_j (bbar_i - abar_ji) within {:.1e}; each <= {:.0e}): {}",
                           spec.bhat_residual, spec.symplectic_residual, kConditionTol,
                           spec.symplectic_conditions ? "yes" : "NO"));
  std::vector<std::string> by_order;
  for (std::size_t k = 0; k < spec.rkn_conditions.residual.size(); ++k)
    by_order.push_back(fmt::format("{}: {:.1e}", k + 1, spec.rkn_conditions.residual[k]));
  rep.line("order conditions", fmt::format("Nystrom trees, residual by order (120 digits) {}",
                                           fmt::join(by_order, ", ")));
  rep.required.push_back("order conditions");
  if (!conditions_verdict(spec.rkn_conditions, spec.rkn_visible, spec.expected, spec.expected_from,
                          rep, "order", "tree"))
    rep.failed.push_back("order conditions");
  rep.js["order_conditions"]["trees"] = "Nystrom trees of order up to " +
                                        std::to_string(kRknConditionsOrder + 1) +
                                        " (HNW I, Sec. II.14)";
  // Shen & Sun's Theorem 10 on this tableau, beside the engine's modified equation (reported).
  {
    const RknTableauT<mpfr_real>& x = spec.rkn_exact;
    const NystromTheorem10 th = nystrom_theorem10(x.c, x.abar, x.bbar, x.b);
    // Every number is the rational of an entry's 120 digits: the theorem and the engine agree
    // to that rounding (1e-100 leaves twenty digits of room), and a wrong formula differs by a
    // polynomial in the entries, far above it.
    constexpr double kAgree = 1e-100;
    // A coefficient at the entries' rounding is 0 (to 1e-100).
    auto coefficient = [&](double x) {
      return std::abs(x) <= kAgree ? std::string("0") : fmt::format("{:.10g}", x);
    };
    const bool same = th.h1_difference <= kAgree && th.h2_difference <= kAgree;
    rep.line("modified equation",
             fmt::format("Shen & Sun, Theorem 10 (the weight b_i of its last sum restored, "
                         "erratum SS-ERR-L421): f^[1] = a f' x', f^[2] = b1 f''<x',x'> + b2 f' f "
                         "with a = {}, b1 = {}, b2 = {}",
                         coefficient(th.alpha), coefficient(th.beta1), coefficient(th.beta2)));
    rep.line("", fmt::format("the engine's modified equation of this tableau (one degree of "
                             "freedom, a generic force f), h and h^2 terms: {}{} (reported only)",
                             same ? fmt::format("the same to {:.0e}", kAgree)
                                  : fmt::format("DIFFERENT by {:.1e} (h) and {:.1e} (h^2)",
                                                th.h1_difference, th.h2_difference),
                             th.weights_residual > kAgree
                                 ? fmt::format("; the theorem assumes sum b_i = 1, here |sum b_i - "
                                               "1| = {:.1e}",
                                               th.weights_residual)
                                 : std::string()));
    rep.js["theorem10"] = {{"alpha", th.alpha},
                           {"beta1", th.beta1},
                           {"beta2", th.beta2},
                           {"h1_difference", th.h1_difference},
                           {"h2_difference", th.h2_difference},
                           {"weights_residual", th.weights_residual},
                           {"agrees_with_engine", same}};
  }
  rep.line("expected order", fmt::format("{:g} ({})", spec.expected, spec.expected_from));
  rep.line("problem", system.line);
  rep.js["tableau"] = {
      {"file", spec.file},
      {"name", spec.name},
      {"source", spec.source},
      {"form", "Runge-Kutta-Nystrom"},
      {"stages", S},
      {"c", t.c},
      {"abar", t.abar},
      {"bbar", t.bbar},
      {"b", t.b},
      {"documented_order", spec.documented_order ? json(*spec.documented_order) : json(nullptr)},
      {"symmetric", spec.symmetric_documented}};
  rep.js["conditions"] = {{"digits", kDigits},
                          {"weights_residual", spec.weights_residual},
                          {"bbar_residual", spec.bhat_residual},
                          {"symplectic_residual", spec.symplectic_residual},
                          {"tolerance", kConditionTol},
                          {"symplectic", spec.symplectic_conditions}};
  rep.js["problem"] = system.js;
  (void)steps;
  measure_map(s, rep);
  const std::string reason =
      spec.symplectic_conditions
          ? "not measured: vibook forms no discrete Lagrangian for an RKN tableau (it has no "
            "momenta stages)"
          : "not defined: the tableau does not satisfy the symplecticity conditions, so the "
            "method has no discrete Lagrangian";
  rep.line("variational order", reason);
  rep.js["variational_order"] = {{"derived", false}, {"measured", false}, {"reason", reason}};
}

void measure(const TableauSpec& spec, int N, const StudySystem& system, const MapStudy& study,
             bool symmetric_claimed, MapMeasurement& rep, std::pair<Step, GeneratingStep> steps,
             bool general_h) {
  MapStudy s = study;
  s.step = std::move(steps.first);
  system.set(s);
  s.expected = spec.expected;
  s.substeps = spec.rkn ? spec.rkn_tableau.stages() : spec.tableau.stages();
  s.max_substeps = 1e6;
  s.symmetric_claimed = symmetric_claimed || spec.symmetric_documented;
  s.symmetric_note = " (reported only: not said to be symmetric)";
  s.exact_symplectic = spec.symplectic_conditions;
  s.exact_symplectic_from =
      fmt::format("b_i ahat_ij + bhat_j a_ji = b_i bhat_j and b = bhat at {} digits", kDigits);

  if (spec.rkn) return measure_rkn(spec, N, system, s, rep, std::move(steps));
  const int S = spec.tableau.stages();
  rep.line("tableau", fmt::format("{} ({} stages), from {}", spec.name, S, spec.file));
  rep.line("  source", spec.source);
  for (int i = 0; i < S; ++i)
    rep.line(i == 0 ? "  a | ahat" : "", list(spec.tableau.a[static_cast<std::size_t>(i)]) + " | " +
                                             list(spec.tableau.ahat[static_cast<std::size_t>(i)]));
  rep.line("  b | bhat", list(spec.tableau.b) + " | " + list(spec.tableau.bhat));
  rep.line("  solved by",
           general_h ? fmt::format("Newton's method on the {} position and momentum stages ({} "
                                   "unknowns), the Hessian of H by AutoDiff",
                                   S, 2 * S * N)
                     : fmt::format("Newton's method on the {} position stages ({} unknowns), "
                                   "the Hessian of the potential by AutoDiff",
                                   S, S * N));
  rep.line("conditions",
           fmt::format("at {} digits from the entries as written: weights sum to 1 within {:.1e}{}",
                       kDigits, spec.weights_residual,
                       spec.row_sum_residual >= 0
                           ? fmt::format(", c = row sums of a within {:.1e}", spec.row_sum_residual)
                           : std::string()));
  rep.line("",
           fmt::format("symplectic (b = bhat within {:.1e}; b_i ahat_ij + bhat_j a_ji = b_i bhat_j "
                       "within {:.1e}; each <= {:.0e}): {}",
                       spec.bhat_residual, spec.symplectic_residual, kConditionTol,
                       spec.symplectic_conditions ? "yes" : "NO"));
  rep.line("expected order", fmt::format("{:g} ({})", spec.expected, spec.expected_from));
  rep.line("problem", system.line);
  rep.js["tableau"] = {
      {"file", spec.file},
      {"name", spec.name},
      {"source", spec.source},
      {"stages", S},
      {"a", spec.tableau.a},
      {"ahat", spec.tableau.ahat},
      {"b", spec.tableau.b},
      {"bhat", spec.tableau.bhat},
      {"documented_order", spec.documented_order ? json(*spec.documented_order) : json(nullptr)},
      {"symmetric", spec.symmetric_documented}};
  rep.js["conditions"] = {
      {"digits", kDigits},
      {"weights_residual", spec.weights_residual},
      {"row_sum_residual",
       spec.row_sum_residual >= 0 ? json(spec.row_sum_residual) : json(nullptr)},
      {"bhat_residual", spec.bhat_residual},
      {"symplectic_residual", spec.symplectic_residual},
      {"tolerance", kConditionTol},
      {"symplectic", spec.symplectic_conditions}};
  rep.js["problem"] = system.js;
  if (spec.symplectic_conditions) {
    s.generating = std::move(steps.second);
    s.generating_from =
        general_h ? "h sum_i b_i (P_i.dH/dp(Q_i, P_i) - H(Q_i, P_i)) at the solved stages (the "
                    "tableau is symplectic, so the method is variational)"
                  : "h sum_i b_i (|P_i|^2/2 - U(Q_i)) at the solved stages (the tableau is "
                    "symplectic, so the method is variational)";
  }
  measure_map(s, rep);
  if (!spec.symplectic_conditions) {
    const std::string reason =
        "the tableau does not satisfy the symplecticity conditions, so the method has no "
        "discrete Lagrangian";
    rep.line("variational order", "not defined: " + reason);
    rep.js["variational_order"] = {{"derived", false}, {"measured", false}, {"reason", reason}};
  }
}

}  // namespace tableau_detail

void measure_tableau(const TableauSpec& spec, const TestProblem& problem,
                     const std::vector<double>& q0, const std::vector<double>& p0,
                     const MapStudy& study, bool symmetric_claimed, MapMeasurement& rep) {
  using tableau_detail::steps_dd_for;
  using tableau_detail::steps_for;
  std::pair<Step, GeneratingStep> steps;
  std::pair<StepDD, GeneratingStepDD> dd;
  MapStudy s = study;
  auto set = [&](const auto& prob) {
    if (spec.rkn) {
      steps = tableau_detail::rkn_steps_for(prob, spec.rkn_tableau);
      dd = tableau_detail::rkn_steps_dd_for(prob, spec.rkn_tableau_dd);
    } else {
      steps = steps_for(prob, spec.tableau);
      dd = steps_dd_for(prob, spec.tableau_dd);
    }
  };
  if (problem.name == "pendulum")
    set(Pendulum{});
  else if (problem.name == "henon-heiles")
    set(HenonHeiles{});
  else
    set(Kepler{});
  s.step_dd = std::move(dd.first);
  s.generating_dd = std::move(dd.second);
  tableau_detail::measure(spec, static_cast<int>(q0.size()), test_problem_system(problem, q0, p0),
                          s, symmetric_claimed, rep, std::move(steps));
}

}  // namespace vibook::verify
