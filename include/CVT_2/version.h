// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The library's version, written here only (CMakeLists.txt reads it from this file).
#ifndef CVT_2_VERSION_H
#define CVT_2_VERSION_H

#define CVT_2_VERSION_MAJOR 0
#define CVT_2_VERSION_MINOR 2
#define CVT_2_VERSION_PATCH 0

#define CVT_2_VERSION_STRINGIFY_(x) #x
#define CVT_2_VERSION_STRINGIFY(x) CVT_2_VERSION_STRINGIFY_(x)
/// "major.minor.patch"
#define CVT_2_VERSION_STRING                   \
  CVT_2_VERSION_STRINGIFY(CVT_2_VERSION_MAJOR) \
  "." CVT_2_VERSION_STRINGIFY(CVT_2_VERSION_MINOR) "." CVT_2_VERSION_STRINGIFY(CVT_2_VERSION_PATCH)

#endif  // CVT_2_VERSION_H
