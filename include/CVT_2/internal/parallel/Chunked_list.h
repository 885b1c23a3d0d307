// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Chunked_list: what the chunks of a parallel pass found, read as one list without a copy.
#ifndef CVT_2_INTERNAL_PARALLEL_CHUNKED_LIST_H
#define CVT_2_INTERNAL_PARALLEL_CHUNKED_LIST_H

#include <CVT_2/internal/parallel/run_chunks.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

// The lists of the chunks of a pass, one after the other, as one random-access list: the chunks
// write their own lists (on several threads), seal() joins them in chunk order. Joining by
// copying would hold every item twice at the peak (the moves of a million generators are 32 MB);
// here an index is found by a table of where each block of indices starts, and a scan of the
// few chunks that overlap the block.
template <class T>
class Chunked_list {
 public:
  using value_type = T;
  class const_iterator;

  // Empties the list, and frees its memory, with room for `n` empty chunks.
  void reset(std::size_t n) {
    m_chunks.clear();
    m_chunks.resize(n);
    m_ends.clear();
    m_block_chunk.clear();
  }
  // The size of chunk c's list when last sealed (0 if none): a guess of its next size.
  std::size_t previous_size(std::size_t c) const { return c < m_sizes.size() ? m_sizes[c] : 0; }
  std::vector<T>& chunk(std::size_t c) { return m_chunks[c]; }  // to write, before seal()
  const std::vector<T>& chunk(std::size_t c) const { return m_chunks[c]; }
  std::size_t number_of_chunks() const { return m_chunks.size(); }
  // the index of chunk c's first item, once sealed
  std::size_t chunk_begin(std::size_t c) const { return m_ends[c] - m_chunks[c].size(); }

  // Joins the chunks' lists, in chunk order.
  void seal() {
    m_ends.resize(m_chunks.size());
    m_sizes.resize(m_chunks.size());
    std::size_t n = 0;
    for (std::size_t c = 0; c < m_chunks.size(); ++c) {
      m_sizes[c] = m_chunks[c].size();
      m_ends[c] = n += m_sizes[c];
    }
    m_block_chunk.clear();
    std::size_t c = 0;
    for (std::size_t first = 0; first < n; first += block) {
      while (m_ends[c] <= first) ++c;
      m_block_chunk.push_back(c);
    }
  }
  void clear() { reset(0); }

  std::size_t size() const { return m_ends.empty() ? 0 : m_ends.back(); }
  bool empty() const { return size() == 0; }
  const T& operator[](std::size_t i) const {
    CGAL_precondition(i < size());
    std::size_t c = m_block_chunk[i / block];
    while (m_ends[c] <= i) ++c;
    return m_chunks[c][i - (m_ends[c] - m_chunks[c].size())];
  }
  const_iterator begin() const { return const_iterator(this, 0); }
  const_iterator end() const { return const_iterator(this, m_chunks.size()); }

  // Forward, chunk by chunk.
  class const_iterator {
   public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = T;
    using difference_type = std::ptrdiff_t;
    using pointer = const T*;
    using reference = const T&;
    const_iterator() = default;
    reference operator*() const { return m_list->m_chunks[m_chunk][m_item]; }
    pointer operator->() const { return &**this; }
    const_iterator& operator++() {
      if (++m_item == m_list->m_chunks[m_chunk].size()) {
        m_item = 0;
        ++m_chunk;
        skip_empty();
      }
      return *this;
    }
    const_iterator operator++(int) {
      const_iterator old = *this;
      ++*this;
      return old;
    }
    friend bool operator==(const const_iterator& a, const const_iterator& b) {
      return a.m_chunk == b.m_chunk && a.m_item == b.m_item;
    }
    friend bool operator!=(const const_iterator& a, const const_iterator& b) { return !(a == b); }

   private:
    friend class Chunked_list;
    const_iterator(const Chunked_list* list, std::size_t chunk) : m_list(list), m_chunk(chunk) {
      skip_empty();
    }
    void skip_empty() {
      while (m_chunk < m_list->m_chunks.size() && m_list->m_chunks[m_chunk].empty()) ++m_chunk;
    }
    const Chunked_list* m_list = nullptr;
    std::size_t m_chunk = 0, m_item = 0;
  };

 private:
  static constexpr std::size_t block = 1024;  // indices a block; a chunk of cells has hundreds
  std::vector<Chunk_vector<T>> m_chunks;
  std::vector<std::size_t> m_ends;         // one past each chunk's last index
  std::vector<std::size_t> m_block_chunk;  // the chunk of each block's first index
  std::vector<std::size_t> m_sizes;        // each chunk's size when last sealed
};

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_PARALLEL_CHUNKED_LIST_H
