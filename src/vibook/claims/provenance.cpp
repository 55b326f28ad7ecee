// The provenance of a ledger (provenance.hpp): versions from the headers compiled against and
// from the libraries loaded, gnuplot's from the program itself.
#include "vibook/claims/provenance.hpp"

#include <gmp.h>
#include <mpfr.h>

#include <array>
#include <cstdio>
#include <memory>

#include <fmt/format.h>
#include <ginac/version.h>
#include <Eigen/Core>
#include <boost/version.hpp>

#ifndef VIBOOK_VERSION
#define VIBOOK_VERSION "unknown"
#endif
#ifndef VIBOOK_QD_VERSION
#define VIBOOK_QD_VERSION "unknown"
#endif

namespace vibook::claims {

namespace {

// The first line `gnuplot --version` prints, or "not found".
std::string gnuplot_version() {
  std::unique_ptr<FILE, int (*)(FILE*)> p(::popen("gnuplot --version 2>/dev/null", "r"), ::pclose);
  if (!p) return "not found";
  std::array<char, 256> buf{};
  std::string line;
  if (std::fgets(buf.data(), static_cast<int>(buf.size()), p.get())) line = buf.data();
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
  return line.empty() ? "not found" : line;
}

std::string html_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

}  // namespace

nlohmann::json provenance(const std::string& commit) {
  nlohmann::json j;
  j["commit"] = commit.empty() ? "unknown" : commit;
  j["vibook"] = VIBOOK_VERSION;
#if defined(__clang__)
  j["compiler"] = fmt::format("clang++ {}", __clang_version__);
#else
  j["compiler"] = fmt::format("g++ {}", __VERSION__);
#endif
  j["eigen"] =
      fmt::format("{}.{}.{}", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION);
  std::string boost = BOOST_LIB_VERSION;
  for (char& c : boost)
    if (c == '_') c = '.';
  j["boost"] = boost;
  j["ginac"] = fmt::format("{}.{}.{} (loaded {}.{}.{})", GINACLIB_MAJOR_VERSION,
                           GINACLIB_MINOR_VERSION, GINACLIB_MICRO_VERSION, GiNaC::version_major,
                           GiNaC::version_minor, GiNaC::version_micro);
  j["qd"] = VIBOOK_QD_VERSION;
  j["mpfr"] = fmt::format("{} (loaded {})", MPFR_VERSION_STRING, mpfr_get_version());
  j["gmp"] = fmt::format("{}.{}.{} (loaded {})", __GNU_MP_VERSION, __GNU_MP_VERSION_MINOR,
                         __GNU_MP_VERSION_PATCHLEVEL, gmp_version);
  j["fmt"] =
      fmt::format("{}.{}.{}", FMT_VERSION / 10000, FMT_VERSION / 100 % 100, FMT_VERSION % 100);
  j["nlohmann_json"] = fmt::format("{}.{}.{}", NLOHMANN_JSON_VERSION_MAJOR,
                                   NLOHMANN_JSON_VERSION_MINOR, NLOHMANN_JSON_VERSION_PATCH);
  j["gnuplot"] = gnuplot_version();
  return j;
}

std::string provenance_html(const nlohmann::json& p, int pending) {
  auto v = [&p](const char* key) { return html_escape(p.value(key, std::string("unknown"))); };
  std::string s = "<p class=\"vibook-provenance\">Built from commit " + v("commit") + ", vibook " +
                  v("vibook") + ", with " + v("compiler") + "; Eigen " + v("eigen") + ", Boost " +
                  v("boost") + ", GiNaC " + v("ginac") + ", libqd " + v("qd") + ", MPFR " +
                  v("mpfr") + ", GMP " + v("gmp") + ", fmt " + v("fmt") + ", nlohmann-json " +
                  v("nlohmann_json") + "; " + v("gnuplot") +
                  ". The same in <a href=\"claims.json\">claims.json</a> (the whole ledger).</p>\n";
  if (pending > 0)
    s += fmt::format(
        "<p class=\"vibook-partial\"><b>A partial build</b>: {} claim{} {} pending, measured by "
        "long studies this build did not run (<code>./build.sh book</code> runs every one, "
        "<code>vibook claims --check STUDY</code> one); the tables and figures they fill say "
        "so where they stand.</p>\n",
        pending, pending == 1 ? "" : "s", pending == 1 ? "is" : "are");
  else
    s += "<p class=\"vibook-partial\">Every claim was measured in this build, the long studies "
         "included.</p>\n";
  return s;
}

}  // namespace vibook::claims
