/// \file black_box.hpp
/// \brief A one-step method vibook did not write, as a black box: n steps of size h from
/// (q, p), in place. StepperLibrary reaches a shared library through the C ABI of
/// stepper_abi.h (loaded with dlopen, into this process); `vibook verify --stepper-lib` and the
/// field audit's Boost.Odeint rows use it. (The line protocol of `--stepper-cmd` is the
/// command's.)
///
/// Chapter: \ref chapter-verify (section "Any stepper as a black box").
#pragma once

#include <functional>
#include <string>

namespace vibook::verify {

/// A black-box stepper.
class BlackBox {
 public:
  virtual ~BlackBox() = default;
  /// n steps of size h from (q, p), in place; a failure is a NumericalError saying why.
  virtual void run(double h, long long n, double* q, double* p) = 0;
  /// n steps of size h from (q, p), in place, `each` called after every step (q, p then hold
  /// its state): n single steps, unless the stepper can answer every state of the run at once.
  virtual void every(double h, long long n, double* q, double* p,
                     const std::function<void()>& each) {
    for (long long k = 0; k < n; ++k) {
      run(h, 1, q, p);
      each();
    }
  }
  /// The stepper takes the time (line protocol 2): it can step a time-dependent system.
  virtual bool takes_time() const { return false; }
  /// The start time of the next run (or of the next `every`), for a stepper that takes_time().
  virtual void set_time(double /*t*/) {}
};

/// A library behind the C ABI (stepper_abi.h), loaded into this process. The constructor
/// throws ArgumentError naming --stepper-lib when the file is missing, does not load, lacks a
/// symbol, speaks another ABI version or its create returns NULL (with its message).
class StepperLibrary final : public BlackBox {
 public:
  StepperLibrary(const std::string& path, const std::string& arg, int dof);
  ~StepperLibrary() override;
  StepperLibrary(const StepperLibrary&) = delete;
  StepperLibrary& operator=(const StepperLibrary&) = delete;
  void run(double h, long long n, double* q, double* p) override;
  /// The ABI version the library implements (1 or 2).
  int abi_version() const { return version_; }
  bool takes_time() const override { return version_ >= 2; }
  void set_time(double t) override { t_ = t; }

 private:
  std::string reason(void* context) const;
  void* handle_ = nullptr;
  void* context_ = nullptr;
  int version_ = 1;
  double t_ = 0;  ///< version 2: the start time of the next run
  int (*step_)(void*, double, double*, double*) = nullptr;
  int (*step_t_)(void*, double, double, double*, double*) = nullptr;
  void (*destroy_)(void*) = nullptr;
  const char* (*message_)(void*) = nullptr;
};

/// The child's side of an isolated library (`vibook verify --stepper-lib`): load it, announce
/// `ready abi V` (V the library's ABI version; `error REASON` when it cannot be loaded), then
/// answer the line protocol's requests on file descriptors 0 and `answers`, numbers in 17
/// significant digits (exact): protocol 1 for a library of version 1, protocol 2 (the start
/// time first) for one of version 2.
/// Anything the library prints on its standard output goes to the captured standard error.
/// Returns the child's exit status: 0 at the end of its input, 2 when the library did not load.
int serve_stepper_library(const std::string& path, const std::string& arg, int dof);

}  // namespace vibook::verify
