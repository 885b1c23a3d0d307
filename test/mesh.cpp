// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The conforming mesh of the diagram and the readers and writers around it; the domain's
// constraints resampled before it.
#include "support/invariants.h"
#include "support/random_domain.h"
#include "support/support.h"

#include <CVT_2/Bvd_mesh_2.h>
#include <CVT_2/Cvt_triangulation_2.h>
#include <CVT_2/IO/read_domain.h>
#include <CVT_2/IO/read_geojson.h>
#include <CVT_2/IO/write_disv.h>
#include <CVT_2/IO/write_geojson.h>
#include <CVT_2/IO/write_poly.h>
#include <CVT_2/IO/write_triangle.h>
#include <CVT_2/IO/write_vtu.h>
#include <CVT_2/Simulation_grid_2.h>
#include <CVT_2/cell_size_scale_2.h>
#include <CVT_2/conforming_sites_2.h>
#include <CVT_2/insert_generators_2.h>
#include <CVT_2/lbfgs_optimize_2.h>
#include <CVT_2/lloyd_optimize_2.h>
#include <CVT_2/random_points_in_domain_2.h>
#include <CVT_2/resample_constraints_2.h>

#include <CGAL/Polygon_2_algorithms.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace support;

namespace {

// The library's default triangulation, whose vertices and faces have ids.
using Cdt_ids = CVT_2::Cvt_triangulation_2<K>;
using Bvd_ids = CVT_2::Bounded_voronoi_diagram_2<Cdt_ids>;
using Mesh = CVT_2::Bvd_mesh_2<Bvd_ids>;

Cdt_ids load(const std::string& file, std::size_t points, unsigned seed) {
  Cdt_ids cdt;
  CVT_2::IO::read_domain(data_path(file), cdt);
  CVT_2::insert_generators_2(
      cdt, CVT_2::random_points_in_domain_2(cdt, points, CVT_2::parameters::random_seed(seed)));
  return cdt;
}

Cdt_ids random_case(unsigned seed) {
  std::vector<Point> generators;
  const auto poly = random_domain(seed, generators, 60);
  Cdt_ids cdt;
  CVT_2::IO::insert_poly(cdt, poly);
  CVT_2::insert_generators_2(cdt, generators);
  return cdt;
}

double triangulation_area(const Cdt_ids& cdt) {
  double a = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->is_inside_domain()) a += cdt.triangle(f).area();
  return a;
}

// The bounded regions outside the domain (holes), each a component of faces not in the domain
// connected through any edge; and the components of the domain (faces through any edge).
std::pair<std::size_t, std::size_t> holes_and_components(const Cdt_ids& cdt) {
  std::map<Cdt_ids::Face_handle, int> seen;
  std::size_t holes = 0, parts = 0;
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) {
    if (seen.count(f)) continue;
    const bool in = f->is_inside_domain();
    bool bounded = true;
    std::vector<Cdt_ids::Face_handle> stack{f};
    seen[f] = 1;
    while (!stack.empty()) {
      const auto g = stack.back();
      stack.pop_back();
      if (cdt.is_infinite(g)) bounded = false;
      for (int i = 0; i < 3; ++i) {
        const auto n = g->neighbor(i);
        if (n->is_inside_domain() == in && !seen.count(n)) seen[n] = 1, stack.push_back(n);
      }
      // Domain faces that touch at a vertex only are one component of the mesh's graph too.
      if (in)
        for (int i = 0; i < 3; ++i) {
          auto fc = cdt.incident_faces(g->vertex(i)), done = fc;
          do
            if (fc->is_inside_domain() && !seen.count(fc)) seen[fc] = 1, stack.push_back(fc);
          while (++fc != done);
        }
    }
    if (in)
      ++parts;
    else if (bounded)
      ++holes;
  }
  return {holes, parts};
}

// The properties every mesh has.
void check_mesh(const Mesh& mesh, const Cdt_ids& cdt) {
  const double area = triangulation_area(cdt);
  double total = 0;
  std::size_t regions = 0, slit_edges = 0;
  for (std::size_t k = 0; k < mesh.number_of_cells(); ++k) {
    const double a = mesh.area(k);
    CHECK(a > 0);
    total += a;
    double lobe_area = 0;
    const auto rings = mesh.polygons(k);
    for (const auto& ring : rings) {
      std::vector<Point> p;
      for (const auto i : ring) p.push_back(mesh.point(i));
      CHECK(CGAL::is_simple_2(p.begin(), p.end(), K()));
      CHECK(CGAL::orientation_2(p.begin(), p.end(), K()) == CGAL::COUNTERCLOCKWISE);
      lobe_area += CGAL::to_double(CGAL::polygon_area_2(p.begin(), p.end(), K()));
    }
    CHECK(lobe_area == Approx(a).epsilon(1e-9));
    // The constraints at a constrained generator cut its cell into one region per wedge between
    // them (the cycle visits the generator once per wedge); a free cell is one region.
    const auto c = mesh.cell(k);
    std::size_t wedges = 0;
    for (const auto i : c) wedges += mesh.vertex_type(i) == Bvd_ids::Cell_vertex::GENERATOR ? 1 : 0;
    CHECK(rings.size() <= std::max<std::size_t>(wedges, 1));
    regions += std::max<std::size_t>(wedges, 1);
    // The generator holds its cell: inside a free cell, a vertex of a constrained one.
    bool generator_is_vertex = false;
    for (const auto i : c)
      generator_is_vertex |= mesh.vertex_type(i) == Bvd_ids::Cell_vertex::GENERATOR &&
                             mesh.point(i) == mesh.generator(k)->point();
    CHECK(generator_is_vertex == mesh.is_constrained(k));
    CHECK(mesh.cell_of(mesh.generator(k)) == k);
    // No edge of no length: a cycle never stays at one vertex (a slit goes there and back).
    std::size_t repeats = 0;
    for (std::size_t j = 0; j < c.size(); ++j) repeats += c[j] == c[(j + 1) % c.size()];
    CHECK(repeats == (c.size() == 1 ? 1u : 0u));
  }
  CHECK(total == Approx(area).epsilon(1e-10));
  // Edges: a bisector edge has two different cells, each with it the other way; an edge on a
  // constraint lies on that constrained edge, with a cell beyond it if and only if the
  // constraint has the domain on both sides.
  std::map<std::pair<std::size_t, std::size_t>, int> walked;  // directed edges of the cycles
  for (std::size_t k = 0; k < mesh.number_of_cells(); ++k) {
    const auto c = mesh.cell(k);
    for (std::size_t j = 0; j < c.size(); ++j) ++walked[{c[j], c[(j + 1) % c.size()]}];
  }
  const auto edges = mesh.edges();
  for (const auto& e : edges) {
    const Point& a = mesh.point(e.vertices[0]);
    const Point& b = mesh.point(e.vertices[1]);
    CHECK(a != b);
    if (e.constraint == Mesh::none) {
      REQUIRE(e.cells[1] != Mesh::none);
      CHECK(e.cells[0] != e.cells[1]);
      CHECK(walked[{e.vertices[1], e.vertices[0]}] == 1);
    } else {
      const auto& k = mesh.constraints()[e.constraint];
      const Point& p = mesh.generator(k[0])->point();
      const Point& q = mesh.generator(k[1])->point();
      const double length = std::sqrt(CGAL::squared_distance(p, q));
      for (const Point& x : {a, b}) {
        CHECK(std::sqrt(CGAL::squared_distance(K::Segment_2(p, q), x)) <= 1e-9 * length);
      }
      if (e.cells[1] != Mesh::none) CHECK(walked[{e.vertices[1], e.vertices[0]}] == 1);
      if (e.cells[0] == e.cells[1]) ++slit_edges;
    }
    CHECK(walked[{e.vertices[0], e.vertices[1]}] == 1);
  }
  // Euler's formula for the planar graph of the edges: V - E + F = 1 + C, F counting the regions
  // of the cells, the holes and the outside, C the domain's components.
  std::set<std::size_t> used;
  for (const auto& e : edges) used.insert(e.vertices[0]), used.insert(e.vertices[1]);
  const auto [holes, parts] = holes_and_components(cdt);
  CAPTURE(used.size(), edges.size(), regions, holes, parts, slit_edges);
  CHECK(long(used.size()) - long(edges.size()) + long(regions + holes + 1) == long(1 + parts));
}

}  // namespace

TEST_CASE("the mesh's cells tile the domain, meet edge to edge, and satisfy Euler's formula",
          "[mesh]") {
  const std::string file =
      GENERATE(as<std::string>{}, "four_clusters.poly", "square_inner_constraints.poly",
               "us_massachusetts_counties.poly", "us_kentucky_counties.poly", "earcut_dude.poly",
               "world_land_110m.poly");
  CAPTURE(file);
  const Cdt_ids cdt = load(file, 1500, 3);
  const Bvd_ids bvd(cdt);
  const Mesh mesh(bvd);
  check_mesh(mesh, cdt);
  // No two vertices at one point on these domains: one vertex per point, as the cells share it.
  std::set<Point> points(mesh.points().begin(), mesh.points().end());
  CHECK(points.size() == mesh.number_of_vertices());
}

TEST_CASE("cocircular generators: a grid, some on constraints, one vertex a point", "[mesh]") {
  // Every four neighbours of the grid are cocircular: faces of one circumcenter around most
  // generators, circumcenters on the constraints, clip points at circumcenters.
  Cdt_ids cdt;
  CVT_2::IO::read_domain(data_path("square_inner_constraints.poly"), cdt);
  std::vector<Point> grid;  // several chunks of faces, for two threads
  for (int i = 1; i < 100; ++i)
    for (int j = 1; j < 100; ++j) grid.emplace_back(i * 0.1, j * 0.1);
  CVT_2::insert_generators_2(cdt, grid);
  const Bvd_ids bvd(cdt);
  REQUIRE(CVT_2::internal::Face_chunks<Cdt_ids>(cdt).size() >= 4);
  for (const unsigned threads : {1u, 2u}) {
    CAPTURE(threads);
    const Mesh mesh(bvd, threads);
    check_mesh(mesh, cdt);
    const std::set<Point> points(mesh.points().begin(), mesh.points().end());
    CHECK(points.size() == mesh.number_of_vertices());
    std::size_t no_length = 0;
    for (std::size_t k = 0; k < mesh.number_of_cells(); ++k) {
      const auto c = mesh.cell(k);
      for (std::size_t j = 0; j < c.size(); ++j)
        no_length += mesh.point(c[j]) == mesh.point(c[(j + 1) % c.size()]);
    }
    CHECK(no_length == 0);
  }
}

TEST_CASE("the mesh of random domains: holes, touching polylines, points on constraints",
          "[mesh]") {
  for (unsigned seed = 1; seed <= random_cases(60); ++seed) {
    CAPTURE(seed);
    const Cdt_ids cdt = random_case(seed);
    const Bvd_ids bvd(cdt);
    check_mesh(Mesh(bvd), cdt);
  }
}

