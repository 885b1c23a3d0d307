// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Natural-neighbour coordinates on the bounded Voronoi diagram against references that share
// none of their code: q inserted into a copy of the triangulation and both diagrams built
// (Sibson: the areas each cell loses; Laplace: q's cell's edges, each given to the nearest
// visible generator of its midpoint by brute force), CGAL's coordinates on a Delaunay
// triangulation of the same nodes where no constraint is near, exact visibility.
#include <CVT_2/Constraint_editor_2.h>
#include <CVT_2/natural_neighbor_coordinates_2.h>

#include "support/invariants.h"
#include "support/random_domain.h"
#include "support/support.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/interpolation_functions.h>
#include <CGAL/natural_neighbor_coordinates_2.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iterator>
#include <map>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

using namespace support;

namespace {

using Weights = std::map<Point, double>;  // node -> normalized weight

struct Coordinates {
  bool inside = false;
  double norm = 0;
  Weights weights;
};

Coordinates coordinates(const Bvd& bvd, const Point& q, CVT_2::Natural_neighbor_method m) {
  std::vector<std::pair<Cdt::Vertex_handle, double>> w;
  const auto r = CVT_2::natural_neighbor_coordinates_2(
      bvd, q, std::back_inserter(w), CVT_2::parameters::natural_neighbor_method(m));
  Coordinates c;
  c.inside = r.third;
  c.norm = r.second;
  for (const auto& [v, x] : w) {
    CHECK(x > 0);  // non-negative, and only nodes that get something are written
    CHECK(c.weights.count(v->point()) == 0);
    c.weights[v->point()] = x / r.second;
  }
  return c;
}

// Whether q lies in the closed domain: in a domain face or on the boundary of one.
bool in_closed_domain(const Cdt& cdt, const Point& q) {
  Cdt::Locate_type lt;
  int li;
  const auto f = cdt.locate(q, lt, li);
  if (lt == Cdt::OUTSIDE_CONVEX_HULL || lt == Cdt::OUTSIDE_AFFINE_HULL) return false;
  if (lt == Cdt::FACE) return f->is_inside_domain();
  if (lt == Cdt::EDGE) return f->is_inside_domain() || f->neighbor(li)->is_inside_domain();
  const auto v = f->vertex(li);
  auto g = cdt.incident_faces(v), done = g;
  do
    if (!cdt.is_infinite(g) && g->is_inside_domain()) return true;
  while (++g != done);
  return false;
}

// The vertex at p, if there is one.
bool find_node(const Cdt& cdt, const Point& p, Cdt::Vertex_handle& v) {
  Cdt::Locate_type lt;
  int li;
  const auto f = cdt.locate(p, lt, li);
  if (lt != Cdt::VERTEX) return false;
  v = f->vertex(li);
  return true;
}

// The reference: q inserted into a copy; q's cell, the area each node's cell loses, and the
// length of q's cell's edges by the node across them (none along a constraint).
struct Reference {
  double cell_area = 0;
  Weights lost, edges;
  bool touches_constraint = false;  // q's cell has a point on a constraint (a clip point, or q)
};

Reference reference(const Cdt& cdt, const Point& q) {
  Reference r;
  Cdt after = cdt;
  CVT_2::insert_generators_2(after, std::vector<Point>{q});
  const Bvd before_bvd(cdt), after_bvd(after);
  Weights area_before;
  before_bvd.for_each_cell(
      [&](Cdt::Vertex_handle v, const Cell& c) { area_before[v->point()] = signed_area(c); });
  Cell cell_q;
  after_bvd.for_each_cell([&](Cdt::Vertex_handle v, const Cell& c) {
    if (v->point() == q) {
      cell_q = c;
      r.cell_area = signed_area(c);
    } else {
      r.lost[v->point()] = area_before.at(v->point()) - signed_area(c);
    }
  });
  const Visibility_oracle oracle(after_bvd);
  for (std::size_t k = 0; k < cell_q.size(); ++k) {
    const Point& a = cell_q[k].point;
    const Point& b = cell_q[(k + 1) % cell_q.size()].point;
    r.touches_constraint |= cell_q[k].type != Bvd::Cell_vertex::CIRCUMCENTER;
    if (a == b) continue;
    const Point m = CGAL::midpoint(a, b);
    Cdt::Vertex_handle best;
    double d = HUGE_VAL;
    for (const auto v : oracle.generators)
      if (v->point() != q && CGAL::squared_distance(v->point(), m) < d && oracle.sees(v, m))
        best = v, d = CGAL::squared_distance(v->point(), m);
    // a bisector edge if its midpoint is as far from that generator as from q; else it runs
    // along a constraint (where the others are hidden or farther)
    const double dq = std::sqrt(CGAL::squared_distance(q, m));
    if (best == Cdt::Vertex_handle() || std::abs(std::sqrt(d) - dq) > 1e-9 * std::max(1.0, dq))
      continue;
    r.edges[best->point()] += std::sqrt(CGAL::squared_distance(a, b));
  }
  return r;
}

// Queries of every kind: at random in the domain, on constraints, at nodes, beside nodes.
std::vector<Point> queries(const Cdt& cdt, std::size_t n, unsigned seed) {
  std::vector<Point> q = random_points_in_domain(cdt, n, seed);
  std::mt19937_64 rng(seed);
  std::vector<Cdt::Edge> constrained;
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e)
    if (cdt.is_constrained(*e)) constrained.push_back(*e);
  const std::vector<Point> nodes = vertex_points(cdt);
  for (std::size_t k = 0; k < n / 4 && !constrained.empty(); ++k) {
    const auto s = cdt.segment(constrained[rng() % constrained.size()]);
    q.push_back(k % 2 ? CGAL::midpoint(s.source(), s.target())
                      : s.source() + uniform(rng, 0, 1) * (s.target() - s.source()));
  }
  for (std::size_t k = 0; k < n / 4; ++k) {
    const Point& p = nodes[rng() % nodes.size()];
    const double h = 1e-7 * std::max(1.0, std::abs(p.x()) + std::abs(p.y()));
    q.push_back(k % 2 ? p : Point(p.x() + uniform(rng, -h, h), p.y() + uniform(rng, -h, h)));
  }
  return q;
}

