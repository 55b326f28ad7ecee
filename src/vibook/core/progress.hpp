/// \file progress.hpp
/// \brief What a long computation is doing now: one stage text per process, set by the
/// symbolic engine and the verification phases, read by the command line's progress line and
/// by its `--max-seconds` message ("stopped after 60 s in: L_mod, jets of order 5 of 8").
#pragma once

#include <mutex>
#include <string>
#include <utility>

namespace vibook::progress {

namespace detail {
struct Stage {
  std::mutex mutex;
  std::string text;
};
inline Stage& current() {
  static Stage s;
  return s;
}
}  // namespace detail

/// Sets the current stage (thread-safe; cheap enough for a loop over orders, not for an
/// inner loop over terms).
inline void set_stage(std::string stage) {
  auto& s = detail::current();
  const std::lock_guard lock(s.mutex);
  s.text = std::move(stage);
}

/// The current stage ("" before any was set).
inline std::string stage() {
  auto& s = detail::current();
  const std::lock_guard lock(s.mutex);
  return s.text;
}

}  // namespace vibook::progress
