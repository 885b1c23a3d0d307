// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Writing the cells of a bounded Voronoi diagram as a MODFLOW 6 DISV grid.
#ifndef CVT_2_IO_WRITE_DISV_H
#define CVT_2_IO_WRITE_DISV_H

#include <CVT_2/IO/Metadata.h>
#include <CVT_2/IO/internal/write_number.h>
#include <CVT_2/Simulation_grid_2.h>

#include <cmath>
#include <cstddef>
#include <fstream>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

// The first of `cells` cells whose top or bottom (one value, or one a cell) is not finite or
// whose bottom is not below its top, as "cell k's ..." (k from 1); empty if none is.
inline std::string layer_error(const std::vector<double>& top, const std::vector<double>& bottom,
                               std::size_t cells) {
  for (std::size_t k = 0; k < cells; ++k) {
    const double t = top[top.size() == 1 ? 0 : k], b = bottom[bottom.size() == 1 ? 0 : k];
    if (!std::isfinite(t) || !std::isfinite(b))
      return "cell " + std::to_string(k + 1) + "'s " + (std::isfinite(t) ? "bottom " : "top ") +
             number_text(std::isfinite(t) ? b : t) + " is not a finite number";
    if (!(b < t))
      return "cell " + std::to_string(k + 1) + "'s bottom " + number_text(b) +
             " is not below its top " + number_text(t);
  }
  return {};
}

}  // namespace internal

namespace IO {

/// \ingroup PkgCvt2IO
/// Writes the cells of `grid` as the input file of MODFLOW 6's DISV package (discretization by
/// vertices), one layer from `bottom` to `top`: `DIMENSIONS` (NLAY 1, NCPL the cells, NVERT the
/// vertices), `GRIDDATA` (TOP and BOTM: `CONSTANT` for one value, `INTERNAL` for one a cell, in
/// the grid's order), `VERTICES` (`iv xv yv`, numbered from 1, each
/// shared by the cells it bounds) and `CELL2D` (`icell2d xc yc ncvert icvert...`: the cell center
/// is its generator, the vertices clockwise, closed by repeating the first, as flopy writes
/// them). This is the grid flopy's `VoronoiGrid` builds by clipping unbounded Voronoi cells, here
/// with the cells bounded by inner constraints too. Cells are numbered as in the grid, from 1.
///
/// MODFLOW 6 connects two cells through the first edge they share in their vertex lists and
/// takes the distances from their centers to that edge's line: so a vertex that only two cells
/// use, between two pieces of the bisector they share (where the bisector crosses a slit), is
/// left out, the face written whole. Without inner constraints, and with barriers, each pair of
/// cells then shares one edge (at a slit, the cells on its two sides also share its pieces).
/// Cells on the two sides of a barrier share no edge: MODFLOW sees no connection there.
/// `metadata`, if any, goes in comment lines after the first (`Metadata`).
/// \tparam Mesh a `Bvd_mesh_2`.
/// \throws std::invalid_argument if `top` or `bottom` has neither one value nor one a cell, or
///         a top or bottom is not finite or a bottom not below its top, naming the cell (from 1).
template <class Mesh>
void write_disv(std::ostream& os, const Simulation_grid_2<Mesh>& grid,
                const std::vector<double>& top, const std::vector<double>& bottom,
                const Metadata& metadata = {}) {
  using internal::write_number;
  using Index = typename Mesh::Index;
  const std::size_t cells = grid.number_of_cells();
  for (const auto& [values, name] : {std::pair(&top, "top"), std::pair(&bottom, "bottom")})
    if (values->size() != 1 && values->size() != cells)
      throw std::invalid_argument("write_disv: " + std::to_string(values->size()) + " " + name +
                                  " values for " + std::to_string(cells) +
                                  " cells (one, or one a cell)");
  const std::string bad = internal::layer_error(top, bottom, cells);
  if (!bad.empty()) throw std::invalid_argument("write_disv: " + bad);
  // Which cells use each vertex, and whether it lies between two bisector pieces of the two.
  std::vector<std::vector<Index>> users(grid.number_of_vertices());
  std::vector<unsigned char> inner(grid.number_of_vertices(), 1);
  for (std::size_t k = 0; k < cells; ++k)
    for (std::size_t j = 0, n = grid.degree(k); j < n; ++j) {
      const Index v = grid.vertex(k, j);
      users[v].push_back(Index(k));
      const auto &in = grid.side(k, (j + n - 1) % n), &out = grid.side(k, j);
      if (in.cell == Mesh::none || in.cell != out.cell || in.constraint != Mesh::none ||
          out.constraint != Mesh::none)
        inner[v] = 0;
    }
  std::vector<Index> number(grid.number_of_vertices(), Mesh::none);
  std::vector<Index> vertices;  // the grid vertex of each number
  for (std::size_t k = 0; k < cells; ++k)
    for (std::size_t j = 0; j < grid.degree(k); ++j) {
      const Index v = grid.vertex(k, j);
      const bool dropped = inner[v] && users[v].size() == 2 && users[v][0] != users[v][1];
      if (!dropped) number[v] = 0;
    }
  for (std::size_t i = 0; i < number.size(); ++i)
    if (number[i] == 0) number[i] = Index(vertices.size()), vertices.push_back(Index(i));

  os << "# MODFLOW 6 DISV: a bounded Voronoi grid written by CVT_2\n";
  for (const auto& [key, value] : metadata)
    os << "# " << internal::comment_text(key) << ": " << internal::comment_text(value) << '\n';
  os << "BEGIN OPTIONS\nEND OPTIONS\n\nBEGIN DIMENSIONS\n  NLAY 1\n  NCPL " << cells << "\n  NVERT "
     << vertices.size() << "\nEND DIMENSIONS\n\nBEGIN GRIDDATA\n  TOP\n";
  const auto array = [&](const std::vector<double>& values) {  // MODFLOW 6's array input
    if (values.size() == 1) {
      os << "    CONSTANT ";
      write_number(os, values[0]);
      os << '\n';
      return;
    }
    os << "    INTERNAL\n";
    for (std::size_t k = 0; k < values.size(); ++k) {
      os << (k % 10 == 0 ? "      " : " ");
      write_number(os, values[k]);
      if (k % 10 == 9 || k + 1 == values.size()) os << '\n';
    }
  };
  array(top);
  os << "  BOTM LAYERED\n";
  array(bottom);
  os << "END GRIDDATA\n\nBEGIN VERTICES\n";
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    os << "  " << i + 1 << ' ';
    write_number(os, grid.point(vertices[i]).x());
    os << ' ';
    write_number(os, grid.point(vertices[i]).y());
    os << '\n';
  }
  os << "END VERTICES\n\nBEGIN CELL2D\n";
  std::vector<Index> outline;
  for (std::size_t k = 0; k < cells; ++k) {
    outline.clear();
    for (std::size_t j = 0; j < grid.degree(k); ++j)
      if (number[grid.vertex(k, j)] != Mesh::none) outline.push_back(number[grid.vertex(k, j)]);
    os << "  " << k + 1 << ' ';
    write_number(os, grid.center(k).x());
    os << ' ';
    write_number(os, grid.center(k).y());
    os << ' ' << (outline.empty() ? 0 : outline.size() + 1);
    for (std::size_t j = outline.size(); j-- > 0;) os << ' ' << outline[j] + 1;
    if (!outline.empty()) os << ' ' << outline.back() + 1;
    os << '\n';
  }
  os << "END CELL2D\n";
}

