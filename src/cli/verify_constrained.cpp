// `vibook verify --constraint EXPR` (repeatable) with --method rattle|shake or with an --ld: the
// options checked before any work, the measurement of vibook/verify/constrained.hpp, the report.
#include "verify_routes.hpp"

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "args.hpp"
#include "verify_map.hpp"
#include "vibook/core/output_file.hpp"
#include "vibook/verify/expression.hpp"

namespace vibook::cli {

namespace {

// The typed constrained system of `o` (--potential, --constraint, --q0, --p0, --dim) and the
// study's settings, checked before any work; `ld` the --ld text when one is stepped.
std::unique_ptr<verify::TypedDiscreteLagrangian> constrained_system(const VerifyOptions& o,
                                                                    const std::string& ld,
                                                                    std::vector<double>& q0,
                                                                    std::vector<double>& p0,
                                                                    MapStudy& study) {
  if (o.potential.empty())
    throw ArgumentError("--potential",
                        "is required with --constraint: the system is H = |p|^2/2 + V(q) on the "
                        "constraint manifold (type V = 0 for a free particle)");
  if (!o.problem.empty())
    throw ArgumentError("--problem",
                        "names a test problem; --constraint and --potential give the "
                        "system: give one of them");
  for (const std::string& g : o.constraints)
    if (g.find_first_not_of(" \t") == std::string::npos)
      throw ArgumentError("--constraint", "is empty");
  if (o.q0.empty() || o.p0.empty())
    throw ArgumentError(o.q0.empty() ? "--q0" : "--p0",
                        "is required with --constraint: a state on the constraint manifold, "
                        "g(q0) = 0 and G(q0) p0 = 0");
  int dim = 0;
  if (!o.dim.empty()) {
    dim = static_cast<int>(parse_integer("--dim", o.dim));
    if (dim < 2 || dim > verify::kMaxConstrainedDim)
      throw ArgumentError(
          "--dim", fmt::format("must lie in 2..{} with --constraint", verify::kMaxConstrainedDim));
  }
  std::unique_ptr<verify::TypedDiscreteLagrangian> sys;
  {
    verify::TypedTexts texts{ld, o.potential, "", "p^2/2 + V(q)", dim};
    texts.system_only = ld.empty();
    texts.constraints = o.constraints;
    sys = std::make_unique<verify::TypedDiscreteLagrangian>(texts);
  }
  check_typed_initial_state(o, sys->dim(), q0, p0, study);
  check_study_options(o, study);
  return sys;
}

}  // namespace

int run_constrained_typed(const VerifyOptions& o, verify::ConstrainedStep step) {
  const bool del = step == verify::ConstrainedStep::del;
  std::vector<double> q0, p0;
  MapStudy study;
  const auto sys = constrained_system(o, del ? o.ld : std::string(), q0, p0, study);
  study.expected = 2;
  if (o.has("--expected-order") || del) study.expected = check_expected_order(o.expected);
  MapReport rep;
  verify::measure_constrained_typed(*sys, {o.potential, o.ld}, step, q0, p0, study, rep);
  return rep.finish(o);
}

int run_constrained_composition(const VerifyOptions& o, verify::CompositionSpec spec,
                                const std::string& given) {
  std::vector<double> q0, p0;
  MapStudy study;
  const auto sys = constrained_system(o, "", q0, p0, study);
  MapReport rep;
  verify::measure_constrained_composition(spec, *sys, o.potential, q0, p0, study, rep, given);
  return rep.finish(o);
}

}  // namespace vibook::cli
