#include "vibook/figures/registry.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "vibook/claims/provenance.hpp"
#include "vibook/core/errors.hpp"
#include "vibook/core/output_file.hpp"
#include "vibook/core/parallel.hpp"
#include "vibook/epavi/checks.hpp"
#include "vibook/integrators/checks.hpp"
#include "vibook/kepler/checks.hpp"
#include "vibook/mechanics/checks.hpp"
#include "vibook/modified/checks.hpp"
#include "vibook/plot/gnuplot.hpp"
#include "vibook/relativistic/checks.hpp"
#include "vibook/verify/checks.hpp"

#include <cstdlib>

namespace vibook::figures {

const std::vector<Check>& registry() {
  static const std::vector<Check> all = {checks::check_s_del(),
                                         checks::sharma_fig1(),
                                         checks::sharma_fig2(),
                                         checks::sharma_fig3(),
                                         checks::sharma_fig4(),
                                         checks::sharma_fig5(),
                                         checks::check_s_eq29(),
                                         checks::check_s_eq39(),
                                         checks::check_s_l1(),
                                         checks::epavi_existence(),
                                         checks::check_v_ex1(),
                                         checks::vermeeren_fig1(),
                                         checks::check_ss_t8(),
                                         checks::shen_sun_fig7(),
                                         checks::relativistic_precession(),
                                         checks::check_ss_t2(),
                                         checks::check_ss_p4(),
                                         checks::check_ss_t6(),
                                         checks::shen_sun_fig2(),
                                         checks::shen_sun_fig345(),
                                         checks::shen_sun_fig6(),
                                         checks::shen_sun_work_precision(),
                                         checks::check_modified(),
                                         checks::check_v_t16(),
                                         checks::vermeeren_fig3(),
                                         checks::shen_sun_fig1(),
                                         checks::check_ss_t13(),
                                         checks::field_audit(),
                                         checks::field_audit_odeint()};
  return all;
}

const std::vector<Check>& long_studies() {
  static const std::vector<Check> all = {checks::sharma_eq29_long(), checks::field_audit_galerkin(),
                                         checks::field_audit_splitting(),
                                         checks::field_audit_systems()};
  return all;
}

bool long_studies_enabled() {
  const char* v = std::getenv("VIBOOK_LONG_STUDIES");
  return v != nullptr && *v != '\0' && std::string_view(v) != "0";
}

const Check* find(std::string_view id) {
  for (const auto& c : long_studies()) {
    if (c.id == id) return &c;
  }
  for (const auto& c : registry()) {
    if (c.id == id) return &c;
  }
  return nullptr;
}

FigureOutput make_figure(const Check& check, const std::filesystem::path& out_root) {
  FigureOutput out;
  out.id = check.id;
  out.dir = out_root / check.id;
  // Everything is written into a fresh hidden directory beside OUT/ID, which replaces OUT/ID
  // only when the data, claims.json and the images are complete: an interrupted run leaves
  // the previous figure, or nothing, under the final name (output_file.hpp).
  const std::filesystem::path tmp = temporary_directory_for(out.dir);
  try {
    out.results = run_check(check, Context{tmp});
    write_output_file((tmp / "claims.json").string(),
                      claims::results_to_json(out.results).dump(2) + "\n", "claims.json");
    try {
      plot::render(check.id, tmp);
      out.rendered = true;
    } catch (const plot::PlotError& e) {
      out.render_error = e.what();
      for (auto at = out.render_error.find(tmp.string()); at != std::string::npos;
           at = out.render_error.find(tmp.string()))
        out.render_error.replace(at, tmp.string().size(), out.dir.string());
    }
    commit_directory(tmp, out.dir);
  } catch (...) {
    discard_temporary_directory(tmp);
    throw;
  }
  return out;
}

std::vector<claims::ClaimResult> run_check(const Check& check, const Context& context) {
  std::vector<claims::ClaimResult> results = check.run(context);
  for (const auto& id : check.claims) {
    const auto it = std::find_if(results.begin(), results.end(),
                                 [&](const claims::ClaimResult& r) { return r.id == id; });
    if (it == results.end() || it->status == claims::Status::pending)
      throw std::logic_error("check " + check.id + " names claim " + id +
                             " but did not measure it");
  }
  for (const auto& r : results) {
    const bool named =
        std::find(check.claims.begin(), check.claims.end(), r.id) != check.claims.end();
    if (!named && r.id.find("-ERR-") == std::string::npos)
      throw std::logic_error("check " + check.id + " measured claim " + r.id +
                             ", which it does not name");
  }
  return results;
}

std::vector<const Check*> select_figures(const std::vector<std::string>& ids,
                                         const std::string& arg) {
  std::vector<const Check*> todo;
  if (ids.empty()) {
    for (const auto& c : registry())
      if (c.is_figure) todo.push_back(&c);
    // A long study without a figure (field-audit-galerkin) is a check: `vibook claims` runs it.
    if (long_studies_enabled())
      for (const auto& c : long_studies())
        if (c.is_figure) todo.push_back(&c);
    return todo;
  }
  for (const auto& id : ids) {
    const auto* c = find(id);
    if (c && !c->is_figure)
      throw ArgumentError(
          arg, fmt::format("'{}' is a check without a figure: `vibook claims --check {}` runs it",
                           id, id));
    if (!c) throw ArgumentError(arg, fmt::format("unknown figure '{}' (see `vibook list`)", id));
    if (std::find(todo.begin(), todo.end(), c) != todo.end())
      throw ArgumentError(arg, fmt::format("'{}' is given twice", id));
    todo.push_back(c);
  }
  return todo;
}

std::vector<FigureOutput> make_figures(const std::vector<const Check*>& figures,
                                       const std::filesystem::path& out_root,
                                       const std::string& arg) {
  ensure_output_directory(out_root, arg);
  struct stat st {};
  std::string bare = out_root.string();  // "link/" would follow the link
  while (bare.size() > 1 && bare.back() == '/') bare.pop_back();
  if (::lstat(bare.c_str(), &st) == 0 && S_ISLNK(st.st_mode))
    throw ArgumentError(
        arg, "'" + out_root.string() + "' is a symbolic link; give the directory it points to");
  for (const auto* c : figures) {
    const std::filesystem::path d = out_root / c->id;
    if (::lstat(d.c_str(), &st) == 0 && !S_ISDIR(st.st_mode))
      throw ArgumentError(arg,
                          "'" + d.string() + "' exists and is not a directory; move it away first");
  }
  std::vector<FigureOutput> outputs(figures.size());
  parallel_for(figures.size(), 0,
               [&](std::size_t i) { outputs[i] = make_figure(*figures[i], out_root); });
  return outputs;
}

std::vector<std::vector<claims::ClaimResult>> run_checks(const std::vector<const Check*>& checks,
                                                         unsigned jobs) {
  std::vector<std::vector<claims::ClaimResult>> results(checks.size());
  parallel_for(checks.size(), jobs,
               [&](std::size_t i) { results[i] = run_check(*checks[i], Context{}); });
  return results;
}

claims::Ledger measure_all(unsigned jobs, const std::optional<std::filesystem::path>& figures_dir) {
  // With figures_dir: a figure (or long study) whose DIR/ID/claims.json exists was measured
  // by `vibook figures` with this same code; its results are read back, not measured again.
  std::vector<const Check*> all;
  std::vector<std::vector<claims::ClaimResult>> reused;
  auto take = [&](const Check& c) {
    const auto file = figures_dir ? *figures_dir / c.id / "claims.json" : std::filesystem::path();
    if (figures_dir && c.is_figure && std::filesystem::exists(file)) {
      // Read back, and refused (naming the file and the option) unless it is what `vibook
      // figures` writes for this check: every claim the check measures, with a status.
      std::vector<claims::ClaimResult> rs;
      try {
        std::ifstream f(file);
        if (!f) throw std::runtime_error("cannot be read");
        rs = claims::results_from_json(nlohmann::json::parse(f));
      } catch (const std::exception& e) {
        throw ArgumentError(
            "--figures-dir",
            "'" + file.string() + "' is not a claims.json of `vibook figures`: " + e.what());
      }
      for (const auto& id : c.claims)
        if (std::none_of(rs.begin(), rs.end(), [&](const claims::ClaimResult& r) {
              return r.id == id && r.status != claims::Status::pending;
            }))
          throw ArgumentError("--figures-dir", "'" + file.string() + "' does not hold claim " + id +
                                                   " of " + c.id +
                                                   " (written by another build? rerun `vibook "
                                                   "figures`)");
      reused.push_back(std::move(rs));
    } else {
      all.push_back(&c);
    }
  };
  for (const auto& c : registry()) take(c);
  if (long_studies_enabled())
    for (const auto& c : long_studies()) take(c);
  std::vector<std::vector<claims::ClaimResult>> measured = run_checks(all, jobs);
  // Recorded in registry order whichever way each check's results were obtained.
  claims::Ledger ledger;
  std::size_t next_run = 0, next_reused = 0;
  auto record_next = [&](const Check& c) {
    const bool ran = next_run < all.size() && all[next_run] == &c;
    for (const auto& r : ran ? measured[next_run++] : reused[next_reused++]) ledger.record(r);
  };
  for (const auto& c : registry()) record_next(c);
  if (long_studies_enabled()) {
    for (const auto& c : long_studies()) record_next(c);
  } else {
    // A claim only a long study measures stays pending, and says which study measures it and
    // how to run it (the report links the study's source from its row).
    for (const auto& c : long_studies())
      for (const auto& id : c.claims) {
        const auto* row = ledger.find(id);
        if (!row || row->result.status != claims::Status::pending) continue;
        claims::ClaimResult r;
        r.id = id;
        r.source = c.id;
        r.note = "Measured by the long study " + c.id +
                 ", which this build did not run: ./build.sh book (VIBOOK_LONG_STUDIES=1) or "
                 "`vibook claims --check " +
                 c.id + "` runs it.";
        ledger.record(r);
      }
  }
  return ledger;
}

claims::Ledger measure(const std::vector<std::string>& ids,
                       const std::optional<std::filesystem::path>& figures_dir,
                       const std::string& arg) {
  if (ids.empty()) return measure_all(0, figures_dir);
  std::vector<const Check*> chosen;
  for (const auto& id : ids) {
    const auto* c = find(id);
    if (!c) throw ArgumentError(arg, fmt::format("unknown check '{}' (see `vibook list`)", id));
    chosen.push_back(c);
  }
  claims::Ledger ledger;
  for (const auto& rs : run_checks(chosen))
    for (const auto& r : rs) ledger.record(r);
  return ledger;
}

}  // namespace vibook::figures

