// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// density_response_2(): whether the cells of a diagram follow a density, as a centroidal
// tessellation's do, or still have the sizes of the points they started from.
#ifndef CVT_2_DENSITY_RESPONSE_2_H
#define CVT_2_DENSITY_RESPONSE_2_H

#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/Concepts/DensityFunction_2.h>
#include <CVT_2/Optimization_result.h>
#include <CVT_2/Uniform_density_2.h>
#include <CVT_2/insert_generators_2.h>
#include <CVT_2/internal/Handle_set.h>
#include <CVT_2/internal/density_evaluation.h>
#include <CVT_2/internal/domain_regions.h>

#include <CGAL/Kernel/global_functions_2.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CVT_2 {

namespace internal {
struct Every_generator {
  template <class Vertex_handle>
  bool operator()(Vertex_handle) const {
    return true;
  }
};

// The values of rho at `points`, checked: a batch density (DensityFunction_2::evaluate()) in
// batches of 2^18 points (4 MiB of coordinates), not one of millions.
template <class K, class Density>
void density_values(const Density& rho, const std::vector<typename K::Point_2>& points,
                    std::vector<typename K::FT>& values) {
  using Point_2 = typename K::Point_2;
  values.clear();
  if constexpr (has_batch_evaluation_v<Density, K>) {
    constexpr std::size_t batch = std::size_t(1) << 18;
    std::vector<Point_2> some;
    std::vector<typename K::FT> got;
    for (std::size_t i = 0; i < points.size(); i += batch) {
      some.assign(points.begin() + std::ptrdiff_t(i),
                  points.begin() + std::ptrdiff_t(std::min(points.size(), i + batch)));
      evaluate_in_batch(rho, some, got);
      values.insert(values.end(), got.begin(), got.end());
    }
  } else {
    const Checked_density<Density, Point_2> checked{rho};
    for (const Point_2& p : points) values.push_back(checked(p));
  }
}

// The point counts of the regions that the constraints of `cdt` separate (a county network's
// counties, islands) into `out`, against those rho asks for: `moving(v)` says which free
// generators count, the others hold their shares of their regions as random_points_in_domain_2()
// deals them (region_weights()). A region of mass M (the integral of rho^(1/2), here by each
// domain face's area and rho at its centroid) in c cells has an energy of about M^2 / c
// (Gersho's law in 2D), least over the domain when c follows M. Nothing is measured with one
// region (islands are regions too), or fewer than Density_response::fewest_cells generators
// that count.
template <class CDT, class Density, class Moving>
void measure_region_counts(const CDT& cdt, const Density& rho, const Moving& moving,
                           Density_response& out) {
  using K = typename CDT::Geom_traits;
  using Point_2 = typename K::Point_2;
  const Domain_regions<CDT> d = domain_regions(cdt);
  if (d.regions < 2) return;
  const auto counts = [&](typename CDT::Vertex_handle v) {
    return !cdt.are_there_incident_constraints(v) && moving(v);
  };
  std::vector<double> count(d.regions, 0.0);
  std::size_t n = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    if (!counts(v)) continue;
    const std::size_t f = d.find(cdt, v->face());  // all its faces are the domain's, or none
    if (f == d.faces.size()) continue;
    count[d.region[f]] += 1;
    ++n;
  }
  if (n < Density_response::fewest_cells) return;
  // each face's mass: its area times rho^(1/2) at its centroid
  const Domain_scale<Point_2> scale = domain_scale(cdt);
  std::vector<double> mass;
  std::vector<Point_2> centroids;
  mass.reserve(d.faces.size());
  centroids.reserve(d.faces.size());
  for (const auto f : d.faces) {
    const auto t = face_triangle(f);
    mass.push_back(scale.area(t));
    centroids.push_back(CGAL::centroid(t[0], t[1], t[2]));
  }
  std::vector<typename K::FT> values;
  density_values<K>(rho, centroids, values);
  for (std::size_t f = 0; f < mass.size(); ++f) mass[f] *= std::sqrt(CGAL::to_double(values[f]));
  const Region_weights w = region_weights(
      cdt, n, d, std::move(mass), scale, [&](typename CDT::Vertex_handle v) { return !counts(v); });
  if (!(w.cell_mass > 0)) return;
  // The energy over Gersho's constant of region r in `held` cells of the generators that do not
  // count and c cells of those that do (a region of no cell at all would have an infinite
  // energy: a quarter cell bounds it), of the counts as they are and as they are dealt. The
  // law prices the differences; the reference is the dealing, tuned on optimized energies,
  // not the law's own optimum, which misplaces a point or two a region where regions hold
  // few (Kentucky at 1300 cells, 165 free points for 121 regions: 5% "above" it).
  const std::vector<std::size_t> dealt = region_quotas(w, n, 0);
  double as_they_are = 0, as_dealt = 0;
  std::size_t compared = 0;
  for (std::size_t r = 0; r < d.regions; ++r) {
    if (!(w.mass[r] > 0)) continue;  // (a region of no area)
    const double held = std::max(0.0, (w.mass[r] - w.weight[r]) / w.cell_mass);
    const auto energy = [&](double c) { return w.mass[r] * w.mass[r] / std::max(held + c, 0.25); };
    as_they_are += energy(count[r]);
    as_dealt += energy(double(dealt[r]));
    ++compared;
  }
  out.regions = compared;
  out.count_excess = as_they_are / as_dealt - 1;
}
}  // namespace internal

