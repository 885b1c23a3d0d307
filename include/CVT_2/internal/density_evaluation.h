// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// A user's density at the points a quadrature asks for: checked, point by point or in batches.
#ifndef CVT_2_INTERNAL_DENSITY_EVALUATION_H
#define CVT_2_INTERNAL_DENSITY_EVALUATION_H

#include <CVT_2/exceptions.h>
#include <CVT_2/internal/to_string.h>
#include <CVT_2/internal/valid_point.h>

#include <CGAL/number_utils.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

// A density value that is not positive and finite, at p.
template <class FT, class Point_2>
Domain_error bad_density_error(const FT& r, const Point_2& p) {
  return Domain_error("the density is " + number_to_string(r) + " at " + to_string(p) +
                      ": it must be positive and finite");
}

// What a density's restrict_to_disk() returns; std::nullptr_t if it has none.
template <class Density, class Point_2, class FT, class = void>
struct Restriction_type {
  using type = std::nullptr_t;
};
template <class Density, class Point_2, class FT>
struct Restriction_type<Density, Point_2, FT,
                        std::void_t<decltype(std::declval<const Density&>().restrict_to_disk(
                            std::declval<const Point_2&>(), std::declval<const FT&>()))>> {
  using type = decltype(std::declval<const Density&>().restrict_to_disk(
      std::declval<const Point_2&>(), std::declval<const FT&>()));
};

// Checks each value of a user density: a value that is not positive and finite names the point.
template <class Density, class Point_2>
struct Checked_density {
  const Density& rho;
  auto operator()(const Point_2& p) const {
    const auto r = rho(p);
    if (!is_positive_finite(r)) throw bad_density_error(r, p);
    return r;
  }
};

// The values of a batch density (DensityFunction_2::evaluate()) at `points`, checked as
// Checked_density checks them, and their count.
template <class Density, class Point_2, class FT>
void evaluate_in_batch(const Density& rho, const std::vector<Point_2>& points,
                       std::vector<FT>& values) {
  values.clear();
  rho.evaluate(points, values);
  if (values.size() != points.size())
    throw Domain_error("the density's batch evaluation gave " + std::to_string(values.size()) +
                       " values for " + std::to_string(points.size()) + " points");
  if (!all_positive_finite(values))
    for (std::size_t i = 0; i < points.size(); ++i)
      if (!is_positive_finite(values[i])) throw bad_density_error(values[i], points[i]);
}

// The two quadrature passes over a chunk of cells with a batch density: the first records the
// points the quadrature asks for (its moments, with a density of 1, are not used), the second
// gives it the batch's values at them, in the same order.
template <class Point_2, class FT>
struct Recording_density {
  std::vector<Point_2>* points;
  FT operator()(const Point_2& p) const {
    points->push_back(p);
    return FT(1);
  }
};

template <class Point_2, class FT>
struct Replaying_density {
  const std::vector<Point_2>* points;
  const std::vector<FT>* values;
  std::size_t* next;
  FT operator()(const Point_2& p) const {
    const std::size_t i = (*next)++;
    if (i >= points->size() || !((*points)[i] == p))
      throw std::logic_error(
          "a density evaluated in batches needs a quadrature that asks for the same points, in "
          "the same order, whatever the density's values");
    return (*values)[i];
  }
};

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_DENSITY_EVALUATION_H
