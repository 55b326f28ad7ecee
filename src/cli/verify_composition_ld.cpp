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
#include "verify_map.hpp"
#include "verify_routes.hpp"
#include "vibook/core/output_file.hpp"
#include "vibook/verify/composition_ld_study.hpp"
#include "vibook/verify/expression.hpp"
#include "vibook/verify/method_symbolic.hpp"

namespace vibook::cli {

namespace {

// The typed L_d and system of `o` (a Hamiltonian, typed or p^2/2 + V, or a typed Lagrangian),
// checked before any work, in 1 to 3 dimensions; `route` names the route in the messages.
std::unique_ptr<verify::TypedDiscreteLagrangian> typed_ld(const VerifyOptions& o,
                                                          const std::string& ld, const char* route,
                                                          bool allow_time) {
  if (!o.lagrangian.empty() && !o.hamiltonian.empty())
    throw ArgumentError("--hamiltonian",
                        "give the system once: --lagrangian or --hamiltonian, not both");
  // The system: a Hamiltonian (typed, or p^2/2 + V), whose field is the reference's and H the
  // energy; or a typed Lagrangian, through its Legendre transform (set_typed_lagrangian).
  const std::string hamiltonian = !o.lagrangian.empty()   ? ""
                                  : o.hamiltonian.empty() ? "p^2/2 + V(q)"
                                                          : o.hamiltonian;
  const int dim = check_dim(o, 3, fmt::format(" with {}", route));
  std::unique_ptr<verify::TypedDiscreteLagrangian> dl;
  {
    verify::TypedTexts texts{ld, o.potential, o.lagrangian, hamiltonian, dim};
    texts.allow_time = allow_time;
    dl = std::make_unique<verify::TypedDiscreteLagrangian>(texts);
  }
  if (dl->dim() > 3)
    throw ArgumentError(
        "--ld", fmt::format("is {}-dimensional; {} runs in 1 to 3 dimensions", dl->dim(), route));
  return dl;
}

}  // namespace

int run_composition_ld(const VerifyOptions& o, verify::CompositionSpec spec, bool allow_time,
                       const std::string& ld) {
  if (ld.empty()) throw ArgumentError("--ld", "is required with --composition ld");
  if (o.potential.empty() && o.hamiltonian.empty() && o.lagrangian.empty())
    throw ArgumentError("--potential",
                        "is required with --composition ld (or --lagrangian or --hamiltonian): "
                        "the system the composition is measured on");
  const auto dl = typed_ld(o, ld, "--composition ld", allow_time);
  if (dl->ld_uses_t() && !dl->time_dependent())
    throw ArgumentError("--ld",
                        "uses the time t, but the system (--potential, --lagrangian or "
                        "--hamiltonian) does not: give the system's own time dependence");
  const verify::SymbolicUse symbolic = verify::parse_symbolic_use(o.symbolic);
  std::vector<double> q0, p0;
  MapStudy study;
  check_typed_initial_state(o, dl->dim(), q0, p0, study);
  check_study_options(o, study);
  MapReport rep;
  verify::measure_ld_composition(std::move(spec), *dl,
                                 {ld, o.potential, o.lagrangian, o.hamiltonian, q0, p0}, study,
                                 symbolic, rep);
  return rep.finish(o);
}

int run_timed_ld(const VerifyOptions& o) {
  // (measure_timed_ld refuses an --ld with t on a system without it, naming --ld, before any
  // work.)
  const auto dl = typed_ld(o, o.ld, "a time-dependent --ld", true);
  std::vector<double> q0, p0;
  MapStudy study;
  check_typed_initial_state(o, dl->dim(), q0, p0, study);
  check_study_options(o, study);
  study.expected = check_expected_order(o.expected);
  MapReport rep;
  verify::measure_timed_ld(*dl, {o.ld, o.potential, o.lagrangian, o.hamiltonian, q0, p0}, study,
                           rep);
  return rep.finish(o);
}

}  // namespace vibook::cli
