// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// insert_generators_2(): inserts generator points into a marked domain, checking each one;
// those a rounding outside go onto the boundary. remove_generators_2(): the converse.
#ifndef CVT_2_INSERT_GENERATORS_2_H
#define CVT_2_INSERT_GENERATORS_2_H

#include <CVT_2/exceptions.h>
#include <CVT_2/internal/Handle_set.h>
#include <CVT_2/internal/layout/sort_faces.h>
#include <CVT_2/internal/parallel/Interrupt_scope.h>
#include <CVT_2/internal/snap_to_boundary.h>
#include <CVT_2/internal/to_string.h>
#include <CVT_2/internal/valid_point.h>
#include <CVT_2/internal/vertices_at.h>
#include <CVT_2/mark_domain_2.h>
#include <CVT_2/parameters.h>

#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <new>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

// Whether p lies in the closed domain; `hint` becomes the face where p was found.
template <class CDT>
bool locate_in_domain(const CDT& cdt, const typename CDT::Point_2& p,
                      typename CDT::Face_handle& hint) {
  if (cdt.dimension() < 2) return false;
  typename CDT::Locate_type lt;
  int li;
  const typename CDT::Face_handle f = cdt.locate(p, lt, li, hint);
  hint = f;
  switch (lt) {
    case CDT::FACE:
      return f->is_inside_domain();
    case CDT::EDGE:
      return f->is_inside_domain() || f->neighbor(li)->is_inside_domain();
    case CDT::VERTEX:
      return has_domain_face(cdt, f->vertex(li));
    default:
      return false;
  }
}

}  // namespace internal

/// \ingroup PkgCvt2Ref
/// Whether `p` lies in the closed domain of `cdt`: in a domain face or on its boundary.
/// \pre the domain is marked (`mark_domain_2()`).
template <class CDT>
bool is_in_domain_2(const CDT& cdt, const typename CDT::Point_2& p) {
  typename CDT::Face_handle hint;
  return internal::locate_in_domain(cdt, p, hint);
}

/// \ingroup PkgCvt2Ref
/// What `insert_generators_2()` did with the points that lay outside the domain by no more than
/// the boundary tolerance: each went onto the boundary, as a constrained vertex.
template <class Point_2>
struct Generator_insertion_result {
  double boundary_tolerance = 0;   ///< the tolerance used (computed, if not given)
  std::vector<std::size_t> moved;  ///< their positions in the input range, in increasing order
  std::vector<Point_2> moved_to;   ///< where each went: onto a boundary edge, or a boundary vertex
  std::vector<double> distances;   ///< how far outside the domain each lay
};

