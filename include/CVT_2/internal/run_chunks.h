// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// run_chunks: numbered pieces of work on several threads, with a deterministic outcome.
#ifndef CVT_2_INTERNAL_RUN_CHUNKS_H
#define CVT_2_INTERNAL_RUN_CHUNKS_H

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#include <unistd.h>
#define CVT_2_HAS_GETPID
#endif
#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#endif

namespace CVT_2 {
namespace internal {

// The number of threads that "0" (all) stands for.
inline unsigned hardware_threads() { return std::max(1u, std::thread::hardware_concurrency()); }

// Threads kept from one parallel pass to the next, for the whole process. An iteration makes
// several passes of a few hundred microseconds to tens of milliseconds: starting threads for
// each costs tens of microseconds, and on a virtual machine an idle core can take longer to
// wake. A worker that finishes a pass spins a little before it sleeps, so that the next pass,
// after the short serial part of an iteration, finds it awake.
//
// A pass hands out tickets: a worker takes one, runs the work, and gives it back. The caller
// runs the work too, then withdraws the tickets not taken and waits only for the workers
// inside, so a worker that wakes late costs nothing. A fork()'s child, which has none of the
// parent's workers, starts its own.
class Worker_pool {
 public:
  // Holds the pool for one pass and gives it back at its end.
  class Lease {
   public:
    explicit Lease(Worker_pool* pool) : m_pool(pool) {}
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    ~Lease() {
      if (!m_pool) return;
      std::lock_guard<std::mutex> lock(the_holder().mutex);
      m_pool->m_busy = false;
    }
    Worker_pool* get() const { return m_pool; }

   private:
    Worker_pool* m_pool;
  };

  // The pool of this process, or null when it is busy with another pass (a nested or a
  // concurrent run_chunks(), which then starts threads of its own).
  static Worker_pool* acquire() {
    Holder& holder = the_holder();
    std::lock_guard<std::mutex> lock(holder.mutex);
#ifdef CVT_2_HAS_GETPID
    if (holder.pool && holder.pool->m_process != ::getpid())
      holder.pool.release();  // in a fork()'s child: the workers are the parent's, forget them
#endif
    if (!holder.pool) holder.pool.reset(new Worker_pool);
    if (holder.pool->m_busy) return nullptr;
    holder.pool->m_busy = true;
    return holder.pool.get();
  }

  // Runs work() on this thread and up to `helpers` workers at once; returns when all are out
  // of it. `work` must not throw.
  template <class Work>
  void run(unsigned helpers, const Work& work) {
    while (m_workers.size() < helpers)
      m_workers.emplace_back([this, index = m_workers.size()] { serve(index); });
    m_work = &work;
    m_call = [](const void* w) { (*static_cast<const Work*>(w))(); };
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_state.store(pack(helpers, 0), std::memory_order_release);
    }
    m_wake.notify_all();
    work();
    // withdraw the tickets not taken, then wait for the workers inside
    std::uint64_t s = m_state.load(std::memory_order_acquire);
    while (!m_state.compare_exchange_weak(s, pack(0, inside(s)), std::memory_order_acq_rel)) {
    }
    while (inside(m_state.load(std::memory_order_acquire)) != 0) pause();
  }

  ~Worker_pool() {
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_stop = true;
    }
    m_wake.notify_all();
    for (std::thread& t : m_workers) t.join();
  }

 private:
  struct Holder {
    std::mutex mutex;
    std::unique_ptr<Worker_pool> pool;  // joins the workers at the process's exit
  };
  static Holder& the_holder() {
    static Holder holder;
    return holder;
  }

  // tickets in the low half, workers inside the work in the high half
  static std::uint64_t pack(std::uint64_t tickets, std::uint64_t in) { return in << 32 | tickets; }
  static std::uint64_t tickets(std::uint64_t s) { return s & 0xffffffffu; }
  static std::uint64_t inside(std::uint64_t s) { return s >> 32; }

  static void pause() {
#if defined(__SSE2__) || defined(_M_X64)
    _mm_pause();
#else
    std::this_thread::yield();
#endif
  }

  bool take_ticket() {
    std::uint64_t s = m_state.load(std::memory_order_acquire);
    while (tickets(s) > 0)
      if (m_state.compare_exchange_weak(s, pack(tickets(s) - 1, inside(s) + 1),
                                        std::memory_order_acq_rel))
        return true;
    return false;
  }

  void serve(std::size_t index) {
    using Clock = std::chrono::steady_clock;
    // more threads than cores (asked for): those beyond the cores sleep at once
    const auto spin = std::chrono::microseconds(index + 1 < hardware_threads() ? 500 : 0);
    for (;;) {
      const Clock::time_point spin_end = Clock::now() + spin;
      for (unsigned k = 1; tickets(m_state.load(std::memory_order_relaxed)) == 0; ++k) {
        pause();
        if (k % 64 == 0 && Clock::now() > spin_end) {
          std::unique_lock<std::mutex> lock(m_mutex);
          m_wake.wait(
              lock, [&] { return m_stop || tickets(m_state.load(std::memory_order_relaxed)) > 0; });
          if (m_stop) return;
          break;
        }
      }
      if (!take_ticket()) continue;
      m_call(m_work);
      m_state.fetch_sub(pack(0, 1), std::memory_order_acq_rel);
    }
  }

  std::vector<std::thread> m_workers;
  std::mutex m_mutex;
  std::condition_variable m_wake;
  std::atomic<std::uint64_t> m_state{0};
  const void* m_work = nullptr;
  void (*m_call)(const void*) = nullptr;
  bool m_stop = false;
  bool m_busy = false;
#ifdef CVT_2_HAS_GETPID
  pid_t m_process = ::getpid();
#endif
};

// Calls task(c) for every chunk c in [0, n), on `threads` threads (0: one per core), each
// taking the next chunk from a counter. The caller gives each chunk its own output, so the
// result does not depend on which thread ran what. If tasks throw, the exception of the lowest
// failing chunk is rethrown: chunks below it all run, chunks above it may be skipped, so
// the exception too is the same whatever the threads.
template <class Task>
void run_chunks(std::size_t n, unsigned threads, const Task& task) {
  if (threads == 0) threads = hardware_threads();
  // a chunk of cells costs hundreds of microseconds, a chunk of the moves' passes tens: each
  // thread gets two chunks or more
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
  const Worker_pool::Lease pool(Worker_pool::acquire());
  if (pool.get()) {
    pool.get()->run(threads - 1, work);
  } else {
    std::vector<std::thread> helpers;
    for (unsigned t = 1; t < threads; ++t) helpers.emplace_back(work);
    work();
    for (std::thread& t : helpers) t.join();
  }
  if (first_failure.load() < n) std::rethrow_exception(errors[first_failure.load()]);
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_RUN_CHUNKS_H
