// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Midpoint_quadrature_2: the paper's midpoint rule on n sub-triangles from longest-edge bisection.
#ifndef CVT_2_MIDPOINT_QUADRATURE_2_H
#define CVT_2_MIDPOINT_QUADRATURE_2_H

#include <CVT_2/Cell_moments_2.h>
#include <CVT_2/internal/polygon_moments.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace CVT_2 {

/// \ingroup PkgCvt2Policies
/// A model of `CellQuadrature_2` for any density: the midpoint rule of the paper (Section 3).
///
/// The cell is cut into its fan triangles \f$(x, c_i, c_{i+1})\f$ (those of zero area, the
/// slits of a generator on constraints, are dropped); then the triangle whose longest edge is
/// longest is bisected at the midpoint of that edge, again and again, until there are
/// `resolution` triangles (none is bisected if the fan has that many already). On each
/// triangle \f$T\f$ of edge midpoints \f$m_{12}, m_{23}, m_{13}\f$,
/// \f$\int_T f \approx \frac{|T|}{3}\left(f(m_{12}) + f(m_{23}) + f(m_{13})\right)\f$ for
/// \f$f = \rho\f$, \f$\rho\,(y - x)\f$ and \f$\rho\,\|y - x\|^2\f$.
///
/// So \f$\rho\f$ is evaluated exactly \f$3\max(n, k)\f$ times, where \f$n\f$ is `resolution` and
/// \f$k\f$ the number of fan triangles of nonzero area. The rule is exact for polynomials of
/// degree at most 2: with a constant \f$\rho\f$ all three moments are exact at any resolution.
/// For a smooth \f$\rho\f$ the error is \f$O(h^3)\f$ for sub-triangles of size \f$h\f$, so
/// \f$O(n^{-3/2})\f$ (about \f$O(n^{-2})\f$ in the tests); it decreases more slowly where
/// \f$\rho\f$ has kinks or varies by orders of magnitude over the cell. The paper uses
/// \f$n = 10\f$ in the first Lloyd iterations and \f$n = 100\f$ in the last ones.
///
/// Up to 128 triangles live on the stack; only larger resolutions allocate.
///
/// \tparam K a CGAL kernel with Cartesian coordinates.
/// \sa `Exact_quadrature_2`, `Cell_moments_2`
template <class K>
class Midpoint_quadrature_2 {
 public:
  using Geom_traits = K;                   ///< the kernel
  using FT = typename K::FT;               ///< the number type
  using Point_2 = typename K::Point_2;     ///< the point type
  using Vector_2 = typename K::Vector_2;   ///< the vector type
  using Cell_moments = Cell_moments_2<K>;  ///< the result type

  /// The moments of `cell` relative to `x` under `rho`, by the midpoint rule on
  /// `max(resolution, k)` sub-triangles (k: the fan triangles of nonzero area).
  /// \tparam Density a model of `DensityFunction_2`: `FT operator()(const Point_2&) const`.
  /// \tparam PointRange a range of `Point_2`, the cell's vertices.
  /// \pre `cell` is a counterclockwise polygon, star-shaped from `x` (it may pass through `x`,
  ///      several times for a generator on constraints).
  template <class Density, class PointRange>
  Cell_moments operator()(const Point_2& x, const PointRange& cell, const Density& rho,
                          std::size_t resolution) const {
    static_assert(std::is_invocable_r_v<FT, const Density&, const Point_2&>,
                  "Density must model DensityFunction_2: FT operator()(const Point_2&) const");
    Triangles triangles;
    subdivide(x, cell, resolution, triangles);
    return sum(
        triangles.size(), [&](std::size_t i) { return nodes_of(triangles[i]); },
        [&](std::size_t, int, const FT& u, const FT& v) {
          return rho(Point_2(x.x() + u, x.y() + v));
        });
  }

  /// For densities evaluated in batches (see `CellQuadrature_2::nodes()`): appends to
  /// `points` the points where `operator()` evaluates the density on `cell`, in its order, and
  /// to `nodes` each sub-triangle's weight $|T|/3$ and midpoints relative to `x`.
  /// Returns the number of points appended.
  template <class PointRange>
  std::size_t nodes(const Point_2& x, const PointRange& cell, std::size_t resolution,
                    std::vector<Point_2>& points, std::vector<FT>& nodes) const {
    Triangles triangles;
    subdivide(x, cell, resolution, triangles);
    for (const Triangle& t : triangles) {
      const Nodes n = nodes_of(t);
      nodes.insert(nodes.end(), n.begin(), n.end());
      for (int j = 0; j < 3; ++j) points.emplace_back(x.x() + n[1 + 2 * j], x.y() + n[2 + 2 * j]);
    }
    return 3 * triangles.size();
  }

  /// The moments `operator()` computes on the cell whose `nodes()` start at `nodes`, from the
  /// density's values at its `number_of_points` points, in order: the same bits.
  Cell_moments moments(const FT* nodes, const FT* values, std::size_t number_of_points) const {
    return sum(
        number_of_points / 3,
        [nodes](std::size_t i) {
          Nodes n;
          std::copy(nodes + 7 * i, nodes + 7 * i + 7, n.begin());
          return n;
        },
        [values](std::size_t i, int j, const FT&, const FT&) { return values[3 * i + j]; });
  }

 private:
  // A sub-triangle relative to x, rotated so that ab is its longest edge (rotation keeps the
  // orientation); key = |b - a|².
  struct Triangle {
    FT ax, ay, bx, by, cx, cy, area, key;
  };
  using Triangles = boost::container::small_vector<Triangle, 128>;
  // What the rule needs of a sub-triangle: its weight |T| / 3, then its edges' midpoints
  // (u, v), relative to x, in the order the rule evaluates them.
  using Nodes = std::array<FT, 7>;

