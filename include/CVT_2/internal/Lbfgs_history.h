// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Lbfgs_history: the curvature pairs of L-BFGS and its two-loop recursion, apart from any CVT.
#ifndef CVT_2_INTERNAL_LBFGS_HISTORY_H
#define CVT_2_INTERNAL_LBFGS_HISTORY_H

#include <CVT_2/internal/parallel/run_chunks.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

// The vectors of L-BFGS in blocks of 2^13 entries (even: whole points), for passes on several
// threads whose sums are put together in block order: the same bits whatever the threads. The
// passes are bound by memory: each does all it can at once.
constexpr std::size_t vector_block = std::size_t(1) << 13;
inline std::size_t number_of_blocks(std::size_t n) { return (n + vector_block - 1) / vector_block; }

// Calls part(b, first, last) for each block b = [first, last) of [0, n), on `threads` threads (0:
// one per core).
template <class Part>
void for_each_block(std::size_t n, unsigned threads, const Part& part) {
  run_chunks(number_of_blocks(n), threads, [&](std::size_t b) {
    part(b, b * vector_block, std::min(n, (b + 1) * vector_block));
  });
}

// partial[b] = part(first, last) for each block b = [first, last) of [0, n).
template <class Part>
void parts_of_blocks(std::size_t n, unsigned threads, std::vector<double>& partial,
                     const Part& part) {
  partial.assign(number_of_blocks(n), 0.0);
  for_each_block(n, threads, [&](std::size_t b, std::size_t first, std::size_t last) {
    partial[b] = part(first, last);
  });
}

// The sum of part(first, last) over the blocks of [0, n), in block order.
template <class Part>
double sum_of_blocks(std::size_t n, unsigned threads, std::vector<double>& partial,
                     const Part& part) {
  parts_of_blocks(n, threads, partial, part);
  double s = 0;
  for (const double v : partial) s += v;
  return s;
}

// The largest part(first, last) over the blocks of [0, n), 0 if none (a NaN part loses to a
// number).
template <class Part>
double max_of_blocks(std::size_t n, unsigned threads, std::vector<double>& partial,
                     const Part& part) {
  parts_of_blocks(n, threads, partial, part);
  double m = 0;
  for (const double v : partial) m = std::max(m, v);
  return m;
}

// The last `capacity` pairs s = x' - x, y = g' - g of an L-BFGS iteration in a ring, and the
// quasi-Newton direction they give (Nocedal and Wright, Algorithm 7.4). The variables come in
// pairs (the two coordinates of a point), and the initial inverse Hessian is diagonal with one
// value per point, h_i for both coordinates of point i, scaled by the newest pair as in Nocedal
// and Wright (7.20). On a quadratic with Hessian A, after pairs along n A-conjugate directions
// the direction is exactly -A^-1 g.
//
// Each vector of a pair is kept as `Stored` numbers times a power of two (its largest entry
// below 1): float halves the memory of the pairs, whatever their magnitude, and the recursion
// uses the pairs as stored (their curvature s.y included), so it is the exact recursion of
// slightly other pairs. With double, the numbers are those of unscaled storage, bit for bit.
template <class Stored = float>
class Lbfgs_history {
 public:
  explicit Lbfgs_history(std::size_t capacity = 0) : m_capacity(capacity) {}
  // the threads of the passes over the vectors (0: one per core); the same bits with any number
  void set_number_of_threads(unsigned n) { m_threads = n; }
  std::size_t capacity() const { return m_capacity; }  // the most pairs kept
  std::size_t size() const { return m_size; }          // the pairs kept now
  void clear() { m_size = 0; }

