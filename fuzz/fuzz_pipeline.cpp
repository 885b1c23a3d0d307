// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the whole pipeline on a fuzzed .poly domain: insert_poly, generators (the
// file's free vertices, else seeded random points), the bounded Voronoi diagram and one Lloyd
// step, with oracles: the cells tile the domain, the energy is finite and does not rise.
#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/IO/read_poly.h>
#include <CVT_2/Lloyd_optimizer_2.h>
#include <CVT_2/exceptions.h>
#include <CVT_2/insert_generators_2.h>
#include <CVT_2/random_points_in_domain_2.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_2<K>;
using Fb = CVT_2::Bvd_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<
    K, Tds, CGAL::No_constraint_intersection_requiring_constructions_tag>;
using Bvd = CVT_2::Bounded_voronoi_diagram_2<CDT>;
using Point = K::Point_2;

namespace {

constexpr std::size_t max_bytes = 8192, max_vertices = 300, random_generators = 20;

[[noreturn]] void violated(const char* what, double a, double b) {
  std::fprintf(stderr, "ORACLE VIOLATED: %s (%.17g vs %.17g)\n", what, a, b);
  std::abort();
}

// Areas in units of 2^e, the domain's extent, so that domains 1e-300 or 1e300 wide neither
// underflow nor overflow: twice the signed area of (a, b, c).
struct Area_meter {
  int e = 0;
  double operator()(const Point& a, const Point& b, const Point& c) const {
    const double ux = std::ldexp(b.x() - a.x(), -e), uy = std::ldexp(b.y() - a.y(), -e);
    const double vx = std::ldexp(c.x() - a.x(), -e), vy = std::ldexp(c.y() - a.y(), -e);
    return ux * vy - uy * vx;
  }
};

Area_meter area_meter(const CDT& cdt) {
  double extent = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->is_inside_domain())
      for (int i = 1; i < 3; ++i)
        extent = std::max({extent, std::abs(f->vertex(i)->point().x() - f->vertex(0)->point().x()),
                           std::abs(f->vertex(i)->point().y() - f->vertex(0)->point().y())});
  Area_meter m;
  if (extent > 0) std::frexp(extent, &m.e);
  return m;
}

double domain_area(const CDT& cdt, const Area_meter& area) {
  double a = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->is_inside_domain())
      a += area(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
  return a;
}

// Every vertex of the closed domain has one cell, no cell is inverted, and the cells tile the
// domain.
void check_cells_tile_domain(const Bvd& bvd, const Area_meter& area) {
  const CDT& cdt = bvd.triangulation();
  const double domain = domain_area(cdt, area);
  std::size_t with_cell = 0, visited = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    with_cell += bvd.has_cell(v);
  double cells = 0;
  bvd.for_each_cell([&](CDT::Vertex_handle, const auto& cell) {
    ++visited;
    double a = 0;
    for (std::size_t i = 1; i + 1 < cell.size(); ++i)
      a += area(cell[0].point, cell[i].point, cell[i + 1].point);
    if (!(a >= -1e-9 * domain)) violated("a cell has negative area", a, domain);
    cells += a;
  });
  if (visited != with_cell) violated("cells visited != vertices with a cell", visited, with_cell);
  if (!(std::abs(cells - domain) <= 1e-9 * domain))
    violated("cell areas do not sum to the domain's area", cells, domain);
}

std::uint64_t fnv1a(const std::uint8_t* data, std::size_t size) {
  std::uint64_t h = 14695981039346656037ull;
  for (std::size_t i = 0; i < size; ++i) h = (h ^ data[i]) * 1099511628211ull;
  return h;
}

}  // namespace

// Only the documented errors are expected; anything else escapes and is a finding.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > max_bytes) return 0;
  std::istringstream is(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const auto poly = CVT_2::IO::read_poly<Point>(is, "fuzz.poly");
    if (poly.vertices.size() > max_vertices) return 0;
    CDT cdt;
    CVT_2::IO::insert_poly(cdt, poly);
    std::vector<bool> on_segment(poly.vertices.size(), false);
    for (const auto& s : poly.segments) on_segment[s[0]] = on_segment[s[1]] = true;
    if (std::find(on_segment.begin(), on_segment.end(), false) == on_segment.end())
      CVT_2::insert_generators_2(
          cdt, CVT_2::random_points_in_domain_2(
                   cdt, random_generators, CVT_2::parameters::random_seed(fnv1a(data, size))));
    const Area_meter area = area_meter(cdt);

    Bvd bvd(cdt);
    bvd.update();
    check_cells_tile_domain(bvd, area);

    CVT_2::Lloyd_optimizer_2<CDT> lloyd(cdt);
    const double e0 = lloyd.evaluate(10).energy;
    lloyd.move();
    const double e1 = lloyd.evaluate(10).energy;
    if (!std::isfinite(e0) || !std::isfinite(e1)) violated("the energy is not finite", e0, e1);
    if (e1 > e0 * (1 + 1e-12)) violated("the energy rose after one Lloyd step", e1, e0);
    check_cells_tile_domain(lloyd.diagram(), area);
  } catch (const CVT_2::IO::Parse_error&) {
  } catch (const CVT_2::Domain_error&) {
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