struct Errors {
  double sibson = 0, laplace = 0, norm = 0, linear = 0, linear_on_constraints = 0;
  std::size_t compared = 0, linear_cases = 0, at_nodes = 0, outside = 0;
};

// Both coordinates of q against the reference; the worst errors into e.
void compare(const Bvd& bvd, const Point& q, Errors& e) {
  INFO("q = " << std::setprecision(17) << q.x() << ' ' << q.y());
  const Cdt& cdt = bvd.triangulation();
  const Coordinates s = coordinates(bvd, q, CVT_2::SIBSON);
  const Coordinates l = coordinates(bvd, q, CVT_2::LAPLACE);
  const bool inside = in_closed_domain(cdt, q);
  CHECK(s.inside == inside);
  CHECK(l.inside == inside);
  if (!inside) {
    CHECK(s.weights.empty());
    CHECK(l.weights.empty());
    ++e.outside;
    return;
  }
  double sum = 0;
  for (const auto& [p, w] : s.weights) sum += w;
  CHECK(sum == Approx(1).margin(1e-13));  // partition of unity
  sum = 0;
  for (const auto& [p, w] : l.weights) sum += w;
  CHECK(sum == Approx(1).margin(1e-13));

  Cdt::Vertex_handle node;
  if (find_node(cdt, q, node)) {  // the Kronecker delta
    CHECK(s.weights == Weights{{q, 1.0}});
    CHECK(l.weights == Weights{{q, 1.0}});
    ++e.at_nodes;
    return;
  }
  const Reference r = reference(cdt, q);
  REQUIRE(r.cell_area > 0);
  CHECK(std::abs(s.norm - r.cell_area) <= 1e-9 * r.cell_area);
  e.norm = std::max(e.norm, std::abs(s.norm - r.cell_area) / r.cell_area);
  // Sibson: every node's share, those with none included (exactly zero: not written)
  for (const auto& [p, lost] : r.lost) {
    const auto it = s.weights.find(p);
    const double w = it == s.weights.end() ? 0 : it->second;
    CAPTURE(p, w, lost / r.cell_area);
    CHECK(std::abs(w - lost / r.cell_area) <= 1e-9);
    e.sibson = std::max(e.sibson, std::abs(w - lost / r.cell_area));
  }
  for (const auto& [p, w] : s.weights) CHECK(r.lost.count(p) == 1);
  // Laplace: s_i / h_i, normalized
  double total = 0;
  for (const auto& [p, s_i] : r.edges) total += s_i / std::sqrt(CGAL::squared_distance(p, q));
  for (const auto& [p, w] : l.weights) CHECK(r.edges.count(p) == 1);
  for (const auto& [p, s_i] : r.edges) {
    const auto it = l.weights.find(p);
    const double w = it == l.weights.end() ? 0 : it->second;
    const double expected = s_i / std::sqrt(CGAL::squared_distance(p, q)) / total;
    CAPTURE(p, w, expected);
    CHECK(std::abs(w - expected) <= 1e-9);
    e.laplace = std::max(e.laplace, std::abs(w - expected));
  }
  // a node with a weight sees q: no constraint but those through q or the node crosses the
  // segment between them (exactly: the kernel's predicates)
  const Visibility_oracle oracle(bvd);
  for (const auto& c : {s, l})
    for (const auto& [p, w] : c.weights) {
      const Segment pq(p, q);
      for (const auto& [constraint, ends] : oracle.constraints)
        if (ends.first->point() != p && ends.second->point() != p && !constraint.has_on(q))
          CHECK(!CGAL::do_intersect(pq, constraint));
    }
  // linear precision: promised where q's cell has no point on a constraint, measured elsewhere
  for (const auto& c : {s, l}) {
    double x = 0, y = 0;
    for (const auto& [p, w] : c.weights) x += w * (p.x() - q.x()), y += w * (p.y() - q.y());
    const double error = std::hypot(x, y);
    if (r.touches_constraint) {
      e.linear_on_constraints = std::max(e.linear_on_constraints, error);
    } else {
      e.linear = std::max(e.linear, error);
      ++e.linear_cases;
    }
  }
  ++e.compared;
}

