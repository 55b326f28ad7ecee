/// \file errors.hpp
/// \brief Typed errors. The command line maps ArgumentError to exit status 2,
/// NumericalError (including SolveError) to exit status 3 and IoError to exit status 4.
#pragma once

#include <stdexcept>
#include <string>

namespace vibook {

/// Outcome of one implicit solve: every solve in vibook reports this.
struct SolveReport {
  double residual = 0.0;  ///< max-norm of the residual at the returned point
  int iterations = 0;     ///< Newton iterations taken
  bool converged = false;
};

/// A user-supplied argument is invalid (command line: exit status 2).
class ArgumentError : public std::invalid_argument {
 public:
  ArgumentError(const std::string& argument, const std::string& message)
      : std::invalid_argument(argument + ": " + message), argument_(argument) {}
  const std::string& argument() const { return argument_; }

 private:
  std::string argument_;
};

/// The one check of a user's argument: throws ArgumentError(argument, message) unless ok.
inline void require_argument(bool ok, const std::string& argument, const std::string& message) {
  if (!ok) throw ArgumentError(argument, message);
}

/// A numerical method could not produce a valid result (command line: exit status 3).
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A run stopped by SIGINT, SIGTERM or SIGHUP (the command exits with 128 + signal after
/// saying where it stopped and what it kept; `vibook run` keeps its rows in FILE.partial).
class Interrupted : public NumericalError {
 public:
  Interrupted(int signal, const std::string& what) : NumericalError(what), signal_(signal) {}
  int signal() const { return signal_; }

 private:
  int signal_;
};

/// An output could not be written: a full disk, a closed pipe, a failed rename (command line:
/// exit status 4).
class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An implicit solve failed to converge, or produced a non-finite value.
class SolveError : public NumericalError {
 public:
  SolveError(const std::string& what, SolveReport report) : NumericalError(what), report_(report) {}
  const SolveReport& report() const { return report_; }

 private:
  SolveReport report_;
};

}  // namespace vibook