namespace {

// The unit square (or [0, 1] x [0, height]), and with `inner` the segments y = 0.3 and x = 0.7
// (cells on both sides).
Cdt_ids unit_square(bool inner, double height = 1) {
  CVT_2::IO::Poly_data<Point> poly;
  add_ring(poly, {{0, 0}, {1, 0}, {1, height}, {0, height}});
  if (inner) {
    poly.vertices.insert(poly.vertices.end(), {{0.1, 0.3}, {0.9, 0.3}, {0.7, 0.45}, {0.7, 0.9}});
    poly.segments.push_back({4, 5});
    poly.segments.push_back({6, 7});
  }
  poly.vertex_lines.assign(poly.vertices.size(), 0);
  poly.segment_lines.assign(poly.segments.size(), 0);
  Cdt_ids cdt;
  CVT_2::IO::insert_poly(cdt, poly);
  return cdt;
}

}  // namespace

TEST_CASE("generators a hair apart beside a constraint keep cells of positive area", "[mesh]") {
  // Two generators at one x, within 1e-16 to 1e-12 of a horizontal constraint (or at one y,
  // of a vertical one): the cell nearer the constraint is a strip that thin, whose points lie
  // within 2^-40 of their distance to the generator. It keeps its area and vertices, and the
  // cells still tile the domain (check_mesh()).
  {  // the issue's case: the lower cell is (0.75, 0) (0.75, 2e-14) (0.25, 2e-14) (0.25, 0)
    Cdt_ids cdt = unit_square(false);
    CVT_2::insert_generators_2(cdt, std::vector<Point>{{0.5, 1e-14}, {0.5, 3e-14}});
    const Bvd_ids bvd(cdt);
    const Mesh mesh(bvd);
    check_mesh(mesh, cdt);
    std::size_t k = 0;
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
      if (v->point() == Point(0.5, 1e-14)) k = mesh.cell_of(v);
    CHECK(mesh.cell(k).size() == 4);
    CHECK(CGAL::to_double(mesh.area(k)) == Approx(0.5 * 2e-14));
  }
  // (vertical, where, towards, from, to): the square's sides and the inner segments, both sides.
  static const double lines[8][5] = {{0, 0, 1, 0.05, 0.95},   {0, 1, -1, 0.05, 0.95},
                                     {0, 0.3, 1, 0.15, 0.85}, {0, 0.3, -1, 0.15, 0.85},
                                     {1, 0, 1, 0.05, 0.95},   {1, 1, -1, 0.05, 0.95},
                                     {1, 0.7, 1, 0.5, 0.85},  {1, 0.7, -1, 0.5, 0.85}};
  std::mt19937_64 rng(7);
  std::size_t thin = 0;
  for (int trial = 0; trial < int(random_cases(300)); ++trial) {
    CAPTURE(trial);
    Cdt_ids cdt = unit_square(true);
    std::vector<Point> generators;
    for (int pair = uniform_int(rng, 1, 3); pair > 0; --pair) {
      const auto& l = lines[uniform_int(rng, 0, 7)];
      const double along = uniform(rng, l[3], l[4]);
      const double d = std::pow(10.0, uniform(rng, -16, -12)), e = d * uniform(rng, 1.5, 4);
      for (const double off : {d, e}) {
        const double across = l[1] + l[2] * off;
        generators.push_back(l[0] == 1 ? Point(across, along) : Point(along, across));
      }
    }
    if (uniform_int(rng, 0, 1) == 1)
      for (const Point& p : CVT_2::random_points_in_domain_2(
               cdt, 20, CVT_2::parameters::random_seed(unsigned(trial))))
        generators.push_back(p);
    CVT_2::insert_generators_2(cdt, generators);
    const Bvd_ids bvd(cdt);
    const Mesh mesh(bvd);
    check_mesh(mesh, cdt);
    // Each cell has the area the walk gives it, thin or not.
    std::size_t k = 0;
    bvd.for_each_cell([&](Cdt_ids::Vertex_handle, const auto& c) {
      const double walked = signed_area(c);
      thin += walked > 0 && walked < 1e-9;
      CHECK(mesh.cell(k).size() >= 3);
      INFO(std::to_string(k) + ": " + std::to_string(walked * 1e20) + "e-20 by the walk, " +
           std::to_string(CGAL::to_double(mesh.area(k)) * 1e20) + "e-20 in the mesh");
      CHECK(CGAL::to_double(mesh.area(k)) == Approx(walked).epsilon(1e-6).margin(1e-15));
      ++k;
    });
  }
  CHECK(thin > 100);  // the thin cells happened
}

TEST_CASE("a circumcenter a hair inside the boundary merges onto it, not the boundary onto it",
          "[mesh]") {
  // Three generators on a circle centred 1e-15 above the bottom side: their circumcenter and
  // the clip points where its bisectors meet the side are one vertex, which stays on the side.
  Cdt_ids cdt = unit_square(false);
  const double r = 0.2, c = 1e-15;
  std::vector<Point> generators;
  for (const double degrees : {-60.0, 60.0, 80.0}) {
    const double t = degrees * CGAL_PI / 180;
    generators.emplace_back(0.5 + r * std::sin(t), c + r * std::cos(t));
  }
  CVT_2::insert_generators_2(cdt, generators);
  const Bvd_ids bvd(cdt);
  const Mesh mesh(bvd);
  check_mesh(mesh, cdt);
  std::size_t on_side = 0;
  for (const auto& e : mesh.edges()) {
    if (e.constraint == Mesh::none || e.cells[1] != Mesh::none) continue;
    for (const auto i : e.vertices) {
      const Point& p = mesh.point(i);
      CAPTURE(p);
      CHECK(std::min({std::abs(p.x()), std::abs(p.y()), std::abs(1 - p.x()),
                      std::abs(1 - p.y())}) <= 1e-16);
      on_side += std::abs(p.x() - 0.5) < 1e-3;
    }
  }
  CHECK(on_side >= 2);  // the merged vertex, on the bottom side
}

TEST_CASE("cell vertices farther apart than a rounding stay apart: a grid off by 1e-10", "[mesh]") {
  // Each four neighbours of the grid are nearly cocircular: their two circumcenters some 1e-10
  // of the step apart, an edge the mesh keeps (it merges points within 2^-40 of their distance
  // to the generator, where a circumcenter's rounding is some 2^-50; 2^10 times that would
  // merge these).
  std::mt19937_64 rng(3);
  std::vector<Point> grid;
  const double h = 1.0 / 32;
  for (int i = 1; i < 32; ++i)
    for (int j = 1; j < 32; ++j)
      grid.emplace_back((i + uniform(rng, -1e-10, 1e-10)) * h,
                        (j + uniform(rng, -1e-10, 1e-10)) * h);
  Cdt_ids cdt = unit_square(false);
  CVT_2::insert_generators_2(cdt, grid);
  const Bvd_ids bvd(cdt);
  const Mesh mesh(bvd);
  check_mesh(mesh, cdt);
  std::size_t k = 0, short_edges = 0;
  bvd.for_each_cell([&](Cdt_ids::Vertex_handle v, const auto& c) {
    // The walk's edges longer than 2^-36 of the distance to the generator are all kept.
    std::size_t kept = 0;
    for (std::size_t j = 0; j < c.size(); ++j) {
      const double far = CGAL::squared_distance(c[j].point, v->point());
      const double length = CGAL::squared_distance(c[j].point, c[(j + 1) % c.size()].point);
      kept += length > 0x1.0p-72 * far;
      short_edges += length > 0x1.0p-72 * far && length < 0x1.0p-50 * far;
    }
    CHECK(mesh.cell(k).size() >= kept);
    ++k;
  });
  CHECK(short_edges > 100);  // edges that a 2^10-fold tolerance would merge
}

TEST_CASE("the two sides of a constraint meet at their own points, a hair apart", "[mesh]") {
  // Rows of generators on both sides of the inner segment y = 0.3 (x from 0.1 to 0.9), the rows
  // below shifted by 1e-10 of their step: the cells above and below meet the segment at points
  // 2.5e-12 apart, each a vertex of the conforming mesh (it merges the two sides' points within
  // 2^-40 of the segment's length, 7e-13; 2^10 times that would merge these).
  Cdt_ids cdt = unit_square(true);
  const double h = 0.8 / 32, shift = 1e-10 * h;
  std::vector<Point> generators;
  for (int i = 1; i < 32; ++i)
    for (const double dy : {0.5 * h, 1.5 * h}) {
      generators.emplace_back(0.1 + i * h, 0.3 + dy);
      generators.emplace_back(0.1 + i * h + shift, 0.3 - dy);
    }
  CVT_2::insert_generators_2(cdt, generators);
  const Bvd_ids bvd(cdt);
  const Mesh mesh(bvd);
  check_mesh(mesh, cdt);
  std::size_t on_segment = 0;
  for (std::size_t i = 0; i < mesh.number_of_vertices(); ++i) {
    const Point& p = mesh.point(i);
    on_segment += std::abs(p.y() - 0.3) < 1e-14 && p.x() > 0.1 + h && p.x() < 0.9 - h;
  }
  CHECK(on_segment == 2 * 30);  // the bisectors between the columns, from above and below
}

TEST_CASE("each mesh cell is its diagram cell, with the vertices the cells beside it add",
          "[mesh]") {
  const Cdt_ids cdt = load("us_massachusetts_counties.poly", 2000, 5);
  const Bvd_ids bvd(cdt);
  const Mesh mesh(bvd);
  std::size_t k = 0;
  std::vector<Bvd_ids::Cell_vertex> cell;
  bvd.for_each_cell([&](Cdt_ids::Vertex_handle v, const auto& c) {
    REQUIRE(mesh.generator(k) == v);
    const auto m = mesh.cell(k);
    // Every diagram vertex is a mesh vertex of the cell (to rounding: a clip point is computed
    // by the cell on its other side too), and the mesh adds only points on the cell's edges.
    const double size = std::sqrt(CGAL::to_double(mesh.area(k)));
    for (const auto& x : c) {
      double nearest = HUGE_VAL;
      for (const auto i : m)
        nearest = std::min(nearest, std::sqrt(CGAL::squared_distance(x.point, mesh.point(i))));
      CHECK(nearest <= 1e-9 * size);
    }
    CHECK(m.size() >= c.size());
    CHECK(CGAL::to_double(mesh.area(k)) == Approx(signed_area(c)).epsilon(1e-9));
    ++k;
  });
  CHECK(k == mesh.number_of_cells());
}

