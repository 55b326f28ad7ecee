// The `vibook` command: list, figure, figures, claims, run.
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string_view>
#include <system_error>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "vibook/claims/ledger.hpp"
#include "vibook/claims/provenance.hpp"
#include "vibook/core/errors.hpp"
#include "vibook/core/output_file.hpp"
#include "vibook/figures/registry.hpp"
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
  return kOk;
}

int cmd_figures(const std::vector<std::string>& ids, const fs::path& out) {
  const auto outputs = figures::make_figures(figures::select_figures(ids, "ID"), out, "--out");
  int rc = kOk;
  for (const auto& o : outputs) {
    for (const auto& r : o.results) {
      fmt::print("{:<16} {:<8} {}\n", o.id, r.id, claims::to_string(r.status));
    }
    if (o.rendered) {
      fmt::print("{:<16} wrote {}/{{{}.svg,{}.png,claims.json,*.csv}}\n", o.id, o.dir.string(),
                 o.id, o.id);
    } else {
      vibook::eprint(fmt::format("vibook: {}: not rendered: {}\n", o.id, o.render_error));
      rc = kFailure;
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
  if (!html_dir.empty()) ensure_output_directory(html_dir, "--html-dir");
  // --check ID: only those checks run; every other claim stays pending in this ledger.
  const claims::Ledger ledger = figures::measure(only, fdir, "--check");
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
  return kOk;
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
  if (!json_out.empty()) check_output_path(json_out, "--json-out", false);
  const printed::DisplayListing listing = printed::list_displays(which, with_inline);
  if (!json_out.empty()) write_output_file(json_out, listing.json, "--json-out");
  if (json)
    std::cout << listing.json;
  else if (json_out.empty())
    std::cout << listing.table;
  return kOk;
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
    vibook::eprint(std::string("vibook: I/O error: ") + e.what() + "\n");
    return vibook::kIo;
  }
  return rc;
}

int main(int argc, char** argv) {
  // A closed pipe (`vibook … | head -1`) is a write error, status 4, not death by SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  // SIGINT, SIGTERM, SIGHUP: temporaries removed, status 128 + N (before any thread starts).
  vibook::start_signal_thread();
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
      vibook::eprint(fmt::format(
          "vibook: error: unknown command '{}' (commands: list, figure, figures, claims, "
          "run, modified, verify, displays; see `vibook --help`)\n",
          word));
      return kBadArgument;
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
        vibook::eprint(fmt::format(
            "vibook: error: {}: its value '{}' begins with '-' and was read as an option; write "
            "{}='{}'\n",
            prev, shown, prev, shown));
        return kBadArgument;
      }
      vibook::eprint(fmt::format(
          "vibook: error: unknown option '{}' of `vibook {}` (see `vibook {} --help`)\n", shown,
          word, word));
      return kBadArgument;
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
    vibook::eprint(fmt::format("vibook: error: {} (see `vibook --help`)\n", msg));
    return kBadArgument;
  }

  try {
    int rc = kOk;
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
    vibook::eprint(fmt::format("vibook: error: {}\n", e.what()));
    return kBadArgument;
  } catch (const Interrupted& e) {
    vibook::eprint(fmt::format("vibook: {}\n", e.what()));
    return 128 + e.signal();
  } catch (const NumericalError& e) {
    vibook::eprint(fmt::format("vibook: numerical failure: {}\n", e.what()));
    return kNumerical;
  } catch (const IoError& e) {
    vibook::eprint(fmt::format("vibook: I/O error: {}\n", e.what()));
    return kIo;
  } catch (const std::system_error& e) {  // fmt's and std::filesystem's write errors
    vibook::eprint(fmt::format("vibook: I/O error: {}\n", e.what()));
    return kIo;
  } catch (const std::exception& e) {
    vibook::eprint(fmt::format("vibook: error: {}\n", e.what()));
    return kFailure;
  }
}
