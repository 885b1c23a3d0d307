// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Random numbers for test data, the same on every platform: the standard distributions
// (std::uniform_real_distribution and the like) are not, so a test's data, and a failure's
// seed, would differ from one standard library to another. Points in a domain come from the
// library's CVT_2::random_points_in_domain_2 (see support.h).
#ifndef CVT_2_TEST_SUPPORT_RANDOM_H
#define CVT_2_TEST_SUPPORT_RANDOM_H

#include <CVT_2/random_points_in_domain_2.h>

#include <cstdint>
#include <random>

namespace support {

// A double in [lo, hi), from the library's platform-stable map of 53 random bits to [0, 1).
inline double uniform(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * CVT_2::internal::uniform01(rng);
}

// An integer in [lo, hi] (the modulo bias, below 2^-40 for the ranges of the tests, is of no
// concern to test data).
inline int uniform_int(std::mt19937_64& rng, int lo, int hi) {
  return lo + static_cast<int>(rng() % static_cast<std::uint64_t>(hi - lo + 1));
}

}  // namespace support

#endif  // CVT_2_TEST_SUPPORT_RANDOM_H
