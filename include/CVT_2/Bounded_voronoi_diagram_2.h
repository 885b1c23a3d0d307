// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Bounded_voronoi_diagram_2: the bounded Voronoi diagram of a constrained Delaunay triangulation.
#ifndef CVT_2_BOUNDED_VORONOI_DIAGRAM_2_H
#define CVT_2_BOUNDED_VORONOI_DIAGRAM_2_H

#include <CVT_2/Bvd_face_base_2.h>
#include <CVT_2/Bvd_traits_2.h>
#include <CVT_2/Concepts/BvdFaceBase_2.h>
#include <CVT_2/Concepts/BvdTraits_2.h>
#include <CVT_2/exceptions.h>
#include <CVT_2/insert_generators_2.h>
#include <CVT_2/internal/construct_cell.h>
#include <CVT_2/internal/for_each_cell_in_faces.h>
#include <CVT_2/internal/tag_blind_faces.h>
#include <CVT_2/mark_domain_2.h>

#include <CGAL/Polygon_2.h>
#include <CGAL/circulator.h>

#include <cstddef>
#include <iterator>
#include <memory>
#include <vector>

namespace CVT_2 {

namespace internal {
struct Tags_as_they_are {};
}  // namespace internal

/// \ingroup PkgCvt2Ref
/// The bounded Voronoi diagram (BVD) of a constrained Delaunay triangulation, its pseudo-dual
/// (Seidel): the cell of a generator \f$x_i\f$ is the set of points of the domain that see
/// \f$x_i\f$ (no constraint crosses the segment between them) and are at least as close to it
/// as to any other generator they see.
///
/// The constructor tags the blind faces (paper, Algorithm 1); each cell is then built on demand
/// by circulating around its vertex (Algorithm 2). Every vertex of the closed domain has a cell,
/// constrained ones included, and the cells tile the domain: a vertex on inner constraints gets
/// one polygon around it that its constraints cross as slits (the polygon goes back to the
/// vertex along each of them).
///
/// The diagram stores nothing but the face tags; it reflects the triangulation as it was when
/// built or last `update()`d.
///
/// \tparam CDT a `CGAL::Constrained_Delaunay_triangulation_2` whose faces model
///         `BvdFaceBase_2` (for example `Bvd_face_base_2`), with its domain marked by
///         `mark_domain_2()` or `mark_domain_from_polygons_2()`.
/// \tparam Traits a model of `BvdTraits_2`; by default `Bvd_traits_2` of the CDT's kernel.
template <class CDT, class Traits = Bvd_traits_2<typename CDT::Geom_traits>>
class Bounded_voronoi_diagram_2 {
  static_assert(is_bvd_face_base_2<typename CDT::Face>::value,
                "CDT::Face must model BvdFaceBase_2: bool is_inside_domain() const, "
                "void set_inside_domain(bool), bool is_blinded() const, "
                "Edge blinding_edge() const, void set_blinding_edge(const Edge&), "
                "void clear_blinding()");
  static_assert(is_bvd_traits_2<Traits>::value,
                "Traits must model BvdTraits_2: FT, Point_2, "
                "bool is_blinded_2_object()(p, q, r, a, b), "
                "Comparison_result compare_blinding_distance_2_object()(p, q, r, a1, b1, a2, b2), "
                "Point_2 construct_clip_point_2_object()(v, w, a, b), "
                "Point_2 construct_circumcenter_2_object()(p, q, r)");

 public:
  using Triangulation = CDT;                                     ///< the triangulation type
  using Geom_traits = Traits;                                    ///< the traits type
  using FT = typename Traits::FT;                                ///< the number type
  using Point_2 = typename Traits::Point_2;                      ///< the point type
  using Polygon_2 = CGAL::Polygon_2<typename CDT::Geom_traits>;  ///< a cell as a polygon
  using Vertex_handle = typename CDT::Vertex_handle;             ///< a generator
  using Face_handle = typename CDT::Face_handle;                 ///< a face of the triangulation
  using Edge = typename CDT::Edge;                               ///< an edge of the triangulation

  /// A vertex of a cell.
  struct Cell_vertex {
    /// What a cell vertex is.
    enum Type {
      CIRCUMCENTER,  ///< the circumcenter of `face`, which sees it
      CLIP_POINT,    ///< where the bisector of the generator and `neighbor` meets `constraint`
      GENERATOR      ///< the generator itself, on the boundary of its cell (constrained vertex)
    };
    Point_2 point;     ///< where it is
    Type type;         ///< what it is
    Face_handle face;  ///< for `CIRCUMCENTER`
    Edge constraint;   ///< for `CLIP_POINT`: the constrained edge the point lies on
    /// for `CLIP_POINT`: the other generator of the bisector; for `CIRCUMCENTER`: the generator
    /// across the cell edge that leaves it, counterclockwise
    Vertex_handle neighbor;
  };

  /// A bidirectional circulator over the vertices of one cell, counterclockwise. It shares the
  /// cell it was made from, so copies are cheap and stay valid on their own.
  class Cell_vertex_circulator {
   public:
    /// \name Circulator types
    /// @{
    using iterator_category = CGAL::Bidirectional_circulator_tag;  ///< a CGAL circulator
    using value_type = Cell_vertex;                                ///< what it points to
    using difference_type = std::ptrdiff_t;                        ///< a difference
    using size_type = std::size_t;                                 ///< a count
    using reference = const Cell_vertex&;                          ///< a cell vertex
    using pointer = const Cell_vertex*;                            ///< to a cell vertex
    /// @}

