// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// natural_neighbours DOMAIN POINTS QUERIES [--laplace]: the natural-neighbour coordinates of
// the constrained natural element method at each query, on the bounded Voronoi diagram of the
// domain's vertices and the points (nodes as bvd_cells builds them). One line per query, in
// input order, on standard output:
//   qx qy m x1 y1 w1 ... xm ym wm    (the m nodes with a nonzero weight, sorted by x then y;
//                                     weights sum to 1; `qx qy 0` outside the closed domain)
// Sibson's coordinates by default, Laplace's with --laplace. POINTS and QUERIES: one `x y` per
// line, `#` comments; POINTS may be `-` for none.
#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/Cvt_triangulation_2.h>
#include <CVT_2/IO/read_domain.h>
#include <CVT_2/IO/read_points.h>
#include <CVT_2/natural_neighbor_coordinates_2.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>
#include <tuple>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using CDT = CVT_2::Cvt_triangulation_2<K>;
using BVD = CVT_2::Bounded_voronoi_diagram_2<CDT>;

int main(int argc, char* argv[]) {
  std::vector<std::string> args(argv + 1, argv + argc);
  const auto laplace = std::find(args.begin(), args.end(), "--laplace");
  const CVT_2::Natural_neighbor_method method =
      laplace == args.end() ? CVT_2::SIBSON : CVT_2::LAPLACE;
  if (laplace != args.end()) args.erase(laplace);
  if (args.size() != 3) {
    std::cerr << "usage: natural_neighbours DOMAIN POINTS QUERIES [--laplace]\n"
                 "  DOMAIN: .poly, .wkt or .geojson; POINTS, QUERIES: 'x y' lines (POINTS '-' "
                 "for none)\n";
    return EXIT_FAILURE;
  }
  try {
    CDT cdt;
    CVT_2::IO::read_domain(args[0], cdt);
    if (args[1] != "-") CVT_2::IO::insert_points(cdt, CVT_2::IO::read_points<K::Point_2>(args[1]));
    const auto queries = CVT_2::IO::read_points<K::Point_2>(args[2]).points;
    const BVD bvd(cdt);
    const auto m = CVT_2::natural_neighbor_matrix_2(
        bvd, queries, CVT_2::parameters::natural_neighbor_method(method));

    std::cout << std::setprecision(17);  // reads back as the same doubles
    const auto number = [](double x) { std::cout << x << ' '; };
    std::vector<std::tuple<double, double, double>> row;
    for (std::size_t k = 0; k < queries.size(); ++k) {
      row.clear();
      for (std::size_t e = m.row_offsets[k]; e < m.row_offsets[k + 1]; ++e) {
        const K::Point_2& p = m.nodes[m.columns[e]]->point();
        row.emplace_back(p.x(), p.y(), m.values[e]);
      }
      std::sort(row.begin(), row.end());
      number(queries[k].x());
      number(queries[k].y());
      std::cout << row.size();
      for (const auto& [x, y, w] : row) {
        std::cout << ' ';
        number(x);
        number(y);
        std::cout << w;
      }
      std::cout << '\n';
    }
  } catch (const std::exception& e) {
    std::cerr << "natural_neighbours: " << e.what() << '\n';
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
