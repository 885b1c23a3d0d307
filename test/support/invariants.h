// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The invariant checker, called after every mutation of a triangulation (as artem-ogre/CDT
// calls verifyTopology after every change), so that a test fails at the step that broke an
// invariant: the triangulation is valid and constrained Delaunay, its domain marks are those of
// a snapshot taken before, and its bounded Voronoi diagram tiles the domain, with convex free
// cells holding their generators, and sample points in the cell of their nearest visible
// generator by brute force.
#ifndef CVT_2_TEST_SUPPORT_INVARIANTS_H
#define CVT_2_TEST_SUPPORT_INVARIANTS_H

#include "support.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <utility>
#include <vector>

namespace support {

// Brute force: the generators that see y, by distance. x sees y when no constrained edge that
// does not end at x meets the segment [x, y].
struct Visibility_oracle {
  std::vector<std::pair<Segment, std::pair<Cdt::Vertex_handle, Cdt::Vertex_handle>>> constraints;
  std::vector<Cdt::Vertex_handle> generators;

  explicit Visibility_oracle(const Bvd& bvd) {
    const Cdt& cdt = bvd.triangulation();
    for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e)
      if (cdt.is_constrained(*e)) {
        const auto a = e->first->vertex(cdt.ccw(e->second)),
                   b = e->first->vertex(cdt.cw(e->second));
        constraints.push_back({Segment(a->point(), b->point()), {a, b}});
      }
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
      if (bvd.has_cell(v)) generators.push_back(v);
  }
  bool sees(Cdt::Vertex_handle x, const Point& y) const {
    const Segment s(x->point(), y);
    const CGAL::Bbox_2 sb = s.bbox();
    for (const auto& c : constraints) {
      if (c.second.first == x || c.second.second == x) continue;
      if (CGAL::do_overlap(sb, c.first.bbox()) && CGAL::do_intersect(s, c.first)) return false;
    }
    return true;
  }
  // The nearest and second nearest visible generators' squared distances, and the nearest.
  // The generators are taken by increasing distance from a heap, so that a sample costs
  // O(n + k log n) for the k nearest that are tried.
  std::pair<Cdt::Vertex_handle, std::pair<double, double>> nearest_visible(const Point& y) const {
    std::vector<std::pair<double, Cdt::Vertex_handle>> heap;
    heap.reserve(generators.size());
    for (const auto v : generators) heap.push_back({CGAL::squared_distance(v->point(), y), v});
    const auto farther = [](const auto& a, const auto& b) { return a.first > b.first; };
    std::make_heap(heap.begin(), heap.end(), farther);
    Cdt::Vertex_handle best;
    double d1 = -1;
    while (!heap.empty()) {
      std::pop_heap(heap.begin(), heap.end(), farther);
      const auto [d, v] = heap.back();
      heap.pop_back();
      if (!sees(v, y)) continue;
      if (d1 < 0) {
        best = v;
        d1 = d;
      } else {
        return {best, {d1, d}};
      }
    }
    return {best, {d1, HUGE_VAL}};
  }
};

// What no optimization may change: the domain flag of the faces on each side of every
// constrained edge (named by its two vertices: constrained vertices never move, and the
// optimizers neither insert nor remove vertices), where the constrained vertices are, how many
// vertices there are, and the domain's area.
struct Domain_marks {
  // (a, b) -> the flag of the face on the left of a -> b; both directions of every edge
  std::map<std::pair<Cdt::Vertex_handle, Cdt::Vertex_handle>, bool> sides;
  std::map<Cdt::Vertex_handle, Point> constrained_points;
  std::size_t number_of_vertices = 0;
  double area = 0;
};

