// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Simulation_grid_2: the cells of a mesh as a finite-volume grid, inner constraints as slits or
// as barriers (the cells split there, no face across them).
#ifndef CVT_2_SIMULATION_GRID_2_H
#define CVT_2_SIMULATION_GRID_2_H

#include <CVT_2/internal/Simulation_grid_builder_2.h>

#include <CGAL/Kernel/global_functions_2.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CVT_2 {

/// \ingroup PkgCvt2Ref
/// What an inner constraint is to a simulation grid.
enum Constraint_kind {
  SLIT,    ///< a line cells cross: a constrained vertex's cell lies on both sides (as in the mesh)
  BARRIER  ///< a wall, a fault, a crack: no cell crosses it and no face connects its two sides
};

/// \ingroup PkgCvt2Ref
/// The cells of a `Bvd_mesh_2` as the grid of a finite-volume simulator (MODFLOW 6's DISV, a
/// two-point flux scheme): each cell one counterclockwise ring of vertex indices (the mesh's
/// `outline()`, slits dropped), its center the generator, each edge knowing the cell beyond.
///
/// At a **barrier** the cell of a generator on it is split into one cell per side, cut along the
/// constraint through the generator: each part keeps the generator as its center, so its faces
/// to the neighbours on its side stay bisectors, perpendicular to the line between the centers.
/// A mesh vertex on a barrier is one grid vertex per side (same point, two numbers; one where
/// the barrier ends in a tip's cell), so that the cells on the two sides share no edge: a simulator
/// that connects cells by shared edges (as MODFLOW does) sees no connection across. Where a barrier
/// ends inside the domain (a crack's tip), the generator's cell is not split (the constraint only
/// enters it) and its vertices are shared: flow goes around the tip through that cell. A **slit**
/// leaves the cells as the mesh has them.
///
/// Cells are numbered in the order of the mesh's cells, the parts of a split cell one after the
/// other from its first visit of the generator; vertices by the mesh vertex they stand for,
/// then by the cell that first uses them. In a grid without barriers, the cells are the mesh's
/// and the vertices those the mesh's outlines use, in the mesh's order.
///
/// \tparam Mesh a `Bvd_mesh_2`.
template <class Mesh>
class Simulation_grid_2 {
 public:
  using Index = typename Mesh::Index;      ///< a vertex, cell or constraint number
  using Point_2 = typename Mesh::Point_2;  ///< the point type
  using FT = typename Mesh::FT;            ///< the number type
  static constexpr Index none = Mesh::none;

  /// What lies beyond an edge of a cell.
  struct Side {
    Index cell = none;        ///< the grid cell beyond, or `none` (the outside or a hole)
    Index constraint = none;  ///< the mesh's constraint the edge lies on, or `none`
    bool barrier = false;     ///< whether it is an inner constraint that is a barrier
  };

  /// The grid of `mesh`, every inner constraint of the kind `kind`.
  explicit Simulation_grid_2(const Mesh& mesh, Constraint_kind kind = SLIT)
      : Simulation_grid_2(mesh, [kind](Index) { return kind == BARRIER; }) {}

  /// The grid of `mesh`, the constraints `c` (numbers of `Mesh::constraints()`) for which
  /// `is_barrier(c)` holds barriers, the other ones slits.
  template <class IsBarrier>
  Simulation_grid_2(const Mesh& mesh, IsBarrier is_barrier) : m_mesh(&mesh) {
    internal::Simulation_grid_builder_2<Simulation_grid_2>(*this, mesh, is_barrier);
  }

  const Mesh& mesh() const { return *m_mesh; }  ///< the mesh it was built from

  /// \name Vertices
  /// @{
  std::size_t number_of_vertices() const { return m_mesh_vertex.size(); }
  const Point_2& point(std::size_t i) const { return m_mesh->point(m_mesh_vertex[i]); }
  Index mesh_vertex(std::size_t i) const { return m_mesh_vertex[i]; }  ///< the one it stands for
  /// @}

