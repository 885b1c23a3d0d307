// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// mark_domain_2(): which faces of a constrained triangulation form the domain (Triangle's rule).
#ifndef CVT_2_MARK_DOMAIN_2_H
#define CVT_2_MARK_DOMAIN_2_H

#include <CVT_2/exceptions.h>
#include <CVT_2/internal/to_string.h>
#include <CVT_2/internal/valid_point.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/enum.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

// Whether the finite vertex v lies in the closed domain: one of its faces is in the domain.
template <class CDT>
bool has_domain_face(const CDT& cdt, typename CDT::Vertex_handle v) {
  if (cdt.dimension() < 2 || cdt.is_infinite(v)) return false;
  auto fc = cdt.incident_faces(v), done = fc;
  do
    if (fc->is_inside_domain()) return true;
  while (++fc != done);
  return false;
}

// How many finite vertices lie in the closed domain: each has a cell.
template <class CDT>
std::size_t number_of_vertices_in_domain(const CDT& cdt) {
  std::size_t n = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    n += has_domain_face(cdt, v) ? 1 : 0;
  return n;
}

// Before `cdt.remove(v)`: `link` gets v's neighbours, `kept` the faces around them but v's
// own, which the removal keeps with their domain marks; the faces around the link after it
// that are not in `kept` fill the hole.
template <class CDT, class FaceSet>
void link_and_kept_faces(const CDT& cdt, typename CDT::Vertex_handle v,
                         std::vector<typename CDT::Vertex_handle>& link, FaceSet& kept) {
  link.clear(), kept.clear();
  FaceSet star;
  auto vc = cdt.incident_vertices(v), done = vc;
  do link.push_back(vc);
  while (++vc != done);
  auto fc = cdt.incident_faces(v), fdone = fc;
  do star.insert(fc);
  while (++fc != fdone);
  for (const auto x : link) {
    auto xc = cdt.incident_faces(x), xdone = xc;
    do
      if (!star.contains(xc)) kept.insert(xc);
    while (++xc != xdone);
  }
}

// Whether some face of the triangulation is in the domain.
template <class CDT>
bool has_domain_face(const CDT& cdt) {
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->is_inside_domain()) return true;
  return false;
}

// Clears the domain flag of every face reachable from the seeds without crossing a constraint.
template <class CDT>
void flood_outside(const CDT& cdt, std::vector<typename CDT::Face_handle>& stack) {
  while (!stack.empty()) {
    const typename CDT::Face_handle f = stack.back();
    stack.pop_back();
    if (!f->is_inside_domain()) continue;
    f->set_inside_domain(false);
    for (int i = 0; i < 3; ++i)
      if (!cdt.is_constrained(typename CDT::Edge(f, i)) && f->neighbor(i)->is_inside_domain())
        stack.push_back(f->neighbor(i));
  }
}

// The simple loops of a ring that may touch itself at vertices (a hole pinched to two holes,
// or a bowtie): the ring is cut at each vertex it comes back to. Loops of fewer than three
// vertices (a spike out and back) enclose nothing. A loop that still is not simple (edges
// that overlap) has no inside: Domain_error.
template <class PointIterator>
std::vector<std::vector<typename std::iterator_traits<PointIterator>::value_type>> simple_loops(
    PointIterator first, PointIterator last) {
  using Point_2 = typename std::iterator_traits<PointIterator>::value_type;
  std::vector<std::vector<Point_2>> loops;
  std::vector<Point_2> path;
  std::map<Point_2, std::size_t> position;  // of each vertex on the path
  const auto close = [&](std::vector<Point_2> loop) {
    if (loop.size() >= 3 && !CGAL::is_simple_2(loop.begin(), loop.end()))
      throw Domain_error("the ring through " + to_string(loop.front()) +
                         " overlaps itself: it has no inside");
    if (loop.size() >= 3) loops.push_back(std::move(loop));
  };
  for (; first != last; ++first) {
    const auto [it, is_new] = position.emplace(*first, path.size());
    if (is_new) {
      path.push_back(*first);
      continue;
    }
    const std::size_t i = it->second;  // back at path[i]: path[i..] is a loop
    for (std::size_t j = i + 1; j < path.size(); ++j) position.erase(path[j]);
    close(std::vector<Point_2>(path.begin() + std::ptrdiff_t(i), path.end()));
    path.resize(i + 1);
  }
  close(std::move(path));
  return loops;
}

