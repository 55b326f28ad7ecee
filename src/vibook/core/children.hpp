/// \file children.hpp
/// \brief The child processes vibook starts (a black-box stepper behind the line protocol),
/// each in a process group of its own, so that every way out of vibook ends them and anything
/// they forked: a normal return (the owner's destructor), an error, a timeout, --max-seconds or
/// a signal to vibook (the command's signal thread and watchdog call end_child_groups() before
/// they exit).
#pragma once

#include <sys/types.h>

namespace vibook {

/// Remember a process group to end on the way out (at most 64 at once; more are not
/// remembered, and only their owner ends them). Async-signal-safe.
void register_child_group(pid_t pgid);
/// Forget it (its owner has ended it). Async-signal-safe.
void unregister_child_group(pid_t pgid);
/// SIGKILL every remembered group. Async-signal-safe: for the exit paths that cannot unwind.
void end_child_groups();

}  // namespace vibook