TEST_CASE("the mesh is the same on any number of threads, and without ids in the records",
          "[mesh]") {
  const Cdt_ids cdt = load("us_massachusetts_counties.poly", 20000, 2);
  const Bvd_ids bvd(cdt);
  const Mesh one(bvd, 1), three(bvd, 3);
  REQUIRE(CVT_2::internal::Face_chunks<Cdt_ids>(cdt).size() >= 6);  // enough for 3 threads
  const auto same = [](const Mesh& a, const Mesh& b) {
    if (a.points() != b.points() || a.number_of_cells() != b.number_of_cells()) return false;
    for (std::size_t k = 0; k < a.number_of_cells(); ++k) {
      const auto x = a.cell(k), y = b.cell(k);
      if (!std::equal(x.begin(), x.end(), y.begin(), y.end())) return false;
      for (std::size_t j = 0; j < x.size(); ++j)
        if (a.side(k, j).cell != b.side(k, j).cell ||
            a.side(k, j).constraint != b.side(k, j).constraint)
          return false;
    }
    return a.constraints() == b.constraints();
  };
  CHECK(same(one, three));
  // The same triangulation with CGAL's default records, numbered in hash maps.
  Domain d;
  load_domain(d, "us_massachusetts_counties.poly");
  insert_random_points(d, 20000, 2);
  const Bvd plain(d.cdt);
  const CVT_2::Bvd_mesh_2<Bvd> mapped(plain, 2);
  CHECK(mapped.points() == one.points());
  CHECK(mapped.number_of_cells() == one.number_of_cells());
  CHECK(mapped.edges().size() == one.edges().size());
}