void check_errors(const Errors& e, double scale) {
  INFO("compared " << e.compared << ", at nodes " << e.at_nodes << ", outside " << e.outside);
  CHECK(e.sibson <= 1e-9);
  CHECK(e.laplace <= 1e-9);
  CHECK(e.norm <= 1e-9);
  CHECK(e.linear <= 1e-12 * scale);
  // measured, not promised: near a constraint, q's cell is clipped and x = sum phi_i x_i fails
  WARN("linear precision: " << e.linear << " over " << e.linear_cases
                            << " cells off the constraints, " << e.linear_on_constraints
                            << " at worst on cells with a point on a constraint (scale " << scale
                            << ")");
}

}  // namespace

TEST_CASE(
    "Sibson and Laplace coordinates equal the areas and edges of q inserted, on random "
    "domains",
    "[natural_neighbors]") {
  Errors e;
  const unsigned cases = random_cases(12, 0.1);
  for (unsigned seed = 1; seed <= cases; ++seed) {
    CAPTURE(seed);
    const Cdt cdt = random_triangulation(seed, 60);
    const Bvd bvd(cdt);
    for (const Point& q : queries(cdt, 24, seed)) compare(bvd, q, e);
    // outside: beyond the bounding box, and in a hole or notch if the grid finds one
    compare(bvd, Point(-1, -1), e);
    for (double x = 0.0625; x < 10; x += 1.25)
      for (double y = 0.0625; y < 10; y += 1.25)
        if (!in_closed_domain(cdt, Point(x, y))) compare(bvd, Point(x, y), e);
  }
  CHECK(e.compared > 100 * cases / 12);
  CHECK(e.at_nodes > 0);
  CHECK(e.outside > 0);
  check_errors(e, 10);
}

TEST_CASE("natural-neighbour coordinates on the bundled domains: county borders, holes, slits",
          "[natural_neighbors]") {
  for (const auto& [file, n] :
       std::vector<std::pair<std::string, std::size_t>>{{"us_massachusetts_counties.poly", 800},
                                                        {"square_inner_constraints.poly", 200},
                                                        {"bubble_with_hole.poly", 200},
                                                        {"four_clusters.poly", 200}}) {
    INFO(file);
    Domain d;
    load_domain(d, file);
    insert_random_points(d, n, 7);
    const Bvd bvd(d.cdt);
    Errors e;
    for (const Point& q : queries(d.cdt, 40, 11)) compare(bvd, q, e);
    const CGAL::Bbox_2 b = domain_bbox(d.cdt);
    check_errors(e, std::max({std::abs(b.xmin()), std::abs(b.xmax()), std::abs(b.ymin()),
                              std::abs(b.ymax()), 1.0}));
  }
}

TEST_CASE("away from constraints, the coordinates are CGAL's on a Delaunay triangulation",
          "[natural_neighbors]") {
  using Dt = CGAL::Delaunay_triangulation_2<K>;
  for (const auto& [file, n] : std::vector<std::pair<std::string, std::size_t>>{
           {"", 2000}, {"us_massachusetts_counties.poly", 3000}}) {
    INFO(file);
    Domain d;
    // (Massachusetts moved to the origin: where it is, at x = -53, the two agree to 1.3e-12,
    // both building circumcenters of triangles 0.02 wide from coordinates near 50)
    file.empty() ? load_square(d) : load_domain(d, file, 1, 53, -42);
    insert_random_points(d, n, 3);
    const Bvd bvd(d.cdt);
    const std::vector<Point> nodes = vertex_points(d.cdt);
    const Dt dt(nodes.begin(), nodes.end());
    std::vector<Segment> constraints;
    for (auto e = d.cdt.finite_edges_begin(); e != d.cdt.finite_edges_end(); ++e)
      if (d.cdt.is_constrained(*e)) constraints.push_back(d.cdt.segment(*e));
    const double spacing = std::sqrt(domain_area(d.cdt) / double(n));
    std::size_t compared = 0;
    double worst = 0;
    for (const Point& q : random_points_in_domain(d.cdt, 1000, 5)) {
      std::vector<std::pair<Point, double>> cgal;
      const auto r = CGAL::natural_neighbor_coordinates_2(dt, q, std::back_inserter(cgal));
      REQUIRE(r.third);
      // no constraint within reach of q's cell: none nearer than twice the farthest neighbour
      double reach = 0, nearest = HUGE_VAL;
      for (const auto& [p, w] : cgal) reach = std::max(reach, CGAL::squared_distance(p, q));
      for (const Segment& s : constraints)
        nearest = std::min(nearest, CGAL::squared_distance(s, q));
      if (nearest <= 4 * reach || nearest < 9 * spacing * spacing) continue;
      const Coordinates ours = coordinates(bvd, q, CVT_2::SIBSON);
      Weights theirs;
      for (const auto& [p, w] : cgal) theirs[p] = w / r.second;
      CHECK(ours.weights.size() == theirs.size());
      for (const auto& [p, w] : theirs) {
        const auto it = ours.weights.find(p);
        REQUIRE(it != ours.weights.end());
        worst = std::max(worst, std::abs(it->second - w));
      }
      ++compared;
    }
    CHECK(compared > 100);
    INFO("worst " << std::setprecision(3) << worst << " over " << compared);
    CHECK(worst <= 1e-12);
  }
}

