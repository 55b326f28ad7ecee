// The `vibook` command: list, figure, figures, claims, run.
#include <sys/stat.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <string_view>
#include <system_error>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "signals.hpp"
#include "vibook/claims/ledger.hpp"
#include "vibook/claims/provenance.hpp"
#include "vibook/core/errors.hpp"
#include "vibook/core/output_file.hpp"
#include "vibook/core/parallel.hpp"
#include "vibook/figures/registry.hpp"
#include "vibook/plot/gnuplot.hpp"
#include "vibook/printed/papers.hpp"

namespace fs = std::filesystem;
using namespace vibook;

namespace {

int cmd_list() {
  fmt::print("FIGURES AND CHECKS\n");
  auto print = [](const figures::Check& c, const char* kind) {
    std::string ids;
    for (const auto& id : c.claims) ids += (ids.empty() ? "" : " ") + id;
    fmt::print("  {:<16} {:<7} {}  [claims: {}]\n", c.id, kind, c.title, ids);
  };
  for (const auto& c : figures::registry()) print(c, c.is_figure ? "figure" : "check");
  fmt::print("LONG STUDIES (./build.sh book, or `vibook figure ID`)\n");
  for (const auto& c : figures::long_studies()) print(c, "study");
  // Statuses are measured, never stored: `vibook claims` runs the checks (a few minutes);
  // list only says what there is.
  fmt::print("\nCLAIMS (their status as measured now: `vibook claims`)\n");
  for (const auto& c : claims::catalogue())
    fmt::print("  {:<8} {:<3} {:<14} {}\n", c.id, c.paper, c.where, c.title);
  return cli::kOk;
}

void ensure_writable_dir(const fs::path& dir, const char* arg = "--out") {
  std::error_code ec;
  // The levels this call creates are recorded: a signal before anything is written there
  // removes them again (they are still empty), so an interrupted command leaves no trace.
  std::vector<fs::path> created;
  for (fs::path p = fs::absolute(dir, ec).lexically_normal(); !p.empty() && !fs::exists(p, ec);
       p = p.parent_path()) {
    created.push_back(p);
    if (p == p.parent_path()) break;
  }
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) {
    throw ArgumentError(arg, fmt::format("cannot create directory '{}'", dir.string()));
  }
  for (auto it = created.rbegin(); it != created.rend(); ++it) track_created_directory(*it);
  const fs::path probe = dir / ".vibook-write-test";
  std::ofstream f(probe);
  if (!f) throw ArgumentError(arg, fmt::format("directory '{}' is not writable", dir.string()));
  f.close();
  fs::remove(probe, ec);
}

