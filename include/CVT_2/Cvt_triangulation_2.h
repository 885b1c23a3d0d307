// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Cvt_triangulation_2: the constrained Delaunay triangulation the library works on by default.
#ifndef CVT_2_CVT_TRIANGULATION_2_H
#define CVT_2_CVT_TRIANGULATION_2_H

#include <CVT_2/Bvd_face_base_2.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_with_id_2.h>

namespace CVT_2 {

/// \ingroup PkgCvt2Ref
/// CGAL's constrained Delaunay triangulation with `Bvd_face_base_2` faces, what the diagram and
/// the optimizers need when nothing else is, and vertices with an `id()` (which `Bvd_mesh_2`
/// numbers the cells with; any vertex base works, a little more slowly):
///
///     using CDT = CGAL::Constrained_Delaunay_triangulation_2<K,
///         CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_with_id_2<K>,
///                                              CVT_2::Bvd_face_base_2<K>>,
///         Itag>;
///
/// With the default `Itag`, constraints that cross are an error (the readers report the
/// segment), not split at a constructed point.
/// \tparam K a CGAL kernel, `CGAL::Exact_predicates_inexact_constructions_kernel` for example.
/// \tparam Itag CGAL's intersection tag.
template <class K, class Itag = CGAL::No_constraint_intersection_requiring_constructions_tag>
using Cvt_triangulation_2 = CGAL::Constrained_Delaunay_triangulation_2<
    K,
    CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_with_id_2<K>,
                                         Bvd_face_base_2<K>>,
    Itag>;

}  // namespace CVT_2

#endif  // CVT_2_CVT_TRIANGULATION_2_H