// For each loop of one ring (simple_loops()), how many of the others contain it. The loops
// touch at vertices only, so the midpoint of an edge of one is inside or outside each other.
template <class Point_2>
std::vector<std::size_t> nesting_depths(const std::vector<std::vector<Point_2>>& loops) {
  std::vector<std::size_t> depth(loops.size(), 0);
  for (std::size_t i = 0; i < loops.size(); ++i) {
    const Point_2 m = CGAL::midpoint(loops[i][0], loops[i][1]);
    for (std::size_t j = 0; j < loops.size(); ++j)
      if (j != i &&
          CGAL::bounded_side_2(loops[j].begin(), loops[j].end(), m) == CGAL::ON_BOUNDED_SIDE)
        ++depth[i];
  }
  return depth;
}

// Calls f(face, index) for each edge of the triangulation along the segment from the vertex u
// to the point b, in order (a constraint from u to b, split by the vertices on it), and returns
// the vertex at b; a null handle if the segment is not made of edges.
template <class CDT, class F>
typename CDT::Vertex_handle for_each_edge_along(const CDT& cdt, typename CDT::Vertex_handle u,
                                                const typename CDT::Point_2& b, const F& f) {
  using Vertex_handle = typename CDT::Vertex_handle;
  const typename CDT::Point_2 a = u->point();
  while (u->point() != b) {
    Vertex_handle next;
    auto ec = cdt.incident_edges(u), done = ec;
    do {
      const typename CDT::Face_handle g = ec->first;
      const int i = ec->second;
      const Vertex_handle w =
          g->vertex(CDT::cw(i)) == u ? g->vertex(CDT::ccw(i)) : g->vertex(CDT::cw(i));
      if (cdt.is_infinite(w)) continue;
      if (w->point() == b ||
          (CGAL::orientation(a, b, w->point()) == CGAL::COLLINEAR &&
           CGAL::collinear_are_strictly_ordered_along_line(u->point(), w->point(), b))) {
        f(g, i);
        next = w;
        break;
      }
    } while (++ec != done);
    if (next == Vertex_handle()) return next;
    u = next;
  }
  return u;
}

// The vertex at p, or a null handle.
template <class CDT>
typename CDT::Vertex_handle vertex_at(const CDT& cdt, const typename CDT::Point_2& p,
                                      typename CDT::Face_handle& hint) {
  typename CDT::Locate_type lt;
  int li;
  hint = cdt.locate(p, lt, li, hint);
  return lt == CDT::VERTEX ? hint->vertex(li) : typename CDT::Vertex_handle();
}

// Calls visit(g, j, inside) for each edge (g, j) of the triangulation along the simple loop
// `loop` (constraints from each of its points to the next), `inside` the face beside the edge
// on the loop's inside (left of it if the loop turns counterclockwise, right otherwise).
// \throws Domain_error if the loop is not made of edges.
template <class CDT, class Visit>
void for_each_edge_of_loop(const CDT& cdt, const std::vector<typename CDT::Point_2>& loop,
                           typename CDT::Face_handle& hint, const Visit& visit) {
  const CGAL::Orientation inside =
      CGAL::orientation_2(loop.begin(), loop.end()) == CGAL::COUNTERCLOCKWISE ? CGAL::LEFT_TURN
                                                                              : CGAL::RIGHT_TURN;
  auto u = vertex_at(cdt, loop[0], hint);
  for (std::size_t i = 0; i < loop.size() && u != typename CDT::Vertex_handle(); ++i) {
    const auto& a = loop[i];
    const auto& b = loop[(i + 1) % loop.size()];
    u = for_each_edge_along(cdt, u, b, [&](typename CDT::Face_handle g, int j) {
      const auto third = g->vertex(j);
      const bool g_inside =
          !cdt.is_infinite(third) && CGAL::orientation(a, b, third->point()) == inside;
      visit(g, j, g_inside ? g : g->neighbor(j));
    });
  }
  if (u == typename CDT::Vertex_handle())
    throw Domain_error("the ring through " + to_string(loop[0]) +
                       " is not made of constraints of the triangulation");
}

