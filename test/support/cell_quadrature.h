// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// An independent quadrature, to check the library's figures without its code: Gauss-Legendre
// on the collapsed (Duffy) square of each sub-triangle of each fan triangle of a cell, and the
// move ratios |x - x*| / diameter of the free generators computed with it from the cell
// polygons alone (no evaluate(), no CVT_2 quadrature, no CVT_2 density wrapper).
#ifndef CVT_2_TEST_SUPPORT_CELL_QUADRATURE_H
#define CVT_2_TEST_SUPPORT_CELL_QUADRATURE_H

#include "support.h"

#include <CVT_2/Cell_moments_2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace support {

// Gauss-Legendre nodes and weights on [0, 1] (Newton on the Legendre polynomial).
inline void gauss_legendre(int n, std::vector<double>& nodes, std::vector<double>& weights) {
  const double pi = std::acos(-1.0);
  nodes.assign(n, 0);
  weights.assign(n, 0);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(pi * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    nodes[i] = (1 - z) / 2;
    weights[i] = 1 / ((1 - z * z) * dp * dp);
  }
}

// The moments of `cell` (ccw, star-shaped from x: a free cell, or a constrained one whose
// slits through x add nothing) under rho, relative to x: mass, first moment, energy. Each fan
// triangle (x, a, b) is cut into split² similar triangles; on each, (p, q, r), the collapsed
// map y = p + s((1 - t)(q - p) + t(r - p)), of Jacobian s cross(q - p, r - p), with order ×
// order Gauss points. Smooth densities need split = 1; a kink (a sizing field's medial axis)
// converges as split grows.
template <class Density, class PointRange>
CVT_2::Cell_moments_2<K> gauss_moments(const Point& x, const PointRange& cell, const Density& rho,
                                       int order = 24, int split = 1) {
  std::vector<double> g, w;
  gauss_legendre(order, g, w);
  double mass = 0, fx = 0, fy = 0, energy = 0;
  // One triangle given relative to x.
  const auto triangle = [&](double px, double py, double qx, double qy, double rx, double ry) {
    const double ax = qx - px, ay = qy - py, bx = rx - px, by = ry - py;
    const double cross = ax * by - ay * bx;
    if (cross == 0) return;
    for (std::size_t is = 0; is < g.size(); ++is)
      for (std::size_t it = 0; it < g.size(); ++it) {
        const double s = g[is], t = g[it];
        const double u = px + s * ((1 - t) * ax + t * bx), v = py + s * ((1 - t) * ay + t * by);
        const double r = w[is] * w[it] * s * cross * double(rho(Point(x.x() + u, x.y() + v)));
        mass += r;
        fx += r * u;
        fy += r * v;
        energy += r * (u * u + v * v);
      }
  };
  const std::vector<Point> points(cell.begin(), cell.end());
  const double m = split;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double ax = points[k].x() - x.x(), ay = points[k].y() - x.y();
    const double bx = points[(k + 1) % points.size()].x() - x.x(),
                 by = points[(k + 1) % points.size()].y() - x.y();
    const auto at = [&](int i, int j, double& px, double& py) {  // x + (i a + j b) / split
      px = (i * ax + j * bx) / m;
      py = (i * ay + j * by) / m;
    };
    for (int i = 0; i < split; ++i)
      for (int j = 0; i + j < split; ++j) {
        double p[2], q[2], r[2], s[2];
        at(i, j, p[0], p[1]);
        at(i + 1, j, q[0], q[1]);
        at(i, j + 1, r[0], r[1]);
        triangle(p[0], p[1], q[0], q[1], r[0], r[1]);
        if (i + j + 2 <= split) {
          at(i + 1, j + 1, s[0], s[1]);
          triangle(q[0], q[1], s[0], s[1], r[0], r[1]);
        }
      }
  }
  CVT_2::Cell_moments_2<K> result;
  result.mass = mass;
  result.first_moment = K::Vector_2(fx, fy);
  result.energy = energy;
  return result;
}

// The largest distance between two vertices of a polygon.
template <class PointRange>
double polygon_diameter(const PointRange& cell) {
  double d2 = 0;
  for (const Point& p : cell)
    for (const Point& q : cell) d2 = std::max(d2, CGAL::squared_distance(p, q));
  return std::sqrt(d2);
}

// What the oracle finds for one free generator's cell.
struct Free_cell {
  Cdt::Vertex_handle vertex;
  double mass = 0;
  Point centroid;
  double diameter = 0;
  double move_ratio = 0;  // |x - x*| / diameter
  bool interior = false;  // no vertex of the cell on a constraint
};

// Every free generator's cell, integrated by gauss_moments (see there for order and split).
template <class Density>
std::vector<Free_cell> free_cells(const Cdt& cdt, const Density& rho, int order, int split) {
  const Bvd bvd(cdt);
  std::vector<Free_cell> cells;
  std::vector<Point> points;
  bvd.for_each_cell([&](Cdt::Vertex_handle v, const Cell& c) {
    if (!bvd.is_free(v)) return;
    points.clear();
    Free_cell f;
    f.vertex = v;
    f.interior = true;
    for (const auto& cv : c) {
      points.push_back(cv.point);
      f.interior = f.interior && cv.type == Bvd::Cell_vertex::CIRCUMCENTER;
    }
    const auto m = gauss_moments(v->point(), points, rho, order, split);
    f.mass = CGAL::to_double(m.mass);
    f.centroid = v->point() + m.first_moment / m.mass;
    f.diameter = polygon_diameter(points);
    f.move_ratio = std::sqrt(m.first_moment.squared_length()) / m.mass / f.diameter;
    cells.push_back(f);
  });
  return cells;
}

// The largest move ratio of free_cells().
inline double max_move_ratio(const std::vector<Free_cell>& cells) {
  double r = 0;
  for (const Free_cell& c : cells) r = std::max(r, c.move_ratio);
  return r;
}

}  // namespace support

#endif  // CVT_2_TEST_SUPPORT_CELL_QUADRATURE_H
