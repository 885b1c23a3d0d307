// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The BvdFaceBase_2 concept: what the bounded Voronoi diagram stores in each face, and its check.
#ifndef CVT_2_CONCEPTS_BVDFACEBASE_2_H
#define CVT_2_CONCEPTS_BVDFACEBASE_2_H

#include <type_traits>
#include <utility>

#ifdef DOXYGEN_RUNNING
// A concept is not a C++ type; as in CGAL, Doxygen sees it as a class that lists the
// requirements. The compiler never sees this class.

/// \ingroup PkgCvt2Concepts
/// The face base of a triangulation that `CVT_2::Bounded_voronoi_diagram_2` can use. It refines
/// CGAL's `ConstrainedTriangulationFaceBase_2` with two pieces of state per face:
/// - whether the face lies in the domain, written by `CVT_2::mark_domain_2()` and read by the
///   diagram and the readers;
/// - whether the face is blind and, if so, its first blinding constraint, written by the diagram
///   (Algorithm 1) and read when it builds cells (Algorithm 2).
///
/// A face is *blind* when a constrained edge meets the segment from the face's centroid to its
/// circumcenter; its blinding edge is the first one met on that way.
///
/// The member names differ from the `is_blind()`, `blinding_constraint()` and `is_in_domain()`
/// of CGAL's face bases, so that a model can be stacked on them and hide nothing.
///
/// \cgalHasModel `CVT_2::Bvd_face_base_2<Gt, Fb>`
/// \sa `CVT_2::is_bvd_face_base_2`
class BvdFaceBase_2 {
 public:
  /// The handle to a face of the triangulation data structure.
  using Face_handle = unspecified_type;
  /// An edge of the triangulation, as CGAL's triangulations spell it: a face and the index of the
  /// vertex opposite the edge.
  using Edge = std::pair<Face_handle, int>;

  /// \name Domain
  /// @{

  /// whether the face belongs to the domain.
  bool is_inside_domain() const;
  /// sets whether the face belongs to the domain.
  void set_inside_domain(bool b);
  /// @}

  /// \name Blindness
  /// @{

  /// whether a constrained edge hides the face's circumcenter from it.
  bool is_blinded() const;
  /// the first constrained edge met on the way from the face's centroid to its circumcenter.
  /// \pre `is_blinded()`
  Edge blinding_edge() const;
  /// makes the face blind, with `e` its first blinding edge; then `is_blinded()` is `true` and
  /// `blinding_edge()` returns `e`.
  /// \pre `e` is a constrained edge of the triangulation, given from either side.
  void set_blinding_edge(const Edge& e);
  /// makes the face see its circumcenter: then `is_blinded()` is `false`.
  void clear_blinding();
  /// @}
};
#endif  // DOXYGEN_RUNNING

namespace CVT_2 {
namespace internal {

template <class Face>
using Bvd_face_edge_t = std::pair<typename Face::Face_handle, int>;

template <class Face>
using Is_inside_domain_result_t = decltype(std::declval<const Face&>().is_inside_domain());
template <class Face>
using Set_inside_domain_result_t = decltype(std::declval<Face&>().set_inside_domain(true));
template <class Face>
using Is_blinded_result_t = decltype(std::declval<const Face&>().is_blinded());
template <class Face>
using Blinding_edge_result_t = decltype(std::declval<const Face&>().blinding_edge());
template <class Face>
using Set_blinding_edge_result_t =
    decltype(std::declval<Face&>().set_blinding_edge(std::declval<const Bvd_face_edge_t<Face>&>()));
template <class Face>
using Clear_blinding_result_t = decltype(std::declval<Face&>().clear_blinding());

}  // namespace internal

/// \ingroup PkgCvt2Concepts
/// Whether the face type `Face` provides what `BvdFaceBase_2` requires: `Face_handle`,
/// `is_inside_domain()` and `is_blinded()` convertible to `bool`, `blinding_edge()` convertible
/// to `std::pair<Face_handle, int>`, and `set_inside_domain(bool)`, `set_blinding_edge(Edge)`
/// and `clear_blinding()` callable. A `std::true_type` or `std::false_type`.
///
/// Give it the face of the triangulation data structure (`CDT::Face`), that is the face base
/// after the data structure rebound it, since only then is `Face_handle` known.
template <class Face, class = void>
struct is_bvd_face_base_2 : std::false_type {};

/// \cond SKIP_IN_MANUAL
template <class Face>
struct is_bvd_face_base_2<
    Face,
    std::void_t<typename Face::Face_handle, internal::Is_inside_domain_result_t<Face>,
                internal::Set_inside_domain_result_t<Face>, internal::Is_blinded_result_t<Face>,
                internal::Blinding_edge_result_t<Face>, internal::Set_blinding_edge_result_t<Face>,
                internal::Clear_blinding_result_t<Face>>>
    : std::bool_constant<
          std::is_convertible<internal::Is_inside_domain_result_t<Face>, bool>::value &&
          std::is_convertible<internal::Is_blinded_result_t<Face>, bool>::value &&
          std::is_convertible<internal::Blinding_edge_result_t<Face>,
                              internal::Bvd_face_edge_t<Face>>::value> {};
/// \endcond

/// \ingroup PkgCvt2Concepts
/// `is_bvd_face_base_2<Face>::value`.
template <class Face>
inline constexpr bool is_bvd_face_base_2_v = is_bvd_face_base_2<Face>::value;

}  // namespace CVT_2

#endif  // CVT_2_CONCEPTS_BVDFACEBASE_2_H