inline Domain_marks snapshot_marks(const Cdt& cdt) {
  Domain_marks m;
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
    if (!cdt.is_constrained(*e)) continue;
    const auto f = e->first, g = f->neighbor(e->second);
    const auto a = f->vertex(cdt.ccw(e->second)), b = f->vertex(cdt.cw(e->second));
    m.sides[{a, b}] = f->is_inside_domain();  // f is on the left of a -> b
    m.sides[{b, a}] = g->is_inside_domain();
  }
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (cdt.are_there_incident_constraints(v)) m.constrained_points[v] = v->point();
  m.number_of_vertices = cdt.number_of_vertices();
  m.area = domain_area(cdt);
  return m;
}

// The triangulation's invariants: valid, constrained Delaunay (no unconstrained edge that
// fails the empty-circle test, symbolically perturbed as CGAL's and the library's flips test
// it), and the marks of the snapshot: every constrained edge's two sides as recorded, both
// sides of every unconstrained finite edge alike, every infinite face outside; the
// constrained vertices where they were. Returns whether all hold (each failure is a CHECK).
inline bool check_triangulation(const Cdt& cdt, const Domain_marks& marks) {
  const bool valid = cdt.is_valid();
  CHECK(valid);
  std::size_t flippable = 0, constrained = 0, wrong_side = 0, unknown = 0, unequal = 0;
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
    const auto f = e->first, g = f->neighbor(e->second);
    if (!cdt.is_constrained(*e)) {
      flippable += cdt.is_flipable(f, e->second);
      unequal += f->is_inside_domain() != g->is_inside_domain();
      continue;
    }
    ++constrained;
    const auto a = f->vertex(cdt.ccw(e->second)), b = f->vertex(cdt.cw(e->second));
    const auto ab = marks.sides.find({a, b}), ba = marks.sides.find({b, a});
    if (ab == marks.sides.end() || ba == marks.sides.end()) {
      ++unknown;
      continue;
    }
    wrong_side += (ab->second != f->is_inside_domain()) + (ba->second != g->is_inside_domain());
  }
  std::size_t infinite_inside = 0, moved = 0, faceless = 0;
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
    infinite_inside += cdt.is_infinite(f) && f->is_inside_domain();
  // CGAL's is_valid() does not look whether a vertex's face holds it
  if (cdt.dimension() == 2)
    for (auto v = cdt.all_vertices_begin(); v != cdt.all_vertices_end(); ++v)
      faceless += !v->face()->has_vertex(v);
  for (const auto& [v, p] : marks.constrained_points) moved += v->point() != p;
  // (a domain whose area under- or overflows double, 1e-300 or 1e300 wide, is not compared)
  const bool same_area = !std::isnormal(marks.area) || !std::isfinite(marks.area) ||
                         domain_area(cdt) == Approx(marks.area).epsilon(1e-12);
  CHECK(flippable == 0);
  CHECK(2 * constrained == marks.sides.size());
  CHECK(unknown == 0);
  CHECK(wrong_side == 0);
  CHECK(unequal == 0);
  CHECK(infinite_inside == 0);
  CHECK(faceless == 0);
  CHECK(moved == 0);
  CHECK(cdt.number_of_vertices() == marks.number_of_vertices);
  CHECK(same_area);
  return valid && same_area && flippable == 0 && 2 * constrained == marks.sides.size() &&
         unknown == 0 && wrong_side == 0 && unequal == 0 && infinite_inside == 0 && faceless == 0 &&
         moved == 0 && cdt.number_of_vertices() == marks.number_of_vertices;
}

