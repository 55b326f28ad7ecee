// `vibook verify`: a discrete Lagrangian and a potential typed as expressions, run by the
// generic variational integrator, measured by the verification helpers (verify/verify.hpp) and
// expanded by the modified-equation engine: the route of examples/ without writing C++.
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
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
#include "vibook/mechanics/discrete_lagrangian.hpp"
#include "vibook/modified/engine.hpp"
#include "vibook/plot/gnuplot.hpp"
#include "vibook/verify/expression.hpp"
#include "vibook/verify/verify.hpp"
#include "vibook_book_stylesheet.hpp"

namespace vibook::cli {

namespace {

struct VerifyOptions {
  std::string ld, potential, dim, q0, p0,
      t_end = "5", h_list = "0.2,0.1,0.05,0.025,0.0125", expected = "2", order_tol = "0.1",
      h = "0.05", steps = "100000", modified_order = "2", format = "text", json_out, report;
  bool json_given = false, report_given = false;
};

struct Plan {
  int dim = 0;
  std::vector<double> q0, p0, hs;
  double t_end = 0, expected = 0, order_tol = 0, h = 0;
  long long steps = 0;
  int modified_order = 0;
  modified::Format format = modified::Format::text;
};

// --report DIR: a new name in an existing writable directory, or an earlier report (a
// directory holding index.html and verify.json), which is replaced; nothing else is.
std::filesystem::path report_path(const std::string& dir) {
  std::filesystem::path d = std::filesystem::path(dir).lexically_normal();
  if (d.filename().empty()) d = d.parent_path();  // "rep/"
  return d;
}

void check_report_dir(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (dir.empty()) throw ArgumentError("--report", "is empty");
  const fs::path d = report_path(dir);
  if (d.empty() || d.filename() == "." || d.filename() == "..")
    throw ArgumentError("--report", "'" + dir + "' does not name a new directory");
  const auto st = fs::symlink_status(d, ec);
  if (fs::exists(st)) {
    if (fs::is_symlink(st) || !fs::is_directory(st))
      throw ArgumentError("--report", "'" + dir + "' exists and is not a directory");
    const bool empty = fs::is_empty(d, ec);
    if (!empty && !(fs::exists(d / "index.html") && fs::exists(d / "verify.json")))
      throw ArgumentError("--report", "'" + dir +
                                          "' exists and is not an earlier report (index.html and "
                                          "verify.json); give a new name");
  }
  const fs::path parent = d.has_parent_path() ? d.parent_path() : fs::path(".");
  if (!fs::is_directory(parent, ec) || ::access(parent.c_str(), W_OK) != 0)
    throw ArgumentError("--report", "cannot create '" + dir + "': '" + parent.string() +
                                        "' is not a writable directory");
}

std::string html_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

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
  if (o.json_given) check_output_path(o.json_out, "--json-out", true);
  if (o.report_given) check_report_dir(o.report);
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

  // Work–precision beside Störmer–Verlet and the implicit midpoint rule, the same generic
  // solver on L = |v|²/2 − V(q), every error against one reference (Störmer–Verlet at
  // h_min/64): error at T against the number of steps.
  verify::WorkPrecision wp;
  if (o.report_given) {
    auto L = [&](const auto& q, const auto& v) -> scalar_t<decltype(q)> {
      using S = scalar_t<decltype(q)>;
      return constant<S>(0.5) * squared_norm(v) - dl.potential<N, S>(Vec<S, N>(q));
    };
    auto sv_dl = stormer_verlet_dl(L);
    auto mid_dl = midpoint_dl(L);
    DelIntegrator<N, decltype(sv_dl)> sv(sv_dl);
    DelIntegrator<N, decltype(mid_dl)> mid(mid_dl);
    const verify::Step sv_step = [&](Eigen::VectorXd& z, double h) {
      sv.reset();
      verify::step_qp<N>(sv, z, h);
    };
    const verify::Step mid_step = [&](Eigen::VectorXd& z, double h) {
      mid.reset();
      verify::step_qp<N>(mid, z, h);
    };
    const Eigen::VectorXd common = verify::integrate(sv_step, z0, hmin / 64, p.t_end);
    wp = verify::work_precision(
        {{"typed", step}, {"stormer_verlet", sv_step}, {"midpoint", mid_step}}, z0, p.t_end, common,
        p.hs);
  }

