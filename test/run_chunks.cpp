// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Tests of run_chunks() and the workers a Worker_pool::Scope keeps between passes: every chunk
// once, the lowest failing chunk's exception, nested and concurrent passes, the caller's
// floating-point environment, a fork()'s child.
#include <CVT_2/internal/parallel/run_chunks.h>

#include <catch2/catch.hpp>

#include <atomic>
#include <cfenv>
#include <chrono>
#include <cstdlib>
#include <mutex>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

namespace {

// Runs `passes` passes of n chunks on `threads` threads; every chunk must run once a pass.
void check_passes(std::size_t n, unsigned threads, int passes) {
  std::vector<std::atomic<int>> runs(n);
  for (int pass = 1; pass <= passes; ++pass) {
    CVT_2::internal::run_chunks(n, threads, [&](std::size_t c) { runs[c].fetch_add(1); });
    for (std::size_t c = 0; c < n; ++c)
      if (runs[c].load() != pass)
        FAIL("chunk " << c << " of " << n << " ran " << runs[c].load() << " times in " << pass
                      << " passes");
  }
}

// Runs `passes` passes of 8 chunks on two threads, where the thread that takes chunk 0 waits (5 s
// at most) for another thread to run a chunk: the thread ids that ran chunks, two unless no
// second thread came, or none if a chunk ran twice or not at all.
std::set<std::thread::id> two_thread_passes(int passes) {
  std::vector<std::atomic<int>> runs(8);
  std::set<std::thread::id> ids;
  std::mutex mutex;
  for (int pass = 1; pass <= passes; ++pass) {
    std::set<std::thread::id> in_pass;
    CVT_2::internal::run_chunks(8, 2, [&](std::size_t c) {
      runs[c]++;
      const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(5);
      for (bool first = true;; first = false) {
        {
          const std::lock_guard<std::mutex> lock(mutex);
          if (first) in_pass.insert(std::this_thread::get_id());
          if (c != 0 || in_pass.size() >= 2 || std::chrono::steady_clock::now() > give_up) break;
        }
        std::this_thread::sleep_for(std::chrono::microseconds(50));
      }
    });
    ids.insert(in_pass.begin(), in_pass.end());
    for (std::atomic<int>& r : runs)
      if (r.load() != pass) return {};
  }
  return ids;
}

}  // namespace

TEST_CASE("run_chunks runs every chunk once a pass, pass after pass, on any number of threads",
          "[threads]") {
  for (bool scope : {false, true}) {
    std::optional<CVT_2::internal::Worker_pool::Scope> pool;
    if (scope) pool.emplace();
    for (unsigned threads : {0u, 1u, 2u, 3u, 8u})
      for (std::size_t n : {0, 1, 2, 3, 4, 7, 64}) {
        CAPTURE(scope, threads, n);
        check_passes(n, threads, scope ? 500 : 50);
      }
  }
}

TEST_CASE("run_chunks runs chunks on two threads, with the scope's workers or without",
          "[threads]") {
  CHECK(two_thread_passes(5).size() >= 2);  // a thread started for each pass
  const CVT_2::internal::Worker_pool::Scope pool;
  CHECK(two_thread_passes(5).size() == 2);  // the caller and the scope's worker
}

TEST_CASE("run_chunks rethrows the lowest failing chunk's exception, on the pool or not",
          "[threads]") {
  for (bool scope : {false, true}) {
    std::optional<CVT_2::internal::Worker_pool::Scope> pool;
    if (scope) pool.emplace();
    for (unsigned threads : {1u, 2u, 4u})
      for (int pass = 0; pass < 100; ++pass) {
        CAPTURE(scope, threads, pass);
        std::atomic<int> below{0};
        try {
          CVT_2::internal::run_chunks(16, threads, [&](std::size_t c) {
            if (c == 5 || c == 9 || c == 15) throw std::runtime_error("chunk " + std::to_string(c));
            if (c < 5) below.fetch_add(1);
          });
          FAIL("no exception");
        } catch (const std::runtime_error& e) {
          CHECK(std::string(e.what()) == "chunk 5");
        }
        CHECK(below.load() == 5);  // every chunk below the failing one ran
      }
    check_passes(16, 2, 10);  // and the pool still works
  }
}

