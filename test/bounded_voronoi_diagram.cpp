// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Properties of the bounded Voronoi diagram: partition, convexity, nearest visible generator.
#include "support/invariants.h"
#include "support/random_domain.h"
#include "support/support.h"

#include <CVT_2/Constraint_editor_2.h>
#include <CVT_2/Cvt_triangulation_2.h>
#include <CVT_2/Lloyd_optimizer_2.h>
#include <CVT_2/internal/layout/sort_faces.h>
#include <CVT_2/internal/parallel/Face_chunks.h>

#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <tuple>

using namespace support;

namespace {

struct Case {
  const char* file;
  std::size_t points;  // random generators added to the file's own
  std::size_t samples;
};
const Case cases[] = {
    {"four_clusters.poly", 300, 3000},
    {"square_inner_constraints.poly", 1500, 3000},
    {"us_massachusetts_counties.poly", 1500, 3000},
    {"earcut_dude.poly", 800, 3000},
    {"earcut_logo.poly", 1500, 2000},
    {"france_mainland.poly", 1000, 2000},
    {"earcut_eberly6.poly", 1500, 1500},
    {"world_land_110m.poly", 2000, 600},
};

}  // namespace

TEST_CASE("cells tile the domain and each sample lies in the cell of its nearest visible generator",
          "[bvd]") {
  const Case k = GENERATE(from_range(std::begin(cases), std::end(cases)));
  const unsigned seed = GENERATE(1u, 2u);
  CAPTURE(k.file, seed);
  Domain d;
  load_domain(d, k.file);
  insert_random_points(d, k.points, seed);
  const Bvd bvd(d.cdt);
  CHECK(check_diagram(bvd, k.samples, seed + 100) > k.samples * 9 / 10);
}

TEST_CASE("blind tags equal a brute-force exact search for the first constraint hit", "[bvd]") {
  using EK = CGAL::Exact_predicates_exact_constructions_kernel;
  const CGAL::Cartesian_converter<K, EK> to_exact;
  const char* file =
      GENERATE("square_inner_constraints.poly", "us_massachusetts_counties.poly",
               "earcut_dude.poly", "four_clusters.poly", "earcut_logo.poly", "earcut_eberly6.poly");
  const unsigned seed = GENERATE(3u, 4u);
  CAPTURE(file, seed);
  Domain d;
  load_domain(d, file);
  insert_random_points(d, 3000, seed);
  const Bvd bvd(d.cdt);

  std::vector<std::pair<EK::Segment_2, Cdt::Edge>> constraints;
  for (auto e = d.cdt.finite_edges_begin(); e != d.cdt.finite_edges_end(); ++e)
    if (d.cdt.is_constrained(*e)) constraints.push_back({to_exact(d.cdt.segment(*e)), *e});
  std::size_t blind = 0, mismatches = 0;
  for (auto f = d.cdt.finite_faces_begin(); f != d.cdt.finite_faces_end(); ++f) {
    if (!f->is_inside_domain()) continue;
    const EK::Triangle_2 t = to_exact(d.cdt.triangle(f));
    const EK::Point_2 g = CGAL::centroid(t), cc = CGAL::circumcenter(t[0], t[1], t[2]);
    const EK::Segment_2 dual(g, cc);
    // The first constraint met by [g, c), c on a constraint's line not counting for that one.
    std::vector<Cdt::Edge> first;
    EK::FT best = -1;
    for (const auto& [s, e] : constraints) {
      if (CGAL::collinear(s.source(), s.target(), cc) || !CGAL::do_intersect(dual, s)) continue;
      const auto x = CGAL::intersection(dual.supporting_line(), s.supporting_line());
      const EK::Point_2* px = boost::get<EK::Point_2>(&*x);
      REQUIRE(px != nullptr);
      const EK::FT dist = CGAL::squared_distance(g, *px);
      if (best < 0 || dist < best) {
        best = dist;
        first.assign(1, e);
      } else if (dist == best) {
        first.push_back(e);
      }
    }
    if (first.empty()) {
      if (f->is_blinded()) ++mismatches;
      continue;
    }
    ++blind;
    bool ok = f->is_blinded();
    if (ok) {
      ok = false;
      for (const auto& e : first)
        ok = ok || CVT_2::internal::is_same_constraint<Cdt>(e, f->blinding_edge());
    }
    if (!ok) ++mismatches;
  }
  CHECK(blind > 0);
  CHECK(blind == bvd.number_of_blinded_faces());
  CHECK(mismatches == 0);
}

TEST_CASE("cells survive translation and scaling of the input", "[bvd]") {
  const double scale = GENERATE(1e-6, 1e-3, 1024.0, 1e6);
  const double offset = GENERATE(0.0, 1e4);
  CAPTURE(scale, offset);
  Domain ref, moved;
  load_domain(ref, "square_inner_constraints.poly");
  load_domain(moved, "square_inner_constraints.poly", scale, offset * scale, -offset * scale);
  const auto pts = random_points_in_domain(ref.cdt, 500, 11);
  std::vector<Point> moved_pts;
  for (const auto& p : pts)
    moved_pts.emplace_back(scale * p.x() + offset * scale, scale * p.y() - offset * scale);
  CVT_2::insert_generators_2(ref.cdt, pts);
  CVT_2::insert_generators_2(moved.cdt, moved_pts);
  const Bvd a(ref.cdt), b(moved.cdt);
  CHECK(total_cell_area(b) == Approx(domain_area(moved.cdt)).epsilon(1e-10));
  // Same generators in the same order: cell areas scale by scale².
  std::vector<double> areas_a, areas_b;
  Cell c;
  for (auto v = ref.cdt.finite_vertices_begin(); v != ref.cdt.finite_vertices_end(); ++v) {
    a.cell(v, c);
    areas_a.push_back(signed_area(c));
  }
  for (auto v = moved.cdt.finite_vertices_begin(); v != moved.cdt.finite_vertices_end(); ++v) {
    b.cell(v, c);
    areas_b.push_back(signed_area(c) / (scale * scale));
  }
  REQUIRE(areas_a.size() == areas_b.size());
  const double tolerance = offset == 0 ? 1e-9 : 1e-5;  // an offset costs digits
  std::size_t differ = 0;
  for (std::size_t i = 0; i < areas_a.size(); ++i)
    if (std::abs(areas_a[i] - areas_b[i]) > tolerance * 100.0 / areas_a.size() + 1e-12) ++differ;
  CHECK(differ == 0);
  check_diagram(b, 1000, 5);
}

