// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Bvd_face_base_2: a face base layer that stores the domain flag and the blinding constraint.
#ifndef CVT_2_BVD_FACE_BASE_2_H
#define CVT_2_BVD_FACE_BASE_2_H

#include <CGAL/Constrained_triangulation_face_base_2.h>

#include <cstddef>
#include <cstdint>
#include <utility>

namespace CVT_2 {

/// \ingroup PkgCvt2Ref
/// A face base layer for a constrained Delaunay triangulation that stores what the bounded
/// Voronoi diagram needs per face: whether the face lies in the domain and, when the face is
/// *blind* (a constraint separates it from its circumcenter, paper Definition 2.1), the first
/// constrained edge met on the way from the face to its circumcenter.
///
/// It stacks on any CGAL constrained face base, `Constrained_Delaunay_triangulation_face_base_2`
/// and `Delaunay_mesh_face_base_2` included, and shadows none of their members: CGAL's
/// `is_blind()`, `blinding_constraint()` and `is_in_domain()` keep their meaning; ours are
/// `is_blinded()`, `blinding_edge()` and `is_inside_domain()`.
///
/// The default base is `Constrained_triangulation_face_base_2`, without the blind flag and edge
/// that CGAL 5.5's `Constrained_Delaunay_triangulation_face_base_2` carries for its own Lloyd
/// optimizer: a face is then 64 bytes with Epick (CGAL's default CDT face: 72).
///
/// \tparam Gt a geometric traits class (a CGAL kernel).
/// \tparam Fb the face base it extends; models `ConstrainedTriangulationFaceBase_2`.
/// \cgalModels `BvdFaceBase_2`
template <class Gt, class Fb = CGAL::Constrained_triangulation_face_base_2<Gt>>
class Bvd_face_base_2 : public Fb {
 public:
  using Geom_traits = Gt;                            ///< the geometric traits
  using Vertex_handle = typename Fb::Vertex_handle;  ///< a vertex of the TDS
  using Face_handle = typename Fb::Face_handle;      ///< a face of the TDS
  using Edge = std::pair<Face_handle, int>;          ///< an edge, as a face and an index

  /// Rebinds the layer to the TDS that stores it.
  template <class Tds2>
  struct Rebind_TDS {  // the TDS plugs itself in, like allocator rebind
    using Other = Bvd_face_base_2<Gt, typename Fb::template Rebind_TDS<Tds2>::Other>;  ///< rebound
  };

  /// \name Creation
  /// The three constructors of a TDS face, passed to the layer below.
  /// @{
  Bvd_face_base_2() : Fb() {}  ///< a face with no vertex
  /// a face with vertices `v0`, `v1`, `v2`, counterclockwise
  Bvd_face_base_2(Vertex_handle v0, Vertex_handle v1, Vertex_handle v2) : Fb(v0, v1, v2) {}
  /// a face with vertices and neighbors (`ni` opposite `vi`)
  Bvd_face_base_2(Vertex_handle v0, Vertex_handle v1, Vertex_handle v2, Face_handle n0,
                  Face_handle n1, Face_handle n2)
      : Fb(v0, v1, v2, n0, n1, n2) {}
  /// @}

  /// whether the face belongs to the domain (set by `mark_domain_2()`).
  bool is_inside_domain() const { return (m_bits & inside_bit) != 0; }
  /// sets the domain flag
  void set_inside_domain(bool b) { m_bits = b ? m_bits | inside_bit : m_bits & ~inside_bit; }

  /// whether a constraint hides the circumcenter from the face (set by the BVD, Algorithm 1).
  bool is_blinded() const { return (m_bits & index_mask) != 0; }
  /// the first constrained edge on the way from the face to its circumcenter.
  /// \pre `is_blinded()`
  Edge blinding_edge() const {
    CGAL_precondition(is_blinded());
    return {m_blinding_face, int(m_bits & index_mask) - 1};
  }
  /// tags the face as blinded by the constrained edge `e`.
  void set_blinding_edge(const Edge& e) {
    m_blinding_face = e.first;
    m_bits = (m_bits & ~index_mask) | std::uint32_t(e.second + 1);
  }
  /// tags the face as seeing its circumcenter
  void clear_blinding() { m_bits &= ~index_mask; }

  /// A number for the algorithms that number faces, below `max_id`: `Bvd_mesh_2` numbers the
  /// circumcenters with it, `random_points_in_domain_2()` and `density_response_2()` the
  /// domain's faces. Each overwrites it.
  std::size_t id() const { return m_bits >> id_shift; }
  /// sets `id()`. \pre `i <= max_id`
  void set_id(std::size_t i) {
    CGAL_precondition(i <= max_id);
    m_bits = (m_bits & ((1u << id_shift) - 1)) | (std::uint32_t(i) << id_shift);
  }
  /// the largest id a face can hold
  static constexpr std::size_t max_id = (std::size_t(1) << 29) - 1;

 private:
  // One word fills the tail padding of the layer below (after the constrained flags of
  // Constrained_triangulation_face_base_2), so that the layer costs 8 bytes per face: bits 0-1
  // the blinding edge's index + 1 (0: the face sees its circumcenter), bit 2 the domain flag,
  // bits 3-31 the id.
  static constexpr std::uint32_t index_mask = 3, inside_bit = 4;
  static constexpr int id_shift = 3;
  std::uint32_t m_bits = 0;
  Face_handle m_blinding_face{};
};

}  // namespace CVT_2

#endif  // CVT_2_BVD_FACE_BASE_2_H
