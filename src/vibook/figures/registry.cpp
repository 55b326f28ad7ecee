#include "vibook/figures/registry.hpp"

#include <algorithm>
#include <atomic>
#include <fstream>
#include <thread>

#include "vibook/plot/gnuplot.hpp"

namespace vibook::figures {

const std::vector<Check>& registry() {
  static const std::vector<Check> all = {check_v_ex1(), vermeeren_fig1()};
  return all;
}

const Check* find(std::string_view id) {
  for (const auto& c : registry()) {
    if (c.id == id) return &c;
  }
  return nullptr;
}

FigureOutput make_figure(const Check& check, const std::filesystem::path& out_root) {
  FigureOutput out;
  out.id = check.id;
  out.dir = out_root / check.id;
  std::filesystem::create_directories(out.dir);
  out.results = check.run(Context{out.dir});
  {
    std::ofstream js(out.dir / "claims.json");
    js << claims::results_to_json(out.results).dump(2) << '\n';
    if (!js) throw std::runtime_error("could not write " + (out.dir / "claims.json").string());
  }
  try {
    plot::render(check.id, out.dir);
    out.rendered = true;
  } catch (const plot::PlotError& e) {
    out.render_error = e.what();
  }
  return out;
}

std::vector<std::vector<claims::ClaimResult>> run_checks(const std::vector<const Check*>& checks,
                                                         unsigned jobs) {
  std::vector<std::vector<claims::ClaimResult>> results(checks.size());
  std::vector<std::exception_ptr> errors(checks.size());
  if (jobs == 0) jobs = std::max(1u, std::thread::hardware_concurrency());
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next++; i < checks.size(); i = next++) {
      try {
        results[i] = checks[i]->run(Context{});
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < std::min<std::size_t>(jobs, checks.size()); ++t)
    pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  for (auto& e : errors) {
    if (e) std::rethrow_exception(e);
  }
  return results;
}

claims::Ledger measure_all(unsigned jobs) {
  std::vector<const Check*> all;
  for (const auto& c : registry()) all.push_back(&c);
  claims::Ledger ledger;
  for (const auto& rs : run_checks(all, jobs)) {
    for (const auto& r : rs) ledger.record(r);
  }
  return ledger;
}

}  // namespace vibook::figures
