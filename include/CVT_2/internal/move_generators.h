// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Moving many free generators to given targets: all at once, then within stars, then flips.
#ifndef CVT_2_INTERNAL_MOVE_GENERATORS_H
#define CVT_2_INTERNAL_MOVE_GENERATORS_H

#include <CVT_2/internal/delaunay_flips.h>
#include <CVT_2/internal/layout/prefetch.h>
#include <CVT_2/internal/move_vertex.h>
#include <CVT_2/internal/parallel/Face_chunks.h>
#include <CVT_2/internal/parallel/run_chunks.h>

#include <CGAL/enum.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iterator>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

// What the moves work in. All is freed at the end of a call but a small one's (release()): the
// lists of one item a vertex would otherwise sit through the evaluation that follows (40 bytes a
// generator), and so would the flips' stacks of a first move from random points (20 bytes a
// generator).
template <class CDT>
struct Move_buffers {
  std::vector<std::size_t> pending, moved, kept_back;
  std::vector<typename CDT::Point_2> from;  // where the vertices of the bulk move were
  std::vector<typename CDT::Face_handle> inverted;
  std::vector<Flip_candidate<CDT>> stack;
  // what each chunk of faces found, before they are put together in the order of the chunks
  std::vector<Chunk_vector<typename CDT::Face_handle>> chunk_inverted;
  std::vector<Chunk_vector<Flip_candidate<CDT>>> chunk_stack;
  std::vector<Chunk_vector<std::size_t>> chunk_pending;
  // for the flips chunk by chunk: each chunk's faces, the flips it leaves for after, the
  // vertices its flips took out of a face
  std::vector<Face_runs<typename CDT::Face>> chunk_runs;
  std::vector<Chunk_vector<Flip_candidate<CDT>>> chunk_deferred;
  std::vector<Chunk_vector<std::pair<typename CDT::Vertex_handle, typename CDT::Face_handle>>>
      chunk_left;
  // flips so far: made by the chunks on their own, and edges they left for after (for tests)
  std::size_t chunk_flips = 0, deferred_edges = 0;
  static constexpr std::size_t small_job = std::size_t(1) << 16;  // vertices moved
  // If set, the moves are local (no pass over all vertices or edges), and every face they
  // change is pushed here (some more than once): the faces around a moved vertex, both faces
  // of each flip.
  std::vector<typename CDT::Face_handle>* changed = nullptr;
  void release() {  // all but the counts and `changed`
    // A small job keeps them: freeing a megabyte or two at each move made glibc trim the heap's
    // top and fault it in again at the next (26% of an iteration at 2 * 10^4 generators).
    if (pending.capacity() < small_job && from.capacity() < small_job) return;
    Move_buffers released;
    released.chunk_flips = chunk_flips;
    released.deferred_edges = deferred_edges;
    released.changed = changed;
    *this = std::move(released);
  }
};

// Lists item(k) for the k of [0, n) with keep(k), in the order of k, into `out`: a pass that
// only reads, in chunks of 4096 on `threads` threads, each chunk listing into its own part of
// `b.chunk_pending`. Before keep(k), the pass prefetches ahead(k + 8) (nullptr: nothing).
template <class CDT, class Ahead, class Keep, class Item>
void list_in_order(std::size_t n, unsigned threads, const Ahead& ahead, const Keep& keep,
                   const Item& item, Move_buffers<CDT>& b, std::vector<std::size_t>& out) {
  constexpr std::size_t distance = 8, chunk_size = 4096;
  const std::size_t chunks = (n + chunk_size - 1) / chunk_size;
  b.chunk_pending.resize(std::max(b.chunk_pending.size(), chunks));
  run_chunks(chunks, threads, [&](std::size_t c) {
    Chunk_vector<std::size_t>& part = b.chunk_pending[c];
    part.clear();
    const std::size_t end = std::min(n, (c + 1) * chunk_size);
    for (std::size_t k = c * chunk_size; k < end; ++k) {
      if (k + distance < end) prefetch(ahead(k + distance));
      if (keep(k)) part.push_back(item(k));
    }
  });
  out.clear();
  for (std::size_t c = 0; c < chunks; ++c) {
    out.insert(out.end(), b.chunk_pending[c].begin(), b.chunk_pending[c].end());
    std::vector<std::size_t>().swap(b.chunk_pending[c]);  // one copy of the list at a time
  }
}

// The i of `order` (random access) whose vertex(i) is not at target(i), in that order, into
// `b.pending`: a read of every vertex, in chunks on `threads` threads.
template <class CDT, class OrderRange, class VertexAt, class TargetAt>
void list_pending(const OrderRange& order, const VertexAt& vertex, const TargetAt& target,
                  unsigned threads, Move_buffers<CDT>& b) {
  const auto first = std::begin(order);
  const auto i = [&](std::size_t k) { return std::size_t(first[std::ptrdiff_t(k)]); };
  list_in_order(
      std::size_t(std::end(order) - first), threads, [&](std::size_t k) { return &*vertex(i(k)); },
      [&](std::size_t k) { return vertex(i(k))->point() != target(i(k)); }, i, b, b.pending);
}