  // The engine, on the same evaluator over GiNaC symbols.
  std::vector<std::vector<std::string>> terms;
  std::vector<std::string> lagrangian;
  std::string lagrangian_error;
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
    try {
      for (const auto& l : engine.l_mod())
        lagrangian.push_back(modified::canonical_string(l, p.format));
    } catch (const NumericalError& e) {
      lagrangian_error = e.what();  // e.g. a Lagrangian that is not regular
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
  out << "modified Lagrangian  L_mod = sum_k h^k L_k:\n";
  if (!lagrangian_error.empty()) out << "  not derived: " << lagrangian_error << '\n';
  for (std::size_t k = 0; k < lagrangian.size(); ++k)
    out << fmt::format("  L_{} = {}\n", k, lagrangian[k]);
  std::cout << out.str();

  nlohmann::json js;
  {
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
    js["modified_lagrangian"] = lagrangian;
  }
  if (o.json_given) write_output_file(o.json_out, js.dump(2) + "\n", "--json-out");
  if (!o.report_given) return kOk;

  // The report: a directory filled beside its final name and renamed onto it at the end.
  namespace fs = std::filesystem;
  const fs::path final_dir = report_path(o.report);
  const fs::path tmp = temporary_directory_for(final_dir);
  bool rendered = false;
  std::string render_error;
  try {
    write_output_file((tmp / "verify.json").string(), js.dump(2) + "\n", "--report");
    std::ostringstream conv;
    conv << "h,steps,typed,stormer_verlet,midpoint\n";
    for (std::size_t i = 0; i < p.hs.size(); ++i)
      conv << fmt::format("{:.17g},{:.0f},{:.17g},{:.17g},{:.17g}\n", wp.h[i], wp.steps[i],
                          wp.error[0][i], wp.error[1][i], wp.error[2][i]);
    write_output_file((tmp / "convergence.csv").string(), conv.str(), "--report");
    std::ostringstream env;
    env << "steps,envelope\n";
    for (std::size_t i = 0; i < en.envelope.size(); ++i)
      env << fmt::format("{:.17g},{:.17g}\n", en.envelope_steps[i], en.envelope[i]);
    write_output_file((tmp / "energy.csv").string(), env.str(), "--report");
    try {
      plot::render("verify-report", tmp);
      rendered = true;
      fs::remove(tmp / "gnuplot.log");
    } catch (const plot::PlotError& e) {
      render_error = e.what();
    }
    std::ostringstream html;
    const auto row = [&](const char* what, const std::string& measured,
                         const std::string& criterion, bool passed) {
      html << "<tr class=\"status-" << (passed ? "reproduced" : "not-reproduced") << "\"><td>"
           << what << "</td><td>" << html_escape(measured) << "</td><td>" << html_escape(criterion)
           << "</td><td class=\"holds\">" << (passed ? "yes" : "no") << "</td></tr>\n";
    };
    // The book's own stylesheet (book/vibook.css, compiled in), so that the report's table
    // reads like the reproduction report: same borders, same status colours.
    write_output_file((tmp / "vibook.css").string(), std::string(kBookStylesheet), "--report");
    html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
            "<title>vibook verify</title>\n<link rel=\"stylesheet\" href=\"vibook.css\">\n"
            "<style>\nbody{font-family:Roboto,'DejaVu Sans',sans-serif;max-width:1100px;"
            "margin:2em auto;padding:0 1em;color:#222;line-height:1.45}\n"
            "code,pre{font-family:'DejaVu Sans Mono',monospace;background:#fbfcfd}\n"
            "pre{padding:.6em;overflow-x:auto;border:1px solid #c4cfe5}\n"
            "h1,h2{color:#354c7b}\n</style></head><body>\n"
         << "<h1>vibook verify</h1>\n<p>Discrete Lagrangian <code>" << html_escape(o.ld)
         << "</code>, potential <code>" << html_escape(o.potential) << "</code>, " << N
         << "-dimensional; initial state q0 = ("
         << html_escape(fmt::format("{}", fmt::join(p.q0, ", "))) << "), p0 = ("
         << html_escape(fmt::format("{}", fmt::join(p.p0, ", "))) << ").</p>\n"
         << "<table class=\"vibook-claims\"><tr><th>property</th><th>measured</th>"
            "<th>criterion</th><th>holds</th></tr>\n";
    row("order",
        fmt::format("{:.3f} over {} step sizes at T = {:g}", order.order, order.points, p.t_end),
        fmt::format("|p − {:g}| < {:g}", p.expected, p.order_tol), order.passed);
    row("symplecticity", fmt::format("|JᵀΩJ − Ω| = {:.2e} at h = {:g}", sym.defect, p.h),
        fmt::format("≤ {:.0e}", sym.tolerance), sym.passed);
    row("time reversibility", fmt::format("|ρΦρΦ(z) − z| = {:.2e} at h = {:g}", rev.defect, p.h),
        fmt::format("≤ {:.0e}", rev.tolerance), rev.passed);
    row("energy",
        fmt::format("{} steps: max |H − H₀| = {:.2e}, envelope exponent {:.3f}", en.steps,
                    en.max_error, en.exponent),
        fmt::format("bounded: exponent < {:g}", en.bounded_below), en.bounded);
    html << "</table>\n";
    if (rendered)
      html << "<p><a href=\"verify-report.png\"><img src=\"verify-report.svg\" alt=\"error at T "
              "against steps beside Störmer–Verlet and the implicit midpoint rule; energy error "
              "envelope\"></a></p>\n<p>Left: error at T = "
           << fmt::format("{:g}", p.t_end)
           << " against the number of steps, each method against Störmer–Verlet at h_min/64 "
              "(data: <a href=\"convergence.csv\">convergence.csv</a>). Right: the envelope "
              "max<sub>k≤K</sub>|H<sub>k</sub> − H<sub>0</sub>| (data: <a "
              "href=\"energy.csv\">energy.csv</a>).</p>\n";
    else
      html << "<p>No figure: " << html_escape(render_error)
           << " (data: <a href=\"convergence.csv\">convergence.csv</a>, <a "
              "href=\"energy.csv\">energy.csv</a>).</p>\n";
    html << "<h2>Modified equation</h2>\n<pre>";
    for (std::size_t k = 0; k < terms.size(); ++k)
      for (int i = 0; i < N; ++i)
        html << html_escape(fmt::format("h^{} term of x{}'': {}", k, i + 1, terms[k][i])) << "\n";
    html << "</pre>\n<h2>Modified Lagrangian</h2>\n<pre>";
    if (!lagrangian_error.empty()) html << "not derived: " << html_escape(lagrangian_error) << "\n";
    for (std::size_t k = 0; k < lagrangian.size(); ++k)
      html << html_escape(fmt::format("h^{} term: {}", k, lagrangian[k])) << "\n";
    html << "</pre>\n<p>Every number: <a "
            "href=\"verify.json\">verify.json</a>.</p>\n</body></html>\n";
    write_output_file((tmp / "index.html").string(), html.str(), "--report");
    commit_directory(tmp, final_dir);
  } catch (...) {
    std::error_code ec;
    fs::remove_all(tmp, ec);
    throw;
  }
  std::cout << "report: " << (final_dir / "index.html").string() << '\n';
  if (!rendered) {
    fmt::print(stderr, "vibook: --report: figure not drawn: {}\n", render_error);
    return kFailure;
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
  c->add_option("--report", o->report,
                "also write an HTML report into this new directory (figures, CSV, JSON; work-"
                "precision beside Störmer-Verlet and the implicit midpoint rule)");
  return [o, c] {
    o->json_given = c->count("--json-out") > 0;
    o->report_given = c->count("--report") > 0;
    return run(*o);
  };
}

}  // namespace vibook::cli
