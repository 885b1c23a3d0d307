// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// run_chunks: numbered pieces of work on several threads, with a deterministic outcome.
#ifndef CVT_2_INTERNAL_PARALLEL_RUN_CHUNKS_H
#define CVT_2_INTERNAL_PARALLEL_RUN_CHUNKS_H

#include <CVT_2/internal/parallel/Interrupt_scope.h>

#include <algorithm>
#include <atomic>
#include <cfenv>
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
#ifdef __linux__
#include <sched.h>
#endif
#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#endif

namespace CVT_2 {
namespace internal {

// The number of threads that "0" (all) stands for. Asked once: glibc reads a file in /sys at
// each call, and every pass of an iteration asks (1 246 reads, a fifth of a 2 000-point job).
inline unsigned hardware_threads() {
  static const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  return threads;
}

// The processors this process may run on (its affinity on Linux), at least 1.
inline unsigned usable_cores() {
#ifdef __linux__
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0) return unsigned(std::max(1, CPU_COUNT(&set)));
#endif
  return hardware_threads();
}

// What the chunks of a pass write as they go (a sum a cell, a list's end an item) must not share
// a cache line with another chunk's: two threads writing one line pass it back and forth between
// their cores at every write ("false sharing"). Outputs kept side by side, one a chunk, are
// therefore aligned to lines of their own: alignas(cache_line) on a struct, or Chunk_vector
// for a list. Two lines of 64 bytes, as x86 processors fetch lines in pairs.
constexpr std::size_t cache_line = 128;

// A std::vector alone on its cache lines: one of the lists the chunks of a pass fill side by side.
template <class T>
struct alignas(cache_line) Chunk_vector : std::vector<T> {
  using std::vector<T>::vector;
  using std::vector<T>::operator=;
};

// Threads kept from one parallel pass to the next for as long as a Scope lives (an
// optimization: lloyd_optimize_2() and lbfgs_optimize_2() open one). An iteration makes several
// passes of a few hundred microseconds to tens of milliseconds: starting threads for each costs
// tens of microseconds, and on a virtual machine an idle core can take longer to wake. A worker
// that finishes a pass spins half a millisecond before it sleeps, so that the next pass, after
// the short serial part of an iteration, finds it awake; workers beyond the processors sleep
// at once.
//
// A pass hands out tickets: a worker takes one, runs the work, and gives it back. The caller
// runs the work too, then withdraws the tickets not taken and waits only for the workers
// inside, so a worker that wakes late costs nothing. Workers run under the caller's
// floating-point environment. Nothing outlives the scope: no thread, no lock at the process's
// exit or in a fork()'s child made outside a scope.
class Worker_pool {
 public:
  // This thread's run_chunks() use the scope's pool until its end, when the workers are joined.
  class Scope;

  // The pool of this thread's innermost scope, or null: no scope, the pool is running a pass
  // (a pass inside a task), or this is a fork()'s child of the pool's process.
  static Worker_pool* available() {
    Worker_pool* pool = current();
    if (!pool || pool->m_busy) return nullptr;
#ifdef CVT_2_HAS_GETPID
    if (pool->m_process != ::getpid()) return nullptr;
#endif
    return pool;
  }

  Worker_pool() = default;
  Worker_pool(const Worker_pool&) = delete;
  Worker_pool& operator=(const Worker_pool&) = delete;

  ~Worker_pool() {
#ifdef CVT_2_HAS_GETPID
    if (m_process != ::getpid()) {  // a fork()'s child: the workers and their waits are the
      m_shared.release();           // parent's; touching them could block
      return;
    }
#endif
    {
      std::lock_guard<std::mutex> lock(m_shared->mutex);
      m_shared->stop = true;
    }
    m_shared->wake.notify_all();
    for (std::thread& t : m_shared->workers) t.join();
  }

  // Runs work() on this thread and up to `helpers` workers at once; returns when all are out
  // of it. `work` must not throw.
  template <class Work>
  void run(unsigned helpers, const Work& work) {
    Shared& sh = *m_shared;
    m_busy = true;
    struct Idle {
      bool& busy;
      ~Idle() { busy = false; }
    } idle{m_busy};
    try {
      while (sh.workers.size() < helpers)
        sh.workers.emplace_back([&sh, index = sh.workers.size()] { serve(sh, index); });
    } catch (const std::exception&) {  // no more threads to be had: with those there are
      helpers = unsigned(sh.workers.size());
    }
    sh.work = &work;
    sh.call = [](const void* w) { (*static_cast<const Work*>(w))(); };
    std::fegetenv(&sh.environment);
    {
      std::lock_guard<std::mutex> lock(sh.mutex);
      sh.state.store(pack(helpers, 0), std::memory_order_release);
    }
    for (unsigned i = 0; i < helpers; ++i) sh.wake.notify_one();
    work();
    // withdraw the tickets not taken, then wait for the workers inside: spin a little, then
    // sleep (a long chunk, or more threads than processors)
    sh.state.fetch_and(~pack(0xffffffffu, 0), std::memory_order_acq_rel);
    for (unsigned k = 0; k < 4096; ++k) {
      if (inside(sh.state.load(std::memory_order_acquire)) == 0) return;
      pause();
    }
    std::unique_lock<std::mutex> lock(sh.mutex);
    sh.done.wait(lock, [&] { return inside(sh.state.load(std::memory_order_acquire)) == 0; });
  }

