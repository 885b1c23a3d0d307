// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Writing which cells of a grid lie on each constraint, for a simulator's boundary conditions.
#ifndef CVT_2_IO_WRITE_CELLS_ON_CONSTRAINTS_H
#define CVT_2_IO_WRITE_CELLS_ON_CONSTRAINTS_H

#include <CVT_2/IO/internal/write_number.h>
#include <CVT_2/internal/input_segments_of_constraints.h>
#include <CVT_2/internal/to_string.h>

#include <CGAL/Kernel/global_functions_2.h>
#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>
#include <ostream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace IO {

/// \ingroup PkgCvt2IO
/// For each constraint of `mesh` (a `Bvd_mesh_2` of `cdt`), the item of the input segment it
/// lies on, or -1: the ids that `write_cells_on_constraints()` writes. `segments` has `ends`
/// (two points a segment) and `items` (one a segment), as `Domain_segments` (from
/// `domain_segments()`); each segment is walked from one end to the other along the
/// constrained edges that lie on it.
template <class CDT, class Mesh, class Segments>
std::vector<std::int64_t> constraint_items(const CDT& cdt, const Mesh& mesh,
                                           const Segments& segments) {
  std::vector<std::int64_t> items =
      internal::input_segments_of_constraints(cdt, mesh, segments.ends);
  for (std::int64_t& i : items)
    if (i >= 0) i = segments.items[std::size_t(i)];
  return items;
}

/// \ingroup PkgCvt2IO
/// Notes on the segments of `segments` (a `Domain_segments`) that lie on earlier ones in the
/// domain: a repeated segment, or one along a part of another (not the edges of polygons'
/// rings, which share their borders). A constrained edge is named by the first segment it lies
/// on, so the pieces of cells along the shared part are listed under the earlier one's item.
/// One note each: `item I: the segment from (x, y) to (x, y) lies on item J's: its pieces are
/// named J` (`lies partly on` where some of it is its own).
template <class CDT, class Segments>
std::vector<std::string> segments_on_earlier_ones(const CDT& cdt, const Segments& segments) {
  constexpr std::size_t none = std::size_t(-1);
  using Vertex_handle = typename CDT::Vertex_handle;
  std::map<std::pair<Vertex_handle, Vertex_handle>, std::size_t> first;  // an edge's first one
  std::vector<std::size_t> earlier(segments.ends.size() / 2, none);
  std::vector<bool> own(earlier.size(), false);  // some edge in the domain is named by it
  internal::for_each_edge_on_input_segments(cdt, segments.ends, [&](auto u, auto w, std::size_t i) {
    if (!internal::has_domain_face(cdt, u) || !internal::has_domain_face(cdt, w)) return;
    const auto [it, added] = first.emplace(std::minmax<Vertex_handle>(u, w), i);
    if (added || it->second == i)
      own[i] = true;
    else if (earlier[i] == none)
      earlier[i] = it->second;
  });
  std::vector<std::string> notes;
  for (std::size_t i = 0; i < earlier.size(); ++i) {
    if (i < segments.rings || earlier[i] == none || segments.items[earlier[i]] == segments.items[i])
      continue;
    const std::string j = std::to_string(segments.items[earlier[i]]);
    notes.push_back("item " + std::to_string(segments.items[i]) + ": the segment from " +
                    internal::to_string(segments.ends[2 * i]) + " to " +
                    internal::to_string(segments.ends[2 * i + 1]) + " lies " +
                    (own[i] ? "partly " : "") + "on item " + j + "'s: " +
                    (own[i] ? "the pieces along it are named " : "its pieces are named ") + j);
  }
  return notes;
}

