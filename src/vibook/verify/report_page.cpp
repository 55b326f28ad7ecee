// The report page of a typed discrete Lagrangian's study (ld_study.hpp, `vibook verify --ld
// --report DIR`): one table of every phase against its criterion, the figure (error at T
// against steps; the energy envelope) with its data, the modified equation, Lagrangian and
// Hamiltonian, and verify.json; written beside its final name and renamed onto it.
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "vibook/core/output_file.hpp"
#include "vibook/plot/gnuplot.hpp"
#include "vibook/verify/ld_study.hpp"
#include "vibook/verify/report_page.hpp"
#include "vibook_book_stylesheet.hpp"

namespace vibook::verify {

using nlohmann::json;

namespace {

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

// The page's head, its title and the command line (every route's page starts so).
std::string page_head(const std::string& command_line) {
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
          "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
          "<title>vibook verify</title>\n<link rel=\"stylesheet\" href=\"vibook.css\">\n"
          "<script type=\"text/x-mathjax-config\">MathJax.Hub.Config({tex2jax: {inlineMath: "
          "[['\\\\(','\\\\)']]}});</script>\n"
          "<script src=\"file:///usr/share/javascript/mathjax/MathJax.js?config=TeX-AMS_SVG\">"
          "</script>\n"
          "<style>\nbody{font-family:Roboto,'DejaVu Sans',sans-serif;max-width:1100px;"
          "margin:2em auto;padding:0 1em;color:#222;line-height:1.45}\n"
          "code,pre{font-family:'DejaVu Sans Mono',monospace;background:#fbfcfd}\n"
          "pre{padding:.6em;overflow-x:auto;border:1px solid #c4cfe5}\n"
          "h1,h2{color:#354c7b}\n</style></head><body>\n"
       << "<h1>vibook verify</h1>\n<p>vibook " << VIBOOK_VERSION << ". Command line:</p>\n<pre>"
       << html_escape(command_line) << "</pre>\n";
  return html.str();
}

// One row of the verdicts' table, coloured as the book's claims table is.
std::string table_row(const std::string& what, const std::string& measured,
                      const std::string& criterion, const std::string& holds, bool passed) {
  return "<tr class=\"status-" + std::string(passed ? "reproduced" : "not-reproduced") + "\"><td>" +
         what + "</td><td>" + html_escape(measured) + "</td><td>" + html_escape(criterion) +
         "</td><td class=\"holds\">" + html_escape(holds) + "</td></tr>\n";
}

}  // namespace

std::string write_ld_report(const LdStudy& st, const LdSettings& p, const std::string& command_line,
                            const std::filesystem::path& final_dir) {
  // Copies: the rows read parts that exist only when their phase ran (as the JSON says).
  const auto part = [&](const char* key) { return st.js.contains(key) ? st.js.at(key) : json(); };
  json jcons = part("consistency"), jref = part("reference"), jvar = part("variational_order"),
       jsym = part("symplecticity"), jsymm = part("symmetry"), jrev = part("reversibility"),
       jada = part("adaptive");
  const std::string intended = st.js.at("input").value("intended", std::string());
  const EnergyVerdict& ev = st.energy_verdict;
  const AdaptiveStudy& ada = st.adaptive;
  const EnergyVerdict& ada_ev = st.adaptive_verdict;
  const auto& terms = st.modified_terms;
  const auto& lagrangian = st.modified_lagrangian;
  const auto& hamiltonian = st.modified_hamiltonian;
  const auto& lagrangian_error = st.lagrangian_error;
  const auto& hamiltonian_error = st.hamiltonian_error;
  namespace fs = std::filesystem;
  const fs::path tmp = temporary_directory_for(final_dir);
  bool rendered = false;
  std::string render_error;
  try {
    write_output_file((tmp / "verify.json").string(), st.js.dump(2) + "\n", "--report");
    std::ostringstream conv;
    if (st.have_work_precision) {
      conv << "h,steps,typed,stormer_verlet,midpoint\n";
      for (std::size_t i = 0; i < st.wp.h.size(); ++i)
        conv << fmt::format("{:.17g},{:.0f},{:.17g},{:.17g},{:.17g}\n", st.wp.h[i], st.wp.steps[i],
                            st.wp.error[0][i], st.wp.error[1][i], st.wp.error[2][i]);
    } else {
      conv << "h,steps,typed\n";
      for (std::size_t i = 0; i < st.order_error.size(); ++i)
        conv << fmt::format("{:.17g},{:.0f},{:.17g}\n", st.order_h[i],
                            std::ceil(p.t_end / st.order_h[i] - 1e-9), st.order_error[i]);
    }
    write_output_file((tmp / "convergence.csv").string(), conv.str(), "--report");
    std::ostringstream env;
    env << "steps,envelope\n";
    for (std::size_t i = 0; i < st.energy.envelope.size(); ++i)
      env << fmt::format("{:.17g},{:.17g}\n", st.energy.envelope_steps[i], st.energy.envelope[i]);
    write_output_file((tmp / "energy.csv").string(), env.str(), "--report");
    if (!st.order_error.empty() && !st.energy.envelope.empty()) {
      try {
        plot::render("verify-report", tmp);
        rendered = true;
        fs::remove(tmp / "gnuplot.log");
      } catch (const plot::PlotError& e) {
        render_error = e.what();
      }
    } else {
      render_error = "the order study or the energy run did not complete";
    }
    std::ostringstream html;
    const auto row = [&](const char* what, const std::string& measured,
                         const std::string& criterion, const std::string& holds, bool passed) {
      html << table_row(what, measured, criterion, holds, passed);
    };
    auto phase_of = [&](const std::string& name) -> const LdPhase* {
      for (const auto& ph : st.phases)
        if (ph.name == name) return &ph;
      return nullptr;
    };
    // The book's own stylesheet (book/vibook.css, compiled in), so that the report's table
    // reads like the reproduction report: same borders, same status colours.
    write_output_file((tmp / "vibook.css").string(), std::string(kBookStylesheet), "--report");
    html << page_head(command_line) << "<p>Discrete Lagrangian <code>" << html_escape(p.ld_text)
         << "</code>; intended system <code>"
         << html_escape(intended == "hamiltonian"          ? "H = " + p.hamiltonian_text
                        : intended == "L = |v|^2/2 - V(q)" ? std::string("L = |v|^2/2 - V(q)")
                                                           : "L = " + p.lagrangian_text)
         << "</code>; potential <code>"
         << html_escape(p.potential_text.empty() ? "(none)" : p.potential_text) << "</code>; "
         << p.dim << "-dimensional; initial state q0 = ("
         << html_escape(fmt::format("{}", fmt::join(p.q0, ", "))) << "), p0 = ("
         << html_escape(fmt::format("{}", fmt::join(p.p0, ", "))) << ").</p>\n"
         << "<table class=\"vibook-claims\"><tr><th>property</th><th>measured</th>"
            "<th>criterion</th><th>verdict</th></tr>\n";
    auto failed_row = [&](const char* what, const std::string& name) {
      const LdPhase* ph = phase_of(name);
      if (ph && ph->status != "ok")
        row(what, ph->status + (ph->reason.empty() ? "" : ": " + ph->reason), "—", ph->status,
            false);
      return ph && ph->status == "ok";
    };
    if (failed_row("consistency", "consistency"))
      row("consistency", "h⁻¹L_d → " + jcons.value("leading_term", std::string()) + " as h → 0",
          "the intended system",
          st.consistent ? "yes" : "no: " + jcons.value("reason", std::string()), st.consistent);
    if (failed_row("reference", "reference"))
      row("reference",
          fmt::format("{} macro-steps, estimated error {:.1e}",
                      static_cast<long>(jref.at("macro_steps")), st.ref_error),
          "independent of the method", "—", true);
    if (phase_of("order") && phase_of("order")->status == "skipped")
      row("order", "not measured", "—", "skipped: no reference", false);
    else if (failed_row("order", "order")) {
      const auto [hmin, hmax] = used_range(st.fit, st.order_h);
      row("order",
          fmt::format("{:.3f} over {} step sizes from h = {:.3g} to {:.3g} at T = {:g} (floor "
                      "{:.1e})",
                      st.fit.slope, st.fit.points, hmax, hmin, p.t_end, st.fit.floor),
          fmt::format("|p − {:g}| < {:g}", p.expected, p.order_tol), st.order_passed ? "yes" : "no",
          st.order_passed);
    }
    if (phase_of("variational order") && phase_of("variational order")->status == "skipped")
      row("variational order", "not derived", "—",
          "skipped: " + phase_of("variational order")->reason, false);
    else if (failed_row("variational order", "variational order")) {
      const bool judged = jvar.contains("passed");
      row("variational order",
          jvar["order"].is_null()
              ? "more than " + std::to_string(st.var_k) + " (L_d − L_d^E vanishes through " +
                    jvar.value("checked_to", std::string()) + ")"
              : fmt::format("{}: L_d − L_d^E = O(h^{})", int(jvar["order"]),
                            int(jvar["order"]) + 1),
          judged ? fmt::format("r = {:g}, from the engine", p.expected) : "not judged",
          judged ? (jvar["passed"] ? "yes" : "no") : "—", !judged || bool(jvar["passed"]));
    }
    const std::string by_scaling =
        "NO when resolved (> 10 × resolution) and growing at least like h^(1/2)";
    if (failed_row("symplecticity", "symplecticity"))
      row("symplecticity",
          fmt::format("|JᵀΩJ − Ω| at h, 2h, 4h, 8h (h = {:g}): {}", p.h,
                      jsym.value("why", std::string())),
          by_scaling, jsym["passed"] ? "yes" : "no", bool(jsym["passed"]));
    if (failed_row("symmetry", "symmetry"))
      row("symmetry",
          fmt::format("|Φ₋ₕΦₕ(z) − z| at h, 2h, 4h, 8h: {}", jsymm.value("why", std::string())),
          by_scaling,
          std::string(jsymm["passed"] ? "yes" : "no") + (p.symmetric ? "" : " (reported)"),
          !p.symmetric || bool(jsymm["passed"]));
    if (failed_row("time reversibility", "reversibility"))
      row("time reversibility",
          fmt::format("|ρΦρΦ(z) − z| at h, 2h, 4h, 8h: {}", jrev.value("why", std::string())),
          by_scaling,
          std::string(jrev["passed"] ? "yes" : "no") +
              (st.system_reversible ? "" : " (the system is not ρ-reversible)"),
          bool(jrev["passed"]));
    if (failed_row("energy", "energy")) {
      row("energy", fmt::format("{} steps of h = {:g}: {}", st.energy.steps, st.energy.h, ev.why),
          fmt::format("round-off: r ≤ {:.1e}; trend: exponent < 0.25; shrinking like h^(p−1/2)",
                      ev.roundoff_bound),
          ev.verdict, ev.passed);
      row("Newton",
          fmt::format(
              "mean {:.2f}, max {} iterations per step, largest residual {:.1e}",
              st.newton_steps ? double(st.newton_iterations) / double(st.newton_steps) : 0.0,
              st.newton_max_iterations, st.newton_max_residual),
          "—", "—", true);
    }
    if (p.adaptive_epavi && failed_row("adaptive (EpAVI)", "adaptive"))
      row("adaptive (EpAVI)",
          fmt::format("{} of {} steps from h0 = {:g}, t reached {:.6g}, steps in [{:.3g}, "
                      "{:.3g}]; {}{}",
                      ada.steps_taken, p.adaptive_steps, p.h, ada.t_reached, ada.dt_min, ada.dt_max,
                      ada.failure.happened
                          ? fmt::format("no admissible step at t = {:.6g} (a fold: no sign "
                                        "change of (16) over dt in [{:.3g}, {:.3g}]); ",
                                        ada.failure.t, ada.failure.scan_lo, ada.failure.scan_hi)
                          : std::string(),
                      ada_ev.why),
          "every step exists; the intended energy as in the energy row",
          ada.failure.happened ? std::string("no admissible step") : ada_ev.verdict,
          bool(jada.value("passed", false)));
    html << "</table>\n";
    if (p.timings) {
      html << "<p>Timings (this machine; with --timings only, so that reports compare equal "
              "otherwise):";
      for (const auto& ph : st.phases) html << fmt::format(" {} {:.2f} s;", ph.name, ph.seconds);
      html << "</p>\n";
    }
    if (rendered)
      html << "<p><a href=\"verify-report.png\"><img src=\"verify-report.svg\" alt=\"error at T "
              "against steps; energy error envelope\"></a></p>\n<p>Left: error at T = "
           << fmt::format("{:g}", p.t_end)
           << " against the number of steps, every method against the independent reference "
              "(data: <a href=\"convergence.csv\">convergence.csv</a>). Right: the envelope "
              "max<sub>k≤K</sub>|H<sub>k</sub> − H<sub>0</sub>| (data: <a "
              "href=\"energy.csv\">energy.csv</a>).</p>\n";
    else
      html << "<p>No figure: " << html_escape(render_error)
           << " (data: <a href=\"convergence.csv\">convergence.csv</a>, <a "
              "href=\"energy.csv\">energy.csv</a>).</p>\n";
    // Formulas as LaTeX (MathJax, from the Debian package, when installed; else the source).
    auto formulas = [&](const char* title, const std::vector<std::string>& xs,
                        const std::string& error, auto label) {
      html << "<h2>" << title << "</h2>\n";
      if (!error.empty()) html << "<p>Not derived: " << html_escape(error) << "</p>\n";
      html << "<ul>\n";
      for (std::size_t k = 0; k < xs.size(); ++k)
        html << "<li>" << html_escape(label(k)) << ": "
             << (p.format == modified::Format::latex ? "\\(" + html_escape(xs[k]) + "\\)"
                                                     : "<code>" + html_escape(xs[k]) + "</code>")
             << "</li>\n";
      html << "</ul>\n";
    };
    std::vector<std::string> flat;
    std::vector<std::string> flat_labels;
    for (std::size_t k = 0; k < terms.size(); ++k)
      for (int i = 0; i < p.dim; ++i) {
        flat.push_back(terms[k][static_cast<std::size_t>(i)]);
        flat_labels.push_back(fmt::format("h^{} term of x{}''", k, i + 1));
      }
    formulas("Modified equation", flat,
             phase_of("modified") && phase_of("modified")->status != "ok"
                 ? phase_of("modified")->reason
                 : std::string(),
             [&](std::size_t k) { return flat_labels[k]; });
    formulas("Modified Lagrangian", lagrangian, lagrangian_error,
             [](std::size_t k) { return fmt::format("h^{} term", k); });
    formulas("Modified Hamiltonian", hamiltonian, hamiltonian_error,
             [](std::size_t k) { return fmt::format("h^{} term", k); });
    html << "<p>Every number: <a href=\"verify.json\">verify.json</a>.</p>\n</body></html>\n";
    write_output_file((tmp / "index.html").string(), html.str(), "--report");
    commit_directory(tmp, final_dir);
  } catch (...) {
    discard_temporary_directory(tmp);
    throw;
  }
  return rendered ? std::string() : render_error;
}

}  // namespace vibook::verify