// Sets vertex(i) to target(i) for every i of `pending`, in chunks on `threads` threads,
// remembering where each was in `b.from`.
template <class CDT, class VertexAt, class TargetAt>
void set_targets(const std::vector<std::size_t>& pending, const VertexAt& vertex,
                 const TargetAt& target, unsigned threads, Move_buffers<CDT>& b) {
  const std::size_t n = pending.size();
  constexpr std::size_t distance = 8, chunk_size = 4096;
  b.from.resize(n);
  run_chunks((n + chunk_size - 1) / chunk_size, threads, [&](std::size_t c) {
    const std::size_t end = std::min(n, (c + 1) * chunk_size);
    for (std::size_t k = c * chunk_size; k < end; ++k) {
      if (k + distance < end) prefetch(&*vertex(pending[k + distance]));
      const typename CDT::Vertex_handle v = vertex(pending[k]);
      b.from[k] = v->point();
      v->set_point(target(pending[k]));
    }
  });
}

// One pass over the domain faces after a bulk move: the faces that are not positive into
// `b.inverted`, and the edges of the positive ones that fail their in-circle test (each edge
// once) onto `b.chunk_stack`. Each chunk of faces has its own outputs, its faces' runs in
// memory included (`b.chunk_runs`); the faces are joined in chunk order, the stacks are not
// (chunk_lawson_flips() pops them chunk by chunk).
template <class CDT>
void check_moved_faces(const CDT& cdt, const Face_chunks<CDT>& chunks, unsigned threads,
                       Move_buffers<CDT>& b) {
  using Face_handle = typename CDT::Face_handle;
  const auto orientation = cdt.geom_traits().orientation_2_object();
  const auto less_xy = cdt.geom_traits().less_xy_2_object();
  b.chunk_inverted.resize(chunks.size());
  b.chunk_stack.resize(chunks.size());
  b.chunk_runs.resize(chunks.size());
  chunks.for_each(
      [&](std::size_t c, auto first, auto last) {
        Chunk_vector<Face_handle>& inverted = b.chunk_inverted[c];
        Chunk_vector<Flip_candidate<CDT>>& stack = b.chunk_stack[c];
        Face_runs<typename CDT::Face>& runs = b.chunk_runs[c];
        inverted.clear();
        stack.clear();
        runs.clear();
        for_each_face_prefetched(first, last, [&](Face_handle f) {
          runs.add(&*f);
          if (!f->is_inside_domain() || cdt.is_infinite(f)) return;
          if (orientation(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()) !=
              CGAL::LEFT_TURN) {
            inverted.push_back(f);
            return;
          }
          for (int i = 0; i < 3; ++i)
            if (tests_edge(cdt, f, i, less_xy) && cdt.is_flipable(f, i))
              stack.push_back(Flip_candidate<CDT>::of(f, i));
        });
        runs.finish();
      },
      threads);
  b.inverted.clear();
  for (std::size_t c = 0; c < chunks.size(); ++c)
    b.inverted.insert(b.inverted.end(), b.chunk_inverted[c].begin(), b.chunk_inverted[c].end());
}

// Lawson's flips from the chunks' stacks and `b.stack`. First each chunk flips what it can alone
// (chunk_local_flips()), on `threads` threads; then, in this thread, the vertices get faces that
// hold them again, and Lawson's flips go on from `b.stack`, then from what each chunk left, the
// last chunk's first. A chunk's flips depend on its faces only, and everything after runs in
// the chunks' order: the same flips whatever the threads. Lawson's flips end at the constrained
// Delaunay triangulation in any order; the faces that hold its triangles and the faces the
// vertices point to depend on the order, and so do the bits of later sums.
template <class CDT>
void chunk_lawson_flips(CDT& cdt, unsigned threads, Move_buffers<CDT>& b) {
  const std::size_t chunks = b.chunk_stack.size();
  b.chunk_deferred.resize(chunks);
  b.chunk_left.resize(chunks);
  std::vector<std::size_t> flips(chunks, 0);
  const auto set_faces = [&] {
    for (std::size_t c = 0; c < chunks; ++c) {
      set_vertex_faces(b.chunk_left[c]);
      std::vector<std::pair<typename CDT::Vertex_handle, typename CDT::Face_handle>>().swap(
          b.chunk_left[c]);
    }
  };
  try {
    run_chunks(chunks, threads, [&](std::size_t c) {
      b.chunk_deferred[c].clear();
      b.chunk_left[c].clear();
      flips[c] = chunk_local_flips(cdt, b.chunk_runs[c], b.chunk_stack[c], b.chunk_deferred[c],
                                   b.chunk_left[c]);
    });
  } catch (...) {  // out of memory: the triangulation stays valid, if not Delaunay
    set_faces();
    throw;
  }
  set_faces();
  for (std::size_t c = 0; c < chunks; ++c) {
    b.chunk_flips += flips[c];
    b.deferred_edges += b.chunk_deferred[c].size();
  }
  lawson_flips(cdt, b.stack);
  for (std::size_t c = chunks; c-- > 0;) {
    b.stack.swap(b.chunk_deferred[c]);
    lawson_flips(cdt, b.stack);
  }
}

