// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The domain's triangles and the regions that its constraints separate, with the points each
// region's mass asks for: random_points_in_domain_2() deals by them, density_response_2()
// checks an optimization's counts against them.
#ifndef CVT_2_INTERNAL_DOMAIN_REGIONS_H
#define CVT_2_INTERNAL_DOMAIN_REGIONS_H

#include <CVT_2/internal/layout/Handle_numbering.h>
#include <CVT_2/internal/parallel/Interrupt_scope.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

// Lengths measured in units of 2^e, the domain's scale, so that areas and squared lengths
// neither underflow nor overflow (a domain 1e-300 wide is not empty). Areas only weigh the
// triangles against each other.
template <class Point_2>
struct Domain_scale {
  using Triangle = std::array<Point_2, 3>;
  int e = 0;

  double dx(const Point_2& a, const Point_2& b) const {
    return std::ldexp(CGAL::to_double(b.x() - a.x()), -e);
  }
  double dy(const Point_2& a, const Point_2& b) const {
    return std::ldexp(CGAL::to_double(b.y() - a.y()), -e);
  }
  // The vertex opposite the longest edge of t.
  int opposite_longest_edge(const Triangle& t) const {
    int o = 0;
    double longest = -1;
    for (int i = 0; i < 3; ++i) {
      const Point_2& a = t[(i + 1) % 3];
      const Point_2& b = t[(i + 2) % 3];
      const double l = dx(a, b) * dx(a, b) + dy(a, b) * dy(a, b);
      if (l > longest) longest = l, o = i;
    }
    return o;
  }
  // The area of t, from the vertex opposite its longest edge: from the tip of a needle, the two
  // long edges' cross product would cancel to zero.
  double area(const Triangle& t) const {
    const int o = opposite_longest_edge(t);
    const Point_2& a = t[o];
    const Point_2& b = t[(o + 1) % 3];
    const Point_2& c = t[(o + 2) % 3];
    return (dx(a, b) * dy(a, c) - dy(a, b) * dx(a, c)) / 2;
  }
};

// The triangles of the domain, at its scale.
template <class Point_2>
struct Domain_triangles : Domain_scale<Point_2> {
  std::vector<std::array<Point_2, 3>> triangles;
};

template <class Face_handle>
auto face_triangle(Face_handle f) {
  return std::array{f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()};
}

// The domain's scale: its triangles' extent.
template <class CDT>
Domain_scale<typename CDT::Point_2> domain_scale(const CDT& cdt) {
  Domain_scale<typename CDT::Point_2> d;
  double extent = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_inside_domain()) continue;
    const auto t = face_triangle(f);
    for (int i = 1; i < 3; ++i)
      extent = std::max({extent, std::abs(CGAL::to_double(t[i].x() - t[0].x())),
                         std::abs(CGAL::to_double(t[i].y() - t[0].y()))});
  }
  if (extent > 0) std::frexp(extent, &d.e);
  return d;
}

// The domain's triangles, at its scale.
template <class CDT>
Domain_triangles<typename CDT::Point_2> domain_triangles(const CDT& cdt) {
  Domain_triangles<typename CDT::Point_2> d;
  static_cast<Domain_scale<typename CDT::Point_2>&>(d) = domain_scale(cdt);
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->is_inside_domain()) d.triangles.push_back(face_triangle(f));
  return d;
}

// The domain's faces, in the order of domain_triangles(), each numbered with its place there
// (in the face's id where it has one) and given its region: the faces joined across edges that
// are not constraints.
template <class CDT>
struct Domain_regions {
  using Face_handle = typename CDT::Face_handle;
  std::vector<Face_handle> faces;
  Handle_numbering<Face_handle> index;
  std::vector<std::size_t> region;  // of each face
  std::size_t regions = 0;
  // the place of f among `faces`, or faces.size() if f is not the domain's
  std::size_t find(const CDT& cdt, Face_handle f) const {
    return !cdt.is_infinite(f) && f->is_inside_domain() ? index.get(f) : faces.size();
  }
};

