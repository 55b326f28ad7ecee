// The field audit (field_audit.hpp): the catalogue's compositions and the wrong ones, each
// measured on Kepler and Hénon–Heiles by the measurement `vibook verify --composition` prints
// (composition_study.hpp), each recorded in the ledger. Chapter: "Verify your own integrator",
// section "The audit".
#include "vibook/verify/field_audit.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <stdexcept>

#include <boost/numeric/odeint/stepper/base/symplectic_rkn_stepper_base.hpp>
#include <boost/numeric/odeint/stepper/symplectic_rkn_sb3a_m4_mclachlan.hpp>
#include <boost/numeric/odeint/stepper/symplectic_rkn_sb3a_mclachlan.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "vibook/core/precision.hpp"
#include "vibook/integrators/composition.hpp"
#include "vibook/integrators/splitting_sequence.hpp"
#include "vibook/plot/gnuplot.hpp"
#include "vibook/verify/black_box.hpp"
#include "vibook/verify/black_box_study.hpp"
#include "vibook/verify/checks.hpp"
#include "vibook/verify/composition_ld_study.hpp"
#include "vibook/verify/composition_study.hpp"
#include "vibook/verify/constrained.hpp"
#include "vibook/verify/expression.hpp"
#include "vibook/verify/map_study.hpp"
#include "vibook/verify/method_study.hpp"
#include "vibook/verify/method_symbolic.hpp"
#include "vibook/verify/tableau_study.hpp"
#include "vibook/verify/typed_system.hpp"

