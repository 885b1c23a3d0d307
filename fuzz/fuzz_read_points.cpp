// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: bytes as a points file, read and inserted as generators into the bundled
// four_clusters domain (the unit square with inner constraints, the file's own domain), whose
// area must not change and whose cells must then tile it.
#include "fuzz_support.h"

#include <CVT_2/IO/read_points.h>
#include <CVT_2/IO/read_poly.h>
#include <CVT_2/insert_generators_2.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

namespace {

const fuzz::CDT& four_clusters() {
  static const fuzz::CDT cdt = [] {
    fuzz::CDT d;
    CVT_2::IO::insert_poly(d,
                           CVT_2::IO::read_poly<fuzz::Point>(CVT_2_DATA_DIR "/four_clusters.poly"));
    return d;
  }();
  return cdt;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream is(std::string(reinterpret_cast<const char*>(data), size));
  fuzz::expecting_documented_errors([&] {
    const auto points = CVT_2::IO::read_points<fuzz::Point>(is, "fuzz.txt");
    fuzz::CDT cdt = four_clusters();
    CVT_2::insert_generators_2(cdt, points.points);
    const double area = fuzz::domain_area(cdt, fuzz::Area_meter());
    if (std::abs(area - 2) > 1e-12) fuzz::violated("the domain's area changed", area / 2, 1);
    fuzz::check_cells_tile_domain(fuzz::Bvd(cdt));
  });
  return 0;
}
