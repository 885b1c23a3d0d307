// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Builds a Simulation_grid_2 from a mesh: cells split at barriers, vertices one per side.
#ifndef CVT_2_INTERNAL_SIMULATION_GRID_BUILDER_2_H
#define CVT_2_INTERNAL_SIMULATION_GRID_BUILDER_2_H

#include <CGAL/Kernel/global_functions_2.h>
#include <CGAL/enum.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

template <class Grid>
class Simulation_grid_builder_2 {
  using Index = typename Grid::Index;
  static constexpr Index none = Grid::none;

  static std::uint64_t key(Index p, Index q) { return (std::uint64_t(p) << 32) | q; }

 public:
  template <class Mesh, class IsBarrier>
  Simulation_grid_builder_2(Grid& grid, const Mesh& mesh, IsBarrier is_barrier) {
    // The rings, in the mesh's vertex numbers.
    std::vector<Index> ring;  // all rings one after the other, offsets in grid.m_offsets
    for (std::size_t k = 0; k < mesh.number_of_cells(); ++k) {
      const std::vector<std::size_t> cuts = barrier_cuts(mesh, k, is_barrier);
      if (cuts.size() < 2) {  // not split: the mesh's outline
        const std::vector<Index> o = mesh.outline(k);
        ring.insert(ring.end(), o.begin(), o.end());
        grid.m_offsets.push_back(ring.size());
        grid.m_mesh_cell.push_back(Index(k));
        continue;
      }
      const auto c = mesh.cell(k);
      for (std::size_t i = 0; i < cuts.size(); ++i) {
        const std::size_t to = i + 1 < cuts.size() ? cuts[i + 1] : cuts[0] + c.size();
        std::vector<Index> part;
        for (std::size_t j = cuts[i]; j < to; ++j) {
          const std::size_t jj = j % c.size();
          if (j != cuts[i] && is_slit_tip(mesh, k, jj)) continue;  // a slit, not a barrier
          if (part.empty() || part.back() != c[jj]) part.push_back(c[jj]);
        }
        clean(mesh, part);
        if (part.size() < 3) continue;  // a part of no area
        ring.insert(ring.end(), part.begin(), part.end());
        grid.m_offsets.push_back(ring.size());
        grid.m_mesh_cell.push_back(Index(k));
      }
    }
    const std::size_t cells = grid.m_mesh_cell.size();
    const auto& offsets = grid.m_offsets;
    const auto next = [&](std::size_t g, std::size_t pos) {
      return pos + 1 < offsets[g + 1] ? pos + 1 : offsets[g];
    };

    // The corners (positions in the rings) at each mesh vertex, in order: a counting sort. An
    // edge's twin, q -> p for p -> q, starts at a corner of q.
    std::vector<Index> cell_at(ring.size());
    for (std::size_t g = 0; g < cells; ++g)
      std::fill(cell_at.begin() + std::ptrdiff_t(offsets[g]),
                cell_at.begin() + std::ptrdiff_t(offsets[g + 1]), Index(g));
    std::vector<std::size_t> first(mesh.number_of_vertices() + 1, 0), corners(ring.size());
    for (const Index v : ring) ++first[v + 1];
    std::partial_sum(first.begin(), first.end(), first.begin());
    {
      std::vector<std::size_t> fill(first.begin(), first.end() - 1);
      for (std::size_t pos = 0; pos < ring.size(); ++pos) corners[fill[ring[pos]]++] = pos;
    }
    const auto twin = [&](std::size_t pos) -> std::size_t {  // its position, or none
      const Index p = ring[pos], q = ring[next(cell_at[pos], pos)];
      for (std::size_t i = first[q]; i < first[q + 1]; ++i)
        if (ring[next(cell_at[corners[i]], corners[i])] == p) return corners[i];
      return std::size_t(-1);
    };
    // The constraint under each constrained edge of the mesh.
    std::unordered_map<std::uint64_t, Index> constraint_of;
    for (std::size_t k = 0; k < mesh.number_of_cells(); ++k) {
      const auto c = mesh.cell(k);
      for (std::size_t j = 0; j < c.size(); ++j)
        if (mesh.side(k, j).constraint != none)
          constraint_of.emplace(key(c[j], c[(j + 1) % c.size()]), mesh.side(k, j).constraint);
    }

    // Sides; corners (a cell's use of a vertex) joined across each edge that is not a barrier.
    std::vector<std::size_t> parent(ring.size());
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    const auto find = [&](std::size_t i) {
      while (parent[i] != i) i = parent[i] = parent[parent[i]];
      return i;
    };
    const auto join = [&](std::size_t a, std::size_t b) {
      a = find(a), b = find(b);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    };
    grid.m_sides.resize(ring.size());
    for (std::size_t g = 0; g < cells; ++g) {
      for (std::size_t pos = offsets[g]; pos < offsets[g + 1]; ++pos) {
        const Index p = ring[pos], q = ring[next(g, pos)];
        auto& side = grid.m_sides[pos];
        auto c = constraint_of.find(key(p, q));
        if (c == constraint_of.end()) c = constraint_of.find(key(q, p));
        if (c != constraint_of.end()) side.constraint = c->second;
        const std::size_t at = twin(pos);
        if (at == std::size_t(-1)) continue;  // the boundary
        const Index h = cell_at[at];
        side.cell = h;
        side.barrier = side.constraint != none && bool(is_barrier(side.constraint));
        if (!side.barrier) join(pos, next(h, at)), join(next(g, pos), at);
      }
      for (std::size_t a = offsets[g]; a < offsets[g + 1]; ++a)  // a cell touching itself
        for (std::size_t b = a + 1; b < offsets[g + 1]; ++b)
          if (ring[a] == ring[b]) join(a, b);
    }

    // One grid vertex a class, by mesh vertex, then by the first corner.
    std::vector<Index> number(ring.size(), none);
    grid.m_vertices.resize(ring.size());
    for (const std::size_t pos : corners) {
      Index& n = number[find(pos)];
      if (n == none) n = Index(grid.m_mesh_vertex.size()), grid.m_mesh_vertex.push_back(ring[pos]);
      grid.m_vertices[pos] = n;
    }
  }

