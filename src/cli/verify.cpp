// `vibook verify`: a discrete Lagrangian and a potential typed as expressions, run by the
// generic variational integrator, measured by the verification helpers (verify/verify.hpp) and
// expanded by the modified-equation engine: the route of examples/ without writing C++.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "args.hpp"
#include "cli.hpp"
#include "vibook/core/output_file.hpp"
#include "vibook/mechanics/del_solver.hpp"
#include "vibook/modified/engine.hpp"
#include "vibook/verify/expression.hpp"
#include "vibook/verify/verify.hpp"

namespace vibook::cli {

namespace {

struct VerifyOptions {
  std::string ld, potential, dim, q0, p0,
      t_end = "5", h_list = "0.2,0.1,0.05,0.025,0.0125", expected = "2", order_tol = "0.1",
      h = "0.05", steps = "100000", modified_order = "2", format = "text", json_out;
};

struct Plan {
  int dim = 0;
  std::vector<double> q0, p0, hs;
  double t_end = 0, expected = 0, order_tol = 0, h = 0;
  long long steps = 0;
  int modified_order = 0;
  modified::Format format = modified::Format::text;
};

// Every argument checked before any work (exit 2 naming it).
Plan check(const VerifyOptions& o, const verify::TypedDiscreteLagrangian& dl) {
  Plan p;
  p.dim = dl.dim();
  auto vector_or = [&](const std::string& arg, const std::string& text, double fill) {
    std::vector<double> v = text.empty() ? std::vector<double>(p.dim, fill) : parse_list(arg, text);
    if (static_cast<int>(v.size()) != p.dim)
      throw ArgumentError(arg, fmt::format("has {} components; the expressions are {}-dimensional",
                                           v.size(), p.dim));
    for (double x : v)
      if (!std::isfinite(x)) throw ArgumentError(arg, "must be finite");
    return v;
  };
  p.q0 = vector_or("--q0", o.q0, 0.1);
  p.p0 = vector_or("--p0", o.p0, 0.1);
  p.t_end = parse_number("--t-end", o.t_end);
  if (!(p.t_end > 0) || !std::isfinite(p.t_end) || p.t_end > 1e6)
    throw ArgumentError("--t-end", "must lie in (0, 1e6]");
  p.hs = parse_list("--h-list", o.h_list);
  if (p.hs.size() < 3) throw ArgumentError("--h-list", "needs at least 3 step sizes");
  for (double h : p.hs)
    if (!(h > 0) || !(h <= p.t_end) || p.t_end / h > 1e8)
      throw ArgumentError("--h-list", fmt::format("{} is not a step size in (T/1e8, T]", h));
  p.expected = parse_number("--expected-order", o.expected);
  if (!(p.expected > 0 && p.expected <= 12))
    throw ArgumentError("--expected-order", "must lie in (0, 12]");
  p.order_tol = parse_number("--order-tol", o.order_tol);
  if (!(p.order_tol > 0 && p.order_tol <= 1))
    throw ArgumentError("--order-tol", "must lie in (0, 1]");
  p.h = parse_number("--h", o.h);
  if (!(p.h > 0 && p.h <= 1)) throw ArgumentError("--h", "must lie in (0, 1]");
  p.steps = parse_integer("--steps", o.steps);
  if (p.steps < 1024 || p.steps > 100000000)
    throw ArgumentError("--steps", "must lie in [1024, 1e8]");
  const long long k = parse_integer("--modified-order", o.modified_order);
  if (k < 0 || k > 6) throw ArgumentError("--modified-order", "must lie in [0, 6]");
  p.modified_order = static_cast<int>(k);
  p.format = modified::parse_format(o.format);
  if (p.format == modified::Format::python)
    throw ArgumentError("--format", "verify prints text or latex");
  if (!o.json_out.empty()) check_output_path(o.json_out, "--json-out", true);
  return p;
}

template <int N>
int run_verify(const VerifyOptions& o, const verify::TypedDiscreteLagrangian& dl, const Plan& p) {
  const auto Ld = dl.bind<N>();
  DelIntegrator<N, decltype(Ld)> vi(Ld);
  Eigen::VectorXd z0(2 * N);
  for (int i = 0; i < N; ++i) {
    z0(i) = p.q0[i];
    z0(N + i) = p.p0[i];
  }
  // Regularity first: D1 D2 L_d must be invertible at the first step, or the discrete
  // Euler–Lagrange equations cannot be solved for q1 (exit 3).
  {
    Vec<double, N> q0, q1;
    for (int i = 0; i < N; ++i) {
      q0(i) = p.q0[i];
      q1(i) = p.q0[i] + p.h * p.p0[i];
    }
    const auto d = ad::two_point<N>(Ld, q0, q1, p.h);
    const double det = d.D12.determinant();
    const double scale = std::pow(d.D12.cwiseAbs().maxCoeff(), N);
    if (!std::isfinite(det) || !(std::abs(det) > 1e-12 * scale))
      throw NumericalError(fmt::format(
          "the discrete Lagrangian is degenerate at the initial state: det D1 D2 L_d = {:.3g} at "
          "q0 = q(0), q1 = q(0) + h p(0), h = {:g} (its discrete Euler-Lagrange equations cannot "
          "be solved for q1)",
          det, p.h));
  }
  const verify::Step step = [&](Eigen::VectorXd& z, double h) {
    vi.reset();  // the helpers move z between calls: no warm start
    verify::step_qp<N>(vi, z, h);
  };
  const verify::Step warm = [&](Eigen::VectorXd& z, double h) { verify::step_qp<N>(vi, z, h); };
  const verify::Observable energy = [&](const Eigen::VectorXd& z) {
    Vec<double, N> q, v;
    for (int i = 0; i < N; ++i) q(i) = z(i), v(i) = z(N + i);
    return 0.5 * v.squaredNorm() + dl.potential<N, double>(q);
  };

  double hmin = p.hs[0];
  for (double h : p.hs) hmin = std::min(hmin, h);
  const Eigen::VectorXd ref = verify::integrate(step, z0, hmin / 64, p.t_end);
  const auto order =
      verify::convergence_order(step, z0, p.t_end, ref, p.hs, p.expected, p.order_tol, 1e-10);
  const std::vector<Eigen::VectorXd> states{z0, ref};
  const auto sym = verify::symplecticity_defect(step, states, p.h, 1e-8);
  const auto rev = verify::reversibility_defect(step, states, p.h, 1e-12);
  vi.reset();
  const auto en = verify::energy_behaviour(warm, energy, z0, p.h, p.steps);

  // The engine, on the same evaluator over GiNaC symbols.
  std::vector<std::vector<std::string>> terms;
  {
    std::lock_guard<std::mutex> lock(modified::ginac_mutex());
    auto jets = std::make_shared<modified::JetSpace>(N);
    modified::Engine engine(modified::symbolic_dl<N>(Ld, jets, "typed discrete Lagrangian"),
                            p.modified_order);
    const auto& f = engine.modified_equation();
    for (std::size_t k = 0; k < f.size(); ++k) {
      terms.emplace_back();
      for (int i = 0; i < N; ++i)
        terms.back().push_back(modified::canonical_string(f[k][i], p.format));
    }
  }

  auto verdict = [](bool b) { return b ? "yes" : "NO"; };
  std::ostringstream out;
  out << fmt::format("discrete Lagrangian  {}\npotential            {}   ({}-dimensional)\n", o.ld,
                     o.potential, N);
  out << fmt::format(
      "order                {:.3f} over {} step sizes at T = {:g}; expected {:g} "
      "(|p - {:g}| < {:g}): {}\n",
      order.order, order.points, p.t_end, p.expected, p.expected, p.order_tol,
      verdict(order.passed));
  out << fmt::format("symplectic           defect |J^T W J - W| = {:.2e} (<= {:.0e}): {}\n",
                     sym.defect, sym.tolerance, verdict(sym.passed));
  out << fmt::format("time-reversible      defect = {:.2e} (<= {:.0e}): {}\n", rev.defect,
                     rev.tolerance, verdict(rev.passed));
  out << fmt::format(
      "energy               {} steps of h = {:g}: max |H - H0| = {:.2e}, envelope "
      "exponent {:.3f} (bounded if < {:g}): {}\n",
      en.steps, en.h, en.max_error, en.exponent, en.bounded_below,
      en.bounded ? "bounded" : "NOT bounded");
  out << "modified equation    x'' = sum_k h^k f_k:\n";
  for (std::size_t k = 0; k < terms.size(); ++k)
    for (int i = 0; i < N; ++i) out << fmt::format("  f_{}[{}] = {}\n", k, i + 1, terms[k][i]);
  std::cout << out.str();

  if (!o.json_out.empty()) {
    nlohmann::json js;
    js["ld"] = o.ld;
    js["potential"] = o.potential;
    js["dim"] = N;
    js["q0"] = p.q0;
    js["p0"] = p.p0;
    js["order"] = {{"h", order.h},           {"error", order.error},   {"fitted", order.order},
                   {"points", order.points}, {"expected", p.expected}, {"tolerance", p.order_tol},
                   {"T", p.t_end},           {"passed", order.passed}};
    js["symplecticity"] = {
        {"defect", sym.defect}, {"tolerance", sym.tolerance}, {"h", p.h}, {"passed", sym.passed}};
    js["reversibility"] = {
        {"defect", rev.defect}, {"tolerance", rev.tolerance}, {"h", p.h}, {"passed", rev.passed}};
    js["energy"] = {{"steps", en.steps},
                    {"h", en.h},
                    {"envelope_steps", en.envelope_steps},
                    {"envelope", en.envelope},
                    {"max_error", en.max_error},
                    {"exponent", en.exponent},
                    {"bounded_below", en.bounded_below},
                    {"bounded", en.bounded}};
    js["modified_equation"] = terms;
    write_output_file(o.json_out, js.dump(2) + "\n", "--json-out");
  }
  return kOk;
}

int run(const VerifyOptions& o) {
  const int dim = o.dim.empty() ? 0 : static_cast<int>(parse_integer("--dim", o.dim));
  if (!o.dim.empty() && (dim < 1 || dim > 3)) throw ArgumentError("--dim", "must be 1, 2 or 3");
  std::unique_ptr<verify::TypedDiscreteLagrangian> dl;
  {
    std::lock_guard<std::mutex> lock(modified::ginac_mutex());
    dl = std::make_unique<verify::TypedDiscreteLagrangian>(o.ld, o.potential, dim);
  }
  const Plan p = check(o, *dl);
  switch (p.dim) {
    case 1:
      return run_verify<1>(o, *dl, p);
    case 2:
      return run_verify<2>(o, *dl, p);
    default:
      return run_verify<3>(o, *dl, p);
  }
}

}  // namespace

std::function<int()> add_verify_command(CLI::App& app) {
  auto o = std::make_shared<VerifyOptions>();
  auto* c = app.add_subcommand(
      "verify",
      "Verify a discrete Lagrangian typed as an expression: measured order, symplecticity, "
      "reversibility, long-time energy, modified equation");
  c->add_option("--ld", o->ld,
                "discrete Lagrangian L_d(q0, q1, h) ≈ h·L in q0, q1, h and V(...), e.g. "
                "'h*((q1-q0)^2/(2*h^2) - (V(q0)+4*V((q0+q1)/2)+V(q1))/6)'; u^2 is |u|^2")
      ->required();
  c->add_option("--potential", o->potential,
                "V of L = |v|^2/2 - V(q), in x, y, z, e.g. 'x^2/2+y^2/2+x^2*y-y^3/3' (a leading "
                "minus: --potential='-cos(x)')")
      ->required();
  c->add_option("--dim", o->dim, "dimension 1-3 (default: the last of x, y, z the potential uses)");
  c->add_option("--q0", o->q0, "initial position, comma-separated (default 0.1 in each)");
  c->add_option("--p0", o->p0, "initial momentum, comma-separated (default 0.1 in each)");
  c->add_option("--t-end", o->t_end, "time of the order study (default 5)");
  c->add_option("--h-list", o->h_list, "step sizes of the order study (default 0.2,...,0.0125)");
  c->add_option("--expected-order", o->expected, "order to test against (default 2)");
  c->add_option("--order-tol", o->order_tol, "accepted |fitted - expected| (default 0.1)");
  c->add_option("--h", o->h, "step of the symplecticity, reversibility and energy tests (0.05)");
  c->add_option("--steps", o->steps, "steps of the energy test (default 100000)");
  c->add_option("--modified-order", o->modified_order,
                "highest h power of the modified equation (2)");
  c->add_option("--format", o->format, "modified equation as text (default) or latex");
  c->add_option("--json-out", o->json_out, "also write every measurement as JSON to this file");
  return [o] { return run(*o); };
}

}  // namespace vibook::cli
