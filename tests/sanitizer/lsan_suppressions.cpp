// LeakSanitizer suppressions of the sanitizer build (compiled into each executable only when
// VIBOOK_SANITIZE is on). Only third-party leaks are listed:
// - Mesa's OSMesa keeps small per-context framebuffer and state objects after
//   OSMesaDestroyContext (measured: a few hundred bytes per render, all allocated inside
//   libOSMesa);
// - CLN (under GiNaC) allocates one object of its own at start-up and never frees it
//   (measured: 26 bytes, allocated inside libcln.so, before main).
// Leaks in vibook's own code are still reported and fail the run.
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libOSMesa.so\nleak:libcln.so\n";
}

// One line of stderr per failure is part of the command line's contract (the CLI tests check
// it): LeakSanitizer's "Suppressions used" summary would add lines of its own.
extern "C" const char* __lsan_default_options() { return "print_suppressions=0"; }
