// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// resample_constraints_2(): the constraints of a marked triangulation resampled to a cell size,
// so that a finely digitised boundary does not pin a speck of a cell at every input vertex;
// cell_size_for_cells_2(): the size that gives a number of cells.
#ifndef CVT_2_RESAMPLE_CONSTRAINTS_2_H
#define CVT_2_RESAMPLE_CONSTRAINTS_2_H

#include <CVT_2/Sliding_runs_2.h>
#include <CVT_2/exceptions.h>
#include <CVT_2/internal/resample_runs.h>
#include <CVT_2/internal/to_string.h>
#include <CVT_2/parameters.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <map>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace CVT_2 {

/// \ingroup PkgCvt2Ref
/// The default spacing of the points that `resample_constraints_2()` puts on the constraints, in
/// cell sizes: a generator on the domain's boundary has half a cell, which at two cell sizes
/// from the next has the area of an inner cell.
inline constexpr double default_spacing_ratio = 2;

namespace internal {

// The check of a spacing ratio, for resample_constraints_2() and the cell size's functions.
inline void check_spacing_ratio(double s) {
  if (!(s > 0) || !std::isfinite(s))
    throw Domain_error("the spacing ratio must be a positive number, not " + number_to_string(s));
}

}  // namespace internal

/// \ingroup PkgCvt2Ref
/// What `resample_constraints_2()` did.
struct Resampling_report {
  std::size_t input_vertices = 0;   ///< vertices on constraints before
  std::size_t output_vertices = 0;  ///< vertices on constraints after
  std::size_t features = 0;         ///< kept as they were: junctions, ends, fixed points, corners
  std::size_t corners = 0;          ///< of the features, the corners at the scale of a cell
  std::size_t runs = 0;             ///< pieces of polyline between features, each resampled
  /// input vertices kept beyond the size's count: where a chord would leave the input by more
  /// than the bound, or cross or cut off another constraint or a generator
  std::size_t kept_for_deviation = 0, kept_for_topology = 0;
  /// rings below `minimum_ring_area`, and the rings and generators inside them, removed
  std::size_t rings_dropped = 0, generators_dropped = 0;
  /// the largest distance from an input vertex to the chord that replaced it (the one-sided
  /// Hausdorff distance from the input polylines to the resampled ones)
  double max_deviation = 0;
  double area_before = 0, area_after = 0;  ///< of the domain
};

/// \ingroup PkgCvt2Ref
/// A constraint of a resampled triangulation, with the input constraint it replaces
/// (`resample_constraints_2()`'s `resampled_chords`): so that outputs name each chord by the
/// input line it comes from (`IO::resampled_segments()`).
template <class Point_2>
struct Resampled_chord {
  Point_2 a, b;  ///< the chord's ends
  /// a constrained edge of the triangulation before: of the chord's stretch of its run, the
  /// one nearest to the chord's middle, which is within the deviation bound of it (the chord
  /// itself if it was kept)
  Point_2 source_a, source_b;
};