/// \ingroup PkgCvt2Ref
/// How the cells of the free generators of `bvd` follow the density `rho`: the least-squares
/// slope of log(area of the cell) against log(rho at its generator), and its standard error. The
/// cells of a centroidal Voronoi tessellation of a density have areas proportional to
/// \f$\rho^{-1/2}\f$ (Gersho's asymptotics, exact in 2D: their size scales as \f$\rho^{-1/4}\f$),
/// so its slope is about -1/2; cells of one size have 0. Lloyd iteration and L-BFGS move points
/// across the domain slowly: from points that do not follow the density (uniform ones under a
/// density of range 16, say), every move ratio falls below 1% long before the cells have the sizes
/// the density asks for, and the slope says so. `random_points_in_domain_2()` draws points that
/// follow it.
///
/// Only cells over which rho varies moderately take part: rho at each vertex of the cell within
/// a factor 8 of rho at its generator (where rho varies more within a cell, a feature smaller
/// than the cells or a step, the law does not hold even at the optimum, and such a cell would
/// say nothing of where its generator is; cells near a boundary where the automatic sizing
/// grows fast do, and must count). The slope is NaN if fewer than 3 cells take part, or if
/// rho varies by less than a factor 2 over them (too little to measure). \throws Domain_error
/// if a value of rho is not positive and finite, naming the point.
/// `moves(v)` says which free generators take part: those an optimization moves (not its
/// `fixed_points`, whose cells have the sizes their places give them); by default all. It
/// numbers the domain's faces in their `id()` (`Bvd_face_base_2`): not concurrently with
/// another pass that uses them on the same triangulation.
///
/// Where constraints cut the domain into regions (a county network's counties, islands), no
/// generator crosses from one to another, and the slope cannot see a region with too many
/// points or too few: each region's cells follow rho among themselves. So the regions' counts
/// of those free generators are compared too with the counts rho asks for, as
/// `random_points_in_domain_2()` deals them (`Density_response::count_excess`), with 128 of
/// them or more.
/// \tparam Diagram a `Bounded_voronoi_diagram_2`.
/// \tparam Density a model of `DensityFunction_2` (one with the batch member is called with
///         2^18 points at most).
/// \tparam Moves a predicate on `Diagram::Vertex_handle`.
template <class Diagram, class Density, class Moves = internal::Every_generator>
Density_response density_response_2(const Diagram& bvd, const Density& rho,
                                    const Moves& moves = Moves()) {
  using K = typename Diagram::Triangulation::Geom_traits;
  using Point_2 = typename K::Point_2;
  using FT = typename K::FT;
  Density_response out;
  internal::measure_region_counts(bvd.triangulation(), rho, moves, out);
  // each cell's generator, then its vertices; `first[k]`: where cell k's points start
  std::vector<Point_2> points;
  std::vector<std::size_t> first;
  std::vector<double> log_areas;
  bvd.for_each_cell([&](auto v, const auto& cell) {
    if (!bvd.is_free(v) || !moves(v)) return;
    // the fan from the generator, as Bvd_mesh_2::area(): no cancellation far from the origin
    double area = 0;
    for (std::size_t i = 0; i < cell.size(); ++i)
      area +=
          CGAL::to_double(CGAL::area(v->point(), cell[i].point, cell[(i + 1) % cell.size()].point));
    if (!(area > 0)) return;  // a cell that underflows says nothing
    first.push_back(points.size());
    points.push_back(v->point());
    for (const auto& c : cell) points.push_back(c.point);
    log_areas.push_back(std::log(area));
  });
  if (log_areas.size() < 3) return out;
  first.push_back(points.size());
  std::vector<FT> values;
  internal::density_values<K>(rho, points, values);
  std::vector<double> log_rho;
  std::size_t kept = 0;
  for (std::size_t k = 0; k + 1 < first.size(); ++k) {
    const double at_generator = std::log(CGAL::to_double(values[first[k]]));
    bool moderate = true;  // within a factor 8 of its value at the generator all over
    for (std::size_t j = first[k] + 1; j < first[k + 1] && moderate; ++j)
      moderate = std::abs(std::log(CGAL::to_double(values[j])) - at_generator) <= std::log(8.0);
    if (!moderate) continue;
    log_rho.push_back(at_generator);
    log_areas[kept++] = log_areas[k];
  }
  log_areas.resize(kept);
  out.cells = kept;
  if (kept < 3) return out;
  const auto [lo, hi] = std::minmax_element(log_rho.begin(), log_rho.end());
  if (*hi - *lo < std::log(2.0)) return out;
  const double n = double(log_rho.size());
  double mean_x = 0, mean_y = 0;
  for (std::size_t i = 0; i < log_rho.size(); ++i) mean_x += log_rho[i], mean_y += log_areas[i];
  mean_x /= n, mean_y /= n;
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < log_rho.size(); ++i) {
    sxy += (log_rho[i] - mean_x) * (log_areas[i] - mean_y);
    sxx += (log_rho[i] - mean_x) * (log_rho[i] - mean_x);
  }
  out.slope = sxy / sxx;
  double residuals = 0;
  for (std::size_t i = 0; i < log_rho.size(); ++i) {
    const double r = log_areas[i] - mean_y - out.slope * (log_rho[i] - mean_x);
    residuals += r * r;
  }
  out.standard_error = std::sqrt(residuals / (n - 2) / sxx);
  return out;
}

