// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: bytes as a points file, read and inserted as generators into the bundled
// four_clusters domain (the file's own domain), whose cells must then tile it.
#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/IO/read_points.h>
#include <CVT_2/IO/read_poly.h>
#include <CVT_2/exceptions.h>
#include <CVT_2/insert_generators_2.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_2<K>;
using Fb = CVT_2::Bvd_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<
    K, Tds, CGAL::No_constraint_intersection_requiring_constructions_tag>;
using Bvd = CVT_2::Bounded_voronoi_diagram_2<CDT>;

namespace {

const CDT& domain() {
  static const CDT cdt = [] {
    CDT d;
    CVT_2::IO::insert_poly(d, CVT_2::IO::read_poly<K::Point_2>(CVT_2_DATA_DIR "/four_clusters.poly"));
    return d;
  }();
  return cdt;
}

[[noreturn]] void violated(const char* what, double a, double b) {
  std::fprintf(stderr, "ORACLE VIOLATED: %s (%.17g vs %.17g)\n", what, a, b);
  std::abort();
}

}  // namespace

// Only the documented errors are expected; anything else escapes and is a finding.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream is(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const auto points = CVT_2::IO::read_points<K::Point_2>(is, "fuzz.txt");
    CDT cdt = domain();
    CVT_2::insert_generators_2(cdt, points.points);
    double domain_area = 0;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
      if (f->is_inside_domain()) domain_area += cdt.triangle(f).area();
    // The unit square: points inserted on constraints or corners must not change it.
    if (std::abs(domain_area - 1) > 1e-12) violated("the domain's area changed", domain_area, 1);
    const Bvd bvd(cdt);
    double cell_area = 0;
    bvd.for_each_cell([&](CDT::Vertex_handle, const auto& cell) {
      const K::Point_2& o = cell.front().point;
      for (std::size_t i = 1; i + 1 < cell.size(); ++i) {
        const K::Vector_2 p = cell[i].point - o, q = cell[i + 1].point - o;
        cell_area += (p.x() * q.y() - q.x() * p.y()) / 2;
      }
    });
    if (!(std::abs(cell_area - domain_area) <= 1e-9 * domain_area))
      violated("cell areas do not sum to the domain's area", cell_area, domain_area);
  } catch (const CVT_2::IO::Parse_error&) {
  } catch (const CVT_2::Domain_error&) {
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
