// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The domain's triangles cut into pieces and weighed by a point density: what random points
// are drawn from, and the mass that sets the cells' size under a density.
#ifndef CVT_2_INTERNAL_DOMAIN_PIECES_H
#define CVT_2_INTERNAL_DOMAIN_PIECES_H

#include <CVT_2/Concepts/DensityFunction_2.h>
#include <CVT_2/exceptions.h>
#include <CVT_2/internal/domain_regions.h>
#include <CVT_2/internal/parallel/Interrupt_scope.h>
#include <CVT_2/parameters.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>

namespace CVT_2 {
namespace internal {

// `t` cut in two at its longest edge's midpoint, or false if that midpoint rounds to an end (a
// triangle a few units in the last place wide, which cuts would not shrink).
template <class Point_2>
bool halve_longest_edge(const Domain_triangles<Point_2>& d, const std::array<Point_2, 3>& t,
                        std::array<std::array<Point_2, 3>, 2>& halves) {
  const int k = d.opposite_longest_edge(t);
  const Point_2 m = CGAL::midpoint(t[(k + 1) % 3], t[(k + 2) % 3]);
  if (m == t[(k + 1) % 3] || m == t[(k + 2) % 3]) return false;
  halves = {{{t[k], t[(k + 1) % 3], m}, {t[k], m, t[(k + 2) % 3]}}};
  return true;
}

// The triangles of `d` cut by longest-edge bisection until each has an area of at most
// `small`, or cannot be cut (halve_longest_edge()); `face_of` gets the triangle each piece was
// cut from.
template <class Point_2>
std::vector<std::array<Point_2, 3>> bisect_triangles(const Domain_triangles<Point_2>& d,
                                                     double small,
                                                     std::vector<std::size_t>& face_of) {
  using Triangle = std::array<Point_2, 3>;
  std::vector<Triangle> pieces, stack;
  std::array<Triangle, 2> halves;
  for (std::size_t f = 0; f < d.triangles.size(); ++f) {
    stack.assign(1, d.triangles[f]);
    while (!stack.empty()) {
      poll_interrupt_sometimes();
      const Triangle u = stack.back();
      stack.pop_back();
      if (d.area(u) <= small || !halve_longest_edge(d, u, halves)) {
        pieces.push_back(u);
        face_of.push_back(f);
        continue;
      }
      stack.push_back(halves[0]);
      stack.push_back(halves[1]);
    }
  }
  return pieces;
}

// The pieces of the domain and their masses, at the domain's scale: without a density its
// triangles (`cut` and `face_of` empty), by area; with the point density of `np` (`density(d)`,
// or `sizing_field(mu)` for d = 1/mu^2) its triangles cut by longest-edge bisection into pieces
// of at most 1/max(n, 10000) of its area, and further where d varies much over one, each
// weighed by the integral of d (midpoint rule).
template <class Point_2>
struct Domain_pieces {
  std::vector<std::array<Point_2, 3>> cut;
  std::vector<std::size_t> face_of;  // the domain triangle each piece was cut from
  std::vector<double> mass;
};

template <class Point_2, class NP>
Domain_pieces<Point_2> weigh_domain(const Domain_triangles<Point_2>& domain, std::size_t n,
                                    const NP& np) {
  using namespace internal_np;
  using Triangle = std::array<Point_2, 3>;
  using K = typename CGAL::Kernel_traits<Point_2>::Kernel;
  Domain_pieces<Point_2> w;
  const auto weigh_pieces = [&](const auto& rho) {
    double domain_area = 0;
    for (const Triangle& t : domain.triangles) domain_area += domain.area(t);
    const double piece_area = domain_area / double(std::max<std::size_t>(n, 10000));
    std::vector<std::size_t> face_of;
    std::vector<Triangle> todo = bisect_triangles(domain, piece_area, face_of);
    const std::size_t most = 2 * todo.size() + 100000;
    // The values at the midpoints of the edges of `todo`, three a piece.
    std::vector<double> values;
    const auto evaluate = [&] {
      std::vector<Point_2> midpoints;
      midpoints.reserve(3 * todo.size());
      for (const Triangle& t : todo)
        for (int i = 0; i < 3; ++i) midpoints.push_back(CGAL::midpoint(t[i], t[(i + 1) % 3]));
      values.clear();
      using Rho = std::decay_t<decltype(rho)>;
      if constexpr (has_batch_evaluation_v<Rho, K>) {
        // A density evaluated in batches (DensityFunction_2::evaluate()): one call a round.
        std::vector<typename K::FT> got;
        rho.evaluate(midpoints, got);
        if (got.size() != midpoints.size())
          throw Domain_error("random points: the density's batch evaluation gave " +
                             std::to_string(got.size()) + " values for " +
                             std::to_string(midpoints.size()) + " points");
        for (const auto& v : got) values.push_back(CGAL::to_double(v));
      } else {
        for (const Point_2& m : midpoints) values.push_back(CGAL::to_double(rho(m)));
      }
    };
    // A piece over which the density varies by more than twice is cut in two, down to 1/4096
    // of the pieces' area (a steep refinement around a well within a piece, or next to the
    // tiny faces that a conforming line's pairs make there, would be weighed by values far from
    // its mean), while the pieces number at most twice as many, and 100 000 more.
    std::array<Triangle, 2> halves;
    for (int round = 0; !todo.empty(); ++round) {
      evaluate();
      std::vector<Triangle> next;
      std::vector<std::size_t> next_face;
      for (std::size_t j = 0; j < todo.size(); ++j) {
        const double* v = &values[3 * j];
        const Triangle& t = todo[j];
        const double area = domain.area(t);
        if (std::max({v[0], v[1], v[2]}) > 2 * std::min({v[0], v[1], v[2]}) && round < 12 &&
            area > piece_area / 4096 && w.cut.size() + next.size() + todo.size() < most &&
            halve_longest_edge(domain, t, halves)) {
          next.push_back(halves[0]);
          next.push_back(halves[1]);
          next_face.insert(next_face.end(), 2, face_of[j]);
          continue;
        }
        w.cut.push_back(t);
        w.face_of.push_back(face_of[j]);
        w.mass.push_back(area * (v[0] + v[1] + v[2]) / 3);
      }
      todo.swap(next);
      face_of.swap(next_face);
    }
  };
  static_assert(!(has_parameter<NP, density_t> && has_parameter<NP, sizing_field_t>),
                "give either density() or sizing_field(), not both");
  if constexpr (has_parameter<NP, density_t>) {
    weigh_pieces(get_parameter(np, density_t()));
  } else if constexpr (has_parameter<NP, sizing_field_t>) {
    const auto& mu = get_parameter(np, sizing_field_t());
    weigh_pieces([&mu](const Point_2& p) {
      const double m = CGAL::to_double(mu(p));
      return 1 / (m * m);
    });
  } else {
    for (const Triangle& t : domain.triangles) w.mass.push_back(domain.area(t));
  }
  return w;
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_DOMAIN_PIECES_H
