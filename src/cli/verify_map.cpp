// The command's side of the measurements of a one-step map (verify_map.hpp).
#include "verify_map.hpp"

#include <iostream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "vibook/core/output_file.hpp"

namespace vibook::cli {

const TestProblem& find_test_problem(const std::string& name) {
  if (const TestProblem* p = verify::find_problem(name)) return *p;
  throw ArgumentError("--problem", "unknown problem '" +
                                       (name.empty() ? std::string("kepler") : name) +
                                       "' (kepler, pendulum or henon-heiles)");
}

void MapReport::variational_order_not_derived(const std::string& reason) {
  line("variational order", "not derived: " + reason);
  js["variational_order"] = {{"derived", false}, {"reason", reason}};
}

int MapReport::finish(bool json_given, const std::string& json_out) {
  js["verdict"] = {{"passed", failed.empty()}, {"failed", failed}, {"required", required}};
  line("verdict", fmt::format("{} ({})", failed.empty() ? "PASS" : "FAIL",
                              fmt::join(failed.empty() ? required : failed, ", ")));
  std::cout << out.str();
  std::cout.flush();
  const int rc = numerical_failure ? kNumerical : failed.empty() ? kOk : kVerdict;
  if (rc == kVerdict)
    eprint(fmt::format("vibook: verify: FAIL ({}); the report above says why\n",
                       fmt::join(failed, ", ")));
  if (rc == kNumerical) eprint("vibook: error: verify: " + first_error + "\n");
  if (json_given) write_output_file(json_out, js.dump(2) + "\n", "--json-out");
  return rc;
}

}  // namespace vibook::cli
