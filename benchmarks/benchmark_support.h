// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// What the benchmarks share: the triangulations (ours and CGAL's optimizer's), the domains and
// their random points, the builds, one energy evaluator for every method, table formatting.
#ifndef CVT_2_BENCHMARKS_BENCHMARK_SUPPORT_H
#define CVT_2_BENCHMARKS_BENCHMARK_SUPPORT_H

#include <CVT_2/Boundary_lipschitz_sizing_2.h>
#include <CVT_2/Cvt_triangulation_2.h>
#include <CVT_2/IO/read_poly.h>
#include <CVT_2/Lloyd_optimizer_2.h>
#include <CVT_2/insert_generators_2.h>
#include <CVT_2/random_points_in_domain_2.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace support {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using Itag = CGAL::No_constraint_intersection_requiring_constructions_tag;
using Vb = CGAL::Triangulation_vertex_base_2<K>;
using CDT = CVT_2::Cvt_triangulation_2<K, Itag>;  // ours
// CGAL's optimizer: sizing info in the vertices, domain and blindness in the faces.
using Tds2 = CGAL::Triangulation_data_structure_2<CGAL::Delaunay_mesh_vertex_base_2<K>,
                                                  CGAL::Delaunay_mesh_face_base_2<K>>;
using CDT2 = CGAL::Constrained_Delaunay_triangulation_2<K, Tds2, Itag>;
using Poly = CVT_2::IO::Poly_data<Point>;
using Clock = std::chrono::steady_clock;

const double nan = std::numeric_limits<double>::quiet_NaN();
const double hexagon = 5.0 / (18.0 * std::sqrt(3.0));  // E N / A² of the hexagonal tiling
const std::string square = "unit_square", massachusetts = "us_massachusetts_counties";

// The machine's load, to print beside figures that depend on it.
inline std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string one, five;
  return in >> one >> five ? one + " (1 min), " + five + " (5 min)" : std::string("unknown");
}

inline double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

struct Domain {
  Poly poly;
  CDT cdt;  // the domain alone, marked: for sampling, locating, sizing and the area
  double area = 0;
};

// The unit square built in code, or a bundled .poly file (CVT_2_DATA_DIR); loaded once.
inline const Domain& domain(const std::string& name) {
  static std::map<std::string, Domain> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  Domain& d = cache[name];
  if (name == square) {
    d.poly.source = name;
    d.poly.vertices = {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)};
    d.poly.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
    d.poly.vertex_lines.assign(4, 0);
    d.poly.segment_lines.assign(4, 0);
  } else {
    d.poly = CVT_2::IO::read_poly<Point>(CVT_2_DATA_DIR "/" + name + ".poly");
  }
  CVT_2::IO::insert_poly(d.cdt, d.poly);
  for (auto f = d.cdt.finite_faces_begin(); f != d.cdt.finite_faces_end(); ++f)
    if (f->is_inside_domain()) d.area += d.cdt.triangle(f).area();
  return d;
}

// The random points of a case (seed 1), uniform or following the density of `np`.
template <class NP = CVT_2::No_named_parameters>
std::vector<Point> initial_points(const Domain& d, std::size_t n,
                                  const NP& np = CVT_2::parameters::default_values()) {
  return CVT_2::random_points_in_domain_2(d.cdt, n, np.random_seed(1));
}

using Sizing = CVT_2::Boundary_lipschitz_sizing_2<K>;
const double lipschitz_k = 0.1;  // as lloyd_adaptive and the Fig. 10 case

// μ(x) = min over boundary edges s of k d(x, s) + length(s), built from the domain alone.
inline const Sizing& sizing(const std::string& name) {
  static std::map<std::string, Sizing> cache;
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, Sizing(domain(name).cdt, lipschitz_k)).first;
  return it->second;
}

// Random points (seed 1) with density 1/μ², about the final spacing of a CVT of density 1/μ⁴
// (as lloyd_adaptive starts).
inline std::vector<Point> adaptive_initial_points(const std::string& name, std::size_t n) {
  const Sizing mu = sizing(name);
  const auto start_density = [mu](const Point& p) { return 1 / (mu(p) * mu(p)); };
  return initial_points(domain(name), n, CVT_2::parameters::density(start_density));
}

// Our CDT of the domain with `points` as generators.
inline void build_ours(CDT& cdt, const Domain& d, const std::vector<Point>& points) {
  CVT_2::IO::insert_poly(cdt, d.poly);
  CVT_2::insert_generators_2(cdt, points);
}

// The same for CGAL's optimizer, its faces marked in or out of our domain by their centroids.
// (CGAL re-marks them after every move from the hole seeds we pass it: the same rule.)
inline void build_cdt2(CDT2& cdt, const Domain& d, const std::vector<Point>& points) {
  std::vector<CDT2::Vertex_handle> vh;
  for (const auto& p : d.poly.vertices) vh.push_back(cdt.insert(p));
  for (const auto& s : d.poly.segments) cdt.insert_constraint(vh[s[0]], vh[s[1]]);
  cdt.insert(points.begin(), points.end());
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
    f->set_in_domain(!cdt.is_infinite(f) &&
                     CVT_2::is_in_domain_2(d.cdt, CGAL::centroid(cdt.triangle(f))));
}

struct Energy {
  double energy = nan;          // raw, by our evaluator at resolution 100
  double normalized = nan;      // E n / A² / (5 / (18 √3)), n = generators with a cell
  double max_move_ratio = nan;  // over the free generators: below 0.01 is the paper's stop
  std::size_t cells = 0;
  std::size_t outside = 0;  // CGAL's free points that left the domain (dropped)
};

// Uniform density, exact quadrature: the energy every method is compared by.
inline Energy measure(CDT& cdt, const Domain& d) {
  CVT_2::Lloyd_optimizer_2<CDT> evaluator(cdt);
  Energy e;
  const auto evaluation = evaluator.evaluate(100);
  e.energy = evaluation.energy;
  e.max_move_ratio = evaluation.max_move_ratio;
  evaluator.diagram().for_each_cell([&e](CDT::Vertex_handle, const auto&) { ++e.cells; });
  e.normalized = e.energy * double(e.cells) / (d.area * d.area) / hexagon;
  return e;
}

// CGAL's result with our evaluator: the constraints and CGAL's free vertices in a fresh CDT.
inline Energy measure(const CDT2& cdt2, const Domain& d) {
  std::vector<Point> points;
  std::size_t outside = 0;
  for (auto v = cdt2.finite_vertices_begin(); v != cdt2.finite_vertices_end(); ++v) {
    if (cdt2.are_there_incident_constraints(v)) continue;
    if (CVT_2::is_in_domain_2(d.cdt, v->point()))
      points.push_back(v->point());
    else
      ++outside;
  }
  CDT cdt;
  build_ours(cdt, d, points);
  Energy e = measure(cdt, d);
  e.outside = outside;
  return e;
}

// `x` printed with `f`, or a dash for a figure that was not measured.
inline std::string fmt(const char* f, double x) {
  if (std::isnan(x)) return "–";
  char b[64];
  std::snprintf(b, sizeof b, f, x);
  return b;
}

}  // namespace support

#endif  // CVT_2_BENCHMARKS_BENCHMARK_SUPPORT_H