namespace vibook::verify {

namespace {

namespace comp = vibook::composition;
using nlohmann::json;

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

const CompositionBase& base_named(const std::string& name) {
  const CompositionBase* b = find_composition_base(name);
  if (!b) throw std::logic_error("field audit: no base method '" + name + "'");
  return *b;
}

// A published method of the catalogue on `base` (its documented base, or another symmetric one).
AuditEntry published(const std::string& name, const std::string& base,
                     const std::string& id_suffix = "") {
  const comp::CatalogueEntry* e = comp::find_entry(name);
  if (!e) throw std::logic_error("field audit: no catalogue entry '" + name + "'");
  const CompositionBase& b = base_named(base);
  AuditEntry a;
  a.base = base;
  a.coefficients = name;
  const bool palindromic = e->base == "symmetric";
  const std::string on = palindromic ? fmt::format("{} ({})", base, b.description) : base;
  a.info = {"A-" + upper(name) + id_suffix, "A", e->source,
            fmt::format("{} on {}: order {}, symplectic{}", name, base, e->order,
                        palindromic ? ", symmetric" : "")};
  if (palindromic)
    a.statement = fmt::format(
        "A palindromic composition of {} stages of a symmetric method of order 2 with order {} "
        "for every such base; composed here of {}. Symplectic as a composition of symplectic "
        "maps, symmetric (its own adjoint) as a palindrome of a symmetric base.",
        e->stages, e->order, on);
  else if (e->base == base)
    a.statement = fmt::format(
        "A composition of {} stages of {} and its adjoint with order {}; symplectic as a "
        "composition of symplectic maps (not symmetric).",
        e->stages, base, e->order);
  else
    a.statement = fmt::format(
        "Documented as {} stages of {} and its adjoint with order {}. Its order conditions are "
        "those of any first-order base with its adjoint, so the same stages of {} ({}) have order "
        "{}; symplectic (not symmetric).",
        e->stages, e->base, e->order, base, b.description, e->order);
  return a;
}

// "a", "a and b", "a, b and c".
std::string and_list(const std::vector<std::string>& v) {
  if (v.size() <= 1) return v.empty() ? std::string() : v[0];
  return fmt::format("{} and {}", fmt::join(v.begin(), v.end() - 1, ", "), v.back());
}

AuditEntry wrong(const std::string& id, const std::string& title, const std::string& what,
                 const std::string& base, const std::string& coefficients, double claimed,
                 std::vector<std::string> must_flag) {
  AuditEntry a;
  a.info = {id, "A", "deliberately wrong", title};
  a.statement = fmt::format(
      "{} Held to order {:g}, a correct audit must fail it on both problems, naming {}.", what,
      claimed, and_list(must_flag));
  a.base = base;
  a.coefficients = coefficients;
  a.expected = claimed;
  a.must_flag = std::move(must_flag);
  return a;
}

// A splitting of the catalogue (splitting_sequence.hpp) at its documented order.
AuditEntry published_splitting(const std::string& name) {
  const comp::SplittingEntry* e = comp::find_splitting(name);
  if (!e) throw std::logic_error("field audit: no splitting '" + name + "'");
  const MpfrDigits digits(kCompositionDigits);
  const bool palindrome =
      comp::is_palindrome(comp::parse_sequence<mpfr_real>("flows", e->flows), 1e-60);
  AuditEntry a;
  a.splitting = name;
  a.info = {"A-SPLIT-" + upper(name), "A", e->source,
            fmt::format("{}, a splitting: order {}{}, symplectic", name, e->order,
                        e->rkn ? " for T = |p|²/2 (Runge–Kutta–Nyström)" : "")};
  a.statement = fmt::format(
      "A splitting of H = T(p) + V(q) into the drift and kick flows, {}, with order {}{}; "
      "symplectic as a product of exact flows{}.",
      e->flows.size() > 120 ? "as published" : "flows " + e->flows, e->order,
      e->rkn ? " when T = |p|²/2 (a Runge–Kutta–Nyström method; lower for two generic flows)" : "",
      palindrome ? ", symmetric as a palindrome" : "");
  return a;
}

AuditEntry wrong_splitting(const std::string& id, const std::string& title, const std::string& what,
                           const std::string& flows, double claimed,
                           std::vector<std::string> must_flag) {
  AuditEntry a = wrong(id, title, what, "", "", claimed, std::move(must_flag));
  a.splitting = flows;
  return a;
}

// A Galerkin variational integrator with S nodes of a Gauss or Lobatto rule (galerkin.hpp).
AuditEntry galerkin(const std::string& family, int stages) {
  const bool gauss = family == "gauss";
  const Quadrature rule = quadrature_rule(family, stages);
  AuditEntry a;
  a.method = fmt::format("{}:{}", family, stages);
  a.info = {fmt::format("A-{}{}", upper(family), stages), "A",
            gauss ? "Marsden & West 2001, Acta Numerica 10, §2.6; Hairer, Lubich & Wanner, GNI, "
                    "§VI.6.4 (Gauss collocation)"
                  : "Marsden & West 2001, Acta Numerica 10, §2.6; Hairer, Lubich & Wanner, GNI, "
                    "§VI.6.4 (Lobatto IIIA–IIIB)",
            fmt::format("{}:{}, the Galerkin VI: order {}, symplectic, symmetric", family, stages,
                        rule.order)};
  a.statement = fmt::format(
      "The Galerkin variational integrator with a polynomial of degree {0} and the {0}-node "
      "{1} rule is the {0}-stage {2}, of order {3}; symplectic as a variational integrator, "
      "symmetric as its rule is.",
      stages, gauss ? "Gauss–Legendre" : "Gauss–Lobatto",
      gauss ? "Gauss collocation method" : "Lobatto IIIA–IIIB pair", rule.order);
  return a;
}

// A Boost.Odeint stepper through the C ABI (examples/black_box/odeint_steppers.cpp, built as
// vibook_odeint_steppers.so), held to `order` (the class's order_value, read at compile time).
AuditEntry odeint_row(const std::string& id, const std::string& stepper, const std::string& cls,
                      int order, bool symmetric, const std::string& what) {
  AuditEntry a;
  a.stepper = stepper;
  a.expected = order;
  a.symmetric_claimed = symmetric;
  a.info = {
      id, "A",
      "Boost.Odeint " + std::to_string(BOOST_VERSION / 100000) + "." +
          std::to_string(BOOST_VERSION / 100 % 1000) + ", " + cls,
      fmt::format("odeint {}: order {}, symplectic{}", cls, order, symmetric ? ", symmetric" : "")};
  a.statement = fmt::format(
      "{} Its order_value is {}; symplectic{}. Measured as a black box through the C ABI.", what,
      order, symmetric ? " and symmetric" : "");
  return a;
}

// The ordinal of a header's Doxygen brief of `cls` ("... of sixth order." -> 6), the brief
// quoted in `quote`; 0 when the header or the brief is not found.
int brief_order(const std::string& header, const std::string& cls, std::string& quote) {
  std::ifstream f(std::string(VIBOOK_BOOST_INCLUDE) + "/" + header);
  if (!f) return 0;
  std::stringstream text;
  text << f.rdbuf();
  const std::string t = text.str();
  const auto at = t.find("\\class " + cls);
  if (at == std::string::npos) return 0;
  const auto b = t.find("\\brief", at);
  if (b == std::string::npos) return 0;
  quote = t.substr(b + 7, t.find('\n', b) - b - 7);
  while (!quote.empty() && quote.front() == ' ') quote.erase(0, 1);
  static const char* ordinals[] = {"first", "second",  "third",  "fourth", "fifth",
                                   "sixth", "seventh", "eighth", "ninth",  "tenth"};
  const std::regex of_order(R"(of (\w+) order)");
  std::smatch m;
  if (!std::regex_search(quote, m, of_order)) return 0;
  for (int k = 0; k < 10; ++k)
    if (m[1] == ordinals[k]) return k + 1;
  return 0;
}

// The module of examples/black_box/odeint_steppers.cpp: the installed copy for an installed
// vibook, else the build tree's. Not finding it is an error of the installation, never a
// finding about a stepper: std::runtime_error.
std::shared_ptr<StepperLibrary> stepper_module(const char* built, const char* installed,
                                               const char* what, const std::string& arg, int dof) {
  std::string path = built;
  if (auto p = plot::installed_path(installed); !p.empty()) path = p.string();
  try {
    return std::make_shared<StepperLibrary>(path, arg, dof);
  } catch (const ArgumentError& e) {
    throw std::runtime_error(std::string("field audit: ") + what + ": " + e.what());
  }
}
std::shared_ptr<StepperLibrary> odeint_module(const std::string& arg, int dof) {
  return stepper_module(VIBOOK_ODEINT_STEPPERS, VIBOOK_INSTALL_ODEINT_REL,
                        "Boost.Odeint's steppers module", arg, dof);
}
// The same for examples/black_box/forced_steppers.cpp (C ABI version 2, the time argument).
std::shared_ptr<StepperLibrary> forced_module(const std::string& arg) {
  return stepper_module(VIBOOK_FORCED_STEPPERS, VIBOOK_INSTALL_FORCED_REL,
                        "the forced steppers module", arg, 1);
}

double number_or_nan(const json& j) {
  return j.is_number() ? j.get<double>() : std::numeric_limits<double>::quiet_NaN();
}

// What one problem's measurement says, for the note and the values.
struct Measured {
  std::string problem;
  std::vector<std::string> failed;
  double order = NAN, symplectic = NAN, reversible = NAN, energy = NAN;
  double expected = NAN, tolerance = NAN;
  double last_slope = NAN;   // between the two smallest step sizes of the fit
  double variational = NAN;  // the measured variational order (NaN: not measured, a black box)
  bool has_variational = false;
  // The variational order derived by the symbolic engine (method_symbolic.hpp), as `vibook
  // verify` derives it by default; -1 where it is not derived, with the reason.
  int derived = -1;
  std::string not_derived;
  std::string brief;  // a stepper's Doxygen brief, quoted
  std::string energy_verdict;
  json conditions, composition;
  std::string stopped;                                      // a measurement that threw: why
  std::vector<std::pair<std::string, double>> constraints;  // a constrained row's residuals
};

Measured read(Measured m, const MapMeasurement& rep);

// A forced system of the audit, typed: L(q, v, t), V(x, t) and the midpoint L_d with the forcing
// at the time `time`.
struct ForcedSystem {
  std::string lagrangian, potential, midpoint;
};

ForcedSystem forced_system(const std::string& name, const std::string& time) {
  if (name == "forced-oscillator")
    return {"v^2/2 - q^2/2 + q*cos(t)", "x^2/2 - x*cos(t)",
            "h*(((q1-q0)/h)^2/2 - ((q0+q1)/2)^2/2 + (q0+q1)/2*cos(" + time + "))"};
  if (name == "forced-pendulum")
    return {"v^2/2 + cos(q) + q*cos(t)/2", "-cos(x) - x*cos(t)/2",
            "h*(((q1-q0)/h)^2/2 + cos((q0+q1)/2) + (q0+q1)/2*cos(" + time + ")/2)"};
  throw std::logic_error("field audit: no forced system '" + name + "'");
}

// A row on the forced systems: a Galerkin method on the typed L(q, v, t), or the midpoint L_d.
void measure_forced(const AuditEntry& a, const std::string& problem_name, MapStudy study,
                    MapMeasurement& rep) {
  const ForcedSystem f = forced_system(problem_name, a.forced_time);
  const std::vector<double> q0{0.5}, p0{0.0};
  if (!a.stepper.empty()) {  // as `vibook verify --stepper-lib vibook_forced_steppers.so ...`
    TypedTexts t{"", f.potential, "", "p^2/2 + V(q)", 0};
    t.system_only = true;
    t.allow_time = true;
    const TypedDiscreteLagrangian sys(t);
    const auto lib = forced_module(a.stepper + "/" + problem_name);
    set_black_box_map(study, *lib, 1);
    set_typed_potential(study, sys, f.potential, q0, p0);
    study.expected = a.expected.value_or(2);
    study.symmetric_claimed = a.symmetric_claimed;
    measure_map(study, rep);
    return;
  }
  if (!a.tableau_json.empty()) {  // as `vibook verify --tableau FILE --potential V(x, t)`
    TypedTexts t{"", f.potential, "", "p^2/2 + V(q)", 0};
    t.system_only = true;
    t.allow_time = true;
    const TypedDiscreteLagrangian sys(t);
    const TableauSpec spec = parse_tableau(a.tableau_json, a.info.id);
    const std::string line = set_typed_potential(study, sys, f.potential, q0, p0);
    measure_tableau_typed(spec, sys, q0, p0, study, line, true, false, rep);
    return;
  }
  if (!a.splitting.empty()) {  // as `vibook verify --splitting NAME --potential V(x, t)`
    const std::string ld = splitting_stage_ld(true);
    TypedTexts t{ld, f.potential, "", "p^2/2 + V(q)", 0};
    t.allow_time = true;
    const TypedDiscreteLagrangian dl(t);
    measure_ld_composition(splitting_spec("--splitting", a.splitting), dl,
                           {ld, f.potential, "", "", q0, p0}, study, SymbolicUse::never, rep);
    return;
  }
  if (!a.method.empty()) {
    TypedTexts t{"", "", f.lagrangian, "", 0};
    t.system_only = true;
    t.allow_time = true;
    const TypedDiscreteLagrangian sys(t);
    const auto colon = a.method.find(':');
    MethodSpec spec;
    spec.name = a.method;
    spec.stages = std::stoi(a.method.substr(colon + 1));
    spec.rule = quadrature_rule(a.method.substr(0, colon), spec.stages);
    spec.expected = spec.rule.order;
    const std::string line = set_typed_lagrangian(study, sys, f.lagrangian, q0, p0);
    measure_method_typed(spec, sys, q0, p0, study, line, rep);
    return;
  }
  TypedTexts t{f.midpoint, f.potential, "", "p^2/2 + V(q)", 0};
  t.allow_time = true;
  const TypedDiscreteLagrangian dl(t);
  if (!a.coefficients.empty()) {  // as `vibook verify --composition ld --coefficients NAME`
    CompositionSpec spec;
    spec.coefficients = a.coefficients;
    spec.entry = comp::find_entry(a.coefficients);
    if (!spec.entry) throw std::logic_error("field audit: no composition '" + a.coefficients + "'");
    study.symmetric_claimed = true;
    measure_ld_composition(std::move(spec), dl, {f.midpoint, f.potential, "", "", q0, p0}, study,
                           SymbolicUse::never, rep);
    return;
  }
  study.expected = a.expected.value_or(2);
  study.symmetric_claimed = true;
  measure_timed_ld(dl, {f.midpoint, f.potential, "", "", q0, p0}, study, rep);
}

Measured measure_row(const AuditEntry& a, const std::string& problem_name) {
  Measured m;
  m.problem = problem_name;
  if (!a.constrained.empty() || a.forced) {
    MapMeasurement rep;
    MapStudy study;
    try {
      if (a.forced) {
        measure_forced(a, problem_name, study, rep);
      } else {
        const ConstrainedProblem* p = find_constrained_problem(problem_name);
        if (!p)
          throw std::logic_error("field audit: no constrained problem '" + problem_name + "'");
        study.expected = a.expected.value_or(2);
        measure_constrained(*p, a.constrained == "rattle", p->q0, p->p0, study, rep);
      }
    } catch (const NumericalError& e) {
      m.stopped = e.what();
      m.failed.push_back("measurement");
      return m;
    }
    return read(m, rep);
  }
  const TestProblem* problem = find_problem(problem_name);
  if (!problem) throw std::logic_error("field audit: no test problem '" + problem_name + "'");
  MapMeasurement rep;
  MapStudy study;  // the command's defaults: T = 5, h = 0.05, 1e5 steps, tolerance 0.2
  if (!a.stepper.empty()) {
    // The header's brief and the module are the installation's: not finding them is an error
    // (std::runtime_error out of the check), never a finding about a stepper.
    double expected = a.expected.value_or(0);
    if (!a.brief_header.empty()) {
      std::string quote;
      expected = brief_order(a.brief_header, a.brief_class, quote);
      if (expected == 0)
        throw std::runtime_error("field audit: no '\\brief ... of <ordinal> order' for " +
                                 a.brief_class + " in " + VIBOOK_BOOST_INCLUDE + "/" +
                                 a.brief_header);
      rep.line("documented", fmt::format("order {:g}, from the brief of {}: \"{}\"", expected,
                                         a.brief_class, quote));
      rep.js["brief"] = quote;
    }
    const int n = static_cast<int>(problem->q0.size());
    auto lib = odeint_module(a.stepper + "/" + problem_name, n);
    study.step = naming_failures(
        [lib, n](Eigen::VectorXd& z, double h) { lib->run(h, 1, z.data(), z.data() + n); }, n);
    study.propagate = [lib, n](Eigen::VectorXd& z, double h, long long k) {
      lib->run(h, k, z.data(), z.data() + n);
    };
    set_problem(study, *problem, problem->q0, problem->p0);
    study.expected = expected;
    study.symmetric_claimed = a.symmetric_claimed;
    study.symmetric_note = " (reported only: not documented as symmetric)";
    measure_map(study, rep);  // a failed step is a NumericalError, reported as a part
    return read(m, rep);
  }
  if (!a.method.empty()) {
    const auto colon = a.method.find(':');
    MethodSpec spec;
    spec.name = a.method;
    spec.stages = std::stoi(a.method.substr(colon + 1));
    spec.rule = quadrature_rule(a.method.substr(0, colon), spec.stages);
    spec.expected = a.expected.value_or(spec.rule.order);
    if (a.expected) spec.expected_from = "the order the row claims";
    derive_galerkin_variational_order(spec, static_cast<int>(problem->q0.size()),
                                      test_problem_lagrangian(problem_name), SymbolicUse::automatic,
                                      study);
    try {
      measure_method(spec, *problem, problem->q0, problem->p0, study, rep);
    } catch (const std::exception& e) {
      m.stopped = e.what();
      m.failed.push_back("measurement");
      return m;
    }
    return read(m, rep);
  }
  // A composition, or a splitting as `vibook verify --splitting` measures it: the flows'
  // conditions, then every phase of its equivalent composition of symplectic Euler (in
  // double-double where double's slopes do not settle).
  CompositionSpec spec;
  if (!a.splitting.empty()) {
    spec = splitting_spec("--splitting", a.splitting);
  } else {
    spec.base = &base_named(a.base);
    spec.coefficients = a.coefficients;
    spec.entry = comp::find_entry(a.coefficients);
  }
  if (a.splitting.empty() && !spec.entry) {
    const MpfrDigits digits(kCompositionDigits);
    std::string item;
    for (std::size_t i = 0; i <= a.coefficients.size(); ++i) {
      if (i == a.coefficients.size() || a.coefficients[i] == ',') {
        spec.typed.push_back(comp::parse_stage<mpfr_real>("coefficients", item));
        item.clear();
      } else {
        item += a.coefficients[i];
      }
    }
  }
  if (a.expected) {
    spec.expected = a.expected;
    spec.expected_from = "the order the row claims";
  }
  if (a.splitting.empty() || !spec.typed.empty())
    derive_composition_variational_order(spec, problem_name, SymbolicUse::automatic, study);
  try {
    measure_composition(spec, *problem, problem->q0, problem->p0, study, rep);
  } catch (const std::exception& e) {
    m.stopped = e.what();
    m.failed.push_back("measurement");
    return m;
  }
  return read(m, rep);
}

Measured read(Measured m, const MapMeasurement& rep) {
  m.failed = rep.failed;
  const json& js = rep.js;
  if (js.contains("brief")) m.brief = js["brief"].get<std::string>();
  if (js.contains("order")) {
    const json& o = js["order"];
    m.order = number_or_nan(o["fitted"]);
    m.expected = number_or_nan(o["expected"]);
    m.tolerance = number_or_nan(o["tolerance"]);
    // The local slope between the two smallest step sizes of the fit.
    const auto h = o["h"].get<std::vector<double>>();
    const auto e = o["error"].get<std::vector<double>>();
    const auto used = o["used_in_fit"].get<std::vector<bool>>();
    std::vector<std::size_t> fitted;
    for (std::size_t i = 0; i < h.size(); ++i)
      if (used[i]) fitted.push_back(i);
    std::sort(fitted.begin(), fitted.end(), [&](auto x, auto y) { return h[x] < h[y]; });
    if (fitted.size() >= 2)
      m.last_slope = std::log(e[fitted[1]] / e[fitted[0]]) / std::log(h[fitted[1]] / h[fitted[0]]);
  }
  if (js.contains("variational_order") && js["variational_order"].contains("order")) {
    m.has_variational = true;
    m.variational = number_or_nan(js["variational_order"]["order"]);
  }
  if (js.contains("variational_order") && js["variational_order"].contains("engine")) {
    const json& e = js["variational_order"]["engine"];
    if (e.value("derived", false) && e["order"].is_number())
      m.derived = e["order"].get<int>();
    else
      m.not_derived = e.value("reason", std::string("not derived"));
  }
  if (js.contains("symplecticity")) m.symplectic = number_or_nan(js["symplecticity"]["defect"]);
  if (js.contains("reversibility")) m.reversible = number_or_nan(js["reversibility"]["defect"]);
  if (js.contains("energy") && js["energy"].contains("verdict")) {
    m.energy = number_or_nan(js["energy"]["relative_error"]);
    m.energy_verdict = js["energy"]["verdict"].get<std::string>();
  } else if (js.contains("energy")) {  // a time-dependent system: not judged
    m.energy = std::numeric_limits<double>::quiet_NaN();
  }
  for (const char* part : {"position_constraint", "hidden_constraint"})
    if (js.contains(part)) m.constraints.emplace_back(part, number_or_nan(js[part]["defect"]));
  m.conditions = js.value("order_conditions", json::object());
  m.composition = js.value("composition", json::object());
  return m;
}

std::string display_name(const std::string& problem) {
  return problem == "kepler"               ? "Kepler"
         : problem == "henon-heiles"       ? "Hénon–Heiles"
         : problem == "forced-oscillator"  ? "the forced oscillator"
         : problem == "forced-pendulum"    ? "the forced pendulum"
         : problem == "spherical-pendulum" ? "the spherical pendulum"
         : problem == "double-pendulum"    ? "the double pendulum"
                                           : problem;
}

std::string brief(const Measured& m) {
  if (!m.stopped.empty())
    return fmt::format("{}: the measurement stopped: {}", display_name(m.problem), m.stopped);
  return fmt::format(
      "{}: order {:.2f} (local slope {:.2f} at the smallest step sizes), {}symplectic defect "
      "{:.1e}, reversibility defect {:.1e}, "
      "energy {} (relative error {:.1e}){}",
      display_name(m.problem), m.order, m.last_slope,
      m.has_variational
          ? fmt::format("variational order {:.2f} (measured, reported){}, ", m.variational,
                        m.derived >= 0 ? fmt::format(" and {} (derived by the engine)", m.derived)
                        : m.not_derived.empty() ? std::string()
                                                : " (not derived by the engine)")
          : std::string(),
      m.symplectic, m.reversible,
      m.energy_verdict.empty() ? std::string("not judged") : m.energy_verdict, m.energy,
      [&] {
        std::string c;
        for (const auto& [part, value] : m.constraints)
          c += fmt::format(", {} residual {:.1e}",
                           part == "position_constraint" ? "position" : "hidden", value);
        return c;
      }() +
          (m.failed.empty() ? std::string(": every part passes")
                            : fmt::format(": FAILS {}", fmt::join(m.failed, ", "))));
}

}  // namespace

namespace {
std::string check_of(const AuditEntry& a);
}  // namespace

claims::ClaimResult judge_audit_entry(const AuditEntry& a) {
  std::vector<Measured> ms;
  for (const auto& problem : a.problems.empty() ? audit_problems() : a.problems)
    ms.push_back(measure_row(a, problem));
  claims::ClaimResult r;
  r.id = a.info.id;
  r.source = check_of(a);
  std::string brief_quote;
  for (const auto& m : ms)
    if (!m.brief.empty()) brief_quote = m.brief;
  double worst_sym = 0, worst_rev = 0, worst_energy = 0;
  r.values.emplace_back("expected_order", ms[0].expected);
  for (const auto& m : ms) {
    r.values.emplace_back("order_" + m.problem, m.order);
    r.values.emplace_back("last_local_slope_" + m.problem, m.last_slope);
    if (m.has_variational) r.values.emplace_back("variational_order_" + m.problem, m.variational);
    if (m.derived >= 0) r.values.emplace_back("derived_variational_order_" + m.problem, m.derived);
    worst_sym = std::max(worst_sym, m.symplectic);
    worst_rev = std::max(worst_rev, m.reversible);
    worst_energy = std::max(worst_energy, m.energy);
  }
  // The order conditions do not depend on the problem: read from the first measurement.
  std::string conditions_text =
      a.forced && !a.stepper.empty()
          ? fmt::format(
                "A black box: vibook_forced_steppers.so through the C ABI, version 2 (the "
                "step's start time an argument), method {}",
                a.stepper)
      : !a.stepper.empty()
          ? fmt::format("A black box: vibook_odeint_steppers.so through the C ABI, method {}{}",
                        a.stepper,
                        brief_quote.empty()
                            ? std::string()
                            : fmt::format("; the order claimed is the brief's: \"{}\" (order {:g})",
                                          brief_quote, ms[0].expected))
      : !a.constrained.empty()
          ? "A constrained method: no composition conditions; its multipliers solved by Newton's "
            "method to the rounding of the constraints"
      : a.forced && !a.tableau_json.empty()
          ? "A partitioned Runge–Kutta tableau (its symplecticity and order conditions checked "
            "by the route at 120 digits)"
      : a.forced ? "A method for a time-dependent system (the time in the state): no composition "
                   "conditions"
      : a.method.empty() ? "Order conditions not evaluated"
                         : "A Galerkin method, so no composition conditions; its step equals the "
                           "partitioned Runge–Kutta method it generates to 64 units in the last "
                           "place (galerkin_test.cpp)";
  if (!ms[0].conditions.empty()) {
    const json& oc = ms[0].conditions;
    const auto residual = oc["residual_by_weight"].get<std::vector<double>>();
    const int order = oc["order"].get<int>();
    const int want = static_cast<int>(std::floor(oc["expected"].get<double>() + 1e-9));
    double satisfied = 0;  // the largest residual of the weights the order needs
    for (int k = 0; k < std::min<int>(want, int(residual.size())); ++k)
      satisfied = std::max(satisfied, residual[static_cast<std::size_t>(k)]);
    r.values.emplace_back("order_by_conditions", order);
    r.values.emplace_back("conditions_residual_to_expected_weight", satisfied);
    conditions_text = fmt::format(
        "Order conditions at {} digits: order {} (each weight's residual <= {:.0e}), largest "
        "residual up to weight {} {:.1e}",
        oc["digits"].get<int>(), order, oc["tolerance"].get<double>(), want, satisfied);
    if (order < int(residual.size()))
      conditions_text += fmt::format(", weight {} fails by {:.1e}", order + 1,
                                     residual[static_cast<std::size_t>(order)]);
    const json& c = ms[0].composition;
    if (c.contains("newton")) {
      const auto pub = c["newton"]["published_residual_by_weight"].get<std::vector<double>>();
      const double worst_pub = *std::max_element(pub.begin(), pub.end());
      const double change = c["newton"]["max_change_from_published"].get<double>();
      r.values.emplace_back("published_digits_residual", worst_pub);
      r.values.emplace_back("newton_change_from_published", change);
      conditions_text += fmt::format(
          "; the published digits satisfy them to {:.1e}, and Newton at 120 digits moves them by "
          "{:.1e}",
          worst_pub, change);
    }
  }
  r.values.emplace_back("symplectic_defect_max", worst_sym);
  r.values.emplace_back("reversibility_defect_max", worst_rev);
  // a time-dependent system's energy is not judged (not conserved): no value to record
  if (std::any_of(ms.begin(), ms.end(), [](const Measured& m) { return std::isfinite(m.energy); }))
    r.values.emplace_back("energy_relative_error_max", worst_energy);
  std::vector<std::string> lines, skipped;
  for (const auto& m : ms) {
    lines.push_back(brief(m));
    if (!m.not_derived.empty())
      skipped.push_back(
          fmt::format(" {}: the variational order is {}.", display_name(m.problem), m.not_derived));
  }
  const std::string measured =
      fmt::format("{}. {}.{}", conditions_text, fmt::join(lines, "; "), fmt::join(skipped, ""));

  if (a.must_flag.empty()) {
    std::vector<std::string> failures;
    for (const auto& m : ms)
      if (!m.failed.empty())
        failures.push_back(
            fmt::format("{} on {}", fmt::join(m.failed, ", "), display_name(m.problem)));
    r.status = failures.empty() ? claims::Status::reproduced : claims::Status::not_reproduced;
    const std::string command =
        a.forced && !a.stepper.empty()
            ? fmt::format(
                  "--stepper-lib vibook_forced_steppers.so --stepper-arg {}/PROBLEM "
                  "--potential V(x, t) --q0 0.5 --p0 0 --expected-order {:g}{}",
                  a.stepper, ms[0].expected, a.symmetric_claimed ? " --symmetric" : "")
        : a.forced && !a.splitting.empty()
            ? "--splitting " + a.splitting + " --potential V(x, t) --q0 0.5 --p0 0"
        : !a.stepper.empty()
            ? fmt::format(
                  "--stepper-lib vibook_odeint_steppers.so --stepper-arg {}/PROBLEM "
                  "--expected-order {:g}{}",
                  a.stepper, ms[0].expected, a.symmetric_claimed ? " --symmetric" : "")
        : !a.splitting.empty()   ? "--splitting " + a.splitting
        : !a.constrained.empty() ? "--method " + a.constrained + " --problem PROBLEM"
        : a.forced && !a.method.empty()
            ? "--method " + a.method + " --lagrangian L(q, v, t) --q0 0.5 --p0 0"
        : a.forced && !a.tableau_json.empty()
            ? "--tableau lobatto3-iiia-iiib.json --potential V(x, t) --q0 0.5 --p0 0 --symmetric"
        : a.forced && !a.coefficients.empty()
            ? "--composition ld --coefficients " + a.coefficients +
                  " --ld L_d(t, q0, q1, h) --potential V(x, t) --q0 0.5 --p0 0 --symmetric"
        : a.forced ? "--ld L_d(t, q0, q1, h) --potential V(x, t) --q0 0.5 --p0 0 --symmetric"
        : a.method.empty()
            ? fmt::format("--composition {} --coefficients {}", a.base, a.coefficients)
            : "--method " + a.method;
    // The criterion is stated once, in the chapter's section "The audit"; the note names it
    // and the command it applies to.
    r.note = fmt::format(
        "Criterion (chapter 8, \"The audit\"): every part of `vibook verify {}` passes on both "
        "problems. {}",
        command, measured);
    if (!failures.empty()) {
      // Pre-asymptotic: only the order failed, and wherever it did, the local slope at the two
      // smallest step sizes of the fit is within the tolerance of the documented order.
      bool pre_asymptotic = true;
      for (const auto& m : ms) {
        if (m.failed.empty()) continue;
        const bool only_order = m.failed.size() == 1 && m.failed[0] == "order";
        pre_asymptotic =
            pre_asymptotic && only_order && std::abs(m.last_slope - m.expected) < m.tolerance;
      }
      r.cause = pre_asymptotic ? "pre-asymptotic" : "does-not-hold";
      r.headline = fmt::format("{}: fails {}{}", a.info.title, fmt::join(failures, "; "),
                               pre_asymptotic ? " (the local slope at the smallest step sizes "
                                                "is within the tolerance: the fitted window is "
                                                "not yet asymptotic)"
                                              : "");
      // A documentation row: what fails is the order the brief states, not the stepper (whose
      // own row, the ID without -BRIEF, holds it to its true order).
      if (!a.brief_class.empty()) {
        std::vector<std::string> orders;
        for (const auto& m : ms)
          orders.push_back(fmt::format("{:.2f} on {}", m.order, display_name(m.problem)));
        r.headline = fmt::format(
            "the order stated in the Doxygen brief of odeint's {} ({:g}) is not the stepper's: "
            "held to it, the stepper fails {}; its measured order is {} (its own row, {}, holds "
            "it to the class's order_value)",
            a.brief_class, ms.front().expected, fmt::join(failures, "; "), fmt::join(orders, ", "),
            a.info.id.substr(0, a.info.id.size() - std::string("-BRIEF").size()));
      }
    }
  } else {
    std::vector<std::string> missed;
    for (const auto& m : ms)
      for (const auto& part : a.must_flag)
        if (std::find(m.failed.begin(), m.failed.end(), part) == m.failed.end())
          missed.push_back(fmt::format("{} on {}", part, display_name(m.problem)));
    r.status = missed.empty() ? claims::Status::reproduced : claims::Status::not_reproduced;
    r.note = fmt::format(
        "Criterion: the verdict fails {} on both problems. {}{}", and_list(a.must_flag), measured,
        missed.empty() ? std::string(" Flagged.")
                       : fmt::format(" NOT flagged: {}.", fmt::join(missed, ", ")));
    if (!missed.empty()) {
      r.cause = "does-not-hold";
      r.headline =
          fmt::format("the audit does not flag a wrong composition ({})", fmt::join(missed, ", "));
    }
  }
  return r;
}

namespace {

// The check that measures a row.
std::string check_of(const AuditEntry& a) {
  return !a.constrained.empty() || a.forced ? "field-audit-systems"
         : !a.method.empty()                ? "field-audit-galerkin"
         : !a.stepper.empty()               ? "field-audit-odeint"
         : !a.splitting.empty()             ? "field-audit-splitting"
                                            : "field-audit";
}

std::vector<std::string> ids(const std::string& check) {
  std::vector<std::string> r;
  for (const auto& a : audit_entries())
    if (check_of(a) == check) r.push_back(a.info.id);
  return r;
}

// The rows of one check, measured and judged.
std::vector<claims::ClaimResult> run_rows(const std::string& check) {
  std::vector<claims::ClaimResult> out;
  for (const auto& a : audit_entries())
    if (check_of(a) == check) out.push_back(judge_audit_entry(a));
  return out;
}

}  // namespace

const std::vector<std::string>& audit_problems() {
  static const std::vector<std::string> p = {"kepler", "henon-heiles"};
  return p;
}

const std::vector<AuditEntry>& audit_entries() {
  static const std::vector<AuditEntry> rows = [] {
    std::vector<AuditEntry> r;
    for (const char* name :
         {"yoshida4", "suzuki4", "yoshida6", "yoshida8", "mclachlan8", "kahanli6", "kahanli8"})
      r.push_back(published(name, "sv"));
    r.push_back(published("yoshida6", "midpoint", "-MIDPOINT"));
    r.push_back(published("yoshida6", "vi2", "-VI2"));
    r.push_back(published("ruth3", "se"));
    r.push_back(published("ruth3", "vi1", "-VI1"));
    // Yoshida's sixth-order solution A as published (15 digits, stages w3 w2 w1 w0 w1 w2 w3)
    // with w1 changed in its eleventh digit (-1.17767998417887 -> -1.17767998416887) and
    // w0 = 1 - 2(w1 + w2 + w3) recomputed, so that the stages still sum to 1.
    r.push_back(wrong("A-WRONG-DIGIT", "yoshida6 with w1 off by 1e-11 on sv: flagged",
                      "Yoshida's sixth-order solution A on Störmer–Verlet with w1 changed by "
                      "1e-11 (the middle stage recomputed so that the stages still sum to 1).",
                      "sv",
                      "0.784513610477560,0.235573213359357,-1.17767998416887,1.315186320663906,"
                      "-1.17767998416887,0.235573213359357,0.784513610477560",
                      6, {"order conditions"}));
    r.push_back(wrong("A-WRONG-ADJOINT", "ruth3 with stage and adjoint swapped: flagged",
                      "Ruth's third-order method with each pair (adjoint, base) applied in the "
                      "other order: the same coefficients, the same operations, a different "
                      "composition.",
                      "se", "3/8,7/24*,-25/24,3/8*,0,1*", 3,
                      {"order conditions", "order", "variational order"}));
    r.push_back(wrong("A-WRONG-BASE", "the triple jump on symplectic Euler: flagged",
                      "Yoshida's fourth-order triple jump built on symplectic Euler (order 1, "
                      "not symmetric) instead of a symmetric base of order 2.",
                      "se", "yoshida4", 4, {"order conditions", "order"}));
    namespace odeint = boost::numeric::odeint;
    using State = std::vector<double>;
    r.push_back(odeint_row("A-ODEINT-VERLET", "velocity_verlet", "velocity_verlet", 2, true,
                           "Boost.Odeint's velocity Verlet, reset before every step (it keeps "
                           "the last acceleration otherwise). The class has no order_value; its "
                           "documented order is 2."));
    r.push_back(odeint_row("A-ODEINT-MCLACHLAN", "mclachlan4", "symplectic_rkn_sb3a_mclachlan",
                           odeint::symplectic_rkn_sb3a_mclachlan<State>::order_value, true,
                           "Boost.Odeint's symmetric B3A Runge–Kutta–Nyström method (McLachlan "
                           "1995), six stages."));
    r.push_back(odeint_row("A-ODEINT-M4", "mclachlan4_m4", "symplectic_rkn_sb3a_m4_mclachlan",
                           odeint::symplectic_rkn_sb3a_m4_mclachlan<State>::order_value, true,
                           "Boost.Odeint's symmetric B3A Runge–Kutta–Nyström method in its M4 "
                           "form (McLachlan 1995)."));
    for (auto [id, stepper, cls] :
         {std::tuple{"A-ODEINT-MCLACHLAN-BRIEF", "mclachlan4", "symplectic_rkn_sb3a_mclachlan"},
          std::tuple{"A-ODEINT-M4-BRIEF", "mclachlan4_m4", "symplectic_rkn_sb3a_m4_mclachlan"}}) {
      AuditEntry a;
      a.stepper = stepper;
      a.symmetric_claimed = true;
      a.brief_header = std::string("boost/numeric/odeint/stepper/") + cls + ".hpp";
      a.brief_class = cls;
      a.info = {id, "A",
                "Boost.Odeint " + std::to_string(BOOST_VERSION / 100000) + "." +
                    std::to_string(BOOST_VERSION / 100 % 1000) + ", " + cls + ", Doxygen brief",
                fmt::format("odeint {}: the order its Doxygen brief states", cls)};
      a.statement = fmt::format(
          "The order the class's Doxygen brief states (read from the installed header {} when "
          "the check runs, and quoted in the note); symplectic and symmetric.",
          a.brief_header);
      r.push_back(a);
    }
    {
      AuditEntry a =
          odeint_row("A-WRONG-EXPLICIT-EULER", "explicit_euler", "symplectic_euler", 1, false, "");
      a.info = {"A-WRONG-EXPLICIT-EULER", "A", "deliberately wrong",
                "explicit Euler sold as symplectic Euler: flagged"};
      a.statement =
          "Explicit Euler (q1 = q0 + h p0, p1 = p0 - h grad V(q0)) behind the same ABI, held to "
          "order 1 as if it were symplectic Euler. A correct audit must fail it on both problems, "
          "naming symplectic.";
      a.must_flag = {"symplectic"};
      r.push_back(a);
    }
    {
      AuditEntry a =
          odeint_row("A-WRONG-CACHED", "velocity_verlet_cached", "velocity_verlet", 2, true, "");
      a.info = {"A-WRONG-CACHED", "A", "deliberately wrong",
                "odeint velocity_verlet without reset: flagged"};
      a.statement =
          "Boost.Odeint's velocity_verlet called without reset(): it reuses the acceleration of "
          "the state it returned last, so the map depends on the previous call. Held to order 2, "
          "a correct audit must fail it on both problems, naming order and symplectic.";
      a.must_flag = {"order", "symplectic"};
      r.push_back(a);
    }
    // The splittings of the catalogue with a documented order above 2, and three wrong ones.
    for (const char* name : {"forest-ruth", "ruth-3", "mclachlan-atela-4", "mclachlan-atela-5"})
      r.push_back(published_splitting(name));
    {
      const std::string t = "(2-2^(1/3))", u = "(2+2^(1/3))";
      r.push_back(wrong_splitting(
          "A-WRONG-SPLIT-MOVED", "Forest–Ruth with its last half drift moved to the front: flagged",
          "Forest and Ruth's seven flows with the last half drift moved to the front, the first "
          "drift whole: the step structure of a code that merges the half drifts of consecutive "
          "steps without the half drifts that begin and end the run (not a palindrome).",
          fmt::format("drift:1/{0},kick:1/{0},drift:(1-2^(1/3))/(2*{0}),kick:-2^(1/3)/{0},"
                      "drift:(1-2^(1/3))/(2*{0}),kick:1/{0}",
                      t),
          4, {"order conditions", "order"}));
      r.push_back(wrong_splitting(
          "A-WRONG-SPLIT-THETA", "Forest–Ruth with the sign inside θ flipped: flagged",
          "Forest and Ruth's method with θ = 1/(2+2^(1/3)) for 1/(2-2^(1/3)): still a consistent "
          "palindrome, symmetric and symplectic, but of order 2.",
          fmt::format("drift:1/(2*{0}),kick:1/{0},drift:(1+2^(1/3))/(2*{0}),kick:2^(1/3)/{0},"
                      "drift:(1+2^(1/3))/(2*{0}),kick:1/{0},drift:1/(2*{0})",
                      u),
          4, {"order conditions", "order"}));
      r.push_back(wrong_splitting(
          "A-WRONG-SPLIT-DRIFT-FIRST",
          "McLachlan–Atela's fourth-order RKN method stepped drift first: flagged",
          "McLachlan and Atela's fourth-order Runge–Kutta–Nyström splitting with each of its "
          "kick–drift pairs applied drift first: the same coefficients, the two flows of every "
          "pair in the other order.",
          "drift:0.5153528374311229364,kick:0.1344961992774310892,drift:-0.085782019412973646,"
          "kick:-0.2248198030794208058,drift:0.4415830236164665242,kick:0.7563200005156682911,"
          "drift:0.1288461583653841854,kick:0.3340036032863214255",
          4, {"order conditions", "order"}));
    }
    for (int s = 1; s <= 4; ++s) r.push_back(galerkin("gauss", s));
    for (int s = 2; s <= 5; ++s) r.push_back(galerkin("lobatto", s));
    // The new kinds of system (long study field-audit-systems).
    {
      const std::vector<std::string> constrained = {"spherical-pendulum", "double-pendulum"};
      AuditEntry a;
      a.constrained = "rattle";
      a.problems = constrained;
      a.info = {"A-RATTLE", "A",
                "Andersen 1983, J. Comput. Phys. 52; Leimkuhler & Skeel 1994; Hairer, Lubich & "
                "Wanner, GNI, §VII.1.4",
                "RATTLE: order 2, symplectic on the constraint manifold, symmetric, both "
                "constraints kept"};
      a.statement =
          "RATTLE for H = |p|²/2 + V(q) with holonomic constraints g(q) = 0 is of order 2, "
          "symmetric, and symplectic as a map of the constraint manifold; it keeps the position "
          "constraint and the hidden constraint G(q)p = 0 to round-off.";
      r.push_back(a);
      AuditEntry w = wrong("A-WRONG-SHAKE",
                           "RATTLE without the velocity projection: flagged on the hidden "
                           "constraint",
                           "RATTLE with the projection of the new momentum onto the hidden "
                           "constraint left out (the momentum leaves the cotangent bundle by O(h) "
                           "a step).",
                           "", "", 2, {"hidden constraint"});
      w.constrained = "shake";
      w.problems = constrained;
      r.push_back(w);
      const std::vector<std::string> forced = forced_problems();
      for (const char* method : {"gauss:2", "lobatto:3"}) {
        AuditEntry g = galerkin(std::string(method).substr(0, std::string(method).find(':')),
                                std::string(method).back() - '0');
        g.forced = true;
        g.problems = forced;
        g.info.id = "A-FORCED-" + g.info.id.substr(2);
        g.info.title = "forced: " + g.info.title;
        g.statement +=
            " On a time-dependent L(q, v, t) the quadrature's nodes sit at the times "
            "t + c_i h, and the same holds.";
        r.push_back(g);
      }
      AuditEntry fr = published_splitting("forest-ruth");
      fr.forced = true;
      fr.problems = forced;
      fr.info.id = "A-FORCED-SPLIT-FOREST-RUTH";
      fr.info.title = "forced: " + fr.info.title;
      fr.statement +=
          " On H(q, p, t) = |p|²/2 + V(q, t) the drifts carry the time (the split "
          "of the extended Hamiltonian), and the same holds.";
      r.push_back(fr);
      AuditEntry mid;
      mid.forced = true;
      mid.forced_time = "t+h/2";
      mid.problems = forced;
      mid.info = {"A-FORCED-MIDPOINT-LD", "A",
                  "Marsden & West 2001, Acta Numerica 10, §2.6 (the midpoint rule), §4 "
                  "(time-dependent systems)",
                  "forced: the midpoint rule as a typed L_d(t, q0, q1, h): order 2, symplectic, "
                  "symmetric"};
      mid.statement =
          "The midpoint rule h L((q0+q1)/2, (q1-q0)/h, t + h/2) of a time-dependent L is a "
          "symmetric variational integrator of order 2.";
      r.push_back(mid);
      // A composition of that typed L_d(t, q0, q1, h): the stages start at the partial sums.
      AuditEntry comp_mid = mid;
      comp_mid.coefficients = "yoshida4";
      comp_mid.info = {"A-FORCED-COMPOSITION-LD-YOSHIDA4", "A",
                       "Yoshida 1990, Phys. Lett. A 150; Marsden & West 2001, §4",
                       "forced: Yoshida's composition of the typed midpoint L_d(t, q0, q1, h): "
                       "order 4, symplectic, symmetric"};
      comp_mid.statement =
          "Yoshida's fourth-order triple jump of the symmetric midpoint rule of a "
          "time-dependent L is of order 4, symmetric and symplectic, each stage starting at "
          "the time the stages before it reached.";
      r.push_back(comp_mid);
      AuditEntry stale = wrong("A-WRONG-FORCED-STALE-LD",
                               "the midpoint rule with the forcing at the step's start: flagged",
                               "The midpoint rule with the forcing evaluated at the step's start "
                               "time t instead of t + h/2 (the time advanced with the wrong "
                               "coefficient); right on an autonomous system.",
                               "", "", 2, {"order"});
      stale.forced = true;
      stale.forced_time = "t";
      stale.problems = forced;
      r.push_back(stale);
      // The tableau family: Lobatto IIIA-IIIB with three stages (examples/tableaus), each stage at
      // t + c_i h.
      AuditEntry tab;
      tab.forced = true;
      tab.problems = forced;
      tab.tableau_json = R"({"name": "Lobatto IIIA-IIIB", "order": 4, "symmetric": true,
        "a": [["0", "0", "0"], ["5/24", "1/3", "-1/24"], ["1/6", "2/3", "1/6"]],
        "b": ["1/6", "2/3", "1/6"],
        "ahat": [["1/6", "-1/6", "0"], ["1/6", "1/3", "0"], ["1/6", "5/6", "0"]],
        "bhat": ["1/6", "2/3", "1/6"]})";
      tab.info = {"A-FORCED-TABLEAU-LOBATTO3", "A",
                  "Hairer, Lubich & Wanner, GNI, §II.2.2 (Lobatto IIIA-IIIB)",
                  "forced: the Lobatto IIIA-IIIB tableau with three stages, its stages at "
                  "t + c_i h: order 4, symplectic, symmetric"};
      tab.statement =
          "The three-stage Lobatto IIIA-IIIB pair is a symmetric symplectic partitioned "
          "Runge–Kutta method of order 4; on H(q, p, t) the time is a position of the extended "
          "system, each stage at t + c_i h, and the same holds.";
      r.push_back(tab);
      // The black-box family: a C library of the ABI's version 2 (the step's start time an
      // argument), examples/black_box/forced_steppers.cpp, right and with the time stale.
      AuditEntry box;
      box.forced = true;
      box.stepper = "sv";
      box.expected = 2;
      box.symmetric_claimed = true;
      box.problems = forced;
      box.info = {"A-FORCED-BLACKBOX-SV", "A",
                  "Hairer, Lubich & Wanner, GNI, §I.1.4 (Störmer–Verlet); vibook's C ABI "
                  "version 2 (vibook/verify/stepper_abi.h)",
                  "forced: Störmer–Verlet in a C library behind the C ABI with the time: order "
                  "2, symplectic, symmetric"};
      box.statement =
          "Störmer–Verlet with the time as a drifting variable (half a kick at t, a drift of h, "
          "half a kick at t + h) is a symmetric symplectic method of order 2 for H(q, p, t) = "
          "p²/2 + V(q, t), measured as a black box told the step's start time.";
      r.push_back(box);
      AuditEntry box_stale =
          wrong("A-WRONG-FORCED-STALE-BLACKBOX",
                "Störmer–Verlet in a C library with the second half kick at the step's start "
                "time: flagged",
                "Störmer–Verlet as a black box whose second half kick reads the step's start "
                "time t instead of t + h (the drift advances the time with coefficient 0); "
                "right on an autonomous system.",
                "", "", 2, {"order"});
      box_stale.forced = true;
      box_stale.stepper = "sv_stale";
      box_stale.symmetric_claimed = true;
      box_stale.problems = forced;
      r.push_back(box_stale);
    }
    return r;
  }();
  return rows;
}

