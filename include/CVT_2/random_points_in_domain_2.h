// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// random_points_in_domain_2(): seeded initial generators, uniform or following a density.
#ifndef CVT_2_RANDOM_POINTS_IN_DOMAIN_2_H
#define CVT_2_RANDOM_POINTS_IN_DOMAIN_2_H

#include <CVT_2/Concepts/DensityFunction_2.h>
#include <CVT_2/exceptions.h>
#include <CVT_2/internal/domain_pieces.h>
#include <CVT_2/internal/domain_regions.h>
#include <CVT_2/internal/parallel/Interrupt_scope.h>
#include <CVT_2/parameters.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/squared_distance_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

namespace CVT_2 {
namespace internal {

// A uniform double in [0, 1) from 53 random bits: the same sequence on every platform, which
// the standard distributions do not promise.
inline double uniform01(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

// A point drawn uniformly in triangle t (rounded).
template <class Point_2>
Point_2 random_point_in_triangle(const std::array<Point_2, 3>& t, std::mt19937_64& rng) {
  double s = uniform01(rng), u = uniform01(rng);
  if (s + u > 1) s = 1 - s, u = 1 - u;
  const Point_2& o = t[0];
  return Point_2(o.x() + s * (t[1].x() - o.x()) + u * (t[2].x() - o.x()),
                 o.y() + s * (t[1].y() - o.y()) + u * (t[2].y() - o.y()));
}

template <class Point_2>
bool in_closed_triangle(const std::array<Point_2, 3>& t, const Point_2& p) {
  return CGAL::orientation(t[0], t[1], p) != CGAL::RIGHT_TURN &&
         CGAL::orientation(t[1], t[2], p) != CGAL::RIGHT_TURN &&
         CGAL::orientation(t[2], t[0], p) != CGAL::RIGHT_TURN;
}

template <class Point_2>
const Point_2& nearest_vertex(const std::array<Point_2, 3>& t, const Point_2& p) {
  const Point_2& ab = CGAL::compare_distance_to_point(p, t[0], t[1]) == CGAL::LARGER ? t[1] : t[0];
  return CGAL::compare_distance_to_point(p, ab, t[2]) == CGAL::LARGER ? t[2] : ab;
}

}  // namespace internal

/// \ingroup PkgCvt2Ref
/// `n` random points in the domain of `cdt`, reproducible from a seed: a triangle is drawn
/// with probability proportional to its mass (among its region's, with `by_region`), then a
/// point uniformly in it. Uniform: the
/// domain faces, by area, exactly. With a density: the domain faces cut by longest-edge
/// bisection into about `max(n, 10000)` triangles of equal area, and further where
/// \f$\rho\f$ differs more than twice at their edges' midpoints (down to 1/4096 of that
/// area), each weighted by \f$\int\rho\f$ (midpoint rule), so the sample follows \f$\rho\f$
/// at a resolution finer than the cells it seeds, a steep refinement too. A CVT of density
/// \f$\rho\f$ has about \f$\rho^{1/2}\f$ points per unit area in 2D: sampling with
/// \f$\rho^{1/2}\f$ starts Lloyd iteration close to it.
/// \param cdt a triangulation whose domain is marked
/// \param n how many points
/// \param np optional: `density(rho)` (default uniform; a density with the batch member of
///        `DensityFunction_2` is called once a round of cuts, for all its sub-triangles), or
///        `sizing_field(mu)` for the density \f$1/\mu^2\f$ that starts Lloyd iteration under
///        `sizing_field(mu)` (\f$\rho = 1/\mu^4\f$) close to its result; `random_seed(s)` (default
///        0); `by_region(true)`: the points dealt to the regions that constraints separate (a
///        county network's counties, islands), each its share of the mass less the cells of
///        the generators already on its boundary or inside it (by area where the mass is 0
///        or infinite), then drawn in each; the regions
///        then have the number of cells their area asks for, which the optimization cannot
///        change (no generator crosses a constraint): independent draws leave a region of k
///        cells about sqrt(k) cells off (default false: independent draws, as before). It
///        numbers the domain's faces in their `id()` (`Bvd_face_base_2`);
///        `keep_out(disks)` (an object with `bool contains(const Point_2&) const`, such as
///        `Conforming_disks`): a point drawn where `disks.contains()` it is drawn again in
///        its region, up to 63 times (then kept), so that the regions keep their counts.
/// \throws Domain_error if the domain is empty; the density's own errors.
template <class CDT, class NP = No_named_parameters>
std::vector<typename CDT::Point_2> random_points_in_domain_2(
    const CDT& cdt, std::size_t n, const NP& np = parameters::default_values()) {
  using namespace internal_np;
  using Point_2 = typename CDT::Point_2;
  using Triangle = std::array<Point_2, 3>;
  const std::uint64_t seed = choose_parameter(get_parameter(np, random_seed_t()), std::uint64_t(0));
  std::mt19937_64 rng(seed);
  const internal::Domain_triangles<Point_2> domain = internal::domain_triangles(cdt);
  double domain_area = 0;
  for (const Triangle& t : domain.triangles) domain_area += domain.area(t);
  if (!(domain_area > 0)) throw Domain_error("random points: the domain is empty");
  // The triangles to draw from, with their masses, and the face each lies in.
  const internal::Domain_pieces<Point_2> weighed = internal::weigh_domain(domain, n, np);
  const std::vector<Triangle>& pieces = weighed.cut.empty() ? domain.triangles : weighed.cut;
  const std::vector<std::size_t>& face_of = weighed.face_of;
  const std::vector<double>& mass = weighed.mass;
  // The pieces in the order they are drawn from, and the ranges of that order with their
  // quotas of points: all at once, or region by region.
  std::vector<std::size_t> piece(pieces.size());
  std::iota(piece.begin(), piece.end(), std::size_t(0));
  std::vector<std::size_t> range_end{pieces.size()}, quota{n};
  if (choose_parameter(get_parameter(np, by_region_t()), false)) {
    const internal::Domain_regions<CDT> regions = internal::domain_regions(cdt);
    const std::vector<std::size_t>& region = regions.region;
    const auto face = [&](std::size_t k) { return face_of.empty() ? k : face_of[k]; };
    std::vector<double> face_mass(regions.faces.size(), 0.0);
    for (std::size_t k = 0; k < piece.size(); ++k) face_mass[face(k)] += mass[k];
    quota = internal::region_quotas(cdt, n, regions, face_mass, domain, seed);
    std::stable_sort(piece.begin(), piece.end(), [&](std::size_t a, std::size_t b) {
      return region[face(a)] < region[face(b)];
    });
    range_end.assign(regions.regions, 0);
    for (const std::size_t k : piece) ++range_end[region[face(k)]];
    std::partial_sum(range_end.begin(), range_end.end(), range_end.begin());
  }
  std::vector<double> cumulative(piece.size());  // the masses in the order drawn from, summed
  double total = 0;
  for (std::size_t i = 0; i < piece.size(); ++i) cumulative[i] = total += mass[piece[i]];
  // Rounding may put a point drawn by a boundary edge just outside the domain face its piece
  // was cut from (a piece's cut points are rounded too): it is drawn again, and so is a point
  // in a circle to keep out of, in its region. A needle thinner than double precision can
  // resolve (a vertex at 1e124 among vertices at 10) holds almost no double point and would
  // reject draws forever: after 64 misses in a row, the vertex of the face nearest to the draw
  // is taken instead (or the point in a circle kept).
  const auto kept_out = [&](const Point_2& p) {
    if constexpr (has_parameter<NP, keep_out_t>)
      return get_parameter(np, keep_out_t()).contains(p);
    else
      return false;
  };
  std::vector<Point_2> points;
  points.reserve(n);
  for (std::size_t r = 0; r < quota.size(); ++r) {
    const std::size_t begin = r > 0 ? range_end[r - 1] : 0, end = range_end[r];
    const double low = begin > 0 ? cumulative[begin - 1] : 0.0;
    const double range_mass = cumulative[end - 1] - low;
    std::size_t misses = 0;
    for (std::size_t drawn = 0; drawn < quota[r];) {
      internal::poll_interrupt_sometimes();
      const double u = low + internal::uniform01(rng) * range_mass;
      const std::size_t i =
          std::min<std::size_t>(std::upper_bound(cumulative.begin() + std::ptrdiff_t(begin),
                                                 cumulative.begin() + std::ptrdiff_t(end), u) -
                                    cumulative.begin(),
                                end - 1);
      const std::size_t k = piece[i];
      const Triangle& face = face_of.empty() ? pieces[k] : domain.triangles[face_of[k]];
      const Point_2 p = internal::random_point_in_triangle(pieces[k], rng);
      const bool inside = internal::in_closed_triangle(face, p);
      if (!(inside && !kept_out(p)) && ++misses < 64) continue;
      points.push_back(inside ? p : internal::nearest_vertex(face, p));
      misses = 0;
      ++drawn;
    }
  }
  return points;
}

}  // namespace CVT_2

#endif  // CVT_2_RANDOM_POINTS_IN_DOMAIN_2_H