namespace {

// Algorithm 1 twice: q's virtual star, tagged face by face by a walk along each way to the
// circumcenter (Virtual_insertion, with its floating-point filters), against the faces around q
// inserted into a copy, tagged from each constraint by the diagram (tag_blind_faces).
struct Tag_count {
  std::size_t faces = 0, blind = 0, ties = 0;
};

void compare_star_tags(const Cdt& cdt, const std::vector<Point>& queries, Tag_count& count) {
  using Insertion = CVT_2::internal::Virtual_insertion<Bvd>;
  const Bvd bvd(cdt);
  Insertion insertion(bvd);
  const CVT_2::Bvd_traits_2<K> traits;
  const auto blinded = traits.is_blinded_2_object();
  const auto compare = traits.compare_blinding_distance_2_object();
  for (const Point& q : queries) {
    INFO("q = " << std::setprecision(17) << q.x() << ' ' << q.y());
    Cdt::Face_handle hint;
    if (insertion.insert(q, hint) != Insertion::INSIDE) continue;
    Cdt after = cdt;
    CVT_2::insert_generators_2(after, std::vector<Point>{q});
    const Bvd tagged(after);
    Cdt::Vertex_handle vq;
    REQUIRE(find_node(after, q, vq));
    std::map<std::pair<Point, Point>, Cdt::Face_handle> around;  // by their other two points
    auto f = after.incident_faces(vq), done = f;
    do {
      const int i = f->index(vq);
      around[{f->vertex(Cdt::ccw(i))->point(), f->vertex(Cdt::cw(i))->point()}] = f;
    } while (++f != done);
    for (const auto& s : insertion.star()) {
      const Point &ps = insertion.point(s.s), &pt = insertion.point(s.t);
      CAPTURE(ps, pt);
      const auto it = around.find({ps, pt});
      REQUIRE(it != around.end());  // the same star
      const Cdt::Face_handle g = it->second;
      CHECK(s.blind == g->is_blinded());
      ++count.faces;
      if (!s.blind || !g->is_blinded()) continue;
      ++count.blind;
      // The same constraint, or another one the way meets at the same point (through a vertex
      // where both end).
      const Point a1 = insertion.point(s.blinding.a), b1 = insertion.point(s.blinding.b);
      const auto e = g->blinding_edge();
      const Point a2 = e.first->vertex(Cdt::ccw(e.second))->point();
      const Point b2 = e.first->vertex(Cdt::cw(e.second))->point();
      CHECK(blinded(q, ps, pt, a1, b1));
      CHECK(compare(q, ps, pt, a1, b1, a2, b2) == CGAL::EQUAL);
      count.ties += !((a1 == a2 && b1 == b2) || (a1 == b2 && b1 == a2));
    }
  }
}

// p -> p 2^exponent, exactly.
Point scaled(const Point& p, int exponent) {
  return Point(std::ldexp(p.x(), exponent), std::ldexp(p.y(), exponent));
}

}  // namespace

TEST_CASE("the virtual star is tagged as Algorithm 1 tags q inserted at any scale",
          "[natural_neighbors]") {
  // 2^-1000 and 2^990: coordinates near 1e-300 and 1e300, where the filters' products leave
  // the normal range; the same domains, exactly scaled.
  const int exponent = GENERATE(0, -1000, 990);
  CAPTURE(exponent);
  Tag_count count;
  const unsigned cases = random_cases(12, 0.1);
  for (unsigned seed = 1; seed <= cases; ++seed) {
    CAPTURE(seed);
    std::vector<Point> generators;
    auto poly = random_domain(seed, generators, 60);
    transform(poly, std::ldexp(1.0, exponent), 0, 0);
    Cdt cdt = triangulate(poly);
    for (Point& p : generators) p = scaled(p, exponent);
    CVT_2::insert_generators_2(cdt, generators);
    compare_star_tags(cdt, queries(cdt, 40, seed), count);
  }
  // A grid of nodes, cocircular by fours, with constraints along a diagonal and a grid line:
  // queries at the centers of the squares (on four nodes' circle), on the grid lines, on the
  // constraints, and a unit in the last place from nodes.
  CVT_2::IO::Poly_data<Point> poly;
  add_ring(poly, {Point(0, 0), Point(8, 0), Point(8, 8), Point(0, 8)});
  poly.vertices.insert(poly.vertices.end(), {Point(2, 2), Point(6, 6), Point(1, 5), Point(4, 5)});
  poly.segments.push_back({4, 5});
  poly.segments.push_back({6, 7});
  transform(poly, std::ldexp(1.0, exponent), 0, 0);
  Cdt grid = triangulate(poly);
  std::vector<Point> nodes, q;
  for (int x = 1; x < 8; ++x)
    for (int y = 1; y < 8; ++y) {
      nodes.push_back(scaled(Point(x, y), exponent));
      const Point& n = nodes.back();
      q.push_back(scaled(Point(x + 0.5, y + 0.5), exponent));
      q.push_back(scaled(Point(x + 0.5, y), exponent));
      q.push_back(Point(std::nextafter(n.x(), HUGE_VAL), n.y()));
      q.push_back(Point(n.x(), std::nextafter(n.y(), -HUGE_VAL)));
    }
  CVT_2::insert_generators_2(grid, nodes);
  for (const double t : {2.25, 3.5, 5.75})
    q.push_back(scaled(Point(t, t), exponent)), q.push_back(scaled(Point(t - 1, 5), exponent));
  compare_star_tags(grid, q, count);
  // A mirror image about x = 4: nodes in mirror pairs (cocircular by fours) and on the axis,
  // constraints that end on the axis (two at one node) or run along it, queries on the axis. A
  // star face on a mirror pair is isosceles: its way runs along the axis, through the nodes
  // there, exactly.
  CVT_2::IO::Poly_data<Point> mirror;
  add_ring(mirror, {Point(0, 0), Point(8, 0), Point(8, 8), Point(0, 8)});
  mirror.vertices.insert(mirror.vertices.end(),
                         {Point(4, 2.5), Point(6, 3), Point(2, 3), Point(4, 5.5), Point(5.5, 7),
                          Point(4, 6.5), Point(4, 7.5)});
  for (const std::size_t end : {5, 6}) mirror.segments.push_back({4, end});
  mirror.segments.push_back({7, 8});
  mirror.segments.push_back({9, 10});
  transform(mirror, std::ldexp(1.0, exponent), 0, 0);
  Cdt symmetric = triangulate(mirror);
  std::mt19937_64 rng(5);
  const auto grid64 = [&rng](int lo, int hi) { return support::uniform_int(rng, lo, hi) / 64.0; };
  nodes.clear(), q.clear();
  for (int k = 0; k < 40; ++k) {
    const double x = grid64(16, 255), y = grid64(16, 496);
    nodes.push_back(scaled(Point(x, y), exponent));
    nodes.push_back(scaled(Point(8 - x, y), exponent));
  }
  for (const double y : {1.0, 4.0, 5.0, 7.0}) nodes.push_back(scaled(Point(4, y), exponent));
  CVT_2::insert_generators_2(symmetric, nodes);
  for (int k = 0; k < 60; ++k) q.push_back(scaled(Point(4, grid64(8, 504) + 1 / 128.0), exponent));
  compare_star_tags(symmetric, q, count);
  INFO("star faces " << count.faces << ", blind " << count.blind << ", ties " << count.ties);
  CHECK(count.blind > count.faces / 20);
}

