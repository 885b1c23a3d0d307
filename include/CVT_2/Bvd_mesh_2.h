// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Bvd_mesh_2: the bounded Voronoi diagram as a conforming polygon mesh, with shared vertices,
// cell adjacency and the constraint under each boundary edge.
#ifndef CVT_2_BVD_MESH_2_H
#define CVT_2_BVD_MESH_2_H

#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/internal/Bvd_mesh_builder_2.h>
#include <CVT_2/internal/layout/Handle_numbering.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CVT_2 {

/// \ingroup PkgCvt2Ref
/// The cells of a bounded Voronoi diagram as one polygon mesh: each circumcenter, clip point and
/// constrained generator is one mesh vertex, shared by the cells it bounds, found from the
/// triangulation's topology (never by comparing coordinates, except that points a cell visits
/// twice in a row at one point, or within 2^-40 of their distance to its generator, are one
/// vertex: a circumcenter that is also a clip point, the circumcenters of nearly cocircular
/// generators, which rounding could otherwise set in a zigzag, the cell no simple polygon;
/// except where that would leave a cell of positive area without area, as a generator a hair
/// from a constraint or from another generator has: the points of such a cell stay apart); each
/// cell is a cycle of vertex indices, counterclockwise; each edge of a cycle knows what lies beyond
/// it: another cell (a bisector edge), or a constraint, with the cell on its other side if the
/// constraint is inside the domain.
///
/// Cells are numbered in the order of `Bounded_voronoi_diagram_2::for_each_cell()`, vertices
/// with the circumcenters first, in the order of their faces in memory, then the other vertices
/// in the order of the cells that first meet them (points merged into one take the number of
/// their constrained generator if they have one, else of their clip point, so that the
/// domain's boundary stays where it is). The same triangulation, with its faces in the
/// same order in memory, gives the same mesh, whatever the number of threads.
///
/// How cells that are not simple polygons are represented:
/// - *slits*: a constraint that ends inside a cell or crosses it at its generator (a vertex on
///   an inner constraint) is walked there and back, `..., m, v, m, ...`, where `v` is the
///   generator and `m` where the constraint leaves the cell; both edges have the cell on both
///   sides and name the constraint.
/// - *lobes*: a generator where the domain pinches (two holes, or a hole and the boundary, that
///   touch at it) has a cell of several pieces that meet only there; the cycle goes through the
///   generator once per piece.
///
/// `polygons()` turns a cell into what GIS tools accept as valid: slits dropped (they have no
/// width), one ring per lobe.
///
/// \tparam Diagram a `Bounded_voronoi_diagram_2`. The mesh is fastest when the triangulation's
///         vertices have an `id()` (CGAL's `Triangulation_vertex_base_with_id_2`, as in
///         `Cvt_triangulation_2`) and its faces one (`Bvd_face_base_2`); building it writes
///         them. Without, it keeps its numbering in hash maps.
template <class Diagram>
class Bvd_mesh_2 {
 public:
  using Triangulation = typename Diagram::Triangulation;  ///< the triangulation type
  using Point_2 = typename Diagram::Point_2;              ///< the point type
  using FT = typename Diagram::FT;                        ///< the number type
  using Vertex_handle = typename Diagram::Vertex_handle;  ///< a generator
  using Cell_vertex = typename Diagram::Cell_vertex;      ///< a vertex of a diagram cell
  using Vertex_type = typename Cell_vertex::Type;         ///< circumcenter, clip point, generator
  using Index = std::uint32_t;                            ///< a vertex, cell or constraint number
  static constexpr Index none = Index(-1);                ///< no cell, no constraint

  /// What lies beyond an edge of a cell.
  struct Side {
    Index cell = none;        ///< the cell beyond, or `none` (the outside or a hole)
    Index constraint = none;  ///< the constraint the edge lies on, or `none` (a bisector edge)
  };

