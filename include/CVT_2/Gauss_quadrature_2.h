// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Gauss_quadrature_2: a degree-5 Gauss rule on each fan triangle of a cell.
#ifndef CVT_2_GAUSS_QUADRATURE_2_H
#define CVT_2_GAUSS_QUADRATURE_2_H

#include <CVT_2/Cell_moments_2.h>
#include <CVT_2/internal/polygon_moments.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace CVT_2 {

/// \ingroup PkgCvt2Policies
/// A model of `CellQuadrature_2` for any smooth density, the default for densities that are
/// not uniform: Radon's seven-point rule, exact for polynomials of degree 5, on each fan
/// triangle \f$(x, c_i, c_{i+1})\f$ of the cell (those of zero area, the slits of a generator on
/// constraints, are dropped, and so are those that rounding makes negative), each cut into
/// `subdivisions`² similar triangles first.
///
/// So \f$\rho\f$ is evaluated \f$7 m^2 k\f$ times (\f$m\f$ = `subdivisions`, \f$k\f$ the fan
/// triangles of nonzero area, about 6): 42 times a cell with the default \f$m = 1\f$, against
/// 300 for `Midpoint_quadrature_2` at the paper's final resolution of 100. The mass, first
/// moment and energy integrate \f$\rho\f$ times polynomials of degree 0, 1 and 2: exact when
/// \f$\rho\f$ is a polynomial of degree 3; for a smooth \f$\rho\f$ the error is \f$O(h^6)\f$
/// relative to the moment, \f$h\f$ the size of a triangle over the scale on which \f$\rho\f$
/// varies. A sizing field density \f$1/\mu^4\f$ with a \f$k\f$-Lipschitz \f$\mu\f$ varies over a
/// cell of size about \f$\mu\f$ by a factor of about \f$1 + 4k\f$: with the paper's \f$k \le 0.2\f$
/// the rule's centroids are within 1e-4 of the cell's size of the exact ones (the tests measure
/// it against a rule refined until the moments no longer change), a hundredth of the usual stop
/// on move ratios. Raise `subdivisions` for densities with steeper variation; kinks (where the
/// nearest boundary segment of a sizing field changes) cost accuracy as for any rule.
///
/// It ignores `resolution`: the Lloyd optimizer's 10 to 100 schedule is the midpoint rule's
/// (`Midpoint_quadrature_2`, still available as the `Quadrature` parameter).
///
/// \tparam K a CGAL kernel with Cartesian coordinates.
/// \sa `Midpoint_quadrature_2`, `Exact_quadrature_2`, `Cell_moments_2`
template <class K>
class Gauss_quadrature_2 {
 public:
  using Geom_traits = K;                   ///< the kernel
  using FT = typename K::FT;               ///< the number type
  using Point_2 = typename K::Point_2;     ///< the point type
  using Vector_2 = typename K::Vector_2;   ///< the vector type
  using Cell_moments = Cell_moments_2<K>;  ///< the result type

  /// The rule on each fan triangle cut into `subdivisions`² triangles.
  /// \throws std::invalid_argument if `subdivisions` is 0.
  explicit Gauss_quadrature_2(std::size_t subdivisions = 1) : m_subdivisions(subdivisions) {
    if (subdivisions == 0)
      throw std::invalid_argument("Gauss_quadrature_2: subdivisions must be at least 1");
  }

  std::size_t subdivisions() const { return m_subdivisions; }  ///< \f$m\f$

  /// The moments of `cell` relative to `x` under `rho`.
  /// \tparam Density a model of `DensityFunction_2`: `FT operator()(const Point_2&) const`.
  /// \tparam PointRange a range of `Point_2`, the cell's vertices.
  /// \pre `cell` is a counterclockwise polygon, star-shaped from `x` (it may pass through `x`,
  ///      several times for a generator on constraints).
  template <class Density, class PointRange>
  Cell_moments operator()(const Point_2& x, const PointRange& cell, const Density& rho,
                          std::size_t /*resolution*/) const {
    static_assert(std::is_invocable_r_v<FT, const Density&, const Point_2&>,
                  "Density must model DensityFunction_2: FT operator()(const Point_2&) const");
    Sums sums;
    for_each_node(x, cell, [&](const FT& w, const FT& u, const FT& v) {
      sums.add(w, u, v, rho(Point_2(x.x() + u, x.y() + v)));
    });
    return sums.moments();
  }

  /// For densities evaluated in batches (see `CellQuadrature_2::nodes()`): appends to `points`
  /// the points where `operator()` evaluates the density on `cell`, in its order, and to `nodes`
  /// each one's weight and position relative to `x`. Returns the number of points appended.
  template <class PointRange>
  std::size_t nodes(const Point_2& x, const PointRange& cell, std::size_t /*resolution*/,
                    std::vector<Point_2>& points, std::vector<FT>& nodes) const {
    const std::size_t before = points.size(), before_nodes = nodes.size();
    // room for this cell (resize grows geometrically: a chunk lists many cells in the same
    // vectors), trimmed to what the rule wrote
    const std::size_t most = 7 * m_subdivisions * m_subdivisions *
                             std::size_t(std::distance(std::begin(cell), std::end(cell)));
    points.resize(before + most);
    nodes.resize(before_nodes + 3 * most);
    Point_2* point = points.data() + before;
    FT* node = nodes.data() + before_nodes;
    for_each_node(x, cell, [&](const FT& w, const FT& u, const FT& v) {
      *node++ = w;
      *node++ = u;
      *node++ = v;
      *point++ = Point_2(x.x() + u, x.y() + v);
    });
    points.resize(std::size_t(point - points.data()));
    nodes.resize(std::size_t(node - nodes.data()));
    return points.size() - before;
  }

