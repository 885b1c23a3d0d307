// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// domain_poly_data(), write_poly(): the domain of a marked triangulation as Triangle's .poly
// description (a resampled domain, to read back or look at).
#ifndef CVT_2_IO_WRITE_POLY_H
#define CVT_2_IO_WRITE_POLY_H

#include <CVT_2/IO/internal/write_number.h>
#include <CVT_2/IO/read_poly.h>
#include <CVT_2/exceptions.h>
#include <CVT_2/internal/to_string.h>

#include <algorithm>
#include <cstddef>
#include <map>
#include <ostream>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace IO {

/// \ingroup PkgCvt2IO
/// The domain of `cdt` as Triangle's description: its constrained edges as segments, its
/// vertices (those on no segment are generators; left out if `with_generators` is false), and
/// one hole point in each region that Triangle's rule would otherwise put in the domain (a region
/// outside it, closed by constraints): `insert_poly()` of the result marks the same faces.
/// \throws Domain_error for a region outside the domain so thin that no centroid of its
///         triangles lies strictly inside it in double precision.
template <class CDT>
Poly_data<typename CDT::Point_2> domain_poly_data(const CDT& cdt,
                                                  const std::string& source = "<triangulation>",
                                                  bool with_generators = true) {
  using Face_handle = typename CDT::Face_handle;
  Poly_data<typename CDT::Point_2> d;
  d.source = source;
  // Vertices in the order of their points, segments in the order of their vertices: the same
  // description whatever the triangulation's layout.
  std::map<typename CDT::Point_2, std::size_t> index;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (with_generators || cdt.are_there_incident_constraints(v)) index.emplace(v->point(), 0);
  for (auto& [p, i] : index) i = d.vertices.size(), d.vertices.push_back(p);
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e)
    if (cdt.is_constrained(*e)) {
      const std::size_t a = index.at(e->first->vertex(CDT::ccw(e->second))->point());
      const std::size_t b = index.at(e->first->vertex(CDT::cw(e->second))->point());
      d.segments.push_back({std::min(a, b), std::max(a, b)});
    }
  std::sort(d.segments.begin(), d.segments.end());
  // Each region outside the domain that the unbounded face does not reach: a hole point at
  // the centroid of its largest triangle (ties: the smaller centroid) whose centroid lies
  // strictly inside a triangle of the region (exact location: not on an edge by rounding).
  std::unordered_set<Face_handle> seen;
  for (auto start = cdt.finite_faces_begin(); start != cdt.finite_faces_end(); ++start) {
    if (start->is_inside_domain() || !seen.insert(Face_handle(start)).second) continue;
    std::vector<Face_handle> stack{start}, region;
    bool bounded = true;
    while (!stack.empty()) {
      const Face_handle f = stack.back();
      stack.pop_back();
      if (cdt.is_infinite(f)) {
        bounded = false;
        continue;
      }
      region.push_back(f);
      for (int i = 0; i < 3; ++i)
        if (!cdt.is_constrained({f, i}) && seen.insert(f->neighbor(i)).second)
          stack.push_back(f->neighbor(i));
    }
    if (!bounded) continue;
    using Point_2 = typename CDT::Point_2;
    std::vector<std::pair<double, Point_2>> candidates;
    for (const Face_handle f : region)
      candidates.emplace_back(
          -CGAL::to_double(cdt.triangle(f).area()),
          CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()));
    std::sort(candidates.begin(), candidates.end());
    const std::unordered_set<Face_handle> in_region(region.begin(), region.end());
    bool seeded = false;
    for (const auto& [minus_area, c] : candidates) {
      typename CDT::Locate_type lt;
      int li;
      const Face_handle f = cdt.locate(c, lt, li);
      if (lt == CDT::FACE && in_region.count(f) > 0) {
        d.holes.push_back(c);
        seeded = true;
        break;
      }
    }
    if (!seeded)
      throw Domain_error("a region outside the domain near " +
                         CVT_2::internal::to_string(candidates.front().second) +
                         " is too thin for a hole point in double precision");
  }
  std::sort(d.holes.begin(), d.holes.end());
  d.vertex_lines.assign(d.vertices.size(), 0);
  d.segment_lines.assign(d.segments.size(), 0);
  d.hole_lines.assign(d.holes.size(), 0);
  return d;
}

/// \ingroup PkgCvt2IO
/// Writes the domain of `cdt` (`domain_poly_data()`) as a Triangle `.poly` file, numbered from
/// 0, coordinates as the shortest decimals that read back as the same doubles.
template <class CDT>
void write_poly(std::ostream& os, const CDT& cdt) {
  const auto d = domain_poly_data(cdt);
  os << "# the domain of a triangulation (CVT_2): vertices, segments, holes\n";
  const auto point_line = [&os](std::size_t i, const typename CDT::Point_2& p) {
    os << i << ' ';
    CVT_2::internal::write_number(os, p.x());
    os << ' ';
    CVT_2::internal::write_number(os, p.y());
    os << '\n';
  };
  os << d.vertices.size() << " 2 0 0\n";
  for (std::size_t i = 0; i < d.vertices.size(); ++i) point_line(i, d.vertices[i]);
  os << d.segments.size() << " 0\n";
  for (std::size_t j = 0; j < d.segments.size(); ++j)
    os << j << ' ' << d.segments[j][0] << ' ' << d.segments[j][1] << '\n';
  os << d.holes.size() << '\n';
  for (std::size_t j = 0; j < d.holes.size(); ++j) point_line(j, d.holes[j]);
}

}  // namespace IO
}  // namespace CVT_2

#endif  // CVT_2_IO_WRITE_POLY_H
