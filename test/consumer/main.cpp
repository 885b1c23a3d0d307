// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Consumer of the installed package: the BVD of a unit square with an inner constraint tiles it.
#include <CVT_2/Bounded_voronoi_diagram_2.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_2<K>;
using Fb = CVT_2::Bvd_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds>;
using BVD = CVT_2::Bounded_voronoi_diagram_2<CDT>;
using Point_2 = K::Point_2;

int main() {
  CDT cdt;
  const std::vector<Point_2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (std::size_t i = 0; i < square.size(); ++i)
    cdt.insert_constraint(square[i], square[(i + 1) % square.size()]);
  cdt.insert_constraint(Point_2(0.2, 0.5), Point_2(0.7, 0.5));  // a wall that blinds faces
  CVT_2::mark_domain_2(cdt, std::vector<Point_2>());
  const std::vector<Point_2> generators{{0.1, 0.1}, {0.45, 0.47}, {0.5, 0.53}, {0.9, 0.2},
                                        {0.3, 0.9}, {0.8, 0.8},   {0.05, 0.6}};
  CVT_2::insert_generators_2(cdt, generators);

  const BVD bvd(cdt);
  double area = 0;
  std::size_t cells = 0;
  bvd.for_each_cell([&](BVD::Vertex_handle, const std::vector<BVD::Cell_vertex>& cell) {
    for (std::size_t i = 1; i + 1 < cell.size(); ++i) {  // shoelace, relative to the first vertex
      const K::Vector_2 p = cell[i].point - cell[0].point, q = cell[i + 1].point - cell[0].point;
      area += 0.5 * (p.x() * q.y() - p.y() * q.x());
    }
    ++cells;
  });
  std::cout << "cvt_2_consumer: " << cells << " cells, total area " << area << ", "
            << bvd.number_of_blinded_faces() << " blind faces\n";
  const bool ok = cells == cdt.number_of_vertices() && std::abs(area - 1) < 1e-12;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