/// \ingroup PkgCvt2IO
/// Writes the cells of `grid` as a DISV grid (as above), its layer from `bottom` to `top`.
/// \throws std::invalid_argument unless `bottom < top`.
template <class Mesh>
void write_disv(std::ostream& os, const Simulation_grid_2<Mesh>& grid, double top = 1,
                double bottom = 0, const Metadata& metadata = {}) {
  write_disv(os, grid, std::vector<double>{top}, std::vector<double>{bottom}, metadata);
}

/// \ingroup PkgCvt2IO
/// Writes the cells of `mesh` as a DISV grid, inner constraints as slits (its
/// `Simulation_grid_2`).
template <class Mesh>
void write_disv(std::ostream& os, const Mesh& mesh, double top = 1, double bottom = 0,
                const Metadata& metadata = {}) {
  write_disv(os, Simulation_grid_2<Mesh>(mesh), top, bottom, metadata);
}

/// \ingroup PkgCvt2IO
/// Writes `mesh` (a `Bvd_mesh_2` or a `Simulation_grid_2`) to the DISV file `filename`; returns
/// false if the file could not be written. \throws std::invalid_argument as the stream version,
/// before the file is opened.
template <class Mesh>
bool write_disv(const std::string& filename, const Mesh& mesh, double top = 1, double bottom = 0,
                const Metadata& metadata = {}) {
  std::ostringstream text;
  write_disv(text, mesh, top, bottom, metadata);
  std::ofstream os(filename);
  if (!os) return false;
  os << text.str();
  return static_cast<bool>(os);
}

}  // namespace IO
}  // namespace CVT_2

#endif  // CVT_2_IO_WRITE_DISV_H