TEST_CASE("degenerate input: cocircular grid, points on constraints, collinear boundary",
          "[bvd][degenerate]") {
  // A square whose sides carry extra collinear vertices, an inner segment, a regular grid of
  // generators (every four of them cocircular) with some of them exactly on the constraints.
  CVT_2::IO::Poly_data<Point> poly;
  const int n = 10;
  for (int i = 0; i < n; ++i) poly.vertices.emplace_back(i, 0);
  for (int i = 0; i < n; ++i) poly.vertices.emplace_back(n, i);
  for (int i = 0; i < n; ++i) poly.vertices.emplace_back(n - i, n);
  for (int i = 0; i < n; ++i) poly.vertices.emplace_back(0, n - i);
  for (std::size_t i = 0; i < poly.vertices.size(); ++i)
    poly.segments.push_back({i, (i + 1) % poly.vertices.size()});
  poly.vertices.emplace_back(2, 5);
  poly.vertices.emplace_back(8, 5);
  poly.segments.push_back({poly.vertices.size() - 2, poly.vertices.size() - 1});
  poly.segment_lines.assign(poly.segments.size(), 0);
  poly.vertex_lines.assign(poly.vertices.size(), 0);
  const double step = GENERATE(0.5, 1.0 / 3.0);
  CAPTURE(step);
  Cdt cdt;
  CVT_2::IO::insert_poly(cdt, poly);
  std::vector<Point> grid;
  for (double x = 0; x <= n; x += step)
    for (double y = 0; y <= n; y += step) grid.emplace_back(x, y);
  CVT_2::insert_generators_2(cdt, grid);
  const Bvd bvd(cdt);
  check_diagram(bvd, 3000, 7);
}

TEST_CASE("degenerate input: right triangles put circumcenters exactly on constraints",
          "[bvd][degenerate]") {
  // Generators mirrored across a slit, at equal distance: circumcenters fall on the slit's line.
  Domain d;
  load_domain(d, "square_inner_constraints.poly");
  std::vector<Point> pts;
  for (int i = 1; i < 40; ++i)
    for (int j = 1; j < 40; ++j) pts.emplace_back(i * 0.25, j * 0.25);
  CVT_2::insert_generators_2(d.cdt, pts);
  const Bvd bvd(d.cdt);
  check_diagram(bvd, 3000, 9);
}

TEST_CASE("tiny and huge domains far from the origin", "[bvd][degenerate]") {
  const double scale = GENERATE(1e-9, 1e9);
  const double offset = GENERATE(0.0, 1e3);
  CAPTURE(scale, offset);
  Domain d;
  load_domain(d, "four_clusters.poly", scale, offset * scale, offset * scale);
  insert_random_points(d, 300, 13);
  const Bvd bvd(d.cdt);
  check_diagram(bvd, 1500, 17);
}

TEST_CASE("a vertex on inner constraints has one cell, with a slit along each constraint",
          "[bvd]") {
  Domain d;
  load_domain(d, "square_inner_constraints.poly");
  insert_random_points(d, 500, 19);
  const Bvd bvd(d.cdt);
  Cell c;
  std::size_t checked = 0;
  for (auto v = d.cdt.finite_vertices_begin(); v != d.cdt.finite_vertices_end(); ++v) {
    bvd.cell(v, c);
    if (bvd.is_free(v)) {
      for (const auto& x : c) CHECK(x.type != Bvd::Cell_vertex::GENERATOR);
      continue;
    }
    // One GENERATOR entry per wedge of domain faces between two constraints around v.
    std::size_t wedges = 0, constraints = 0;
    auto e = d.cdt.incident_edges(v), done = e;
    do {
      if (!d.cdt.is_constrained(*e)) continue;
      ++constraints;
      // the face after this constraint, counterclockwise around v
      const Cdt::Vertex_handle vh = v;
      const auto f =
          e->first->vertex(d.cdt.ccw(e->second)) == vh ? e->first : e->first->neighbor(e->second);
      if (f->is_inside_domain() && !d.cdt.is_infinite(f)) ++wedges;
    } while (++e != done);
    std::size_t generators = 0;
    for (const auto& x : c) generators += x.type == Bvd::Cell_vertex::GENERATOR;
    CHECK(generators == wedges);
    ++checked;
  }
  CHECK(checked >= 18);
}

TEST_CASE(
    "cell vertices say what they are: circumcenters, clip points on their constraint, generator",
    "[bvd]") {
  Domain d;
  load_domain(d, "us_massachusetts_counties.poly");
  insert_random_points(d, 1000, 23);
  const Bvd bvd(d.cdt);
  std::size_t clips = 0;
  for (auto v = d.cdt.finite_vertices_begin(); v != d.cdt.finite_vertices_end(); ++v) {
    auto circ = bvd.cell_vertices(v);
    if (circ == nullptr) {
      CHECK(!bvd.has_cell(v));
      continue;
    }
    const auto polygon = bvd.cell_polygon(v);
    CHECK(polygon.size() == circ.size());
    auto done = circ;
    std::size_t i = 0;
    do {
      CHECK(polygon[i++] == circ->point);
      switch (circ->type) {
        case Bvd::Cell_vertex::CIRCUMCENTER:
          CHECK(circ->point == d.cdt.circumcenter(circ->face));
          CHECK(!circ->face->is_blinded());
          break;
        case Bvd::Cell_vertex::CLIP_POINT: {
          ++clips;
          const auto s = d.cdt.segment(circ->constraint);
          CHECK(CGAL::squared_distance(s, circ->point) <= 1e-20 * s.squared_length());
          CHECK(CGAL::squared_distance(v->point(), circ->point) ==
                Approx(CGAL::squared_distance(circ->neighbor->point(), circ->point)).epsilon(1e-9));
          break;
        }
        case Bvd::Cell_vertex::GENERATOR:
          CHECK(circ->point == v->point());
          CHECK(!bvd.is_free(v));
          break;
      }
    } while (++circ != done);
  }
  CHECK(clips > 0);
}

