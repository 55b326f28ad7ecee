// A black-box stepper behind the C ABI (black_box.hpp, stepper_abi.h).
#include "vibook/verify/black_box.hpp"

#include <dlfcn.h>
#include <sys/stat.h>

#include <fmt/format.h>

#include "vibook/core/errors.hpp"
#include "vibook/verify/stepper_abi.h"

namespace vibook::verify {

StepperLibrary::StepperLibrary(const std::string& path, const std::string& arg, int dof) {
  // A bare name would be searched on the library path; the user means the file.
  const std::string file = path.find('/') == std::string::npos ? "./" + path : path;
  struct stat st {};
  if (::stat(file.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
    throw ArgumentError("--stepper-lib", "'" + path + "' is not a file");
  handle_ = ::dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle_) {
    const char* e = ::dlerror();
    throw ArgumentError("--stepper-lib",
                        "cannot be loaded: " + std::string(e ? e : "dlopen failed"));
  }
  auto need = [&](const char* name) {
    void* s = ::dlsym(handle_, name);
    if (!s)
      throw ArgumentError("--stepper-lib", fmt::format("'{}' does not export {} (the vibook "
                                                       "stepper ABI: vibook/verify/stepper_abi.h)",
                                                       path, name));
    return s;
  };
  auto version = reinterpret_cast<int (*)()>(need("vibook_stepper_abi_version"));
  auto create = reinterpret_cast<void* (*)(int, const char*)>(need("vibook_stepper_create"));
  step_ = reinterpret_cast<int (*)(void*, double, double*, double*)>(need("vibook_stepper_step"));
  destroy_ = reinterpret_cast<void (*)(void*)>(need("vibook_stepper_destroy"));
  message_ = reinterpret_cast<const char* (*)(void*)>(::dlsym(handle_, "vibook_stepper_message"));
  if (const int v = version(); v != VIBOOK_STEPPER_ABI_VERSION)
    throw ArgumentError("--stepper-lib", fmt::format("'{}' implements stepper ABI version {}; "
                                                     "this vibook speaks version {}",
                                                     path, v, VIBOOK_STEPPER_ABI_VERSION));
  context_ = create(dof, arg.c_str());
  if (!context_)
    throw ArgumentError("--stepper-lib",
                        fmt::format("vibook_stepper_create({}, \"{}\") returned NULL{}", dof, arg,
                                    reason(nullptr)));
}

StepperLibrary::~StepperLibrary() {
  if (context_) destroy_(context_);
  if (handle_) ::dlclose(handle_);
}

void StepperLibrary::run(double h, long long n, double* q, double* p) {
  for (long long k = 0; k < n; ++k)
    if (const int status = step_(context_, h, q, p); status != 0)
      throw NumericalError(
          fmt::format("vibook_stepper_step returned {}{}", status, reason(context_)));
}

std::string StepperLibrary::reason(void* context) const {
  const char* m = message_ ? message_(context) : nullptr;
  return m && *m ? std::string(": ") + m : std::string();
}

}  // namespace vibook::verify
