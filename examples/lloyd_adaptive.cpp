// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// lloyd_adaptive [DOMAIN.poly] [OUT.svg] [N] [ITERATIONS] [K]: a centroidal Voronoi tessellation
// graded by the paper's automatic sizing field (Section 4): cells as small as the boundary edges
// on the boundary, growing by K (default 0.1) per unit of distance away from it.
#include <CVT_2/Boundary_lipschitz_sizing_2.h>
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
  const std::string domain = argc > 1 ? argv[1] : CVT_2_DATA_DIR "/earcut_logo.poly";
  const std::string svg = argc > 2 ? argv[2] : "lloyd_adaptive.svg";
  try {
    const std::size_t n = argc > 3 ? std::stoul(argv[3]) : 1500;
    const std::size_t iterations = argc > 4 ? std::stoul(argv[4]) : 1000;
    const double k = argc > 5 ? std::stod(argv[5]) : 0.1;
    CDT cdt;
    CVT_2::IO::insert_poly(cdt, CVT_2::IO::read_poly<K::Point_2>(domain));
    // mu(x) = min over boundary edges s of k d(x, s) + length(s). Built before the generators
    // are inserted: one inserted on a constraint would split it into shorter edges.
    const CVT_2::Boundary_lipschitz_sizing_2<K> mu(cdt, k);

    // A CVT of density 1/mu^4 has about 1/mu^2 generators per unit area: start from that.
    const auto start_density = [&mu](const K::Point_2& p) { return 1 / (mu(p) * mu(p)); };
    CVT_2::insert_generators_2(
        cdt, CVT_2::random_points_in_domain_2(
                 cdt, n, CVT_2::parameters::density(start_density).random_seed(1)));

    // sizing_field(mu) iterates with the density 1/mu^4, integrated by the Gauss rule
    // (Gauss_quadrature_2, the default for a density that is not uniform).
    const CVT_2::Optimization_result r = CVT_2::lloyd_optimize_2(
        cdt, CVT_2::parameters::sizing_field(mu).number_of_iterations(iterations));

    std::cout << "lloyd_adaptive: " << n << " generators, k = " << k << ", "
              << r.number_of_iterations << " iterations, "
              << "stopped: " << CVT_2::to_string(r.stop_reason) << ", energy " << r.energy
              << ", largest move ratio " << r.max_move_ratio << ", " << r.seconds << " s\n";
    if (!CVT_2::IO::write_svg(svg, CVT_2::Bounded_voronoi_diagram_2<CDT>(cdt)))
      throw std::runtime_error("cannot write " + svg);
    std::cout << "lloyd_adaptive: picture in " << svg << '\n';
  } catch (const std::exception& e) {
    std::cerr << "lloyd_adaptive: " << e.what() << '\n';
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