 private:
  // At position j of cell k's cycle, a slit's tip: the generator, reached and left along one
  // constraint.
  template <class Mesh>
  static bool is_slit_tip(const Mesh& mesh, std::size_t k, std::size_t j) {
    const auto c = mesh.cell(k);
    if (mesh.vertex_type(c[j]) != Mesh::Cell_vertex::GENERATOR) return false;
    const Index in = mesh.side(k, (j + c.size() - 1) % c.size()).constraint;
    return in != none && in == mesh.side(k, j).constraint;
  }

  // Where cell k is cut into parts: if a barrier's slit ends at its generator, at each visit of
  // the generator but the tips of other slits (lobes and the boundary cut it too).
  template <class Mesh, class IsBarrier>
  static std::vector<std::size_t> barrier_cuts(const Mesh& mesh, std::size_t k,
                                               IsBarrier& is_barrier) {
    std::vector<std::size_t> cuts;
    bool barrier = false;
    const auto c = mesh.cell(k);
    if (c.size() < 3) return cuts;
    for (std::size_t j = 0; j < c.size(); ++j) {
      if (mesh.vertex_type(c[j]) != Mesh::Cell_vertex::GENERATOR) continue;
      if (is_slit_tip(mesh, k, j)) {
        if (!is_barrier(mesh.side(k, j).constraint)) continue;
        barrier = true;
      }
      cuts.push_back(j);
    }
    if (!barrier) cuts.clear();
    return cuts;
  }

  // As Bvd_mesh_2::polygons() cleans a ring: the ends joined, spikes a, b, a folded (what is
  // left of a slit with vertices along it), points where the ring turns back along itself
  // dropped.
  template <class Mesh>
  static void clean(const Mesh& mesh, std::vector<Index>& r) {
    const auto is_generator = [&](Index i) {
      return mesh.vertex_type(i) == Mesh::Cell_vertex::GENERATOR;
    };
    while (r.size() > 1 && r.back() == r.front()) r.pop_back();
    for (bool changed = true; changed && r.size() >= 3;) {
      changed = false;
      for (std::size_t j = 0; j < r.size() && r.size() >= 3; ++j) {
        const std::size_t n = r.size(), i = (j + n - 1) % n, l = (j + 1) % n;
        const auto &a = mesh.point(r[i]), &b = mesh.point(r[j]), &c = mesh.point(r[l]);
        const bool spike = r[i] == r[l] && !is_generator(r[j]) && !is_generator(r[l]);
        const bool back =
            r[i] != r[l] && CGAL::orientation(a, b, c) == CGAL::COLLINEAR && (b - a) * (c - b) <= 0;
        if (!spike && !back) continue;
        if (spike) {
          r.erase(r.begin() + std::ptrdiff_t(std::max(j, l)));
          r.erase(r.begin() + std::ptrdiff_t(std::min(j, l)));
        } else {
          r.erase(r.begin() + std::ptrdiff_t(j));
        }
        changed = true;
      }
    }
  }
};

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_SIMULATION_GRID_BUILDER_2_H
