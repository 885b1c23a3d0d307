// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// insert_generators_2(): inserts generator points into a marked domain, checking each one.
#ifndef CVT_2_INSERT_GENERATORS_2_H
#define CVT_2_INSERT_GENERATORS_2_H

#include <CVT_2/exceptions.h>
#include <CVT_2/internal/sort_faces.h>
#include <CVT_2/internal/valid_point.h>
#include <CVT_2/mark_domain_2.h>

#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <iterator>
#include <new>
#include <numeric>
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
/// Inserts generators into a triangulation whose domain is marked, and keeps the marking: the
/// faces a new vertex creates (all around it) take the flag of the face where it landed, or,
/// for a point on a constraint, of the face on their side. So any marking is kept, by seeds or
/// from polygons. A point on a constraint is kept and becomes a constrained vertex, as in
/// Triangle; a point already present is merged.
///
/// When the new vertices are at least half of all (the domain's own vertices count), the faces
/// are then laid out in memory along a Hilbert curve, so that the optimizers' passes, which
/// read them in memory order, find the faces around each vertex close by (at 10^6 generators, a
/// Lloyd iteration takes about a quarter less time). Face handles held before the call then
/// refer to other faces, and the faces' blind tags are cleared: as after any change of the
/// triangulation, a diagram on it must be updated. The layout takes 16 bytes a face while it
/// runs, and is skipped if that memory cannot be had.
/// \throws Domain_error (with `index()` the position in `points`) for a NaN or infinite
///         coordinate, one beyond 1e300 in magnitude, or a point outside the closed domain;
///         nothing is inserted then.
template <class CDT, class PointRange>
void insert_generators_2(CDT& cdt, const PointRange& points) {
  using Point_2 = typename CDT::Point_2;
  using Face_handle = typename CDT::Face_handle;
  std::vector<Point_2> pts(std::begin(points), std::end(points));
  if (pts.empty()) return;  // make_property_map() would take the address of pts[0]
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (!internal::is_valid_point(pts[i]))
      throw Domain_error(
          internal::invalid_point_message("generator " + internal::to_string(pts[i])), i);
  // Locate in spatial order, each from the previous: a walk of a few faces per point.
  std::vector<std::size_t> order(pts.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  using Map = typename CGAL::Pointer_property_map<Point_2>::const_type;
  CGAL::spatial_sort(order.begin(), order.end(),
                     CGAL::Spatial_sort_traits_adapter_2<typename CDT::Geom_traits, Map>(
                         CGAL::make_property_map(std::as_const(pts))));
  Face_handle hint;
  std::size_t inserted = 0;
  for (const std::size_t i : order)
    if (!internal::locate_in_domain(cdt, pts[i], hint))
      throw Domain_error("generator " + internal::to_string(pts[i]) + " lies outside the domain",
                         i);
  for (const std::size_t i : order) {
    const Point_2& p = pts[i];
    typename CDT::Locate_type lt;
    int li;
    const Face_handle f = cdt.locate(p, lt, li, hint);
    if (lt == CDT::VERTEX) {  // already there
      hint = f;
      continue;
    }
    // Where p lands: one face, or an edge with a face on each side (a constraint's two sides
    // may differ: a boundary).
    const bool inside = f->is_inside_domain();
    const bool on_edge = lt == CDT::EDGE;
    const bool other = on_edge && f->neighbor(li)->is_inside_domain();
    const Point_2 a = on_edge ? f->vertex(CDT::ccw(li))->point() : p;
    const Point_2 b = on_edge ? f->vertex(CDT::cw(li))->point() : p;
    const CGAL::Orientation f_side =
        on_edge ? CGAL::orientation(a, b, f->vertex(li)->point()) : CGAL::COLLINEAR;
    const auto v = cdt.insert(p, lt, f, li);
    auto fc = cdt.incident_faces(v), done = fc;
    do {
      bool flag = inside;
      if (on_edge && inside != other) {
        const int j = fc->index(v);
        const Point_2& q = fc->vertex(CDT::ccw(j))->point();
        const Point_2& r = fc->vertex(CDT::cw(j))->point();
        const CGAL::Orientation side = CGAL::orientation(a, b, q) != CGAL::COLLINEAR
                                           ? CGAL::orientation(a, b, q)
                                           : CGAL::orientation(a, b, r);
        flag = side == f_side ? inside : other;
      }
      fc->set_inside_domain(flag && !cdt.is_infinite(fc));
    } while (++fc != done);
    hint = v->face();
    ++inserted;
  }
  // Laid out again when most of the triangulation is new: not at each of many small calls. The
  // layout only speeds up what follows: without the memory for it, the faces stay as they are.
  if (inserted * 2 < cdt.number_of_vertices()) return;
  std::vector<std::size_t>().swap(order);
  std::vector<Point_2>().swap(pts);
  try {
    internal::sort_faces(cdt);
  } catch (const std::bad_alloc&) {
  }
}

}  // namespace CVT_2

#endif  // CVT_2_INSERT_GENERATORS_2_H
