// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the whole pipeline on a fuzzed .poly domain: insert_poly, generators (the
// file's free vertices, else seeded random points), the bounded Voronoi diagram and one Lloyd
// step, with oracles: the cells tile the domain, so do the mesh's, the energy is finite and
// does not rise.
#include "fuzz_support.h"

#include <CVT_2/IO/read_poly.h>
#include <CVT_2/Lloyd_optimizer_2.h>
#include <CVT_2/insert_generators_2.h>
#include <CVT_2/random_points_in_domain_2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

namespace {

constexpr std::size_t max_bytes = 8192, max_vertices = 300, random_generators = 20;

std::uint64_t fnv1a(const std::uint8_t* data, std::size_t size) {
  std::uint64_t h = 14695981039346656037ull;
  for (std::size_t i = 0; i < size; ++i) h = (h ^ data[i]) * 1099511628211ull;
  return h;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > max_bytes) return 0;
  std::istringstream is(std::string(reinterpret_cast<const char*>(data), size));
  fuzz::expecting_documented_errors([&] {
    const auto poly = CVT_2::IO::read_poly<fuzz::Point>(is, "fuzz.poly");
    if (poly.vertices.size() > max_vertices) return;
    fuzz::CDT cdt;
    CVT_2::IO::insert_poly(cdt, poly);
    std::vector<bool> on_segment(poly.vertices.size(), false);
    for (const auto& s : poly.segments) on_segment[s[0]] = on_segment[s[1]] = true;
    if (std::find(on_segment.begin(), on_segment.end(), false) == on_segment.end())
      CVT_2::insert_generators_2(
          cdt, CVT_2::random_points_in_domain_2(cdt, random_generators,
                                                CVT_2::parameters::random_seed(fnv1a(data, size))));

    fuzz::Bvd bvd(cdt);
    bvd.update();
    fuzz::check_cells_tile_domain(bvd);
    fuzz::check_mesh(bvd);

    // One Lloyd step with the default exact quadrature never raises the energy (beyond
    // rounding, on a well-conditioned triangulation).
    CVT_2::Lloyd_optimizer_2<fuzz::CDT> lloyd(cdt);
    const double e0 = lloyd.evaluate(10).energy;
    const bool well_conditioned = fuzz::is_well_conditioned(cdt);
    lloyd.move();
    const double e1 = lloyd.evaluate(10).energy;
    if (!std::isfinite(e0) || !std::isfinite(e1))
      fuzz::violated("the energy is not finite", e0, e1);
    if (well_conditioned && fuzz::is_well_conditioned(cdt) && e1 > e0 * (1 + 1e-12))
      fuzz::violated("the energy rose after one Lloyd step", e1, e0);
    fuzz::check_cells_tile_domain(lloyd.diagram());
  });
  return 0;
}
