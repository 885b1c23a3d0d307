// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Writing the domain's triangulation in Triangle's .node, .ele and .edge formats.
#ifndef CVT_2_IO_WRITE_TRIANGLE_H
#define CVT_2_IO_WRITE_TRIANGLE_H

#include <CVT_2/IO/internal/write_number.h>

#include <CGAL/Kernel/global_functions.h>

#include <cstddef>
#include <fstream>
#include <ostream>
#include <string>
#include <unordered_map>

namespace CVT_2 {
namespace IO {

/// \ingroup PkgCvt2IO
/// Writes the triangles of the domain of `cdt` as Shewchuk's Triangle writes a mesh, numbered
/// from 1: `node` (`<#vertices> 2 0 1`, then `i x y marker`, marker 1 on constrained vertices),
/// `ele` (`<#triangles> 3 0`, then `i a b c`, counterclockwise) and `edge` (`<#edges> 1`, then
/// `i a b marker`, marker 1 on constrained edges, the domain's boundary and inner constraints).
/// Only vertices and edges of domain triangles are written.
/// \tparam CDT a constrained triangulation whose faces model `BvdFaceBase_2`.
template <class CDT>
void write_triangle(std::ostream& node, std::ostream& ele, std::ostream& edge, const CDT& cdt) {
  using Vertex_handle = typename CDT::Vertex_handle;
  std::unordered_map<Vertex_handle, std::size_t> index;
  std::size_t triangles = 0, edges = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_inside_domain()) continue;
    ++triangles;
    for (int i = 0; i < 3; ++i) index.emplace(f->vertex(i), 0);
  }
  // An edge of the domain once: from its only domain face, or from the one of its two that
  // sees its smaller end (in x, then y) first, counterclockwise.
  const auto writes_edge = [&](typename CDT::Face_handle f, int i) {
    const auto g = f->neighbor(i);
    return cdt.is_infinite(g) || !g->is_inside_domain() ||
           CGAL::compare_xy(f->vertex(CDT::ccw(i))->point(), f->vertex(CDT::cw(i))->point()) ==
               CGAL::SMALLER;
  };
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->is_inside_domain())
      for (int i = 0; i < 3; ++i) edges += writes_edge(f, i) ? 1 : 0;
  node << index.size() << " 2 0 1\n";
  std::size_t n = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    const auto it = index.find(v);
    if (it == index.end()) continue;
    it->second = ++n;
    node << n << ' ';
    internal::write_number(node, v->point().x());
    node << ' ';
    internal::write_number(node, v->point().y());
    node << ' ' << (cdt.are_there_incident_constraints(v) ? 1 : 0) << '\n';
  }
  ele << triangles << " 3 0\n";
  edge << edges << " 1\n";
  std::size_t t = 0, e = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_inside_domain()) continue;
    ele << ++t << ' ' << index[f->vertex(0)] << ' ' << index[f->vertex(1)] << ' '
        << index[f->vertex(2)] << '\n';
    for (int i = 0; i < 3; ++i)
      if (writes_edge(f, i))
        edge << ++e << ' ' << index[f->vertex(CDT::ccw(i))] << ' ' << index[f->vertex(CDT::cw(i))]
             << ' ' << (f->is_constrained(i) ? 1 : 0) << '\n';
  }
}

/// \ingroup PkgCvt2IO
/// Writes the files `prefix.node`, `prefix.ele` and `prefix.edge`; returns false if one could
/// not be written.
template <class CDT>
bool write_triangle(const std::string& prefix, const CDT& cdt) {
  std::ofstream node(prefix + ".node"), ele(prefix + ".ele"), edge(prefix + ".edge");
  if (!node || !ele || !edge) return false;
  write_triangle(node, ele, edge, cdt);
  return node && ele && edge;
}

}  // namespace IO
}  // namespace CVT_2

#endif  // CVT_2_IO_WRITE_TRIANGLE_H