TEST_CASE("CGAL's interpolation functions take the output as it is", "[natural_neighbors]") {
  Domain d;
  load_square(d);
  insert_random_points(d, 300, 1);
  const Bvd bvd(d.cdt);
  std::map<Cdt::Vertex_handle, double> f;  // a linear field at the nodes
  for (auto v = d.cdt.finite_vertices_begin(); v != d.cdt.finite_vertices_end(); ++v)
    f[v] = 2 * v->point().x() - 3 * v->point().y() + 1;
  const Point q(0.4321, 0.5678);
  std::vector<std::pair<Cdt::Vertex_handle, double>> w;
  const auto r = CVT_2::natural_neighbor_coordinates_2(bvd, q, std::back_inserter(w));
  REQUIRE(r.third);
  const double value = CGAL::linear_interpolation(
      w.begin(), w.end(), r.second, CGAL::Data_access<std::map<Cdt::Vertex_handle, double>>(f));
  CHECK(value == Approx(2 * q.x() - 3 * q.y() + 1).margin(1e-12));
}

TEST_CASE("the coordinates are continuous off the constraints and at the nodes",
          "[natural_neighbors]") {
  Domain d;
  load_domain(d, "square_inner_constraints.poly");
  insert_random_points(d, 400, 2);
  const Bvd bvd(d.cdt);
  const double spacing = std::sqrt(domain_area(d.cdt) / 400.0);
  std::mt19937_64 rng(9);
  double worst = 0;  // the largest change of a coordinate over the step, in steps per spacing
  for (const Point& q : random_points_in_domain(d.cdt, 200, 4)) {
    const double step = 1e-6 * spacing, angle = uniform(rng, 0, 6.283185307179586);
    const Point r(q.x() + step * std::cos(angle), q.y() + step * std::sin(angle));
    if (!in_closed_domain(d.cdt, r)) continue;
    for (const auto method : {CVT_2::SIBSON, CVT_2::LAPLACE}) {
      Weights a = coordinates(bvd, q, method).weights, b = coordinates(bvd, r, method).weights;
      for (const auto& [p, w] : b) a.emplace(p, 0.0);  // nodes in b alone: 0 in a
      for (const auto& [p, w] : a) {
        const auto it = b.find(p);
        worst = std::max(worst, std::abs(w - (it == b.end() ? 0 : it->second)) / 1e-6);
      }
    }
  }
  CHECK(worst < 100);  // O(step / spacing): a wrong share would jump by O(1)
  // approaching a node, its coordinate goes to 1
  const auto v = d.cdt.finite_vertices_begin();
  for (auto g = d.cdt.incident_faces(v), done = g;;) {
    if (!d.cdt.is_infinite(g) && g->is_inside_domain()) {
      const Point c = CGAL::centroid(d.cdt.triangle(g));
      for (const double t : {1e-3, 1e-6, 1e-9}) {
        const Point q = v->point() + t * (c - v->point());
        const auto w = coordinates(bvd, q, CVT_2::SIBSON).weights;
        CHECK(w.at(v->point()) > 1 - 1e3 * t);
      }
      break;
    }
    if (++g == done) FAIL("no domain face at a vertex");
  }
}