// Rounds of putting back: a face that is not positive has a vertex that moved (at their old
// places, its vertices made a positive face), so each round puts back at least one and the
// rounds end, at the latest with the old triangulation. A round looks its vertices up in one
// pass over `pending` (in chunks on `threads` threads: it only reads), so that everything
// happens in the order of `pending`, not of addresses; the few vertices a round wants are
// sorted, and a bitmap of their hashes turns away almost every other vertex of the pass in one
// read. The vertices put back are listed in `b.kept_back`, in the order of `pending`.
template <class CDT, class VertexAt>
void put_back_inverted(const CDT& cdt, const std::vector<std::size_t>& pending,
                       const VertexAt& vertex, unsigned threads, Move_buffers<CDT>& b) {
  using Vertex_handle = typename CDT::Vertex_handle;
  const auto orientation = cdt.geom_traits().orientation_2_object();
  const std::size_t n = pending.size();
  std::vector<bool> put_back(b.inverted.empty() ? 0 : n, false);
  constexpr std::size_t bits = std::size_t(1) << 16;
  std::vector<std::uint64_t> bitmap(b.inverted.empty() ? 0 : bits / 64);
  const auto hash = [](Vertex_handle v) {  // 16 bits of the address, mixed (on any width)
    const std::uint64_t a = std::uint64_t(reinterpret_cast<std::uintptr_t>(&*v));
    return std::size_t((a * std::uint64_t(0x9E3779B97F4A7C15u)) >> 48);
  };
  const auto less = [](Vertex_handle u, Vertex_handle v) {
    return std::less<const void*>()(&*u, &*v);
  };
  std::vector<Vertex_handle> wanted;
  std::vector<std::size_t> found;  // where in `pending` the vertices of a round are
  while (!b.inverted.empty()) {
    wanted.clear();
    for (const auto f : b.inverted)
      for (int i = 0; i < 3; ++i) wanted.push_back(f->vertex(i));
    std::sort(wanted.begin(), wanted.end(), less);
    wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());
    std::fill(bitmap.begin(), bitmap.end(), 0);
    for (const Vertex_handle v : wanted) bitmap[hash(v) >> 6] |= std::uint64_t(1) << (hash(v) & 63);
    b.inverted.clear();
    list_in_order(
        n, threads, [](std::size_t) { return nullptr; },  // it reads lists, no vertex
        [&](std::size_t k) {
          const Vertex_handle v = vertex(pending[k]);
          const std::size_t h = hash(v);
          return !put_back[k] && (bitmap[h >> 6] >> (h & 63) & 1) &&
                 std::binary_search(wanted.begin(), wanted.end(), v, less);
        },
        [](std::size_t k) { return k; }, b, found);
    for (const std::size_t k : found) {
      const Vertex_handle v = vertex(pending[k]);
      put_back[k] = true;
      v->set_point(b.from[k]);
      auto fc = cdt.incident_faces(v), end = fc;
      do {
        if (orientation(fc->vertex(0)->point(), fc->vertex(1)->point(), fc->vertex(2)->point()) !=
            CGAL::LEFT_TURN)
          b.inverted.push_back(fc);
      } while (++fc != end);
    }
  }
  b.kept_back.clear();
  for (std::size_t k = 0; k < put_back.size(); ++k)
    if (put_back[k]) b.kept_back.push_back(pending[k]);
}