template <class CDT>
Domain_regions<CDT> domain_regions(const CDT& cdt) {
  using Face_handle = typename CDT::Face_handle;
  Domain_regions<CDT> d;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->is_inside_domain()) d.faces.push_back(f);
  d.index.reserve(d.faces.size());
  for (std::size_t k = 0; k < d.faces.size(); ++k) d.index.set(d.faces[k], k);
  const std::size_t none = d.faces.size();
  d.region.assign(d.faces.size(), none);
  std::vector<std::size_t> stack;
  for (std::size_t seed = 0; seed < d.faces.size(); ++seed) {
    if (d.region[seed] != none) continue;
    d.region[seed] = d.regions;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const Face_handle f = d.faces[stack.back()];
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        if (cdt.is_constrained(typename CDT::Edge(f, i))) continue;
        const std::size_t g = d.find(cdt, f->neighbor(i));
        if (g == none || d.region[g] != none) continue;
        d.region[g] = d.regions;
        stack.push_back(g);
      }
    }
    ++d.regions;
  }
  return d;
}

// The free points' shares of the regions that the constraints separate (by_region): region r
// gets `n` times its weight, its mass less its generators' shares, over the sum of the
// weights (region_weights()), rounded to whole points by largest remainder (region_quotas()).
// A generator inside a region holds one cell's mass m there (the domain's mass over its cells,
// these n included). A generator on a constraint holds, in each wedge of a region that meets
// it, `constrained_vertex_share` of m, whatever the wedge's angle (a crack's tip, one wedge all
// round, too); less where its two constrained edges there are on average shorter than half a
// cell size (a finely digitised line, whose vertices' cells are slivers): that times their
// mean length over half the size.
//
// The share was measured: cvt2 --cells 2000 --boundary slide on Kentucky's 120 counties,
// normalized energy at the stop, mean of seeds 1 to 6: 1.1328 with 0.3, 1.1318 with 0.35,
// 1.1322 with 0.4, 1.1335 with 0.45; seeds 1 to 3: 1.143 by the regions' masses alone (0),
// 1.146 with 0.55; seed 1 with independent draws, 1.220. The world's islands gain up to 0.55.
inline constexpr double constrained_vertex_share = 0.35;

// What the regions weigh before `n` free points are dealt to them: each region's mass, and its
// weight, the mass less the shares of the generators of `cdt` in the domain with holds(v).
struct Region_weights {
  std::vector<double> mass, weight;
  double total = 0;      // the domain's mass (its area, where the mass is 0 or infinite)
  double cell_mass = 0;  // m: the domain's mass over its cells, the n included
};

template <class CDT, class Holds>
Region_weights region_weights(const CDT& cdt, std::size_t n, const Domain_regions<CDT>& d,
                              std::vector<double> mass,
                              const Domain_scale<typename CDT::Point_2>& scale,
                              const Holds& holds) {
  using Face_handle = typename CDT::Face_handle;
  const std::vector<Face_handle>& faces = d.faces;
  const std::vector<std::size_t>& face_region = d.region;
  const std::size_t regions = d.regions;
  Region_weights out;
  double& total = out.total;
  total = std::accumulate(mass.begin(), mass.end(), 0.0);
  if (!(total > 0 && total < HUGE_VAL)) {  // a density of no mass or an infinite one: by area
    for (std::size_t f = 0; f < faces.size(); ++f) mass[f] = scale.area(face_triangle(faces[f]));
    total = std::accumulate(mass.begin(), mass.end(), 0.0);
  }
  std::vector<double>& region_mass = out.mass;
  region_mass.assign(regions, 0.0);
  for (std::size_t f = 0; f < faces.size(); ++f) region_mass[face_region[f]] += mass[f];
  std::vector<double>& weight = out.weight;
  weight = region_mass;  // less the generators' shares, below
  // the domain's face at v, if any: v is a generator of the domain
  const auto face_at = [&](const auto v) {
    auto fc = cdt.incident_faces(v), done = fc;
    do
      if (const std::size_t f = d.find(cdt, fc); f < faces.size()) return f;
    while (++fc != done);
    return faces.size();
  };
  std::size_t cells = n;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (holds(v) && face_at(v) < faces.size()) ++cells;
  const double m = out.cell_mass = total / double(cells);
  std::vector<Face_handle> around;
  std::vector<char> cut;
  std::vector<double> length;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    poll_interrupt_sometimes();
    if (!holds(v)) continue;
    around.clear();
    auto fc = cdt.incident_faces(v), done = fc;
    do around.push_back(fc);
    while (++fc != done);
    const std::size_t k = around.size();
    // The edge between around[t] and around[t + 1]: whether a constraint, and its length.
    cut.assign(k, 0);
    length.assign(k, 0.0);
    for (std::size_t t = 0; t < k; ++t) {
      const Face_handle f = around[t], g = around[(t + 1) % k];
      const int j = f->index(g);
      cut[t] = cdt.is_constrained(typename CDT::Edge(f, j));
      if (!cut[t]) continue;  // (an edge to the infinite vertex is never a constraint)
      const auto& a = f->vertex(CDT::ccw(j))->point();
      const auto& b = f->vertex(CDT::cw(j))->point();
      length[t] = std::hypot(scale.dx(a, b), scale.dy(a, b));
    }
    const auto first_cut = std::find(cut.begin(), cut.end(), char(1));
    if (first_cut == cut.end()) {  // a generator inside a region: a whole cell
      if (const std::size_t f = face_at(v); f < faces.size()) weight[face_region[f]] -= m;
      continue;
    }
    // The wedges between consecutive constraints around v.
    const std::size_t t0 = std::size_t(first_cut - cut.begin());
    std::size_t last_cut = t0, region = regions;
    double wedge_mass = 0, wedge_area = 0;
    for (std::size_t s = 1; s <= k; ++s) {
      const std::size_t t = (t0 + s) % k;
      if (const std::size_t f = d.find(cdt, around[t]); f < faces.size()) {
        region = face_region[f];
        wedge_mass += mass[f];
        wedge_area += scale.area(face_triangle(faces[f]));
      }
      if (!cut[t]) continue;
      if (region < regions && wedge_mass > 0) {
        // the cell size at which the wedge's mass per area makes cells of mass m
        const double size = std::sqrt(m * wedge_area / wedge_mass / (std::sqrt(3.0) / 2));
        const double edges = (length[last_cut] + length[t]) / 2;
        weight[region] -= constrained_vertex_share * m * std::min(1.0, edges / (size / 2));
      }
      last_cut = t;
      region = regions;
      wedge_mass = wedge_area = 0;
    }
  }
  return out;
}

