// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Lbfgs_history: the curvature pairs of L-BFGS and its two-loop recursion, apart from any CVT.
#ifndef CVT_2_INTERNAL_LBFGS_HISTORY_H
#define CVT_2_INTERNAL_LBFGS_HISTORY_H

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

inline double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

// The last `capacity` pairs s = x' - x, y = g' - g of an L-BFGS iteration in a ring, and the
// quasi-Newton direction they give (Nocedal and Wright, Algorithm 7.4). The variables come in
// pairs (the two coordinates of a point), and the initial inverse Hessian is diagonal with one
// value per point, h_i for both coordinates of point i, scaled by the newest pair as in Nocedal
// and Wright (7.20). On a quadratic with Hessian A, after pairs along n A-conjugate directions
// the direction is exactly -A^-1 g.
class Lbfgs_history {
 public:
  explicit Lbfgs_history(std::size_t capacity = 0) : m_capacity(capacity) {}

  std::size_t capacity() const { return m_capacity; }  // the most pairs kept
  std::size_t size() const { return m_size; }          // the pairs kept now
  void clear() { m_size = 0; }

  // Adds the pair s = x1 - x0, y = g1 - g0, unless its curvature s.y is not positive (relative
  // to |s||y|): such a pair would make the inverse Hessian indefinite. When the ring is full the
  // oldest pair leaves. Returns whether the pair was added.
  bool add(const std::vector<double>& x0, const std::vector<double>& x1,
           const std::vector<double>& g0, const std::vector<double>& g1) {
    if (m_capacity == 0) return false;
    const std::size_t n = x0.size();
    m_new_s.resize(n);
    m_new_y.resize(n);
    for (std::size_t j = 0; j < n; ++j) {
      m_new_s[j] = x1[j] - x0[j];
      m_new_y[j] = g1[j] - g0[j];
    }
    const double sy = dot(m_new_s, m_new_y);
    if (!(sy > 1e-10 * std::sqrt(dot(m_new_s, m_new_s) * dot(m_new_y, m_new_y)))) return false;
    if (m_s.size() < m_capacity) {
      m_s.resize(m_capacity);
      m_y.resize(m_capacity);
      m_inverse_sy.resize(m_capacity);
    }
    const std::size_t k = slot(m_size);  // past the newest; the oldest's slot when full
    m_s[k].swap(m_new_s);
    m_y[k].swap(m_new_y);
    m_inverse_sy[k] = 1 / sy;
    if (m_size < m_capacity)
      ++m_size;
    else
      m_first = (m_first + 1) % m_capacity;
    return true;
  }

  // The direction d = -H g of the two-loop recursion, with H0 = gamma diag(h) as above.
  // Returns whether it goes downhill (g.d < 0, finite).
  // \pre size() > 0; g.size() == 2 h.size().
  bool direction(const std::vector<double>& g, const std::vector<double>& h,
                 std::vector<double>& d) {
    d = g;
    m_alpha.resize(m_size);
    for (std::size_t t = m_size; t-- > 0;) {
      const std::size_t k = slot(t);
      m_alpha[t] = m_inverse_sy[k] * dot(m_s[k], d);
      for (std::size_t j = 0; j < d.size(); ++j) d[j] -= m_alpha[t] * m_y[k][j];
    }
    const std::size_t newest = slot(m_size - 1);
    const std::vector<double>& y = m_y[newest];
    double yhy = 0;
    for (std::size_t i = 0; i < h.size(); ++i)
      yhy += h[i] * (y[2 * i] * y[2 * i] + y[2 * i + 1] * y[2 * i + 1]);
    const double gamma = 1 / (m_inverse_sy[newest] * yhy);
    for (std::size_t i = 0; i < h.size(); ++i) {
      d[2 * i] *= gamma * h[i];
      d[2 * i + 1] *= gamma * h[i];
    }
    for (std::size_t t = 0; t < m_size; ++t) {
      const std::size_t k = slot(t);
      const double beta = m_inverse_sy[k] * dot(m_y[k], d);
      for (std::size_t j = 0; j < d.size(); ++j) d[j] += (m_alpha[t] - beta) * m_s[k][j];
    }
    for (double& v : d) v = -v;
    const double slope = dot(g, d);
    return slope < 0 && std::isfinite(slope);
  }

 private:
  std::size_t slot(std::size_t t) const { return (m_first + t) % m_capacity; }  // t-th oldest

  std::size_t m_capacity, m_first = 0, m_size = 0;
  std::vector<std::vector<double>> m_s, m_y;  // the pairs, a ring
  std::vector<double> m_inverse_sy;           // 1 / (s . y) of each pair
  std::vector<double> m_new_s, m_new_y, m_alpha;
};

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_LBFGS_HISTORY_H
