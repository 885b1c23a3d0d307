// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// lloyd_four_clusters [DOMAIN.poly] [PREFIX]: the paper's Fig. 7, Lloyd iteration step by step
// from clustered generators, a picture after 1, 5, 10 and 100 iterations and at convergence.
#include <CVT_2/Cvt_triangulation_2.h>
#include <CVT_2/IO/read_poly.h>
#include <CVT_2/IO/write_svg.h>
#include <CVT_2/Lloyd_optimizer_2.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstdlib>
#include <iostream>
#include <string>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using CDT = CVT_2::Cvt_triangulation_2<K>;  // CGAL's CDT with Bvd_face_base_2 faces

int main(int argc, char* argv[]) {
  const std::string domain = argc > 1 ? argv[1] : CVT_2_DATA_DIR "/four_clusters.poly";
  const std::string prefix = argc > 2 ? argv[2] : "lloyd_four_clusters";
  try {
    CDT cdt;
    CVT_2::IO::insert_poly(cdt, CVT_2::IO::read_poly<K::Point_2>(domain));  // its free vertices
    CVT_2::Lloyd_optimizer_2<CDT> lloyd(cdt);                               // are the generators
    const double bound = 0.01;  // the paper's stopping rule: every move ratio below 1%
    for (std::size_t it = 0;; ++it) {
      const auto& e = lloyd.evaluate(100);
      const bool converged = e.max_move_ratio < bound;
      if (it == 0 || it == 1 || it == 5 || it == 10 || it == 100 || converged) {
        const std::string svg =
            prefix + "_" + (converged ? "converged" : std::to_string(it)) + ".svg";
        CVT_2::IO::write_svg(svg, lloyd.diagram());
        std::cout << "iteration " << it << ": energy " << e.energy << ", largest move ratio "
                  << e.max_move_ratio << " -> " << svg << '\n';
      }
      if (converged || it == 2000) break;
      lloyd.move();
    }
  } catch (const std::exception& e) {
    std::cerr << "lloyd_four_clusters: " << e.what() << '\n';
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
