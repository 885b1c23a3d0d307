// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// clang-format off
// The list of named parameters: one line a parameter, CVT_2_add_named_parameter(tag, name).
// No include guard: included with a different definition of the macro each time.

CVT_2_add_named_parameter(number_of_iterations_t, number_of_iterations)
CVT_2_add_named_parameter(maximum_running_time_t, maximum_running_time)
CVT_2_add_named_parameter(move_ratio_bound_t, move_ratio_bound)
CVT_2_add_named_parameter(density_t, density)
CVT_2_add_named_parameter(sizing_field_t, sizing_field)
CVT_2_add_named_parameter(quadrature_t, quadrature)
CVT_2_add_named_parameter(minimum_quadrature_resolution_t, minimum_quadrature_resolution)
CVT_2_add_named_parameter(maximum_quadrature_resolution_t, maximum_quadrature_resolution)
CVT_2_add_named_parameter(lbfgs_memory_t, lbfgs_memory)
CVT_2_add_named_parameter(callback_t, callback)
CVT_2_add_named_parameter(verbose_t, verbose)
CVT_2_add_named_parameter(number_of_threads_t, number_of_threads)
CVT_2_add_named_parameter(random_seed_t, random_seed)
CVT_2_add_named_parameter(geom_traits_t, geom_traits)
CVT_2_add_named_parameter(natural_neighbor_method_t, natural_neighbor_method)
CVT_2_add_named_parameter(hint_t, hint)
CVT_2_add_named_parameter(lips_t, lips)
CVT_2_add_named_parameter(boundary_tolerance_t, boundary_tolerance)
CVT_2_add_named_parameter(deviation_bound_t, deviation_bound)
CVT_2_add_named_parameter(corner_angle_t, corner_angle)
CVT_2_add_named_parameter(fixed_points_t, fixed_points)
CVT_2_add_named_parameter(region_t, region)
CVT_2_add_named_parameter(region_rings_t, region_rings)
CVT_2_add_named_parameter(minimum_ring_area_t, minimum_ring_area)