TEST_CASE(
    "the face base stacks on CGAL's Delaunay_mesh_face_base_2 and costs at most 8 bytes a face",
    "[bvd]") {
  using Mesh_fb = CVT_2::Bvd_face_base_2<K, CGAL::Delaunay_mesh_face_base_2<K>>;
  using Mesh_tds = CGAL::Triangulation_data_structure_2<Vb, Mesh_fb>;
  using Mesh_cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Mesh_tds>;
  STATIC_REQUIRE(sizeof(Fb) <= sizeof(CGAL::Constrained_Delaunay_triangulation_face_base_2<K>) + 8);
  Mesh_cdt cdt;
  const auto poly = CVT_2::IO::read_poly<Point>(data_path("earcut_dude.poly"));
  CVT_2::IO::insert_poly(cdt, poly);
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->set_in_domain(false);
  const CVT_2::Bounded_voronoi_diagram_2<Mesh_cdt> bvd(cdt);
  double area = 0;
  std::vector<CVT_2::Bounded_voronoi_diagram_2<Mesh_cdt>::Cell_vertex> c;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    bvd.cell(v, c);
    for (std::size_t i = 1; i + 1 < c.size(); ++i)
      area += CGAL::area(c[0].point, c[i].point, c[i + 1].point);
  }
  double domain = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    CHECK(!f->is_in_domain());  // CGAL's flag is CGAL's: ours did not touch it
    if (f->is_inside_domain()) domain += cdt.triangle(f).area();
  }
  CHECK(area == Approx(domain).epsilon(1e-10));
}

TEST_CASE("nested constraints: a face keeps the first constraint on the way to its circumcenter",
          "[bvd][degenerate]") {
  // A flat face under a slit y = 9, x in [4, 6], below the top side y = 10: its circumcenter
  // (5, 10.1) lies beyond both, and the slit is met first. Algorithm 2 must clip on the slit.
  // Both orders of insertion and four rotations, since the walks' order follows storage.
  const bool reversed = GENERATE(false, true);
  const int quarter_turns = GENERATE(0, 1, 2, 3);
  CAPTURE(reversed, quarter_turns);
  const auto turn = [quarter_turns](Point p) {  // a quarter turn about (5, 5), exact
    for (int i = 0; i < quarter_turns; ++i) p = Point(10 - p.y(), p.x());
    return p;
  };
  CVT_2::IO::Poly_data<Point> poly;
  poly.vertices = {Point(0, 0),  Point(10, 0), Point(10, 10),
                   Point(0, 10), Point(4, 9),  Point(6, 9)};
  for (auto& p : poly.vertices) p = turn(p);
  poly.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}};
  if (reversed) {
    std::reverse(poly.vertices.begin(), poly.vertices.end());
    for (auto& s : poly.segments) s = {5 - s[0], 5 - s[1]};
    std::reverse(poly.segments.begin(), poly.segments.end());
  }
  poly.vertex_lines.assign(6, 0);
  poly.segment_lines.assign(5, 0);
  Cdt cdt;
  CVT_2::IO::insert_poly(cdt, poly);
  std::vector<Point> pts{Point(4.5, 8.9), Point(5.5, 8.9), Point(5, 8.8), Point(2, 2),
                         Point(8, 3),     Point(5, 5),     Point(2, 7),   Point(8, 7)};
  for (auto& p : pts) p = turn(p);
  if (reversed) std::reverse(pts.begin(), pts.end());
  CVT_2::insert_generators_2(cdt, pts);
  const Bvd bvd(cdt);
  Cdt::Face_handle f;
  Cdt::Vertex_handle v[3];
  int k = 0;
  for (const Point& p : {Point(4.5, 8.9), Point(5.5, 8.9), Point(5, 8.8)}) {
    Cdt::Locate_type lt;
    int li;
    const auto g = cdt.locate(turn(p), lt, li);
    REQUIRE(lt == Cdt::VERTEX);
    v[k++] = g->vertex(li);
  }
  REQUIRE(cdt.is_face(v[0], v[1], v[2], f));
  REQUIRE(f->is_blinded());
  const auto s = cdt.segment(f->blinding_edge());
  const auto slit = K::Segment_2(turn(Point(4, 9)), turn(Point(6, 9)));
  CHECK((s == slit || s == slit.opposite()));
  check_diagram(bvd, 4000, 29);
}

TEST_CASE("extreme scales: a power-of-two scaling scales every cell exactly", "[bvd][degenerate]") {
  // Feature sizes near 1e-290 or 1e290 make the circumcenter formula's cubic terms underflow
  // or overflow in double; the constructions rescale their differences, so the cells are the
  // unit-scale cells, scaled, to the bit.
  const int exponent = GENERATE(-960, -200, 200, 960);
  CAPTURE(exponent);
  Domain ref, scaled;
  load_domain(ref, "square_inner_constraints.poly");
  load_domain(scaled, "square_inner_constraints.poly", std::ldexp(1.0, exponent));
  const auto pts = random_points_in_domain(ref.cdt, 300, 31);
  std::vector<Point> scaled_pts;
  for (const auto& p : pts)
    scaled_pts.emplace_back(std::ldexp(p.x(), exponent), std::ldexp(p.y(), exponent));
  CVT_2::insert_generators_2(ref.cdt, pts);
  CVT_2::insert_generators_2(scaled.cdt, scaled_pts);
  const Bvd a(ref.cdt), b(scaled.cdt);
  Cell ca, cb;
  std::size_t cells = 0, differ = 0;
  auto vb = scaled.cdt.finite_vertices_begin();
  for (auto va = ref.cdt.finite_vertices_begin(); va != ref.cdt.finite_vertices_end(); ++va, ++vb) {
    a.cell(va, ca);
    b.cell(vb, cb);
    cells += !ca.empty();
    bool same = ca.size() == cb.size();
    for (std::size_t i = 0; same && i < ca.size(); ++i)
      same = ca[i].point ==
             Point(std::ldexp(cb[i].point.x(), -exponent), std::ldexp(cb[i].point.y(), -exponent));
    differ += !same;
  }
  CHECK(cells > 300);
  CHECK(differ == 0);
}

