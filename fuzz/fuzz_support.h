// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// What the fuzz targets share: the triangulation types, the cheap oracles, and the rule that
// only the library's documented errors may escape.
#ifndef CVT_2_FUZZ_SUPPORT_H
#define CVT_2_FUZZ_SUPPORT_H

#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/Bvd_mesh_2.h>
#include <CVT_2/Cvt_triangulation_2.h>
#include <CVT_2/exceptions.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <stdexcept>
#include <utility>

namespace fuzz {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using CDT = CVT_2::Cvt_triangulation_2<K>;
using Bvd = CVT_2::Bounded_voronoi_diagram_2<CDT>;

// Runs f; the documented errors (all std::invalid_argument) are expected answers to bad input.
// Any other exception escapes, and libFuzzer reports it.
template <class F>
void expecting_documented_errors(F f) {
  try {
    f();
  } catch (const CVT_2::IO::Parse_error&) {
  } catch (const CVT_2::Domain_error&) {
  } catch (const std::invalid_argument&) {
  }
}

[[noreturn]] inline void violated(const char* what, double a, double b) {
  std::fprintf(stderr, "ORACLE VIOLATED: %s (%.17g vs %.17g)\n", what, a, b);
  std::abort();
}

// Areas in units of 2^e, the domain's extent, so that domains 1e-300 or 1e300 wide neither
// underflow nor overflow: operator() is twice the signed area of (a, b, c). `condition` says
// how ill-conditioned the domain faces are: the largest of the extent over the shortest edge
// and, for each face, its longest edge squared over twice its area (1.15 for an equilateral
// triangle; a needle's is huge).
struct Area_meter {
  int e = 0;
  double condition = 1;
  double operator()(const Point& a, const Point& b, const Point& c) const {
    const double ux = std::ldexp(b.x() - a.x(), -e), uy = std::ldexp(b.y() - a.y(), -e);
    const double vx = std::ldexp(c.x() - a.x(), -e), vy = std::ldexp(c.y() - a.y(), -e);
    return ux * vy - uy * vx;
  }
};

inline Area_meter area_meter(const CDT& cdt) {
  Area_meter m;
  double extent = 0, shortest = HUGE_VAL;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->is_inside_domain())
      for (int i = 0; i < 3; ++i) {
        const Point& p = f->vertex(i)->point();
        const Point& q = f->vertex((i + 1) % 3)->point();
        const double l = std::max(std::abs(q.x() - p.x()), std::abs(q.y() - p.y()));
        extent = std::max(extent, l);
        shortest = std::min(shortest, l);
      }
  if (extent > 0) std::frexp(extent, &m.e);
  m.condition = extent / shortest;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_inside_domain()) continue;
    int o = 0;  // the vertex opposite the longest edge: the area from it does not cancel
    double longest = -1;
    for (int i = 0; i < 3; ++i) {
      const Point& p = f->vertex((i + 1) % 3)->point();
      const Point& q = f->vertex((i + 2) % 3)->point();
      const double dx = std::ldexp(q.x() - p.x(), -m.e), dy = std::ldexp(q.y() - p.y(), -m.e);
      if (dx * dx + dy * dy > longest) longest = dx * dx + dy * dy, o = i;
    }
    const double twice_area = std::abs(
        m(f->vertex(o)->point(), f->vertex((o + 1) % 3)->point(), f->vertex((o + 2) % 3)->point()));
    m.condition = std::max(m.condition, twice_area > 0 ? longest / twice_area : HUGE_VAL);
  }
  return m;
}

inline double domain_area(const CDT& cdt, const Area_meter& area) {
  double a = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->is_inside_domain())
      a += area(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
  return a;
}

// Whether the tolerances of the oracles hold: beyond a condition of 1e6, rounding alone can
// exceed them (a vertex at 1e300 among vertices at 10 does; a needle's area cancels), and only
// finiteness is checked.
inline bool is_well_conditioned(const CDT& cdt) { return area_meter(cdt).condition <= 1e6; }

