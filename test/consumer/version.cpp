// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The consumer of the build tree or the source tree: the headers found (CVT_2's, and CGAL's
// through CVT_2's target) are this build's. main.cpp, built against the installed package,
// proves that a diagram builds and tiles; this one compiles in half a second instead of ten.
#include <CGAL/version.h>
#include <CVT_2/version.h>

#include <cstdlib>
#include <cstring>
#include <iostream>

int main() {
  std::cout << "cvt_2_consumer: CVT_2 " << CVT_2_VERSION_STRING << " (expected "
            << CVT_2_EXPECTED_VERSION << "), CGAL " << CGAL_VERSION_STR << "\n";
  return std::strcmp(CVT_2_VERSION_STRING, CVT_2_EXPECTED_VERSION) == 0 ? EXIT_SUCCESS
                                                                        : EXIT_FAILURE;
}
