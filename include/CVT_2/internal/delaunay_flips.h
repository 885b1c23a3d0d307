// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Edge flips back to the constrained Delaunay property after free vertices moved.
#ifndef CVT_2_INTERNAL_DELAUNAY_FLIPS_H
#define CVT_2_INTERNAL_DELAUNAY_FLIPS_H

#include <CVT_2/internal/layout/prefetch.h>
#include <CVT_2/internal/parallel/Face_chunks.h>

#include <CGAL/assertions.h>

#include <cstddef>
#include <utility>
#include <vector>

// CGAL's own CDT::propagating_flip(f, i) follows only the edges opposite one new vertex, as after
// an insertion, while a moved vertex can break edges anywhere in its link; its List_edges
// overload orders the edges by face address, which would make the flips, and so every later
// result, depend on where the allocator put the faces. Hence Lawson's flips from a stack here.

namespace CVT_2 {
namespace internal {

// An edge to examine: a face and an index, and the edge's vertices, which tell whether a flip
// since has made (face, index) another edge.
template <class CDT>
struct Flip_candidate {
  typename CDT::Face_handle f;
  int i;
  typename CDT::Vertex_handle a, b;

  // The edge i of f, as it is now.
  static Flip_candidate of(typename CDT::Face_handle f, int i) {
    return {f, i, f->vertex(CDT::ccw(i)), f->vertex(CDT::cw(i))};
  }
  // Whether (f, i) is still the edge from a to b.
  bool is_current() const { return f->vertex(CDT::ccw(i)) == a && f->vertex(CDT::cw(i)) == b; }
};

// Pushes the four other edges of f and g, which a flip has just made to share an edge: those
// whose in-circle tests the flip changed.
template <class CDT>
void push_edges_around_flip(typename CDT::Face_handle f, typename CDT::Face_handle g,
                            std::vector<Flip_candidate<CDT>>& stack) {
  for (const typename CDT::Face_handle h : {f, g}) {
    const int k = h->index(h == f ? g : f);
    stack.push_back(Flip_candidate<CDT>::of(h, CDT::ccw(k)));
    stack.push_back(Flip_candidate<CDT>::of(h, CDT::cw(k)));
  }
}

// Lawson's flips: an edge on the stack that is not constrained and fails the (symbolically
// perturbed) empty-circle test is flipped, and the four edges around it are examined in turn.
// From any valid constrained triangulation this ends at the constrained Delaunay one.
// `flipped(f, g)` sees the two faces of each flip, after it.
template <class CDT, class Flipped = void (*)(typename CDT::Face_handle, typename CDT::Face_handle)>
void lawson_flips(
    CDT& cdt, std::vector<Flip_candidate<CDT>>& stack,
    Flipped flipped = [](typename CDT::Face_handle, typename CDT::Face_handle) {}) {
  using Face_handle = typename CDT::Face_handle;
  while (!stack.empty()) {
    Flip_candidate<CDT> e = stack.back();
    stack.pop_back();
    if (!e.is_current() && !cdt.is_edge(e.a, e.b, e.f, e.i)) continue;  // flipped away
    if (!cdt.is_flipable(e.f, e.i)) continue;
    Face_handle f = e.f;
    const Face_handle g = f->neighbor(e.i);
    cdt.flip(f, e.i);
    flipped(f, g);
    push_edges_around_flip<CDT>(f, g, stack);
  }
}

// Flips the unconstrained edge i of f as CDT::flip() does, constrained flags included, but
// leaves the vertices' face pointers alone: CGAL's flip reads and may rewrite those of the
// edge's endpoints, which faces of other chunks share. The edge's endpoints each lose a face:
// f->vertex(cw(i)) leaves f and stays in the neighbour, f->vertex(ccw(i)) the other way round.
template <class CDT>
void flip_leaving_vertex_faces(CDT& cdt, typename CDT::Face_handle f, int i) {
  using Face_handle = typename CDT::Face_handle;
  const auto cw = [](int k) { return CDT::cw(k); };
  const auto ccw = [](int k) { return CDT::ccw(k); };
  const Face_handle g = f->neighbor(i);
  const int j = cdt.mirror_index(f, i);
  // the four faces around, each with its index toward f or g: their flags tell the constrained
  // edges, which stay where they are and change faces on our side
  const std::pair<Face_handle, int> wings[4] = {{f->neighbor(cw(i)), cdt.mirror_index(f, cw(i))},
                                                {f->neighbor(ccw(i)), cdt.mirror_index(f, ccw(i))},
                                                {g->neighbor(cw(j)), cdt.mirror_index(g, cw(j))},
                                                {g->neighbor(ccw(j)), cdt.mirror_index(g, ccw(j))}};
  const auto& [tr, tri] = wings[1];
  const auto& [bl, bli] = wings[3];
  f->set_vertex(cw(i), g->vertex(j));
  g->set_vertex(cw(j), f->vertex(i));
  cdt.tds().set_adjacency(f, i, bl, bli);
  cdt.tds().set_adjacency(f, ccw(i), g, ccw(j));
  cdt.tds().set_adjacency(g, j, tr, tri);
  f->set_constraint(ccw(i), false);
  g->set_constraint(ccw(j), false);
  for (const auto& [w, k] : wings)
    w->neighbor(k)->set_constraint(cdt.mirror_index(w, k), w->is_constrained(k));
}

// Lawson's flips within one chunk of faces, which `runs` holds, while other threads flip in
// theirs: only the edges whose flip touches faces of the chunk alone (its two faces and the
// four around them). Every edge on `stack` has a face of the chunk. An edge goes to `deferred`,
// for lawson_flips() once all chunks are done, untested if its other face is another chunk's,
// or if it fails its in-circle test and a face around it is another chunk's. No vertex's face
// pointer is read or written here: the vertices that lose a face are listed in `left` with a
// face they keep, for set_vertex_faces(), before the flip (a list that cannot grow throws with
// the triangulation as it was). An edge whose face a flip has changed since it was pushed is
// dropped, not looked for: that flip pushed the edges around it, this one included if it is
// still there. Returns the number of flips.
template <class CDT>
std::size_t chunk_local_flips(
    CDT& cdt, const Face_runs<typename CDT::Face>& runs, std::vector<Flip_candidate<CDT>>& stack,
    std::vector<Flip_candidate<CDT>>& deferred,
    std::vector<std::pair<typename CDT::Vertex_handle, typename CDT::Face_handle>>& left) {
  using Face_handle = typename CDT::Face_handle;
  const auto ours = [&](Face_handle h) { return runs.holds(&*h); };
  std::size_t flips = 0;
  while (!stack.empty()) {
    const Flip_candidate<CDT> e = stack.back();
    stack.pop_back();
    const Face_handle f = e.f;
    CGAL_assertion(ours(f));
    if (!e.is_current()) continue;
    if (f->is_constrained(e.i)) continue;
    const Face_handle g = f->neighbor(e.i);
    if (!ours(g)) {
      deferred.push_back(e);
      continue;
    }
    if (!cdt.is_flipable(f, e.i)) continue;
    const int j = cdt.mirror_index(f, e.i);
    if (!ours(f->neighbor(CDT::cw(e.i))) || !ours(f->neighbor(CDT::ccw(e.i))) ||
        !ours(g->neighbor(CDT::cw(j))) || !ours(g->neighbor(CDT::ccw(j)))) {
      deferred.push_back(e);
      continue;
    }
    left.emplace_back(f->vertex(CDT::cw(e.i)), g);
    left.emplace_back(f->vertex(CDT::ccw(e.i)), f);
    flip_leaving_vertex_faces(cdt, f, e.i);
    ++flips;
    push_edges_around_flip<CDT>(f, g, stack);
  }
  return flips;
}

// Gives each vertex of `left` whose face pointer no longer holds it the face listed with it,
// from the last listed: the last face listed for a vertex in one chunk's list still holds it
// (a flip that took it out would have listed it again).
template <class Vertex_handle, class Face_handle>
void set_vertex_faces(const std::vector<std::pair<Vertex_handle, Face_handle>>& left) {
  for (auto it = left.rbegin(); it != left.rend(); ++it)
    if (!it->first->face()->has_vertex(it->first)) it->first->set_face(it->second);
}

// Pushes every edge of the faces around v on the stack: the edges whose in-circle tests a move
// of v changes.
template <class CDT>
void push_star_edges(const CDT& cdt, typename CDT::Vertex_handle v,
                     std::vector<Flip_candidate<CDT>>& stack) {
  auto fc = cdt.incident_faces(v), end = fc;
  do {
    const typename CDT::Face_handle f = fc;
    for (int j = 0; j < 3; ++j) stack.push_back(Flip_candidate<CDT>::of(f, j));
  } while (++fc != end);
}

// Whether the domain face f is the one to test its unconstrained edge i, so that a pass over
// the domain faces tests each edge once: the edge's only domain face, or of its two the one
// that sees the edge's smaller endpoint in (x, y) order first, counterclockwise (the other sees
// the endpoints the other way round). Not by address: the flips, hence the faces' layout and all
// sums over them, must be the same from run to run.
template <class CDT, class Less_xy>
bool tests_edge(const CDT& cdt, typename CDT::Face_handle f, int i, const Less_xy& less_xy) {
  if (f->is_constrained(i)) return false;
  const auto g = f->neighbor(i);
  return !g->is_inside_domain() || cdt.is_infinite(g) ||
         !less_xy(f->vertex(CDT::cw(i))->point(), f->vertex(CDT::ccw(i))->point());
}

// Restores the constrained Delaunay property of the domain after its free vertices moved:
// every edge with a domain face on its side is tested in place, and Lawson's flips start from
// those that fail, so the stack holds only the few edges around flips.
template <class CDT>
void restore_delaunay(CDT& cdt, std::vector<Flip_candidate<CDT>>& stack) {
  const auto less_xy = cdt.geom_traits().less_xy_2_object();
  for_each_face_prefetched(cdt.finite_faces_begin(), cdt.finite_faces_end(),
                           [&](typename CDT::Face_handle f) {
                             if (!f->is_inside_domain()) return;
                             for (int i = 0; i < 3; ++i) {
                               if (!tests_edge(cdt, f, i, less_xy) || !cdt.is_flipable(f, i))
                                 continue;
                               stack.assign(1, Flip_candidate<CDT>::of(f, i));
                               lawson_flips(cdt, stack);
                             }
                           });
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_DELAUNAY_FLIPS_H
