// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// density_response_2(): whether the cells of a diagram follow a density, as a centroidal
// tessellation's do, or still have the sizes of the points they started from.
#ifndef CVT_2_DENSITY_RESPONSE_2_H
#define CVT_2_DENSITY_RESPONSE_2_H

#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/Concepts/DensityFunction_2.h>
#include <CVT_2/insert_generators_2.h>
#include <CVT_2/internal/density_evaluation.h>

#include <CGAL/Kernel/global_functions_2.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace CVT_2 {

/// \ingroup PkgCvt2Ref
/// How the cells of the free generators of `bvd` follow the density `rho`: the least-squares
/// slope of log(area of the cell) against log(rho at its generator). The cells of a centroidal
/// Voronoi tessellation of a density have areas proportional to \f$\rho^{-1/2}\f$ (Gersho's
/// asymptotics, exact in 2D: their size scales as \f$\rho^{-1/4}\f$), so its slope is about
/// -1/2; cells of one size have 0. Lloyd iteration and L-BFGS move points across the domain
/// slowly: from points that do not follow the density (uniform ones under a density of range
/// 16, say), every move ratio falls below 1% long before the cells have the sizes the density
/// asks for, and the slope says so. `random_points_in_domain_2()` draws points that follow it.
///
/// Returns NaN if fewer than 3 free generators have a cell, or if rho varies by less than a
/// factor 2 over them (too little to measure). \throws Domain_error if a value of rho is not
/// positive and finite, naming the point.
/// \tparam Diagram a `Bounded_voronoi_diagram_2`.
/// \tparam Density a model of `DensityFunction_2` (one with the batch member is called once).
template <class Diagram, class Density>
double density_response_2(const Diagram& bvd, const Density& rho) {
  using K = typename Diagram::Triangulation::Geom_traits;
  using Point_2 = typename K::Point_2;
  using FT = typename K::FT;
  std::vector<Point_2> generators;
  std::vector<double> log_areas;
  bvd.for_each_cell([&](auto v, const auto& cell) {
    if (!bvd.is_free(v)) return;
    // the fan from the generator, as Bvd_mesh_2::area(): no cancellation far from the origin
    double area = 0;
    for (std::size_t i = 0; i < cell.size(); ++i)
      area +=
          CGAL::to_double(CGAL::area(v->point(), cell[i].point, cell[(i + 1) % cell.size()].point));
    if (!(area > 0)) return;  // a cell that underflows says nothing
    generators.push_back(v->point());
    log_areas.push_back(std::log(area));
  });
  const double none = std::numeric_limits<double>::quiet_NaN();
  if (generators.size() < 3) return none;
  std::vector<FT> values;
  if constexpr (has_batch_evaluation_v<Density, K>) {
    internal::evaluate_in_batch(rho, generators, values);
  } else {
    const internal::Checked_density<Density, Point_2> checked{rho};
    for (const Point_2& p : generators) values.push_back(checked(p));
  }
  std::vector<double> log_rho(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) log_rho[i] = std::log(CGAL::to_double(values[i]));
  const auto [lo, hi] = std::minmax_element(log_rho.begin(), log_rho.end());
  if (*hi - *lo < std::log(2.0)) return none;
  const double n = double(log_rho.size());
  double mean_x = 0, mean_y = 0;
  for (std::size_t i = 0; i < log_rho.size(); ++i) mean_x += log_rho[i], mean_y += log_areas[i];
  mean_x /= n, mean_y /= n;
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < log_rho.size(); ++i) {
    sxy += (log_rho[i] - mean_x) * (log_areas[i] - mean_y);
    sxx += (log_rho[i] - mean_x) * (log_rho[i] - mean_x);
  }
  return sxy / sxx;
}

namespace internal {
// Half way from cells of one size (0) to a centroidal tessellation's (-1/2).
inline constexpr double density_response_bound = -0.25;
}  // namespace internal

/// \ingroup PkgCvt2Ref
/// Whether the free generators of `bvd` are spread as a start for a centroidal tessellation of
/// `rho` must be: `density_response_2()` at most -1/4, half way from cells of one size to a
/// centroidal tessellation's, or not defined (rho varies by less than a factor 2). Points that
/// do not follow the density (uniform ones under a density that varies) take the optimizers
/// hundreds of iterations to move across the domain, and the move ratios fall below 1% long
/// before they arrive; points drawn by `random_points_in_domain_2()` follow it, and
/// `remove_generators_2()` takes the others away (`cvt2 --redistribute` and the Python
/// module's `optimize(redistribute=)` replace them so by default).
/// \tparam Diagram a `Bounded_voronoi_diagram_2`.
/// \tparam Density a model of `DensityFunction_2`.
template <class Diagram, class Density>
bool follows_density_2(const Diagram& bvd, const Density& rho) {
  return !(density_response_2(bvd, rho) > internal::density_response_bound);
}

/// \ingroup PkgCvt2Ref
/// The generators that points drawn from the density `rho` should replace before an optimization
/// under it: the free generators of `cdt` (in the domain, on no constraint) but those at the
/// points `fixed`, the ones an optimizer with `fixed_points(fixed)` moves: all of them with
/// `always`, else all of them unless they follow rho (`follows_density_2()`), and then none.
/// `remove_generators_2()` removes them and `random_points_in_domain_2()` draws as many from rho:
/// `cvt2 --redistribute` and the Python module's `optimize(redistribute=)` do so.
/// \tparam CDT a constrained Delaunay triangulation whose faces model `BvdFaceBase_2`.
/// \tparam Density a model of `DensityFunction_2`.
/// \param cdt the triangulation, its domain marked and its generators inserted.
/// \param rho the density (not evaluated with `always`).
/// \param fixed a range of points, each a generator of `cdt`, that stay.
/// \param always whether to replace them whether they follow rho or not.
/// \throws std::invalid_argument naming a point of `fixed` that is not a generator.
template <class CDT, class Density, class PointRange>
std::vector<typename CDT::Vertex_handle> generators_to_redistribute_2(const CDT& cdt,
                                                                      const Density& rho,
                                                                      const PointRange& fixed,
                                                                      bool always = false) {
  std::vector<typename CDT::Vertex_handle> given = internal::movable_generators(cdt, fixed);
  if (!given.empty() && !always && follows_density_2(Bounded_voronoi_diagram_2<CDT>(cdt), rho))
    given.clear();
  return given;
}

namespace internal {

// A note for a result whose cells do not follow the density (a slope of density_response_2()
// above density_response_bound), empty otherwise.
inline std::string density_response_note(double slope) {
  if (!(slope > density_response_bound)) return {};
  char s[32];
  std::snprintf(s, sizeof s, "%.2f", slope);
  return std::string("the cells do not follow the density: their areas scale as density^") + s +
         ", a centroidal tessellation's as density^-0.50. The points started far from the "
         "density's distribution and the iteration moves them across the domain slowly; start "
         "from points drawn from the density (random points with the same density), as "
         "redistribute='auto' (cvt2 --redistribute auto), the default, does";
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_DENSITY_RESPONSE_2_H
