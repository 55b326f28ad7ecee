/// \file run.hpp
/// \brief `vibook run` as a library call: one problem integrated by one method, the trajectory
/// streamed as CSV (never half-written: core/output_file.hpp).
///
/// The command parses and checks its options into Settings and calls run_trajectory; a C++ user
/// can do the same. The problems are harmonic, pendulum, kepler and relativistic-kepler (Shen &
/// Sun 2025, (3.16)–(3.22)); the methods those of `vibook run --help`: the fixed-step
/// symplectic methods and the generic discrete Euler–Lagrange solver, the splitting methods
/// VI-1 and VI-2 (Shen & Sun §3), and the adaptive EpAVI, AVI1 and AVI2 of Sharma et al. 2022
/// on Kepler (EpAVI in any precision of core/precision.hpp). A setting that does not apply is an
/// ArgumentError naming the option of the command; a step that fails a NumericalError saying
/// where, with the rows written so far kept in FILE.partial.
///
/// Chapter: \ref chapter-vi "variational integrators" (the README's `vibook run`).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace vibook::run {

/// The options of `vibook run`, parsed and checked (their values; which apply to which method
/// is the command's check).
struct Settings {
  std::string problem, method, discrete_lagrangian = "midpoint", csv = "-";
  std::string precision = "double", energy_target = "previous", solver = "closed-form";
  double h = 0.01;
  std::optional<double> t_end, periods, e, c, tau_end, h0, tol, alpha;
  std::optional<unsigned> digits;
  double max_seconds = 0;  ///< 0: no limit
  std::vector<double> q0, p0;
  long long every = 1;
  std::string plan_arg = "--h";  ///< the option named when the step plan is impossible
};

/// What the step loop asks of its caller: the signal recorded since the loop began (0: none),
/// and its name. A recorded signal stops the loop like a failed step, by an Interrupted error.
struct Hooks {
  std::function<int()> pending_signal = [] { return 0; };
  std::function<const char*(int)> signal_name = [](int) { return "a signal"; };
};

/// Integrates the problem of `s` with its method and writes the trajectory to s.csv.
void run_trajectory(const Settings& s, const Hooks& hooks = {});

}  // namespace vibook::run