  /// An edge of the mesh: `cells[0]` lies left of `vertices[0]` -> `vertices[1]`.
  struct Edge {
    std::array<Index, 2> vertices;  ///< its ends
    std::array<Index, 2> cells;     ///< left and right; `cells[1]` is `none` on the boundary
    Index constraint;               ///< the constraint it lies on, or `none`
  };

  /// A constrained edge of the triangulation, by the cells of its two end points (constrained
  /// vertices have cells), the smaller first. An input segment on which vertices lie is several.
  using Constraint = std::array<Index, 2>;

  /// Builds the mesh of the diagram `bvd`, its cells on `threads` threads (0: one per core).
  /// \pre the triangulation has not changed since `bvd` was built or updated.
  explicit Bvd_mesh_2(const Diagram& bvd, unsigned threads = 0);

  /// \name Vertices
  /// @{
  std::size_t number_of_vertices() const { return m_points.size(); }  ///< mesh vertices
  const Point_2& point(std::size_t i) const { return m_points[i]; }   ///< where vertex `i` is
  /// what vertex `i` is: a circumcenter, a clip point (on a constraint) or a generator
  Vertex_type vertex_type(std::size_t i) const { return m_types[i]; }
  const std::vector<Point_2>& points() const { return m_points; }  ///< all, by index
  /// @}

  /// \name Cells
  /// @{
  std::size_t number_of_cells() const { return m_generators.size(); }  ///< one per generator
  /// the vertex indices of cell `k`, counterclockwise (`begin()`, `end()`, `size()`)
  struct Index_range {
    const Index* first;
    const Index* last;
    const Index* begin() const { return first; }
    const Index* end() const { return last; }
    std::size_t size() const { return std::size_t(last - first); }
    Index operator[](std::size_t j) const { return first[j]; }
  };
  Index_range cell(std::size_t k) const {
    return {m_cell_vertices.data() + m_offsets[k], m_cell_vertices.data() + m_offsets[k + 1]};
  }
  /// what lies beyond the edge from `cell(k)[j]` to `cell(k)[j + 1]` (the last to the first)
  const Side& side(std::size_t k, std::size_t j) const { return m_sides[m_offsets[k] + j]; }
  Vertex_handle generator(std::size_t k) const { return m_generators[k]; }  ///< of cell `k`
  /// whether the generator of cell `k` is constrained (a vertex of its own cell)
  bool is_constrained(std::size_t k) const { return m_constrained[k] != 0; }
  /// the cell of generator `v`. \pre `v` has a cell
  /// The ids of the triangulation's vertices hold it, until they are written again (by another
  /// mesh of the triangulation, say).
  std::size_t cell_of(Vertex_handle v) const { return cell_number(v); }
  FT area(std::size_t k) const;           ///< of cell `k` (slits add nothing)
  Point_2 centroid(std::size_t k) const;  ///< of cell `k`, as a uniform polygon
  /// the cells that share an edge with cell `k`, in the order of its cycle, each once
  std::vector<Index> neighbors(std::size_t k) const;
  /// Cell `k` as valid polygons: slits dropped, one counterclockwise ring (vertex indices, not
  /// closed) per lobe, several rings only where the cell meets itself at its generator.
  std::vector<std::vector<Index>> polygons(std::size_t k) const;
  /// Cell `k` as one ring: slits dropped, lobes kept, joined at the generator (a ring that
  /// touches itself there): the cell for formats with one vertex list a cell.
  std::vector<Index> outline(std::size_t k) const;
  /// @}

  /// \name Edges and constraints
  /// @{
  /// Each edge once, from the cell on its left (computed at each call).
  std::vector<Edge> edges() const;
  /// The constrained edges of the triangulation that cell edges lie on, in the order met.
  const std::vector<Constraint>& constraints() const { return m_constraints; }
  /// @}

 private:
  friend class internal::Bvd_mesh_builder_2<Diagram>;  // which fills the arrays below
  using Face_handle = typename Triangulation::Face_handle;

