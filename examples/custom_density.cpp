// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// custom_density [DOMAIN.poly] [OUT.svg] [N] [ITERATIONS]: a density of one's own, a lambda, here
// concentrated along a sine wave across the domain's bounding box (cells there are 4x smaller).
#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/Cvt_triangulation_2.h>
#include <CVT_2/IO/read_poly.h>
#include <CVT_2/IO/write_svg.h>
#include <CVT_2/insert_generators_2.h>
#include <CVT_2/lloyd_optimize_2.h>
#include <CVT_2/random_points_in_domain_2.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using CDT = CVT_2::Cvt_triangulation_2<K>;  // CGAL's CDT with Bvd_face_base_2 faces

int main(int argc, char* argv[]) {
  const std::string domain = argc > 1 ? argv[1] : CVT_2_DATA_DIR "/square_inner_constraints.poly";
  const std::string svg = argc > 2 ? argv[2] : "custom_density.svg";
  try {
    const std::size_t n = argc > 3 ? std::stoul(argv[3]) : 1500;
    const std::size_t iterations = argc > 4 ? std::stoul(argv[4]) : 1000;
    CDT cdt;
    CVT_2::IO::insert_poly(cdt, CVT_2::IO::read_poly<K::Point_2>(domain));

    // rho = 1 + 255 exp(-(d/w)^2), d the vertical distance to the wave: up to 256 = 4^4 times
    // denser on it, and cell size goes as rho^(-1/4). Any positive function of a point works.
    const CGAL::Bbox_2 box = CGAL::bbox_2(cdt.points_begin(), cdt.points_end());
    const double pi = std::acos(-1.0), w = box.xmax() - box.xmin(), h = box.ymax() - box.ymin();
    const auto rho = [=](const K::Point_2& p) {
      const double wave = box.ymin() + h / 2 + h / 4 * std::sin(2 * pi * (p.x() - box.xmin()) / w);
      const double d = (p.y() - wave) / (0.06 * w);
      return 1 + 255 * std::exp(-d * d);
    };
    // Start near the result: a CVT of density rho has about sqrt(rho) generators per unit area.
    const auto start_density = [&rho](const K::Point_2& p) { return std::sqrt(rho(p)); };
    CVT_2::insert_generators_2(
        cdt, CVT_2::random_points_in_domain_2(
                 cdt, n, CVT_2::parameters::density(start_density).random_seed(1)));

    const CVT_2::Optimization_result r = CVT_2::lloyd_optimize_2(
        cdt, CVT_2::parameters::density(rho).number_of_iterations(iterations));

    std::cout << "custom_density: " << n << " generators, " << r.number_of_iterations
              << " iterations, "
              << "stopped: " << CVT_2::to_string(r.stop_reason) << ", energy " << r.energy
              << ", largest move ratio " << r.max_move_ratio << ", " << r.seconds << " s\n";
    if (!CVT_2::IO::write_svg(svg, CVT_2::Bounded_voronoi_diagram_2<CDT>(cdt)))
      throw std::runtime_error("cannot write " + svg);
    std::cout << "custom_density: picture in " << svg << '\n';
  } catch (const std::exception& e) {
    std::cerr << "custom_density: " << e.what() << '\n';
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
