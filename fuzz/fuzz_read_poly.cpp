// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: bytes as a .poly file, read and inserted into a CDT as a user would.
#include "fuzz_support.h"

#include <CVT_2/IO/read_poly.h>

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream is(std::string(reinterpret_cast<const char*>(data), size));
  fuzz::expecting_documented_errors([&] {
    const auto poly = CVT_2::IO::read_poly<fuzz::Point>(is, "fuzz.poly");
    fuzz::CDT cdt;
    CVT_2::IO::insert_poly(cdt, poly);
  });
  return 0;
}
