// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// lloyd_world [DOMAIN.poly] [PREFIX] [N] [ITERATIONS]: the paper's Fig. 9, centroidal Voronoi
// tessellations of the world's land from the same N random generators, with a uniform density
// (PREFIX_uniform.svg) and with the automatic sizing field, k = 0.1 (PREFIX_adaptive.svg).
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
  const std::string domain = argc > 1 ? argv[1] : CVT_2_DATA_DIR "/world_land_110m.poly";
  const std::string prefix = argc > 2 ? argv[2] : "lloyd_world";
  try {
    const std::size_t n = argc > 3 ? std::stoul(argv[3]) : 3000;
    const std::size_t iterations = argc > 4 ? std::stoul(argv[4]) : 1000;
    const auto poly = CVT_2::IO::read_poly<K::Point_2>(domain);
    for (const bool adaptive : {false, true}) {
      CDT cdt;
      CVT_2::IO::insert_poly(cdt, poly);
      // mu: half a degree (55 km) on every coast, + 0.1 per degree inland (N sets the cell size,
      // mu its grading). One size for all: the coast's edges, from under 1 km to over 300 km
      // long, would make poor sizes.
      const CVT_2::Boundary_lipschitz_sizing_2<K> mu(cdt, 0.1, 0.5);
      // The same seed, so both runs start from the same uniformly drawn generators.
      CVT_2::insert_generators_2(
          cdt, CVT_2::random_points_in_domain_2(cdt, n, CVT_2::parameters::random_seed(1)));
      const auto np = CVT_2::parameters::number_of_iterations(iterations);
      const CVT_2::Optimization_result r = adaptive
                                               ? CVT_2::lloyd_optimize_2(cdt, np.sizing_field(mu))
                                               : CVT_2::lloyd_optimize_2(cdt, np);

      const std::string svg = prefix + (adaptive ? "_adaptive.svg" : "_uniform.svg");
      std::cout << "lloyd_world: " << (adaptive ? "adaptive, k = 0.1: " : "uniform: ") << n
                << " generators, " << r.number_of_iterations << " iterations, "
                << "stopped: " << CVT_2::to_string(r.stop_reason) << ", energy " << r.energy
                << ", largest move ratio " << r.max_move_ratio << ", " << r.seconds << " s -> "
                << svg << '\n';
      if (!CVT_2::IO::write_svg(svg, CVT_2::Bounded_voronoi_diagram_2<CDT>(cdt), 1800))
        throw std::runtime_error("cannot write " + svg);
    }
  } catch (const std::exception& e) {
    std::cerr << "lloyd_world: " << e.what() << '\n';
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
