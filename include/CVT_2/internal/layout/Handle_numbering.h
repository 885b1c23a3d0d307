// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Handle_numbering: a number for each vertex or face, kept in the record itself when it has room.
#ifndef CVT_2_INTERNAL_LAYOUT_HANDLE_NUMBERING_H
#define CVT_2_INTERNAL_LAYOUT_HANDLE_NUMBERING_H

#include <cstddef>
#include <type_traits>
#include <unordered_map>
#include <utility>

namespace CVT_2 {
namespace internal {

template <class T, class = void>
struct has_set_id : std::false_type {};  // set_id(std::size_t), std::size_t id() const
template <class T>
struct has_set_id<T, std::void_t<decltype(std::declval<T&>().set_id(std::size_t(0))),
                                 decltype(std::size_t(std::declval<const T&>().id()))>>
    : std::true_type {};

template <class T, class = void>
struct has_id_reference : std::false_type {};  // int& id(), as CGAL's *_with_id_2 bases
template <class T>
struct has_id_reference<T, std::void_t<decltype(std::declval<T&>().id() = 0)>> : std::true_type {};

// A number for each handle of a triangulation, written by one pass and read by later ones. It
// lives in the record when the record has an id (CGAL's Triangulation_vertex_base_with_id_2,
// CVT_2::Bvd_face_base_2), where the passes that read it have the record in cache already;
// otherwise in a hash map. Writes must not race with reads: set() in one pass, get() in the next.
template <class Handle>
class Handle_numbering {
  using Record = std::remove_reference_t<decltype(*std::declval<Handle>())>;

 public:
  static constexpr bool in_record = has_set_id<Record>::value || has_id_reference<Record>::value;

  // Makes room for n numbers (for the map; nothing for records).
  void reserve(std::size_t n) {
    if constexpr (!in_record) m_map.reserve(n);
  }
  void set(Handle h, std::size_t i) {
    if constexpr (has_set_id<Record>::value)
      h->set_id(i);
    else if constexpr (has_id_reference<Record>::value)
      h->id() = static_cast<int>(i);
    else
      m_map[h] = i;
  }
  std::size_t get(Handle h) const {
    if constexpr (in_record)
      return static_cast<std::size_t>(h->id());
    else
      return m_map.at(h);
  }

 private:
  std::unordered_map<Handle, std::size_t> m_map;  // only without an id in the record
};

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_LAYOUT_HANDLE_NUMBERING_H
