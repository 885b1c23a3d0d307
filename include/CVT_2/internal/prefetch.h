// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// prefetch: a hint that memory will be read soon (the passes over large triangulations are
// memory-bound; a no-op where the compiler has no builtin).
#ifndef CVT_2_INTERNAL_PREFETCH_H
#define CVT_2_INTERNAL_PREFETCH_H

namespace CVT_2 {
namespace internal {

inline void prefetch(const void* p) {
#if defined(__GNUC__)
  __builtin_prefetch(p);
#else
  (void)p;
#endif
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_PREFETCH_H
