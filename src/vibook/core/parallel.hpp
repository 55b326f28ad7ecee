/// \file parallel.hpp
/// \brief parallel_for: run independent tasks on a few threads, rethrowing the first error.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace vibook {

/// Call task(i) for i = 0 .. n−1 on at most `jobs` threads (0: one per hardware thread).
/// Every task runs even if another throws; afterwards the exception of the lowest i that
/// threw is rethrown.
template <class Task>
void parallel_for(std::size_t n, unsigned jobs, Task&& task) {
  if (jobs == 0) jobs = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::exception_ptr> errors(n);
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next++; i < n; i = next++) {
      try {
        task(i);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  const std::size_t threads = std::min<std::size_t>(jobs, n);
  for (std::size_t t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  for (auto& e : errors) {
    if (e) std::rethrow_exception(e);
  }
}

}  // namespace vibook