// Sets vertex(i) to target(i) for every i of `pending`, all at once, then puts back where it
// was every vertex of a face that this left without a positive orientation, and the vertices
// of the faces that this in turn leaves so, until every face is positive: the triangulation is
// then valid again (a vertex moved crossed no edge, hence no constraint), and every vertex is
// at its target but those put back, listed in `b.kept_back` in the order of `pending`.
//
// This is one linear pass over the vertices and one over the faces, both in memory order and
// prefetched, instead of a walk around each vertex's star; when most vertices move, as in
// Lloyd iteration, only a few are put back. Both passes run in chunks on `threads` threads,
// each chunk with its own output, put together in the order of the chunks: the same bits
// whatever the threads. The pass over the faces also runs the in-circle test of every edge of
// the domain once and pushes those that fail on the chunks' stacks: with the edges around the
// vertices put back (push_star_edges, on `b.stack`), the stacks then hold every edge that can
// have lost the Delaunay property, ready for chunk_lawson_flips(). The faces around a moved vertex
// are all in the domain (it is free and has a cell). An in-circle test next to a face that is not
// positive means nothing, but that face's edges are all pushed again, with its vertices put back.
template <class CDT, class VertexAt, class TargetAt>
void move_all_at_once(CDT& cdt, const Face_chunks<CDT>& chunks, unsigned threads,
                      const std::vector<std::size_t>& pending, const VertexAt& vertex,
                      const TargetAt& target, Move_buffers<CDT>& b) {
  set_targets(pending, vertex, target, threads, b);
  check_moved_faces(cdt, chunks, threads, b);
  put_back_inverted(cdt, pending, vertex, threads, b);
}

// Moves each free vertex vertex(i) toward target(i), for i in `order` (a range of numbers in
// the cells' visit order, kind to the cache), in at most `passes` passes. A pass moves every
// vertex not yet at its target as far as its star allows (move_free_vertex: no edge is crossed,
// so no constraint), then edge flips restore the constrained Delaunay property; the next pass
// goes on from the new stars. When most vertices move, the first pass moves them all at once
// instead (move_all_at_once) and only those it puts back within their stars. A vertex that
// reaches its target is at it to the bit. Returns how many did not reach it.
template <class CDT, class OrderRange, class VertexAt, class TargetAt>
std::size_t move_free_vertices(CDT& cdt, const Face_chunks<CDT>& chunks, unsigned threads,
                               const OrderRange& order, const VertexAt& vertex,
                               const TargetAt& target, std::size_t passes, Move_buffers<CDT>& b) {
  std::vector<std::size_t>& pending = b.pending;
  list_pending(order, vertex, target, threads, b);
  for (std::size_t pass = 0; pass < passes && !pending.empty(); ++pass) {
    const bool at_once = pass == 0 && pending.size() * 8 > order.size() && !b.changed;
    if (at_once) {
      b.stack.clear();
      move_all_at_once(cdt, chunks, threads, pending, vertex, target, b);  // fills the stacks
      pending.swap(b.kept_back);
    } else {
      b.moved.clear();
    }
    std::size_t kept = 0;
    for_each_star_prefetched(
        pending.size(), [&](std::size_t k) { return vertex(pending[k]); },
        [&](std::size_t k) {
          const std::size_t i = pending[k];
          const double done = move_free_vertex(cdt, vertex(i), target(i));
          if (at_once) {
            push_star_edges(cdt, vertex(i), b.stack);  // put back, then perhaps moved: retest
          } else if (done > 0) {
            b.moved.push_back(i);
            if (b.changed) push_star(cdt, vertex(i), *b.changed);
          }
          if (done < 1) pending[kept++] = i;
        });
    pending.resize(kept);
    if (at_once) {
      chunk_lawson_flips(cdt, threads, b);
      continue;
    }
    if (b.moved.empty()) break;  // every remaining vertex is stuck where it is
    if (b.moved.size() * 8 > order.size() && !b.changed) {
      restore_delaunay(cdt, b.stack);  // most vertices moved: each edge of the domain once
    } else {
      // Few moved: only edges of their stars and links can have lost the Delaunay property
      // (their in-circle tests involve a moved vertex); Lawson's flips go on from there.
      b.stack.clear();
      for (const std::size_t i : b.moved) push_star_edges(cdt, vertex(i), b.stack);
      if (b.changed)
        lawson_flips(cdt, b.stack, [&](auto f, auto g) {
          b.changed->push_back(f);
          b.changed->push_back(g);
        });
      else
        lawson_flips(cdt, b.stack);
    }
  }
  const std::size_t missed = pending.size();
  b.release();
  return missed;
}

// The same with the vertices and targets in two vectors.
template <class CDT>
std::size_t move_free_vertices(CDT& cdt, const Face_chunks<CDT>& chunks, unsigned threads,
                               const std::vector<typename CDT::Vertex_handle>& vertices,
                               const std::vector<typename CDT::Point_2>& targets,
                               const std::vector<std::size_t>& order, std::size_t passes,
                               Move_buffers<CDT>& b) {
  CGAL_precondition(vertices.size() == targets.size() && order.size() == vertices.size());
  return move_free_vertices(
      cdt, chunks, threads, order, [&](std::size_t i) { return vertices[i]; },
      [&](std::size_t i) -> const typename CDT::Point_2& { return targets[i]; }, passes, b);
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_MOVE_GENERATORS_H