TEST_CASE(
    "degenerate input: generators closer to each other than double spacing at their "
    "neighbors, and at the edge of underflow",
    "[bvd][degenerate]") {
  // Found by fuzz_read_points on four_clusters.poly. Relative to a far vertex, the two near
  // ones' differences round alike, CGAL's circumcenter formula divides by 0 and the cells were
  // NaN; the traits now build such circumcenters exactly.
  const std::vector<Point> pts =
      GENERATE(std::vector<Point>{{0, .000000000000000006}},
               std::vector<Point>{{.000000000000000005, .7}, {0, .7}},
               std::vector<Point>{{.000000000000000005, .78567}, {0, .78567}},
               std::vector<Point>{{1e-323, 0}}, std::vector<Point>{{1, 4.9e-324}},
               std::vector<Point>{{4.9e-324, 4.9e-324}}, std::vector<Point>{{0.5, 1e-320}});
  CAPTURE(pts);
  Domain d;
  load_domain(d, "four_clusters.poly");
  CVT_2::insert_generators_2(d.cdt, pts);
  const Bvd bvd(d.cdt);
  Cell c;
  for (auto v = d.cdt.finite_vertices_begin(); v != d.cdt.finite_vertices_end(); ++v) {
    bvd.cell(v, c);
    for (const auto& x : c) REQUIRE((std::isfinite(x.point.x()) && std::isfinite(x.point.y())));
  }
  const bool subnormal = std::any_of(pts.begin(), pts.end(), [](const Point& p) {
    return std::fpclassify(p.x()) == FP_SUBNORMAL || std::fpclassify(p.y()) == FP_SUBNORMAL;
  });
  check_diagram(bvd, 2000, 37, subnormal);
}

TEST_CASE("the circumcenter is CGAL's where CGAL's is accurate, and exact where it cancels",
          "[bvd][degenerate]") {
  using EK = CGAL::Exact_predicates_exact_constructions_kernel;
  const CVT_2::Bvd_traits_2<K> traits;
  const auto circumcenter = traits.construct_circumcenter_2_object();
  const auto exact = [](const Point& p, const Point& q, const Point& r) {
    const EK::Point_2 c = CGAL::circumcenter(EK::Point_2(p.x(), p.y()), EK::Point_2(q.x(), q.y()),
                                             EK::Point_2(r.x(), r.y()));
    return std::pair<EK::FT, EK::FT>(c.x(), c.y());
  };
  // A well-shaped triangle: CGAL's bits.
  const Point p(0.1, 0.2), q(1.3, 0.25), r(0.7, 1.1);
  CHECK(circumcenter(p, q, r) == K().construct_circumcenter_2_object()(p, q, r));
  // q and r 5e-18 apart, 0.7 from p: the nearest double to the exact circumcenter.
  const Point a(0, 0), b(5e-18, 0.7), c2(0, 0.7);
  const Point got = circumcenter(a, b, c2);
  const auto [ex, ey] = exact(a, b, c2);
  CHECK(std::abs(CGAL::to_double(ex - EK::FT(got.x()))) <= std::nextafter(got.x(), 1.0) - got.x());
  CHECK(std::abs(CGAL::to_double(ey - EK::FT(got.y()))) <= std::nextafter(got.y(), 1.0) - got.y());
  // A subnormal side (2^-1073): the circumcenter is exact, (2^-1074, 0.5).
  const Point s = circumcenter(Point(0, 0), Point(std::ldexp(1.0, -1073), 0), Point(0, 1));
  CHECK(s == Point(std::ldexp(1.0, -1074), 0.5));
}

TEST_CASE("degenerate input: a domain with 2500 holes", "[bvd][degenerate]") {
  // A 100 x 100 square with a 50 x 50 grid of unit square holes, each seeded at its center.
  Cdt cdt = square_with_holes(50);
  CHECK(domain_area(cdt) == Approx(10000 - 2500).epsilon(1e-12));
  CVT_2::insert_generators_2(cdt, random_points_in_domain(cdt, 5000, 41));
  const Bvd bvd(cdt);
  std::size_t cells = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    cells += bvd.has_cell(v);
  CHECK(cells == cdt.number_of_vertices());
  check_diagram(bvd, 300, 43);
}

TEST_CASE("degenerate input: constraints meeting at sharp angles", "[bvd][degenerate]") {
  // Inner segments from (1, 1) at angles 0.3, 1e-2, 1e-4, 1e-7 and 0 rad, and a spike of the
  // domain out of the left side whose tip is a 1e-5 rad corner, with generators scattered
  // between them and on them.
  CVT_2::IO::Poly_data<Point> poly;
  add_ring(poly, {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 5.0001}, {-10, 5.00005}, {0, 5}});
  const std::size_t hub = poly.vertices.size();
  poly.vertices.emplace_back(1, 1);
  for (const double a : {0.3, 1e-2, 1e-4, 1e-7, 0.0}) {
    poly.vertices.emplace_back(9, 1 + 8 * std::tan(a));
    poly.segments.push_back({hub, poly.vertices.size() - 1});
  }
  Cdt cdt = triangulate(poly);
  std::vector<Point> generators = random_points_in_domain(cdt, 1500, 47);
  for (int k = 1; k < 8; ++k) generators.emplace_back(1 + k, 1 + k * std::tan(1e-4));  // near one
  for (int k = 1; k < 8; ++k) generators.emplace_back(1 + k, 1.0);  // exactly on one
  CVT_2::insert_generators_2(cdt, generators);
  check_diagram(Bvd(cdt), 3000, 53);
}

TEST_CASE("degenerate input: thin domains and a boundary of slivers", "[bvd][degenerate]") {
  SECTION("a 1 x 1e-6 strip") {
    CVT_2::IO::Poly_data<Point> poly;
    add_ring(poly, {{0, 0}, {1, 0}, {1, 1e-6}, {0, 1e-6}});
    Cdt cdt = triangulate(poly);
    CVT_2::insert_generators_2(cdt, random_points_in_domain(cdt, 300, 59));
    check_diagram(Bvd(cdt), 2000, 61);
  }
  SECTION("a bottom side of 200 vertices 1e-12 from collinear") {
    std::vector<Point> ring;
    for (int i = 0; i <= 200; ++i) {
      const double x = i / 200.0;
      ring.emplace_back(x, 1e-12 * x * (1 - x));
    }
    ring.emplace_back(1, 1);
    ring.emplace_back(0, 1);
    CVT_2::IO::Poly_data<Point> poly;
    add_ring(poly, ring);
    Cdt cdt = triangulate(poly);
    CVT_2::insert_generators_2(cdt, random_points_in_domain(cdt, 500, 67));
    check_diagram(Bvd(cdt), 2000, 71);
  }
}

TEST_CASE("random domains on a grid: holes, touching polylines, points on constraints",
          "[bvd][random]") {
  // Each case a new domain; the properties of check_diagram hold on all of them. 400 cases
  // here; CVT_2_RANDOM_CASES=N runs N (thousands for a nightly run).
  const unsigned cases = random_cases(400);
  for (unsigned seed = 1; seed <= cases; ++seed) {
    CAPTURE(seed);
    const Cdt cdt = random_triangulation(seed, 120);
    check_triangulation(cdt, snapshot_marks(cdt));  // valid, Delaunay, marks alike across edges
    const Bvd bvd(cdt);
    check_diagram(bvd, 300, seed);
  }
}