// The diagram's invariants: partition, convexity, the nearest-visible-generator oracle on
// `samples` points drawn with `seed`; returns the samples that were decided (not within
// rounding of a tie). Cells have positive area, or with subnormal_cells, non-negative: a cell
// of area below 1e-323 may round to 0.
inline std::size_t check_diagram(const Bvd& bvd, std::size_t samples, unsigned seed,
                                 bool subnormal_cells = false) {
  const Cdt& cdt = bvd.triangulation();
  const double area = domain_area(cdt);
  REQUIRE(area > 0);
  CHECK(total_cell_area(bvd) == Approx(area).epsilon(1e-10));

  // Every free cell is convex, counterclockwise, and holds its generator; every cell has
  // positive area.
  Cell c;
  std::size_t non_convex = 0, not_containing = 0, not_positive = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    bvd.cell(v, c);
    if (c.empty()) continue;
    if (!(signed_area(c) > 0) && !(subnormal_cells && signed_area(c) == 0)) ++not_positive;
    if (!bvd.is_free(v)) continue;
    double size = 0;
    for (const auto& x : c)
      size = std::max(size, std::sqrt(CGAL::squared_distance(x.point, v->point())));
    for (std::size_t i = 0; i < c.size(); ++i) {
      const auto& a = c[i].point;
      const auto& b = c[(i + 1) % c.size()].point;
      const auto& d = c[(i + 2) % c.size()].point;
      const double turn = (b.x() - a.x()) * (d.y() - b.y()) - (b.y() - a.y()) * (d.x() - b.x());
      if (turn < -1e-9 * size * size) ++non_convex;
    }
    if (!polygon_contains(c, v->point())) ++not_containing;
  }
  CHECK(not_positive == 0);
  CHECK(non_convex == 0);
  CHECK(not_containing == 0);

  // The optimizers' pass lists each cell's points as cell() does, to the bit, each vertex once:
  // the cells it reads straight from the faces (free, no blind face) and the others.
  std::map<Cdt::Vertex_handle, std::vector<Point>> listed;
  std::vector<Point> points;
  std::size_t twice = 0, wrong_points = 0, wrong_free = 0;
  CVT_2::internal::for_each_cell_points_in_faces(
      bvd, cdt.all_faces_begin(), cdt.all_faces_end(), points,
      [&](Cdt::Vertex_handle v, const std::vector<Point>& p, bool is_free) {
        if (!listed.emplace(v, p).second) ++twice;
        if (is_free != bvd.is_free(v)) ++wrong_free;
      });
  std::size_t with_cell = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    bvd.cell(v, c);
    if (c.empty()) continue;
    ++with_cell;
    const auto it = listed.find(v);
    if (it == listed.end() || it->second.size() != c.size()) {
      ++wrong_points;
      continue;
    }
    for (std::size_t i = 0; i < c.size(); ++i)
      if (it->second[i] != c[i].point) ++wrong_points;
  }
  CHECK(twice == 0);
  CHECK(wrong_points == 0);
  CHECK(wrong_free == 0);
  CHECK(listed.size() == with_cell);

  // Sample points fall in the cell of their nearest visible generator (brute force).
  if (samples == 0) return 0;
  const Visibility_oracle oracle(bvd);
  const double tol = 1e-9 * area;  // squared-distance gap below which a tie is rounding's call
  std::size_t decided = 0, wrong = 0;
  for (const Point& y : random_points_in_domain(cdt, samples, seed)) {
    const auto [v, d] = oracle.nearest_visible(y);
    REQUIRE(v != Cdt::Vertex_handle());
    if (d.second - d.first < tol) continue;
    ++decided;
    bvd.cell(v, c);
    if (!polygon_contains(c, y)) {
      ++wrong;
      if (wrong <= 3) {
        CAPTURE(y, v->point(), d.first, d.second);
        CHECK(polygon_contains(c, y));
      }
    }
  }
  CHECK(wrong == 0);
  return decided;
}

// Every invariant after a mutation: the triangulation's against the snapshot `marks`, then the
// diagram's, with `samples` points for the nearest-visible oracle (a few dozen keep a check
// after each Lloyd iteration cheap).
inline void check_invariants(const Cdt& cdt, const Domain_marks& marks, std::size_t samples = 200,
                             unsigned seed = 1, bool subnormal_cells = false) {
  check_triangulation(cdt, marks);
  check_diagram(Bvd(cdt), samples, seed, subnormal_cells);
}

}  // namespace support

#endif  // CVT_2_TEST_SUPPORT_INVARIANTS_H
