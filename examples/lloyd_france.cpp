// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// lloyd_france [DOMAIN.poly] [OUT.svg] [N] [ITERATIONS]: the paper's Fig. 8, a uniform centroidal
// Voronoi tessellation of mainland France from N random generators, with progress reported by
// a callback.
#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/Cvt_triangulation_2.h>
#include <CVT_2/IO/read_poly.h>
#include <CVT_2/IO/write_svg.h>
#include <CVT_2/insert_generators_2.h>
#include <CVT_2/lloyd_optimize_2.h>
#include <CVT_2/random_points_in_domain_2.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using CDT = CVT_2::Cvt_triangulation_2<K>;  // CGAL's CDT with Bvd_face_base_2 faces

int main(int argc, char* argv[]) {
  const std::string domain = argc > 1 ? argv[1] : CVT_2_DATA_DIR "/france_mainland.poly";
  const std::string svg = argc > 2 ? argv[2] : "lloyd_france.svg";
  try {
    const std::size_t n = argc > 3 ? std::stoul(argv[3]) : 3000;
    const std::size_t iterations = argc > 4 ? std::stoul(argv[4]) : 1000;
    CDT cdt;  // the coastline and the land borders are constraints; their vertices have cells
    CVT_2::IO::insert_poly(cdt, CVT_2::IO::read_poly<K::Point_2>(domain));
    CVT_2::insert_generators_2(
        cdt, CVT_2::random_points_in_domain_2(cdt, n, CVT_2::parameters::random_seed(1)));

    // Called after each evaluation with the figures so far; returning false would stop.
    const auto progress = [](const CVT_2::Optimization_result& r) {
      if (r.number_of_iterations % 25 == 0)
        std::cout << "  iteration " << r.number_of_iterations << ": energy " << r.energy
                  << ", largest move ratio " << r.max_move_ratio << '\n';
      return true;
    };
    const CVT_2::Optimization_result r = CVT_2::lloyd_optimize_2(
        cdt, CVT_2::parameters::number_of_iterations(iterations).callback(progress));

    std::cout << "lloyd_france: " << n << " generators, " << r.number_of_iterations
              << " iterations, "
              << "stopped: " << CVT_2::to_string(r.stop_reason) << ", energy " << r.energy
              << ", largest move ratio " << r.max_move_ratio << ", " << r.seconds << " s\n";
    if (!CVT_2::IO::write_svg(svg, CVT_2::Bounded_voronoi_diagram_2<CDT>(cdt), 1200))
      throw std::runtime_error("cannot write " + svg);
    std::cout << "lloyd_france: picture in " << svg << '\n';
  } catch (const std::exception& e) {
    std::cerr << "lloyd_france: " << e.what() << '\n';
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
