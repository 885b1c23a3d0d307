// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Tests of run_chunks() and the workers it keeps between passes: every chunk once, the lowest
// failing chunk's exception, nested and concurrent passes, a fork()'s child.
#include <CVT_2/internal/run_chunks.h>

#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <mutex>
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

}  // namespace

TEST_CASE("run_chunks runs every chunk once a pass, pass after pass, on any number of threads",
          "[threads]") {
  for (unsigned threads : {0u, 1u, 2u, 3u, 8u})
    for (std::size_t n : {0, 1, 2, 3, 4, 7, 64}) {
      CAPTURE(threads, n);
      check_passes(n, threads, 500);
    }
}

TEST_CASE("run_chunks runs chunks on more than one thread", "[threads]") {
  // chunks long enough that the caller cannot run them all before a worker takes one
  std::set<std::thread::id> ids;
  std::mutex mutex;
  for (int pass = 0; pass < 20; ++pass)
    CVT_2::internal::run_chunks(8, 2, [&](std::size_t) {
      std::this_thread::sleep_for(std::chrono::microseconds(300));
      const std::lock_guard<std::mutex> lock(mutex);
      ids.insert(std::this_thread::get_id());
    });
  CHECK(ids.size() >= 2);  // the caller and a worker (any of them, when a test asked for more)
}

TEST_CASE("run_chunks rethrows the lowest failing chunk's exception, on the pool or not",
          "[threads]") {
  for (unsigned threads : {1u, 2u, 4u})
    for (int pass = 0; pass < 200; ++pass) {
      CAPTURE(threads, pass);
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

TEST_CASE("run_chunks inside run_chunks, and from several threads at once", "[threads]") {
  // a nested pass and a concurrent one find the pool busy and start threads of their own
  std::vector<std::atomic<int>> runs(8 * 6);
  CVT_2::internal::run_chunks(8, 2, [&](std::size_t outer) {
    CVT_2::internal::run_chunks(6, 2, [&](std::size_t inner) { runs[outer * 6 + inner]++; });
  });
  for (std::size_t i = 0; i < runs.size(); ++i) CHECK(runs[i].load() == 1);

  std::vector<std::thread> callers;
  std::atomic<int> failures{0};
  for (int t = 0; t < 3; ++t)
    callers.emplace_back([&failures] {
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

#if defined(__unix__) || defined(__APPLE__)
TEST_CASE("run_chunks in a fork()'s child, after the parent kept workers", "[threads]") {
  check_passes(8, 2, 5);  // the parent's pool has a worker
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    // the parent's workers do not exist here: the child's passes must not wait for them, and
    // must still run on two threads
    std::vector<std::atomic<int>> runs(8);
    std::set<std::thread::id> ids;
    std::mutex mutex;
    bool ok = true;
    for (int pass = 1; pass <= 20; ++pass) {
      CVT_2::internal::run_chunks(8, 2, [&](std::size_t c) {
        std::this_thread::sleep_for(std::chrono::microseconds(300));
        runs[c]++;
        const std::lock_guard<std::mutex> lock(mutex);
        ids.insert(std::this_thread::get_id());
      });
      for (std::atomic<int>& r : runs) ok = ok && r.load() == pass;
    }
    _exit(!ok ? 1 : ids.size() < 2 ? 2 : 0);
  }
  int status = 0;
  pid_t done = 0;
  for (int wait = 0; wait < 600 && done == 0; ++wait) {  // 60 s at most
    done = waitpid(child, &status, WNOHANG);
    if (done == 0) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  if (done == 0) {
    kill(child, SIGKILL);
    waitpid(child, &status, 0);
    FAIL("the child hangs");
  }
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);  // 1: a chunk ran twice or not at all, 2: on one thread
  check_passes(8, 2, 5);            // the parent's pool too
}
#endif
