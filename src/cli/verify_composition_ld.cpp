// `vibook verify --composition ld --ld EXPR --coefficients NAME|LIST`: a composition built on
// the user's own typed discrete Lagrangian (vibook/verify/composition_ld_study.cpp measures it);
// here the options are checked before any work and the report printed.
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "args.hpp"
#include "cli.hpp"
#include "verify_composition.hpp"
#include "verify_map.hpp"
#include "vibook/core/output_file.hpp"
#include "vibook/modified/engine.hpp"
#include "vibook/verify/composition_ld_study.hpp"
#include "vibook/verify/expression.hpp"
#include "vibook/verify/method_symbolic.hpp"

namespace vibook::cli {

int run_composition_ld(const CompositionOptions& t, verify::CompositionSpec spec) {
  const CompositionOptions& o = t;
  if (t.ld.empty()) throw ArgumentError("--ld", "is required with --composition ld");
  if (!t.lagrangian.empty() && !t.hamiltonian.empty())
    throw ArgumentError("--hamiltonian",
                        "give the system once: --lagrangian or --hamiltonian, not both");
  if (t.potential.empty() && t.hamiltonian.empty() && t.lagrangian.empty())
    throw ArgumentError("--potential",
                        "is required with --composition ld (or --lagrangian or --hamiltonian): "
                        "the system the composition is measured on");
  // The system: a Hamiltonian (typed, or p^2/2 + V), whose field is the reference's and H the
  // energy; or a typed Lagrangian, through its Legendre transform (set_typed_lagrangian).
  const std::string hamiltonian = !t.lagrangian.empty()   ? ""
                                  : t.hamiltonian.empty() ? "p^2/2 + V(q)"
                                                          : t.hamiltonian;
  int dim = 0;
  if (!t.dim.empty()) {
    dim = static_cast<int>(parse_integer("--dim", t.dim));
    if (dim < 1 || dim > 3) throw ArgumentError("--dim", "must lie in 1..3 with --composition ld");
  }
  std::unique_ptr<verify::TypedDiscreteLagrangian> dl;
  {
    std::lock_guard<std::mutex> lock(modified::ginac_mutex());
    verify::TypedTexts texts{t.ld, t.potential, t.lagrangian, hamiltonian, dim};
    texts.allow_time = t.allow_time;
    dl = std::make_unique<verify::TypedDiscreteLagrangian>(texts);
  }
  if (dl->dim() > 3)
    throw ArgumentError("--ld", fmt::format("is {}-dimensional; --composition ld runs in 1 to 3 "
                                            "dimensions",
                                            dl->dim()));
  const int n = dl->dim();
  const verify::SymbolicUse symbolic = verify::parse_symbolic_use(o.symbolic);
  std::vector<double> q0, p0;
  MapStudy study;
  check_typed_initial_state(o, n, q0, p0, study);
  check_study_options(o, study);
  if (o.json_given) check_output_path(o.json_out, "--json-out", true);
  MapReport rep;
  verify::measure_ld_composition(std::move(spec), *dl,
                                 {o.ld, o.potential, o.lagrangian, o.hamiltonian, q0, p0}, study,
                                 symbolic, rep);
  return rep.finish(o);
}

int run_timed_ld(const CompositionOptions& o) {
  if (!o.lagrangian.empty() && !o.hamiltonian.empty())
    throw ArgumentError("--hamiltonian",
                        "give the system once: --lagrangian or --hamiltonian, not both");
  const std::string hamiltonian = !o.lagrangian.empty()   ? ""
                                  : o.hamiltonian.empty() ? "p^2/2 + V(q)"
                                                          : o.hamiltonian;
  int dim = 0;
  if (!o.dim.empty()) {
    dim = static_cast<int>(parse_integer("--dim", o.dim));
    if (dim < 1 || dim > 3)
      throw ArgumentError("--dim", "must lie in 1..3 for a time-dependent --ld");
  }
  std::unique_ptr<verify::TypedDiscreteLagrangian> dl;
  {
    std::lock_guard<std::mutex> lock(modified::ginac_mutex());
    verify::TypedTexts texts{o.ld, o.potential, o.lagrangian, hamiltonian, dim};
    texts.allow_time = true;
    dl = std::make_unique<verify::TypedDiscreteLagrangian>(texts);
  }
  if (dl->dim() > 3)
    throw ArgumentError("--ld", fmt::format("is {}-dimensional; a time-dependent --ld runs in 1 to "
                                            "3 dimensions",
                                            dl->dim()));
  if (!dl->time_dependent())
    throw ArgumentError("--ld",
                        "uses the time t, but the system (--potential, --lagrangian or "
                        "--hamiltonian) does not: give the system's own time dependence");
  std::vector<double> q0, p0;
  MapStudy study;
  check_typed_initial_state(o, dl->dim(), q0, p0, study);
  check_study_options(o, study);
  study.expected = parse_number("--expected-order", o.expected);
  if (!(study.expected > 0 && study.expected <= verify::kMaxOrder))
    throw ArgumentError("--expected-order",
                        fmt::format("must lie in (0, {:g}]", verify::kMaxOrder));
  if (o.json_given) check_output_path(o.json_out, "--json-out", true);
  MapReport rep;
  verify::measure_timed_ld(*dl, {o.ld, o.potential, o.lagrangian, o.hamiltonian, q0, p0}, study,
                           rep);
  return rep.finish(o);
}

}  // namespace vibook::cli