/// \ingroup PkgCvt2IO
/// Two cells beside a line that is no constraint (a conforming line, `conforming_sites_2()`),
/// for `write_cells_on_constraints()`: the line's id and the two cells of the grid.
struct Line_pair {
  std::int64_t line;  ///< written as the row's `constraint`
  std::size_t cell;   ///< the grid cell on one side
  std::size_t other;  ///< the grid cell on the other side
  /// The part of the line that the pair's face lies along, x0, y0, x1, y1: the face is written
  /// where it runs along it, not past its ends (a line's free end); NaN: the whole face.
  std::array<double, 4> along{
      std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(),
      std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
};

/// \ingroup PkgCvt2IO
/// The `Line_pair` of each of `pairs` (a range of `Conforming_pair_2`, whose points are vertices
/// of `cdt`, the triangulation of `grid`'s mesh): the grid cells of its two generators (the
/// first part of a split cell), `ids[line]` as the line's id, and the part of the line it lies
/// along (`Conforming_pair_2::from`, `to`). A pair whose points are not both vertices is left
/// out.
template <class CDT, class Grid, class PairRange>
std::vector<Line_pair> conforming_line_pairs(const CDT& cdt, const Grid& grid,
                                             const PairRange& pairs,
                                             const std::vector<std::int64_t>& ids) {
  const auto& mesh = grid.mesh();
  std::vector<std::size_t> first_part(mesh.number_of_cells(), Grid::none);
  for (std::size_t g = grid.number_of_cells(); g-- > 0;) first_part[grid.mesh_cell(g)] = g;
  std::vector<Line_pair> out;
  typename CDT::Face_handle hint;
  for (const auto& p : pairs) {
    typename CDT::Locate_type lt[2];
    int li[2];
    const auto f = cdt.locate(p.left, lt[0], li[0], hint);
    const auto g = cdt.locate(p.right, lt[1], li[1], f);
    hint = g;
    if (lt[0] == CDT::VERTEX && lt[1] == CDT::VERTEX)
      out.push_back({ids.at(p.line),
                     first_part[mesh.cell_of(f->vertex(li[0]))],
                     first_part[mesh.cell_of(g->vertex(li[1]))],
                     {CGAL::to_double(p.from.x()), CGAL::to_double(p.from.y()),
                      CGAL::to_double(p.to.x()), CGAL::to_double(p.to.y())}});
  }
  return out;
}

/// \ingroup PkgCvt2IO
/// Writes, as CSV with the header `constraint,cell,length,other_cell`, one row per piece of a
/// constraint that bounds or crosses a cell of `grid` (a `Simulation_grid_2`): `constraint` is
/// `ids[c]` for the mesh's constraint `c` (the input line it lies on, say; -1 if `ids` is
/// shorter), `cell` the grid cell from 1 (as in the DISV), `length` the piece's length,
/// `other_cell` the cell on the other side from 1, or -1 on the domain's boundary. A piece of an
/// inner constraint between two cells has a row from each side; a slit (an inner constraint
/// that is not a barrier, inside the cell of a generator on it) has one row, the cell its own
/// other cell. The rows go cell after cell, the edges of each in order, its slits after them.
/// This is what a MODFLOW 6 package needs for the cells along a line: CHD and GHB on the
/// boundary, RIV and DRN along a river, HFB between the pairs of a wall. Then, for each of
/// `pairs` whose cells share edges, a row from each side, `length` that of the edges along the
/// pair's part of the line, `Line_pair::along` (the pairs of a conforming line: a face that runs
/// past the line's free end counts to the end; none where its face is not theirs).
template <class Grid>
void write_cells_on_constraints(std::ostream& os, const Grid& grid,
                                const std::vector<std::int64_t>& ids,
                                const std::vector<Line_pair>& pairs = {}) {
  using Index = typename Grid::Index;
  const auto& mesh = grid.mesh();
  const auto id = [&](Index c) { return c < ids.size() ? ids[c] : std::int64_t(-1); };
  const auto row = [&](Index c, std::size_t cell, const auto& a, const auto& b,
                       std::int64_t other) {
    os << id(c) << ',' << cell + 1 << ',';
    internal::write_number(os, std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b))));
    os << ',' << other << '\n';
  };
  os << "constraint,cell,length,other_cell\n";
  std::vector<std::pair<Index, Index>> edges;  // of the parts of a mesh cell, in mesh vertices
  for (std::size_t g = 0; g < grid.number_of_cells(); ++g) {
    const std::size_t n = grid.degree(g);
    for (std::size_t j = 0; j < n; ++j) {
      const auto& side = grid.side(g, j);
      if (side.constraint == Grid::none) continue;
      row(side.constraint, g, grid.point(grid.vertex(g, j)),
          grid.point(grid.vertex(g, (j + 1) % n)),
          side.cell == Grid::none ? std::int64_t(-1) : std::int64_t(side.cell) + 1);
    }
    // The slits of its mesh cell, after its last part: each walked there and back, written
    // once, in the part that has the slit's outer end (the first part if none has).
    const Index k = grid.mesh_cell(g);
    if (g + 1 < grid.number_of_cells() && grid.mesh_cell(g + 1) == k) continue;
    std::size_t first = g;
    while (first > 0 && grid.mesh_cell(first - 1) == k) --first;
    edges.clear();
    for (std::size_t h = first; h <= g; ++h)
      for (std::size_t j = 0, m = grid.degree(h); j < m; ++j)
        edges.emplace_back(grid.mesh_vertex(grid.vertex(h, j)),
                           grid.mesh_vertex(grid.vertex(h, (j + 1) % m)));
    const auto c = mesh.cell(k);
    for (std::size_t j = 0; j < c.size(); ++j) {
      const auto& side = mesh.side(k, j);
      const Index p = c[j], q = c[(j + 1) % c.size()];
      if (side.cell != k || side.constraint == Grid::none || p > q ||
          std::find(edges.begin(), edges.end(), std::make_pair(p, q)) != edges.end())
        continue;
      // Every part has the generator: the other end says which part the piece lies in.
      const auto is_generator = [&](Index i) {
        return mesh.vertex_type(i) == std::decay_t<decltype(mesh)>::Cell_vertex::GENERATOR;
      };
      const Index outer = is_generator(p) ? q : p;
      const auto has_end = [&](std::size_t h) {
        for (std::size_t i = 0; i < grid.degree(h); ++i)
          if (grid.mesh_vertex(grid.vertex(h, i)) == outer) return true;
        return false;
      };
      std::size_t part = first;
      while (part < g && !has_end(part)) ++part;
      if (!has_end(part)) part = first;
      row(side.constraint, part, mesh.point(p), mesh.point(q), std::int64_t(part) + 1);
    }
  }
  for (const Line_pair& pair : pairs) {
    const auto& [x0, y0, x1, y1] = pair.along;
    const double dx = x1 - x0, dy = y1 - y0, dd = dx * dx + dy * dy;
    double length = 0;
    for (std::size_t j = 0, n = grid.degree(pair.cell); j < n; ++j) {
      if (grid.side(pair.cell, j).cell != pair.other) continue;
      const auto &a = grid.point(grid.vertex(pair.cell, j)),
                 &b = grid.point(grid.vertex(pair.cell, (j + 1) % n));
      const double edge = std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b)));
      if (!(dd > 0)) {  // no part given (NaN), or none
        length += edge;
        continue;
      }
      // the share of the edge within the part, by their parameters along it
      const auto at = [&](const auto& p) {
        return ((CGAL::to_double(p.x()) - x0) * dx + (CGAL::to_double(p.y()) - y0) * dy) / dd;
      };
      const double ta = at(a), tb = at(b);
      const double lo = std::max(0.0, std::min(ta, tb)), hi = std::min(1.0, std::max(ta, tb));
      if (hi > lo) length += edge * (hi - lo) / std::abs(tb - ta);
    }
    if (!(length > 0)) continue;
    for (const auto& [a, b] :
         {std::pair(pair.cell, pair.other), std::pair(pair.other, pair.cell)}) {
      os << pair.line << ',' << a + 1 << ',';
      internal::write_number(os, length);
      os << ',' << b + 1 << '\n';
    }
  }
}

/// \ingroup PkgCvt2IO
/// Writes the cells on the constraints of `grid` to the CSV file `filename`; returns false if
/// the file could not be written.
template <class Grid>
bool write_cells_on_constraints(const std::string& filename, const Grid& grid,
                                const std::vector<std::int64_t>& ids,
                                const std::vector<Line_pair>& pairs = {}) {
  std::ofstream os(filename);
  if (!os) return false;
  write_cells_on_constraints(os, grid, ids, pairs);
  return static_cast<bool>(os);
}

}  // namespace IO
}  // namespace CVT_2

#endif  // CVT_2_IO_WRITE_CELLS_ON_CONSTRAINTS_H
