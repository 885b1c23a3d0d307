// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// crack_interpolation [OUT.txt] [N] [GRID]: a field with a jump across a crack, interpolated
// from N nodes with Sibson's coordinates on the bounded Voronoi diagram (the constrained
// natural element method) and, for comparison, with CGAL's on a Delaunay triangulation of the
// same nodes, which does not know the crack. The domain is the unit square; the crack runs from
// its left side to its middle. The field is the crack-opening displacement of fracture
// mechanics, sqrt(r) sin(theta / 2) around the crack tip: continuous, but for a jump of
// 2 sqrt(r) across the crack. Writes GRID x GRID samples, one line each: `x y exact ours cgal`
// (scripts/plot_crack_interpolation.py draws them), and prints the largest errors.
#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/Cvt_triangulation_2.h>
#include <CVT_2/IO/read_poly.h>
#include <CVT_2/insert_generators_2.h>
#include <CVT_2/lloyd_optimize_2.h>
#include <CVT_2/natural_neighbor_coordinates_2.h>
#include <CVT_2/random_points_in_domain_2.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/interpolation_functions.h>
#include <CGAL/natural_neighbor_coordinates_2.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <utility>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using CDT = CVT_2::Cvt_triangulation_2<K>;
using BVD = CVT_2::Bounded_voronoi_diagram_2<CDT>;
using DT = CGAL::Delaunay_triangulation_2<K>;

const Point tip(0.5, 0.5);

// The field, with the crack's two faces as theta = +-pi; on the crack itself, its upper face.
double field(const Point& p) {
  const double theta = std::atan2(p.y() - tip.y(), p.x() - tip.x());
  const double r = std::sqrt(CGAL::squared_distance(p, tip));
  return std::sqrt(r) * std::sin((p.y() == tip.y() && p.x() < tip.x() ? M_PI : theta) / 2);
}

int main(int argc, char* argv[]) {
  const std::string out = argc > 1 ? argv[1] : "crack_interpolation.txt";
  if (out.size() > 1 && out[0] == '-') {  // -h, --help: the usage, not a file of that name
    std::cout << "usage: crack_interpolation [OUT.txt] [N] [GRID]\n";
    return out == "-h" || out == "--help" ? EXIT_SUCCESS : EXIT_FAILURE;
  }
  try {
    const std::size_t n = argc > 2 ? std::stoul(argv[2]) : 1500;
    const int grid = argc > 3 ? std::stoi(argv[3]) : 300;
    // The square, and the crack as an inner constraint from (0, 0.5) to the tip.
    CVT_2::IO::Poly_data<Point> poly;
    poly.vertices = {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1), Point(0, 0.5), tip};
    poly.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 0}, {4, 5}};
    poly.vertex_lines.assign(poly.vertices.size(), 0);
    poly.segment_lines.assign(poly.segments.size(), 0);
    CDT cdt;
    CVT_2::IO::insert_poly(cdt, poly);
    // Nodes well spread: random points, then a centroidal Voronoi tessellation of them.
    CVT_2::insert_generators_2(
        cdt, CVT_2::random_points_in_domain_2(cdt, n, CVT_2::parameters::random_seed(2)));
    CVT_2::lloyd_optimize_2(cdt, CVT_2::parameters::number_of_iterations(50));
    const BVD bvd(cdt);

    // The node values: on the crack, a node belongs to both faces; it takes the value of the
    // face q sees it from, so each query reads the side it is on.
    std::vector<Point> nodes;
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
      nodes.push_back(v->point());
    const DT dt(nodes.begin(), nodes.end());

    std::ofstream os(out);
    if (!os) throw std::runtime_error("cannot write " + out);
    os.precision(10);
    double ours_worst = 0, cgal_worst = 0;
    std::vector<std::pair<CDT::Vertex_handle, double>> w;
    std::vector<std::pair<Point, double>> wc;
    CDT::Face_handle hint;
    for (int i = 0; i < grid; ++i)
      for (int j = 0; j < grid; ++j) {
        const Point q((j + 0.5) / grid, (i + 0.5) / grid);
        const double side = q.y() >= tip.y() ? 1 : -1;  // the crack face q would see
        const auto value = [&](const Point& p) {
          return p.y() == tip.y() && p.x() < tip.x() ? side * std::sqrt(tip.x() - p.x()) : field(p);
        };
        w.clear();
        const auto r = CVT_2::natural_neighbor_coordinates_2(bvd, q, std::back_inserter(w),
                                                             CVT_2::parameters::hint(hint));
        double ours = 0;
        for (const auto& [v, x] : w) ours += x * value(v->point());
        ours /= r.second;
        wc.clear();
        const auto rc = CGAL::natural_neighbor_coordinates_2(dt, q, std::back_inserter(wc));
        double cgal = 0;
        for (const auto& [p, x] : wc) cgal += x * value(p);
        cgal /= rc.second;
        const double exact = field(q);
        ours_worst = std::max(ours_worst, std::abs(ours - exact));
        cgal_worst = std::max(cgal_worst, std::abs(cgal - exact));
        os << q.x() << ' ' << q.y() << ' ' << exact << ' ' << ours << ' ' << cgal << '\n';
      }
    std::cout << "crack_interpolation: " << nodes.size() << " nodes, " << grid * grid
              << " samples; largest error: bounded Voronoi diagram " << ours_worst
              << ", Delaunay (CGAL) " << cgal_worst << "; samples in " << out << '\n';
  } catch (const std::exception& e) {
    std::cerr << "crack_interpolation: " << e.what() << '\n';
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
