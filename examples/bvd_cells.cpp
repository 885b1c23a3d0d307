// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// bvd_cells DOMAIN [POINTS] [OUT.svg]: the bounded Voronoi diagram of the domain's own
// generators (.poly free vertices, WKT or GeoJSON points) and of the points, one line per
// vertex of the closed domain on standard output:
//   x y c k x1 y1 ... xk yk      (c = 1 for a constrained vertex; the cell, counterclockwise)
#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/Cvt_triangulation_2.h>
#include <CVT_2/IO/read_domain.h>
#include <CVT_2/IO/read_points.h>
#include <CVT_2/IO/write_cells.h>
#include <CVT_2/IO/write_svg.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstdlib>
#include <iostream>
#include <string>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using CDT = CVT_2::Cvt_triangulation_2<K>;  // CGAL's CDT with Bvd_face_base_2 faces
using BVD = CVT_2::Bounded_voronoi_diagram_2<CDT>;

int main(int argc, char* argv[]) {
  const std::string domain = argc > 1 ? argv[1] : CVT_2_DATA_DIR "/four_clusters.poly";
  const std::string svg = argc > 3 ? argv[3] : "bvd_cells.svg";
  try {
    CDT cdt;
    const auto file = CVT_2::IO::read_domain(domain, cdt);  // .poly, .wkt or .geojson
    if (!file.repeated.empty())
      std::cerr << "bvd_cells: note: " << file.repeated[0] << " (" << file.repeated.size()
                << " repeated points in all): merged\n";
    if (argc > 2) CVT_2::IO::insert_points(cdt, CVT_2::IO::read_points<K::Point_2>(argv[2]));
    const BVD bvd(cdt);
    CVT_2::IO::write_cells(std::cout, bvd);
    if (!CVT_2::IO::write_svg(svg, bvd)) {
      std::cerr << "bvd_cells: cannot write " << svg << '\n';
      return EXIT_FAILURE;
    }
    std::cerr << "bvd_cells: " << bvd.number_of_blinded_faces() << " blind faces; picture in "
              << svg << '\n';
  } catch (const std::exception& e) {
    std::cerr << "bvd_cells: " << e.what() << '\n';
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