int cmd_figures(std::vector<std::string> ids, const fs::path& out) {
  std::vector<const figures::Check*> todo;
  if (ids.empty()) {
    for (const auto& c : figures::registry()) {
      if (c.is_figure) todo.push_back(&c);
    }
    // A long study without a figure (field-audit-galerkin) is a check: `vibook claims` runs it.
    if (figures::long_studies_enabled())
      for (const auto& c : figures::long_studies())
        if (c.is_figure) todo.push_back(&c);
  } else {
    for (const auto& id : ids) {
      const auto* c = figures::find(id);
      if (c && !c->is_figure)
        throw ArgumentError("ID", fmt::format("'{}' is a check without a figure: `vibook claims "
                                              "--check {}` runs it",
                                              id, id));
      if (!c) throw ArgumentError("ID", fmt::format("unknown figure '{}' (see `vibook list`)", id));
      if (std::find(todo.begin(), todo.end(), c) != todo.end())
        throw ArgumentError("ID", fmt::format("'{}' is given twice", id));
      todo.push_back(c);
    }
  }
  ensure_writable_dir(out);
  // Before any work: --out itself must not be a symbolic link (followed silently, it would
  // write elsewhere), and OUT/ID, where it exists, must be a directory.
  {
    struct stat st {};
    std::string bare = out.string();  // "link/" would follow the link
    while (bare.size() > 1 && bare.back() == '/') bare.pop_back();
    if (::lstat(bare.c_str(), &st) == 0 && S_ISLNK(st.st_mode))
      throw ArgumentError(
          "--out", "'" + out.string() + "' is a symbolic link; give the directory it points to");
    for (const auto* c : todo) {
      const fs::path d = out / c->id;
      if (::lstat(d.c_str(), &st) == 0 && !S_ISDIR(st.st_mode))
        throw ArgumentError(
            "--out", "'" + d.string() + "' exists and is not a directory; move it away first");
    }
  }
  // Figures are independent: one thread per figure, at most one per core.
  std::vector<figures::FigureOutput> outputs(todo.size());
  parallel_for(todo.size(), 0,
               [&](std::size_t i) { outputs[i] = figures::make_figure(*todo[i], out); });
  int rc = cli::kOk;
  for (const auto& o : outputs) {
    for (const auto& r : o.results) {
      fmt::print("{:<16} {:<8} {}\n", o.id, r.id, claims::to_string(r.status));
    }
    if (o.rendered) {
      fmt::print("{:<16} wrote {}/{{{}.svg,{}.png,claims.json,*.csv}}\n", o.id, o.dir.string(),
                 o.id, o.id);
    } else {
      vibook::cli::eprint(fmt::format("vibook: {}: not rendered: {}\n", o.id, o.render_error));
      rc = cli::kFailure;
    }
  }
  return rc;
}

int cmd_claims(bool json, const std::string& json_out, const std::string& html_dir,
               const std::string& figures_dir, const std::vector<std::string>& only,
               const std::string& commit) {
  // Every output checked before the checks run (they take a minute or more).
  std::optional<fs::path> fdir;
  if (!figures_dir.empty()) {
    if (!fs::is_directory(figures_dir))
      throw ArgumentError("--figures-dir", fmt::format("'{}' is not a directory", figures_dir));
    fdir = figures_dir;
  }
  if (!json_out.empty()) check_output_path(json_out, "--json-out", false);
  if (!html_dir.empty()) ensure_writable_dir(html_dir, "--html-dir");
  // --check ID: only those checks run; every other claim stays pending in this ledger.
  std::vector<const figures::Check*> chosen;
  for (const auto& id : only) {
    const auto* c = figures::find(id);
    if (!c)
      throw ArgumentError("--check", fmt::format("unknown check '{}' (see `vibook list`)", id));
    chosen.push_back(c);
  }
  claims::Ledger ledger;
  if (only.empty()) {
    ledger = figures::measure_all(0, fdir);
  } else {
    for (const auto& rs : figures::run_checks(chosen))
      for (const auto& r : rs) ledger.record(r);
  }
  // What the ledger was measured with (the commit as given, the compiler, the libraries).
  nlohmann::json js = ledger.to_json();
  js["provenance"] = claims::provenance(commit);
  if (!json_out.empty()) write_output_file(json_out, js.dump(2) + "\n", "--json-out");
  if (!html_dir.empty())
    figures::write_claim_tables(ledger, js["provenance"], html_dir, "--html-dir");
  // The ledger is printed whatever else was written (--json-out and --html-dir write "also").
  if (json)
    std::cout << js.dump(2) << '\n';
  else
    std::cout << ledger.to_table();
  return cli::kOk;
}