TEST_CASE("a crack: no weight leaks across it, and a jump is interpolated exactly on each side",
          "[natural_neighbors]") {
  using Dt = CGAL::Delaunay_triangulation_2<K>;
  Domain d;  // the unit square with a crack of two segments inside, (0.2, 0.5) to (0.8, 0.5)
  add_ring(d.poly, {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)});
  d.poly.vertices.insert(d.poly.vertices.end(),
                         {Point(0.2, 0.5), Point(0.5, 0.5), Point(0.8, 0.5)});
  d.poly.segments.push_back({4, 5});
  d.poly.segments.push_back({5, 6});
  d.cdt = triangulate(d.poly);
  std::vector<Point> points;
  for (const Point& p : random_points_in_domain(d.cdt, 600, 8))
    if (p.y() != 0.5) points.push_back(p);
  CVT_2::insert_generators_2(d.cdt, points);
  const Bvd bvd(d.cdt);
  const std::vector<Point> nodes = vertex_points(d.cdt);
  const Dt dt(nodes.begin(), nodes.end());
  const auto side = [](const Point& p) { return p.y() > 0.5 ? 1 : p.y() < 0.5 ? -1 : 0; };
  std::size_t cgal_leaks = 0, exact = 0;
  std::mt19937_64 rng(3);
  for (int k = 0; k < 400; ++k) {
    const Point q(uniform(rng, 0.25, 0.75), 0.5 + (k % 2 ? 1 : -1) * uniform(rng, 1e-9, 0.05));
    for (const auto method : {CVT_2::SIBSON, CVT_2::LAPLACE}) {
      const Weights w = coordinates(bvd, q, method).weights;
      double value = 0;
      bool crack_node = false;
      for (const auto& [p, x] : w) {
        CHECK(side(p) != -side(q));  // nothing from across the crack
        crack_node |= side(p) == 0;
        value += x * (side(p) > 0 ? 1 : 0);
      }
      if (!crack_node) {  // the field's value on q's side, to rounding
        CHECK(value == Approx(side(q) > 0 ? 1 : 0).margin(1e-14));
        ++exact;
      }
    }
    std::vector<std::pair<Point, double>> cgal;
    CGAL::natural_neighbor_coordinates_2(dt, q, std::back_inserter(cgal));
    for (const auto& [p, x] : cgal) cgal_leaks += side(p) == -side(q) && x > 0;
  }
  CHECK(exact > 400);
  CHECK(cgal_leaks > 100);  // the unconstrained coordinates do leak: the test can tell
}

TEST_CASE("lips: a node along a crack has a column for each side, and a jump is exact up to it",
          "[natural_neighbors][lips]") {
  Domain d;  // the unit square with a crack from (0.2, 0.5) to (0.8, 0.5), a node every 0.1
  add_ring(d.poly, {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)});
  for (int i = 2; i <= 8; ++i) {
    d.poly.vertices.emplace_back(0.1 * i, 0.5);
    if (i > 2) d.poly.segments.push_back({d.poly.vertices.size() - 2, d.poly.vertices.size() - 1});
  }
  d.cdt = triangulate(d.poly);
  std::vector<Point> points;
  for (const Point& p : random_points_in_domain(d.cdt, 800, 9))
    if (p.y() != 0.5) points.push_back(p);
  CVT_2::insert_generators_2(d.cdt, points);
  const Bvd bvd(d.cdt);
  std::vector<Point> q;
  std::mt19937_64 rng(5);
  for (int k = 0; k < 3000; ++k)
    q.emplace_back(uniform(rng, 0.25, 0.75), 0.5 + (k % 2 ? 1 : -1) * uniform(rng, 1e-12, 0.1));
  q.emplace_back(0.5, 0.5);  // at a node on the crack
  for (const auto method : {CVT_2::SIBSON, CVT_2::LAPLACE}) {
    const auto np = CVT_2::parameters::natural_neighbor_method(method);
    const auto plain = CVT_2::natural_neighbor_matrix_2(bvd, q, np);
    const auto m = CVT_2::natural_neighbor_matrix_2(bvd, q, np.lips(true));
    const std::size_t n = m.nodes.size();
    REQUIRE(m.nodes == plain.nodes);
    REQUIRE(m.lip_nodes.size() == 10);  // the 5 nodes inside the crack, 2 lips each; tips have 1
    // the field: 1 above the crack, 0 below; on a lip node, 1 on the lip that sees up
    const auto side = [](const Point& p) { return p.y() > 0.5 ? 1 : p.y() < 0.5 ? -1 : 0; };
    std::vector<double> u(n + m.lip_nodes.size(), 0);
    std::vector<bool> lip_node(n, false), tip(n, false);
    for (std::size_t j = 0; j < n; ++j) {
      u[j] = side(m.nodes[j]->point()) > 0 ? 1 : 0;
      tip[j] = side(m.nodes[j]->point()) == 0;
    }
    for (std::size_t k = 0; k < m.lip_nodes.size(); ++k) {
      const std::size_t j = m.lip_nodes[k];
      CHECK(side(m.nodes[j]->point()) == 0);
      lip_node[j] = true;
      tip[j] = false;
      const std::size_t first = k == 0 || m.lip_nodes[k - 1] != j ? k : k - 1;
      const auto up = m.nodes[j]->point() + K::Vector_2(0, 0.01);
      u[n + k] = int(k - first) == CVT_2::internal::lip_toward(d.cdt, m.nodes[j], up) ? 1 : 0;
    }
    // the lips are numbered by the geometry alone, not by which face a vertex points to
    for (std::size_t k = 0; k < m.lip_nodes.size(); ++k) {
      const auto v = m.nodes[m.lip_nodes[k]];
      const auto up = v->point() + K::Vector_2(0, 0.01);
      const int lip = CVT_2::node_lip_2(bvd, v, up);
      const auto kept = v->face();
      auto fc = d.cdt.incident_faces(v), done = fc;
      do {
        v->set_face(fc);
        CHECK(CVT_2::node_lip_2(bvd, v, up) == lip);
      } while (++fc != done);
      v->set_face(kept);
    }
    std::size_t exact = 0, through_lips = 0;
    for (std::size_t r = 0; r < q.size(); ++r) {
      CAPTURE(q[r]);
      double sum = 0, value = 0;
      bool near_tip = false, uses_lips = false;
      std::map<std::size_t, double> folded;
      for (std::size_t e = m.row_offsets[r]; e < m.row_offsets[r + 1]; ++e) {
        const std::size_t c = m.columns[e];
        const std::size_t j = c < n ? c : m.lip_nodes[c - n];
        CHECK(!(c < n && lip_node[j]));  // a lip node's own column stays empty
        near_tip |= tip[j];
        uses_lips |= c >= n;
        folded[j] += m.values[e];
        sum += m.values[e];
        value += m.values[e] * u[c];
      }
      // folding the lips back gives the row without them, bit for bit
      std::map<std::size_t, double> row;
      for (std::size_t e = plain.row_offsets[r]; e < plain.row_offsets[r + 1]; ++e)
        row[plain.columns[e]] = plain.values[e];
      CHECK(folded == row);
      CHECK(sum == Approx(1).margin(1e-14));
      if (near_tip || side(q[r]) == 0) continue;
      CHECK(value == Approx(side(q[r]) > 0 ? 1 : 0).margin(1e-14));
      ++exact;
      through_lips += uses_lips;
    }
    CHECK(exact > 1500);
    CHECK(through_lips > 300);
  }
}