/// \ingroup PkgCvt2Ref
/// Inserts generators into a triangulation whose domain is marked, and keeps the marking: the
/// faces a new vertex creates (all around it) take the flag of the face where it landed, or,
/// for a point on a constraint, of the face on their side. So any marking is kept, by seeds or
/// from polygons. A point on a constraint is kept and becomes a constrained vertex, as in
/// Triangle; a point already present is merged.
///
/// A point outside the domain by no more than the boundary tolerance (a boundary point computed
/// in floating point: an edge's midpoint, a projection) goes onto the boundary as a constrained
/// vertex: merged with a boundary vertex within the tolerance and at most twice as far as the
/// boundary, plus a rounding (no cell thinner than its distance outside beside the vertex, and
/// a point beside an edge goes onto the edge however large the tolerance), or else at its
/// projection onto the nearest boundary edge, rounded: onto the edge when a rounding lies
/// on it exactly (the constraint is split there), else next to it, where two constraints
/// through the point replace the edge (the boundary bends by a rounding, and the domain's
/// marks follow it). Such points are inserted after the others, and listed in the result.
///
/// When the new vertices are at least half of all (the domain's own vertices count), the faces
/// are then laid out in memory along a Hilbert curve, so that the optimizers' passes, which
/// read them in memory order, find the faces around each vertex close by (at 10^6 generators, a
/// Lloyd iteration takes about a quarter less time). Face handles held before the call then
/// refer to other faces, and the faces' blind tags are cleared: as after any change of the
/// triangulation, a diagram on it must be updated. The layout takes 16 bytes a face while it
/// runs, and is skipped if that memory cannot be had.
/// \param np optional: `boundary_tolerance(t)`, a distance \f$\ge 0\f$ (0: no point outside is
///        taken); default \f$2^{-50}\f$ of the largest coordinate magnitude of the
///        triangulation's vertices (4 to 8 units in the last place of it), so that it scales
///        with the coordinates (projected coordinates in metres, say).
/// \returns the points moved onto the boundary (`Generator_insertion_result`).
/// \throws std::invalid_argument for a tolerance that is negative or not finite.
/// \throws Domain_error (with `index()` the position in `points`) for a NaN or infinite
///         coordinate, one beyond 1e300 in magnitude, or points outside the domain by more than
///         the tolerance (the message gives how many, the first few, and the first one's
///         distance to the domain); nothing is inserted then.
template <class CDT, class PointRange, class NP = No_named_parameters>
Generator_insertion_result<typename CDT::Point_2> insert_generators_2(
    CDT& cdt, const PointRange& points, const NP& np = parameters::default_values()) {
  using Point_2 = typename CDT::Point_2;
  using Face_handle = typename CDT::Face_handle;
  using internal_np::boundary_tolerance_t;
  constexpr bool has_tolerance = internal_np::has_parameter<NP, boundary_tolerance_t>;
  double tolerance = -1;  // computed when a point outside needs it
  if constexpr (has_tolerance) {
    tolerance = double(internal_np::get_parameter(np, boundary_tolerance_t{}));
    if (!(tolerance >= 0) || !std::isfinite(tolerance))
      throw std::invalid_argument("boundary_tolerance must be >= 0 and finite, not " +
                                  internal::number_to_string(tolerance));
  }
  Generator_insertion_result<Point_2> result;
  std::vector<Point_2> pts(std::begin(points), std::end(points));
  if (pts.empty()) return result;  // make_property_map() would take the address of pts[0]
  for (std::size_t i = 0; i < pts.size(); ++i) {
    internal::poll_interrupt_sometimes();
    if (!internal::is_valid_point(pts[i]))
      throw Domain_error(
          internal::invalid_point_message("generator " + internal::to_string(pts[i])), i);
  }
  // Locate in spatial order, each from the previous: a walk of a few faces per point.
  std::vector<std::size_t> order(pts.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  using Map = typename CGAL::Pointer_property_map<Point_2>::const_type;
  using Sort_traits = CGAL::Spatial_sort_traits_adapter_2<typename CDT::Geom_traits, Map>;
  CGAL::spatial_sort(order.begin(), order.end(),
                     internal::Interruptible_sort_traits_2<Sort_traits>(
                         Sort_traits(CGAL::make_property_map(std::as_const(pts)))));
  Face_handle hint;
  std::vector<std::size_t> outside;                  // positions, beyond the tolerance
  std::vector<std::pair<std::size_t, double>> near;  // within it, with their distance
  for (const std::size_t i : order) {
    internal::poll_interrupt_sometimes();
    if (internal::locate_in_domain(cdt, pts[i], hint)) continue;
    if (tolerance < 0) tolerance = internal::default_boundary_tolerance(cdt);
    const auto place =
        tolerance > 0 && cdt.dimension() == 2
            ? internal::nearest_boundary(cdt, pts[i], hint, tolerance, tolerance, tolerance)
            : internal::Boundary_place<CDT>();
    if (place.found())
      near.emplace_back(i, place.distance);
    else
      outside.push_back(i);
  }
  result.boundary_tolerance = tolerance < 0 ? 0 : tolerance;
  if (!outside.empty()) {
    std::sort(outside.begin(), outside.end());
    const std::size_t first = outside[0];
    std::string what = "generator " + internal::to_string(pts[first]) + " lies outside the domain";
    if (cdt.dimension() == 2)
      what += ", at " + internal::short_number(internal::distance_to_domain(cdt, pts[first])) +
              " from it (boundary tolerance " + internal::short_number(tolerance) + ")";
    internal::Generators_outside_error::Others others;
    for (std::size_t k = 1; k < outside.size() && k <= 5; ++k)
      others.emplace_back(outside[k], internal::to_string(pts[outside[k]]));
    throw internal::Generators_outside_error(first, what, others, outside.size());
  }
  std::size_t inserted = 0;
  // Inserts p located at (lt, f, li): the new faces take the flag of the face where p landed,
  // or, on an edge whose sides differ (a boundary), the flag of the side they lie on.
  const auto insert = [&](const Point_2& p, typename CDT::Locate_type lt, Face_handle f, int li) {
    const bool inside = f->is_inside_domain();
    const bool on_edge = lt == CDT::EDGE;
    const bool other = on_edge && f->neighbor(li)->is_inside_domain();
    const Point_2 a = on_edge ? f->vertex(CDT::ccw(li))->point() : p;
    const Point_2 b = on_edge ? f->vertex(CDT::cw(li))->point() : p;
    // The side of ab that f lies on, from its third vertex, or the other face's if that one
    // is the infinite vertex.
    CGAL::Orientation f_side = CGAL::COLLINEAR;
    if (on_edge && inside != other)
      f_side = !cdt.is_infinite(f->vertex(li))
                   ? CGAL::orientation(a, b, f->vertex(li)->point())
                   : -CGAL::orientation(a, b, cdt.mirror_vertex(f, li)->point());
    const auto v = cdt.insert(p, lt, f, li);
    auto fc = cdt.incident_faces(v), done = fc;
    do {
      bool flag = inside;
      if (cdt.is_infinite(fc)) {
        flag = false;
      } else if (on_edge && inside != other) {
        const int j = fc->index(v);
        const Point_2& q = fc->vertex(CDT::ccw(j))->point();
        const Point_2& r = fc->vertex(CDT::cw(j))->point();
        const CGAL::Orientation side = CGAL::orientation(a, b, q) != CGAL::COLLINEAR
                                           ? CGAL::orientation(a, b, q)
                                           : CGAL::orientation(a, b, r);
        flag = side == f_side ? inside : other;
      }
      fc->set_inside_domain(flag);
    } while (++fc != done);
    hint = v->face();
    ++inserted;
    return v;
  };
  std::vector<bool> is_near(pts.size(), false);
  for (const auto& n : near) is_near[n.first] = true;
  for (const std::size_t i : order) {
    internal::poll_interrupt_sometimes();  // the points inserted so far stay
    if (is_near[i]) continue;
    typename CDT::Locate_type lt;
    int li;
    const Face_handle f = cdt.locate(pts[i], lt, li, hint);
    if (lt == CDT::VERTEX) {  // already there
      hint = f;
      continue;
    }
    insert(pts[i], lt, f, li);
  }
  // The points near the boundary, after the others: the boundary they go onto is as it will be,
  // but for the roundings by which earlier ones bent it.
  std::sort(near.begin(), near.end());
  const double rounding = near.empty() ? 0 : internal::default_boundary_tolerance(cdt);
  const double radius = 2 * tolerance + rounding;
  // A point a rounding off a boundary edge goes to the side whose flag new faces are created
  // with (that of a default face: outside, for Bvd_face_base_2), so that the faces CGAL makes
  // when the boundary is bent through it are marked right (replace_boundary_edge()).
  const bool fresh = typename CDT::Face().is_inside_domain();
  for (const auto& [i, distance] : near) {
    const Point_2& p = pts[i];
    typename CDT::Locate_type lt;
    int li;
    Face_handle f = cdt.locate(p, lt, li, hint);
    hint = f;
    const auto place = internal::nearest_boundary(cdt, p, f, radius, tolerance, rounding);
    Point_2 to;
    bool done = false;
    if (place.vertex != typename CDT::Vertex_handle()) {
      to = place.vertex->point(), done = true;
    } else if (place.found()) {
      const auto a = place.face->vertex(CDT::ccw(place.index));
      const auto b = place.face->vertex(CDT::cw(place.index));
      for (const auto& [c, on_edge] :
           internal::points_near_boundary_edge<CDT>(p, place.face, place.index, fresh)) {
        f = cdt.locate(c, lt, li, hint);
        if (lt == CDT::VERTEX) {
          to = c, done = true;
          break;
        }
        if (!on_edge && !internal::lands_in(cdt, lt, f, li, fresh)) continue;
        const auto v = insert(c, lt, f, li);
        if (!on_edge) {
          try {
            internal::replace_boundary_edge(cdt, a, b, v);
          } catch (const typename CDT::Intersection_of_constraints_exception&) {
            throw Domain_error("generator " + internal::to_string(p) +
                                   ": a constraint passes within a rounding of the boundary point "
                                   "it would go to",
                               i);
          }
          hint = v->face();  // the constraints' insertion may have deleted the one insert() left
        }
        to = c, done = true;
        break;
      }
    }
    if (!done)  // only next to faces thinner than a rounding
      throw Domain_error("generator " + internal::to_string(p) + " lies " +
                             internal::distance_outside(distance) +
                             ", within the boundary tolerance, but could not be moved onto the "
                             "boundary",
                         i);
    result.moved.push_back(i);
    result.moved_to.push_back(to);
    result.distances.push_back(distance);
  }
  // Laid out again when most of the triangulation is new: not at each of many small calls. The
  // layout only speeds up what follows: without the memory for it, the faces stay as they are.
  if (inserted * 2 < cdt.number_of_vertices()) return result;
  std::vector<std::size_t>().swap(order);
  std::vector<Point_2>().swap(pts);
  try {
    internal::sort_faces(cdt);
  } catch (const std::bad_alloc&) {
  }
  return result;
}

/// \ingroup PkgCvt2Ref
/// Removes generators from a triangulation whose domain is marked, and keeps the marking: the
/// faces that fill each hole are in the domain, as all the faces around a free generator were.
/// Face handles held before the call may refer to other faces, and the faces' blind tags of the
/// filled holes are cleared: a diagram on it must be updated.
/// \param vertices a range of vertex handles of `cdt`, each a free generator: in the domain,
///        with no constraint through it (a repeated handle counts once).
/// \throws std::invalid_argument naming a vertex that is not a free generator; nothing is
///         removed then.
template <class CDT, class VertexRange>
void remove_generators_2(CDT& cdt, const VertexRange& vertices) {
  using Vertex_handle = typename CDT::Vertex_handle;
  using Face_handle = typename CDT::Face_handle;
  std::vector<Vertex_handle> removed;
  internal::Handle_set<Vertex_handle> seen;
  for (const Vertex_handle v : vertices) {
    if (cdt.is_infinite(v) || cdt.are_there_incident_constraints(v) ||
        !internal::has_domain_face(cdt, v))
      throw std::invalid_argument("remove_generators_2: the vertex at " +
                                  internal::to_string(v->point()) +
                                  " is not a free generator (a constrained vertex, or outside "
                                  "the domain)");
    if (seen.insert(v)) removed.push_back(v);
  }
  std::vector<Vertex_handle> link;
  internal::Handle_set<Face_handle> kept;
  for (const Vertex_handle v : removed) {
    internal::poll_interrupt_sometimes();
    internal::link_and_kept_faces(cdt, v, link, kept);
    cdt.remove(v);  // Delaunay fills the hole with new faces only (CGAL's remove_2D)
    for (const Vertex_handle x : link) {
      if (cdt.is_infinite(x)) continue;
      auto xc = cdt.incident_faces(x), xdone = xc;
      do
        if (!kept.contains(xc) && !cdt.is_infinite(xc)) xc->set_inside_domain(true);
      while (++xc != xdone);
    }
  }
}

namespace internal {

// The free generators of `cdt` (in the domain, no constraint through them) but those at the
// points `fixed`: the generators an optimizer with fixed_points(fixed) moves.
// \throws std::invalid_argument naming a point of `fixed` that is not a vertex.
template <class CDT, class PointRange>
std::vector<typename CDT::Vertex_handle> movable_generators(const CDT& cdt,
                                                            const PointRange& fixed) {
  Handle_set<typename CDT::Vertex_handle> kept;
  for (const auto v : vertices_at(cdt, fixed, "fixed_points")) kept.insert(v);
  std::vector<typename CDT::Vertex_handle> out;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (!cdt.are_there_incident_constraints(v) && has_domain_face(cdt, v) && !kept.contains(v))
      out.push_back(v);
  return out;
}

// The note on the points insert_generators_2() moved onto the boundary: the first in full,
// named by `name(k)` for its input position k (a file and line, a row), then how many others
// and the next few, named by `other(k)` (a line, a row).
template <class Point_2, class PointRange, class Name, class Other>
std::string moved_points_note(const Generator_insertion_result<Point_2>& r,
                              const PointRange& points, const Name& name, const Other& other) {
  if (r.moved.empty()) return {};
  const std::size_t first = r.moved[0];
  const Point_2 p = *std::next(std::begin(points), std::ptrdiff_t(first));
  std::string note = name(first) + ": generator " + to_string(p) + " lies " +
                     distance_outside(r.distances[0]) + ", within the boundary tolerance " +
                     short_number(r.boundary_tolerance) + ": moved onto the boundary at " +
                     to_string(r.moved_to[0]) + ", a constrained vertex";
  if (r.moved.size() > 1) {
    note += r.moved.size() == 2 ? "; so was 1 more:"
                                : "; so were " + std::to_string(r.moved.size() - 1) + " more:";
    for (std::size_t k = 1; k < r.moved.size() && k <= 5; ++k)
      note += (k > 1 ? ", " : " ") + other(r.moved[k]);
    if (r.moved.size() > 6) note += ", and " + std::to_string(r.moved.size() - 6) + " more";
  }
  return note;
}

}  // namespace internal

}  // namespace CVT_2

#endif  // CVT_2_INSERT_GENERATORS_2_H