namespace vibook::verify {

// The page of a one-step-map route (--method, --tableau, --composition, a black box): the
// verdicts' table from the same JSON as --json-out, the text report, the order study's data.
void write_map_report(const MapMeasurement& m, const std::string& command_line,
                      const std::filesystem::path& final_dir) {
  const json& js = m.js;
  const std::filesystem::path tmp = temporary_directory_for(final_dir);
  try {
    write_output_file((tmp / "verify.json").string(), js.dump(2) + "\n", "--report");
    write_output_file((tmp / "vibook.css").string(), std::string(kBookStylesheet), "--report");
    const bool have_order =
        js.contains("order") && js.at("order").contains("h") && js.at("order").contains("error");
    if (have_order) {
      std::ostringstream conv;
      conv << "h,error\n";
      const json& h = js.at("order").at("h");
      const json& e = js.at("order").at("error");
      for (std::size_t i = 0; i < h.size() && i < e.size(); ++i)
        conv << fmt::format("{:.17g},{}\n", h[i].get<double>(),
                            e[i].is_number() ? fmt::format("{:.17g}", e[i].get<double>()) : "");
      write_output_file((tmp / "convergence.csv").string(), conv.str(), "--report");
    }
    std::ostringstream html;
    html << page_head(command_line)
         << "<table class=\"vibook-claims\"><tr><th>property</th><th>measured</th>"
            "<th>criterion</th><th>verdict</th></tr>\n";
    // Each part the JSON judged, in the report's order; "required" as the verdict line says.
    const std::vector<std::pair<const char*, const char*>> parts = {
        {"consistency", "consistency"},
        {"order", "order"},
        {"variational_order", "variational order"},
        {"symplecticity", "symplecticity"},
        {"symmetry", "symmetry"},
        {"reversibility", "time reversibility"},
        {"energy", "energy"}};
    for (const auto& [key, what] : parts) {
      if (!js.contains(key) || !js.at(key).is_object()) continue;
      const json& j = js.at(key);
      std::string measured = j.value("why", std::string());
      if (std::string(key) == "order" && j.contains("fitted") && j.at("fitted").is_number())
        measured = fmt::format("{:.3f}", j.at("fitted").get<double>());
      if (std::string(key) == "energy") measured = j.value("verdict", std::string());
      if (std::string(key) == "variational_order")
        measured = j.contains("order") && j.at("order").is_number()
                       ? fmt::format("{:g}", j.at("order").get<double>())
                       : j.value("reason", std::string("not derived"));
      const bool judged = j.contains("passed") && j.at("passed").is_boolean();
      const bool passed = judged && j.at("passed").get<bool>();
      html << table_row(what, measured, j.value("criterion", std::string("see the report")),
                        judged ? (passed ? "yes" : "no") : "—", !judged || passed);
    }
    const json& v = js.contains("verdict") ? js.at("verdict") : json::object();
    const bool pass = v.value("passed", false);
    html << "</table>\n<p>Verdict: <strong>" << (pass ? "PASS" : "FAIL") << "</strong>";
    if (v.contains(pass ? "required" : "failed"))
      html << " ("
           << html_escape(fmt::format(
                  "{}",
                  fmt::join(v.at(pass ? "required" : "failed").get<std::vector<std::string>>(),
                            ", ")))
           << ")";
    html << ". The report as printed:</p>\n<pre>" << html_escape(m.out.str()) << "</pre>\n"
         << "<p>No figure for this route yet; the order study's data: "
         << (have_order ? "<a href=\"convergence.csv\">convergence.csv</a>" : "none")
         << ". Every number: <a href=\"verify.json\">verify.json</a>.</p>\n</body></html>\n";
    write_output_file((tmp / "index.html").string(), html.str(), "--report");
    commit_directory(tmp, final_dir);
  } catch (...) {
    discard_temporary_directory(tmp);
    throw;
  }
}

}  // namespace vibook::verify
