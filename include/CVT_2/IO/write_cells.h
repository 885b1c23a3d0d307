// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Writing generators and cells as text, one line each.
#ifndef CVT_2_IO_WRITE_CELLS_H
#define CVT_2_IO_WRITE_CELLS_H

#include <CVT_2/IO/internal/write_number.h>

#include <fstream>
#include <ostream>
#include <string>

namespace CVT_2 {
namespace IO {

/// \ingroup PkgCvt2IO
/// Writes one line per generator with a cell, in the order of
/// `Bounded_voronoi_diagram_2::for_each_cell()`: `x y c`, `c` = 1 for a constrained vertex.
/// Coordinates are the shortest decimals that read back as the same doubles.
/// \tparam BVD a `Bounded_voronoi_diagram_2`.
template <class BVD>
void write_points(std::ostream& os, const BVD& bvd) {
  bvd.for_each_cell([&](typename BVD::Vertex_handle v, const auto&) {
    internal::write_number(os, v->point().x());
    os << ' ';
    internal::write_number(os, v->point().y());
    os << ' ' << (bvd.is_free(v) ? 0 : 1) << '\n';
  });
}

/// \ingroup PkgCvt2IO
/// Writes one line per cell, in the order of `Bounded_voronoi_diagram_2::for_each_cell()`:
/// `x y c k x1 y1 ... xk yk`, the generator, `c` = 1 for a constrained vertex, then the cell's
/// `k` vertices counterclockwise (a constrained generator is one of them, once per slit).
/// \tparam BVD a `Bounded_voronoi_diagram_2`.
template <class BVD>
void write_cells(std::ostream& os, const BVD& bvd) {
  const auto xy = [&os](const auto& p) {
    internal::write_number(os, p.x());
    os << ' ';
    internal::write_number(os, p.y());
  };
  bvd.for_each_cell([&](typename BVD::Vertex_handle v, const auto& cell) {
    xy(v->point());
    os << ' ' << (bvd.is_free(v) ? 0 : 1) << ' ' << cell.size();
    for (const auto& c : cell) os << ' ', xy(c.point);
    os << '\n';
  });
}

}  // namespace IO
}  // namespace CVT_2

#endif  // CVT_2_IO_WRITE_CELLS_H