namespace vibook::figures {

void write_claim_tables(const claims::Ledger& ledger, const nlohmann::json& provenance,
                        const std::filesystem::path& dir, const std::string& arg) {
  const auto write = [&](const std::string& name, const std::string& text) {
    write_output_file((dir / name).string(), text, arg);
  };
  int pending = 0;
  for (const auto& row : ledger.rows()) pending += row.result.status == claims::Status::pending;
  write("claims.html", ledger.to_html());
  write("summary.html", ledger.to_summary_html());
  write("provenance.html", claims::provenance_html(provenance, pending));
  for (const char* paper : {"S", "V", "SS", "A"})
    write(fmt::format("claims-{}.html", paper), ledger.to_html(paper));
  // Each claim with the check naming the fewest claims (the first of equals in order).
  std::map<std::string, const Check*> owner;
  for (const auto* list : {&registry(), &long_studies()})
    for (const auto& c : *list)
      for (const auto& id : c.claims) {
        const auto it = owner.find(id);
        if (it == owner.end() || c.claims.size() < it->second->claims.size()) owner[id] = &c;
      }
  for (const auto* list : {&registry(), &long_studies()}) {
    for (const auto& c : *list) {
      std::vector<std::string> own, elsewhere;
      for (const auto& id : c.claims) (owner[id] == &c ? own : elsewhere).push_back(id);
      std::string html = own.empty() ? std::string() : ledger.to_html({}, own);
      if (!elsewhere.empty()) {
        html +=
            "<p class=\"vibook-claims-elsewhere\">Also measured here, and shown with its own "
            "check:";
        for (const auto& id : elsewhere)
          html += fmt::format(" <a href=\"report.html#claim-{0}\">{0}</a>", id);
        html += ".</p>\n";
      }
      write(c.id + ".html", html);
    }
  }
}

}  // namespace vibook::figures
