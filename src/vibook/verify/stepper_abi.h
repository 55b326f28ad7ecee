/* vibook's black-box stepper ABI, version 2 (version 1 still accepted): how `vibook verify
 * --stepper-lib LIB.so` calls a one-step method compiled elsewhere (a C, C++, Fortran or Rust
 * library), so that its order, symplecticity, reversibility and energy are measured against
 * Hamilton's equations of the system it is meant for (`--problem` or `--hamiltonian`), never
 * against the method itself.
 *
 * The library exports four functions with C linkage; vibook resolves them with dlsym and checks
 * the version before any work:
 *
 *   int   vibook_stepper_abi_version(void);
 *       returns the version the library implements: 1, or 2 (VIBOOK_STEPPER_ABI_VERSION).
 *   void* vibook_stepper_create(int dof, const char* arg);
 *       one stepper for a system with `dof` degrees of freedom (1–6); `arg` is the text of
 *       --stepper-arg ("" when not given), e.g. the name of the method or of the system among
 *       several the library holds. Returns a context pointer, or NULL when it cannot (say why
 *       through vibook_stepper_message(NULL) if the library defines it).
 *   int   vibook_stepper_step(void* context, double h, double* q, double* p);
 *       one step of size h (h > 0) from (q, p), in place: q and p each have `dof` entries.
 *       Returns 0 on success; anything else is a failure (an implicit solve that did not
 *       converge, a step outside the method's domain), reported as a numerical failure with the
 *       step size and the state. Must not keep the pointers. vibook also calls it on states
 *       near the trajectory (to difference the map for its Jacobian) and with p reversed (for
 *       reversibility).
 *   void  vibook_stepper_destroy(void* context);
 *
 * Version 2 adds the time, for a time-dependent system (t in --hamiltonian or --potential):
 *   int   vibook_stepper_step_t(void* context, double t, double h, double* q, double* p);
 *       one step of size h from (q, p) at the time t (the step's start), in place; otherwise as
 *       vibook_stepper_step. Required in version 2, and then the only step vibook calls (with
 *       t = 0 at the initial state and advancing by h, also for an autonomous system); the
 *       step may then return a failure for vibook_stepper_step or leave it out.
 * A library of version 1 is refused for a time-dependent system, with that reason.
 *
 * Optional:
 *   const char* vibook_stepper_message(void* context);
 *       the reason for the last failure (context NULL: for vibook_stepper_create), or NULL.
 *
 * The library is loaded into vibook's process: a crash in it ends vibook. A stepper in another
 * language, or one to keep at arm's length, goes through `--stepper-cmd` and its line protocol
 * instead (book, chapter "Verifying your own discrete Lagrangian", section "Any stepper as a
 * black box").
 */
#ifndef VIBOOK_STEPPER_ABI_H
#define VIBOOK_STEPPER_ABI_H

#define VIBOOK_STEPPER_ABI_VERSION 2

#ifdef __cplusplus
extern "C" {
#endif

int vibook_stepper_abi_version(void);
void* vibook_stepper_create(int dof, const char* arg);
int vibook_stepper_step(void* context, double h, double* q, double* p);
int vibook_stepper_step_t(void* context, double t, double h, double* q, double* p);
void vibook_stepper_destroy(void* context);
const char* vibook_stepper_message(void* context);

#ifdef __cplusplus
}
#endif

#endif /* VIBOOK_STEPPER_ABI_H */