namespace {

// A square with a crack from its middle to the right side and a wall across the left half that
// ends inside: generators at the crack's tip and on the wall.
Cdt_ids crack_and_wall(std::size_t generators = 200) {
  CVT_2::IO::Poly_data<Point> poly;
  add_ring(poly, {{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  const std::size_t first = poly.vertices.size();
  poly.vertices.insert(poly.vertices.end(), {{2, 2}, {4, 2}, {0.5, 1}, {1.5, 1}, {1, 1}});
  poly.segments.push_back({first, first + 1});  // the crack, ending on the side at (4, 2)
  poly.segments.push_back({first + 2, first + 4});
  poly.segments.push_back({first + 4, first + 3});  // the wall, through (1, 1)
  Cdt_ids cdt;
  poly.vertex_lines.assign(poly.vertices.size(), 0);
  poly.segment_lines.assign(poly.segments.size(), 0);
  CVT_2::IO::insert_poly(cdt, poly);
  CVT_2::insert_generators_2(
      cdt, CVT_2::random_points_in_domain_2(cdt, generators, CVT_2::parameters::random_seed(4)));
  return cdt;
}

}  // namespace

TEST_CASE("a vertex on inner constraints has one cell with slits; polygons() drops them",
          "[mesh]") {
  const Cdt_ids cdt = crack_and_wall();
  const Bvd_ids bvd(cdt);
  const Mesh mesh(bvd);
  check_mesh(mesh, cdt);
  for (const Point p : {Point(2, 2), Point(1, 1), Point(0.5, 1)}) {
    CAPTURE(p);
    std::size_t k = Mesh::none;
    for (std::size_t i = 0; i < mesh.number_of_cells(); ++i)
      if (mesh.generator(i)->point() == p) k = i;
    REQUIRE(k != Mesh::none);
    std::size_t slits = 0;
    for (std::size_t j = 0; j < mesh.cell(k).size(); ++j)
      slits += mesh.side(k, j).cell == k ? 1 : 0;
    CHECK(slits >= 2);  // each slit walked there and back
    const auto rings = mesh.polygons(k);
    REQUIRE(rings.size() == 1);
    for (const auto i : rings[0]) CHECK(mesh.point(i) != p);  // the generator is inside
  }
}

TEST_CASE("a barrier splits the cells on it, one per side; no edge is shared across",
          "[mesh][grid]") {
  const Cdt_ids cdt = crack_and_wall();
  const Bvd_ids bvd(cdt);
  const Mesh mesh(bvd);
  using Grid = CVT_2::Simulation_grid_2<Mesh>;
  const auto parts_of = [&](const Grid& grid) {
    std::vector<std::vector<std::size_t>> parts(mesh.number_of_cells());
    for (std::size_t k = 0; k < grid.number_of_cells(); ++k) parts[grid.mesh_cell(k)].push_back(k);
    return parts;
  };
  // Slits: the mesh's outlines, vertex for vertex, one grid vertex a mesh vertex they use.
  const Grid slit(mesh);
  REQUIRE(slit.number_of_cells() == mesh.number_of_cells());
  std::set<Mesh::Index> used;
  for (std::size_t k = 0; k < mesh.number_of_cells(); ++k)
    for (const auto i : mesh.outline(k)) used.insert(i);
  CHECK(slit.number_of_vertices() == used.size());
  for (std::size_t k = 0; k < mesh.number_of_cells(); ++k) {
    const auto outline = mesh.outline(k);
    REQUIRE(slit.degree(k) == outline.size());
    for (std::size_t j = 0; j < outline.size(); ++j)
      CHECK(slit.mesh_vertex(slit.vertex(k, j)) == outline[j]);
  }
  // Barriers: the generators inside the wall (1, 1) and where the crack meets the side (4, 2)
  // have two cells; the tips (2, 2), (0.5, 1), (1.5, 1) one; the parts' areas are the cell's.
  const Grid grid(mesh, CVT_2::BARRIER);
  const auto parts = parts_of(grid);
  for (std::size_t k = 0; k < mesh.number_of_cells(); ++k) {
    const Point& p = mesh.generator(k)->point();
    CAPTURE(p);
    const bool split = p == Point(1, 1) || p == Point(4, 2);
    CHECK(parts[k].size() == (split ? 2u : 1u));
    double area = 0;
    for (const std::size_t g : parts[k]) {
      CHECK(grid.area(g) > 0);
      area += CGAL::to_double(grid.area(g));
    }
    CHECK(area == Approx(CGAL::to_double(mesh.area(k))).epsilon(1e-12).margin(1e-15));
  }
  // Each edge is its cell beyond's, the other way round: with the same vertex numbers where
  // no barrier lies under it, not both where one does (copies of the same points; the end
  // where a barrier ends in a cell is one vertex).
  std::size_t barrier_edges = 0;
  for (std::size_t k = 0; k < grid.number_of_cells(); ++k)
    for (std::size_t j = 0, n = grid.degree(k); j < n; ++j) {
      const auto& side = grid.side(k, j);
      const auto a = grid.vertex(k, j), b = grid.vertex(k, (j + 1) % n);
      CHECK(side.barrier == (side.constraint != Grid::none && side.cell != Grid::none));
      if (side.cell == Grid::none) continue;
      barrier_edges += side.barrier;
      bool found = false;
      for (std::size_t i = 0, m = grid.degree(side.cell); i < m; ++i) {
        const auto c = grid.vertex(side.cell, i), d = grid.vertex(side.cell, (i + 1) % m);
        if (grid.point(c) != grid.point(b) || grid.point(d) != grid.point(a)) continue;
        found = true;
        CHECK((c == b && d == a) == !side.barrier);
      }
      CHECK(found);
      if (!side.barrier) CHECK(grid.mesh_cell(side.cell) != grid.mesh_cell(k));
    }
  CHECK(barrier_edges >= 8);
  // The DISV: the cells of the grid, vertices with their copies.
  std::ostringstream disv;
  CVT_2::IO::write_disv(disv, grid);
  CHECK_THAT(disv.str(), Catch::Contains("NCPL " + std::to_string(grid.number_of_cells())));
  CHECK(grid.number_of_cells() == mesh.number_of_cells() + 2);
}

TEST_CASE("conforming sites: the faces between each mirrored pair are the line's steps",
          "[mesh][grid]") {
  // A bent line across a square that is not a constraint; the pairs alone as generators.
  const std::vector<Point> line{{0.1, 0.3}, {0.45, 0.38}, {0.7, 0.62}, {0.93, 0.6}};
  const auto c = CVT_2::conforming_sites_2(line, 0.05);
  REQUIRE(c.sites.size() == 2 * (c.nodes.size() - 1));
  for (std::size_t k = 0; k + 1 < c.nodes.size(); ++k) {
    const Point &a = c.nodes[k], &b = c.nodes[k + 1], &l = c.sites[2 * k], &r = c.sites[2 * k + 1];
    CHECK(CGAL::orientation(a, b, l) == CGAL::LEFT_TURN);
    CHECK(CGAL::orientation(a, b, r) == CGAL::RIGHT_TURN);
    for (const Point& n : {a, b})  // each node equidistant from the pair: on their bisector
      CHECK(std::sqrt(CGAL::squared_distance(n, l)) ==
            Approx(std::sqrt(CGAL::squared_distance(n, r))).epsilon(1e-12));
  }
  Cdt_ids cdt = unit_square(false);
  CVT_2::insert_generators_2(cdt, c.sites);
  const Bvd_ids bvd(cdt);
  const Mesh mesh(bvd);
  check_mesh(mesh, cdt);
  // The face between the pair of step k runs from node k to node k + 1 (the first and last
  // steps' go on beyond the line's ends, where no other generator closes them here).
  for (std::size_t k = 1; k + 2 < c.nodes.size(); ++k) {
    CAPTURE(k);
    Cdt_ids::Locate_type lt;
    int li;
    const auto f = cdt.locate(c.sites[2 * k], lt, li);
    REQUIRE(lt == Cdt_ids::VERTEX);
    const std::size_t left = mesh.cell_of(f->vertex(li));
    const auto g = cdt.locate(c.sites[2 * k + 1], lt, li);
    const std::size_t right = mesh.cell_of(g->vertex(li));
    double length = 0;
    for (std::size_t j = 0; j < mesh.cell(left).size(); ++j) {
      if (mesh.side(left, j).cell != right) continue;
      const Point& p = mesh.point(mesh.cell(left)[j]);
      const Point& q = mesh.point(mesh.cell(left)[(j + 1) % mesh.cell(left).size()]);
      CHECK(std::sqrt(CGAL::squared_distance(p, Segment(c.nodes[k], c.nodes[k + 1]))) < 1e-12);
      CHECK(std::sqrt(CGAL::squared_distance(q, Segment(c.nodes[k], c.nodes[k + 1]))) < 1e-12);
      length += std::sqrt(CGAL::squared_distance(p, q));
    }
    CHECK(length == Approx(std::sqrt(CGAL::squared_distance(c.nodes[k], c.nodes[k + 1]))));
  }
  CHECK_THROWS_AS(CVT_2::conforming_sites_2(line, 0.0), std::invalid_argument);
  CHECK_THROWS_AS(CVT_2::conforming_sites_2(std::vector<Point>{{0, 0}, {0, 0}}, 1.0),
                  std::invalid_argument);
}

TEST_CASE("keep_out: no free generator stays in or enters the circles of a conforming line",
          "[mesh][grid][keep_out]") {
  // the bent river of python/tests/test_modflow_grid.py, in kilometres, at the cell size of
  // 1 500 cells
  const std::vector<Point> line{{0, 0.25}, {0.3, 0.28}, {0.55, 0.4}, {0.8, 0.38}, {1, 0.45}};
  const double h = std::sqrt(0.6 / 1500);
  const auto c = CVT_2::conforming_sites_2(line, h);
  CVT_2::Conforming_disks<Point> disks;
  disks.add(c);
  // outside(): a point inside goes out along the radius, one outside stays
  CHECK(disks.outside(Point(0.5, 0.59), Point(0.5, 0.595)) == Point(0.5, 0.595));
  const Point inside = c.nodes[2] + K::Vector_2(1e-4, 2e-4);
  REQUIRE(disks.contains(inside));
  const Point out = disks.outside(inside, inside);
  CHECK(!disks.contains(out));
  CHECK(std::sqrt(CGAL::squared_distance(out, inside)) < 2 * h);
  std::size_t inside_without = 0;
  for (const bool keep : {true, false}) {
    for (const bool lbfgs : {false, true}) {
      CAPTURE(keep, lbfgs);
      Cdt_ids cdt = unit_square(false, 0.6);
      std::vector<Point> sites;
      for (const Point& p : c.sites)
        if (p.x() > 0 && p.x() < 1) sites.push_back(p);
      std::vector<Point> points;
      for (const Point& p : CVT_2::random_points_in_domain_2(cdt, 1500 - sites.size(),
                                                             CVT_2::parameters::random_seed(1)))
        if (!disks.contains(p)) points.push_back(p);
      for (const std::size_t k : {5, 20, 35})  // three starts inside circles, off their nodes
        points.push_back(c.nodes[k] + K::Vector_2(0.3 * c.radii[k], 0.1 * c.radii[k]));
      CVT_2::insert_generators_2(cdt, sites);
      CVT_2::insert_generators_2(cdt, points);
      const auto np = CVT_2::parameters::fixed_points(sites);
      const CVT_2::Conforming_disks<Point> none;
      if (lbfgs)
        CVT_2::lbfgs_optimize_2(cdt, np.keep_out(keep ? disks : none));
      else
        CVT_2::lloyd_optimize_2(cdt, np.keep_out(keep ? disks : none));
      std::size_t in = 0;
      for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
        in += disks.contains(v->point());
      if (keep)
        CHECK(in == 0);
      else
        inside_without += in;
    }
  }
  CHECK(inside_without > 0);  // without keep_out, starts inside stay there: the test can tell
}

namespace {

// The length of the faces that the cells of each pair of a conforming line share.
double length_between_pairs(const Cdt_ids& cdt, const Mesh& mesh,
                            const std::vector<CVT_2::Conforming_pair_2<Point>>& pairs) {
  double length = 0;
  for (const auto& p : pairs) {
    Cdt_ids::Locate_type lt;
    int li;
    const auto f = cdt.locate(p.left, lt, li);
    REQUIRE(lt == Cdt_ids::VERTEX);
    const std::size_t left = mesh.cell_of(f->vertex(li));
    const auto g = cdt.locate(p.right, lt, li);
    REQUIRE(lt == Cdt_ids::VERTEX);
    const std::size_t right = mesh.cell_of(g->vertex(li));
    const auto& cell = mesh.cell(left);
    for (std::size_t j = 0; j < cell.size(); ++j)
      if (mesh.side(left, j).cell == right)
        length += std::sqrt(
            CGAL::squared_distance(mesh.point(cell[j]), mesh.point(cell[(j + 1) % cell.size()])));
  }
  return length;
}

}  // namespace

TEST_CASE(
    "conforming lines as a network: corners, junctions and a line that ends on another "
    "lie on faces all along",
    "[mesh][grid][keep_out]") {
  // In the unit square, at the spacing of 1 000 cells: a V of 30 degrees, a right-angled loop,
  // a tributary that ends on the interior of a river's segment (a rounding beside it: snapped),
  // two lines crossing at a vertex they share, three meeting at a Y, and a zigzag of 10 and 20
  // degrees. Each pair's cells share
  // the face along its step, after Lloyd with the pairs fixed and the circles kept out: the
  // faces between pairs add up to the lines' length. (Placed line by line, each corner sharper
  // than 90 degrees and each junction put two pairs on one point or a pair in a circle.)
  const double a = 3.14159265358979323846 / 6;
  const std::vector<std::vector<Point>> lines{
      {{0.45, 0.5}, {0.15, 0.5}, {0.15 + 0.3 * std::cos(a), 0.5 + 0.3 * std::sin(a)}},
      {{0.1, 0.1}, {0.3, 0.1}, {0.3, 0.3}, {0.1, 0.3}, {0.1, 0.1}},
      {{0.5, 0.1}, {0.9, 0.13}},
      {{0.7, 0.115}, {0.72, 0.4}},  // on the river but for a rounding (left of it)
      {{0.55, 0.6}, {0.7, 0.75}, {0.85, 0.9}},
      {{0.55, 0.9}, {0.7, 0.75}, {0.85, 0.6}},
      {{0.3, 0.8}, {0.45, 0.8}},
      {{0.3, 0.8}, {0.2, 0.95}},
      {{0.3, 0.8}, {0.2, 0.65}},
      {{0.45, 0.2}, {0.6, 0.2 + 0.15 * std::tan(a / 3)}, {0.45, 0.4}}};
  double length = 0;
  for (const auto& l : lines)
    for (std::size_t k = 0; k + 1 < l.size(); ++k)
      length += std::sqrt(CGAL::squared_distance(l[k], l[k + 1]));
  const double h = std::sqrt(2 / (std::sqrt(3.0) * 1000));
  Cdt_ids cdt = unit_square(false);
  CVT_2::Conforming_disks<Point> disks;
  std::size_t left_out = 1;
  const auto pairs = CVT_2::insert_conforming_sites_2(cdt, lines, h, disks, &left_out);
  CHECK(left_out == 0);
  std::vector<Point> fixed;
  for (const auto& p : pairs) fixed.push_back(p.left), fixed.push_back(p.right);
  CVT_2::insert_generators_2(
      cdt, CVT_2::random_points_in_domain_2(cdt, 1000 - fixed.size(),
                                            CVT_2::parameters::random_seed(1).keep_out(disks)));
  CVT_2::lloyd_optimize_2(cdt, CVT_2::parameters::fixed_points(fixed).keep_out(disks));
  std::size_t inside = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    inside += disks.contains(v->point());
  CHECK(inside == 0);
  const Bvd_ids bvd(cdt);
  const Mesh mesh(bvd);
  check_mesh(mesh, cdt);
  const double on_faces = length_between_pairs(cdt, mesh, pairs);
  // All along (the Voronoi vertices at the nodes rounded), and past the 14 ends of lines by
  // less than a step each (a face goes on until a free cell closes it).
  CHECK(on_faces > (1 - 1e-7) * length);
  CHECK(on_faces < length + 14 * h);
  // Lines that cross where neither has a vertex are refused, the segments named.
  Cdt_ids other = unit_square(false);
  CHECK_THROWS_WITH(
      CVT_2::insert_conforming_sites_2(
          other,
          std::vector<std::vector<Point>>{{{0.2, 0.5}, {0.8, 0.5}}, {{0.5, 0.2}, {0.5, 0.8}}}, h,
          disks),
      Catch::Contains("a line crosses itself or an earlier one where neither has a vertex: its "
                      "segment (0.5, 0.2) - (0.5, 0.8) crosses (0.2, 0.5) - (0.8, 0.5)"));
}

TEST_CASE("conforming lines follow a spacing that varies, and still lie on faces all along",
          "[mesh][grid][keep_out]") {
  // A river with a bend past a well, steps of 0.01 at the well growing to 0.1 at 0.3 from it
  // (a refinement), as a function of the point.
  const Point well(0.5, 0.54);
  const auto spacing = [&](const Point& p) {
    return 0.01 + 0.09 * std::min(1.0, std::sqrt(CGAL::squared_distance(p, well)) / 0.3);
  };
  const std::vector<std::vector<Point>> lines{{{0.03, 0.5}, {0.6, 0.5}, {0.97, 0.45}}};
  Cdt_ids cdt = unit_square(false);
  CVT_2::Conforming_disks<Point> disks;
  std::size_t left_out = 1;
  const auto pairs = CVT_2::insert_conforming_sites_2(cdt, lines, spacing, disks, &left_out);
  CHECK(left_out == 0);
  // As many steps as the integral of 1 / spacing along the line, rounded up on each segment
  // (and a step or two more at the bend); each pair about a step apart, a step as long as the
  // spacing where it lies or a little shorter. (A pair lies on the circles of its step's nodes,
  // sized by each node's longer step: here, where the spacing grows by a third a step, up to 30%
  // further apart than its own step is long.)
  double steps = 0;
  for (std::size_t k = 0; k + 1 < lines[0].size(); ++k) {
    const Point &u = lines[0][k], &w = lines[0][k + 1];
    double integral = 0;
    for (int j = 0; j < 100000; ++j)
      integral += std::sqrt(CGAL::squared_distance(u, w)) / 100000 /
                  spacing(u + (w - u) * ((j + 0.5) / 100000));
    steps += std::ceil(integral);
  }
  CHECK(double(pairs.size()) >= steps - 0.5);
  CHECK(double(pairs.size()) <= steps + 4.5);
  for (const auto& p : pairs) {
    const double apart = std::sqrt(CGAL::squared_distance(p.left, p.right)),
                 h = spacing(CGAL::midpoint(p.left, p.right));
    CHECK(apart < 1.35 * h);
    CHECK(apart > 0.5 * h);
  }
  // The same faces along the line as at a constant spacing.
  std::vector<Point> fixed;
  for (const auto& p : pairs) fixed.push_back(p.left), fixed.push_back(p.right);
  CVT_2::insert_generators_2(
      cdt, CVT_2::random_points_in_domain_2(
               cdt, 600, CVT_2::parameters::random_seed(1).keep_out(disks).sizing_field(spacing)));
  CVT_2::lloyd_optimize_2(
      cdt, CVT_2::parameters::fixed_points(fixed).keep_out(disks).sizing_field(spacing));
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    CHECK_FALSE(disks.contains(v->point()));
  const Bvd_ids bvd(cdt);
  const Mesh mesh(bvd);
  check_mesh(mesh, cdt);
  double length = 0;
  for (std::size_t k = 0; k + 1 < lines[0].size(); ++k)
    length += std::sqrt(CGAL::squared_distance(lines[0][k], lines[0][k + 1]));
  const double on_faces = length_between_pairs(cdt, mesh, pairs);
  CHECK(on_faces > (1 - 1e-7) * length);
  CHECK(on_faces < length + 2 * 0.1);
  // A constant function places the pairs of the constant, to the bit.
  Cdt_ids a = unit_square(false), b = unit_square(false);
  CVT_2::Conforming_disks<Point> da, db;
  const auto by_number = CVT_2::insert_conforming_sites_2(a, lines, 0.05, da);
  const auto by_function = CVT_2::insert_conforming_sites_2(
      b, lines, [](const Point&) { return 0.05; }, db);
  REQUIRE(by_function.size() == by_number.size());
  for (std::size_t k = 0; k < by_number.size(); ++k) {
    CHECK(by_function[k].left == by_number[k].left);
    CHECK(by_function[k].right == by_number[k].right);
  }
  // One line alone (conforming_sites_2()): the same, node for node.
  const auto alone = CVT_2::conforming_sites_2(lines[0], spacing);
  REQUIRE(alone.sites.size() == 2 * pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) CHECK(alone.sites[2 * k] == pairs[k].left);
  CHECK(CVT_2::conforming_sites_2(lines[0], [](const Point&) { return 0.05; }).sites ==
        CVT_2::conforming_sites_2(lines[0], 0.05).sites);
  // The roundings that join lines are measured by the spacing where they are: a tributary that
  // ends 1e-4 short of a river, where the spacing is 0.02, is joined to it, though a well along
  // the river asks for 0.005 (by the lines' smallest spacing, 5e-5, it was not, and its pairs
  // fell in the river's circles).
  {
    Cdt_ids t = unit_square(false);
    CVT_2::Conforming_disks<Point> d;
    const auto refined = [](const Point& p) {
      return 0.005 +
             0.015 * std::min(1.0, std::sqrt(CGAL::squared_distance(p, Point(0.7, 0.5))) / 0.1);
    };
    const auto joined = CVT_2::insert_conforming_sites_2(
        t, std::vector<std::vector<Point>>{{{0, 0.5}, {1, 0.5}}, {{0.3, 0.9}, {0.3, 0.5001}}},
        refined, d);
    for (const auto& p : joined) {
      CHECK_FALSE(d.contains(p.left));
      CHECK_FALSE(d.contains(p.right));
    }
  }
  // A spacing that grows six times faster than the steps may (slope 3, from 0.005 at a line's
  // end, where a steep density asks for tiny cells at the boundary): the steps grow by about
  // half their length from one to the next, as many as the integral of 1 / (0.005 + s / 2)
  // says, and no pair lies in a circle (the raw spacing gave 5 steps, each three or four times
  // the one before: in cvt2, pairs in the next node's circle and halvings that cascade).
  {
    Cdt_ids t = unit_square(false);
    CVT_2::Conforming_disks<Point> d;
    const auto steep = [](const Point& p) { return 0.005 + 3 * (p.x() - 0.03); };
    const auto graded = CVT_2::insert_conforming_sites_2(
        t, std::vector<std::vector<Point>>{{{0.03, 0.5}, {0.97, 0.5}}}, steep, d);
    const double integral = 2 * std::log((0.005 + 0.94 / 2) / 0.005);  // 9.1
    CHECK(double(graded.size()) >= integral);
    CHECK(double(graded.size()) <= integral + 2);
    for (std::size_t k = 0; k < graded.size(); ++k) {
      CHECK_FALSE(d.contains(graded[k].left));
      if (k == 0) continue;
      const double apart = std::sqrt(CGAL::squared_distance(graded[k].left, graded[k].right)),
                   before =
                       std::sqrt(CGAL::squared_distance(graded[k - 1].left, graded[k - 1].right));
      CHECK(apart / before < 1.8);
      CHECK(apart / before > 1 / 1.8);
    }
    // A line across a jump from 0.05 to 0.0005: the drop is found between samples, and the steps
    // shrink by that slope before it (sampled a quarter of 0.05 apart, steps ten times too long
    // ran past the jump).
    Cdt_ids u = unit_square(false);
    CVT_2::Conforming_disks<Point> du;
    const auto across = CVT_2::insert_conforming_sites_2(
        u, std::vector<std::vector<Point>>{{{0.5, 0.05}, {0.5, 0.95}}},
        [](const Point& p) { return p.y() > 0.503 ? 0.0005 : 0.05; }, du);
    for (std::size_t k = 1; k < across.size(); ++k) {
      const double apart = std::sqrt(CGAL::squared_distance(across[k].left, across[k].right)),
                   before =
                       std::sqrt(CGAL::squared_distance(across[k - 1].left, across[k - 1].right));
      CHECK(apart / before < 1.8);
      CHECK(apart / before > 1 / 1.8);
      CHECK(apart > 0.0005 * 0.9);
      if (across[k].left.y() > 0.503) CHECK(apart < 0.0005 * 1.5);
    }
  }
  // A spacing that falls below the rounding of the parameter along a segment is refused, not
  // sampled forever.
  Cdt_ids e = unit_square(false);
  CHECK_THROWS_WITH(
      CVT_2::insert_conforming_sites_2(
          e, lines,
          [](const Point& p) { return 1e-17 + 0.05 * std::min(1.0, std::abs(p.x() - 0.3) / 0.1); },
          db),
      Catch::Contains("into too many steps"));
  // A spacing that is not positive somewhere on the line is refused, the point named.
  Cdt_ids c = unit_square(false);
  CHECK_THROWS_WITH(CVT_2::insert_conforming_sites_2(
                        c, lines, [](const Point& p) { return p.x() < 0.8 ? 0.05 : -1.0; }, db),
                    Catch::Contains("the spacing at (") && Catch::Contains("not -1"));
}

TEST_CASE("cell_size_scale_2: hexagons of the sizes a density asks for number the cells",
          "[mesh][grid]") {
  const Cdt_ids square = unit_square(false);
  // uniform: the size of n equal hexagons
  CHECK(CVT_2::cell_size_scale_2(square, 1000) ==
        Approx(std::sqrt(2 / (std::sqrt(3.0) * 1000))).epsilon(1e-12));
  // a sizing: (2/sqrt3) times the integral of 1/(kappa mu)^2, by the midpoint rule on a grid
  // of 10^6 squares, is n
  const auto mu = [](const Point& p) {
    return 0.2 + 0.8 * std::min(1.0, std::sqrt(CGAL::squared_distance(p, Point(0.3, 0.6))) / 0.5);
  };
  const double kappa = CVT_2::cell_size_scale_2(square, 5000, CVT_2::parameters::sizing_field(mu));
  double cells = 0;
  for (int i = 0; i < 1000; ++i)
    for (int j = 0; j < 1000; ++j) {
      const double h = kappa * mu(Point((i + 0.5) / 1000, (j + 0.5) / 1000));
      cells += 2 / (std::sqrt(3.0) * h * h) * 1e-6;
    }
  CHECK(cells == Approx(5000).epsilon(0.002));
  // a point density d = sqrt(rho): the same for d = 1/mu^2
  CHECK(CVT_2::cell_size_scale_2(square, 5000, CVT_2::parameters::density([&](const Point& p) {
                                   return 1 / (mu(p) * mu(p));
                                 })) == Approx(kappa).epsilon(1e-12));
  CHECK_THROWS_AS(CVT_2::cell_size_scale_2(square, 0), CVT_2::Domain_error);
}

TEST_CASE("a cell that meets itself at its generator becomes one ring per lobe", "[mesh]") {
  // Two triangular holes touching at (2, 2): the cell of that vertex has two lobes.
  CVT_2::IO::Poly_data<Point> poly;
  add_ring(poly, {{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  add_ring(poly, {{2, 2}, {3, 1}, {3, 3}});
  add_ring(poly, {{2, 2}, {1, 3}, {1, 1}});
  poly.holes = {Point(2.7, 2), Point(1.3, 2)};
  const Cdt_ids cdt = [&] {
    poly.vertex_lines.assign(poly.vertices.size(), 0);
    poly.segment_lines.assign(poly.segments.size(), 0);
    poly.hole_lines.assign(poly.holes.size(), 0);
    Cdt_ids t;
    CVT_2::IO::insert_poly(t, poly);
    CVT_2::insert_generators_2(
        t, CVT_2::random_points_in_domain_2(t, 300, CVT_2::parameters::random_seed(2)));
    return t;
  }();
  const Bvd_ids bvd(cdt);
  const Mesh mesh(bvd);
  check_mesh(mesh, cdt);
  std::size_t k = Mesh::none;
  for (std::size_t i = 0; i < mesh.number_of_cells(); ++i)
    if (mesh.generator(i)->point() == Point(2, 2)) k = i;
  REQUIRE(k != Mesh::none);
  CHECK(mesh.polygons(k).size() == 2);
  // The GeoJSON writer makes it a MultiPolygon.
  std::ostringstream os;
  CVT_2::IO::write_geojson(os, mesh);
  const auto fc = nlohmann::json::parse(os.str());
  REQUIRE(fc["features"].size() == mesh.number_of_cells());
  CHECK(fc["features"][k]["geometry"]["type"] == "MultiPolygon");
  CHECK(fc["features"][k]["properties"]["constrained"] == true);
}

TEST_CASE(
    "GeoJSON domains: features, inner constraints, generators, and errors naming the "
    "feature",
    "[io][geojson]") {
  const auto read = [](const std::string& text) {
    std::istringstream is(text);
    return CVT_2::IO::read_geojson<K>(is, "t.geojson");
  };
  const auto w = read(R"({"type": "FeatureCollection", "features": [
      {"type": "Feature", "properties": {"name": "square"}, "geometry": {"type": "Polygon",
       "coordinates": [[[0, 0], [4, 0], [4, 4], [0, 4], [0, 0]], [[1, 1], [1, 2], [2, 2], [1, 1]]]}},
      {"type": "Feature", "properties": {}, "geometry": {"type": "MultiLineString",
       "coordinates": [[[3, 0.5], [3, 3.5]]]}},
      {"type": "Feature", "geometry": {"type": "GeometryCollection", "geometries": [
       {"type": "Point", "coordinates": [0.5, 3, 10]}, {"type": "MultiPoint", "coordinates": [[3.5, 1]]}]}},
      {"type": "Feature", "geometry": null}]})");
  CHECK(w.polygons.size() == 1);
  CHECK(w.polygons[0].number_of_holes() == 1);
  CHECK(w.polylines.size() == 1);
  CHECK(w.points == std::vector<Point>{Point(0.5, 3), Point(3.5, 1)});
  CHECK(w.point_lines == std::vector<std::size_t>{3, 3});
  Cdt_ids cdt;
  CVT_2::IO::insert_wkt(cdt, w);
  CHECK(triangulation_area(cdt) == Approx(16 - 0.5));
  const auto error = [&](const std::string& text) {
    try {
      read(text);
    } catch (const CVT_2::IO::Parse_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(error("{\"type\": \"Feature\",\n \"geometry\": [1, 2,}") ==
        "t.geojson:2: column 20: not JSON: syntax error while parsing value - unexpected '}'; "
        "expected '[', '{', or a literal");
  CHECK_THAT(error(R"({"type": "Feature", "properties": {"name": "Adair"}, "geometry":
      {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1], [0, 1]]]}})"),
             Catch::StartsWith("t.geojson: feature 1 (Adair): a linear ring is not closed"));
  CHECK_THAT(error(R"({"type": "FeatureCollection", "features": [{"type": "Feature", "id": 7,
      "geometry": {"type": "Circle", "coordinates": [0, 0]}}]})"),
             Catch::StartsWith("t.geojson: feature 1 (7): unknown geometry type \"Circle\""));
  CHECK_THAT(error(R"({"type": "Point", "coordinates": [0, "a"]})"),
             Catch::Contains("a position must be [x, y] with numbers"));
  CHECK_THAT(error(R"({"type": "Polygon", "coordinates": [[[0, 0], [1e400, 0], [1, 1], [0, 0]]]})"),
             Catch::Contains("not JSON"));
  CHECK_THAT(error(R"({"type": "LineString", "coordinates": [[0, 0], [1, 1]]})"),
             Catch::Contains("no Polygon or MultiPolygon"));
  CHECK_THAT(error(R"([1, 2])"), Catch::Contains("not GeoJSON"));
}