  // Adds the pair s = x1 - x0, y = g1 - g0, unless its curvature s.y is not positive (relative
  // to |s||y|, beyond the rounding of the stored numbers): such a pair would make the inverse
  // Hessian indefinite. When the ring is full the oldest pair leaves. Returns whether the pair
  // was added.
  bool add(const std::vector<double>& x0, const std::vector<double>& x1,
           const std::vector<double>& g0, const std::vector<double>& g1) {
    if (m_capacity == 0) return false;
    const std::size_t n = x0.size(), blocks = number_of_blocks(n);
    // The largest |s| and |y| (NaN loses to a number in max; the sums below catch it).
    std::vector<double> s_max(blocks, 0.0), y_max(blocks, 0.0);
    for_each_block(n, m_threads, [&](std::size_t b, std::size_t first, std::size_t last) {
      double s = 0, y = 0;  // in registers: the blocks' maxima share cache lines
      for (std::size_t j = first; j < last; ++j) {
        s = std::max(s, std::abs(x1[j] - x0[j]));
        y = std::max(y, std::abs(g1[j] - g0[j]));
      }
      s_max[b] = s, y_max[b] = y;
    });
    const double s_largest = blocks ? *std::max_element(s_max.begin(), s_max.end()) : 0;
    const double y_largest = blocks ? *std::max_element(y_max.begin(), y_max.end()) : 0;
    if (!(s_largest > 0 && y_largest > 0 && std::isfinite(s_largest) && std::isfinite(y_largest)))
      return false;
    int es, ey;  // s = 2^es s', y = 2^ey y', |s'|, |y'| < 1
    std::frexp(s_largest, &es);
    std::frexp(y_largest, &ey);
    if (std::abs(es) > 1000 || std::abs(ey) > 1000) return false;  // scales out of range
    // Multiplying by a power of two is exact, as ldexp is, without a library call an entry.
    const double to_s = std::ldexp(1.0, -es), to_y = std::ldexp(1.0, -ey);
    const auto stored = [](double v, double scale) { return Stored(v * scale); };
    // s'.y', s'.s' and y'.y' as stored
    std::vector<double>& sy_part = s_max;
    std::vector<double>& ss_part = y_max;
    std::vector<double> yy_part(blocks, 0.0);
    for_each_block(n, m_threads, [&](std::size_t b, std::size_t first, std::size_t last) {
      double sy = 0, ss = 0, yy = 0;
      for (std::size_t j = first; j < last; ++j) {
        const double s = stored(x1[j] - x0[j], to_s), y = stored(g1[j] - g0[j], to_y);
        sy += s * y, ss += s * s, yy += y * y;
      }
      sy_part[b] = sy, ss_part[b] = ss, yy_part[b] = yy;
    });
    double sy = 0, ss = 0, yy = 0;
    for (std::size_t b = 0; b < blocks; ++b) sy += sy_part[b], ss += ss_part[b], yy += yy_part[b];
    constexpr double least = std::max(1e-10, 64 * double(std::numeric_limits<Stored>::epsilon()));
    if (!(sy > least * std::sqrt(ss * yy))) return false;
    // s.y, 1 / s.y and y.y unscaled, which the recursion forms, in the normal range
    const double sy_unscaled = std::ldexp(sy, es + ey), yy_unscaled = std::ldexp(yy, 2 * ey);
    if (!std::isnormal(sy_unscaled) || !std::isnormal(1 / sy_unscaled) ||
        !std::isnormal(yy_unscaled))
      return false;
    if (m_pairs.size() < m_capacity) m_pairs.resize(m_capacity);
    Pair& p = m_pairs[slot(m_size)];  // past the newest; the oldest's slot when full
    p.s.resize(n);
    p.y.resize(n);
    for_each_block(n, m_threads, [&](std::size_t, std::size_t first, std::size_t last) {
      for (std::size_t j = first; j < last; ++j) {
        p.s[j] = stored(x1[j] - x0[j], to_s);
        p.y[j] = stored(g1[j] - g0[j], to_y);
      }
    });
    p.s_exponent = es, p.y_exponent = ey;
    p.inverse_sy = std::ldexp(1 / sy, -es - ey);
    if (m_size < m_capacity)
      ++m_size;
    else
      m_first = (m_first + 1) % m_capacity;
    return true;
  }