const std::vector<std::string>& forced_problems() {
  static const std::vector<std::string> p = {"forced-oscillator", "forced-pendulum"};
  return p;
}

}  // namespace vibook::verify

namespace vibook::checks {

// (Each check's definition is written out, `return {"ID", ...`: the report links its source.)
Check field_audit() {
  return {"field-audit",
          "The field audit: published compositions and deliberately wrong ones on Kepler and "
          "Hénon–Heiles",
          false, verify::ids("field-audit"),
          [](const Context&) { return verify::run_rows("field-audit"); }};
}

Check field_audit_odeint() {
  return {"field-audit-odeint",
          "The field audit: Boost.Odeint's steppers through the C ABI, and two wrong ones, on "
          "Kepler and Hénon–Heiles",
          false, verify::ids("field-audit-odeint"),
          [](const Context&) { return verify::run_rows("field-audit-odeint"); }};
}

Check field_audit_splitting() {
  return {"field-audit-splitting",
          "The field audit: splittings of the catalogue (drift and kick flows) and three wrong "
          "ones, on Kepler and Hénon–Heiles (long study: about a minute)",
          false, verify::ids("field-audit-splitting"),
          [](const Context&) { return verify::run_rows("field-audit-splitting"); }};
}

Check field_audit_systems() {
  return {"field-audit-systems",
          "The field audit: new kinds of system, RATTLE on two constrained pendulums and methods "
          "of two families on a forced oscillator and a forced pendulum, each with a wrong one "
          "(long study: about 15 s)",
          false, verify::ids("field-audit-systems"),
          [](const Context&) { return verify::run_rows("field-audit-systems"); }};
}

Check field_audit_galerkin() {
  return {"field-audit-galerkin",
          "The field audit: Galerkin variational integrators (Gauss 1-4, Lobatto 2-5 nodes) on "
          "Kepler and Hénon–Heiles (long study: about 45 s)",
          false, verify::ids("field-audit-galerkin"),
          [](const Context&) { return verify::run_rows("field-audit-galerkin"); }};
}

}  // namespace vibook::checks
