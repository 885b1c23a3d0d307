// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Handle_set: a set of CGAL handles for the small walks of a local update, reused between walks
// without allocating (std::unordered_set allocates a node per element).
#ifndef CVT_2_INTERNAL_HANDLE_SET_H
#define CVT_2_INTERNAL_HANDLE_SET_H

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace CVT_2 {
namespace internal {

// Open addressing with linear probing; the null handle marks an empty slot. clear() costs the
// number of elements, not the capacity. The elements also come in the order of insertion.
template <class Handle>
class Handle_set {
 public:
  // Whether h (not null) was new.
  bool insert(Handle h) {
    if (2 * (m_elements.size() + 1) > m_slots.size()) grow();
    std::size_t i = slot(h);
    for (; m_slots[i] != Handle(); i = (i + 1) & m_mask)
      if (m_slots[i] == h) return false;
    m_slots[i] = h;
    m_elements.push_back(h);
    return true;
  }
  bool contains(Handle h) const {
    if (m_slots.empty()) return false;
    for (std::size_t i = slot(h); m_slots[i] != Handle(); i = (i + 1) & m_mask)
      if (m_slots[i] == h) return true;
    return false;
  }
  void clear() {
    for (const Handle h : m_elements) {
      std::size_t i = slot(h);
      while (m_slots[i] != Handle()) m_slots[i] = Handle(), i = (i + 1) & m_mask;
    }
    m_elements.clear();
  }
  std::size_t size() const { return m_elements.size(); }
  bool empty() const { return m_elements.empty(); }
  auto begin() const { return m_elements.begin(); }
  auto end() const { return m_elements.end(); }

 private:
  std::size_t slot(Handle h) const {
    return std::size_t((std::uint64_t(std::hash<Handle>()(h)) * 0x9e3779b97f4a7c15ULL) >> 20) &
           m_mask;
  }
  void grow() {
    const std::vector<Handle> elements = m_elements;
    m_slots.assign(m_slots.empty() ? 64 : 2 * m_slots.size(), Handle());
    m_mask = m_slots.size() - 1;
    m_elements.clear();
    for (const Handle h : elements) insert(h);
  }

  std::vector<Handle> m_slots;
  std::vector<Handle> m_elements;
  std::size_t m_mask = 0;
};

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_HANDLE_SET_H
