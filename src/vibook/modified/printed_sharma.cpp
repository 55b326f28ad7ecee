// Sharma et al. 2022, §4.3–4.4, read from the paper's LaTeX and compared with the engine: the
// meshed Lagrangian's definition (46) and the worked example of a 1-DOF mechanical system
// in the time-transformed setting, (56)–(66). The degrees of freedom are q and t as functions
// of the fictitious time a; derivatives in a are primes; only q'' is solved for (§4.3).
#include <random>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "vibook/avi/avi.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/mechanics/extended.hpp"
#include "vibook/modified/ginac_eigen.hpp"
#include "vibook/modified/printed_checks.hpp"

namespace vibook::checks::printed_detail {

namespace {

using GiNaC::numeric;
using modified::Engine;
using modified::JetSpace;

// One component of the engine's vector series.
Target column(const std::vector<std::vector<ex>>& f, std::size_t i, int through) {
  std::vector<ex> c;
  for (const auto& fk : f) c.push_back(fk.at(i));
  return Target::scalar_series(c, through);
}

}  // namespace

std::vector<claims::ClaimResult> sharma_prints(std::vector<claims::ClaimResult>& errata) {
  auto J = std::make_shared<JetSpace>(2);  // dof 0: q, dof 1: t
  const int Vf = J->add_family("V", "V", {0});
  const GiNaC::symbol m("m");
  auto L = [&](const auto& q, const auto& v) -> ex {
    return m * v(0) * v(0) / 2 - modified::abstract_call(Vf, {q(0)});
  };
  const auto Lext = extended_midpoint_dl(L);  // (25)/(57): the template EpAVI steps with
  auto dl = [&](const auto& a, const auto& b, const auto&) -> ex {
    const Vec<ex, 1> q0(a(0)), q1(b(0));
    return Lext(a(1), q0, b(1), q1);
  };
  modified::SymbolicDL sdl = modified::symbolic_dl<2>(dl, J, "Sharma (57)");
  sdl.solve_for = {0};
  Engine E(sdl, 3);
  const GiNaC::symbol h = J->h();

  // The notation of §4.4: q and t of a, primes, Δa, V with V_q, V_{qq}, …, m; the engine's
  // \bar{\mathfrak{L}}_{disc}, _{mesh}, _{mod}; d/dt = (1/t') d/da.
  JetNotation n(J, {0});
  n.curve("q", {0}).curve("t", {1}).primes_for_curves().step_name("Delta a").time_name("a");
  n.time_alias("t", 1 / J->x(1, 1));
  n.field("V", "", n.abstract_field({{Vf, 1}}), "q");
  n.constant("m", Value::scalar(m)).parameter(m);
  // [\bar{q}]: the jets of (q, t), the argument of the \mathfrak{L}'s (which ignore it)
  const Value qbar = Value::vector({J->x(0, 0), J->x(0, 1)});
  n.constant("\\bar{q}", qbar).constant("\\bar{\\mathbf{q}}", qbar);
  Engine* engine = &E;
  n.callable("mathfrak{L}",
             [engine, h](const printed::Atom& a, const std::vector<Value>&) -> Value {
               const std::string sub = a.sub_text();
               if (sub == "disc") return Value::scalar(series_sum(engine->l_disc(), h));
               if (sub == "mesh") return Value::scalar(series_sum(engine->l_mesh(), h));
               if (sub == "mod" || sub == "mod,3")
                 return Value::scalar(series_sum(engine->l_mod(), h, 3));
               throw printed::ReadError("no \\mathfrak{L}_{" + sub + "}");
             });
  Compared cmp{kCheck, {}};
  const std::string eng = "the engine, on EpAVI's discrete Lagrangian (25) in (q, t), ";

  // (46): the meshed Lagrangian's definition, in the setting of the example, through the
  // Δa⁴ term it shows (the engine to order 5 for its meshed Lagrangian). Both derivatives are in
  // t where the mesh is uniform in a: the natural correction reads both as d/da (one slip made
  // twice), stated here and compared like the print; the search's single edit would fix only
  // the first.
  {
    Engine E5(sdl, 5);
    JetNotation n5 = n;
    Engine* e5 = &E5;
    n5.callable("mathfrak{L}", [e5, h](const printed::Atom& a, const std::vector<Value>&) -> Value {
      const std::string sub = a.sub_text();
      if (sub == "disc") return Value::scalar(series_sum(e5->l_disc(), h));
      if (sub == "mesh") return Value::scalar(series_sum(e5->l_mesh(), h));
      throw printed::ReadError("no \\mathfrak{L}_{" + sub + "}");
    });
    printed::Spec sp;
    sp.paper = Paper::S;
    sp.quote =
        R"(\bar{\mathfrak{L}}_{\text{mesh}}([\bar{\mathbf{q}}], \Delta a) := \bar{\mathfrak{L}}_{\text{disc}}([\bar{\mathbf{q}}], \Delta a) - \frac{\Delta a^2}{24} \frac{d^2}{dt^2} \bar{\mathfrak{L}}_{\text{disc}}([\bar{\mathbf{q}}], \Delta a) + \frac{7\Delta a^4}{5760} \frac{d^4}{dt^4} \bar{\mathfrak{L}}_{\text{disc}}([\bar{\mathbf{q}}], \Delta a) + \dots)";
    sp.part = "the definition of the meshed Lagrangian (46), in the example's setting";
    sp.against = eng + "meshed Lagrangian (the Euler–Maclaurin sum over the uniform mesh in a)";
    sp.members = {1};
    sp.proposed =
        R"(\bar{\mathfrak{L}}_{\text{mesh}}([\bar{\mathbf{q}}], \Delta a) := \bar{\mathfrak{L}}_{\text{disc}}([\bar{\mathbf{q}}], \Delta a) - \frac{\Delta a^2}{24} \frac{d^2}{da^2} \bar{\mathfrak{L}}_{\text{disc}}([\bar{\mathbf{q}}], \Delta a) + \frac{7\Delta a^4}{5760} \frac{d^4}{da^4} \bar{\mathfrak{L}}_{\text{disc}}([\bar{\mathbf{q}}], \Delta a) + \dots)";
    sp.proposed_edit =
        "\\(d/dt\\) read as \\(d/da\\) in both derivatives, \\(\\frac{d^2}{da^2}\\) "
        "and \\(\\frac{d^4}{da^4}\\) (the mesh is uniform in a)";
    sp.prefer_proposed = true;
    cmp.spec(std::move(sp), {{&n5, Target::scalar_series(E5.l_mesh(), 5), ""}});
  }
  // (56): the transformed Lagrangian.
  {
    const ex q1 = J->x(1, 0), t1 = J->x(1, 1);
    const ex V = printed::field_tensor(n.abstract_field({{Vf, 1}}), 0, n).c[0];
    JetNotation nl = n;
    nl.callable("L", [&](const printed::Atom&, const std::vector<Value>& a) -> Value {
      if (a.size() != 2) throw printed::IllFormed("L(q, q̇)");
      const ex v = a[1].as_scalar("a velocity");
      const ex q = a[0].as_scalar("a position");
      return Value::scalar(m * v * v / 2 - n.abstract_field({{Vf, 1}}).subs(n.point()[0] == q));
    });
    cmp(Paper::S,
        R"(= t'(a)L\left(q(a), \frac{q'(a)}{t'(a)}\right) = t'(a)\left(\frac{1}{2}m\left(\frac{q'(a)}{t'(a)}\right)^2 - V(q(a))\right).)",
        "the transformed Lagrangian (56)", "t'·L(q, q'/t') with L = ½mq̇² − V(q)", nl,
        Target::exactly(t1 * (m / 2 * GiNaC::pow(q1 / t1, 2) - V)), {0, 1});
  }
  // (57): the discretized Lagrangian, in discrete variables, against EpAVI's template (25).
  {
    const GiNaC::symbol qk("q_k"), qk1("q_k1"), tk("t_k"), tk1("t_k1");
    JetNotation nd(J, {0});
    nd.anywhere().step_name("Delta a");
    nd.field("V", "", nd.abstract_field({{Vf, 1}}), "q");
    nd.constant("m", Value::scalar(m));
    nd.discrete("q", 'k', [&](int off, const printed::Atom&, bool&) {
      return Value::scalar(off == 0 ? ex(qk) : ex(qk1));
    });
    nd.discrete("t", 'k', [&](int off, const printed::Atom&, bool&) {
      return Value::scalar(off == 0 ? ex(tk) : ex(tk1));
    });
    const ex target =
        modified::exact_rationals(Lext(ex(tk), Vec<ex, 1>(qk), ex(tk1), Vec<ex, 1>(qk1))) / h;
    cmp(Paper::S,
        R"(= \frac{t_{k+1} - t_k}{\Delta a} \left( \frac{1}{2}m \left( \frac{q_{k+1} - q_k}{t_{k+1} - t_k} \right)^2 - V\left(\frac{q_{k+1} + q_k}{2}\right) \right).)",
        "the discretized Lagrangian (57)",
        "the library's extended_midpoint_dl (25), the template EpAVI steps with, divided by Δa", nd,
        Target::exactly(target));
  }
  // The inline expansions before (58), in the sentence "Using the power series expansions for
  // …": q_{k±1}(a) and t_{k±1}(a) about the step's midpoint a (their Δa/2 and Δa²/8 say so, and
  // (58)'s first form is built on them: (q_{k+1} − q_k)/Δa = q' + Δa²/24 q''' + …), i.e. the
  // Taylor series of q(a ± Δa/2), each sign, through Δa³. Their left-hand sides name q_{k+1}
  // and q_k loosely (k ± 1 for both ends of one step); only the right-hand sides are compared.
  for (const int curve : {0, 1}) {
    std::vector<JetNotation> ns(2, n);
    std::vector<Case> cases;
    for (int s = 0; s < 2; ++s) ns[s].pm_sign(s == 0 ? 1 : -1).discrete_index('k');
    for (int s = 0; s < 2; ++s)
      cases.push_back(
          {&ns[s],
           Target::scalar_series(shifted_taylor(*J, curve, numeric(s == 0 ? 1 : -1, 2), 4), 3),
           s == 0 ? "the upper sign" : "the lower sign"});
    const std::string c = curve == 0 ? "q" : "t";
    auto quote = [&c](const std::string& third) {
      return c + R"(_{k\pm 1}(a) = )" + c + R"((a) \pm \frac{\Delta a}{2})" + c +
             R"('(a) + \frac{\Delta a^2}{8})" + c + R"(''(a) \pm \frac{\Delta a^3}{)" + third +
             "}" + c + R"('''(a) + O(\Delta a^4))";
    };
    Spec sp;
    sp.paper = Paper::S;
    sp.quote = quote("24");
    sp.members = {1};
    sp.part = "the inline expansion of " + c + " about the step's midpoint before (58), each sign";
    sp.against = "the Taylor series of " + c + "(a ± Δa/2) through Δa³";
    sp.proposed = quote("48");
    sp.prefer_proposed = true;
    sp.proposed_edit =
        "Δa³/24 read as Δa³/48: (Δa/2)³/3! (the expansion is about the midpoint, "
        "as its Δa/2 and Δa²/8 are)";
    cmp.spec(sp, cases);
  }
  cmp(Paper::S,
      R"(\bar{\mathfrak{L}}_{disc}([\bar{q}], \Delta a) &= \left( t' + \frac{\Delta a^2}{24}t''' + \dots \right) \left( \frac{1}{2}m \left( \frac{q' + \frac{\Delta a^2}{24}q''' + \dots}{t' + \frac{\Delta a^2}{24}t''' + \dots} \right)^2 - V\left(q + \frac{\Delta a^2}{8}q'' + \dots\right) \right))",
      "the expansion (58), first form (through Δa², where its dots begin)", eng + "L_disc", n,
      Target::scalar_series(E.l_disc(), 2), {1});
  cmp(Paper::S,
      R"(&= t' \left( \frac{1}{2}m \left( \frac{q'}{t'} \right)^2 - V \right) + \frac{\Delta a^2}{24} \left( \frac{mq'q'''}{t'} - \frac{m(q')^2t'''}{2(t')^2} - 3q''t'V_q - t'''V \right) + O(\Delta a^4),)",
      "the expansion (58), result", eng + "L_disc", n, Target::scalar_series(E.l_disc(), 3));
  cmp(Paper::S,
      R"(\bar{\mathfrak{L}}_{mesh}([\bar{q}], \Delta a) &= \bar{\mathfrak{L}}_{disc}([\bar{q}], \Delta a) - \frac{\Delta a^2}{24} \frac{d^2}{da^2} \bar{\mathfrak{L}}_{disc}([\bar{q}], \Delta a) + O(\Delta a^4) \\ &= t' \left( \frac{1}{2}m \left( \frac{q'}{t'} \right)^2 - V \right) + \frac{\Delta a^2}{24} \left( -\frac{m(q'')^2}{t'} + \frac{2mq'q''t''}{(t')^2} - \frac{m(q')^2(t'')^2}{(t')^3} \right) \\ &\quad + \frac{\Delta a^2}{24} (2q't''V_q + (q')^2t'V_{qq} - 2q''t'V_q) + O(\Delta a^4).)",
      "the meshed Lagrangian (59), from its definition and written out", eng + "meshed Lagrangian",
      n, Target::scalar_series(E.l_mesh(), 3), {1, 2});
  const auto el = E.euler_lagrange_two_term(E.l_mesh());
  cmp(Paper::S,
      R"(O(\Delta a^4) &= \frac{\partial \bar{\mathfrak{L}}_{mesh}}{\partial q} - \frac{d}{da} \left( \frac{\partial \bar{\mathfrak{L}}_{mesh}}{\partial q'} \right) \\ &= -\frac{mq''}{t'} + \frac{mq't''}{(t')^2} - t'V_q + \frac{\Delta a^2}{24} \left( -(q'')^2t'V_{qqq} - 2t'''V_q - 2q't''V_{qq} - 4q''t'V_{qq} \right) \\ &\quad - \frac{\Delta a^2}{24} \left( \frac{2mq'''t''}{(t')^2} + \frac{2mq''t'''}{(t')^2} - \frac{6mq''(t'')^2}{(t')^3} - \frac{4mq't''t'''}{(t')^3} + \frac{6mq'(t'')^3}{(t')^4} \right),)",
      "the modified Euler–Lagrange equation in q (60), its definition and its value",
      eng + "∂L_mesh/∂q − d/da ∂L_mesh/∂q'", n, column(el, 0, 3), {1, 2});
  cmp(Paper::S,
      R"(O(\Delta a^4) &= \frac{\partial \bar{\mathfrak{L}}_{mesh}}{\partial t} - \frac{d}{da} \left( \frac{\partial \bar{\mathfrak{L}}_{mesh}}{\partial t'} \right) \\ &= \left( \frac{q'}{t'} \right) \left( -\frac{mq''}{t'} + \frac{mq't''}{(t')^2} - t'V_q \right) + O(\Delta a^2),)",
      "the modified energy equation (61), its definition and its value",
      eng + "∂L_mesh/∂t − d/da ∂L_mesh/∂t'", n, column(el, 1, 1), {1, 2});
  // (62): the same equation with the leading-order q'' put into the Δa² terms: compared on
  // solutions of the modified equation (it holds there, and only there).
  {
    const auto& f = E.modified_equation();
    Target t0 = Target::exactly(ex(0));
    t0.reduce = on_shell(*J, {0}, f, 3);
    printed::Spec sp;
    sp.paper = Paper::S;
    sp.quote =
        R"(&= -\frac{mq''}{t'} + \frac{mq't''}{(t')^2} - t'V_q + \frac{\Delta a^2}{24} \left( \frac{4(t')^3 V_q V_{qq}}{m} - 4q't''V_{qq} - (q')^2 t'V_{qqq} \right) + O(\Delta a^4), \tag{62})";
    sp.part = "(62), its result, on solutions of the modified equation (q'' by (63) through Δa³)";
    sp.against = "zero: the equation holds on solutions of the engine's modified equation";
    cmp.spec(sp, {{&n, t0, ""}});
  }
  cmp(Paper::S,
      R"(q'' = \frac{q't''}{t'} - \frac{(t')^2 V_q}{m} + \frac{\Delta a^2}{24m} \left( \frac{4(t')^4 V_q V_{qq}}{m} - 4q't't''V_{qq} - (q')^2 (t')^2 V_{qqq} \right) + O(\Delta a^4). \tag{63})",
      "the modified equation (63)", eng + "modified equation, solved for q''", n,
      column(E.modified_equation(), 0, 3));
  cmp(Paper::S,
      R"(&= t' \left( \frac{1}{2} m \left( \frac{q'}{t'} \right)^2 - V \right) + \frac{\Delta a^2}{24} \left( \frac{t'^3 (V_q)^2}{m} + q'^2 t'V_{qq} \right) + O(\Delta a^4). \tag{64})",
      "the modified Lagrangian (64)", eng + "modified Lagrangian", n,
      Target::scalar_series(E.l_mod(), 3));
  {
    std::vector<ex> lmod3(E.l_mod().begin(), E.l_mod().end());
    const auto el3 = E.euler_lagrange(lmod3);
    cmp(Paper::S,
        R"(&= -t'V_q + \frac{\Delta a^2}{24} \left( \frac{2t'^3 V_q V_{qq}}{m} + V_{qqq} q'^2 t' \right) - \frac{d}{da} \left( \frac{mq'}{t'} + \frac{\Delta a^2}{24} (2V_{qq} q' t') \right) \\
&= -\frac{mq''}{t'} + \frac{mq't''}{(t')^2} - t'V_q + \frac{\Delta a^2}{24} \left( \frac{2t'^3 V_q V_{qq}}{m} - 2q'V_{qq} t'' - V_{qqq} q'^2 t' - 2V'' q' t' \right). \tag{65})",
        "the Euler–Lagrange equation of L_mod,3 (65), both forms",
        eng + "Euler–Lagrange expression of L_mod,3 in q", n, column(el3, 0, 3), {0, 1});
  }
  cmp(Paper::S,
      R"(&= \frac{q't''}{t'} - \frac{(t')^2 V_q}{m} + \frac{\Delta a^2}{24m} \left( \frac{4(t')^4 V_q V_{qq}}{m} - 4q't't''V_{qq} - (q')^2 (t')^2 V_{qqq} \right) + O(\Delta a^4), \tag{66})",
      "(65) solved for q'' (66), result", eng + "modified equation, solved for q''", n,
      column(E.modified_equation(), 0, 3));

  claims::ClaimResult r;
  r.id = "S-EQ58";
  r.source = kCheck;
  r.status = claims::Status::reproduced;
  r.note =
      "Midpoint rule in the time-transformed setting, 1 DOF, V generic, m symbolic; the discrete "
      "Lagrangian is EpAVI's template (25) on (q, t); only q'' is solved for (t', t'', … free). "
      "The definition (46) in this setting, the inline expansions of q and t that lead to (58), "
      "and (56)–(66), read from the paper and compared with the engine.";
  // the two inline expansions carry one slip, the same coefficient in both: one erratum
  printed::conclude(r, cmp.take(), errata, {{"I401.2", "S-ERR-I401"}});
  add_evidence(
      errata, "S-ERR-I401",
      " Independently, SymPy's Taylor series of q(a ± Δa/2) has Δa³/48, and only that "
      "coefficient gives (58)'s q' + Δa²/24 q''' (tests/cli/s_i401_sympy.py, a test of its "
      "own). The left-hand sides name the step's two ends q_{k+1}, q_k as q_{k±1}; only the "
      "right-hand sides are compared.");
  return {r};
}

// ---- Sharma §2.2 (13)–(18), §3.2 (24)–(27), §4.2 (39)–(41): displays in discrete variables --
// The printed side is read from the paper; ours is the library's own template (the extended
// midpoint L_d of (25) over the Kepler Lagrangian, AVI's monitor functions) evaluated on GiNaC
// symbols, and for (13)–(18) vibook's convention p_{k+1} = D4 L_d, E_{k+1} = −D3 L_d
// (extended.hpp), the one its time-marching step solves.
std::vector<claims::FormulaComparison> sharma_discrete_prints(
    const std::string& group, const std::string& check,
    std::vector<std::pair<std::string, double>>* second_route) {
  using V2 = Vec<ex, 2>;
  auto J = std::make_shared<JetSpace>(2);
  Compared cmp{check, {}};
  const auto L = mechanical_lagrangian(Kepler{});
  const auto Ld = extended_midpoint_dl(L);
  // t_{k−1}, t_k, t_{k+1}; q_{k+o} and its components q^i_{k+o}; p_k, E_k
  const std::vector<GiNaC::symbol> t = {GiNaC::symbol("t_km1", "t_{k-1}"),
                                        GiNaC::symbol("t_k", "t_{k}"),
                                        GiNaC::symbol("t_kp1", "t_{k+1}")};
  std::vector<std::vector<GiNaC::symbol>> q(3);
  const char* const sub[] = {"k-1", "k", "k+1"};
  for (int o = 0; o < 3; ++o)
    for (int i = 0; i < 2; ++i)
      q[o].emplace_back(fmt::format("q{}_{}", i + 1, o - 1),
                        fmt::format("{{q^{{{}}}_{{{}}}}}", i + 1, sub[o]));
  const std::vector<std::vector<GiNaC::symbol>> p = {
      {GiNaC::symbol("p1_k"), GiNaC::symbol("p2_k")},
      {GiNaC::symbol("p1_kp1"), GiNaC::symbol("p2_kp1")}};
  const std::vector<GiNaC::symbol> E = {GiNaC::symbol("E_k"), GiNaC::symbol("E_kp1")};
  auto qv = [&](int o) { return V2(ex(q[o + 1][0]), ex(q[o + 1][1])); };
  auto Ld_at = [&](int o) {
    return modified::exact_rationals(Ld(ex(t[o + 1]), qv(o), ex(t[o + 2]), qv(o + 1)));
  };
  auto in_range = [](int o, int lo) {
    if (o < lo || o > 1) throw printed::ReadError(fmt::format("no step offset {} here", o));
  };

  JetNotation n(J);
  n.anywhere();
  n.discrete("t", 'k', [&](int o, const printed::Atom&, bool&) {
    in_range(o, -1);
    return Value::scalar(t[o + 1]);
  });
  n.discrete("q", 'k', [&](int o, const printed::Atom& a, bool& consumed) -> Value {
    in_range(o, -1);
    if (a.sup) {  // q_k^1: one component
      consumed = true;
      const std::string c = a.sup_text();
      if (c != "1" && c != "2") throw printed::ReadError("q_k^" + c + ": no such component");
      return Value::scalar(q[o + 1][c == "1" ? 0 : 1]);
    }
    return Value::vector({q[o + 1][0], q[o + 1][1]});
  });
  n.discrete("p", 'k', [&](int o, const printed::Atom& a, bool& consumed) -> Value {
    in_range(o, 0);
    if (a.sup) {
      consumed = true;
      return Value::scalar(p[o][a.sup_text() == "1" ? 0 : 1]);
    }
    return Value::vector({p[o][0], p[o][1]});
  });
  n.discrete("E", 'k', [&](int o, const printed::Atom&, bool&) -> Value {
    in_range(o, 0);
    return Value::scalar(E[o]);
  });
  n.slot_derivative("D");
  // L(q, v) is the Kepler Lagrangian ½|v|² + 1/|q| (the Legendre transform of (24)); L_d is
  // the library's extended midpoint L_d (25) over it.
  n.callable("L", [&](const printed::Atom& a, const std::vector<Value>& args) -> Value {
    auto vec = [](const Value& v) {
      if (v.tuple || v.rank != 1 || v.c.size() != 2)
        throw printed::IllFormed("L takes vectors in the plane");
      return V2(v.c[0], v.c[1]);
    };
    if (a.sub_text() == "d") {
      if (args.empty()) return Value::scalar(Ld_at(0));  // "L_d =": at (t_k, q_k, t_{k+1}, q_{k+1})
      if (args.size() != 4)
        throw printed::IllFormed("L_d(t_0, q_0, t_1, q_1) takes four arguments");
      return Value::scalar(modified::exact_rationals(Ld(
          args[0].as_scalar("a time"), vec(args[1]), args[2].as_scalar("a time"), vec(args[3]))));
    }
    if (!a.sub && args.size() == 2)
      return Value::scalar(modified::exact_rationals(L(vec(args[0]), vec(args[1]))));
    throw printed::ReadError("no L" + (a.sub ? "_" + a.sub_text() : std::string()) +
                             " of this kind");
  });
  auto d_slot = [&](int o, int slot) {  // ∂L_d(k+o, k+o+1)/∂(argument slot), slots 1..4
    const ex f = Ld_at(o);
    if (slot == 1) return std::vector<ex>{f.diff(t[o + 1])};
    if (slot == 3) return std::vector<ex>{f.diff(t[o + 2])};
    const auto& x = q[slot == 2 ? o + 1 : o + 2];
    return std::vector<ex>{f.diff(x[0]), f.diff(x[1])};
  };
  auto neg = [](std::vector<ex> v) {
    for (auto& x : v) x = -x;
    return v;
  };
  const std::string dl = "the library's extended midpoint L_d (25) over the Kepler Lagrangian";

  if (group == "del") {
    const std::string conv = "vibook's time-marching step (extended.hpp) on " + dl +
                             ": p_k = −D2 L_d(k, k+1) = "
                             "D4 L_d(k−1, k) and E_k = D1 L_d(k, k+1) = −D3 L_d(k−1, k)";
    // Our side shown in the step's midpoint, difference and duration (Target::shown_as): a
    // derivative of L_d(k+o, k+o+1) written in q̄ = (q_{k+o} + q_{k+o+1})/2, Δq = q_{k+o+1} −
    // q_{k+o} and Δt = t_{k+o+1} − t_{k+o}, instead of the components of q_{k+o}, q_{k+o+1}
    // multiplied out (|q̄|² as six terms).
    const char* const half[] = {"k-\\frac{1}{2}", "k+\\frac{1}{2}"};
    std::vector<std::vector<GiNaC::symbol>> qb(2), dqs(2);
    std::vector<GiNaC::symbol> dts;
    for (int o = 0; o < 2; ++o) {
      for (int i = 0; i < 2; ++i) {
        qb[o].emplace_back(fmt::format("qbar{}_{}", i + 1, o),
                           fmt::format("{{\\bar{{q}}^{{{}}}_{{{}}}}}", i + 1, half[o]));
        dqs[o].emplace_back(fmt::format("dq{}_{}", i + 1, o),
                            fmt::format("{{\\Delta q^{{{}}}_{{{}}}}}", i + 1, half[o]));
      }
      dts.emplace_back(fmt::format("dt_{}", o), fmt::format("{{\\Delta t_{{{}}}}}", half[o]));
    }
    // step o = −1 (from k−1 to k) or 0 (from k to k+1): into the abbreviations and back
    auto to_short = [&](int o) {
      GiNaC::exmap m;
      for (int i = 0; i < 2; ++i) {
        m[q[o + 1][i]] = qb[o + 1][i] - dqs[o + 1][i] / 2;
        m[q[o + 2][i]] = qb[o + 1][i] + dqs[o + 1][i] / 2;
      }
      m[t[o + 1]] = t[o + 2] - dts[o + 1];
      return m;
    };
    auto back = [&](std::initializer_list<int> steps) {
      GiNaC::exmap m;
      for (int o : steps) {
        for (int i = 0; i < 2; ++i) {
          m[qb[o + 1][i]] = (q[o + 1][i] + q[o + 2][i]) / 2;
          m[dqs[o + 1][i]] = q[o + 2][i] - q[o + 1][i];
        }
        m[dts[o + 1]] = t[o + 2] - t[o + 1];
      }
      return m;
    };
    auto where = [&](std::initializer_list<int> steps) {
      std::vector<std::string> parts;
      for (int o : steps) {
        const std::string a = o < 0 ? "k-1" : "k", b = o < 0 ? "k" : "k+1";
        parts.push_back(fmt::format(
            "\\bar{{\\mathbf{{q}}}}_{{{0}}} = \\tfrac{{1}}{{2}}(\\mathbf{{q}}_{{{1}}} + "
            "\\mathbf{{q}}_{{{2}}}),\\ \\Delta\\mathbf{{q}}_{{{0}}} = \\mathbf{{q}}_{{{2}}} - "
            "\\mathbf{{q}}_{{{1}}},\\ \\Delta t_{{{0}}} = t_{{{2}}} - t_{{{1}}}",
            half[o + 1], a, b));
      }
      return "\\text{with } " + fmt::format("{}", fmt::join(parts, ",\\ "));
    };
    // a derivative of L_d(k+o, k+o+1), shown: the powers' bases multiplied out again, so that
    // |q̄|² reads as two squares
    auto tidy = [](const ex& e) {
      struct Bases : GiNaC::map_function {
        ex operator()(const ex& x) override {
          if (GiNaC::is_a<GiNaC::power>(x))
            return GiNaC::pow(GiNaC::expand(x.op(0).map(*this)), x.op(1));
          return x.map(*this);
        }
      } bases;
      return bases(e);
    };
    auto shown = [&](int o, const std::vector<ex>& d) {
      std::vector<ex> r;
      for (const ex& x : d) r.push_back(tidy(x.subs(to_short(o))));
      return r;
    };
    // (11)–(12): the variation of the discrete action Σ L_d (9) with respect to q_k and t_k.
    std::vector<ex> dq, dt, dq_shown, dt_shown;
    {
      const ex S = Ld_at(-1) + Ld_at(0);
      dq = {S.diff(q[1][0]), S.diff(q[1][1])};
      dt = {S.diff(t[1])};
      for (int i = 0; i < 2; ++i)
        dq_shown.push_back(shown(-1, {Ld_at(-1).diff(q[1][i])})[0] +
                           shown(0, {Ld_at(0).diff(q[1][i])})[0]);
      dt_shown = {shown(-1, {Ld_at(-1).diff(t[1])})[0] + shown(0, {Ld_at(0).diff(t[1])})[0]};
    }
    auto exact_shown = [&](const std::vector<ex>& target, const std::vector<ex>& display,
                           std::initializer_list<int> steps) {
      Target tg = Target::exactly(target);
      tg.shown_as(display, back(steps), where(steps));
      return tg;
    };
    auto one_step = [&](int o, const std::vector<ex>& target) {
      return exact_shown(target, shown(o, target), {o});
    };
    const std::string var = "the derivative of the discrete action Σ L_d (9), with " + dl + ", ";
    cmp(Paper::S,
        R"(\mathbf{D}_4 L_d(t_{k-1}, \mathbf{q}_{k-1}, t_k, \mathbf{q}_k) + \mathbf{D}_2 L_d(t_k, \mathbf{q}_k, t_{k+1}, \mathbf{q}_{k+1}) = \mathbf{0}, \quad (11))",
        "the discrete Euler–Lagrange equation in q (11), its left-hand side",
        var + "with respect to q_k", n, exact_shown(dq, dq_shown, {-1, 0}), {0});
    cmp(Paper::S,
        R"(\mathbf{D}_3 L_d(t_{k-1}, \mathbf{q}_{k-1}, t_k, \mathbf{q}_k) + \mathbf{D}_1 L_d(t_k, \mathbf{q}_k, t_{k+1}, \mathbf{q}_{k+1}) = 0. \quad (12))",
        "the discrete energy equation (12), its left-hand side", var + "with respect to t_k", n,
        exact_shown(dt, dt_shown, {-1, 0}), {0});
    cmp(Paper::S,
        R"(\mathbf{p}_k = \mathbf{D}_4 L_d(t_{k-1}, \mathbf{q}_{k-1}, t_k, \mathbf{q}_k). \quad (13))",
        "the discrete momentum (13)", conv, n, one_step(-1, d_slot(-1, 4)), {1});
    cmp(Paper::S,
        R"(E_k = \mathbf{D}_3 L_d(t_{k-1}, \mathbf{q}_{k-1}, t_k, \mathbf{q}_k). \quad (14))",
        "the discrete energy (14)", conv, n, one_step(-1, neg(d_slot(-1, 3))), {1});
    cmp(Paper::S,
        R"(-\mathbf{D}_2 L_d(t_k, \mathbf{q}_k, t_{k+1}, \mathbf{q}_{k+1}) = \mathbf{p}_k, \quad (15))",
        "the momentum equation (15)", conv, n, one_step(0, neg(d_slot(0, 2))), {0});
    cmp(Paper::S,
        R"(\mathbf{D}_1 L_d(t_k, \mathbf{q}_k, t_{k+1}, \mathbf{q}_{k+1}) = E_k, \quad (16))",
        "the energy equation (16)", conv, n, one_step(0, d_slot(0, 1)), {0});
    cmp(Paper::S,
        R"(\mathbf{p}_{k+1} = \mathbf{D}_4 L_d(t_k, \mathbf{q}_k, t_{k+1}, \mathbf{q}_{k+1}), \quad (17))",
        "the momentum update (17)", conv, n, one_step(0, d_slot(0, 4)), {1});
    cmp(Paper::S,
        R"(E_{k+1} = -\mathbf{D}_3 L_d(t_k, \mathbf{q}_k, t_{k+1}, \mathbf{q}_{k+1}). \quad (18))",
        "the energy update (18)", conv, n, one_step(0, neg(d_slot(0, 3))), {1});
  } else if (group == "eq39") {
    const V2 qs(J->x(0, 0), J->x(0, 1));
    {
      // (24): H(q, p) = ½|p|² + U(q) with the library's Kepler potential.
      const V2 pv{ex(p[0][0]), ex(p[0][1])};
      JetNotation nh(J);
      nh.constant("q^{1}", Value::scalar(qs(0))).constant("q^{2}", Value::scalar(qs(1)));
      nh.constant("p^{1}", Value::scalar(pv(0))).constant("p^{2}", Value::scalar(pv(1)));
      nh.constant("q^1", Value::scalar(qs(0))).constant("q^2", Value::scalar(qs(1)));
      nh.constant("p^1", Value::scalar(pv(0))).constant("p^2", Value::scalar(pv(1)));
      const ex H =
          modified::exact_rationals(constant<ex>(0.5) * squared_norm(pv) + Kepler{}.potential(qs));
      cmp(Paper::S,
          R"(= \frac{(p^1)^2 + (p^2)^2}{2} - \frac{1}{\sqrt{(q^1)^2 + (q^2)^2}}. \quad (24))",
          "the Kepler Hamiltonian (24)", "½|p|² + U(q) with the library's Kepler potential", nh,
          Target::exactly(H));
    }
    cmp(Paper::S,
        R"(L_d = (t_{k+1} - t_k)L\left(\frac{\mathbf{q}_k + \mathbf{q}_{k+1}}{2}, \frac{\mathbf{q}_{k+1} - \mathbf{q}_k}{t_{k+1} - t_k}\right). \quad (25))",
        "the midpoint extended discrete Lagrangian (25)",
        "the library's extended_midpoint_dl over the Kepler Lagrangian, at (t_k, q_k, t_{k+1}, "
        "q_{k+1})",
        n, Target::exactly(Ld_at(0)), {1});
    const std::string mom = "−D2 L_d(t_k, q_k, t_{k+1}, q_{k+1}) (15), of " + dl;
    const auto pk = neg(d_slot(0, 2));
    // (39)-(40): two slips, as a referee names them: the force term's sign, and its
    // denominator, which is 4|q̄|³ of the midpoint q̄ = (q_k + q_{k+1})/2 of (25), printed with
    // the sums q_k + q_{k+1} themselves (8 times too large). The search's smallest edit, the term
    // times -8, merges the two; the check states the natural correction, which is read and
    // compared like the print, and the search runs if it does not agree.
    for (int i : {1, 2}) {
      const std::string m = std::to_string(i);
      printed::Spec sp;
      sp.paper = Paper::S;
      sp.quote =
          i == 1
              ? R"(\left(\frac{q_{k+1}^1 - q_k^1}{t_{k+1} - t_k}\right) - (t_{k+1} - t_k) \left(\frac{q_k^1 + q_{k+1}^1}{4 \left((q_k^1 + q_{k+1}^1)^2 + (q_k^2 + q_{k+1}^2)^2\right)^{\frac{3}{2}}}\right) = p_k^1, \quad (39))"
              : R"(\left(\frac{q_{k+1}^2 - q_k^2}{t_{k+1} - t_k}\right) - (t_{k+1} - t_k) \left(\frac{q_k^2 + q_{k+1}^2}{4 \left((q_k^1 + q_{k+1}^1)^2 + (q_k^2 + q_{k+1}^2)^2\right)^{\frac{3}{2}}}\right) = p_k^2, \quad (40))";
      sp.part = "the Kepler midpoint momentum equation (" + std::string(i == 1 ? "39" : "40") +
                "), its left-hand side";
      sp.against = mom + (i == 1 ? ", first component" : ", second component");
      sp.members = {0};
      sp.proposed = "\\left(\\frac{q_{k+1}^" + m + " - q_k^" + m +
                    "}{t_{k+1} - t_k}\\right) + (t_{k+1} - t_k) \\left(\\frac{q_k^" + m +
                    " + q_{k+1}^" + m +
                    "}{4 \\left(\\left(\\frac{q_k^1 + q_{k+1}^1}{2}\\right)^2 + "
                    "\\left(\\frac{q_k^2 + q_{k+1}^2}{2}\\right)^2\\right)^{\\frac{3}{2}}}"
                    "\\right) = p_k^" +
                    m + ", \\quad (" + (i == 1 ? "39" : "40") + ")";
      sp.proposed_edit =
          "two slips: the sign of the force term reversed, and in its denominator the sums "
          "\\(q_k^j + q_{k+1}^j\\) read as the midpoint's coordinates "
          "\\(\\frac{q_k^j + q_{k+1}^j}{2}\\) (4|q̄|³ of the midpoint q̄ of (25), printed 8 "
          "times too large)";
      sp.prefer_proposed = true;
      cmp.spec(std::move(sp), {{&n, Target::exactly(pk[static_cast<std::size_t>(i - 1)]), ""}});
    }
    cmp(Paper::S,
        R"(\frac{1}{2} \left(\frac{q_{k+1}^1 - q_k^1}{t_{k+1} - t_k}\right)^2 + \frac{1}{2} \left(\frac{q_{k+1}^2 - q_k^2}{t_{k+1} - t_k}\right)^2 - \frac{2}{\sqrt{(q_k^1 + q_{k+1}^1)^2 + (q_k^2 + q_{k+1}^2)^2}} = E_k. \quad (41))",
        "the Kepler midpoint energy equation (41), its left-hand side",
        "D1 L_d(t_k, q_k, t_{k+1}, q_{k+1}) (16), of " + dl, n, Target::exactly(d_slot(0, 1)), {0});
    if (second_route) {
      // The second route: the display as the comparison left it, read again and evaluated in
      // binary64, against the AutoDiff derivatives of the integrator's own L_d in double.
      auto vi =
          make_extended_del_integrator<2>(extended_midpoint_dl(mechanical_lagrangian(Kepler{})));
      std::mt19937_64 rng(20220539);
      std::uniform_real_distribution<double> U(-1.5, 1.5), H(1e-3, 0.1);
      struct Point {
        double t0, t1;
        Vec<double, 2> q0, q1;
      };
      std::vector<Point> pts;
      for (int k = 0; k < 1000; ++k) {
        Point P;
        // (Drawn one by one, the second component first: argument evaluation order is
        // unspecified, GCC and clang differ, and this is the order the book's numbers were
        // first drawn in.)
        const double y0 = U(rng), x0 = U(rng);
        P.q0 = Vec<double, 2>(x0, y0);
        const double dy = 0.1 * U(rng), dx = 0.1 * U(rng);
        P.q1 = P.q0 + Vec<double, 2>(dx, dy);
        P.t0 = U(rng);
        P.t1 = P.t0 + H(rng);
        pts.push_back(P);
      }
      for (const auto& c : cmp.list) {
        if (c.display != "(39)" && c.display != "(40)" && c.display != "(41)") continue;
        const std::string text = c.corrected.empty() ? c.quote : c.corrected;
        const ex e = printed::read(text, n).members.at(0).as_scalar("the left-hand side");
        double dev = 0;
        for (const auto& P : pts) {
          GiNaC::exmap at{{t[1], P.t0},       {t[2], P.t1},       {q[1][0], P.q0(0)},
                          {q[1][1], P.q0(1)}, {q[2][0], P.q1(0)}, {q[2][1], P.q1(1)}};
          const double mine = GiNaC::ex_to<numeric>(GiNaC::evalf(e.subs(at))).to_double();
          const auto d = vi.derivatives(P.t0, P.q0, P.t1, P.q1);
          const double ref = c.display == "(41)" ? d.D1(0) : -d.D1(c.display == "(39)" ? 1 : 2);
          const double scale = c.display == "(41)" ? std::max(std::abs(ref), 1.0)
                                                   : d.D1.tail<2>().lpNorm<Eigen::Infinity>();
          dev = std::max(dev, std::abs(mine - ref) / scale);
        }
        second_route->push_back(
            {fmt::format("max_rel_dev_{}_{}_vs_autodiff",
                         c.corrected.empty() ? "printed" : "corrected", c.display.substr(1, 2)),
             dev});
      }
    }
  } else if (group == "monitors") {
    // (26), (27): g_1 and g_2 as AVI evaluates them, M = I, at the energy H_0 = −1/2.
    const V2 qs(J->x(0, 0), J->x(0, 1));
    const double H0 = -0.5;
    JetNotation nm(J);
    const V2 y(nm.point()[0], nm.point()[1]);  // the field's own variables
    nm.field("V", "", modified::exact_rationals(Kepler{}.potential(y)));
    nm.constant("\\mathbf{q}", Value::vector({qs(0), qs(1)}));
    nm.constant("H_{0}", Value::scalar(constant<ex>(H0)))
        .constant("H_0", Value::scalar(constant<ex>(H0)));
    Value Minv = Value::zeros(2, 2);
    Minv.c = {ex(1), ex(0), ex(0), ex(1)};
    nm.constant("M^{-1}", Minv);
    cmp(Paper::S,
        R"(= (2(H_0 - V(\mathbf{q})) + \nabla V(\mathbf{q})^T M^{-1} \nabla V(\mathbf{q}))^{-\frac{1}{2}}, \quad (26))",
        "the monitor function g_1 (26)",
        "AVI1's MonitorArclength (avi.hpp) on the Kepler problem, M = I, H_0 = −1/2", nm,
        Target::exactly(modified::exact_rationals(MonitorArclength{H0}(Kepler{}, qs))));
    cmp(Paper::S, R"(= \mathbf{q}^\top \mathbf{q}, \quad (27))", "the monitor function g_2 (27)",
        "AVI2's MonitorQuadratic (avi.hpp)", nm,
        Target::exactly(modified::exact_rationals(MonitorQuadratic{}(Kepler{}, qs))));
  } else {
    throw std::invalid_argument("sharma_discrete_prints: no group " + group);
  }
  return cmp.take();
}

}  // namespace vibook::checks::printed_detail