  /// The moments `operator()` computes on the cell whose `nodes()` start at `nodes`, from the
  /// density's values at its `number_of_points` points, in order: the same bits.
  Cell_moments moments(const FT* nodes, const FT* values, std::size_t number_of_points) const {
    Sums sums;
    for (std::size_t i = 0; i < number_of_points; ++i)
      sums.add(nodes[3 * i], nodes[3 * i + 1], nodes[3 * i + 2], values[i]);
    return sums.moments();
  }

 private:
  struct Sums {
    FT mass = 0, moment_x = 0, moment_y = 0, energy = 0;
    void add(const FT& w, const FT& u, const FT& v, const FT& r) {
      const FT wr = w * r;
      mass += wr;
      moment_x += wr * u;
      moment_y += wr * v;
      energy += wr * (u * u + v * v);
    }
    Cell_moments moments() const {
      Cell_moments m;
      m.mass = mass;
      m.first_moment = Vector_2(moment_x, moment_y);
      m.energy = energy;
      return m;
    }
  };

  // visit(weight, u, v) for each node of the rule, (u, v) relative to x: the fan triangles
  // (0, a, b), each cut into m² triangles of the grid p(i, j) = (i a + j b) / m, i + j <= m.
  template <class PointRange, class Visit>
  void for_each_node(const Point_2& x, const PointRange& cell, const Visit& visit) const {
    const std::size_t m = m_subdivisions;
    internal::for_each_polygon_edge(cell, [&](const Point_2& p, const Point_2& q) {
      const FT ax = p.x() - x.x(), ay = p.y() - x.y();
      const FT bx = q.x() - x.x(), by = q.y() - x.y();
      const FT area = (ax * by - ay * bx) / 2;
      // Star-shaped from x, the cell has no fan triangle of negative area: one computed so is a
      // rounding of 0 (x a rounding off the cell's edge), which a steep density's values would
      // make a negative mass.
      if (!(area > 0)) return;
      if (m == 1) return triangle(FT(0), FT(0), ax, ay, bx, by, area, visit);
      const FT part = area / FT(double(m * m)), inv = FT(1) / FT(double(m));
      const auto at = [&](std::size_t i, std::size_t j, FT& u, FT& v) {
        const FT s = FT(double(i)) * inv, t = FT(double(j)) * inv;
        u = s * ax + t * bx;
        v = s * ay + t * by;
      };
      for (std::size_t j = 0; j < m; ++j)
        for (std::size_t i = 0; i + j < m; ++i) {
          FT u0, v0, u1, v1, u2, v2;
          at(i, j, u0, v0);
          at(i + 1, j, u1, v1);
          at(i, j + 1, u2, v2);
          triangle(u0, v0, u1, v1, u2, v2, part, visit);
          if (i + j + 2 <= m) {
            FT u3, v3;
            at(i + 1, j + 1, u3, v3);
            triangle(u1, v1, u3, v3, u2, v2, part, visit);
          }
        }
    });
  }

  // Radon's rule (Dunavant's of degree 5): the centroid, and the points (1 - 2r, r, r) for
  // r = (6 -+ sqrt 15) / 21 with their permutations.
  template <class Visit>
  static void triangle(const FT& ax, const FT& ay, const FT& bx, const FT& by, const FT& cx,
                       const FT& cy, const FT& area, const Visit& visit) {
    constexpr double r1 = 0.10128650732345633880, s1 = 1 - 2 * r1;  // (6 - sqrt 15) / 21
    constexpr double r2 = 0.47014206410511508977, s2 = 1 - 2 * r2;  // (6 + sqrt 15) / 21
    constexpr double w0 = 0.225, w1 = 0.12593918054482715260, w2 = 0.13239415278850618074;
    visit(FT(w0) * area, (ax + bx + cx) / 3, (ay + by + cy) / 3);
    const auto orbit = [&](double s, double r, double w) {
      const FT weight = FT(w) * area;
      visit(weight, s * ax + r * (bx + cx), s * ay + r * (by + cy));
      visit(weight, s * bx + r * (cx + ax), s * by + r * (cy + ay));
      visit(weight, s * cx + r * (ax + bx), s * cy + r * (ay + by));
    };
    orbit(s1, r1, w1);
    orbit(s2, r2, w2);
  }

  std::size_t m_subdivisions;
};

}  // namespace CVT_2

#endif  // CVT_2_GAUSS_QUADRATURE_2_H