TEST_CASE(
    "the matrix of many queries: the single queries' rows, the same bits on any number "
    "of threads",
    "[natural_neighbors]") {
  Domain d;
  load_domain(d, "us_massachusetts_counties.poly");
  insert_random_points(d, 2000, 4);
  const Bvd bvd(d.cdt);
  std::vector<Point> q = queries(d.cdt, 3000, 6);
  q.push_back(Point(-1e9, 0));  // outside
  // The diagram is not the matrix's to write: numbers in the vertices' ids (a mesh's, the
  // user's) stay.
  const auto mark_ids = [&d](bool check) {
    int k = 0;
    bool kept = true;
    for (auto v = d.cdt.finite_vertices_begin(); v != d.cdt.finite_vertices_end(); ++v, ++k)
      check ? kept = kept && v->id() == 7 * k + 3 : v->id() = 7 * k + 3;
    return kept;
  };
  mark_ids(false);
  for (const auto method : {CVT_2::SIBSON, CVT_2::LAPLACE}) {
    const auto np = CVT_2::parameters::natural_neighbor_method(method);
    const auto m1 = CVT_2::natural_neighbor_matrix_2(bvd, q, np.number_of_threads(1));
    CHECK(mark_ids(true));
    for (const unsigned threads : {2u, 3u}) {
      const auto m = CVT_2::natural_neighbor_matrix_2(bvd, q, np.number_of_threads(threads));
      CHECK(m.nodes == m1.nodes);
      CHECK(m.row_offsets == m1.row_offsets);
      CHECK(m.columns == m1.columns);
      CHECK(m.values == m1.values);
      CHECK(m.inside == m1.inside);
    }
    REQUIRE(m1.row_offsets.size() == q.size() + 1);
    CHECK(m1.inside.back() == 0);
    CHECK(m1.row_offsets[q.size()] == m1.row_offsets[q.size() - 1]);
    std::size_t nodes_with_cells = 0;
    for (auto v = d.cdt.finite_vertices_begin(); v != d.cdt.finite_vertices_end(); ++v)
      nodes_with_cells += bvd.has_cell(v);
    CHECK(m1.nodes.size() == nodes_with_cells);
    for (std::size_t k = 0; k < q.size(); k += 7) {
      const Coordinates c = coordinates(bvd, q[k], method);
      CHECK(bool(m1.inside[k]) == c.inside);
      Weights row;
      for (std::size_t e = m1.row_offsets[k]; e < m1.row_offsets[k + 1]; ++e) {
        if (e > m1.row_offsets[k]) CHECK(m1.columns[e - 1] < m1.columns[e]);
        row[m1.nodes[m1.columns[e]]->point()] = m1.values[e];
      }
      REQUIRE(row.size() == c.weights.size());
      for (const auto& [p, w] : c.weights) CHECK(row.at(p) == Approx(w).margin(1e-15));
    }
  }
}

