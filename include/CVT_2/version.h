// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The library's version, kept in sync with CMakeLists.txt.
#ifndef CVT_2_VERSION_H
#define CVT_2_VERSION_H

#define CVT_2_VERSION_MAJOR 0
#define CVT_2_VERSION_MINOR 1
#define CVT_2_VERSION_PATCH 0
#define CVT_2_VERSION_STRING "0.1.0"

#endif  // CVT_2_VERSION_H
