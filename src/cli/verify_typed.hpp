// `vibook verify`: the options as typed (every route). The study
// of a typed discrete Lagrangian itself is the library's (vibook/verify/ld_study.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "vibook/modified/canonical.hpp"
#include "vibook/verify/expression.hpp"

namespace vibook::cli {

struct VerifyOptions {
  std::string ld, potential, lagrangian, hamiltonian, dim, q0, p0,
      t_end = "5", h_list = "0.2,0.1,0.05,0.025,0.0125", expected = "2", order_tol = "0.1",
      h = "0.05", steps = "100000", modified_order = "2", format = "text", json_out, report, floor,
      max_seconds, composition, coefficients, problem, stepper_lib, stepper_cmd, stepper_arg,
      stepper_timeout, stepper_protocol, method, tableau, splitting, adaptive,
      adaptive_steps = "10000", symbolic = "auto";
  std::vector<std::string> constraints;  ///< --constraint, repeatable
  bool json_given = false, report_given = false, timings = false, symmetric = false,
       progress = false, reference = false;
};

}  // namespace vibook::cli