// `vibook displays`: the papers' displayed formulas as vibook finds them in their text (and,
// with --inline, the inline formulas), the list the book's formula tables have one row per.
int cmd_displays(const std::vector<std::string>& papers, bool with_inline, bool json,
                 const std::string& json_out) {
  std::vector<printed::Paper> which;
  for (const auto& k : papers) {
    try {
      which.push_back(printed::paper_from_key(k));
    } catch (const std::invalid_argument&) {
      throw ArgumentError("--paper", fmt::format("'{}' is not a paper (S, V or SS)", k));
    }
  }
  if (which.empty()) which = {printed::Paper::S, printed::Paper::V, printed::Paper::SS};
  if (!json_out.empty()) check_output_path(json_out, "--json-out", false);
  nlohmann::json out = nlohmann::json::array();
  std::string table;
  for (printed::Paper p : which) {
    std::vector<const printed::Display*> all;
    for (const auto& d : printed::displays(p)) all.push_back(&d);
    if (with_inline)
      for (const auto& d : printed::inline_formulas(p)) all.push_back(&d);
    for (const auto* d : all) {
      out.push_back({{"paper", std::string(printed::key(p))},
                     {"id", d->id()},
                     {"label", d->label()},
                     {"place", d->place()},
                     {"number", d->number},
                     {"line", d->line},
                     {"section", d->section},
                     {"context", d->context},
                     {"inline", d->inline_math},
                     {"latex", d->latex}});
      std::string head = d->latex.substr(0, 70);
      for (auto& ch : head)
        if (ch == '\n') ch = ' ';
      table += fmt::format("{:<3} {:<8} {:<40.40} {}{}\n", printed::key(p), d->id(),
                           d->section + (d->context.empty() ? "" : " / " + d->context), head,
                           d->latex.size() > 70 ? "…" : "");
    }
  }
  if (!json_out.empty()) write_output_file(json_out, out.dump(2) + "\n", "--json-out");
  if (json)
    std::cout << out.dump(2) << '\n';
  else if (json_out.empty())
    std::cout << table;
  return cli::kOk;
}

// The subcommands, for the message about an unknown one.
constexpr const char* kCommands[] = {"list", "figure",   "figures", "claims",
                                     "run",  "modified", "verify",  "displays"};

}  // namespace

namespace vibook::cli {
namespace {
std::string& command_line_storage() {
  static std::string s;
  return s;
}
}  // namespace
const std::string& command_line() { return command_line_storage(); }
std::string one_line(const std::string& text) {
  // A progress line (carriage return, escape) is drawn as it is.
  if (text.empty() || text[0] == '\r' || text[0] == '\033') return text;
  const bool newline = text.back() == '\n';
  std::string body = text.substr(0, text.size() - (newline ? 1 : 0));
  for (char& c : body)
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  if (body.size() > kMaxMessage) {
    // The beginning (what failed, which argument) and the end (why) are kept, the middle (an
    // echoed argument, a state) is cut, at character boundaries (not inside a UTF-8
    // sequence), and the cut says so.
    std::size_t head = 150, tail = body.size() - 120;
    while (head > 0 && (static_cast<unsigned char>(body[head]) & 0xC0) == 0x80) --head;
    while (tail < body.size() && (static_cast<unsigned char>(body[tail]) & 0xC0) == 0x80) ++tail;
    body = body.substr(0, head) + fmt::format(" [... {} characters cut ...] ", tail - head) +
           body.substr(tail);
  }
  return newline ? body + '\n' : body;
}

void eprint(const std::string& message) {
  const std::string text = one_line(message);
  // fwrite on a closed descriptor sets the error flag and returns; nothing is thrown.
  (void)std::fwrite(text.data(), 1, text.size(), stderr);
  (void)std::fflush(stderr);
  std::clearerr(stderr);
}
void set_command_line(int argc, char** argv) {
  std::string s = "vibook";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool plain = !a.empty() && a.find_first_not_of(
                                         "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                         "0123456789-_.,/=+:") == std::string::npos;
    if (plain) {
      s += " " + a;
    } else {
      std::string q = "'";
      for (char c : a) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
      s += " " + q + "'";
    }
  }
  command_line_storage() = s;
}
}  // namespace vibook::cli

// Help and version text must have arrived too (`vibook --help > /dev/full` is status 4).
int help_exit(int rc) {
  try {
    vibook::check_standard_output();
  } catch (const std::exception& e) {
    vibook::cli::eprint(std::string("vibook: I/O error: ") + e.what() + "\n");
    return vibook::cli::kIo;
  }
  return rc;
}

