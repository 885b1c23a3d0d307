// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Point_refinement_sizing_2: a background cell size, finer around given points (wells).
#ifndef CVT_2_POINT_REFINEMENT_SIZING_2_H
#define CVT_2_POINT_REFINEMENT_SIZING_2_H

#include <CVT_2/internal/to_string.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace CVT_2 {

/// \ingroup PkgCvt2Policies
/// A sizing field of size `background` everywhere but around refinement points: a point `c`
/// with size `s` and radius `r` asks for cells of spacing `s` at `c`, growing linearly with the
/// distance to `background` at distance `r`; where several ask, the finest wins:
/// \f$\mu(p) = \min(B, \min_i s_i + (B - s_i)\min(1, |p - c_i| / r_i))\f$.
/// This is what a groundwater modeller asks around a well, as MODFLOW's gridding tools refine a
/// quadtree around it. With a fixed number of generators, the ratios of the sizes are what the
/// optimizer follows: the cells far away come out as `background` only if the number of
/// generators matches it.
///
/// \tparam K a CGAL kernel.
/// \cgalModels `SizingField_2`
template <class K>
class Point_refinement_sizing_2 {
 public:
  using Geom_traits = K;                ///< the kernel
  using FT = typename K::FT;            ///< the number type
  using Point_2 = typename K::Point_2;  ///< the point type

  /// The size `background` everywhere. \throws std::invalid_argument unless it is positive
  /// and finite.
  explicit Point_refinement_sizing_2(double background) : m_background(background) {
    check("background size", background);
  }

  /// Cells of spacing `size` at `center`, growing to the background size at distance
  /// `radius`. \throws std::invalid_argument unless `size` and `radius` are positive and
  /// finite, and `size` at most the background size.
  void add_point(const Point_2& center, double size, double radius) {
    check("refinement size", size);
    check("refinement radius", radius);
    if (size > m_background)
      throw std::invalid_argument("Point_refinement_sizing_2: the refinement size " +
                                  internal::number_to_string(size) + " at " +
                                  internal::to_string(center) + " exceeds the background size " +
                                  internal::number_to_string(m_background));
    m_points.push_back({CGAL::to_double(center.x()), CGAL::to_double(center.y()), size, radius});
  }

  /// \f$\mu(p)\f$
  FT operator()(const Point_2& p) const {
    double mu = m_background;
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
    for (const Refinement& r : m_points) {
      const double t = std::min(1.0, std::hypot(x - r.x, y - r.y) / r.radius);
      mu = std::min(mu, r.size + (m_background - r.size) * t);
    }
    return FT(mu);
  }

  double background() const { return m_background; }  ///< the background size

 private:
  struct Refinement {
    double x, y, size, radius;
  };
  static void check(const char* what, double value) {
    if (!(value > 0) || !std::isfinite(value))
      throw std::invalid_argument(std::string("Point_refinement_sizing_2: the ") + what +
                                  " must be positive and finite, not " +
                                  internal::number_to_string(value));
  }
  double m_background;
  std::vector<Refinement> m_points;
};

}  // namespace CVT_2

#endif  // CVT_2_POINT_REFINEMENT_SIZING_2_H