TEST_CASE(
    "an outer ring that touches itself closes off a pocket outside the domain, as GEOS "
    "reads it",
    "[io][wkt]") {
  // The pocket (5, 10), (3, 7), (7, 7) of area 6, closed off by the outer ring at (5, 10); in the
  // second, a hole that touches itself around an island, (2, 2), (4, 2), (4, 4): the hole's loop
  // around it is a hole, the loop inside that one is in the domain again.
  const auto area = [](const std::string& text) {
    std::istringstream is(text);
    Cdt_ids cdt;
    CVT_2::IO::insert_wkt(cdt, CVT_2::IO::read_wkt<K>(is, "t.wkt"));
    return triangulation_area(cdt);
  };
  CHECK(area("POLYGON((0 0,10 0,10 10,5 10,3 7,7 7,5 10,0 10,0 0))") == Approx(100 - 6));
  CHECK(area("POLYGON((0 0,10 0,10 10,0 10,0 0),(1 1,1 5,5 5,5 1,3 1,4 2,2 2,3 1,1 1))") ==
        Approx(100 - 16 + 1));
}

TEST_CASE("the writers: DISV counts and clockwise cells, VTU cells, Triangle's edges",
          "[io][mesh]") {
  const Cdt_ids cdt = load("four_clusters.poly", 300, 1);
  const Bvd_ids bvd(cdt);
  const Mesh mesh(bvd);
  std::ostringstream disv, vtu, node, ele, edge;
  CVT_2::IO::write_disv(disv, mesh);
  CVT_2::IO::write_vtu(vtu, mesh);
  CVT_2::IO::write_triangle(node, ele, edge, cdt);
  CHECK_THAT(disv.str(), Catch::Contains("NCPL " + std::to_string(mesh.number_of_cells())));
  CHECK_THAT(vtu.str(),
             Catch::Contains("NumberOfCells=\"" + std::to_string(mesh.number_of_cells())));
  // Each CELL2D line: clockwise (negative shoelace), closed, vertices shared with neighbors.
  std::istringstream lines(disv.str());
  std::map<std::size_t, Point> vertices;
  std::string line, block;
  std::size_t cells = 0;
  while (std::getline(lines, line)) {
    std::istringstream t(line);
    std::string w;
    t >> w;
    if (w == "BEGIN") t >> block;
    if (w == "BEGIN" || w == "END" || w.empty()) continue;
    if (block == "VERTICES") {
      double x, y;
      t >> x >> y;
      vertices[std::stoul(w)] = Point(x, y);
    } else if (block == "CELL2D") {
      double xc, yc;
      std::size_t n;
      t >> xc >> yc >> n;
      std::vector<Point> ring;
      for (std::size_t i = 0, v; i < n && t >> v; ++i) ring.push_back(vertices.at(v));
      REQUIRE(ring.size() == n);
      CHECK(ring.front() == ring.back());
      ring.pop_back();
      CHECK(CGAL::polygon_area_2(ring.begin(), ring.end(), K()) < 0);
      ++cells;
    }
  }
  CHECK(cells == mesh.number_of_cells());
  std::size_t triangles = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    triangles += f->is_inside_domain() ? 1 : 0;
  CHECK_THAT(ele.str(), Catch::StartsWith(std::to_string(triangles) + " 3 0\n"));
}

