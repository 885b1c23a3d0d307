// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Double_pair: two doubles at once, for the loops over many quadrature points.
#ifndef CVT_2_INTERNAL_LAYOUT_DOUBLE_PAIR_H
#define CVT_2_INTERNAL_LAYOUT_DOUBLE_PAIR_H

#include <algorithm>
#include <cmath>
#include <cstddef>

#if (defined(__SSE2__) || defined(_M_X64)) && !defined(CVT_2_NO_SIMD)
#include <emmintrin.h>
#define CVT_2_SSE2_PAIRS
#endif

namespace CVT_2 {
namespace internal {

// Two doubles at once: SSE2 where there is (every x86-64), else two scalars (also with
// CVT_2_NO_SIMD defined in every translation unit, to compare them); the same operations in
// the same order either way, so the same bits for finite values.
#ifdef CVT_2_SSE2_PAIRS
struct Double_pair {
  using type = __m128d;
  static type all(double a) { return _mm_set1_pd(a); }
  static type load(const double* p) { return _mm_loadu_pd(p); }
  static void store(double* p, type a) { _mm_storeu_pd(p, a); }
  static double first(type a) { return _mm_cvtsd_f64(a); }
  static double second(type a) { return _mm_cvtsd_f64(_mm_unpackhi_pd(a, a)); }
  static type add(type a, type b) { return _mm_add_pd(a, b); }
  static type sub(type a, type b) { return _mm_sub_pd(a, b); }
  static type mul(type a, type b) { return _mm_mul_pd(a, b); }
  static type sqrt(type a) { return _mm_sqrt_pd(a); }
  static type min(type a, type b) { return _mm_min_pd(a, b); }  // b if either is NaN
  static type max(type a, type b) { return _mm_max_pd(a, b); }  // b if either is NaN
  // c <= 0 ? a : (c > l ? b : m)
  static type select(type c, type l, type a, type b, type m) {
    const type before = _mm_cmple_pd(c, _mm_setzero_pd()), after = _mm_cmpgt_pd(c, l);
    const type rest = _mm_or_pd(_mm_and_pd(after, b), _mm_andnot_pd(after, m));
    return _mm_or_pd(_mm_and_pd(before, a), _mm_andnot_pd(before, rest));
  }
};
#else
struct Double_pair {
  struct type {
    double v[2];
  };
  template <class F>
  static type map(F f, type a, type b) {
    return {{f(a.v[0], b.v[0]), f(a.v[1], b.v[1])}};
  }
  static type all(double a) { return {{a, a}}; }
  static type load(const double* p) { return {{p[0], p[1]}}; }
  static void store(double* p, type a) { p[0] = a.v[0], p[1] = a.v[1]; }
  static double first(type a) { return a.v[0]; }
  static double second(type a) { return a.v[1]; }
  static type add(type a, type b) {
    return map([](double x, double y) { return x + y; }, a, b);
  }
  static type sub(type a, type b) {
    return map([](double x, double y) { return x - y; }, a, b);
  }
  static type mul(type a, type b) {
    return map([](double x, double y) { return x * y; }, a, b);
  }
  static type sqrt(type a) { return {{std::sqrt(a.v[0]), std::sqrt(a.v[1])}}; }
  static type min(type a, type b) {  // as minpd: b if either is NaN
    return map([](double x, double y) { return x < y ? x : y; }, a, b);
  }
  static type max(type a, type b) {  // as maxpd: b if either is NaN
    return map([](double x, double y) { return x > y ? x : y; }, a, b);
  }
  static type select(type c, type l, type a, type b, type m) {
    type r;
    for (int i = 0; i < 2; ++i) r.v[i] = c.v[i] <= 0 ? a.v[i] : (c.v[i] > l.v[i] ? b.v[i] : m.v[i]);
    return r;
  }
};
#endif

// The least and the greatest of a pair's two values.
inline double least_lane(Double_pair::type a) {
  return std::min(Double_pair::first(a), Double_pair::second(a));
}
inline double greatest_lane(Double_pair::type a) {
  return std::max(Double_pair::first(a), Double_pair::second(a));
}

// Whether all of the n values at `v` are positive and finite, two at a time without a branch:
// their least must be positive (a NaN may drop out of a minimum) and the sum of each value
// times 0 must be 0 (inf and NaN make it NaN).
inline bool all_positive_finite(const double* v, std::size_t n) {
  using P = Double_pair;
  auto least = P::all(1), zero = P::all(0), times_zero = zero;
  std::size_t i = 0;
  for (; i + 2 <= n; i += 2) {
    const auto x = P::load(v + i);
    least = P::min(least, x);
    times_zero = P::add(times_zero, P::mul(x, zero));
  }
  if (i < n) {  // the last one in both lanes
    const auto x = P::all(v[i]);
    least = P::min(least, x);
    times_zero = P::add(times_zero, P::mul(x, zero));
  }
  return least_lane(least) > 0 && P::first(times_zero) == 0 && P::second(times_zero) == 0;
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_LAYOUT_DOUBLE_PAIR_H
