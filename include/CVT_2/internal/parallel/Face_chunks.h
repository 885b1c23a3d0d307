// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Face_chunks: the faces of a triangulation cut into runs, in memory order, for parallel passes.
#ifndef CVT_2_INTERNAL_PARALLEL_FACE_CHUNKS_H
#define CVT_2_INTERNAL_PARALLEL_FACE_CHUNKS_H

#include <CVT_2/internal/parallel/run_chunks.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <iterator>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

// The faces of a triangulation (infinite ones included) in runs, in memory order, for passes
// that run on several threads: a chunk holds the faces of chunk_size() consecutive slots of the
// triangulation's face container (fewer faces where slots are free; a chunk without any is
// left out). The chunks depend on the container only, so that chunks, and any sum made chunk
// by chunk and then over the chunks in order, do not depend on the number of threads; and
// update() finds each chunk's first face by its slot number, without a walk over the faces
// (a serial pass at every evaluation). Smaller chunks for heavier work per face, so that small
// triangulations still have chunks for two threads (run_chunks() gives each thread two or
// more). Moving vertices and flipping edges create and delete no face, so the chunks stay
// valid across them; inserting or removing vertices invalidates them.
template <class CDT>
class Face_chunks {
 public:
  using Face_iterator = typename CDT::All_faces_iterator;
  static constexpr std::size_t default_chunk_size = 4096;
  // for cells under a quadrature rule, several times the work of exact formulas (tens of
  // density values a cell): a few thousand cells already make chunks for two threads
  static constexpr std::size_t quadrature_chunk_size = default_chunk_size / 4;

  explicit Face_chunks(std::size_t chunk_size = default_chunk_size)
      : m_chunk_size(std::max<std::size_t>(chunk_size, 1)) {}
  explicit Face_chunks(const CDT& cdt, std::size_t chunk_size = default_chunk_size)
      : Face_chunks(chunk_size) {
    update(cdt);
  }

  // Cuts the faces of `cdt` into chunks again. The slots are numbered by the block sizes that
  // the triangulation's own growth gives its face container (CGAL's Compact_container, a slot
  // by number in O(1)); a container assigned or merged into by hand would break that.
  void update(const CDT& cdt) {
    m_cdt = &cdt;
    std::vector<Face_iterator> starts;
    if (cdt.dimension() == 2) {
      auto& faces = cdt.tds().faces();
      const std::size_t slots = faces.capacity();
      starts.reserve((slots + m_chunk_size - 1) / m_chunk_size);
      for (std::size_t first = 0; first < slots; first += m_chunk_size) {
        const std::size_t last = std::min(slots, first + m_chunk_size);
        std::size_t i = first;
        while (i < last && !faces.is_used(i)) ++i;
        if (i == last) continue;
        starts.push_back(faces.iterator_to(faces[i]));
        CGAL_assertion(faces.index(starts.back()) == i);
      }
    }
    m_starts.swap(starts);  // all or nothing
  }

  std::size_t size() const { return m_starts.size(); }     // the number of chunks
  std::size_t chunk_size() const { return m_chunk_size; }  // slots a chunk, hence most faces

  // Calls visit(chunk, first, last) for every chunk, with the range of its faces, on `threads`
  // threads (0: one per core; 1: in order, in this thread), as run_chunks() does: `visit` must
  // allow concurrent calls for different chunks, and writing to an output of its own chunk
  // makes the outcome independent of the threads.
  template <class Visit>
  void for_each(const Visit& visit, unsigned threads) const {
    run_chunks(m_starts.size(), threads, [&](std::size_t c) {
      const Face_iterator last = c + 1 < m_starts.size() ? m_starts[c + 1] : m_cdt->all_faces_end();
      visit(c, m_starts[c], last);
    });
  }

 private:
  std::size_t m_chunk_size;
  const CDT* m_cdt = nullptr;
  std::vector<Face_iterator> m_starts;  // the first face of each chunk
};

// The faces of one chunk as runs of neighbours in memory, built by a pass over the chunk in
// memory order: whether a face is one of them takes a search among the runs and no read of
// the face, which another chunk's thread may be writing meanwhile. A chunk laid out in one or
// two blocks of the face container is one or two runs; free slots cut more.
template <class Face>
class alignas(cache_line) Face_runs {
 public:
  void clear() { m_runs.clear(); }
  // Adds f, which follows the faces added so far in memory order.
  void add(const Face* f) {
    if (!m_runs.empty() && m_runs.back().second == f)
      ++m_runs.back().second;
    else
      m_runs.emplace_back(f, f + 1);
  }
  // Sorts the runs by address (blocks need not follow each other in memory), for holds().
  void finish() {
    std::sort(m_runs.begin(), m_runs.end(), [](const Run& a, const Run& b) {
      return std::less<const Face*>()(a.first, b.first);
    });
  }
  // Whether f is one of the faces added. \pre finish() after the last add()
  bool holds(const Face* f) const {
    const std::less<const Face*> less;
    const auto after =
        std::upper_bound(m_runs.begin(), m_runs.end(), f,
                         [&](const Face* p, const Run& r) { return less(p, r.first); });
    return after != m_runs.begin() && less(f, std::prev(after)->second);
  }

 private:
  using Run = std::pair<const Face*, const Face*>;  // [first, last)
  std::vector<Run> m_runs;
};

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_PARALLEL_FACE_CHUNKS_H
