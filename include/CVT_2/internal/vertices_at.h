// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// vertices_at: the vertices of a triangulation at given points, or an error naming the first.
#ifndef CVT_2_INTERNAL_VERTICES_AT_H
#define CVT_2_INTERNAL_VERTICES_AT_H

#include <CVT_2/internal/to_string.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace CVT_2 {
namespace internal {

// The vertices of `cdt` at `points`, in order. \throws std::invalid_argument naming the
// option `what` and a point that is not a vertex.
template <class CDT, class PointRange>
std::vector<typename CDT::Vertex_handle> vertices_at(const CDT& cdt, const PointRange& points,
                                                     const std::string& what) {
  std::vector<typename CDT::Vertex_handle> vertices;
  typename CDT::Face_handle hint;
  for (const auto& p : points) {
    typename CDT::Locate_type lt;
    int li;
    hint = cdt.locate(p, lt, li, hint);
    if (lt != CDT::VERTEX)
      throw std::invalid_argument(what + ": " + to_string(p) +
                                  " is not a generator (insert it first)");
    vertices.push_back(hint->vertex(li));
  }
  return vertices;
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_VERTICES_AT_H