// The faces of the region a ring encloses, read as mark_domain_from_polygons_2() reads it (its
// loops touch at vertices; a loop inside an odd number of the others is a hole in it): flooded
// from inside its loops, across every edge but its own. The ring's edges are constraints.
template <class CDT, class PointIterator>
std::unordered_set<typename CDT::Face_handle> ring_region(const CDT& cdt, PointIterator first,
                                                          PointIterator last) {
  using Face_handle = typename CDT::Face_handle;
  using Key = std::pair<const void*, const void*>;
  const auto key = [](typename CDT::Vertex_handle x, typename CDT::Vertex_handle y) {
    const void *p = &*x, *q = &*y;
    return p < q ? Key(p, q) : Key(q, p);
  };
  const auto loops = simple_loops(first, last);
  const auto depth = nesting_depths(loops);
  std::set<Key> own;
  std::vector<Face_handle> stack;
  Face_handle hint;
  for (std::size_t l = 0; l < loops.size(); ++l)
    for_each_edge_of_loop(cdt, loops[l], hint, [&](Face_handle g, int j, Face_handle inside) {
      own.insert(key(g->vertex(CDT::ccw(j)), g->vertex(CDT::cw(j))));
      // a hole in the ring's region: its inside is not in it
      if (depth[l] % 2 == 0) stack.push_back(inside);
    });
  std::unordered_set<Face_handle> region;
  while (!stack.empty()) {
    const Face_handle f = stack.back();
    stack.pop_back();
    if (cdt.is_infinite(f) || !region.insert(f).second) continue;
    for (int i = 0; i < 3; ++i)
      if (!own.count(key(f->vertex(CDT::ccw(i)), f->vertex(CDT::cw(i)))))
        stack.push_back(f->neighbor(i));
  }
  return region;
}

// GEOS's rules for the holes of a valid polygon: each lies inside the polygon's exterior ring,
// covers less than all of it, and none lies inside another (they may touch the exterior and each
// other at points; along edges, which GEOS does not allow, they are read as its buffer(0) reads
// them: a hole along the exterior is a notch, holes along each other are one). A hole outside
// would remove nothing, silently. `where(i, r)` names ring r (0: the exterior) of the i-th polygon
// in messages. The rings are constraints of `cdt`.
template <class CDT, class PolygonWithHolesRange, class Where>
void check_holes_inside(const CDT& cdt, const PolygonWithHolesRange& polygons, const Where& where) {
  if (cdt.dimension() < 2) return;  // no area: the domain is empty
  std::size_t i = 0;
  for (const auto& pwh : polygons) {
    if (pwh.number_of_holes() > 0) {
      const auto shell = ring_region(cdt, pwh.outer_boundary().vertices_begin(),
                                     pwh.outer_boundary().vertices_end());
      std::unordered_map<typename CDT::Face_handle, std::size_t> hole_of;
      std::size_t r = 1;
      for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h, ++r) {
        const auto region = ring_region(cdt, h->vertices_begin(), h->vertices_end());
        bool in = false, out = false;
        std::size_t overlapped = 0;  // the first earlier hole it shares a face with
        for (const auto& f : region) {
          (shell.count(f) ? in : out) = true;
          const auto [it, is_new] = hole_of.emplace(f, r);
          if (!is_new && (overlapped == 0 || it->second < overlapped)) overlapped = it->second;
        }
        const std::string hole = "the hole through " + to_string(*h->vertices_begin());
        if (out)
          throw Domain_error(where(i, r) + hole + (in ? " reaches outside" : " lies outside") +
                             " the polygon's exterior (ring 0): a hole must lie inside it");
        if (region.size() == shell.size())  // inside it and as large: all of it
          throw Domain_error(where(i, r) + hole +
                             " covers the polygon's exterior (ring 0): the polygon has no area");
        if (overlapped)
          throw Domain_error(where(i, r) + hole + " overlaps the hole of ring " +
                             std::to_string(overlapped) + ": holes may not lie inside one another");
      }
    }
    ++i;
  }
}