// --- the domain's constraints resampled to a cell size --------------------------------------

namespace {

struct Input_polylines {
  std::vector<Segment> segments;  // the constrained edges
  std::vector<Point> vertices;    // their vertices
  std::set<Point> junctions;      // vertices of one or of three or more edges
  std::vector<Point> generators;  // vertices on no constraint
};

Input_polylines input_polylines(const Cdt_ids& cdt) {
  Input_polylines in;
  std::map<Point, int> degree;
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e)
    if (cdt.is_constrained(*e)) {
      in.segments.push_back(cdt.segment(*e));
      ++degree[in.segments.back().source()], ++degree[in.segments.back().target()];
    }
  for (const auto& [p, d] : degree) {
    in.vertices.push_back(p);
    if (d != 2) in.junctions.insert(p);
  }
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (degree.count(v->point()) == 0) in.generators.push_back(v->point());
  return in;
}

double distance_to(const Point& p, const std::vector<Segment>& segments) {
  double d = std::numeric_limits<double>::infinity();
  for (const Segment& s : segments) d = std::min(d, CGAL::squared_distance(p, s));
  return std::sqrt(d);
}

bool in_domain(const Cdt_ids& cdt, const Point& p) {
  const auto f = cdt.locate(p);
  return !cdt.is_infinite(f) && f->is_inside_domain();
}

// Every property resample_constraints_2() promises, against the triangulation before it: the new
// constrained vertices on the input polylines (to rounding), the junctions and ends kept, every
// input vertex within the bound of the new polylines, the generators kept, and every point
// farther than the bound from the input on the same side as before.
void check_resampling(const Cdt_ids& before, const Cdt_ids& after, double h, double bound,
                      const CVT_2::Resampling_report& r) {
  const Input_polylines in = input_polylines(before), out = input_polylines(after);
  const CGAL::Bbox_2 box = domain_bbox(before);
  const double scale = std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  std::size_t off_input = 0, lost_junctions = 0, too_far = 0, lost_generators = 0;
  for (const Point& p : out.vertices) off_input += distance_to(p, in.segments) > 1e-14 * scale;
  for (const Point& p : in.junctions)
    lost_junctions += !std::binary_search(out.vertices.begin(), out.vertices.end(), p);
  double deviation = 0;
  for (const Point& p : in.vertices) deviation = std::max(deviation, distance_to(p, out.segments));
  too_far += deviation > bound * (1 + 1e-12);
  for (const Point& g : in.generators)
    lost_generators +=
        std::find(out.generators.begin(), out.generators.end(), g) == out.generators.end() ||
        in_domain(before, g) != in_domain(after, g);
  CHECK(off_input == 0);
  CHECK(lost_junctions == 0);
  CHECK(too_far == 0);
  CHECK(deviation <= r.max_deviation + 1e-12 * scale);
  CHECK(lost_generators == 0);
  CHECK(r.input_vertices == in.vertices.size());
  CHECK(r.output_vertices == out.vertices.size());
  CHECK(r.area_before == Approx(domain_area(before)));
  CHECK(r.area_after == Approx(domain_area(after)));
  // Points clear of the input by more than the bound keep their side.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> x(box.xmin(), box.xmax()), y(box.ymin(), box.ymax());
  std::size_t sampled = 0, changed = 0;
  while (sampled < 400) {
    const Point p(x(rng), y(rng));
    if (distance_to(p, in.segments) <= bound * (1 + 1e-9)) continue;
    ++sampled;
    changed += in_domain(before, p) != in_domain(after, p);
  }
  CHECK(changed == 0);
  (void)h;
}

}  // namespace

TEST_CASE("resampled constraints lie on the input, keep its junctions, bound and sides",
          "[resample]") {
  for (const std::string file :
       {"france_mainland.poly", "world_land_110m.wkt", "us_kentucky_counties.wkt",
        "us_massachusetts_counties.wkt", "earcut_dude.poly", "four_clusters.poly"})
    for (const std::size_t cells : {300, 3000}) {
      INFO(file << " at " << cells << " cells");
      Cdt_ids before;
      CVT_2::IO::read_domain(data_path(file), before);
      const double h = CVT_2::cell_size_for_cells_2(before, cells);
      Cdt_ids after = before;
      std::vector<CVT_2::Resampled_chord<Point>> chords;
      const auto r =
          CVT_2::resample_constraints_2(after, h, CVT_2::parameters::resampled_chords(&chords));
      check_resampling(before, after, h, h / 4, r);
      CHECK(r.output_vertices <= r.input_vertices);
      // Each constraint after is a chord, with a constrained edge before as its source, whose
      // middle is within the bound of it: what outputs name the chord by.
      const auto constrained_edge = [](const Cdt_ids& t, const Point& a, const Point& b) {
        const auto vertex = [&t](const Point& p) {
          Cdt_ids::Locate_type lt;
          int li = 0;
          const auto f = t.locate(p, lt, li);
          return lt == Cdt_ids::VERTEX ? f->vertex(li) : Cdt_ids::Vertex_handle();
        };
        const auto u = vertex(a), v = vertex(b);
        Cdt_ids::Face_handle f;
        int i = 0;
        return u != Cdt_ids::Vertex_handle() && v != Cdt_ids::Vertex_handle() &&
               t.is_edge(u, v, f, i) && t.is_constrained({f, i});
      };
      std::size_t constraints = 0, unknown = 0, far = 0;
      for (auto e = after.finite_edges_begin(); e != after.finite_edges_end(); ++e)
        constraints += after.is_constrained(*e) ? 1 : 0;
      for (const auto& c : chords) {
        unknown +=
            !constrained_edge(after, c.a, c.b) || !constrained_edge(before, c.source_a, c.source_b);
        far += CGAL::squared_distance(CGAL::midpoint(c.a, c.b),
                                      K::Segment_2(c.source_a, c.source_b)) > h * h / 16 * 1.0001;
      }
      CHECK(chords.size() == constraints);
      CHECK(unknown == 0);
      CHECK(far == 0);
      // Its description read back (Triangle's rule, hole points) marks the same domain.
      auto poly = CVT_2::IO::domain_poly_data(after);
      const Cdt_ids described = triangulate(poly);
      CHECK(domain_area(described) == Approx(domain_area(after)).epsilon(1e-12));
      CHECK(described.number_of_vertices() == after.number_of_vertices());
      std::size_t differ = 0;
      for (auto f = after.finite_faces_begin(); f != after.finite_faces_end(); ++f)
        differ += in_domain(described, CGAL::centroid(after.triangle(f))) != f->is_inside_domain();
      CHECK(differ == 0);
      // The cells of the resampled domain tile it.
      CVT_2::insert_generators_2(
          after, CVT_2::random_points_in_domain_2(after, 200, CVT_2::parameters::random_seed(3)));
      check_invariants(after, snapshot_marks(after), 100);
    }
}

