// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The test runner's main, alone in its translation unit.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