  // A generator's cell number is in its id: its chunk of faces (internal::Face_chunks) above
  // cell_bits, its number in the chunk below; the chunks' offsets make it global.
  static constexpr int cell_bits = 14;
  Index cell_number(Vertex_handle v) const {
    const std::size_t id = m_cell_of.get(v);
    return Index(m_cell_offsets[id >> cell_bits] + (id & ((1u << cell_bits) - 1)));
  }

  std::vector<Point_2> m_points;
  std::vector<Vertex_type> m_types;
  std::vector<std::size_t> m_offsets{0};
  std::vector<Index> m_cell_vertices;
  std::vector<Side> m_sides;
  std::vector<Vertex_handle> m_generators;
  std::vector<unsigned char> m_constrained;
  std::vector<Constraint> m_constraints;
  internal::Handle_numbering<Vertex_handle> m_cell_of;
  std::vector<std::size_t> m_cell_offsets;  // of each chunk
};

template <class Diagram>
Bvd_mesh_2<Diagram>::Bvd_mesh_2(const Diagram& bvd, unsigned threads) {
  internal::Bvd_mesh_builder_2<Diagram>(*this, bvd, threads);
}

// A bisector edge or an inner constraint's from the smaller of its two cells, a slit from its
// walk toward its larger vertex number.
template <class Diagram>
auto Bvd_mesh_2<Diagram>::edges() const -> std::vector<Edge> {
  std::vector<Edge> edges;
  edges.reserve(m_sides.size() / 2 + 1);
  for (std::size_t k = 0; k + 1 < m_offsets.size(); ++k) {
    const std::size_t b = m_offsets[k], n = m_offsets[k + 1] - b;
    if (n < 2) continue;
    for (std::size_t j = 0; j < n; ++j) {
      const Side& s = m_sides[b + j];
      const Index p = m_cell_vertices[b + j], q = m_cell_vertices[b + (j + 1) % n];
      if (s.cell == none || s.cell > k || (s.cell == k && p < q))
        edges.push_back(Edge{{p, q}, {Index(k), s.cell}, s.constraint});
    }
  }
  return edges;
}

template <class Diagram>
typename Bvd_mesh_2<Diagram>::FT Bvd_mesh_2<Diagram>::area(std::size_t k) const {
  const Index_range c = cell(k);
  if (c.size() < 3) return FT(0);
  const Point_2& o = m_points[c[0]];
  FT a = 0;
  for (std::size_t j = 1; j + 1 < c.size(); ++j)
    a += CGAL::area(o, m_points[c[j]], m_points[c[j + 1]]);
  return a;
}

template <class Diagram>
typename Bvd_mesh_2<Diagram>::Point_2 Bvd_mesh_2<Diagram>::centroid(std::size_t k) const {
  const Index_range c = cell(k);
  const Point_2& o = m_points[c[0]];
  FT a = 0, x = 0, y = 0;
  for (std::size_t j = 1; j + 1 < c.size(); ++j) {
    const auto u = m_points[c[j]] - o, w = m_points[c[j + 1]] - o;
    const FT t = (u.x() * w.y() - u.y() * w.x()) / 2;
    a += t;
    x += t * (u.x() + w.x()) / 3;
    y += t * (u.y() + w.y()) / 3;
  }
  if (a == 0) return o;
  return Point_2(o.x() + x / a, o.y() + y / a);
}

template <class Diagram>
auto Bvd_mesh_2<Diagram>::neighbors(std::size_t k) const -> std::vector<Index> {
  std::vector<Index> n;
  for (std::size_t j = 0; j < cell(k).size(); ++j) {
    const Index c = side(k, j).cell;
    if (c != none && c != k && std::find(n.begin(), n.end(), c) == n.end()) n.push_back(c);
  }
  return n;
}