/// \ingroup PkgCvt2Ref
/// Resamples the constraints of `cdt` to the cell size `h`: each input polyline (outer rings,
/// holes, inner constraints) is cut at its *features*, which stay: junctions (vertices of three
/// or more constrained edges, or of one: the ends of open polylines), `fixed_points`, and
/// corners, where the polyline turns by more than `corner_angle` between the chords to the
/// points at distance `h` before and after (so that a coastline jagged far below a cell has
/// none, and a square has four). Between two features, the *run* is replaced by points on it
/// spaced by about `spacing_ratio` times `h` (the chords of a divider walk, evened out so that the
/// last one ends at the feature; at least three points on a ring). An input vertex is kept too
/// where a chord would leave the input by more than `deviation_bound`, or cross another constraint,
/// or sweep over a vertex or generator (topology is kept: no ring disappears, nothing changes
/// side).
///
/// Rebuilds `cdt` with the new points, the chords as constraints, its generators (vertices on
/// no constraint) and the domain marked as before: each chord's sides inherit the marks of its
/// run. Constraints with the domain on neither side are kept as they are.
///
/// New points are computed on their input segment in double precision: on the input polyline
/// to rounding. Its vertices get new handles.
///
/// \tparam CDT a constrained Delaunay triangulation whose faces model `BvdFaceBase_2`, marked.
/// \param cdt the triangulation.
/// \param h the cell size, the spacing of neighbouring generators in a hexagonal tiling.
/// \param np named parameters:
///   - `spacing_ratio(s)`: the spacing of the new points along a run, in cell sizes (default 2:
///     a generator on the domain's boundary has half a cell, which at `2 h` apart has the area of
///     an inner cell; generators on a line cost more energy than free ones whose cells it clips,
///     so that 2 also lowers the energy along inner constraints, see the manual);
///   - `deviation_bound(d)`: how far a chord may leave the input (default `h / 4`);
///   - `corner_angle(a)`: the turn, in degrees, above which a vertex is a corner (default 30);
///   - `fixed_points(r)`: a range of points: constrained vertices there are features;
///   - `minimum_ring_area(a)`: a ring (a closed polyline meeting no other, with no fixed point)
///     that encloses less than `a` is removed, with the lines, rings and generators inside it:
///     an island below it is dropped, a hole below it filled (default 0: none);
///   - `sliding_runs(&runs)`: a pointer to a `Sliding_runs_2<CDT>`, which gets the runs with
///     the domain on a side, three points or more and a length of three cell sizes or more
///     (their input polylines and new vertices; a shorter ring, a small island, could only
///     collapse), and the deviation bound: for `lloyd_optimize_2()` and `lbfgs_optimize_2()` with
///     `sliding_runs(&runs)`, which slide the vertices along the input;
///   - `resampled_chords(&chords)`: a pointer to a `std::vector<Resampled_chord<Point_2>>`,
///     which gets every constraint of the result with the input constraint it replaces.
/// \throws Domain_error for a size that is not a positive number, a bound, angle or area that
///         is not a non-negative one, or a minimum ring area that removes the whole domain (the
///         triangulation is then unchanged).
template <class CDT, class NP = No_named_parameters>
Resampling_report resample_constraints_2(CDT& cdt, double h, const NP& np = NP()) {
  using Point_2 = typename CDT::Point_2;
  using Vertex_handle = typename CDT::Vertex_handle;
  using internal_np::choose_parameter;
  using internal_np::get_parameter;
  if (!(h > 0) || !std::isfinite(h))
    throw Domain_error("the cell size must be a positive number, not " +
                       internal::number_to_string(h));
  const double ratio =
      choose_parameter(get_parameter(np, internal_np::spacing_ratio_t()), default_spacing_ratio);
  internal::check_spacing_ratio(ratio);
  const double bound = choose_parameter(get_parameter(np, internal_np::deviation_bound_t()), h / 4);
  if (!(bound >= 0) || !std::isfinite(bound))
    throw Domain_error("the deviation bound must be a non-negative number, not " +
                       internal::number_to_string(bound));
  const double corner_degrees =
      choose_parameter(get_parameter(np, internal_np::corner_angle_t()), 30.0);
  if (!(corner_degrees >= 0) || !std::isfinite(corner_degrees))
    throw Domain_error("the corner angle must be a non-negative number of degrees, not " +
                       internal::number_to_string(corner_degrees));
  const double corner = corner_degrees * CGAL_PI / 180;
  std::vector<Point_2> fixed;
  if constexpr (internal_np::has_parameter<NP, internal_np::fixed_points_t>)
    for (const auto& p : get_parameter(np, internal_np::fixed_points_t())) fixed.push_back(p);

  const double minimum_ring_area =
      choose_parameter(get_parameter(np, internal_np::minimum_ring_area_t()), 0.0);
  if (!(minimum_ring_area >= 0) || !std::isfinite(minimum_ring_area))
    throw Domain_error("the minimum ring area must be a non-negative number, not " +
                       internal::number_to_string(minimum_ring_area));
  internal::Run_resampler<CDT> resampler(cdt, h, ratio * h, bound, corner, fixed,
                                         minimum_ring_area);
  resampler.resample();
  Resampling_report report;
  report.input_vertices = resampler.input_vertices;
  report.output_vertices = resampler.output_vertices;
  report.features = resampler.features;
  report.corners = resampler.corners;
  report.runs = resampler.runs;
  report.kept_for_deviation = resampler.kept_for_deviation;
  report.kept_for_topology = resampler.kept_for_topology;
  report.rings_dropped = resampler.rings_dropped;
  report.generators_dropped = resampler.generators_dropped;
  report.max_deviation = resampler.max_deviation;
  report.area_before = internal::Run_resampler<CDT>::domain_area(cdt);

  // The new triangulation: generators and points in spatial order, then the chords.
  const std::vector<Point_2>& points = resampler.points();
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  using Map = typename CGAL::Pointer_property_map<Point_2>::const_type;
  CGAL::spatial_sort(order.begin(), order.end(),
                     CGAL::Spatial_sort_traits_adapter_2<typename CDT::Geom_traits, Map>(
                         Map(points.data())));  // not make_property_map(): &v[0] of none
  CDT out(cdt.geom_traits());
  std::vector<Vertex_handle> handle(points.size());
  typename CDT::Face_handle hint;
  for (const std::size_t i : order) {
    handle[i] = out.insert(points[i], hint);
    hint = handle[i]->face();
  }
  // The domain's side of each chord, by its vertices, both ways: true if inside on the left.
  std::map<std::pair<const void*, const void*>, bool> left_inside;
  for (const auto& c : resampler.chords()) {
    out.insert_constraint(handle[c.a], handle[c.b]);
    left_inside[{&*handle[c.a], &*handle[c.b]}] = c.left_inside;
    left_inside[{&*handle[c.b], &*handle[c.a]}] = c.right_inside;
  }
  internal::mark_by_sides(out, left_inside);
  if (report.area_before > 0 && !(internal::Run_resampler<CDT>::domain_area(out) > 0))
    throw Domain_error("the minimum ring area " + internal::number_to_string(minimum_ring_area) +
                       " removes the whole domain; the triangulation is unchanged");
  cdt.swap(out);
  if constexpr (internal_np::has_parameter<NP, internal_np::resampled_chords_t>) {
    auto& chords = *get_parameter(np, internal_np::resampled_chords_t());
    chords.clear();
    for (const auto& c : resampler.chords())
      chords.push_back({points[c.a], points[c.b], c.source_a, c.source_b});
  }
  if constexpr (internal_np::has_parameter<NP, internal_np::sliding_runs_t>) {
    Sliding_runs_2<CDT>& runs = *get_parameter(np, internal_np::sliding_runs_t());
    runs.set_deviation_bound(bound);
    for (const auto& r : resampler.resampled_runs()) {
      const std::vector<double> length = Sliding_runs_2<CDT>::arc_lengths(r.polyline);
      if (length.back() < 3 * h) continue;  // too short to gain (a small island's three points)
      std::vector<Vertex_handle> vertices;
      std::vector<double> at;
      for (std::size_t k = 0; k < r.points.size(); ++k) {
        vertices.push_back(handle[r.points[k]]);
        const std::size_t i = r.seg[k];
        at.push_back(k + 1 == r.points.size() ? length.back()
                     : i + 1 < length.size()  ? length[i] + r.t[k] * (length[i + 1] - length[i])
                                              : length[i]);
      }
      // (arc lengths a rounding apart on a polyline with repeated points: that run stays)
      if (std::adjacent_find(at.begin(), at.end(), std::greater_equal<double>()) == at.end())
        runs.add_run(r.polyline, std::move(vertices), std::move(at));
    }
  }
  report.area_after = internal::Run_resampler<CDT>::domain_area(cdt);
  return report;
}

