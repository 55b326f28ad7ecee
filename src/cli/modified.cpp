// `vibook modified`: the modified-equation engine on the command line (Vermeeren 2017 §3–5,
// Shen & Sun 2025 §4).
#include <algorithm>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "args.hpp"
#include "cli.hpp"
#include "vibook/modified/command.hpp"
#include "vibook/modified/engine.hpp"
#include "vibook/verify/expression.hpp"

namespace vibook::cli {

namespace {
struct ModifiedOptions {
  std::string method, potential = "generic", what = "equation", format = "text", alpha, ld;
  std::string lagrangian;            // the user's continuous L(q, v), discretized by --method
  std::vector<std::string> params;   // symbolic constants of --ld / --lagrangian / --potential
  std::string dim_text, order_text;  // parsed whole, in base 10 (parse_integer)
  std::string max_seconds_text;
  double max_seconds = 0;
  bool progress = false;
  int dim = 0, order = -1;
  bool cross_check = false, reference = false, dim_given = false, alpha_given = false;
  bool components = false;
  bool method_given = false, potential_given = false, ld_given = false, lagrangian_given = false;
};

int run_modified(ModifiedOptions o) {
  using namespace modified;
  o.order =
      static_cast<int>(std::clamp<long long>(parse_integer("--order", o.order_text), -1, 1000));
  if (o.dim_given)
    o.dim = static_cast<int>(std::clamp<long long>(parse_integer("--dim", o.dim_text), 0, 1000));
  // Either a method of the library (--method, a named --potential) or the user's own discrete
  // Lagrangian typed as in `vibook verify` (--ld, with --potential an expression).
  // Or a method of the library on the user's own continuous Lagrangian (--method with
  // --lagrangian, --potential then an expression too).
  if (o.lagrangian_given && o.ld_given)
    throw ArgumentError("--lagrangian",
                        "is discretized by --method; --ld is a discrete Lagrangian already");
  if (o.ld_given && o.method_given)
    throw ArgumentError("--ld", "give either --method or --ld (your own discrete Lagrangian)");
  if (!o.ld_given && !o.method_given)
    throw ArgumentError("--method", "required (or give your own discrete Lagrangian with --ld)");
  const Method m = o.ld_given ? Method::sv : parse_method(o.method);
  if (o.lagrangian_given && m != Method::sv && m != Method::midpoint && m != Method::se &&
      m != Method::se_adjoint)
    throw ArgumentError("--lagrangian",
                        fmt::format("--method {} splits a potential (φ^[1] + φ^[2]); a "
                                    "Lagrangian is discretized by sv, se, se-adjoint or midpoint",
                                    o.method));
  const bool typed_texts = o.ld_given || o.lagrangian_given;
  if (!o.params.empty() && !typed_texts)
    throw ArgumentError("--param",
                        "names a constant of your own --ld or --lagrangian (the "
                        "library's methods have none)");
  const Potential p = typed_texts ? Potential::generic : parse_potential(o.potential);
  const Format f = parse_format(o.format);
  if (typed_texts && o.alpha_given)
    throw ArgumentError("--alpha", fmt::format("applies to the library's splitting methods, not "
                                               "to {}",
                                               o.ld_given ? "--ld" : "--lagrangian"));
  static const std::set<std::string> whats = {"equation",     "lagrangian", "hamiltonian",
                                              "vector-field", "meshed",     "disc"};
  if (!whats.count(o.what))
    throw ArgumentError("--what", fmt::format("unknown '{}' (equation, lagrangian, hamiltonian, "
                                              "vector-field, meshed, disc)",
                                              o.what));
  if (o.dim_given && (o.dim < 1 || o.dim > 3))
    throw ArgumentError("--dim", fmt::format("{}: give 1, 2 or 3 degrees of freedom", o.dim));
  // The typed discrete Lagrangian is parsed and checked before any work (status 2 naming --ld,
  // --potential or --dim); it must outlive the engine.
  std::optional<verify::TypedDiscreteLagrangian> typed;
  if (o.lagrangian_given) {
    verify::TypedTexts t;
    t.system_only = true;  // no discrete Lagrangian: --method makes it from L
    t.lagrangian = o.lagrangian;
    t.params = o.params;
    if (o.potential_given) t.potential = o.potential;
    t.dim = o.dim_given ? o.dim : 0;
    typed.emplace(t);
    if (typed->dim() > 3)
      throw ArgumentError(
          "--lagrangian",
          fmt::format("{} degrees of freedom: the symbolic engine takes 1 to 3", typed->dim()));
  } else if (o.ld_given) {
    verify::TypedTexts t;
    t.ld = o.ld;
    t.params = o.params;
    // The engine needs only L_d; the intended system matters to `vibook verify` alone. Without
    // --potential, a placeholder system lets an L_d that does not use V through (one that does
    // is refused: "V is used but no --potential was given").
    if (o.potential_given)
      t.potential = o.potential;
    else
      t.lagrangian = "v^2/2";
    t.dim = o.dim_given ? o.dim : 0;
    typed.emplace(t);
    if (typed->dim() > 3)
      throw ArgumentError("--ld", fmt::format("{} degrees of freedom: the symbolic engine takes 1 "
                                              "to 3",
                                              typed->dim()));
  }
  const int dim = typed ? typed->dim() : (o.dim_given ? o.dim : (p == Potential::kepler ? 2 : 1));
  if (o.components && f != Format::latex)
    throw ArgumentError("--components",
                        "applies to --format latex (text and python are always "
                        "written in components)");
  if (o.cross_check && o.what != "equation")
    throw ArgumentError("--cross-check",
                        fmt::format("compares two derivations of the modified equation; it does "
                                    "not apply to --what {}",
                                    o.what));
  std::optional<GiNaC::numeric> alpha;
  if (o.alpha_given) {
    if (m != Method::vi1 && m != Method::vi1_adjoint && m != Method::vi2)
      throw ArgumentError("--alpha", "only the splitting methods vi1, vi1-adjoint, vi2 have α");
    if (p == Potential::generic)
      throw ArgumentError("--alpha",
                          "with a generic potential the pieces are abstract (phi1, phi2)");
    alpha = verify::parse_rational(o.alpha, "--alpha");
    if (*alpha < 0 || *alpha > 1)
      throw ArgumentError("--alpha", fmt::format("{}: the split φ^[1] = αU needs α in [0, 1] (as "
                                                 "vibook run)",
                                                 o.alpha));
  }
  if (o.order < 0 || o.order > max_order)
    throw ArgumentError("--order",
                        fmt::format("{}: supported orders are 0 to {}", o.order, max_order));
  if (!o.max_seconds_text.empty()) {
    o.max_seconds = parse_number("--max-seconds", o.max_seconds_text);
    if (!(o.max_seconds > 0 && o.max_seconds <= 1e7))
      throw ArgumentError("--max-seconds", "must be a positive number of seconds, at most 1e7");
  }
  // Every argument checked: from here on the derivation shows its stage and keeps its limit.
  const Watchdog watchdog("modified", o.max_seconds, o.progress);
  modified::Derivation d;
  d.method = m;
  d.potential = p;
  d.dim = dim;
  d.order = o.order;
  d.what = o.what;
  d.format = f;
  d.alpha = alpha;
  d.cross_check = o.cross_check;
  d.reference = o.reference;
  d.components = o.components;
  d.typed = typed ? &*typed : nullptr;
  d.typed_lagrangian = o.lagrangian_given;
  d.description = o.lagrangian_given ? fmt::format("--method {} on the typed Lagrangian {}",
                                                   o.method, o.lagrangian)
                                     : "typed discrete Lagrangian " + o.ld;
  fmt::print("{}", modified::derive(d));
  return kOk;
}
}  // namespace

std::function<int()> add_modified_command(CLI::App& app) {
  auto o = std::make_shared<ModifiedOptions>();
  auto* c = app.add_subcommand(
      "modified",
      "Derive the modified equation, modified Lagrangian or modified Hamiltonian of a method "
      "(Vermeeren 2017) with the symbolic engine");
  c->add_option("--method", o->method,
                "sv, se (L(x1,v)), se-adjoint (L(x0,v)), midpoint, vi1, vi1-adjoint (Shen & Sun "
                "(3.3)), vi2 ((3.8); the interior node is eliminated); required unless --ld");
  c->add_option("--lagrangian", o->lagrangian,
                "your own continuous Lagrangian L(q, v), discretized by --method (sv, se, "
                "se-adjoint, midpoint), typed as in vibook verify, e.g. '(1+q^2)*v^2/2 - V(q)' "
                "(--potential then an expression)");
  c->add_option("--param", o->params,
                "a symbolic constant of --ld, --lagrangian or --potential (a coupling, an energy "
                "level): it stays a symbol in the result; repeat or separate by commas")
      ->delimiter(',');
  c->add_option("--ld", o->ld,
                "your own discrete Lagrangian L_d(q0, q1, h) instead of --method, typed as in "
                "vibook verify, e.g. 'h*((q1-q0)^2/(2*h^2) - (V(q0)+V(q1))/2)'");
  c->add_option(
      "--potential", o->potential,
      "generic (derivatives U, U_1, U_11, … as symbols), kepler (2-D), pendulum, "
      "harmonic (default generic); with --ld or --lagrangian: V as an expression in x, y, z (or q, "
      "q[1], …), as in vibook verify");
  c->add_option("--dim", o->dim_text,
                "degrees of freedom of a generic potential, 1 to 3 (default 1; with --ld or "
                "--lagrangian: from "
                "the expressions)");
  c->add_option("--order", o->order_text,
                fmt::format("highest power of h, 0 to {}", modified::max_order))
      ->required();
  c->add_option("--what", o->what,
                "equation (default), lagrangian (L_mod), hamiltonian (H_mod), vector-field (the "
                "first-order system xdot = dH_mod/dp, pdot = -dH_mod/dx, p = dL_mod/dv), meshed "
                "(L_mesh), disc (L_disc([x],h))");
  c->add_option("--format", o->format, "text (default), latex, python (SymPy)");
  c->add_option("--alpha", o->alpha,
                "vi1, vi1-adjoint, vi2 with a concrete potential: the split φ^[1] = αU (default: "
                "symbolic α)");
  c->add_option("--max-seconds", o->max_seconds_text,
                "stop with status 3, naming the stage reached, if the derivation takes longer");
  c->add_flag("--progress", o->progress,
              "show the stage on standard error also when it is not a terminal (every 5 s)");
  c->add_flag("--reference", o->reference,
              "derive on the engine's slow reference path (GiNaC diff symbol by symbol, no early "
              "truncation), to check the fast path's output against");
  c->add_flag("--components", o->components,
              "latex: write a 2- or 3-dimensional abstract potential's result component by "
              "component; by default it is written in vector notation as Shen & Sun write "
              "theirs (∇φ·ẋ, |∇φ|², φ_xx⟨ẋ,ẋ⟩, φ_xx∇φ, …, the rest in components)");
  c->add_flag("--cross-check", o->cross_check,
              "equation: also derive it from the discrete Euler–Lagrange equation (Vermeeren "
              "§3.2) and require term-by-term agreement");
  return [o, c] {
    o->dim_given = c->count("--dim") > 0;
    o->alpha_given = c->count("--alpha") > 0;
    o->method_given = c->count("--method") > 0;
    o->potential_given = c->count("--potential") > 0;
    o->ld_given = c->count("--ld") > 0;
    o->lagrangian_given = c->count("--lagrangian") > 0;
    return run_modified(*o);
  };
}

}  // namespace vibook::cli