TEST_CASE("run_chunks inside run_chunks, and from several threads at once", "[threads]") {
  // a pass inside a task finds the pool busy, or no pool on a worker: threads of its own
  const CVT_2::internal::Worker_pool::Scope pool;
  std::vector<std::atomic<int>> runs(8 * 6);
  CVT_2::internal::run_chunks(8, 2, [&](std::size_t outer) {
    CVT_2::internal::run_chunks(6, 2, [&](std::size_t inner) { runs[outer * 6 + inner]++; });
  });
  for (std::size_t i = 0; i < runs.size(); ++i) CHECK(runs[i].load() == 1);

  std::vector<std::thread> callers;
  std::atomic<int> failures{0};
  for (int t = 0; t < 3; ++t)
    callers.emplace_back([&failures, t] {
      std::optional<CVT_2::internal::Worker_pool::Scope> own;
      if (t > 0) own.emplace();  // one thread without a scope, two with their own
      std::vector<std::atomic<int>> counts(10);
      for (int pass = 1; pass <= 300; ++pass) {
        CVT_2::internal::run_chunks(10, 2, [&](std::size_t c) { counts[c]++; });
        for (std::atomic<int>& c : counts)
          if (c.load() != pass) failures++;
      }
    });
  for (std::thread& t : callers) t.join();
  CHECK(failures.load() == 0);
}

TEST_CASE("the scope's workers run under the caller's rounding mode", "[threads]") {
  const CVT_2::internal::Worker_pool::Scope pool;
  check_passes(8, 2, 3);  // the workers exist, started under the default rounding
  const int saved = std::fegetround();
  for (int mode : {FE_UPWARD, FE_DOWNWARD, FE_TONEAREST}) {
    REQUIRE(std::fesetround(mode) == 0);
    volatile double one = 1, three = 3;
    const double expected = one / three;
    std::vector<double> values(64);
    for (int pass = 0; pass < 20; ++pass) {
      CVT_2::internal::run_chunks(64, 2, [&](std::size_t c) {
        std::this_thread::sleep_for(std::chrono::microseconds(20));
        values[c] = one / three;
      });
      for (std::size_t c = 0; c < values.size(); ++c)
        if (values[c] != expected) FAIL("rounding mode " << mode << ", chunk " << c);
    }
  }
  std::fesetround(saved);
}

#if defined(__unix__) || defined(__APPLE__)
namespace {

// Forks; the child runs `child` and exits with its status by exit() (not _exit: the process's
// exit must not hang either). The parent waits 60 s at most and returns the child's status.
template <class Child>
int in_child(const Child& child) {
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) std::exit(child());
  int status = 0;
  pid_t done = 0;
  for (int wait = 0; wait < 600 && done == 0; ++wait) {
    done = waitpid(pid, &status, WNOHANG);
    if (done == 0) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  if (done == 0) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    FAIL("the child hangs");
  }
  REQUIRE(WIFEXITED(status));
  return WEXITSTATUS(status);
}

}  // namespace

TEST_CASE("run_chunks in a fork()'s child, made after a scope or inside one", "[threads]") {
  // 1: a chunk ran twice or not at all, 2: on one thread
  const auto passes = [] {
    const std::set<std::thread::id> ids = two_thread_passes(5);
    return ids.empty() ? 1 : ids.size() < 2 ? 2 : 0;
  };
  {
    const CVT_2::internal::Worker_pool::Scope pool;
    check_passes(8, 2, 5);
  }
  CHECK(in_child([&] {
          const CVT_2::internal::Worker_pool::Scope pool;
          return passes();
        }) == 0);
  std::optional<CVT_2::internal::Worker_pool::Scope> pool;
  pool.emplace();
  check_passes(8, 2, 5);
  std::this_thread::sleep_for(std::chrono::milliseconds(5));  // the worker asleep
  // the parent's pool is not the child's: its passes start threads, and the end of its scopes,
  // the parent's one included, leaves the parent's workers alone
  CHECK(in_child(passes) == 0);
  CHECK(in_child([&] {
          {
            const CVT_2::internal::Worker_pool::Scope inner;
            if (const int status = passes()) return status;
          }
          const int status = passes();
          pool.reset();
          return status;
        }) == 0);
  check_passes(8, 2, 5);  // the parent's pool too
}
#endif