TEST_CASE("Cvt_triangulation_2 is the triangulation the tests spell out", "[bvd]") {
  STATIC_REQUIRE(std::is_same<CVT_2::Cvt_triangulation_2<K>, Cdt>::value);
  CVT_2::Cvt_triangulation_2<K> cdt;
  cdt.insert_constraint(Point(0, 0), Point(1, 0));
  cdt.insert_constraint(Point(1, 0), Point(0, 1));
  cdt.insert_constraint(Point(0, 1), Point(0, 0));
  CVT_2::mark_domain_2(cdt, std::vector<Point>{});
  CHECK(CVT_2::Bounded_voronoi_diagram_2<CVT_2::Cvt_triangulation_2<K>>(cdt).has_cell(
      cdt.finite_vertices_begin()));
}

TEST_CASE("Face_chunks: every face once, in memory order, in runs of slots, free slots skipped",
          "[bvd]") {
  Domain d;
  load_domain(d, "square_inner_constraints.poly");
  insert_random_points(d, 20000, 3);
  const auto& slots = d.cdt.tds().faces();
  // The faces the chunks visit, in the order of the chunks, against a walk of all faces; the
  // number of faces in each chunk.
  const auto check = [&](std::size_t size) {
    CAPTURE(size);
    const CVT_2::internal::Face_chunks<Cdt> chunks(d.cdt, size);
    std::vector<Cdt::Face_handle> visited, all;
    std::vector<std::size_t> faces(chunks.size(), 0);
    chunks.for_each(
        [&](std::size_t c, auto first, auto last) {
          for (; first != last; ++first, ++faces[c]) visited.push_back(first);
        },
        1);  // in order, on this thread
    for (auto f = d.cdt.all_faces_begin(); f != d.cdt.all_faces_end(); ++f) all.push_back(f);
    CHECK(visited == all);
    CHECK(chunks.size() <= (slots.capacity() + size - 1) / size);
    for (const std::size_t n : faces) {
      CHECK(n >= 1);
      CHECK(n <= size);
    }
    return chunks.size();
  };
  for (const std::size_t size : {1u, 16u, 4096u}) check(size);
  // Free slots in the middle: the free generators left of the median removed.
  std::vector<Cdt::Vertex_handle> removed;
  for (auto v = d.cdt.finite_vertices_begin(); v != d.cdt.finite_vertices_end(); ++v)
    if (!d.cdt.are_there_incident_constraints(v)) removed.push_back(v);
  const auto middle = removed.begin() + std::ptrdiff_t(removed.size() / 2);
  std::nth_element(removed.begin(), middle, removed.end(),
                   [](auto u, auto v) { return u->point().x() < v->point().x(); });
  removed.erase(middle, removed.end());
  REQUIRE(removed.size() > 5000);
  for (const auto v : removed) d.cdt.remove(v);
  REQUIRE(slots.size() + 10000 < slots.capacity());
  for (const std::size_t size : {1u, 4096u}) check(size);
  // chunks of 16 slots all free, left out
  CHECK(check(16) < (slots.capacity() + 15) / 16);
  // An evaluation visits every free generator's cell once, on any number of threads.
  CVT_2::mark_domain_2(d.cdt, d.poly.holes);
  std::set<Cdt::Vertex_handle> free;
  for (auto v = d.cdt.finite_vertices_begin(); v != d.cdt.finite_vertices_end(); ++v)
    if (!d.cdt.are_there_incident_constraints(v)) free.insert(v);
  std::vector<double> energies;
  for (const unsigned threads : {1u, 2u}) {
    CVT_2::Lloyd_optimizer_2<Cdt> lloyd(d.cdt);
    lloyd.set_number_of_threads(threads);
    energies.push_back(lloyd.evaluate(10).energy);
    std::multiset<Cdt::Vertex_handle> found;
    for (const auto& g : lloyd.free_generators()) found.insert(g.vertex);
    CHECK(found.size() == free.size());
    CHECK(std::set<Cdt::Vertex_handle>(found.begin(), found.end()) == free);
  }
  CHECK(energies[0] == energies[1]);
  CHECK(CVT_2::internal::Face_chunks<Cdt>(Cdt()).size() == 0);  // no plane: no chunks
}

