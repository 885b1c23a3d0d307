// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Writing a bounded Voronoi diagram as an SVG picture: domain, cells, constraints, generators.
#ifndef CVT_2_IO_WRITE_SVG_H
#define CVT_2_IO_WRITE_SVG_H

#include <CGAL/number_utils.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace CVT_2 {
namespace IO {

/// \ingroup PkgCvt2IO
/// Writes `bvd` as an SVG picture `width` pixels wide, y up: the domain in grey, each cell
/// outlined, constraints in black, free generators as black dots and constrained ones in red.
/// \tparam BVD a `Bounded_voronoi_diagram_2`.
template <class BVD>
void write_svg(std::ostream& os, const BVD& bvd, double width = 800) {
  const auto& cdt = bvd.triangulation();
  double xmin = std::numeric_limits<double>::max(), ymin = xmin, xmax = -xmin, ymax = -xmin;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_inside_domain()) continue;
    for (int i = 0; i < 3; ++i) {
      const double x = CGAL::to_double(f->vertex(i)->point().x());
      const double y = CGAL::to_double(f->vertex(i)->point().y());
      xmin = std::min(xmin, x), xmax = std::max(xmax, x);
      ymin = std::min(ymin, y), ymax = std::max(ymax, y);
    }
  }
  if (xmin > xmax) xmin = ymin = 0, xmax = ymax = 1;  // empty domain
  const double margin = 10, span = std::max({xmax - xmin, ymax - ymin, 1e-300});
  const double scale = (width - 2 * margin) / std::max(xmax - xmin, span * 1e-3);
  const double height = (ymax - ymin) * scale + 2 * margin;
  const auto X = [&](double x) { return margin + (x - xmin) * scale; };
  const auto Y = [&](double y) { return height - margin - (y - ymin) * scale; };
  const auto pt = [&](const auto& p) {
    return std::to_string(X(CGAL::to_double(p.x()))) + "," +
           std::to_string(Y(CGAL::to_double(p.y())));
  };

  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
     << "\" viewBox=\"0 0 " << width << ' ' << height << "\">\n"
     << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  os << "<g fill=\"#e8eef4\" stroke=\"#e8eef4\" stroke-width=\"0.5\">\n";
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->is_inside_domain())
      os << "<polygon points=\"" << pt(f->vertex(0)->point()) << ' ' << pt(f->vertex(1)->point())
         << ' ' << pt(f->vertex(2)->point()) << "\"/>\n";
  os << "</g>\n<g fill=\"none\" stroke=\"#3a6ea5\" stroke-width=\"0.7\">\n";
  std::vector<typename BVD::Cell_vertex> cell;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    bvd.cell(v, cell);
    if (cell.empty()) continue;
    os << "<polygon points=\"";
    for (const auto& c : cell) os << pt(c.point) << ' ';
    os << "\"/>\n";
  }
  os << "</g>\n<g stroke=\"black\" stroke-width=\"1.6\" stroke-linecap=\"round\">\n";
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
    if (!cdt.is_constrained(*e)) continue;
    const auto& a = e->first->vertex(cdt.ccw(e->second))->point();
    const auto& b = e->first->vertex(cdt.cw(e->second))->point();
    os << "<line x1=\"" << X(CGAL::to_double(a.x())) << "\" y1=\"" << Y(CGAL::to_double(a.y()))
       << "\" x2=\"" << X(CGAL::to_double(b.x())) << "\" y2=\"" << Y(CGAL::to_double(b.y()))
       << "\"/>\n";
  }
  os << "</g>\n<g stroke=\"none\">\n";
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    if (!bvd.has_cell(v)) continue;
    os << "<circle cx=\"" << X(CGAL::to_double(v->point().x())) << "\" cy=\""
       << Y(CGAL::to_double(v->point().y())) << "\" r=\"1.6\" fill=\""
       << (bvd.is_free(v) ? "black" : "#c0392b") << "\"/>\n";
  }
  os << "</g>\n</svg>\n";
}

/// \ingroup PkgCvt2IO
/// Writes `bvd` to the SVG file `filename`; returns false if the file could not be written.
template <class BVD>
bool write_svg(const std::string& filename, const BVD& bvd, double width = 800) {
  std::ofstream os(filename);
  if (!os) return false;
  write_svg(os, bvd, width);
  return static_cast<bool>(os);
}

}  // namespace IO
}  // namespace CVT_2

#endif  // CVT_2_IO_WRITE_SVG_H