TEST_CASE("a hint, a query that is not a number, a query outside", "[natural_neighbors]") {
  Domain d;
  load_domain(d, "four_clusters.poly");
  insert_random_points(d, 300, 1);
  const Bvd bvd(d.cdt);
  const Point q = random_points_in_domain(d.cdt, 1, 2)[0];
  std::vector<std::pair<Cdt::Vertex_handle, double>> w1, w2;
  CVT_2::natural_neighbor_coordinates_2(bvd, q, std::back_inserter(w1));
  auto far = d.cdt.finite_faces_begin();
  for (auto f = d.cdt.finite_faces_begin(); f != d.cdt.finite_faces_end(); ++f)
    if (CGAL::squared_distance(d.cdt.triangle(f).vertex(0), q) >
        CGAL::squared_distance(d.cdt.triangle(far).vertex(0), q))
      far = f;
  CVT_2::natural_neighbor_coordinates_2(bvd, q, std::back_inserter(w2),
                                        CVT_2::parameters::hint(Cdt::Face_handle(far)));
  std::sort(w1.begin(), w1.end());
  std::sort(w2.begin(), w2.end());
  CHECK(w1 == w2);

  // A query on an edge is located in either face beside it, by the hint: the weights were
  // summed around it from there, a last bit apart (29 of 1 247 midpoints of edges on the
  // square with inner constraints, 400 nodes). Now the same bits from either side.
  Domain e;
  load_domain(e, "square_inner_constraints.poly");
  insert_random_points(e, 400, 3);
  const Bvd bvd_e(e.cdt);
  std::size_t on_edges = 0, differ = 0;
  for (auto edge = e.cdt.finite_edges_begin(); edge != e.cdt.finite_edges_end(); ++edge) {
    const auto [f, i] = *edge;
    const Point a = f->vertex(Cdt::ccw(i))->point(), b = f->vertex(Cdt::cw(i))->point();
    const Point m = CGAL::midpoint(a, b);
    if (!CGAL::collinear(a, b, m) || e.cdt.is_infinite(f->neighbor(i))) continue;
    ++on_edges;
    for (const auto method : {CVT_2::SIBSON, CVT_2::LAPLACE}) {
      std::vector<std::pair<Cdt::Vertex_handle, double>> from_f, from_g;
      const auto rf = CVT_2::natural_neighbor_coordinates_2(
          bvd_e, m, std::back_inserter(from_f),
          CVT_2::parameters::hint(f).natural_neighbor_method(method));
      const auto rg = CVT_2::natural_neighbor_coordinates_2(
          bvd_e, m, std::back_inserter(from_g),
          CVT_2::parameters::hint(f->neighbor(i)).natural_neighbor_method(method));
      std::sort(from_f.begin(), from_f.end());
      std::sort(from_g.begin(), from_g.end());
      differ += from_f != from_g || rf.second != rg.second;
    }
  }
  CHECK(on_edges > 300);
  CHECK(differ == 0);

  std::vector<std::pair<Cdt::Vertex_handle, double>> w;
  CHECK_THROWS_WITH(
      CVT_2::natural_neighbor_coordinates_2(bvd, Point(std::nan(""), 0), std::back_inserter(w)),
      Catch::Contains("query") && Catch::Contains("nan"));
  CHECK_THROWS_AS(CVT_2::natural_neighbor_matrix_2(bvd, std::vector<Point>{q, Point(HUGE_VAL, 0)}),
                  std::invalid_argument);
  const auto r = CVT_2::natural_neighbor_coordinates_2(bvd, Point(1e6, 1e6), std::back_inserter(w));
  CHECK(!r.third);
  CHECK(r.second == 0);
  CHECK(w.empty());
}

// Beside CGAL's own natural_neighbor_coordinates_2() (included above, found by argument-dependent
// lookup on CGAL's points), the editor calls ours: a crack's new vertex carries the Sibson
// coordinates the diagram gave its point before the edit.
TEST_CASE("Constraint_editor_2 carries the Sibson coordinates of the diagram before the edit",
          "[natural_neighbors][edit]") {
  Domain d;
  load_domain(d, "four_clusters.poly");
  insert_random_points(d, 300, 3);
  Bvd bvd(d.cdt);
  CVT_2::Constraint_editor_2<Cdt> editor(d.cdt, bvd);
  editor.carry_weights(true);
  const std::vector<Point> crack = random_points_in_domain(d.cdt, 2, 5);
  std::vector<Weights> before;
  for (const Point& p : crack)
    before.push_back(coordinates(bvd, p, CVT_2::Natural_neighbor_method::SIBSON).weights);
  editor.insert_constraint(crack);
  const auto& report = editor.report();
  REQUIRE(report.new_vertices.size() == 2);
  REQUIRE(report.carried_weights.size() == 2);
  for (std::size_t k = 0; k < 2; ++k) {
    const std::size_t i = report.new_vertices[k]->point() == crack[0] ? 0 : 1;
    REQUIRE(report.carried_weights[k].size() == before[i].size());
    for (const auto& [v, w] : report.carried_weights[k]) {
      REQUIRE(before[i].count(v->point()) == 1);
      CHECK(std::abs(w - before[i].at(v->point())) < 1e-12);
    }
  }
}
