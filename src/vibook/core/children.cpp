// The process groups of the children vibook started (children.hpp).
#include "vibook/core/children.hpp"

#include <signal.h>

#include <array>
#include <atomic>

namespace vibook {

namespace {
std::array<std::atomic<pid_t>, 64> g_groups{};
}  // namespace

void register_child_group(pid_t pgid) {
  for (auto& g : g_groups) {
    pid_t empty = 0;
    if (g.compare_exchange_strong(empty, pgid)) return;
  }
}

void unregister_child_group(pid_t pgid) {
  for (auto& g : g_groups) {
    pid_t want = pgid;
    if (g.compare_exchange_strong(want, 0)) return;
  }
}

void end_child_groups() {
  for (auto& g : g_groups) {
    const pid_t pgid = g.exchange(0);
    if (pgid > 0) ::kill(-pgid, SIGKILL);
  }
}

}  // namespace vibook