// The `n` free points' shares of the regions by their weights `w`, rounded to whole points by
// largest remainder.
inline std::vector<std::size_t> region_quotas(const Region_weights& w, std::size_t n,
                                              std::uint64_t seed) {
  const std::size_t regions = w.mass.size();
  std::vector<double> weight = w.weight;
  double sum = 0;
  for (double& x : weight) sum += (x = std::max(x, 0.0));
  if (!(sum > 0)) {  // generators fill every region already: by mass alone
    weight = w.mass;
    sum = w.total;
  }
  std::vector<std::size_t> quota(regions, 0);
  std::vector<double> remainder(regions);
  std::size_t dealt = 0;
  for (std::size_t r = 0; r < regions; ++r) {
    const double q = double(n) * (weight[r] / sum);
    quota[r] = std::size_t(q);
    remainder[r] = q - double(quota[r]);
    dealt += quota[r];
  }
  // The largest remainders first. Equal ones (a grid of equal squares: the same to 2^-30, to
  // the nearest, as rounding leaves them) in an order drawn from the seed, apart from the
  // points' draws: in the faces' order, the same regions would get the extra points whatever
  // the seed, and no optimization moves them out.
  std::vector<double> rank(regions);
  std::vector<std::uint64_t> tie(regions);
  std::mt19937_64 tie_rng(seed ^ 0x9e3779b97f4a7c15u);
  for (std::size_t r = 0; r < regions; ++r)
    rank[r] = std::nearbyint(std::ldexp(remainder[r], 30)), tie[r] = tie_rng();
  std::vector<std::size_t> order(regions);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return rank[a] != rank[b] ? rank[a] > rank[b] : tie[a] < tie[b];
  });
  for (std::size_t i = 0; dealt < n; i = (i + 1) % regions) ++quota[order[i]], ++dealt;
  for (std::size_t i = 0; dealt > n; i = (i + 1) % regions)
    if (quota[order[regions - 1 - i]] > 0) --quota[order[regions - 1 - i]], --dealt;
  return quota;
}

// The free points' shares of the regions (region_weights(), every generator holding).
template <class CDT>
std::vector<std::size_t> region_quotas(const CDT& cdt, std::size_t n, const Domain_regions<CDT>& d,
                                       std::vector<double> mass,
                                       const Domain_scale<typename CDT::Point_2>& scale,
                                       std::uint64_t seed) {
  return region_quotas(region_weights(cdt, n, d, std::move(mass), scale, [](auto) { return true; }),
                       n, seed);
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_DOMAIN_REGIONS_H
