// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// random_points_in_domain_2(): seeded initial generators, uniform or following a density.
#ifndef CVT_2_RANDOM_POINTS_IN_DOMAIN_2_H
#define CVT_2_RANDOM_POINTS_IN_DOMAIN_2_H

#include <CVT_2/exceptions.h>
#include <CVT_2/parameters.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/squared_distance_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace CVT_2 {
namespace internal {

// A uniform double in [0, 1) from 53 random bits: the same sequence on every platform, which
// the standard distributions do not promise.
inline double uniform01(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

}  // namespace internal

/// \ingroup PkgCvt2Ref
/// `n` random points in the domain of `cdt`, reproducible from a seed: a triangle is drawn
/// with probability proportional to its mass, then a point uniformly in it. Uniform: the
/// domain faces, by area, exactly. With a density: the domain faces cut by longest-edge
/// bisection into about `max(n, 10000)` triangles of equal area, each weighted by
/// \f$\int\rho\f$ (midpoint rule), so the sample follows \f$\rho\f$ at a resolution finer
/// than the cells it seeds. A CVT of density \f$\rho\f$ has about \f$\rho^{1/2}\f$ points per
/// unit area in 2D: sampling with \f$\rho^{1/2}\f$ starts Lloyd iteration close to it.
/// \param cdt a triangulation whose domain is marked
/// \param n how many points
/// \param np optional: `density(rho)` (default uniform), `random_seed(s)` (default 0).
/// \throws Domain_error if the domain is empty; the density's own errors.
template <class CDT, class NP = No_named_parameters>
std::vector<typename CDT::Point_2> random_points_in_domain_2(
    const CDT& cdt, std::size_t n, const NP& np = parameters::default_values()) {
  using namespace internal_np;
  using Point_2 = typename CDT::Point_2;
  using Triangle = std::array<Point_2, 3>;
  std::mt19937_64 rng(choose_parameter(get_parameter(np, random_seed_t()), std::uint64_t(0)));
  std::vector<Triangle> triangles;
  double extent = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_inside_domain()) continue;
    triangles.push_back({f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()});
    for (int i = 1; i < 3; ++i)
      extent = std::max({extent, std::abs(CGAL::to_double(triangles.back()[i].x() - triangles.back()[0].x())),
                         std::abs(CGAL::to_double(triangles.back()[i].y() - triangles.back()[0].y()))});
  }
  // Areas only weigh the triangles against each other: measured in units of 2^e, the domain's
  // scale, they neither underflow nor overflow (a domain 1e-300 wide is not empty). They are
  // taken from the vertex opposite the longest edge: from the tip of a needle, the two long
  // edges' cross product would cancel to zero.
  int e = 0;
  if (extent > 0) std::frexp(extent, &e);
  const auto area = [e](const Triangle& t) {
    int o = 0;  // the vertex opposite the longest edge
    double longest = -1;
    for (int i = 0; i < 3; ++i) {
      const double dx = std::ldexp(CGAL::to_double(t[(i + 2) % 3].x() - t[(i + 1) % 3].x()), -e);
      const double dy = std::ldexp(CGAL::to_double(t[(i + 2) % 3].y() - t[(i + 1) % 3].y()), -e);
      if (dx * dx + dy * dy > longest) longest = dx * dx + dy * dy, o = i;
    }
    const Point_2& a = t[o];
    const Point_2& b = t[(o + 1) % 3];
    const Point_2& c = t[(o + 2) % 3];
    const double ux = std::ldexp(CGAL::to_double(b.x() - a.x()), -e);
    const double uy = std::ldexp(CGAL::to_double(b.y() - a.y()), -e);
    const double vx = std::ldexp(CGAL::to_double(c.x() - a.x()), -e);
    const double vy = std::ldexp(CGAL::to_double(c.y() - a.y()), -e);
    return (ux * vy - uy * vx) / 2;
  };
  double domain_area = 0;
  for (const Triangle& t : triangles) domain_area += area(t);
  if (!(domain_area > 0)) throw Domain_error("random points: the domain is empty");
  std::vector<double> cumulative;
  double total = 0;
  std::vector<Triangle> faces;        // with a density: the domain faces, cut into `triangles`
  std::vector<std::size_t> face_of;   // the face each piece was cut from
  if constexpr (has_parameter<NP, density_t>) {
    const auto& rho = get_parameter(np, density_t());
    const double small = domain_area / double(std::max<std::size_t>(n, 10000));
    std::vector<Triangle> pieces, stack;
    for (std::size_t f = 0; f < triangles.size(); ++f) {
      stack.assign(1, triangles[f]);
      while (!stack.empty()) {
        const Triangle u = stack.back();
        stack.pop_back();
        if (area(u) <= small) {
          pieces.push_back(u);
          face_of.push_back(f);
          continue;
        }
        int k = 0;  // the vertex opposite the longest edge
        double longest = -1;
        for (int i = 0; i < 3; ++i) {
          const double l = CGAL::to_double(CGAL::squared_distance(u[(i + 1) % 3], u[(i + 2) % 3]));
          if (l > longest) longest = l, k = i;
        }
        const Point_2 m = CGAL::midpoint(u[(k + 1) % 3], u[(k + 2) % 3]);
        stack.push_back({u[k], u[(k + 1) % 3], m});
        stack.push_back({u[k], m, u[(k + 2) % 3]});
      }
    }
    faces.swap(triangles);
    triangles.swap(pieces);
    for (const Triangle& t : triangles) {
      double s = 0;
      for (int i = 0; i < 3; ++i) s += CGAL::to_double(rho(CGAL::midpoint(t[i], t[(i + 1) % 3])));
      total += area(t) * s / 3;
      cumulative.push_back(total);
    }
  } else {
    for (const Triangle& t : triangles) cumulative.push_back(total += area(t));
  }
  std::vector<Point_2> points;
  points.reserve(n);
  std::size_t misses = 0;  // draws in a row that fell outside their face
  while (points.size() < n) {
    const double u = internal::uniform01(rng) * total;
    const std::size_t k = std::min<std::size_t>(
        std::upper_bound(cumulative.begin(), cumulative.end(), u) - cumulative.begin(),
        triangles.size() - 1);
    double s = internal::uniform01(rng), t = internal::uniform01(rng);
    if (s + t > 1) s = 1 - s, t = 1 - t;
    const Triangle& piece = triangles[k];
    const Point_2& o = piece[0];
    Point_2 p(o.x() + s * (piece[1].x() - o.x()) + t * (piece[2].x() - o.x()),
              o.y() + s * (piece[1].y() - o.y()) + t * (piece[2].y() - o.y()));
    // Rounding may put a point drawn by a boundary edge just outside: draw again. The test is
    // against the domain face (a piece's cut points are rounded). A needle thinner than double
    // precision can resolve (a vertex at 1e124 among vertices at 10) holds almost no double
    // point and would reject draws forever: after 64 misses in a row, the vertex of the face
    // nearest to the draw is taken instead.
    const Triangle& face = face_of.empty() ? piece : faces[face_of[k]];
    const Point_2& a = face[0];
    const Point_2& b = face[1];
    const Point_2& c = face[2];
    if (CGAL::orientation(a, b, p) == CGAL::RIGHT_TURN ||
        CGAL::orientation(b, c, p) == CGAL::RIGHT_TURN ||
        CGAL::orientation(c, a, p) == CGAL::RIGHT_TURN) {
      if (++misses < 64) continue;
      const Point_2& ab = CGAL::compare_distance_to_point(p, a, b) == CGAL::LARGER ? b : a;
      p = CGAL::compare_distance_to_point(p, ab, c) == CGAL::LARGER ? c : ab;
    }
    misses = 0;
    points.push_back(p);
  }
  return points;
}

}  // namespace CVT_2

#endif  // CVT_2_RANDOM_POINTS_IN_DOMAIN_2_H