  /// \name Cells
  /// @{
  std::size_t number_of_cells() const { return m_mesh_cell.size(); }
  /// the vertex indices of cell `k`, counterclockwise
  std::vector<Index> cell(std::size_t k) const {
    return {m_vertices.begin() + std::ptrdiff_t(m_offsets[k]),
            m_vertices.begin() + std::ptrdiff_t(m_offsets[k + 1])};
  }
  std::size_t degree(std::size_t k) const { return m_offsets[k + 1] - m_offsets[k]; }
  Index vertex(std::size_t k, std::size_t j) const { return m_vertices[m_offsets[k] + j]; }
  /// what lies beyond the edge from vertex `j` of cell `k` to the next (the last to the first)
  const Side& side(std::size_t k, std::size_t j) const { return m_sides[m_offsets[k] + j]; }
  Index mesh_cell(std::size_t k) const { return m_mesh_cell[k]; }  ///< the mesh cell it is of
  /// its center: the generator of its mesh cell
  const Point_2& center(std::size_t k) const { return generator(k)->point(); }
  FT area(std::size_t k) const;  ///< of cell `k`
  /// @}

  /// \name As a mesh
  /// What the writers read of a `Bvd_mesh_2`, so that they write a grid as well.
  /// @{
  using Vertex_handle = typename Mesh::Vertex_handle;  ///< a generator
  typename Mesh::Vertex_handle generator(std::size_t k) const {
    return m_mesh->generator(m_mesh_cell[k]);
  }
  bool is_constrained(std::size_t k) const { return m_mesh->is_constrained(m_mesh_cell[k]); }
  std::vector<Index> outline(std::size_t k) const { return cell(k); }  ///< `cell(k)`
  /// cell `k` as valid polygons: one ring per lobe (a cell that meets itself at its generator)
  std::vector<std::vector<Index>> polygons(std::size_t k) const;
  /// the cells that share an edge with cell `k` that is not on a barrier, each once
  std::vector<Index> neighbors(std::size_t k) const;
  /// @}

 private:
  friend class internal::Simulation_grid_builder_2<Simulation_grid_2>;
  const Mesh* m_mesh;
  std::vector<Index> m_mesh_vertex;
  std::vector<Index> m_mesh_cell;
  std::vector<std::size_t> m_offsets{0};
  std::vector<Index> m_vertices;
  std::vector<Side> m_sides;
};

template <class Mesh>
typename Simulation_grid_2<Mesh>::FT Simulation_grid_2<Mesh>::area(std::size_t k) const {
  const std::size_t n = degree(k);
  if (n < 3) return FT(0);
  const Point_2& o = point(vertex(k, 0));
  FT a = 0;
  for (std::size_t j = 1; j + 1 < n; ++j)
    a += CGAL::area(o, point(vertex(k, j)), point(vertex(k, j + 1)));
  return a;
}

// A lobe ends where the ring comes back to a vertex it has been at: the generator where the
// domain pinches.
template <class Mesh>
auto Simulation_grid_2<Mesh>::polygons(std::size_t k) const -> std::vector<std::vector<Index>> {
  std::vector<std::vector<Index>> rings;
  const std::vector<Index> r = cell(k);
  if (r.size() < 3) return rings;
  std::size_t first = 0;  // a vertex the ring visits twice, if any, and where it does
  std::vector<std::size_t> visits;
  for (std::size_t j = 0; j < r.size() && visits.empty(); ++j)
    for (std::size_t i = j + 1; i < r.size(); ++i)
      if (r[i] == r[j]) first = j, visits.push_back(i);
  if (visits.empty()) return {r};
  std::vector<std::size_t> cuts{first};
  cuts.insert(cuts.end(), visits.begin(), visits.end());
  for (std::size_t i = 0; i < cuts.size(); ++i) {
    const std::size_t to = i + 1 < cuts.size() ? cuts[i + 1] : cuts[0] + r.size();
    std::vector<Index> lobe;
    for (std::size_t j = cuts[i]; j < to; ++j) lobe.push_back(r[j % r.size()]);
    if (lobe.size() >= 3) rings.push_back(std::move(lobe));
  }
  return rings;
}

template <class Mesh>
auto Simulation_grid_2<Mesh>::neighbors(std::size_t k) const -> std::vector<Index> {
  std::vector<Index> n;
  for (std::size_t j = 0; j < degree(k); ++j) {
    const Side& s = side(k, j);
    if (s.cell != none && s.cell != k && !s.barrier &&
        std::find(n.begin(), n.end(), s.cell) == n.end())
      n.push_back(s.cell);
  }
  return n;
}

}  // namespace CVT_2

#endif  // CVT_2_SIMULATION_GRID_2_H