 private:
  // What the workers share with the caller (left to a fork()'s child untouched).
  struct Shared {
    std::vector<std::thread> workers;
    std::mutex mutex;
    std::condition_variable wake, done;
    std::atomic<std::uint64_t> state{0};  // tickets in the low half, workers inside the high
    const void* work = nullptr;
    void (*call)(const void*) = nullptr;
    std::fenv_t environment;
    bool stop = false;
  };

  static Worker_pool*& current() {
    static thread_local Worker_pool* pool = nullptr;
    return pool;
  }

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

  static bool take_ticket(Shared& sh) {
    std::uint64_t s = sh.state.load(std::memory_order_acquire);
    while (tickets(s) > 0)
      if (sh.state.compare_exchange_weak(s, pack(tickets(s) - 1, inside(s) + 1),
                                         std::memory_order_acq_rel))
        return true;
    return false;
  }

  static void serve(Shared& sh, std::size_t index) {
    using Clock = std::chrono::steady_clock;
    const auto spin = std::chrono::microseconds(index + 1 < usable_cores() ? 500 : 0);
    for (;;) {
      const Clock::time_point spin_end = Clock::now() + spin;
      for (unsigned k = 1; tickets(sh.state.load(std::memory_order_relaxed)) == 0; ++k) {
        pause();
        if (k % 64 == 0 && Clock::now() > spin_end) {
          std::unique_lock<std::mutex> lock(sh.mutex);
          sh.wake.wait(lock, [&] {
            return sh.stop || tickets(sh.state.load(std::memory_order_relaxed)) > 0;
          });
          if (sh.stop) return;
          break;
        }
      }
      if (!take_ticket(sh)) continue;
      std::fesetenv(&sh.environment);
      sh.call(sh.work);
      const std::uint64_t was = sh.state.fetch_sub(pack(0, 1), std::memory_order_acq_rel);
      if (inside(was) == 1 && tickets(was) == 0) {  // the last one out: the caller may sleep
        { std::lock_guard<std::mutex> lock(sh.mutex); }
        sh.done.notify_one();
      }
    }
  }

  std::unique_ptr<Shared> m_shared{new Shared};
  bool m_busy = false;
#ifdef CVT_2_HAS_GETPID
  pid_t m_process = ::getpid();
#endif
};

// A Worker_pool for this thread's run_chunks() until the end of the scope.
class Worker_pool::Scope {
 public:
  Scope() : m_previous(current()) { current() = &m_pool; }
  Scope(const Scope&) = delete;
  Scope& operator=(const Scope&) = delete;
  ~Scope() { current() = m_previous; }

 private:
  Worker_pool m_pool;
  Worker_pool* m_previous;
};

// Calls task(c) for every chunk c in [0, n), on `threads` threads (0: one per core), each
// taking the next chunk from a counter. The caller gives each chunk its own output, so the
// result does not depend on which thread ran what. If tasks throw, the exception of the lowest
// failing chunk is rethrown: chunks below it all run, chunks above it may be skipped, so
// the exception too is the same whatever the threads. The calling thread polls its
// Interrupt_scope before each chunk it runs, as if the chunk had thrown.
template <class Task>
void run_chunks(std::size_t n, unsigned threads, const Task& task) {
  if (threads == 0) threads = hardware_threads();
  // a chunk of cells costs hundreds of microseconds, a chunk of the moves' passes tens: each
  // thread gets two chunks or more
  threads = static_cast<unsigned>(std::min<std::size_t>(threads, n / 2));
  if (threads <= 1) {
    for (std::size_t c = 0; c < n; ++c) {
      Interrupt_scope::poll();
      task(c);
    }
    return;
  }
  std::atomic<std::size_t> next{0}, first_failure{n};
  std::vector<std::exception_ptr> errors(n);
  const auto work = [&] {
    for (std::size_t c; (c = next.fetch_add(1)) < n;) {
      if (c > first_failure.load()) continue;
      try {
        Interrupt_scope::poll();  // a no-op on the workers, which have no scope
        task(c);
      } catch (...) {
        errors[c] = std::current_exception();
        std::size_t f = first_failure.load();
        while (c < f && !first_failure.compare_exchange_weak(f, c)) {
        }
      }
    }
  };
  if (Worker_pool* pool = Worker_pool::available()) {
    pool->run(threads - 1, work);
  } else {
    std::vector<std::thread> helpers;
    try {
      for (unsigned t = 1; t < threads; ++t) helpers.emplace_back(work);
    } catch (const std::exception&) {  // no more threads to be had: with those there are
    }
    work();
    for (std::thread& t : helpers) t.join();
  }
  if (first_failure.load() < n) std::rethrow_exception(errors[first_failure.load()]);
}

// Buffers lent to the threads of a pass, one each, and kept for the next pass: big ones are
// not allocated (and their pages faulted in) again for each chunk. A copy starts empty.
template <class Buffers>
class Buffer_pool {
 public:
  Buffer_pool() = default;
  Buffer_pool(const Buffer_pool&) {}
  Buffer_pool& operator=(const Buffer_pool&) { return *this; }
  std::unique_ptr<Buffers> take() const {
    const std::lock_guard<std::mutex> lock(m_mutex);
    if (m_free.empty()) return std::make_unique<Buffers>();
    std::unique_ptr<Buffers> b = std::move(m_free.back());
    m_free.pop_back();
    return b;
  }
  void give_back(std::unique_ptr<Buffers>& b) const {
    const std::lock_guard<std::mutex> lock(m_mutex);
    m_free.push_back(std::move(b));
  }

 private:
  mutable std::mutex m_mutex;
  mutable std::vector<std::unique_ptr<Buffers>> m_free;
};

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_PARALLEL_RUN_CHUNKS_H