// Whether a polyline inserted as constraints meets the domain: an edge along it has a domain
// face on a side, or, if its points are all one, that point is in the closed domain.
template <class CDT, class PointRange>
bool polyline_meets_domain(const CDT& cdt, const PointRange& polyline,
                           typename CDT::Face_handle& hint) {
  using Vertex_handle = typename CDT::Vertex_handle;
  auto it = std::begin(polyline);
  if (it == std::end(polyline)) return true;
  Vertex_handle u = vertex_at(cdt, *it, hint);
  if (u == Vertex_handle()) return true;  // not inserted: not for this check to say
  bool meets = has_domain_face(cdt, u);
  bool one_point = true;
  for (++it; it != std::end(polyline) && u != Vertex_handle(); ++it) {
    if (*it == u->point()) continue;
    one_point = false;
    meets = false;
    u = for_each_edge_along(cdt, u, *it, [&](typename CDT::Face_handle g, int j) {
      meets = meets || g->is_inside_domain() || g->neighbor(j)->is_inside_domain();
    });
    if (meets) return true;
  }
  return u == Vertex_handle() || (one_point && meets);
}

}  // namespace internal

/// \ingroup PkgCvt2Ref
/// Marks the domain by Triangle's rule, the rule of the `.poly` format: a face is in the domain
/// unless it can be reached from the unbounded face or from the face holding a hole seed point
/// without crossing a constrained edge. Regions closed by inner constraints (county borders
/// meeting a state border) therefore stay in; a nesting-parity rule would drop every other one.
///
/// Call it again after inserting vertices: new faces are created outside the domain.
/// \tparam CDT a constrained triangulation whose faces model `BvdFaceBase_2`.
/// \tparam PointRange a range of `CDT::Point_2`.
/// \throws Domain_error (with `index()` the seed's position) if a seed has a NaN or infinite
///         coordinate, lies on a constrained edge or vertex (it would not say which side is the
///         hole), or lies outside every region the segments enclose (it would remove nothing:
///         a seed misplaced, or a hole's segments that do not close).
template <class CDT, class PointRange>
void mark_domain_2(const CDT& cdt, const PointRange& hole_seeds) {
  using Face_handle = typename CDT::Face_handle;
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->set_inside_domain(true);
  if (cdt.dimension() < 2) {
    for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->set_inside_domain(false);
    return;
  }
  std::vector<Face_handle> stack{cdt.infinite_face()};
  internal::flood_outside(cdt, stack);
  // Every seed is checked against the regions closed by segments, before any hole is removed:
  // two seeds in one hole are fine.
  Face_handle hint;
  std::size_t k = 0;
  for (const auto& p : hole_seeds) {
    if (!internal::is_valid_point(p))
      throw Domain_error(internal::invalid_point_message("hole point " + internal::to_string(p)),
                         k);
    typename CDT::Locate_type lt;
    int li;
    const Face_handle f = cdt.locate(p, lt, li, hint);
    hint = f;
    const std::size_t before = stack.size();
    if (lt == CDT::FACE) {
      stack.push_back(f);
    } else if (lt == CDT::EDGE) {
      if (cdt.is_constrained(typename CDT::Edge(f, li)))
        throw Domain_error("hole point " + internal::to_string(p) +
                               " lies on a segment: it does not say which side is the hole",
                           k);
      stack.push_back(f);
      stack.push_back(f->neighbor(li));
    } else if (lt == CDT::VERTEX) {
      if (cdt.are_there_incident_constraints(f->vertex(li)))
        throw Domain_error(
            "hole point " + internal::to_string(p) +
                " lies on a segment endpoint: it does not say which side is the hole",
            k);
      auto fc = cdt.incident_faces(f->vertex(li)), done = fc;
      do stack.push_back(fc);
      while (++fc != done);
    }
    if (std::none_of(stack.begin() + std::ptrdiff_t(before), stack.end(),
                     [](Face_handle g) { return g->is_inside_domain(); }))
      throw Domain_error("hole point " + internal::to_string(p) +
                             " lies outside the domain, in no region the segments enclose: it "
                             "removes nothing",
                         k);
    ++k;
  }
  internal::flood_outside(cdt, stack);
}

