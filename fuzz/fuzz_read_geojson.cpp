// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: bytes as a GeoJSON file (polygons, inner constraints, generators), read and
// inserted as cvt2 does; when that succeeds and the input is small, the cells must tile the
// domain.
#include "fuzz_support.h"

#include <CVT_2/IO/read_geojson.h>
#include <CVT_2/IO/read_wkt.h>

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream is(std::string(reinterpret_cast<const char*>(data), size));
  fuzz::expecting_documented_errors([&] {
    const auto geojson = CVT_2::IO::read_geojson<fuzz::K>(is, "fuzz.geojson");
    fuzz::CDT cdt;
    CVT_2::IO::insert_wkt(cdt, geojson);
    if (cdt.number_of_vertices() <= 2000) fuzz::check_cells_tile_domain(fuzz::Bvd(cdt));
  });
  return 0;
}
