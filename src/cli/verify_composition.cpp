// `vibook verify --composition BASE --coefficients NAME|LIST`: the arguments checked before any
// work, then the measurement of vibook/verify/composition_study.hpp (order conditions at 120
// digits, measured order, symplecticity, reversibility, energy) printed. Every part is printed,
// even after one fails; the verdict names the parts that failed.
#include "verify_routes.hpp"

#include <cmath>
#include <mutex>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "args.hpp"
#include "cli.hpp"
#include "verify_map.hpp"
#include "vibook/core/output_file.hpp"
#include "vibook/core/precision.hpp"
#include "vibook/integrators/composition.hpp"
#include "vibook/verify/composition_ld_study.hpp"
#include "vibook/verify/composition_study.hpp"
#include "vibook/verify/expression.hpp"
#include "vibook/verify/method_symbolic.hpp"

namespace vibook::cli {

namespace {

namespace comp = vibook::composition;

// Everything checked before any work.
struct Plan {
  verify::CompositionSpec spec;
  const TestProblem* problem = nullptr;
  std::vector<double> q0, p0;
  MapStudy study;  // the measurement settings (--t-end, --h-list, --h, --steps, …)
  verify::SymbolicUse symbolic = verify::SymbolicUse::automatic;
};

// The largest size of a typed stage coefficient.
constexpr double kMaxCoefficient = 1e3;

// --expected-order, when given.
void check_expected(const VerifyOptions& o, verify::CompositionSpec& spec) {
  if (!o.has("--expected-order")) return;
  const double e = check_expected_order(o.expected);
  spec.expected = e;
}

// The coefficients: a catalogue entry or a typed list (parsed at 120 digits), and
// --expected-order.
void check_coefficients(const VerifyOptions& o, verify::CompositionSpec& spec) {
  if (o.coefficients.empty())
    throw ArgumentError("--coefficients",
                        "is required with --composition: a catalogue name (yoshida4, suzuki4, "
                        "yoshida6, yoshida8, mclachlan8, kahanli6, kahanli8, ruth3) or a list");
  spec.coefficients = o.coefficients;
  spec.entry = comp::find_entry(o.coefficients);
  if (!spec.entry) {
    const bool looks_like_list = o.coefficients.find_first_of("0123456789") != std::string::npos;
    if (!looks_like_list)
      throw ArgumentError("--coefficients", "no catalogue entry '" + o.coefficients +
                                                "' (yoshida4, suzuki4, yoshida6, yoshida8, "
                                                "mclachlan8, kahanli6, kahanli8, ruth3)");
    const MpfrDigits digits(verify::kCompositionDigits);
    for (const auto& item : split_list("--coefficients", o.coefficients)) {
      spec.typed.push_back(comp::parse_stage<mpfr_real>("--coefficients", item));
      // A stage of more than 1e3 steps (or one beyond double's range, 1e9223372036854775808)
      // is a typing error, not a method: no published composition has a coefficient above 3.
      const double c = static_cast<double>(spec.typed.back().c);
      if (!(std::abs(c) <= kMaxCoefficient))
        throw ArgumentError(
            "--coefficients",
            fmt::format("stage {} ('{}') lies beyond {:g} in size", spec.typed.size(),
                        item.size() > 40 ? item.substr(0, 40) + "..." : item, kMaxCoefficient));
    }
    if (spec.typed.empty() || spec.typed.size() > 64)
      throw ArgumentError("--coefficients", "needs 1 to 64 stages");
  }
  check_expected(o, spec);
}

Plan check(const VerifyOptions& o) {
  Plan p;
  if (!o.splitting.empty()) {
    p.spec = verify::splitting_spec("--splitting", o.splitting);
    check_expected(o, p.spec);
  } else {
    p.spec.base = verify::find_composition_base(o.composition);
    if (!p.spec.base)
      throw ArgumentError("--composition",
                          "unknown base method '" + o.composition +
                              "' (sv, midpoint, se, se-adjoint, vi1, vi1-adjoint, vi2, or ld "
                              "for the --ld typed)");
  }
  p.problem = &find_test_problem(o.problem);
  if (o.splitting.empty()) check_coefficients(o, p.spec);
  p.symbolic = verify::parse_symbolic_use(o.symbolic);
  check_initial_state(o, *p.problem, p.q0, p.p0, p.study);
  check_study_options(o, p.study);
  return p;
}

}  // namespace

int run_composition(const VerifyOptions& o) {
  // Compositions of RATTLE on a constrained system (the chapter's "Compositions of RATTLE"):
  // each stage a whole RATTLE step; no other base is stepped on a constraint manifold.
  if (!o.constraints.empty() || (o.splitting.empty() && o.composition == "rattle")) {
    VerifyOptions c = o;
    if (o.composition == "rattle" && !o.problem.empty()) {
      // a constrained test problem: its potential, constraints and state, typed
      const verify::ConstrainedProblem* cp = verify::find_constrained_problem(o.problem);
      if (!cp)
        throw ArgumentError("--problem", "'" + o.problem +
                                             "' is not a constrained test problem "
                                             "(spherical-pendulum, double-pendulum)");
      if (!o.potential.empty() || !o.constraints.empty())
        throw ArgumentError("--problem",
                            "names a constrained test problem; --potential and --constraint "
                            "give the system: give one of them");
      c.problem.clear();
      c.potential = cp->potential;
      c.constraints = cp->constraint_texts;
      if (c.q0.empty()) c.q0 = fmt::format("{}", fmt::join(cp->q0, ","));
      if (c.p0.empty()) c.p0 = fmt::format("{}", fmt::join(cp->p0, ","));
    }
    if (!o.splitting.empty())
      throw ArgumentError("--constraint",
                          "does not apply to --splitting: its drifts and kicks leave the "
                          "constraint manifold (compose RATTLE: --composition rattle)");
    if (o.composition != "rattle")
      throw ArgumentError("--constraint",
                          "does not apply to --composition " + o.composition +
                              ": only RATTLE's steps are composed on a constraint manifold "
                              "(--composition rattle)");
    if (c.constraints.empty())
      throw ArgumentError("--constraint",
                          "is required with --composition rattle (with --potential), or a "
                          "constrained --problem: RATTLE steps a constrained system");
    for (const char* other : {"--ld", "--lagrangian", "--hamiltonian", "--symbolic"})
      if (o.has(other))
        throw ArgumentError(other,
                            "does not apply to --composition rattle: the system is H = "
                            "|p|^2/2 + V(q) with --potential and the constraints");
    verify::CompositionSpec spec;
    check_coefficients(o, spec);
    return run_constrained_composition(
        c, std::move(spec),
        o.problem.empty() ? "--potential" : "the test problem " + o.problem + ", typed");
  }
  if (!o.splitting.empty() && !o.potential.empty()) {
    // A splitting on H = |p|^2/2 + V typed: its equivalent composition of symplectic Euler,
    // stepped as the composition of a typed L_d: symplectic Euler's own discrete Lagrangian
    // (drift, then kick) and its adjoint -L_d(q1, q0, -h) (kick, then drift).
    if (!o.problem.empty())
      throw ArgumentError("--potential",
                          "gives the system; --problem names a test problem: give one of them");
    verify::CompositionSpec spec = verify::splitting_spec("--splitting", o.splitting);
    check_expected(o, spec);
    // A potential V(q, t): the drifts advance the time, the kicks read it (the extended
    // Hamiltonian's split, T + p_t and V). The stage L_d then has no part in the study (the
    // variational order is not measured for a time-dependent system): its kinetic part only.
    bool timed = false;
    {
      verify::TypedTexts t{"", o.potential, "", "p^2/2 + V(q)", 0};
      t.system_only = true;
      t.allow_time = true;
      timed = verify::TypedDiscreteLagrangian(t).time_dependent();
    }
    return run_composition_ld(o, std::move(spec), timed, verify::splitting_stage_ld(timed));
  }
  if (o.splitting.empty() && o.composition == "ld") {
    if (!o.problem.empty())
      throw ArgumentError("--problem",
                          "does not apply to --composition ld: the system is --potential, "
                          "--lagrangian or --hamiltonian");
    verify::CompositionSpec spec;
    check_coefficients(o, spec);
    // L_d(t, q0, q1, h) on a time-dependent system: each stage starts at the time the stages
    // before it reached (composition_ld_study.cpp)
    return run_composition_ld(o, std::move(spec), true, o.ld);
  }
  // (--ld, --potential, --lagrangian, --hamiltonian and --dim with another base are refused by
  // the route table of verify.cpp.)
  Plan p = check(o);
  if (o.splitting.empty() || !p.spec.typed.empty())
    verify::derive_composition_variational_order(p.spec, p.problem->name, p.symbolic, p.study);
  MapReport rep;
  verify::measure_composition(p.spec, *p.problem, p.q0, p.p0, p.study, rep);
  return rep.finish(o);
}

}  // namespace vibook::cli
