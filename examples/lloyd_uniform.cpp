// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// lloyd_uniform [DOMAIN.poly] [OUT.svg] [N] [ITERATIONS]: a centroidal Voronoi tessellation of
// uniform density from N random generators, by lloyd_optimize_2() with named parameters.
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
  const std::string domain = argc > 1 ? argv[1] : CVT_2_DATA_DIR "/square_inner_constraints.poly";
  const std::string svg = argc > 2 ? argv[2] : "lloyd_uniform.svg";
  try {
    const std::size_t n = argc > 3 ? std::stoul(argv[3]) : 1000;
    const std::size_t iterations = argc > 4 ? std::stoul(argv[4]) : 1000;
    CDT cdt;
    CVT_2::IO::insert_poly(cdt, CVT_2::IO::read_poly<K::Point_2>(domain));
    CVT_2::insert_generators_2(
        cdt, CVT_2::random_points_in_domain_2(cdt, n, CVT_2::parameters::random_seed(1)));

    // Uniform density (the default), so the cells are integrated exactly; the paper's stop.
    const CVT_2::Optimization_result r = CVT_2::lloyd_optimize_2(
        cdt, CVT_2::parameters::number_of_iterations(iterations).move_ratio_bound(0.01));

    std::cout << "lloyd_uniform: " << n << " generators, " << r.number_of_iterations
              << " iterations, "
              << "stopped: " << CVT_2::to_string(r.stop_reason) << ", energy " << r.energy
              << ", largest move ratio " << r.max_move_ratio << ", " << r.seconds << " s\n";
    if (!CVT_2::IO::write_svg(svg, CVT_2::Bounded_voronoi_diagram_2<CDT>(cdt)))
      throw std::runtime_error("cannot write " + svg);
    std::cout << "lloyd_uniform: picture in " << svg << '\n';
  } catch (const std::exception& e) {
    std::cerr << "lloyd_uniform: " << e.what() << '\n';
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
