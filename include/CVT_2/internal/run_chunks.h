// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// run_chunks: numbered pieces of work on several threads, with a deterministic outcome.
#ifndef CVT_2_INTERNAL_RUN_CHUNKS_H
#define CVT_2_INTERNAL_RUN_CHUNKS_H

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace CVT_2 {
namespace internal {

// The number of threads that "0" (all) stands for.
inline unsigned hardware_threads() { return std::max(1u, std::thread::hardware_concurrency()); }

// Calls task(c) for every chunk c in [0, n), on `threads` threads (0: one per core), each
// taking the next chunk from a counter. The caller gives each chunk its own output, so the
// result does not depend on which thread ran what. If tasks throw, the exception of the lowest
// failing chunk is rethrown: chunks below it all run, chunks above it may be skipped, so
// the exception too is the same whatever the threads.
template <class Task>
void run_chunks(std::size_t n, unsigned threads, const Task& task) {
  if (threads == 0) threads = hardware_threads();
  // A thread costs tens of microseconds to start, a chunk of cells hundreds to run, a chunk of
  // the moves' passes tens: each thread gets two chunks or more.
  threads = static_cast<unsigned>(std::min<std::size_t>(threads, n / 2));
  if (threads <= 1) {
    for (std::size_t c = 0; c < n; ++c) task(c);
    return;
  }
  std::atomic<std::size_t> next{0}, first_failure{n};
  std::vector<std::exception_ptr> errors(n);
  const auto work = [&] {
    for (std::size_t c; (c = next.fetch_add(1)) < n;) {
      if (c > first_failure.load()) continue;
      try {
        task(c);
      } catch (...) {
        errors[c] = std::current_exception();
        std::size_t f = first_failure.load();
        while (c < f && !first_failure.compare_exchange_weak(f, c)) {
        }
      }
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  if (first_failure.load() < n) std::rethrow_exception(errors[first_failure.load()]);
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_RUN_CHUNKS_H
