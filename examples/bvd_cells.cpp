// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// bvd_cells DOMAIN.poly|DOMAIN.wkt [POINTS] [OUT.svg]: the bounded Voronoi diagram of the
// domain's free vertices (or WKT points) and of the points, one line per vertex of the closed domain on standard output:
//   x y c k x1 y1 ... xk yk      (c = 1 for a constrained vertex; the cell, counterclockwise)
#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/Cvt_triangulation_2.h>
#include <CVT_2/IO/read_points.h>
#include <CVT_2/IO/read_poly.h>
#include <CVT_2/IO/read_wkt.h>
#include <CVT_2/IO/write_svg.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using CDT = CVT_2::Cvt_triangulation_2<K>;  // CGAL's CDT with Bvd_face_base_2 faces
using BVD = CVT_2::Bounded_voronoi_diagram_2<CDT>;

int main(int argc, char* argv[]) {
  const std::string domain = argc > 1 ? argv[1] : CVT_2_DATA_DIR "/four_clusters.poly";
  const std::string svg = argc > 3 ? argv[3] : "bvd_cells.svg";
  try {
    CDT cdt;
    std::vector<std::array<std::size_t, 2>> repeated;  // points the triangulation merges
    if (domain.size() > 4 && domain.compare(domain.size() - 4, 4, ".wkt") == 0) {
      const auto wkt = CVT_2::IO::read_wkt<K>(domain);
      repeated = wkt.repeated_points;
      CVT_2::IO::insert_wkt(cdt, wkt);
    } else {
      const auto poly = CVT_2::IO::read_poly<K::Point_2>(domain);
      repeated = poly.repeated_vertices;
      CVT_2::IO::insert_poly(cdt, poly);
    }
    if (!repeated.empty())
      std::cerr << "bvd_cells: note: " << domain << ":" << repeated[0][0] << " repeats line "
                << repeated[0][1] << " (" << repeated.size() << " repeated points in all): merged\n";
    if (argc > 2) {
      const auto points = CVT_2::IO::read_points<K::Point_2>(argv[2]);
      try {
        CVT_2::insert_generators_2(cdt, points.points);
      } catch (const CVT_2::Domain_error& e) {  // say which line of the points file
        throw CVT_2::Domain_error(points.source + ":" + std::to_string(points.lines.at(e.index())) +
                                  ": " + e.what());
      }
    }
    const BVD bvd(cdt);

    std::cout.precision(17);
    std::vector<BVD::Cell_vertex> cell;
    std::size_t cells = 0;
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
      bvd.cell(v, cell);
      if (cell.empty()) continue;
      std::cout << v->point() << ' ' << (bvd.is_free(v) ? 0 : 1) << ' ' << cell.size();
      for (const auto& c : cell) std::cout << ' ' << c.point;
      std::cout << '\n';
      ++cells;
    }
    if (!CVT_2::IO::write_svg(svg, bvd)) {
      std::cerr << "bvd_cells: cannot write " << svg << '\n';
      return EXIT_FAILURE;
    }
    std::cerr << "bvd_cells: " << cells << " cells, " << bvd.number_of_blinded_faces()
              << " blind faces; picture in " << svg << '\n';
  } catch (const std::exception& e) {
    std::cerr << "bvd_cells: " << e.what() << '\n';
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