TEST_CASE("sort_faces: the same triangulation, its faces in the Hilbert order of their centroids",
          "[bvd]") {
  using Vh = Cdt::Vertex_handle;
  using Key = std::array<Vh, 3>;  // a face's vertices, in its order
  struct Flags {
    bool inside;
    std::array<bool, 3> constrained;
    std::pair<Vh, Vh> blinding;  // the blinding edge's ends, or none
    bool operator==(const Flags& o) const {
      return inside == o.inside && constrained == o.constrained && blinding == o.blinding;
    }
  };
  const auto key = [](Cdt::Face_handle f) { return Key{f->vertex(0), f->vertex(1), f->vertex(2)}; };
  const auto flags = [](Cdt::Face_handle f) {
    Flags r{f->is_inside_domain(), {}, {}};
    for (int i = 0; i < 3; ++i) r.constrained[std::size_t(i)] = f->is_constrained(i);
    if (f->is_blinded()) {
      const auto e = f->blinding_edge();
      r.blinding =
          std::minmax(e.first->vertex(Cdt::ccw(e.second)), e.first->vertex(Cdt::cw(e.second)));
    }
    return r;
  };
  const auto faces = [&](const Cdt& cdt) {
    std::map<Key, Flags> m;
    for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) m.emplace(key(f), flags(f));
    return m;
  };
  const auto cells = [](const Bvd& bvd) {  // each cell's points, sorted (its first may change)
    std::map<Vh, std::vector<Point>> m;
    bvd.for_each_cell([&](Vh v, const auto& cell) {
      for (const auto& c : cell) m[v].push_back(c.point);
      std::sort(m[v].begin(), m[v].end());
    });
    return m;
  };
  Domain d;
  load_domain(d, "us_massachusetts_counties.poly");
  const std::vector<Point> points = random_points_in_domain(d.cdt, 5000, 5);
  d.cdt.insert(points.begin(), points.end());  // CGAL's insertion: the faces where it made them
  std::vector<Vh> removed;                     // a few, to free slots
  for (auto v = d.cdt.finite_vertices_begin(); v != d.cdt.finite_vertices_end(); ++v)
    if (!d.cdt.are_there_incident_constraints(v) && removed.size() < 20) removed.push_back(v);
  for (const Vh v : removed) d.cdt.remove(v);
  CVT_2::mark_domain_2(d.cdt, d.poly.holes);
  REQUIRE(d.cdt.tds().faces().capacity() > d.cdt.tds().faces().size());  // free slots
  Bvd bvd(d.cdt);
  REQUIRE(bvd.number_of_blinded_faces() > 0);
  // The share of the neighbors of finite faces that lie within 64 faces in memory.
  const auto near = [](const Cdt& cdt) {
    std::map<Cdt::Face_handle, std::ptrdiff_t> rank;
    for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
      rank.emplace(f, std::ptrdiff_t(rank.size()));
    std::size_t near = 0, all = 0;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
      for (int i = 0; i < 3; ++i)
        if (!cdt.is_infinite(f->neighbor(i))) {
          ++all;
          near += std::abs(rank[f->neighbor(i)] - rank[f]) <= 64;
        }
    return double(near) / double(all);
  };
  const double near_before = near(d.cdt);
  std::vector<Point> centroids_before;  // the finite faces' centroids, in memory order
  for (auto f = d.cdt.finite_faces_begin(); f != d.cdt.finite_faces_end(); ++f)
    centroids_before.push_back(CGAL::centroid(d.cdt.triangle(f)));
  const auto faces_before = faces(d.cdt);
  const auto cells_before = cells(bvd);
  const auto slots = [](const Cdt& cdt) {
    std::vector<Cdt::Face_handle> v;
    for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) v.push_back(f);
    return v;
  };
  const auto slots_before = slots(d.cdt);

  CVT_2::internal::sort_faces(d.cdt);
  CHECK(d.cdt.is_valid());
  std::size_t blind = 0;
  for (auto f = d.cdt.all_faces_begin(); f != d.cdt.all_faces_end(); ++f) blind += f->is_blinded();
  CHECK(blind == 0);  // cleared
  // The same slots, holding the same faces (vertices in the same order, the same flags) but for
  // the blind tags, which the diagram's update gives back.
  CHECK(slots(d.cdt) == slots_before);
  bvd.update();
  CHECK(faces(d.cdt) == faces_before);
  CHECK(cells(bvd) == cells_before);
  // Memory order: the finite faces in the Hilbert order of their centroids, then the infinite.
  std::vector<Point> centroids;
  bool infinite_seen = false, finite_after_infinite = false;
  for (auto f = d.cdt.all_faces_begin(); f != d.cdt.all_faces_end(); ++f) {
    if (d.cdt.is_infinite(f)) {
      infinite_seen = true;
      continue;
    }
    finite_after_infinite = finite_after_infinite || infinite_seen;
    centroids.push_back(CGAL::centroid(d.cdt.triangle(f)));
  }
  CHECK(!finite_after_infinite);
  // CGAL's Hilbert sort of them, in single precision relative to the first vertex (it shuffles
  // with a fixed seed first, and leaves a set that falls in one quadrant of its box as it is:
  // the order depends on the order given)
  using Float_point = CGAL::Simple_cartesian<float>::Point_2;
  using Item = std::pair<Float_point, std::size_t>;
  const Point origin = d.cdt.finite_vertices_begin()->point();
  std::vector<Item> items;
  for (const Point& c : centroids_before) {
    // as sort_faces() computes it: the mean of the three vertices' coordinates, in double
    items.emplace_back(Float_point(float(c.x() - origin.x()), float(c.y() - origin.y())),
                       items.size());
  }
  CGAL::hilbert_sort(items.begin(), items.end(),
                     CGAL::Spatial_sort_traits_adapter_2<CGAL::Simple_cartesian<float>,
                                                         CGAL::First_of_pair_property_map<Item>>(),
                     CGAL::Hilbert_sort_median_policy());
  std::vector<Point> expected;
  for (const Item& i : items) expected.push_back(centroids_before[i.second]);
  CHECK(centroids == expected);
  const double near_after = near(d.cdt);
  CAPTURE(near_before, near_after);
  CHECK(near_after > near_before + 0.3);
  // Again: most faces stay where they are (a face is not its own neighbor, even for a while).
  CVT_2::internal::sort_faces(d.cdt);
  CHECK(d.cdt.is_valid());
  bvd.update();
  CHECK(faces(d.cdt) == faces_before);
  CHECK(near(d.cdt) > near_before + 0.3);

  // insert_generators_2() lays out the faces when the new vertices are half or more, not after
  // a few: the faces it leaves alone keep their slots (a layout would shift most of them).
  std::map<Cdt::Face_handle, Key> slot_face;
  for (auto f = d.cdt.all_faces_begin(); f != d.cdt.all_faces_end(); ++f) slot_face[f] = key(f);
  const std::size_t vertices = d.cdt.number_of_vertices();
  CVT_2::insert_generators_2(d.cdt, random_points_in_domain(d.cdt, 10, 6));
  CHECK(d.cdt.number_of_vertices() == vertices + 10);
  std::size_t kept = 0;
  for (auto f = d.cdt.all_faces_begin(); f != d.cdt.all_faces_end(); ++f) {
    const auto s = slot_face.find(f);
    kept += s != slot_face.end() && s->second == key(f);
  }
  CHECK(kept + 100 > slot_face.size());
  // From an empty domain, 5000 generators: laid out.
  Domain e;
  load_domain(e, "us_massachusetts_counties.poly");
  CVT_2::insert_generators_2(e.cdt, points);
  CHECK(e.cdt.is_valid());
  CHECK(near(e.cdt) == Approx(near_after).margin(0.02));
  // A domain of two squares far apart: each laid out (a sort that stopped at a cluster in one
  // quadrant of its box would leave the big square's faces as they came).
  CVT_2::IO::Poly_data<Point> two;
  add_ring(two, {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)});
  add_ring(two, {Point(10, 10), Point(10.1, 10), Point(10.1, 10.1), Point(10, 10.1)});
  Cdt islands = triangulate(two);
  CVT_2::insert_generators_2(islands, random_points_in_domain(islands, 5000, 7));
  CHECK(islands.is_valid());
  CHECK(near(islands) > 0.8);
  // Far from the origin, as projected coordinates in metres are, and at extreme scales (the
  // centroids are sorted in single precision: relative to a vertex, not to the origin, whose
  // floats are 0.06 and 0.25 apart here, and scaled, as a float ends near 3e38).
  for (const auto& [corner, side] :
       {std::pair<Point, double>(Point(1e6, 4e6), 1), std::pair<Point, double>(Point(0, 0), 1e200),
        std::pair<Point, double>(Point(0, 0), 1e-200)}) {
    CAPTURE(corner, side);
    CVT_2::IO::Poly_data<Point> far;
    const double x = corner.x(), y = corner.y();
    add_ring(far, {corner, Point(x + side, y), Point(x + side, y + side), Point(x, y + side)});
    Cdt cdt = triangulate(far);
    CVT_2::insert_generators_2(cdt, random_points_in_domain(cdt, 5000, 8));
    CHECK(cdt.is_valid());
    CHECK(near(cdt) > 0.8);
  }
  // No plane, no layout.
  Cdt line;
  CVT_2::internal::sort_faces(line);
  line.insert(Point(0, 0));
  line.insert(Point(1, 0));
  CVT_2::internal::sort_faces(line);
  CHECK(line.dimension() == 1);
  CHECK(line.is_valid());
}