// The cycle with its slits dropped: at each visit of the generator, the edges in and out lie on
// the same constraint when a slit passes there (both sides of the constraint are in the cell),
// on two when the cell's boundary passes through the generator. Slits go; what is left splits
// at the generator's remaining visits into lobes, or is one ring if none is left.
template <class Diagram>
auto Bvd_mesh_2<Diagram>::polygons(std::size_t k) const -> std::vector<std::vector<Index>> {
  const Index_range c = cell(k);
  const std::size_t n = c.size();
  std::vector<std::vector<Index>> rings;
  if (n < 3) return rings;
  std::vector<Index> kept;  // positions of the cycle left, the generator's kept visits as none
  std::vector<std::size_t> cuts;
  for (std::size_t j = 0; j < n; ++j) {
    if (m_types[c[j]] == Cell_vertex::GENERATOR) {
      const Index in = side(k, (j + n - 1) % n).constraint, out = side(k, j).constraint;
      if (in == out && in != none) continue;  // a slit's tip
      cuts.push_back(kept.size());
    }
    if (!kept.empty() && kept.back() == c[j]) continue;  // the two ends of a slit
    kept.push_back(c[j]);
  }
  while (kept.size() > 1 && kept.back() == kept.front()) kept.pop_back();
  // A slit with vertices along it leaves a spike a, b, a where its tip was: folded away.
  for (bool folded = true; folded && kept.size() >= 3;) {
    folded = false;
    for (std::size_t j = 0; j < kept.size() && kept.size() >= 3; ++j) {
      const std::size_t n2 = kept.size(), i = (j + n2 - 1) % n2, l = (j + 1) % n2;
      if (kept[i] != kept[l] || m_types[kept[j]] == Cell_vertex::GENERATOR ||
          m_types[kept[l]] == Cell_vertex::GENERATOR)
        continue;
      const std::size_t first = std::min(j, l), second = std::max(j, l);
      for (std::size_t& cut : cuts) cut -= (cut > second) + (cut > first);
      kept.erase(kept.begin() + std::ptrdiff_t(second));
      kept.erase(kept.begin() + std::ptrdiff_t(first));
      folded = true;
    }
  }
  // A vertex where the ring turns back along itself (a circumcenter that rounding puts a hair
  // beyond the clip point next to it on a constraint) is dropped: a polygon cannot overlap
  // itself, and the part it had is of no width.
  const auto add_ring = [&](std::vector<Index> ring) {
    for (bool dropped = true; dropped && ring.size() >= 3;) {
      dropped = false;
      for (std::size_t j = 0; j < ring.size() && ring.size() >= 3; ++j) {
        const Point_2& a = m_points[ring[(j + ring.size() - 1) % ring.size()]];
        const Point_2& b = m_points[ring[j]];
        const Point_2& c = m_points[ring[(j + 1) % ring.size()]];
        if (CGAL::orientation(a, b, c) != CGAL::COLLINEAR || (b - a) * (c - b) > 0) continue;
        ring.erase(ring.begin() + std::ptrdiff_t(j));
        dropped = true;
      }
    }
    if (ring.size() >= 3) rings.push_back(std::move(ring));
  };
  if (cuts.size() <= 1) {
    add_ring(kept);
    return rings;
  }
  for (std::size_t i = 0; i < cuts.size(); ++i) {
    const std::size_t from = cuts[i],
                      to = i + 1 < cuts.size() ? cuts[i + 1] : cuts[0] + kept.size();
    std::vector<Index> ring;
    for (std::size_t j = from; j < to; ++j) ring.push_back(kept[j % kept.size()]);
    add_ring(std::move(ring));
  }
  return rings;
}

template <class Diagram>
auto Bvd_mesh_2<Diagram>::outline(std::size_t k) const -> std::vector<Index> {
  std::vector<Index> ring;
  for (const std::vector<Index>& lobe : polygons(k))
    ring.insert(ring.end(), lobe.begin(), lobe.end());
  return ring;
}

}  // namespace CVT_2

#endif  // CVT_2_BVD_MESH_2_H