/// \ingroup PkgCvt2Ref
/// Whether the free generators of `bvd` are spread as a start for a centroidal tessellation of
/// `rho` must be (`Density_response::is_followed()`): the slope of `density_response_2()` not
/// above -1/4, half way from cells of one size to a centroidal tessellation's, by two standard
/// errors, or not defined; and the counts of the regions between constraints costing 2% of the
/// energy at most, or not measured. Points that do not follow the density (uniform ones under a
/// density that varies) take the optimizers hundreds of iterations to move across the domain,
/// and the move ratios fall below 1% long before they arrive; wrong counts between regions no
/// move mends. Points drawn by `random_points_in_domain_2()` and dealt by region follow it, and
/// `remove_generators_2()` takes the others away (`cvt2 --redistribute` and the Python
/// module's `optimize(redistribute=)` replace them so by default).
/// \tparam Diagram a `Bounded_voronoi_diagram_2`.
/// \tparam Density a model of `DensityFunction_2`.
template <class Diagram, class Density, class Moves = internal::Every_generator>
bool follows_density_2(const Diagram& bvd, const Density& rho, const Moves& moves = Moves()) {
  return density_response_2(bvd, rho, moves).is_followed();
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
/// \param response if not null, gets what `density_response_2()` found (not with `always`).
/// Like `density_response_2()`, it numbers the domain's faces in their `id()`.
/// \throws std::invalid_argument naming a point of `fixed` that is not a generator.
template <class CDT, class Density, class PointRange>
std::vector<typename CDT::Vertex_handle> generators_to_redistribute_2(
    const CDT& cdt, const Density& rho, const PointRange& fixed, bool always = false,
    Density_response* response = nullptr) {
  std::vector<typename CDT::Vertex_handle> given = internal::movable_generators(cdt, fixed);
  if (given.empty() || always) return given;
  internal::Handle_set<typename CDT::Vertex_handle> moved;
  for (const auto v : given) moved.insert(v);
  const auto moves = [&moved](typename CDT::Vertex_handle v) { return moved.contains(v); };
  const Density_response r = density_response_2(Bounded_voronoi_diagram_2<CDT>(cdt), rho, moves);
  if (response) *response = r;
  if (r.is_followed()) given.clear();
  return given;
}

namespace internal {

// After a run over the whole domain under rho: the final cells' density response into `r`, and
// a CONVERGED stop whose cells do not follow rho made STALLED, a stop far from the optimum. A
// uniform density has no response to measure.
template <class CDT, class Traits, class Density>
void judge_density_response(const CDT& cdt, const Traits& traits, const Density& rho,
                            const std::vector<typename CDT::Vertex_handle>& fixed,
                            Optimization_result& r) {
  if constexpr (!std::is_same_v<Density, Uniform_density_2<typename CDT::Geom_traits>>) {
    Handle_set<typename CDT::Vertex_handle> held;
    for (const auto v : fixed) held.insert(v);
    r.density_response =
        density_response_2(Bounded_voronoi_diagram_2<CDT, Traits>(cdt, traits), rho,
                           [&held](typename CDT::Vertex_handle v) { return !held.contains(v); });
    if (r.stop_reason == CONVERGED && !r.density_response.is_followed()) r.stop_reason = STALLED;
  }
}

// Why points do not follow the density, for a note on their redistribution: what
// `response.is_followed()` found.
inline std::string density_response_reason(const Density_response& response) {
  const bool cells = !response.is_followed_in_cells(), counts = !response.is_followed_by_counts();
  return std::string(cells ? "their cells' areas do not shrink as it grows" : "") +
         (cells && counts ? ", and " : "") +
         (counts ? "the regions between constraints hold too many of them or too few" : "");
}

// A note for a result whose cells do not follow the density, empty otherwise; `drawn`: the
// free generators were drawn from the density (or redistributed), so a start far from its
// distribution is not the reason.
inline std::string density_response_note(const Density_response& response, bool drawn) {
  const bool cells = !response.is_followed_in_cells(), counts = !response.is_followed_by_counts();
  if (!cells && !counts) return {};
  char s[32];
  std::string note;
  if (cells) {
    std::snprintf(s, sizeof s, "%.2f", response.slope);
    note = std::string("the cells do not follow the density: their areas scale as density^") + s +
           ", a centroidal tessellation's as density^-0.50";
  }
  if (counts) {
    std::snprintf(s, sizeof s, "%.0f%%", 100 * response.count_excess);
    note += std::string(cells ? "; and of the " : "of the ") + std::to_string(response.regions) +
            " regions between constraints, some hold too many points or too few for the "
            "density (the counts cost at least about " +
            s + " more energy than counts that follow it, and no point crosses a constraint)";
  }
  note += ": far from the optimum. ";
  if (!drawn)
    return note +
           (cells ? "The points started far from the density's distribution, and the "
                    "iteration moves them across the domain slowly. "
                  : "") +
           "Start from points drawn from the density (random points with the same density, "
           "which deals them to the regions), as redistribute='auto' (cvt2 --redistribute "
           "auto), the default, does";
  if (cells)
    note +=
        "The points were drawn from the density: it varies faster than this many cells can "
        "follow, or the iteration stopped early (a smaller move ratio bound, more "
        "iterations)";
  if (counts)
    note += std::string(cells ? "; they" : "The points") +
            " were dealt to the regions by their masses, measured on the domain's triangles: "
            "the density varies within them";
  return note;
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_DENSITY_RESPONSE_2_H