TEST_CASE("no plane: neither pass over the faces visits a cell", "[bvd][degenerate]") {
  Cdt cdt;
  for (const Point& p : {Point(0, 0), Point(1, 0), Point(2, 0)}) {
    cdt.insert(p);
    const Bvd bvd(cdt);
    std::size_t visits = 0;
    bvd.for_each_cell([&](Cdt::Vertex_handle, const auto&) { ++visits; });
    // the face container itself, which holds the edges without a plane (CGAL's face iterators
    // are then empty)
    std::vector<Point> points;
    CVT_2::internal::for_each_cell_points_in_faces(
        bvd, cdt.tds().faces().begin(), cdt.tds().faces().end(), points,
        [&](Cdt::Vertex_handle, const std::vector<Point>&, bool) { ++visits; });
    CHECK(visits == 0);
  }
  CHECK(cdt.dimension() == 1);
}

// ---------------------------------------------------------------------------------------------
// Constraint_editor_2: edits with a local update.

namespace {

using Editor = CVT_2::Constraint_editor_2<Cdt>;
using Cells = std::map<Cdt::Vertex_handle, std::vector<Point>>;

Cells all_cells(const Cdt& cdt, const Bvd& bvd) {
  Cells cells;
  Cell cell;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    bvd.cell(v, cell);
    auto& points = cells[v];
    for (const auto& x : cell) points.push_back(x.point);
  }
  return cells;
}

// Whether the tags and domain marks are those of a rebuild (Triangle's rule from the hole
// seeds, then Algorithm 1 on every face); leaves the rebuilt ones, which are then the same.
bool as_rebuilt(Cdt& cdt, Bvd& bvd, const std::vector<Point>& holes) {
  std::vector<std::tuple<Cdt::Face_handle, bool, bool, Cdt::Edge>> tags;
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
    tags.emplace_back(f, f->is_inside_domain(), f->is_blinded(),
                      f->is_blinded() ? f->blinding_edge() : Cdt::Edge());
  CVT_2::mark_domain_2(cdt, holes);
  bvd.update();
  std::size_t wrong_marks = 0, wrong_tags = 0;
  for (const auto& [f, inside, blinded, e] : tags) {
    wrong_marks += f->is_inside_domain() != inside;
    wrong_tags += f->is_blinded() != blinded || (blinded && f->blinding_edge() != e);
  }
  CHECK(wrong_marks == 0);
  CHECK(wrong_tags == 0);
  return wrong_marks == 0 && wrong_tags == 0;
}