// Every vertex of the closed domain has one cell and every cell a finite area, always. On a
// well-conditioned triangulation, also: no cell is inverted and the cell areas sum to the
// domain's (relative 1e-9).
inline void check_cells_tile_domain(const Bvd& bvd) {
  const CDT& cdt = bvd.triangulation();
  const Area_meter area = area_meter(cdt);
  const double domain = domain_area(cdt, area);
  const double tolerance = is_well_conditioned(cdt) ? 1e-9 * domain : HUGE_VAL;
  std::size_t with_cell = 0, visited = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    with_cell += bvd.has_cell(v);
  double cells = 0;
  bvd.for_each_cell([&](CDT::Vertex_handle, const auto& cell) {
    ++visited;
    double a = 0;
    for (std::size_t i = 1; i + 1 < cell.size(); ++i)
      a += area(cell[0].point, cell[i].point, cell[i + 1].point);
    if (!std::isfinite(a)) violated("a cell's area is not finite", a, domain);
    if (!(a >= -tolerance)) violated("a cell has negative area", a, domain);
    cells += a;
  });
  if (visited != with_cell)
    violated("cells visited != vertices with a cell", double(visited), double(with_cell));
  if (!(std::abs(cells - domain) <= tolerance))
    violated("cell areas do not sum to the domain's area", cells, domain);
}

// The mesh of the diagram: a cell for every vertex with one, the same on one and two threads;
// no cycle stays at one vertex; a bisector edge is walked the other way by the cell beyond it;
// a cell of positive area by the walk keeps three vertices and positive area (merging points a
// rounding apart never empties a thin cell); and on a well-conditioned triangulation the cell
// areas sum to the domain's.
inline void check_mesh(const Bvd& bvd) {
  using Mesh = CVT_2::Bvd_mesh_2<Bvd>;
  const Mesh mesh(bvd, 1), two(bvd, 2);
  const CDT& cdt = bvd.triangulation();
  std::size_t with_cell = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    with_cell += bvd.has_cell(v);
  if (mesh.number_of_cells() != with_cell)
    violated("mesh cells != vertices with a cell", double(mesh.number_of_cells()),
             double(with_cell));
  if (mesh.points() != two.points() || mesh.number_of_cells() != two.number_of_cells())
    violated("the mesh differs on two threads", double(mesh.number_of_vertices()),
             double(two.number_of_vertices()));
  const Area_meter area = area_meter(cdt);
  const double domain = domain_area(cdt, area);
  double cells = 0;
  std::map<std::pair<Mesh::Index, Mesh::Index>, Mesh::Index> walked;  // edge -> its cell
  for (std::size_t k = 0; k < mesh.number_of_cells(); ++k) {
    const auto c = mesh.cell(k), d = two.cell(k);
    if (!std::equal(c.begin(), c.end(), d.begin(), d.end()))
      violated("a mesh cell differs on two threads", double(k), double(c.size()));
    for (std::size_t j = 1; j + 1 < c.size(); ++j)
      cells += area(mesh.point(c[0]), mesh.point(c[j]), mesh.point(c[j + 1]));
    for (std::size_t j = 0; j < c.size(); ++j) {
      const Mesh::Index a = c[j], b = c[(j + 1) % c.size()];
      if (c.size() > 1 && a == b) violated("a mesh cycle stays at one vertex", double(k), a);
      if (mesh.side(k, j).constraint == Mesh::none) walked[{a, b}] = Mesh::Index(k);
    }
  }
  std::size_t k = 0;
  bvd.for_each_cell([&](CDT::Vertex_handle, const auto& cell) {
    double walked = 0, meshed = 0;
    for (std::size_t i = 1; i + 1 < cell.size(); ++i)
      walked += area(cell[0].point, cell[i].point, cell[i + 1].point);
    const auto c = mesh.cell(k);
    for (std::size_t j = 1; j + 1 < c.size(); ++j)
      meshed += area(mesh.point(c[0]), mesh.point(c[j]), mesh.point(c[j + 1]));
    if (walked > 0 && (c.size() < 3 || !(meshed > 0)))
      violated("a cell of positive area has none in the mesh", walked, double(c.size()));
    ++k;
  });
  for (std::size_t k = 0; k < mesh.number_of_cells(); ++k) {
    const auto c = mesh.cell(k);
    for (std::size_t j = 0; j < c.size(); ++j) {
      const Mesh::Side& s = mesh.side(k, j);
      if (s.constraint != Mesh::none) continue;
      const auto back = walked.find({c[(j + 1) % c.size()], c[j]});
      if (back == walked.end() || back->second != s.cell)
        violated("a bisector edge is not walked back by the cell beyond", double(k), double(j));
    }
  }
  if (is_well_conditioned(cdt) && !(std::abs(cells - domain) <= 1e-9 * domain))
    violated("mesh cell areas do not sum to the domain's area", cells, domain);
}

}  // namespace fuzz

#endif  // CVT_2_FUZZ_SUPPORT_H
