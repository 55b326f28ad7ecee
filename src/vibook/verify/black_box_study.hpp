/// \file black_box_study.hpp
/// \brief A black-box stepper (black_box.hpp) as the one-step map of a map study, and the
/// work–precision table that compares it with two methods vibook steps on the same system.
/// `vibook verify --stepper-lib` and `--stepper-cmd` use it; a C++ user can too. Internal: not
/// installed.
///
/// Chapter: \ref chapter-verify (section "Any stepper as a black box").
#pragma once

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "vibook/verify/black_box.hpp"
#include "vibook/verify/expression.hpp"
#include "vibook/verify/map_study.hpp"

namespace vibook::verify {

/// The black box's first step of size h from z0 = (q, p) (`dof` degrees of freedom), before any
/// measurement: a stepper that refuses it or returns a non-finite state is an ArgumentError
/// naming `option` (the option that gave the stepper); one that crashes (StepperKilled) is a
/// NumericalError.
void check_first_step(BlackBox& box, const Eigen::VectorXd& z0, double h, int dof,
                      const std::string& option);

/// The study's one-step map from the black box: MapStudy::step (one step), propagate (a run of
/// the order study, one request) and every (the energy runs' states). A failure, or a
/// non-finite state, is a NumericalError naming the step size, the number of steps and the
/// state they started from. `box` must outlive the study.
void set_black_box_map(MapStudy& s, BlackBox& box, int dof);

/// Work against precision (report only): the black box's error at T against the reference of
/// `rep` (after measure_map), at five step sizes spread log-evenly over the range its order was
/// fitted on (each rounded to T/n), beside the classical Runge–Kutta method (order 4, not
/// symplectic) and, when `separable` (H = |p|²/2 + V), Störmer–Verlet, both stepped by vibook on
/// the typed system `sys`. Steps are the work measure; `timings` adds each run's wall-clock
/// seconds (which makes the report differ from run to run). Nothing when `rep` has no reference
/// or no order fit.
void black_box_work_precision(const MapStudy& s, const TypedDiscreteLagrangian& sys, bool separable,
                              bool timings, MapMeasurement& rep);

/// What a black-box study is told about the stepper and the system it is meant for (the report's
/// first lines and its JSON).
struct BlackBoxSetup {
  bool library = false;     ///< a shared library (ABI) rather than a command
  std::string path;         ///< the library's file or the command line
  std::string arg;          ///< the text passed to vibook_stepper_create (library)
  int abi = 0;              ///< the library's ABI version
  int protocol = 1;         ///< the command's line protocol
  std::string hamiltonian;  ///< H as typed (or the test problem's)
  std::string system_from;  ///< "--hamiltonian", "--potential", "--problem NAME"
  std::string potential;    ///< V of --potential (a constrained system's too)
  std::vector<std::string> constraints;
  std::vector<double> q0, p0;
  bool timings = false;  ///< the work-precision table's seconds
};

/// The study of a black box `box` (already past check_first_step) against the typed system
/// `sys` of `setup`: its map (set_black_box_map), the system's reference (constrained: the
/// index-1 reference, the residuals and the manifold's tangents), the report's first lines, the
/// map study (`s`: settings and the expected order), work against precision where the system is
/// not constrained, and the variational order as not derived (a black box has no discrete
/// Lagrangian). A command answers at the speed of its language: its walk of step counts stops
/// at 1e5 steps a run.
void measure_black_box(BlackBox& box, const TypedDiscreteLagrangian& sys,
                       const BlackBoxSetup& setup, MapStudy s, MapMeasurement& rep);

}  // namespace vibook::verify
