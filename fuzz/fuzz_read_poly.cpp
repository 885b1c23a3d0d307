// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: bytes as a .poly file, read and inserted into a CDT as a user would.
#include <CVT_2/Bvd_face_base_2.h>
#include <CVT_2/IO/read_poly.h>
#include <CVT_2/exceptions.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_2<K>;
using Fb = CVT_2::Bvd_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<
    K, Tds, CGAL::No_constraint_intersection_requiring_constructions_tag>;

// Only the documented errors are expected; anything else escapes and is a finding.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream is(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const auto poly = CVT_2::IO::read_poly<K::Point_2>(is, "fuzz.poly");
    CDT cdt;
    CVT_2::IO::insert_poly(cdt, poly);
  } catch (const CVT_2::IO::Parse_error&) {
  } catch (const CVT_2::Domain_error&) {
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
