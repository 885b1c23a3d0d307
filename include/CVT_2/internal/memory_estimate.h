// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// What an optimization of n generators needs at most against the machine's memory, for the front
// ends (cvt2, the Python module) to refuse a count before minutes of work end in a kill.
#ifndef CVT_2_INTERNAL_MEMORY_ESTIMATE_H
#define CVT_2_INTERNAL_MEMORY_ESTIMATE_H

#if defined(__unix__) || defined(__APPLE__)
#include <unistd.h>
#define CVT_2_HAS_SYSCONF 1
#endif

#include <string>

namespace CVT_2 {
namespace internal {

// The physical memory in bytes, or 0 where the system does not say.
inline double physical_memory() {
#ifdef CVT_2_HAS_SYSCONF
  return double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
#else
  return 0;
#endif
}

// Peak memory per generator, at most (triangulation, cells, moves, the faces' layout after the
// insertion; L-BFGS's history); benchmarks/README.md measures 243 and 445 bytes.
inline double peak_bytes_per_generator(bool lbfgs) { return lbfgs ? 750 : 360; }

// "n points need about X GB; this machine has Y GB" if n generators more may not fit in the
// physical memory, else empty.
inline std::string memory_shortfall(double n, bool lbfgs) {
  const double needed = peak_bytes_per_generator(lbfgs) * n, memory = physical_memory();
  if (memory <= 0 || needed <= memory) return {};
  return std::to_string(static_cast<long long>(n)) + " points need about " +
         std::to_string(static_cast<long long>(needed / 1e9)) + " GB; this machine has " +
         std::to_string(static_cast<long long>(memory / 1e9)) + " GB";
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_MEMORY_ESTIMATE_H