    /// \name Circulator operations
    /// @{
    Cell_vertex_circulator() = default;
    reference operator*() const { return (*m_cell)[m_index]; }
    pointer operator->() const { return &(*m_cell)[m_index]; }
    Cell_vertex_circulator& operator++() {
      if (++m_index == m_cell->size()) m_index = 0;
      return *this;
    }
    Cell_vertex_circulator operator++(int) {
      Cell_vertex_circulator tmp = *this;
      ++*this;
      return tmp;
    }
    Cell_vertex_circulator& operator--() {
      m_index = (m_index == 0 ? m_cell->size() : m_index) - 1;
      return *this;
    }
    Cell_vertex_circulator operator--(int) {
      Cell_vertex_circulator tmp = *this;
      --*this;
      return tmp;
    }
    bool operator==(const Cell_vertex_circulator& c) const {
      return m_cell == c.m_cell && m_index == c.m_index;
    }
    bool operator!=(const Cell_vertex_circulator& c) const { return !(*this == c); }
    bool operator==(std::nullptr_t) const { return m_cell == nullptr; }  // empty cell
    bool operator!=(std::nullptr_t) const { return m_cell != nullptr; }
    /// the cell's vertex count
    size_type size() const { return m_cell ? m_cell->size() : 0; }
    /// @}

   private:
    friend class Bounded_voronoi_diagram_2;
    explicit Cell_vertex_circulator(std::shared_ptr<const std::vector<Cell_vertex>> cell)
        : m_cell(cell->empty() ? nullptr : std::move(cell)) {}
    std::shared_ptr<const std::vector<Cell_vertex>> m_cell;
    std::size_t m_index = 0;
  };

  /// Builds the diagram of `cdt`: tags its blind faces (Algorithm 1).
  explicit Bounded_voronoi_diagram_2(const CDT& cdt, const Traits& traits = Traits())
      : m_cdt(cdt), m_traits(traits) {
    update();
  }

  /// \cond SKIP_IN_MANUAL
  // A diagram of `cdt` that leaves the tags as they are, for a user that tags the faces it
  // needs itself (Cvt_energy_2: all at each evaluation, or those around a region).
  Bounded_voronoi_diagram_2(const CDT& cdt, const Traits& traits, internal::Tags_as_they_are)
      : m_cdt(cdt), m_traits(traits) {}
  /// \endcond

  /// Tags the blind faces again, after the triangulation or its domain changed.
  void update() { internal::tag_blind_faces(m_cdt, m_traits); }
  /// \cond SKIP_IN_MANUAL
  // update(), its pass over the faces on `threads` threads, in the chunks of the optimizers
  // (up to date with the triangulation); the same tags.
  void update(const internal::Face_chunks<CDT>& chunks, unsigned threads) {
    internal::tag_blind_faces(m_cdt, m_traits, chunks, threads);
  }
  /// \endcond

  const CDT& triangulation() const { return m_cdt; }      ///< the triangulation
  const Traits& geom_traits() const { return m_traits; }  ///< the traits
  /// the number of domain faces that a constraint hides from their circumcenter, counted (the
  /// tags may change without this object: an editor's edits, a relaxation in a region)
  std::size_t number_of_blinded_faces() const {
    std::size_t n = 0;
    for (auto f = m_cdt.finite_faces_begin(); f != m_cdt.finite_faces_end(); ++f)
      n += f->is_blinded() ? 1 : 0;
    return n;
  }

  /// whether `v` lies in the closed domain, and so has a cell.
  bool has_cell(Vertex_handle v) const { return internal::has_domain_face(m_cdt, v); }

  /// whether `v` is a free generator: on no constrained edge. Free generators move under Lloyd
  /// iteration; the others stay and their cells have `v` on their boundary.
  bool is_free(Vertex_handle v) const { return !m_cdt.are_there_incident_constraints(v); }

  /// The cell of `v` into `out` (cleared first), counterclockwise; empty if `v` has no cell.
  /// Reusing `out` across calls avoids an allocation per cell.
  void cell(Vertex_handle v, std::vector<Cell_vertex>& out) const {
    internal::construct_cell(m_cdt, m_traits, v, out);
  }

  /// Calls `visit(v, cell)` for every vertex `v` that has a cell, with its cell (the vector is
  /// reused between calls). The vertices come in the order of their incident faces in memory,
  /// which is much kinder to the cache than the vertices' own order.
  template <class Visitor>
  void for_each_cell(Visitor visit) const {
    if (m_cdt.dimension() < 2) return;
    internal::for_each_cell_in_faces(*this, m_cdt.all_faces_begin(), m_cdt.all_faces_end(), visit);
  }

  /// A circulator over the cell of `v`, counterclockwise; equal to `nullptr` if `v` has no cell.
  Cell_vertex_circulator cell_vertices(Vertex_handle v) const {
    auto c = std::make_shared<std::vector<Cell_vertex>>();
    cell(v, *c);
    return Cell_vertex_circulator(std::move(c));
  }

  /// The cell of `v` as a counterclockwise polygon (a vertex on inner constraints appears once
  /// per slit, where the polygon goes back to it).
  Polygon_2 cell_polygon(Vertex_handle v) const {
    std::vector<Cell_vertex> c;
    cell(v, c);
    Polygon_2 polygon;
    for (const Cell_vertex& x : c) polygon.push_back(x.point);
    return polygon;
  }

 private:
  const CDT& m_cdt;
  Traits m_traits;
  // GCC 12 takes an object of only a reference and empty traits for uninitialized when it
  // passes the traits on (-Wmaybe-uninitialized); a byte written at construction tells it.
  bool m_constructed = true;
};

}  // namespace CVT_2

#endif  // CVT_2_BOUNDED_VORONOI_DIAGRAM_2_H