  // The direction d = -H g of the two-loop recursion, with H0 = gamma diag(h) as above (h in
  // double or float: gamma rescales it). Returns whether it goes downhill (g.d < 0, finite).
  // \pre size() > 0; g.size() == 2 h.size().
  template <class H>
  bool direction(const std::vector<double>& g, const std::vector<H>& h, std::vector<double>& d) {
    const std::size_t n = g.size();
    d.resize(n);
    m_alpha.resize(m_size);
    // Each pass applies one update to d and takes the dot product the next update needs.
    // First loop, newest to oldest: alpha_t = rho_t s_t.d, d -= alpha_t y_t.
    const Pair& newest = m_pairs[slot(m_size - 1)];
    double dot = sum_of_blocks(n, m_threads, m_partial, [&](std::size_t first, std::size_t last) {
      double acc = 0;
      for (std::size_t j = first; j < last; ++j) acc += double(newest.s[j]) * (d[j] = g[j]);
      return acc;
    });
    const double yhy =
        sum_of_blocks(n, m_threads, m_partial, [&](std::size_t first, std::size_t last) {
          double acc = 0;
          for (std::size_t j = first; j < last; j += 2) {
            const double y0 = newest.y[j], y1 = newest.y[j + 1];
            acc += double(h[j / 2]) * (y0 * y0 + y1 * y1);
          }
          return acc;
        });
    const double gamma =
        1 / (newest.inverse_sy * std::ldexp(yhy, 2 * newest.y_exponent));  // s.y / y.H0 y
    for (std::size_t t = m_size; t-- > 0;) {
      const Pair& p = m_pairs[slot(t)];
      m_alpha[t] = p.inverse_sy * std::ldexp(dot, p.s_exponent);
      const double a = std::ldexp(m_alpha[t], p.y_exponent);
      // then the next s, or, after the oldest pair, H0 = gamma diag(h) and the oldest y
      const Pair& next = m_pairs[slot(t > 0 ? t - 1 : 0)];
      dot = sum_of_blocks(n, m_threads, m_partial, [&](std::size_t first, std::size_t last) {
        double acc = 0;
        if (t > 0) {
          for (std::size_t j = first; j < last; ++j)
            acc += double(next.s[j]) * (d[j] -= a * double(p.y[j]));
        } else {
          for (std::size_t j = first; j < last; ++j) {
            d[j] -= a * double(p.y[j]);
            acc += double(next.y[j]) * (d[j] *= gamma * double(h[j / 2]));
          }
        }
        return acc;
      });
    }
    // Second loop, oldest to newest: beta_t = rho_t y_t.d, d += (alpha_t - beta_t) s_t; the
    // last pass turns d around and takes g.d.
    for (std::size_t t = 0; t < m_size; ++t) {
      const Pair& p = m_pairs[slot(t)];
      const double beta = p.inverse_sy * std::ldexp(dot, p.y_exponent);
      const double a = std::ldexp(m_alpha[t] - beta, p.s_exponent);
      const bool last_pair = t + 1 == m_size;
      const Pair& next = m_pairs[slot(last_pair ? t : t + 1)];
      dot = sum_of_blocks(n, m_threads, m_partial, [&](std::size_t first, std::size_t last) {
        double acc = 0;
        if (!last_pair) {
          for (std::size_t j = first; j < last; ++j)
            acc += double(next.y[j]) * (d[j] += a * double(p.s[j]));
        } else {
          for (std::size_t j = first; j < last; ++j)
            acc += g[j] * (d[j] = -(d[j] + a * double(p.s[j])));
        }
        return acc;
      });
    }
    const double slope = dot;
    return slope < 0 && std::isfinite(slope);
  }

 private:
  struct Pair {
    std::vector<Stored> s, y;
    int s_exponent = 0, y_exponent = 0;  // s = 2^s_exponent s_stored; likewise y
    double inverse_sy = 0;               // 1 / (s . y)
  };
  std::size_t slot(std::size_t t) const { return (m_first + t) % m_capacity; }  // t-th oldest
  std::size_t m_capacity, m_first = 0, m_size = 0;
  std::vector<Pair> m_pairs;  // a ring
  std::vector<double> m_alpha, m_partial;
  unsigned m_threads = 0;  // one per core
};

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_LBFGS_HISTORY_H