/// \ingroup PkgCvt2Ref
/// The cell size (the spacing `H` of a hexagonal tiling, a cell of area `sqrt(3)/2 H^2`) at which
/// `cells` cells fill the domain of `cdt` when its constraints are resampled to it with the
/// spacing ratio `s` (`resample_constraints_2()`, default 2): the domain's area `A` holds
/// `A / (sqrt(3)/2 H^2)` cells, and a generator on the domain's boundary, `s H` from the next,
/// has half a cell `s H` long (half a hexagon's depth), so that the boundary of length `L`
/// adds `L (2 - s) / (2 s H)`: nothing at `s = 2`, `L / (2 H)` at `s = 1`. `H` solves
/// `A / (sqrt(3)/2 H^2) + L (2 - s) / (2 s H) = cells`. Inner constraints, with the domain on both
/// sides, add nothing.
/// \throws Domain_error if the domain is empty, `cells` is 0 or `s` is not a positive number.
template <class CDT>
double cell_size_for_cells_2(const CDT& cdt, std::size_t cells, double s = default_spacing_ratio) {
  const double area = internal::Run_resampler<CDT>::domain_area(cdt);
  const double length = internal::Run_resampler<CDT>::boundary_length(cdt);
  if (!(area > 0)) throw Domain_error("the domain is empty: no cell size gives cells in it");
  if (cells == 0) throw Domain_error("a cell size for 0 cells does not exist");
  internal::check_spacing_ratio(s);
  // In u = 1/H: (2A/sqrt3) u^2 + L (2 - s) / (2 s) u - cells = 0, the positive root.
  const double a = 2 * area / std::sqrt(3.0), b = length * (2 - s) / (2 * s), c = -double(cells);
  const double root = std::sqrt(b * b - 4 * a * c);                      // > |b|: c < 0 < a
  const double u = b >= 0 ? 2 * -c / (b + root) : (root - b) / (2 * a);  // no cancellation
  return 1 / u;
}

/// \ingroup PkgCvt2Ref
/// The number of cells that the cell size `h` gives the domain of `cdt` with the spacing ratio
/// `s`, the inverse of `cell_size_for_cells_2()`: `A / (sqrt(3)/2 h^2) + L (2 - s) / (2 s h)`,
/// not rounded.
/// \throws Domain_error if `h` or `s` is not a positive number.
template <class CDT>
double cells_for_cell_size_2(const CDT& cdt, double h, double s = default_spacing_ratio) {
  if (!(h > 0) || !std::isfinite(h))
    throw Domain_error("the cell size must be a positive number, not " +
                       internal::number_to_string(h));
  internal::check_spacing_ratio(s);
  const double area = internal::Run_resampler<CDT>::domain_area(cdt);
  const double length = internal::Run_resampler<CDT>::boundary_length(cdt);
  return area / (std::sqrt(3.0) / 2 * h * h) + length * (2 - s) / (2 * s * h);
}

}  // namespace CVT_2

#endif  // CVT_2_RESAMPLE_CONSTRAINTS_2_H