// Random edits on a domain with random generators: after each, the tags and marks of a rebuild,
// and every cell the report does not name is the cell it was; every few, the invariants.
void random_edits(const std::string& file, std::size_t points, int edits, unsigned seed) {
  Domain d;
  load_domain(d, file);
  insert_random_points(d, points, seed);
  Cdt& cdt = d.cdt;
  Bvd bvd(cdt);
  Editor editor(cdt, bvd);
  editor.carry_weights(true);
  std::mt19937_64 rng(seed);
  const double h = std::sqrt(domain_area(cdt) / double(cdt.number_of_vertices()));
  const auto random_step = [&](const Point& from, double lo, double hi) {
    const double angle = uniform(rng, 0, 6.283185307179586), r = uniform(rng, lo, hi) * h;
    return Point(from.x() + r * std::cos(angle), from.y() + r * std::sin(angle));
  };
  std::vector<std::pair<Point, Point>> on_axis_edges;
  for (auto e = cdt.constrained_edges_begin(); e != cdt.constrained_edges_end(); ++e) {
    const Point& a = e->first->vertex(Cdt::ccw(e->second))->point();
    const Point& b = e->first->vertex(Cdt::cw(e->second))->point();
    if (a.x() == b.x() || a.y() == b.y()) on_axis_edges.emplace_back(a, b);
  }
  std::vector<Editor::Constraint_id> live;
  std::map<std::string, int> done, refused;
  Cells before = all_cells(cdt, bvd);
  for (int k = 0; k < edits; ++k) {
    const std::size_t vertices = cdt.number_of_vertices(), faces = cdt.number_of_faces();
    const int what = live.empty() ? 0 : uniform_int(rng, 0, 9);
    const std::string name = what < 3   ? "insert"
                             : what < 6 ? "extend"
                             : what < 8 ? "move"
                                        : "remove";
    INFO("edit " << k << ": " << name);
    bool succeeded = false;
    try {
      if (name == "insert") {
        std::vector<Point> line = random_points_in_domain(cdt, 1, unsigned(rng()));
        // or from a constrained edge parallel to an axis (a point exactly on it, which splits
        // it), or from a constrained vertex (a junction)
        const int from = uniform_int(rng, 0, 3);
        if (from < 2 && !on_axis_edges.empty()) {
          const auto& [a, b] =
              on_axis_edges[std::size_t(uniform_int(rng, 0, int(on_axis_edges.size()) - 1))];
          const double t = uniform(rng, 0.1, 0.9);
          line[0] = a.x() == b.x() ? Point(a.x(), a.y() + t * (b.y() - a.y()))
                                   : Point(a.x() + t * (b.x() - a.x()), a.y());
        } else if (from == 2) {
          std::vector<Point> constrained;
          for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
            if (cdt.are_there_incident_constraints(v)) constrained.push_back(v->point());
          line[0] = constrained[std::size_t(uniform_int(rng, 0, int(constrained.size()) - 1))];
        }
        for (int i = uniform_int(rng, 1, 3); i > 0; --i)
          line.push_back(random_step(line.back(), 0.5, 3));
        live.push_back(editor.insert_constraint(line));
      } else {
        const std::size_t j = std::size_t(uniform_int(rng, 0, int(live.size()) - 1));
        const auto id = live[j];
        const auto& line = editor.vertices_in_constraint(id);
        if (name == "extend") {
          editor.extend_constraint(id, random_step(line.back()->point(), 0.5, 2),
                                   uniform_int(rng, 0, 1) * 0.5 * h);
        } else if (name == "move") {
          const auto v = line[std::size_t(uniform_int(rng, 0, int(line.size()) - 1))];
          editor.move_constrained_vertex(v, random_step(v->point(), 0.05, 0.4));
        } else {
          editor.remove_constraint(id);
          live.erase(live.begin() + std::ptrdiff_t(j));
        }
      }
      ++done[name];
      succeeded = true;
    } catch (const CVT_2::Domain_error&) {
      ++refused[name];
      CHECK(cdt.number_of_vertices() == vertices);  // a refused edit changes nothing
      if (name != "move") CHECK(cdt.number_of_faces() == faces);
    }
    if (!as_rebuilt(cdt, bvd, d.poly.holes)) break;
    const auto& report = editor.report();
    if (succeeded && (name == "insert" || name == "extend")) {  // Sibson before, normalized
      CHECK(report.carried_weights.size() == report.new_vertices.size());
      for (const auto& weights : report.carried_weights) {
        double sum = 0;
        std::size_t negative = 0;
        for (const auto& vw : weights) sum += vw.second, negative += vw.second < 0;
        CHECK(negative == 0);
        CHECK(std::abs(sum - 1) < 1e-12);
      }
    }
    const Cells after = all_cells(cdt, bvd);
    const auto& changed = editor.report().changed_cells;
    std::size_t unreported = 0;
    for (const auto& [v, cell] : before)
      if (std::find(changed.begin(), changed.end(), v) == changed.end() && after.at(v) != cell)
        ++unreported;
    CHECK(unreported == 0);
    if (unreported != 0 && std::getenv("CVT_2_EDIT_DEBUG")) {
      std::cout << "edit " << k << " " << name << " refused=" << refused[name] << "\n";
      for (const auto& [v, cell] : before)
        if (std::find(changed.begin(), changed.end(), v) == changed.end() && after.at(v) != cell)
          std::cout << "  " << v->point()
                    << " constrained=" << cdt.are_there_incident_constraints(v) << " cell "
                    << cell.size() << " -> " << after.at(v).size() << "\n";
      for (const auto v : changed) std::cout << "  reported " << v->point() << "\n";
    }
    before = after;
    if (k % 25 == 24) check_diagram(bvd, 100, seed + unsigned(k));
  }
  INFO(file);
  for (const char* name : {"insert", "extend", "move", "remove"}) {
    INFO(name << ": " << done[name] << " done, " << refused[name] << " refused");
    CHECK(done[name] >= edits / 40);
    if (std::getenv("CVT_2_EDIT_STATS"))
      std::cout << file << ' ' << name << ": " << done[name] << " done, " << refused[name]
                << " refused\n";
  }
}

}  // namespace

TEST_CASE("Constraint_editor_2: random edits give the tags and marks of a rebuild", "[bvd][edit]") {
  random_edits("square_inner_constraints.poly", 1500, 300, 7);
  random_edits("us_massachusetts_counties.poly", 1500, 300, 8);
  random_edits("earcut_dude.poly", 800, 200, 9);
}

TEST_CASE("Constraint_editor_2: a crack's new vertices carry a field from each side to each lip",
          "[bvd][edit][lips]") {
  Domain d;
  load_domain(d, "square_inner_constraints.poly");
  insert_random_points(d, 2000, 12);
  Bvd bvd(d.cdt);
  CVT_2::Constraint_editor_2<Cdt> editor(d.cdt, bvd);
  editor.carry_weights(true);
  // a crack along y = 0.75 from the left edge, grown in steps with a vertex every 0.1
  const double y = 0.75;
  const auto id = editor.insert_constraint(std::vector<Point>{Point(0, y), Point(0.5, y)});
  std::size_t lips = 0, tips = 0, crack_nodes_seen = 0;
  for (double x = 1; x <= 4; x += 0.5) {
    editor.extend_constraint(id, Point(x, y), 0.1);
    const auto& r = editor.report();
    // every new vertex but the tip has two lips, one each side, each fed from its side only
    std::map<Cdt::Vertex_handle, std::vector<int>> sides;
    std::map<Cdt::Vertex_handle, std::vector<std::set<Point>>> on_crack;
    for (const auto& c : r.carried_lips) {
      CAPTURE(c.vertex->point(), c.lip);
      double sum = 0, side = 0;
      on_crack[c.vertex].emplace_back();
      for (const auto& [node, w] : c.weights) {
        sum += w;
        const double dy = node->point().y() - y;
        CHECK(dy * side >= 0);  // no node from the other side
        if (dy != 0) side = dy;
        if (dy == 0) on_crack[c.vertex].back().insert(node->point());
      }
      CHECK(sum == Approx(1).margin(1e-12));
      REQUIRE(side != 0);
      sides[c.vertex].push_back(side > 0 ? 1 : -1);
      ++lips;
    }
    for (const auto v : r.new_vertices) {
      if (v->point() == Point(x, y)) {
        ++tips;
        CHECK(sides.count(v) == 0);
        continue;
      }
      REQUIRE(sides.count(v) == 1);
      CHECK(sides[v].size() == 2);
      CHECK(sides[v][0] == -sides[v][1]);
      CHECK(on_crack[v][0] == on_crack[v][1]);  // the crack's nodes count on both lips
      crack_nodes_seen += on_crack[v][0].size();
    }
  }
  CHECK(tips == 7);
  CHECK(crack_nodes_seen > 0);
  CHECK(lips == 2 * 7 * 4);  // 4 vertices inside each step of 0.5
  // A negative or NaN spacing was taken for 0 (no vertices on the way), silently.
  for (const double bad : {-0.1, std::numeric_limits<double>::quiet_NaN()})
    CHECK_THROWS_WITH(editor.extend_constraint(id, Point(4.5, y), bad),
                      Catch::Contains("a positive length, or 0 for no vertices"));
}