  static Nodes nodes_of(const Triangle& t) {
    return {t.area / 3,        (t.ax + t.bx) / 2, (t.ay + t.by) / 2, (t.bx + t.cx) / 2,
            (t.by + t.cy) / 2, (t.cx + t.ax) / 2, (t.cy + t.ay) / 2};
  }

  // The fan (x, c_i, c_i+1) of the cell, relative to x so that the midpoints, weights and
  // moments stay accurate far from the origin, its triangles of zero area dropped, bisected
  // until there are `resolution` triangles.
  template <class PointRange>
  static void subdivide(const Point_2& x, const PointRange& cell, std::size_t resolution,
                        Triangles& triangles) {
    internal::for_each_polygon_edge(cell, [&](const Point_2& p, const Point_2& q) {
      const FT ax = p.x() - x.x(), ay = p.y() - x.y();
      const FT bx = q.x() - x.x(), by = q.y() - x.y();
      const FT area = (ax * by - ay * bx) / 2;
      if (area > 0)  // none is negative but by a rounding of 0 (as Gauss_quadrature_2)
        triangles.push_back(make_triangle(FT(0), FT(0), ax, ay, bx, by, area));
    });
    if (triangles.empty()) return;

    // Each step bisects the triangle whose longest edge is longest of all, which adds one
    // triangle. Halving the area (exact in binary floating point) keeps the sub-triangles' areas
    // summing to the fan's.
    if (triangles.size() < resolution) {
      Heap heap;
      for (std::size_t i = 0; i < triangles.size(); ++i) push(heap, {triangles[i].key, i});
      do {
        const std::size_t i = heap[0].index;
        const Triangle t = triangles[i];
        const FT mx = (t.ax + t.bx) / 2, my = (t.ay + t.by) / 2, half = t.area / 2;
        triangles[i] = make_triangle(t.ax, t.ay, mx, my, t.cx, t.cy, half);
        replace_top(heap, {triangles[i].key, i});
        triangles.push_back(make_triangle(mx, my, t.bx, t.by, t.cx, t.cy, half));
        push(heap, {triangles.back().key, triangles.size() - 1});
      } while (triangles.size() < resolution);
    }
  }

  // The rule's sums over n sub-triangles: nodes(i) gives triangle i's Nodes, value(i, j, u, v)
  // the density at its j-th midpoint (u, v).
  template <class NodesAt, class ValueAt>
  static Cell_moments sum(std::size_t n, const NodesAt& nodes, const ValueAt& value) {
    if (n == 0) return Cell_moments();
    FT mass = 0, moment_x = 0, moment_y = 0, energy = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const Nodes t = nodes(i);
      FT m = 0, fx = 0, fy = 0, e = 0;
      for (int j = 0; j < 3; ++j) {
        const FT &u = t[1 + 2 * j], &v = t[2 + 2 * j];
        const FT r = value(i, j, u, v);
        m += r;
        fx += r * u;
        fy += r * v;
        e += r * (u * u + v * v);
      }
      const FT w = t[0];
      mass += w * m;
      moment_x += w * fx;
      moment_y += w * fy;
      energy += w * e;
    }
    Cell_moments result;
    result.mass = mass;
    result.first_moment = Vector_2(moment_x, moment_y);
    result.energy = energy;
    return result;
  }

  static Triangle make_triangle(const FT& ax, const FT& ay, const FT& bx, const FT& by,
                                const FT& cx, const FT& cy, const FT& area) {
    const FT ab = (bx - ax) * (bx - ax) + (by - ay) * (by - ay);
    const FT bc = (cx - bx) * (cx - bx) + (cy - by) * (cy - by);
    const FT ca = (ax - cx) * (ax - cx) + (ay - cy) * (ay - cy);
    if (bc > ab && bc >= ca) return {bx, by, cx, cy, ax, ay, area, bc};
    if (ca > ab && ca > bc) return {cx, cy, ax, ay, bx, by, area, ca};
    return {ax, ay, bx, by, cx, cy, area, ab};
  }

  // A binary max-heap of triangle indices keyed by their squared longest edge (children of h
  // at 2h + 1 and 2h + 2). replace_top sifts the first half down from the root in one pass,
  // where std::pop_heap then std::push_heap go down to a leaf and back up: the whole call is
  // twice as fast at n = 100. Keys and indices apart from the triangles keep the moves small.
  struct Heap_entry {
    FT key;
    std::size_t index;
  };
  using Heap = boost::container::small_vector<Heap_entry, 128>;

  static void push(Heap& heap, const Heap_entry& e) {
    std::size_t h = heap.size();
    heap.push_back(e);
    while (h > 0) {
      const std::size_t parent = (h - 1) / 2;
      if (!(heap[parent].key < e.key)) break;
      heap[h] = heap[parent];
      h = parent;
    }
    heap[h] = e;
  }

  static void replace_top(Heap& heap, const Heap_entry& e) {
    const std::size_t size = heap.size();
    std::size_t h = 0;
    for (;;) {
      std::size_t child = 2 * h + 1;
      if (child >= size) break;
      if (child + 1 < size && heap[child].key < heap[child + 1].key) ++child;
      if (!(e.key < heap[child].key)) break;
      heap[h] = heap[child];
      h = child;
    }
    heap[h] = e;
  }
};

}  // namespace CVT_2

#endif  // CVT_2_MIDPOINT_QUADRATURE_2_H