int main(int argc, char** argv) {
  // A closed pipe (`vibook … | head -1`) is a write error, status 4, not death by SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  // SIGINT, SIGTERM, SIGHUP: temporaries removed, status 128 + N (before any thread starts).
  vibook::cli::start_signal_thread();
  vibook::cli::set_command_line(argc, argv);
  CLI::App app{
      "vibook — variational integrators, checked against their papers.\n"
      "Exit status: 0 success, 1 other failure (gnuplot missing), 2 bad argument, 3 numerical "
      "failure, 4 an output could not be written, 5 `vibook verify`: a verdict failed."};
  app.set_version_flag("--version", std::string("vibook ") + VIBOOK_VERSION);
  app.require_subcommand(1);

  app.add_subcommand("list", "List every figure, check and claim (instant; statuses: `claims`)");

  auto* fig = app.add_subcommand(
      "figure", "Regenerate the named figures: DIR/ID/ holds CSV, ID.svg, ID.png, claims.json");
  std::vector<std::string> fig_ids;
  std::string fig_out = "vibook-figures";
  fig->add_option("ID", fig_ids, "figure IDs (see `vibook list`)")->required();
  fig->add_option("--out", fig_out, "output directory (default ./vibook-figures)");

  auto* figs = app.add_subcommand("figures", "Regenerate every figure, in parallel");
  std::string figs_out = "vibook-figures";
  figs->add_option("--out", figs_out, "output directory (default ./vibook-figures)");

  auto* cl = app.add_subcommand("claims", "Run every claim check and print the ledger");
  bool cl_json = false;
  std::string cl_json_out, cl_html_dir, cl_figures_dir;
  cl->add_flag("--json", cl_json, "print the ledger as JSON");
  std::vector<std::string> cl_only;
  cl->add_option("--check", cl_only,
                 "run only these checks (IDs of `vibook list`, repeatable); the other claims are "
                 "reported pending");
  cl->add_option("--json-out", cl_json_out,
                 "also write the JSON ledger to this file (the ledger is still printed)");
  cl->add_option("--html-dir", cl_html_dir,
                 "also write the book's HTML claims tables into this directory");
  std::string cl_commit;
  cl->add_option("--commit", cl_commit,
                 "the source commit to record with the ledger (its provenance in the JSON and "
                 "the book's landing page); the book build passes git's hash and date");
  cl->add_option("--figures-dir", cl_figures_dir,
                 "read the results of the figures from DIR/ID/claims.json (written by `vibook "
                 "figures --out DIR` of this build) instead of running them again");

  auto* disp = app.add_subcommand(
      "displays",
      "List the papers' displayed formulas as vibook reads them from the papers' text (the rows "
      "of the book's formula tables)");
  std::vector<std::string> disp_papers;
  bool disp_inline = false, disp_json = false;
  std::string disp_json_out;
  disp->add_option("--paper", disp_papers, "S, V or SS (repeatable; default all three)");
  disp->add_flag("--inline", disp_inline, "also list the inline formulas $…$ of the text");
  disp->add_flag("--json", disp_json,
                 "print JSON: paper, id, label, number, line, section, context, latex");
  disp->add_option("--json-out", disp_json_out, "write the JSON to this file");

  const auto run = cli::add_run_command(app);
  const auto modified = cli::add_modified_command(app);
  const auto verify = cli::add_verify_command(app);

  // A first word that is neither an option nor a command: say which word.
  if (argc > 1 && argv[1][0] != '-') {
    const std::string_view word = argv[1];
    bool known = false;
    for (const char* c : kCommands) known = known || word == c;
    if (!known) {
      vibook::cli::eprint(fmt::format(
          "vibook: error: unknown command '{}' (commands: list, figure, figures, claims, "
          "run, modified, verify, displays; see `vibook --help`)\n",
          word));
      return cli::kBadArgument;
    }
    // An unknown option is named before CLI11 would complain about a missing required one.
    CLI::App* sub = app.get_subcommand(std::string(word));
    for (int i = 2; i < argc; ++i) {
      const std::string_view tok = argv[i];
      if (tok.size() < 2 || tok[0] != '-' || (tok[1] >= '0' && tok[1] <= '9') || tok[1] == '.')
        continue;  // a value: "-", "-0.1"
      const std::string name(tok.substr(0, tok.find('=')));
      if (name == "-h" || name == "--help" || sub->get_option_no_throw(name) != nullptr) continue;
      // A value that begins with '-' (an expression such as '-v^2/2 - q^2/2') after an option:
      // say how to give it, and show at most 60 characters of it.
      const std::string prev = i > 2 ? std::string(argv[i - 1]) : std::string();
      const bool looks_like_value =
          name.find_first_of(" ^*/()+") != std::string::npos && prev.rfind("--", 0) == 0 &&
          prev.find('=') == std::string::npos && sub->get_option_no_throw(prev) != nullptr;
      const std::string shown = name.size() > 60 ? name.substr(0, 60) + "..." : name;
      if (looks_like_value) {
        vibook::cli::eprint(fmt::format(
            "vibook: error: {}: its value '{}' begins with '-' and was read as an option; write "
            "{}='{}'\n",
            prev, shown, prev, shown));
        return cli::kBadArgument;
      }
      vibook::cli::eprint(fmt::format(
          "vibook: error: unknown option '{}' of `vibook {}` (see `vibook {} --help`)\n", shown,
          word, word));
      return cli::kBadArgument;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return help_exit(app.exit(e));
  } catch (const CLI::CallForAllHelp& e) {
    return help_exit(app.exit(e));
  } catch (const CLI::CallForVersion& e) {
    return help_exit(app.exit(e));
  } catch (const CLI::ParseError& e) {
    std::string msg = e.what();
    for (auto& c : msg) {
      if (c == '\n') c = ' ';
    }
    vibook::cli::eprint(fmt::format("vibook: error: {} (see `vibook --help`)\n", msg));
    return cli::kBadArgument;
  }

  try {
    int rc = cli::kOk;
    if (app.got_subcommand("list"))
      rc = cmd_list();
    else if (app.got_subcommand("figure"))
      rc = cmd_figures(fig_ids, fig_out);
    else if (app.got_subcommand("figures"))
      rc = cmd_figures({}, figs_out);
    else if (app.got_subcommand("claims"))
      rc = cmd_claims(cl_json, cl_json_out, cl_html_dir, cl_figures_dir, cl_only, cl_commit);
    else if (app.got_subcommand("modified"))
      rc = modified();
    else if (app.got_subcommand("verify"))
      rc = verify();
    else if (app.got_subcommand("displays"))
      rc = cmd_displays(disp_papers, disp_inline, disp_json, disp_json_out);
    else
      rc = run();
    // Whatever went to standard output must have arrived (a full disk, a closed pipe).
    check_standard_output();
    return rc;
  } catch (const ArgumentError& e) {
    vibook::cli::eprint(fmt::format("vibook: error: {}\n", e.what()));
    return cli::kBadArgument;
  } catch (const Interrupted& e) {
    vibook::cli::eprint(fmt::format("vibook: {}\n", e.what()));
    return 128 + e.signal();
  } catch (const NumericalError& e) {
    vibook::cli::eprint(fmt::format("vibook: numerical failure: {}\n", e.what()));
    return cli::kNumerical;
  } catch (const IoError& e) {
    vibook::cli::eprint(fmt::format("vibook: I/O error: {}\n", e.what()));
    return cli::kIo;
  } catch (const std::system_error& e) {  // fmt's and std::filesystem's write errors
    vibook::cli::eprint(fmt::format("vibook: I/O error: {}\n", e.what()));
    return cli::kIo;
  } catch (const std::exception& e) {
    vibook::cli::eprint(fmt::format("vibook: error: {}\n", e.what()));
    return cli::kFailure;
  }
}
