// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Lbfgs_history: the curvature pairs of L-BFGS and its two-loop recursion, apart from any CVT.
#ifndef CVT_2_INTERNAL_LBFGS_HISTORY_H
#define CVT_2_INTERNAL_LBFGS_HISTORY_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

// a.b in double, a's numbers as stored (double or float)
template <class T>
double dot(const std::vector<T>& a, const std::vector<double>& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += double(a[i]) * b[i];
  return s;
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
    const std::size_t n = x0.size();
    double s_max = 0, y_max = 0;
    for (std::size_t j = 0; j < n; ++j) {
      s_max = std::max(s_max, std::abs(x1[j] - x0[j]));
      y_max = std::max(y_max, std::abs(g1[j] - g0[j]));
    }
    if (!(s_max > 0 && y_max > 0 && std::isfinite(s_max) && std::isfinite(y_max))) return false;
    int es, ey;  // s = 2^es s', y = 2^ey y', |s'|, |y'| < 1
    std::frexp(s_max, &es);
    std::frexp(y_max, &ey);
    if (std::abs(es) > 1000 || std::abs(ey) > 1000) return false;  // scales out of range
    // Multiplying by a power of two is exact, as ldexp is, without a library call an entry.
    const double to_s = std::ldexp(1.0, -es), to_y = std::ldexp(1.0, -ey);
    const auto stored = [](double v, double scale) { return Stored(v * scale); };
    double sy = 0, ss = 0, yy = 0;  // of s' and y' as stored
    for (std::size_t j = 0; j < n; ++j) {
      const double s = stored(x1[j] - x0[j], to_s), y = stored(g1[j] - g0[j], to_y);
      sy += s * y, ss += s * s, yy += y * y;
    }
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
    for (std::size_t j = 0; j < n; ++j) {
      p.s[j] = stored(x1[j] - x0[j], to_s);
      p.y[j] = stored(g1[j] - g0[j], to_y);
    }
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
    d = g;
    m_alpha.resize(m_size);
    for (std::size_t t = m_size; t-- > 0;) {
      const Pair& p = m_pairs[slot(t)];
      m_alpha[t] = p.inverse_sy * std::ldexp(dot(p.s, d), p.s_exponent);
      const double a = std::ldexp(m_alpha[t], p.y_exponent);
      for (std::size_t j = 0; j < d.size(); ++j) d[j] -= a * double(p.y[j]);
    }
    const Pair& newest = m_pairs[slot(m_size - 1)];
    double yhy = 0;
    for (std::size_t i = 0; i < h.size(); ++i) {
      const double y0 = newest.y[2 * i], y1 = newest.y[2 * i + 1];
      yhy += double(h[i]) * (y0 * y0 + y1 * y1);
    }
    const double gamma =
        1 / (newest.inverse_sy * std::ldexp(yhy, 2 * newest.y_exponent));  // s.y / y.H0 y
    for (std::size_t i = 0; i < h.size(); ++i) {
      d[2 * i] *= gamma * double(h[i]);
      d[2 * i + 1] *= gamma * double(h[i]);
    }
    for (std::size_t t = 0; t < m_size; ++t) {
      const Pair& p = m_pairs[slot(t)];
      const double beta = p.inverse_sy * std::ldexp(dot(p.y, d), p.y_exponent);
      const double a = std::ldexp(m_alpha[t] - beta, p.s_exponent);
      for (std::size_t j = 0; j < d.size(); ++j) d[j] += a * double(p.s[j]);
    }
    for (double& v : d) v = -v;
    const double slope = dot(g, d);
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
  std::vector<double> m_alpha;
};

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_LBFGS_HISTORY_H