TEST_CASE(
    "resampling drops a coastline's jags, keeps its corners, islands and the sides of "
    "points in a bay",
    "[resample]") {
  // A square whose bottom edge is a saw of 400 teeth 1e-3 high, a cape on its top edge lower
  // than the deviation bound with a generator in it, a tiny square island with a tinier one in
  // it, a wavy crack, and a pinned vertex on it.
  CVT_2::IO::Poly_data<Point> poly;
  std::vector<Point> outer;
  for (int i = 0; i <= 400; ++i) outer.emplace_back(i / 400.0, (i % 2) * 1e-3);
  outer.insert(outer.end(),
               {Point(1, 1), Point(0.55, 1), Point(0.5, 1.02), Point(0.45, 1), Point(0, 1)});
  add_ring(poly, outer);
  add_ring(poly, {Point(0.3, 0.3), Point(0.301, 0.3), Point(0.301, 0.301), Point(0.3, 0.301)});
  add_ring(poly, {Point(0.3005, 0.3004), Point(0.3006, 0.3005), Point(0.3005, 0.3006)});  // in it
  const std::size_t crack = poly.vertices.size();
  for (int i = 0; i <= 40; ++i)
    poly.vertices.emplace_back(0.6 + i * 0.005, 0.5 + 0.01 * std::sin(i));
  for (std::size_t i = crack; i + 1 < poly.vertices.size(); ++i)
    poly.segments.push_back({i, i + 1});
  poly.vertices.emplace_back(0.5, 1.01);  // a generator in the cape
  Cdt_ids before = triangulate(poly);
  const Point pinned = poly.vertices[crack + 20];
  const double h = 0.1;
  Cdt_ids after = before;
  const auto r = CVT_2::resample_constraints_2(
      after, h, CVT_2::parameters::fixed_points(std::vector<Point>{pinned}));
  check_resampling(before, after, h, h / 4, r);
  const Input_polylines out = input_polylines(after);
  const auto kept = [&](const Point& p) {
    return std::binary_search(out.vertices.begin(), out.vertices.end(), p);
  };
  CHECK(kept(Point(1, 1)));  // corners
  CHECK(kept(Point(0, 1)));
  CHECK(kept(Point(0, 0)));
  CHECK(kept(Point(1, 0)));
  CHECK(kept(pinned));
  CHECK(kept(poly.vertices[crack]));  // the crack's ends
  CHECK(kept(poly.vertices[crack + 40]));
  // The saw keeps about one point a cell size, not its 401 vertices; the islands three each.
  CHECK(r.output_vertices < 60);
  std::size_t island = 0;
  for (const Point& p : out.vertices)
    island += p.x() > 0.29 && p.x() < 0.31 && p.y() > 0.29 && p.y() < 0.31;
  CHECK(island >= 6);
  CHECK(r.max_deviation <= h / 4);
  // Nothing is kept a second time: resampling what was resampled changes nothing.
  Cdt_ids again = after;
  const auto r2 = CVT_2::resample_constraints_2(
      again, h, CVT_2::parameters::fixed_points(std::vector<Point>{pinned}));
  CHECK(r2.output_vertices == r.output_vertices);
}

TEST_CASE("the resampled points are spacing_ratio cell sizes apart, two by default", "[resample]") {
  // A 10 x 1 rectangle whose bottom edge has 1 000 vertices: at h = 0.1, 10 / (s h) chords.
  CVT_2::IO::Poly_data<Point> poly;
  std::vector<Point> outer;
  for (int i = 0; i <= 1000; ++i) outer.emplace_back(i / 100.0, 0);
  outer.insert(outer.end(), {Point(10, 1), Point(0, 1)});
  add_ring(poly, outer);
  const Cdt_ids before = triangulate(poly);
  const double h = 0.1;
  const auto bottom = [](const Cdt_ids& t) {
    std::vector<double> x;
    for (auto v = t.finite_vertices_begin(); v != t.finite_vertices_end(); ++v)
      if (v->point().y() == 0) x.push_back(v->point().x());
    std::sort(x.begin(), x.end());
    return x;
  };
  for (const double s : {0.0, 1.0, 2.0, 3.0}) {  // 0: the default
    INFO("spacing ratio " << s);
    Cdt_ids after = before;
    if (s > 0)
      CVT_2::resample_constraints_2(after, h, CVT_2::parameters::spacing_ratio(s));
    else
      CVT_2::resample_constraints_2(after, h);
    const std::vector<double> x = bottom(after);
    const double spacing = (s > 0 ? s : 2) * h;
    CHECK(double(x.size() - 1) == Approx(10 / spacing).margin(1));
    for (std::size_t i = 0; i + 1 < x.size(); ++i)
      CHECK(x[i + 1] - x[i] == Approx(spacing).epsilon(0.1));
  }
}

TEST_CASE("resampling ends where a chord is its input segment and still meets another line",
          "[resample]") {
  // The world's 5 004 vertices at 14 degrees apart with a bound of 0.88: a chord that the
  // topology pass had reduced to its input segment kept conflicting, and the passes never ended.
  Cdt_ids before;
  CVT_2::IO::read_domain(data_path("world_land_110m.wkt"), before);
  const double h = 14.081024241025908, bound = 0.8800640150641192;
  Cdt_ids after = before;
  const auto r = CVT_2::resample_constraints_2(
      after, h, CVT_2::parameters::spacing_ratio(1.0).deviation_bound(bound));
  check_resampling(before, after, h, bound, r);
  CHECK(r.kept_for_topology > 0);
}

