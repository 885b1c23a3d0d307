// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Interrupt_scope: a check that the long loops call every few milliseconds, so that their caller
// can stop them by throwing from it (the Python module's Ctrl-C).
#ifndef CVT_2_INTERNAL_PARALLEL_INTERRUPT_SCOPE_H
#define CVT_2_INTERNAL_PARALLEL_INTERRUPT_SCOPE_H

#include <cstdint>
#include <functional>
#include <utility>

namespace CVT_2 {
namespace internal {

// While a scope lives, poll() on its thread calls `check`, which stops the work by throwing: the
// exception leaves the library's function as its own would, and a triangulation the function was
// changing may be left unfinished, even invalid (generators moved, their flips not yet made):
// the caller destroys it. Polled by run_chunks() before each chunk the calling thread runs, so
// that every parallel pass is covered, and by the long serial loops. Thread-local, like
// Worker_pool::Scope, so that no signature changes for it: worker threads have no scope and
// never call it. `check` may be called very often: it keeps its own pace (by a clock, say).
class Interrupt_scope {
 public:
  explicit Interrupt_scope(std::function<void()> check)
      : m_check(std::move(check)), m_previous(current()) {
    current() = this;
  }
  Interrupt_scope(const Interrupt_scope&) = delete;
  Interrupt_scope& operator=(const Interrupt_scope&) = delete;
  ~Interrupt_scope() { current() = m_previous; }

  static void poll() {
    if (Interrupt_scope* s = current()) s->m_check();
  }

 private:
  static Interrupt_scope*& current() {
    static thread_local Interrupt_scope* scope = nullptr;
    return scope;
  }

  std::function<void()> m_check;
  Interrupt_scope* m_previous;
};

// poll() at every 2^12-th call on this thread: for loops whose steps take a microsecond or less.
inline void poll_interrupt_sometimes() {
  static thread_local std::uint32_t calls = 0;
  if ((++calls & 0xfff) == 0) Interrupt_scope::poll();
}

// Sort traits (CGAL's spatial_sort(), hilbert_sort()) whose comparisons poll now and then: a
// sort of millions of points takes most of a second, and throwing from a comparison leaves the
// range a permutation of itself.
template <class Traits>
struct Interruptible_sort_traits_2 : Traits {
  template <class Less>
  struct Polling_less : Less {
    template <class A, class B>
    bool operator()(const A& a, const B& b) const {
      poll_interrupt_sometimes();
      return Less::operator()(a, b);
    }
  };
  using Less_x_2 = Polling_less<typename Traits::Less_x_2>;
  using Less_y_2 = Polling_less<typename Traits::Less_y_2>;

  Interruptible_sort_traits_2() = default;
  explicit Interruptible_sort_traits_2(const Traits& t) : Traits(t) {}
  Less_x_2 less_x_2_object() const { return {Traits::less_x_2_object()}; }
  Less_y_2 less_y_2_object() const { return {Traits::less_y_2_object()}; }
};

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_PARALLEL_INTERRUPT_SCOPE_H
