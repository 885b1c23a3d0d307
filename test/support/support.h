// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Test support: the triangulation types, loaders, seeded random points, cell measures. The
// invariant checker and the brute-force oracles are in invariants.h, the independent
// quadrature in cell_quadrature.h.
#ifndef CVT_2_TEST_SUPPORT_H
#define CVT_2_TEST_SUPPORT_H

#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/IO/read_poly.h>
#include <CVT_2/insert_generators_2.h>
#include <CVT_2/random_points_in_domain_2.h>

#include "random.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_id_2.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace support {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using Segment = K::Segment_2;
using Vb = CGAL::Triangulation_vertex_base_with_id_2<K>;  // CVT_2::Cvt_triangulation_2's
using Fb = CVT_2::Bvd_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<
    K, Tds, CGAL::No_constraint_intersection_requiring_constructions_tag>;
using Bvd = CVT_2::Bounded_voronoi_diagram_2<Cdt>;
using Cell = std::vector<Bvd::Cell_vertex>;

inline std::string data_path(const std::string& file) {
  return std::string(CVT_2_DATA_DIR) + "/" + file;
}

// A domain from a bundled .poly file, optionally moved by p -> scale * p + offset.
struct Domain {
  CVT_2::IO::Poly_data<Point> poly;
  Cdt cdt;
};
inline void transform(CVT_2::IO::Poly_data<Point>& poly, double scale, double ox, double oy) {
  for (auto& p : poly.vertices) p = Point(scale * p.x() + ox, scale * p.y() + oy);
  for (auto& p : poly.holes) p = Point(scale * p.x() + ox, scale * p.y() + oy);
}
inline void load_domain(Domain& d, const std::string& file, double scale = 1, double ox = 0,
                        double oy = 0) {
  d.poly = CVT_2::IO::read_poly<Point>(data_path(file));
  transform(d.poly, scale, ox, oy);
  CVT_2::IO::insert_poly(d.cdt, d.poly);
}

// The square [0, side]², no generators.
inline void load_square(Domain& d, double side = 1) {
  d.poly = CVT_2::IO::Poly_data<Point>();
  d.poly.vertices = {Point(0, 0), Point(side, 0), Point(side, side), Point(0, side)};
  d.poly.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  d.poly.vertex_lines.assign(4, 0);
  d.poly.segment_lines.assign(4, 0);
  CVT_2::IO::insert_poly(d.cdt, d.poly);
}

// A closed polygon into poly: vertices and segments (no segment markers, no vertex lines).
inline void add_ring(CVT_2::IO::Poly_data<Point>& poly, const std::vector<Point>& ring) {
  const std::size_t first = poly.vertices.size();
  for (std::size_t i = 0; i < ring.size(); ++i) {
    poly.vertices.push_back(ring[i]);
    poly.segments.push_back({first + i, first + (i + 1) % ring.size()});
  }
}

// The triangulation of a domain built in code (its lines, for messages, are all 0).
inline Cdt triangulate(CVT_2::IO::Poly_data<Point>& poly) {
  poly.vertex_lines.assign(poly.vertices.size(), 0);
  poly.segment_lines.assign(poly.segments.size(), 0);
  poly.hole_lines.assign(poly.holes.size(), 0);
  Cdt cdt;
  CVT_2::IO::insert_poly(cdt, poly);
  return cdt;
}

// A 2n x 2n square with an n x n grid of unit square holes, each seeded at its center.
inline Cdt square_with_holes(int n) {
  CVT_2::IO::Poly_data<Point> poly;
  add_ring(poly, {{0, 0}, {2.0 * n, 0}, {2.0 * n, 2.0 * n}, {0, 2.0 * n}});
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = 2 * i + 0.5, y = 2 * j + 0.5;
      add_ring(poly, {{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}});
      poly.holes.emplace_back(x + 0.5, y + 0.5);
    }
  return triangulate(poly);
}

inline CGAL::Bbox_2 domain_bbox(const Cdt& cdt) {
  CGAL::Bbox_2 b;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->is_inside_domain()) b += cdt.triangle(f).bbox();
  return b;
}

// n points drawn uniformly in the domain, the same on every platform (the library's sampling).
inline std::vector<Point> random_points_in_domain(const Cdt& cdt, std::size_t n, unsigned seed) {
  return CVT_2::random_points_in_domain_2(cdt, n, CVT_2::parameters::random_seed(seed));
}
inline void insert_random_points(Domain& d, std::size_t n, unsigned seed) {
  CVT_2::insert_generators_2(d.cdt, random_points_in_domain(d.cdt, n, seed));
}

// Shoelace relative to the first vertex, so that coordinates far from the origin do not cancel.
inline double signed_area(const Cell& c) {
  if (c.empty()) return 0;
  const Point& o = c[0].point;
  double a = 0;
  for (std::size_t i = 1; i + 1 < c.size(); ++i) {
    const auto p = c[i].point - o, q = c[i + 1].point - o;
    a += p.x() * q.y() - q.x() * p.y();
  }
  return a / 2;
}

inline double domain_area(const Cdt& cdt) {
  double a = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->is_inside_domain()) a += cdt.triangle(f).area();
  return a;
}

inline double total_cell_area(const Bvd& bvd) {
  double a = 0;
  Cell c;
  for (auto v = bvd.triangulation().finite_vertices_begin();
       v != bvd.triangulation().finite_vertices_end(); ++v) {
    bvd.cell(v, c);
    a += signed_area(c);
  }
  return a;
}

// Even-odd test, which slits (edges walked both ways) do not disturb.
inline bool polygon_contains(const Cell& c, const Point& y) {
  bool in = false;
  for (std::size_t i = 0, j = c.size() - 1; i < c.size(); j = i++) {
    const Point& a = c[i].point;
    const Point& b = c[j].point;
    if ((a.y() > y.y()) != (b.y() > y.y()) &&
        y.x() < (b.x() - a.x()) * (y.y() - a.y()) / (b.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

// The positions of the vertices, in the triangulation's order.
inline std::vector<Point> vertex_points(const Cdt& cdt) {
  std::vector<Point> p;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    p.push_back(v->point());
  return p;
}

// The region of each free vertex: its domain faces' component when connected without crossing
// a constraint (a county of Massachusetts, say).
inline std::map<Cdt::Vertex_handle, int> regions(const Cdt& cdt) {
  std::map<Cdt::Face_handle, int> id;
  int next = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_inside_domain() || id.count(f)) continue;
    std::vector<Cdt::Face_handle> stack{f};
    id[f] = next;
    while (!stack.empty()) {
      const auto g = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i)
        if (!g->is_constrained(i) && !id.count(g->neighbor(i))) {
          id[g->neighbor(i)] = next;
          stack.push_back(g->neighbor(i));
        }
    }
    ++next;
  }
  std::map<Cdt::Vertex_handle, int> region;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (!cdt.are_there_incident_constraints(v)) region[v] = id.at(v->face());
  return region;
}

}  // namespace support

#endif  // CVT_2_TEST_SUPPORT_H