/// \ingroup PkgCvt2Ref
/// Marks the domain of a triangulation into which the caller inserted the rings of polygons
/// with holes (for example read by `CGAL::IO::read_WKT()`), without seed points: the faces
/// inside each hole ring, next to its edges, serve as hole seeds (but those that are also just
/// inside another polygon's ring: an island in the hole, along its edge), and Triangle's rule
/// does the rest. Polygons may share edges and vertices (a map of counties); their union is the
/// domain, an island that fills a hole filling it. A hole along its own polygon's exterior
/// (invalid for GEOS) is cut out of it, a notch, as GEOS's `buffer(0)` reads it.
///
/// A ring that touches itself at a vertex is read as GEOS reads it (`make_valid()`): cut there
/// into simple loops, a loop of an outer ring that lies inside another loop of the same ring
/// (an ESRI-style "inverted hole", a pocket closed off by the ring) is a hole, a loop inside
/// that one an island again; the loops of a hole ring are holes, those inside them islands.
/// \tparam PolygonWithHolesRange a range of `CGAL::Polygon_with_holes_2`.
/// \throws Domain_error for a ring whose loops overlap (no inside).
template <class CDT, class PolygonWithHolesRange>
void mark_domain_from_polygons_2(const CDT& cdt, const PolygonWithHolesRange& polygons) {
  using Face_handle = typename CDT::Face_handle;
  mark_domain_2(cdt, std::vector<typename CDT::Point_2>());
  if (cdt.dimension() < 2) return;
  // visit(f, hole) for the face f just inside each edge of the loops of a ring, `hole` for the
  // loops whose depth has the parity `hole_parity`.
  Face_handle hint;
  const auto for_each_inside_face = [&](auto first, auto last, std::size_t hole_parity,
                                        const auto& visit) {
    const auto loops = internal::simple_loops(first, last);
    const auto depth = internal::nesting_depths(loops);
    for (std::size_t l = 0; l < loops.size(); ++l)
      internal::for_each_edge_of_loop(cdt, loops[l], hint, [&](Face_handle, int, Face_handle f) {
        visit(f, depth[l] % 2 == hole_parity);
      });
  };
  // Holes are flooded from the faces just inside their edges, but for a face that is also just
  // inside a loop with area of another ring (an island in the hole, along its edge: the
  // island's face, which the flood would have taken with it; a hole an island fills is no hole
  // of the union). A face just inside its own polygon's exterior is a seed all the same: the
  // hole runs along the exterior there and is cut out, a notch. `solid` maps a face to the
  // polygon whose exterior alone makes it solid, `other` if another ring does.
  constexpr std::size_t other = std::numeric_limits<std::size_t>::max();
  std::unordered_map<Face_handle, std::size_t> solid;
  std::vector<std::pair<Face_handle, std::size_t>> seeds;  // and the hole's polygon
  std::size_t i = 0;
  for (const auto& pwh : polygons) {
    const auto outer = [&](Face_handle f, bool hole) {
      if (hole) {
        seeds.emplace_back(f, other);  // a pocket the exterior closes off
      } else {
        const auto [it, is_new] = solid.emplace(f, i);
        if (!is_new && it->second != i) it->second = other;
      }
    };
    const auto inner = [&](Face_handle f, bool hole) {
      if (hole)
        seeds.emplace_back(f, i);
      else
        solid[f] = other;  // an island the hole ring closes off
    };
    for_each_inside_face(pwh.outer_boundary().vertices_begin(), pwh.outer_boundary().vertices_end(),
                         1, outer);
    for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h)
      for_each_inside_face(h->vertices_begin(), h->vertices_end(), 0, inner);
    ++i;
  }
  std::vector<Face_handle> stack;
  for (const auto& [f, polygon] : seeds) {
    const auto it = solid.find(f);
    if (it == solid.end() || (polygon != other && it->second == polygon)) stack.push_back(f);
  }
  internal::flood_outside(cdt, stack);
}

}  // namespace CVT_2

#endif  // CVT_2_MARK_DOMAIN_2_H