TEST_CASE("a size from a number of cells, and back", "[resample]") {
  Cdt_ids cdt;
  CVT_2::IO::read_domain(data_path("france_mainland.poly"), cdt);
  for (const std::size_t n : {100, 2000, 50000})
    for (const double s : {1.0, 2.0, 3.0}) {
      const double h = CVT_2::cell_size_for_cells_2(cdt, n, s);
      CHECK(CVT_2::cells_for_cell_size_2(cdt, h, s) == Approx(double(n)).epsilon(1e-12));
    }
  // The unit square: A / (sqrt(3)/2 h^2) + 4 (2 - s) / (2 s h) cells; at the default s = 2 the
  // boundary's half cells have an inner cell's area.
  CVT_2::IO::Poly_data<Point> unit;
  add_ring(unit, {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  Cdt_ids square = triangulate(unit);
  const double h = 0.05;
  CHECK(CVT_2::cells_for_cell_size_2(square, h, 1) ==
        Approx(1 / (std::sqrt(3.0) / 2 * h * h) + 2 / h));
  CHECK(CVT_2::cells_for_cell_size_2(square, h) == Approx(1 / (std::sqrt(3.0) / 2 * h * h)));
  CHECK_THROWS_AS(CVT_2::cell_size_for_cells_2(square, 0), CVT_2::Domain_error);
  CHECK_THROWS_AS(CVT_2::cell_size_for_cells_2(square, 10, 0.0), CVT_2::Domain_error);
  CHECK_THROWS_AS(
      CVT_2::resample_constraints_2(square, 0.1, CVT_2::parameters::spacing_ratio(-1.0)),
      CVT_2::Domain_error);
  CHECK_THROWS_AS(CVT_2::resample_constraints_2(square, -1.0), CVT_2::Domain_error);
  CHECK_THROWS_AS(CVT_2::cells_for_cell_size_2(square, 0.0), CVT_2::Domain_error);
  CHECK_THROWS_AS(CVT_2::resample_constraints_2(square, 0.1, CVT_2::parameters::corner_angle(-1.0)),
                  CVT_2::Domain_error);
  // A minimum ring area that would remove the whole domain is an error, the domain unchanged.
  const std::size_t vertices = square.number_of_vertices();
  CHECK_THROWS_WITH(
      CVT_2::resample_constraints_2(square, 0.1, CVT_2::parameters::minimum_ring_area(2.0)),
      Catch::Contains("removes the whole domain"));
  CHECK(square.number_of_vertices() == vertices);
  CHECK(domain_area(square) == Approx(1));
}

TEST_CASE("rings below the minimum area go with what is inside them: islands, lakes, holes",
          "[resample]") {
  // The unit square with a hole (0.04) holding an island (1e-4) with a generator and a lake
  // (1e-6) in it, and a small hole (1e-4) elsewhere.
  CVT_2::IO::Poly_data<Point> poly;
  const auto square = [&](double x, double y, double side) {
    add_ring(poly, {{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}});
  };
  square(0, 0, 1);
  square(0.2, 0.2, 0.2), poly.holes.emplace_back(0.21, 0.21);
  square(0.3, 0.3, 0.01);
  square(0.303, 0.303, 0.001), poly.holes.emplace_back(0.3035, 0.3035);
  square(0.7, 0.7, 0.01), poly.holes.emplace_back(0.705, 0.705);
  poly.vertices.emplace_back(0.305, 0.307);  // a generator on the island
  const Cdt_ids before = triangulate(poly);
  REQUIRE(in_domain(before, Point(0.305, 0.305)));
  for (const double minimum : {0.0, 1e-3}) {
    INFO("minimum ring area " << minimum);
    Cdt_ids after = before;
    const auto r =
        CVT_2::resample_constraints_2(after, 0.05, CVT_2::parameters::minimum_ring_area(minimum));
    const bool drop = minimum > 0;
    CHECK(r.rings_dropped == (drop ? 3u : 0u));
    CHECK(r.generators_dropped == (drop ? 1u : 0u));
    CHECK(r.area_before == Approx(1 - 0.04 + 1e-4 - 1e-6 - 1e-4));
    CHECK(r.area_after == Approx(drop ? 1 - 0.04 : r.area_before));
    CHECK(in_domain(after, Point(0.305, 0.305)) == !drop);  // the island
    CHECK(in_domain(after, Point(0.705, 0.705)) == drop);   // the small hole, filled
    CHECK(!in_domain(after, Point(0.25, 0.25)));            // the big hole stays
    std::size_t in_small_rings = 0;
    for (auto v = after.finite_vertices_begin(); v != after.finite_vertices_end(); ++v) {
      const Point& p = v->point();
      in_small_rings += (p.x() >= 0.3 && p.x() <= 0.31 && p.y() >= 0.3 && p.y() <= 0.31) ||
                        (p.x() >= 0.7 && p.x() <= 0.71 && p.y() >= 0.7 && p.y() <= 0.71);
    }
    // Kept, each ring of the three is a triangle (three points at least, all within the bound).
    CHECK(in_small_rings == (drop ? 0u : 3u + 3u + 3u + 1u));
    check_invariants(after, snapshot_marks(after), 100);
  }
}

// --- vertices that slide along the input ------------------------------------------------------

namespace {

// The constrained vertices of `cdt` whose points differ from all of `points` (sorted).
std::size_t vertices_not_among(const Cdt_ids& cdt, const std::vector<Point>& points) {
  std::size_t n = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    n += cdt.are_there_incident_constraints(v) &&
         !std::binary_search(points.begin(), points.end(), v->point());
  return n;
}

// What sliding promises, after an optimization of `after` (resampled from `before` at size h,
// bound `bound`) with `runs`: every constrained vertex on the input to rounding, the junctions
// and ends where they were, every input vertex within the bound of the new lines, the
// triangulation valid and constrained Delaunay with the sides of each constraint as `marks`
// recorded them (its constrained points and area now), and its diagram the one a rebuild from
// its points and constraints gives, cell by cell.
void check_slid(const Cdt_ids& before, const Cdt_ids& after, double bound,
                const CVT_2::Sliding_runs_2<Cdt_ids>& runs, Domain_marks marks) {
  const Input_polylines in = input_polylines(before), out = input_polylines(after);
  const CGAL::Bbox_2 box = domain_bbox(before);
  const double scale = std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  std::size_t off_input = 0, lost_junctions = 0;
  for (const Point& p : out.vertices) off_input += distance_to(p, in.segments) > 1e-14 * scale;
  for (const Point& p : in.junctions)
    lost_junctions += !std::binary_search(out.vertices.begin(), out.vertices.end(), p);
  double deviation = 0;
  for (const Point& p : in.vertices) deviation = std::max(deviation, distance_to(p, out.segments));
  CHECK(off_input == 0);
  CHECK(lost_junctions == 0);
  CHECK(deviation <= bound * (1 + 1e-12));
  CHECK(runs.max_deviation() <= bound * (1 + 1e-12));
  for (auto& [v, p] : marks.constrained_points) p = v->point();
  marks.area = domain_area(after);
  marks.number_of_vertices = after.number_of_vertices();
  check_invariants(after, marks, 100);
  // A rebuild: the lines as Triangle's description, then the free generators.
  auto poly = CVT_2::IO::domain_poly_data(after);
  Cdt_ids rebuilt = triangulate(poly);
  CHECK(rebuilt.number_of_vertices() == after.number_of_vertices());
  const Bvd_ids bvd(after), fresh(rebuilt);
  std::map<Point, double> area;
  Cell cell;
  for (auto v = after.finite_vertices_begin(); v != after.finite_vertices_end(); ++v) {
    bvd.cell(v, cell);
    area[v->point()] = signed_area(cell);
  }
  std::size_t differ = 0;
  for (auto v = rebuilt.finite_vertices_begin(); v != rebuilt.finite_vertices_end(); ++v) {
    fresh.cell(v, cell);
    differ += std::abs(signed_area(cell) - area[v->point()]) > 1e-12 * scale * scale;
  }
  CHECK(differ == 0);
}

// The unit square, its sides cut into `n` collinear pieces each, with a square hole whose sides
// are too: runs that are straight, so that the domain stays as it is while vertices slide.
Cdt_ids finely_cut_squares(int n) {
  CVT_2::IO::Poly_data<Point> poly;
  const auto ring = [&](double x, double y, double side) {
    std::vector<Point> r;
    const Point corner[] = {{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}};
    for (int c = 0; c < 4; ++c)
      for (int i = 0; i < n; ++i) {
        const Point &a = corner[c], &b = corner[(c + 1) % 4];
        const double t = double(i) / n;
        r.emplace_back(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y()));
      }
    add_ring(poly, r);
  };
  ring(0, 0, 1);
  ring(0.3, 0.4, 0.25);
  poly.holes.emplace_back(0.4, 0.5);
  return triangulate(poly);
}

}  // namespace

TEST_CASE("sliding on straight runs: the energy never rises, the domain stays, a rebuild agrees",
          "[slide]") {
  const Cdt_ids before = finely_cut_squares(64);
  const double h = CVT_2::cell_size_for_cells_2(before, 600);
  for (const bool lbfgs : {false, true}) {
    INFO((lbfgs ? "L-BFGS" : "Lloyd"));
    Cdt_ids after = before;
    CVT_2::Sliding_runs_2<Cdt_ids> runs;
    CVT_2::resample_constraints_2(after, h, CVT_2::parameters::sliding_runs(&runs));
    REQUIRE(runs.number_of_runs() == 8u);  // the sides between the corners
    REQUIRE(runs.number_of_sliding_vertices() > 40u);
    const Domain_marks marks = snapshot_marks(after);
    std::vector<Point> start;
    for (auto v = after.finite_vertices_begin(); v != after.finite_vertices_end(); ++v)
      start.push_back(v->point());
    std::sort(start.begin(), start.end());
    CVT_2::insert_generators_2(
        after, CVT_2::random_points_in_domain_2(after, 500, CVT_2::parameters::random_seed(5)));
    std::vector<double> energies;
    const std::function<bool(const CVT_2::Optimization_result&)> record =
        [&](const CVT_2::Optimization_result& r) {
          energies.push_back(r.energy);
          return true;
        };
    const auto np = CVT_2::parameters::sliding_runs(&runs)
                        .number_of_iterations(60)
                        .move_ratio_bound(0)
                        .callback(record);
    lbfgs ? CVT_2::lbfgs_optimize_2(after, np) : CVT_2::lloyd_optimize_2(after, np);
    REQUIRE(energies.size() > 50);
    std::size_t rises = 0;
    for (std::size_t i = 1; i < energies.size(); ++i)
      rises += energies[i] > energies[i - 1] * (1 + 1e-12);
    CHECK(rises == 0);
    // The vertices slid, the domain did not change.
    CHECK(vertices_not_among(after, start) > runs.number_of_sliding_vertices() / 2);
    CHECK(domain_area(after) == Approx(1 - 0.25 * 0.25).epsilon(1e-12));
    check_slid(before, after, h / 4, runs, marks);
  }
}

TEST_CASE("sliding stops at a chord a point split, and at fixed points", "[slide]") {
  const Cdt_ids before = finely_cut_squares(64);
  const double h = CVT_2::cell_size_for_cells_2(before, 600);
  Cdt_ids after = before;
  CVT_2::Sliding_runs_2<Cdt_ids> runs;
  CVT_2::resample_constraints_2(after, h, CVT_2::parameters::sliding_runs(&runs));
  // The bottom side's vertices, in order: split the chord between the second and the third,
  // and fix the fifth.
  std::vector<Point> bottom;
  for (auto v = after.finite_vertices_begin(); v != after.finite_vertices_end(); ++v)
    if (v->point().y() == 0) bottom.push_back(v->point());
  std::sort(bottom.begin(), bottom.end());
  REQUIRE(bottom.size() > 6);
  const Point split((bottom[1].x() + bottom[2].x()) / 2, 0);
  CVT_2::insert_generators_2(after, std::vector<Point>{split});  // on the chord: splits it
  const Point fixed = bottom[4];
  CVT_2::insert_generators_2(
      after, CVT_2::random_points_in_domain_2(after, 500, CVT_2::parameters::random_seed(7)));
  CVT_2::lloyd_optimize_2(after, CVT_2::parameters::sliding_runs(&runs)
                                     .fixed_points(std::vector<Point>{fixed})
                                     .number_of_iterations(30)
                                     .move_ratio_bound(0));
  std::set<Point> now;
  for (auto v = after.finite_vertices_begin(); v != after.finite_vertices_end(); ++v)
    now.insert(v->point());
  CHECK(now.count(bottom[1]) == 1);  // the ends of the split chord stayed
  CHECK(now.count(bottom[2]) == 1);
  CHECK(now.count(split) == 1);
  CHECK(now.count(fixed) == 1);  // the fixed one too
  CHECK(std::count_if(bottom.begin() + 5, bottom.end(),
                      [&](const Point& p) { return now.count(p) == 0; }) > 0);  // others slid
  CHECK(runs.max_deviation() == 0);                                             // a straight run
}

TEST_CASE("sliding on real coasts and county lines: on the input, within the bound, converged",
          "[slide]") {
  for (const std::string file : {"france_mainland.poly", "us_massachusetts_counties.wkt",
                                 "earcut_dude.poly", "world_land_110m.wkt"}) {
    for (const bool lbfgs : {false, true}) {
      INFO(file << (lbfgs ? " L-BFGS" : " Lloyd"));
      Cdt_ids before;
      CVT_2::IO::read_domain(data_path(file), before);
      const double h = CVT_2::cell_size_for_cells_2(before, 1500);
      Cdt_ids after = before;
      CVT_2::Sliding_runs_2<Cdt_ids> runs;
      CVT_2::resample_constraints_2(after, h, CVT_2::parameters::sliding_runs(&runs));
      const Domain_marks marks = snapshot_marks(after);
      const std::size_t own = after.number_of_vertices();
      CVT_2::insert_generators_2(
          after, CVT_2::random_points_in_domain_2(after, 1500 - std::min<std::size_t>(own, 1000),
                                                  CVT_2::parameters::random_seed(2)));
      const auto np = CVT_2::parameters::sliding_runs(&runs).number_of_iterations(400);
      const auto r =
          lbfgs ? CVT_2::lbfgs_optimize_2(after, np) : CVT_2::lloyd_optimize_2(after, np);
      CHECK(r.stop_reason == CVT_2::CONVERGED);
      check_slid(before, after, h / 4, runs, marks);
    }
  }
}

TEST_CASE("sliding runs: bad runs are refused, relocate finds the vertices again", "[slide]") {
  Cdt_ids cdt = finely_cut_squares(8);
  CVT_2::Sliding_runs_2<Cdt_ids> runs;
  CVT_2::resample_constraints_2(cdt, 0.2, CVT_2::parameters::sliding_runs(&runs));
  REQUIRE(!runs.empty());
  auto v = cdt.finite_vertices_begin();
  const std::vector<Point> line{{0, 0}, {1, 0}};
  CHECK_THROWS_AS(runs.add_run(line, {v, v}, {0, 2}), std::invalid_argument);  // not to the end
  CHECK_THROWS_AS(runs.add_run(line, {v}, {0}), std::invalid_argument);
  Cdt_ids copy = cdt;
  runs.relocate(copy);
  std::size_t found = 0;
  for (auto w = copy.finite_vertices_begin(); w != copy.finite_vertices_end(); ++w)
    found += runs.slider(w) != CVT_2::Sliding_runs_2<Cdt_ids>::none;
  CHECK(found == runs.number_of_sliding_vertices());
  Cdt_ids empty;
  CHECK_THROWS_AS(runs.relocate(empty), std::invalid_argument);
}
