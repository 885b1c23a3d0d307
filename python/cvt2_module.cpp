// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// cvt2._cvt2, the compiled part of the Python module cvt2: domains, random points, optimization
// and bounded Voronoi diagrams as numpy arrays. Conversions and the GIL only: the algorithms are
// the library's, called as the cvt2 program calls them, so that the same input gives the same
// bits. cvt2/__init__.py is the documented interface.
#include <CVT_2/Boundary_lipschitz_sizing_2.h>
#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/Bvd_mesh_2.h>
#include <CVT_2/Constraint_editor_2.h>
#include <CVT_2/Cvt_triangulation_2.h>
#include <CVT_2/IO/read_domain.h>
#include <CVT_2/IO/write_cells_on_constraints.h>
#include <CVT_2/IO/write_disv.h>
#include <CVT_2/IO/write_geojson.h>
#include <CVT_2/IO/write_poly.h>
#include <CVT_2/IO/write_vtu.h>
#include <CVT_2/IO/write_wkb.h>
#include <CVT_2/Simulation_grid_2.h>
#include <CVT_2/Sliding_runs_2.h>
#include <CVT_2/cell_size_scale_2.h>
#include <CVT_2/conforming_sites_2.h>
#include <CVT_2/density_response_2.h>
#include <CVT_2/exceptions.h>
#include <CVT_2/insert_generators_2.h>
#include <CVT_2/internal/input_segments_of_constraints.h>
#include <CVT_2/internal/memory_estimate.h>
#include <CVT_2/internal/parallel/Interrupt_scope.h>
#include <CVT_2/internal/to_string.h>
#include <CVT_2/internal/valid_point.h>
#include <CVT_2/lbfgs_optimize_2.h>
#include <CVT_2/lloyd_optimize_2.h>
#include <CVT_2/mark_domain_2.h>
#include <CVT_2/natural_neighbor_coordinates_2.h>
#include <CVT_2/random_points_in_domain_2.h>
#include <CVT_2/resample_constraints_2.h>
#include <CVT_2/version.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <new>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using CDT = CVT_2::Cvt_triangulation_2<K>;
using BVD = CVT_2::Bounded_voronoi_diagram_2<CDT>;
using Mesh = CVT_2::Bvd_mesh_2<BVD>;
using Grid = CVT_2::Simulation_grid_2<Mesh>;
using Point_2 = K::Point_2;
using Sizing = CVT_2::Boundary_lipschitz_sizing_2<K>;
using Domain_data = CVT_2::IO::Domain_data<K>;
using Poly_data = CVT_2::IO::Poly_data<Point_2>;
using Wkt_data = CVT_2::IO::Wkt_data<K>;
using Index = Mesh::Index;
using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// --- errors ------------------------------------------------------------------------------------

// cvt2.ParseError and cvt2.DomainError, both ValueErrors; created once, never freed (a static
// Python object would be released after the interpreter).
PyObject* parse_error_type = nullptr;
PyObject* domain_error_type = nullptr;

py::str utf8(const std::string& s) {
  return py::reinterpret_steal<py::str>(
      PyUnicode_DecodeUTF8(s.data(), py::ssize_t(s.size()), "replace"));
}

// The library's exceptions as Python ones, with what they know as attributes.
void translate_exception(std::exception_ptr p) {
  try {
    if (p) std::rethrow_exception(p);
  } catch (const CVT_2::IO::Parse_error& e) {
    py::object x = py::handle(parse_error_type)(utf8(e.what()));
    x.attr("file") = utf8(e.file());
    x.attr("line") = e.line();
    x.attr("token") = utf8(e.token());
    PyErr_SetObject(parse_error_type, x.ptr());
  } catch (const CVT_2::Domain_error& e) {
    py::object x = py::handle(domain_error_type)(utf8(e.what()));
    x.attr("index") = e.index() == CVT_2::Domain_error::no_index ? py::object(py::none())
                                                                 : py::object(py::int_(e.index()));
    PyErr_SetObject(domain_error_type, x.ptr());
  } catch (const std::ios_base::failure& e) {
    PyErr_SetObject(PyExc_OSError, utf8(e.what()).ptr());
  }
}

std::string shape_of(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

// Whether an array holds what a double takes as meant: integers and floats, not booleans,
// strings, complex numbers or objects, which numpy would cast without a word.
bool holds_real_numbers(const py::array& a) {
  const char kind = a.dtype().kind();
  return kind == 'f' || kind == 'i' || kind == 'u';
}

// An array of shape (n, 2) of numbers (a list of pairs works), as points; an empty sequence is no
// point. Coordinates are checked where they are used, with the library's messages.
std::vector<Point_2> to_points(py::handle object, const std::string& name) {
  const std::string what = name + " must be an array of shape (n, 2) of numbers";
  if (object.is_none()) throw py::type_error(what + ", not None");
  const py::array given = py::array::ensure(object);
  if (!given) throw py::type_error(what);
  if (!holds_real_numbers(given))
    throw py::type_error(what + ", not an array of " + std::string(py::str(given.dtype())));
  const Array a = Array::ensure(given);
  if (!a) throw py::type_error(what);
  if (a.ndim() == 1 && a.shape(0) == 0) return {};
  if (a.ndim() != 2 || a.shape(1) != 2)
    throw py::value_error(name + " must have shape (n, 2), not " + shape_of(a));
  std::vector<Point_2> points;
  points.reserve(std::size_t(a.shape(0)));
  const auto r = a.unchecked<2>();
  for (py::ssize_t i = 0; i < r.shape(0); ++i) points.emplace_back(r(i, 0), r(i, 1));
  return points;
}

Array to_array(const std::vector<Point_2>& points) {
  Array a({py::ssize_t(points.size()), py::ssize_t(2)});
  auto w = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < points.size(); ++i)
    w(py::ssize_t(i), 0) = points[i].x(), w(py::ssize_t(i), 1) = points[i].y();
  return a;
}

template <class T>
py::array_t<T> to_array(const std::vector<T>& v, py::ssize_t columns = 1) {
  std::vector<py::ssize_t> shape{py::ssize_t(v.size()) / columns};
  if (columns > 1) shape.push_back(columns);
  py::array_t<T> a(shape);
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

// Generators into a triangulation whose domain is marked; a bad one is named by its row (the
// first few of those outside, with how many). Returns the notes: the points moved onto the
// boundary, outside it by no more than `boundary_tolerance` (None: the library's default).
// `where`, if given, receives where each point is now (as given, or moved onto the boundary):
// the positions vertices_of() finds their vertices at.
std::vector<std::string> insert_points(CDT& cdt, const std::vector<Point_2>& points,
                                       const std::string& name,
                                       std::optional<double> boundary_tolerance = {},
                                       std::vector<Point_2>* where = nullptr) {
  const auto row = [&name](std::size_t k) { return name + "[" + std::to_string(k) + "]"; };
  try {
    const auto r =
        boundary_tolerance
            ? CVT_2::insert_generators_2(cdt, points,
                                         CVT_2::parameters::boundary_tolerance(*boundary_tolerance))
            : CVT_2::insert_generators_2(cdt, points);
    if (where != nullptr) {  // where each point is now: as given, or moved onto the boundary
      *where = points;
      for (std::size_t i = 0; i < r.moved.size(); ++i) (*where)[r.moved[i]] = r.moved_to[i];
    }
    const std::string note = CVT_2::internal::moved_points_note(r, points, row, row);
    return note.empty() ? std::vector<std::string>() : std::vector<std::string>{note};
  } catch (const CVT_2::internal::Generators_outside_error& e) {
    throw CVT_2::Domain_error(row(e.index()) + ": " + e.message(row), e.index());
  } catch (const CVT_2::Domain_error& e) {
    if (e.index() == CVT_2::Domain_error::no_index) throw;
    throw CVT_2::Domain_error(row(e.index()) + ": " + e.what(), e.index());
  }
}

// Ctrl-C while the library works without the GIL: its long loops poll an Interrupt_scope with
// this check, which takes the GIL at most every 20 ms for Python to run its signal handlers, and
// throws their exception (KeyboardInterrupt). What the call was building is then dropped.
struct Signal_check {
  std::chrono::steady_clock::time_point next{};
  void operator()() {
    const auto now = std::chrono::steady_clock::now();
    if (now < next) return;
    next = now + std::chrono::milliseconds(20);
    const py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  }
};

// The vertex at each of `points` in `cdt`, where insert_points() put them (its `where`: points
// moved onto the boundary are where they went; duplicates share one); none (a null handle) for a
// point that is no vertex. Looking for the vertex nearest to where a point was given instead
// found another point's along a slanted edge, a rounding away.
std::vector<CDT::Vertex_handle> vertices_of(const CDT& cdt, const std::vector<Point_2>& points) {
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  if (!points.empty()) {  // make_property_map() would take the address of points[0]
    using Map = CGAL::Pointer_property_map<Point_2>::const_type;
    CGAL::spatial_sort(
        order.begin(), order.end(),
        CVT_2::internal::Interruptible_sort_traits_2<CGAL::Spatial_sort_traits_adapter_2<K, Map>>(
            CGAL::Spatial_sort_traits_adapter_2<K, Map>(CGAL::make_property_map(points))));
  }
  std::vector<CDT::Vertex_handle> out(points.size());
  CDT::Face_handle hint;
  for (const std::size_t i : order) {
    CVT_2::internal::poll_interrupt_sometimes();
    CDT::Locate_type lt;
    int li;
    const CDT::Face_handle f = cdt.locate(points[i], lt, li, hint);
    hint = f;
    if (lt == CDT::VERTEX) out[i] = f->vertex(li);
  }
  return out;
}

// --- domains -----------------------------------------------------------------------------------

// A domain as described (a file's contents, arrays, shapely geometries), never a triangulation:
// each use builds its own, as cvt2 does from the file, so a domain can be used again.
struct Domain {
  Domain_data data;
  std::string format;  // poly, wkt, geojson, arrays, shapely
  // The input segments (their ends, two points each), which ridges are numbered by, and the item
  // of each: its row (.poly, arrays), its line (.wkt) or feature (.geojson), its geometry
  // (shapely: 0 the polygon, k + 1 constraints[k]).
  std::vector<Point_2> segment_ends;
  std::vector<std::int64_t> segment_items;
  std::size_t segment_rings = 0;  // the first segments, polygons' ring edges (Domain_segments)
  // the file's repeated points and the segments that lie on earlier ones, as cvt2 notes them
  std::vector<std::string> notes;
  double area = 0;
  std::array<double, 4> bounds{};
  std::size_t own_cells = 0;  // the vertices of the triangulation with a cell: on the domain
  // What the writers put in their headers, as cvt2 writes it for the same domain.
  CVT_2::IO::Metadata metadata;
  // A domain that Domain.resample made: the runs its new vertices can slide on (by their points).
  std::shared_ptr<const CVT_2::Sliding_runs_2<CDT>> runs;
  // A domain whose lines optimize(..., constraints="conforming") made conforming: their pairs of
  // generators and the lines' items.
  std::vector<CVT_2::Conforming_pair_2<Point_2>> conforming_pairs;
  std::vector<std::int64_t> conforming_items;
  std::int64_t item_offset = 0;  // from a polyline's number in the description to its item

  // A GeoJSON feature's "kind" for the input item `item` ("slit", "barrier", "conforming"), or
  // `by_default` where it says none (as cvt2's --constraints).
  const std::string& kind(std::int64_t item, const std::string& by_default) const {
    const auto* w = std::get_if<1>(&data.description);
    if (w == nullptr) return by_default;
    const std::int64_t k = item - item_offset - 1;  // item_kinds counts items from 1
    if (k >= 0 && std::size_t(k) < w->item_kinds.size() && !w->item_kinds[std::size_t(k)].empty())
      return w->item_kinds[std::size_t(k)];
    return by_default;
  }
  bool has_kinds() const {
    const auto* w = std::get_if<1>(&data.description);
    return w != nullptr && std::any_of(w->item_kinds.begin(), w->item_kinds.end(),
                                       [](const std::string& k) { return !k.empty(); });
  }

  std::unique_ptr<CDT> triangulation() const {
    auto cdt = std::make_unique<CDT>();
    CVT_2::IO::insert_domain(*cdt, data);
    return cdt;
  }

  // Builds the triangulation once, which checks the domain, and lists its segments.
  void finish(std::int64_t offset = 0) {
    item_offset = offset;
    if (metadata.empty())
      metadata = {{"program", std::string("cvt2 ") + CVT_2_VERSION_STRING},
                  {"domain", data.file.source},
                  {"boundary", "keep"}};
    auto segments = CVT_2::IO::domain_segments(data);
    segment_ends = std::move(segments.ends);
    segment_items = std::move(segments.items);
    segment_rings = segments.rings;
    if (data.description.index() == 1)
      for (std::int64_t& item : segment_items) item += offset;
    const auto cdt = triangulation();
    notes = data.file.repeated;  // a copy's own: a domain made from another has other segments
    for (const std::string& note : CVT_2::IO::segments_on_earlier_ones(
             *cdt, CVT_2::IO::Domain_segments<K>{segment_ends, segment_items, segment_rings}))
      notes.push_back(data.file.source + ": " + note);
    own_cells = CVT_2::internal::number_of_vertices_in_domain(*cdt);
    bounds = {HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (auto f = cdt->finite_faces_begin(); f != cdt->finite_faces_end(); ++f) {
      if (!f->is_inside_domain()) continue;
      area += cdt->triangle(f).area();
      for (int i = 0; i < 3; ++i) {
        const Point_2& p = f->vertex(i)->point();
        bounds = {std::min(bounds[0], p.x()), std::min(bounds[1], p.y()),
                  std::max(bounds[2], p.x()), std::max(bounds[3], p.y())};
      }
    }
  }
};

std::shared_ptr<Domain> domain_from_file(const std::string& path) {
  auto d = std::make_shared<Domain>();
  py::gil_scoped_release release;
  d->data = CVT_2::IO::read_domain_data<K>(path);
  d->format = d->data.file.format;
  d->finish();
  return d;
}

// Triangle's description, as the `triangle` package takes it: rows are named in messages as
// `<arrays>:ROW:` (rows from 0).
std::shared_ptr<Domain> domain_from_arrays(py::handle vertices, py::handle segments,
                                           py::handle holes) {
  auto d = std::make_shared<Domain>();
  Poly_data& p = d->data.description.emplace<0>();
  p.source = "<arrays>";
  p.vertices = to_points(vertices, "vertices");
  const auto s = py::array::ensure(segments);
  if (!s) throw py::type_error("segments must be an array of shape (m, 2) of vertex indices");
  if (s.size() > 0 && s.dtype().kind() != 'i' && s.dtype().kind() != 'u')
    throw py::type_error("segments must hold integers (vertex indices), not " +
                         std::string(py::str(s.dtype())));
  const auto segs = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(s);
  if (!(segs.ndim() == 1 && segs.shape(0) == 0) && (segs.ndim() != 2 || segs.shape(1) != 2))
    throw py::value_error("segments must have shape (m, 2), not " + shape_of(segs));
  const std::int64_t* x = segs.data();
  const std::size_t m = segs.ndim() == 2 ? std::size_t(segs.shape(0)) : 0;
  for (std::size_t j = 0; j < m; ++j) {
    for (int e = 0; e < 2; ++e)
      if (x[2 * j + e] < 0 || std::uint64_t(x[2 * j + e]) >= p.vertices.size())
        throw py::index_error("segments[" + std::to_string(j) + "] = (" + std::to_string(x[2 * j]) +
                              ", " + std::to_string(x[2 * j + 1]) + "): no such vertex among " +
                              std::to_string(p.vertices.size()));
    p.segments.push_back({std::size_t(x[2 * j]), std::size_t(x[2 * j + 1])});
    p.segment_lines.push_back(j);
  }
  for (std::size_t i = 0; i < p.vertices.size(); ++i) p.vertex_lines.push_back(i);
  if (!holes.is_none()) p.holes = to_points(holes, "holes");
  for (std::size_t i = 0; i < p.holes.size(); ++i) p.hole_lines.push_back(i);
  for (std::size_t i = 0; i < p.holes.size(); ++i)
    if (!CVT_2::internal::is_valid_point(p.holes[i]))
      throw CVT_2::Domain_error(CVT_2::internal::invalid_point_message(
          "holes[" + std::to_string(i) + "] " + CVT_2::internal::to_string(p.holes[i])));
  std::vector<bool> on_segment(p.vertices.size(), false);
  for (const auto& e : p.segments) on_segment[e[0]] = on_segment[e[1]] = true;
  for (const bool b : on_segment) d->data.file.number_of_generators += b ? 0 : 1;
  d->data.file.source = p.source;
  d->data.file.format = d->format = "arrays";
  py::gil_scoped_release release;
  d->finish();
  return d;
}

// Shapely's geometries as the WKT and GeoJSON readers read them: `polygons` a list of polygons,
// each a list of closed rings (arrays (k, 2), the exterior first), `lines` a list of arrays
// (k, 2) with `line_items[i]` the constraint each comes from. Items are named in messages:
// `<shapely>: polygon: ...`, `<shapely>: constraints[2]: ...`.
std::shared_ptr<Domain> domain_from_shapely(const std::vector<std::vector<py::object>>& polygons,
                                            const std::vector<py::object>& lines,
                                            const std::vector<std::size_t>& line_items) {
  auto d = std::make_shared<Domain>();
  Wkt_data& w = d->data.description.emplace<1>();
  w.source = "<shapely>";
  w.item_names.push_back("polygon");
  const auto checked = [&](py::handle a, const std::string& item, const std::string& what) {
    std::vector<Point_2> p = to_points(a, what);
    for (const Point_2& q : p)
      if (!CVT_2::internal::is_valid_point(q))
        throw CVT_2::Domain_error(
            w.source + ": " + item + ": " +
            CVT_2::internal::invalid_point_message("point " + CVT_2::internal::to_string(q)));
    return p;
  };
  for (const auto& rings : polygons) {
    CGAL::Polygon_with_holes_2<K> pwh;
    for (std::size_t r = 0; r < rings.size(); ++r) {
      std::vector<Point_2> p = checked(rings[r], "polygon", "a ring");
      if (p.size() < 4 || p.front() != p.back())
        throw CVT_2::Domain_error(w.source +
                                  ": polygon: a ring must be closed, with 4 "
                                  "positions or more");
      p.pop_back();
      std::vector<Point_2> distinct = p;
      std::sort(distinct.begin(), distinct.end());
      if (std::unique(distinct.begin(), distinct.end()) - distinct.begin() < 3)
        throw CVT_2::Domain_error(w.source + ": polygon: a ring needs 3 distinct points");
      if (r == 0)
        pwh = CGAL::Polygon_with_holes_2<K>(CGAL::Polygon_2<K>(p.begin(), p.end()));
      else
        pwh.add_hole(CGAL::Polygon_2<K>(p.begin(), p.end()));
    }
    w.polygons.push_back(std::move(pwh));
    w.polygon_lines.push_back(1);
  }
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string name = "constraints[" + std::to_string(line_items[i]) + "]";
    while (w.item_names.size() < line_items[i] + 2) w.item_names.push_back(name);
    w.item_names[line_items[i] + 1] = name;
    std::vector<Point_2> p = checked(lines[i], name, "a constraint");
    if (p.size() < 2) throw CVT_2::Domain_error(w.source + ": " + name + ": a line needs 2 points");
    w.polylines.push_back(std::move(p));
    w.polyline_lines.push_back(line_items[i] + 2);
  }
  if (w.polygons.empty()) throw CVT_2::Domain_error(w.source + ": no polygon");
  d->data.file.source = w.source;
  d->data.file.format = d->format = "shapely";
  py::gil_scoped_release release;
  d->finish(-1);
  return d;
}

// The description's own arrays, for Python: vertices and segments as Triangle has them (a WKT
// domain's rings and lines one after the other), holes and generators.
py::dict domain_arrays(const Domain& d) {
  py::dict out;
  std::vector<Point_2> vertices, holes, generators;
  std::vector<std::int64_t> segments;
  if (const auto* p = std::get_if<0>(&d.data.description)) {
    vertices = p->vertices;
    for (const auto& s : p->segments)
      segments.push_back(std::int64_t(s[0])), segments.push_back(std::int64_t(s[1]));
    holes = p->holes;
    std::vector<bool> on_segment(p->vertices.size(), false);
    for (const auto& s : p->segments) on_segment[s[0]] = on_segment[s[1]] = true;
    for (std::size_t i = 0; i < p->vertices.size(); ++i)
      if (!on_segment[i]) generators.push_back(p->vertices[i]);
  } else {
    // The rings' and lines' points, each once (the triangulation merges equal points too).
    std::map<Point_2, std::int64_t> number;
    for (const Point_2& p : d.segment_ends) {
      const auto [it, is_new] = number.emplace(p, std::int64_t(vertices.size()));
      if (is_new) vertices.push_back(p);
      segments.push_back(it->second);
    }
    generators = std::get<1>(d.data.description).points;
  }
  out["vertices"] = to_array(vertices);
  out["segments"] = to_array(segments, 2);
  out["segment_items"] = to_array(d.segment_items);
  out["holes"] = to_array(holes);
  out["generators"] = to_array(generators);
  return out;
}

// The item of each row of `out`'s segments: that of the segment of `ends`/`items` (two points,
// one item a segment) that it lies on, walked along the constrained edges of `cdt`, out's
// triangulation; -1 for none. So a resampled or slid domain names its lines as the input does.
void name_segments(Domain& out, const CDT& cdt, const std::vector<Point_2>& ends,
                   const std::vector<std::int64_t>& items) {
  const auto of_edge =
      CVT_2::IO::constrained_edge_items(cdt, CVT_2::IO::Domain_segments<K>{ends, items, 0});
  for (std::size_t i = 0; i < out.segment_items.size(); ++i) {
    const auto it = of_edge.find(std::minmax(out.segment_ends[2 * i], out.segment_ends[2 * i + 1]));
    out.segment_items[i] = it == of_edge.end() ? -1 : it->second;
  }
}

// The domain with its constraints resampled (resample_constraints_2()) to the size h, or to
// the size that gives `cells` cells: a new domain described as Triangle's arrays, and what the
// resampling did.
py::tuple domain_resample(const Domain& d, std::optional<std::size_t> cells,
                          std::optional<double> size, std::optional<double> deviation_bound,
                          double corner_angle, py::handle fixed, double minimum_ring_area,
                          std::optional<double> spacing) {
  const double spacing_ratio = spacing.value_or(CVT_2::default_spacing_ratio);
  // The numbers are checked by resample_constraints_2() and cell_size_for_cells_2().
  if (cells.has_value() == size.has_value()) throw py::value_error("give one of cells and size");
  if (d.has_kinds())
    throw py::value_error(
        "Domain.resample does not carry the GeoJSON features' \"kind\" properties yet (its "
        "conforming lines would be resampled as constraints): use cvt2 --boundary resample, or "
        "a domain without kinds");
  const std::vector<Point_2> fixed_points =
      fixed.is_none() ? std::vector<Point_2>() : to_points(fixed, "fixed_points");
  for (std::size_t k = 0; k < fixed_points.size(); ++k)  // NaN matched no vertex: ignored
    if (!CVT_2::internal::is_valid_point(fixed_points[k]))
      throw CVT_2::Domain_error("fixed_points[" + std::to_string(k) + "]: " +
                                    CVT_2::internal::invalid_point_message(
                                        "point " + CVT_2::internal::to_string(fixed_points[k])),
                                k);
  auto out = std::make_shared<Domain>();
  CVT_2::Resampling_report r;
  double h = 0;
  {
    py::gil_scoped_release release;
    const auto cdt = d.triangulation();
    for (std::size_t k = 0; k < fixed_points.size(); ++k)  // as cvt2 --fixed-points says it
      if (!CVT_2::is_in_domain_2(*cdt, fixed_points[k]))
        throw CVT_2::Domain_error("fixed_points[" + std::to_string(k) + "]: point " +
                                      CVT_2::internal::to_string(fixed_points[k]) +
                                      " lies outside the domain",
                                  k);
    h = size ? *size : CVT_2::cell_size_for_cells_2(*cdt, *cells, spacing_ratio);
    auto runs = std::make_shared<CVT_2::Sliding_runs_2<CDT>>();
    // The input item of each constrained edge, for the chords that replace them.
    const auto edge_items = CVT_2::IO::constrained_edge_items(
        *cdt, CVT_2::IO::Domain_segments<K>{d.segment_ends, d.segment_items, d.segment_rings});
    std::vector<CVT_2::Resampled_chord<Point_2>> chords;
    auto np = CVT_2::parameters::corner_angle(corner_angle)
                  .spacing_ratio(spacing_ratio)
                  .fixed_points(fixed_points)
                  .minimum_ring_area(minimum_ring_area)
                  .sliding_runs(runs.get())
                  .resampled_chords(&chords);
    r = deviation_bound
            ? CVT_2::resample_constraints_2(*cdt, h, np.deviation_bound(*deviation_bound))
            : CVT_2::resample_constraints_2(*cdt, h, np);
    out->data.description = CVT_2::IO::domain_poly_data(*cdt, "<arrays>");
    out->runs = std::move(runs);
    out->data.file.source = d.data.file.source + " (resampled)";
    using CVT_2::internal::number_text;
    out->metadata = {d.metadata[0],
                     d.metadata[1],
                     {"boundary", "resample"},
                     {"cell_size", number_text(h)},
                     {"spacing_ratio", number_text(spacing_ratio)},
                     {"deviation_bound", number_text(deviation_bound ? *deviation_bound : h / 4)},
                     {"max_deviation", number_text(r.max_deviation)}};
    out->data.file.format = out->format = "arrays";
    const auto& poly = std::get<0>(out->data.description);
    std::vector<bool> on_segment(poly.vertices.size(), false);
    for (const auto& s : poly.segments) on_segment[s[0]] = on_segment[s[1]] = true;
    for (const bool b : on_segment) out->data.file.number_of_generators += b ? 0 : 1;
    out->finish();
    // Each chord named by the input line it replaces, not by its row.
    const auto named = CVT_2::IO::resampled_segments<K>(chords, edge_items);
    name_segments(*out, *cdt, named.ends, named.items);
  }
  py::dict report;
  report["size"] = h;
  report["spacing_ratio"] = spacing_ratio;
  report["deviation_bound"] = deviation_bound ? *deviation_bound : h / 4;
  report["input_vertices"] = r.input_vertices;
  report["output_vertices"] = r.output_vertices;
  report["features"] = r.features;
  report["corners"] = r.corners;
  report["runs"] = r.runs;
  report["kept_for_deviation"] = r.kept_for_deviation;
  report["kept_for_topology"] = r.kept_for_topology;
  report["rings_dropped"] = r.rings_dropped;
  report["generators_dropped"] = r.generators_dropped;
  report["max_deviation"] = r.max_deviation;
  report["area_before"] = r.area_before;
  report["area_after"] = r.area_after;
  return py::make_tuple(out, report);
}

// The domain of `cdt` after its vertices slid along `runs` (optimize(..., boundary="slide")): its
// lines where they are now, as Triangle's arrays, so that the diagram's ridges and the writers
// name them, the runs as they are (to slide again), the largest deviation in the metadata; its
// generators are the optimization's.
std::shared_ptr<Domain> slid_domain(const Domain& d, const CDT& cdt,
                                    const CVT_2::Sliding_runs_2<CDT>& runs,
                                    const CVT_2::Slid_vertices_2<CDT>& slid) {
  auto out = std::make_shared<Domain>();
  out->data.description = CVT_2::IO::domain_poly_data(cdt, "<arrays>", false);
  out->data.file.source = d.data.file.source;
  out->data.file.format = out->format = "arrays";
  out->metadata = d.metadata;
  for (auto& [key, value] : out->metadata)
    if (key == "boundary") value = "slide";
  // the resampling's bound the chords that did not slide
  CVT_2::IO::raise_metadata_number(out->metadata, "max_deviation", runs.max_deviation());
  out->runs = std::make_shared<const CVT_2::Sliding_runs_2<CDT>>(runs);
  out->finish();
  // Each line named as before the slide: d's segments, their ends where their vertices slid,
  // walked in the slid triangulation.
  std::vector<Point_2> ends = d.segment_ends;
  slid.follow(ends);
  name_segments(*out, cdt, ends, d.segment_items);
  return out;
}

// The domain without its conforming lines, those whose kind (a GeoJSON feature's, else
// `by_default`) is "conforming": `lines` gets them and `items` their items.
std::shared_ptr<Domain> without_conforming_lines(const Domain& d, const std::string& by_default,
                                                 std::vector<std::vector<Point_2>>& lines,
                                                 std::vector<std::int64_t>& items) {
  auto out = std::make_shared<Domain>();
  out->data = d.data;
  auto& lw = std::get<1>(out->data.description);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < lw.polylines.size(); ++i) {
    const std::int64_t item = std::int64_t(lw.polyline_lines[i]) + d.item_offset;
    if (d.kind(item, by_default) == "conforming") {
      lines.push_back(std::move(lw.polylines[i]));
      items.push_back(item);
    } else {
      if (kept != i) lw.polylines[kept] = std::move(lw.polylines[i]);
      lw.polyline_lines[kept++] = lw.polyline_lines[i];
    }
  }
  lw.polylines.resize(kept);
  lw.polyline_lines.resize(kept);
  out->format = d.format;
  out->metadata = d.metadata;
  if (by_default == "conforming") out->metadata.emplace_back("constraints", "conforming");
  out->finish(d.item_offset);
  return out;
}

// The number of cells that the size h gives the domain (cells_for_cell_size_2()).
double domain_cells_for_size(const Domain& d, double h, std::optional<double> spacing_ratio) {
  py::gil_scoped_release release;
  return CVT_2::cells_for_cell_size_2(*d.triangulation(), h,
                                      spacing_ratio.value_or(CVT_2::default_spacing_ratio));
}

// The description's own points, numbered in Python after the points a call is given:
// domain_arrays()' vertices (a WKT, GeoJSON or shapely domain's ring and line points, each once,
// in order of first appearance), then a WKT or GeoJSON domain's generators (a .poly's are among
// its vertices).
std::vector<Point_2> own_points(const Domain& d) {
  if (const auto* p = std::get_if<0>(&d.data.description)) return p->vertices;
  std::vector<Point_2> out;
  std::set<Point_2> seen;
  for (const Point_2& p : d.segment_ends)
    if (seen.insert(p).second) out.push_back(p);
  const auto& generators = std::get<1>(d.data.description).points;
  out.insert(out.end(), generators.begin(), generators.end());
  return out;
}

// --- densities ---------------------------------------------------------------------------------

// A Python callable as a density evaluated in batches (DensityFunction_2::evaluate()): it gets
// an array (m, 2) of points and returns m values, with the GIL held only while it runs. It holds
// the callable by address (the caller keeps it), so that copies of it, made without the GIL, do
// not touch reference counts. With `square_root`, the square roots of its values: the sampling
// density of random points that start a CVT of that density close to its result.
struct Python_density {
  const py::object* function;
  bool square_root = false;

  double operator()(const Point_2& p) const {
    std::vector<double> values;
    evaluate(std::vector<Point_2>{p}, values);
    return values[0];
  }

  void evaluate(const std::vector<Point_2>& points, std::vector<double>& values) const {
    const py::gil_scoped_acquire gil;
    const py::ssize_t n = py::ssize_t(points.size());
    values.resize(points.size());
    {
      Array xy({n, py::ssize_t(2)});
      auto w = xy.mutable_unchecked<2>();
      for (py::ssize_t i = 0; i < n; ++i)
        w(i, 0) = points[std::size_t(i)].x(), w(i, 1) = points[std::size_t(i)].y();
      const py::object result = (*function)(xy);
      if (py::isinstance<py::array>(result) &&
          !holds_real_numbers(py::reinterpret_borrow<py::array>(result)))
        throw py::type_error("the density must return an array of numbers, not an array of " +
                             std::string(py::str(result.attr("dtype"))));
      const Array a = Array::ensure(result);
      if (!a)
        throw py::type_error("the density must return an array of numbers, not " +
                             std::string(py::str(py::type::of(result).attr("__name__"))));
      if (a.ndim() != 1 || a.shape(0) != n)
        throw py::value_error(
            "the density returned shape " + shape_of(a) + " for " + std::to_string(n) +
            " points: it must return one value a point, shape (" + std::to_string(n) + ",)");
      std::copy(a.data(), a.data() + n, values.begin());
    }
    if (!square_root) return;  // the optimizer checks the values itself
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (!(values[i] > 0) || !std::isfinite(values[i]))
        throw CVT_2::internal::bad_density_error(values[i], points[i]);
      values[i] = std::sqrt(values[i]);
    }
  }
};

// The density option: None or "uniform", "lipschitz" (with k and the boundary size), or a
// callable.
struct Density_choice {
  enum Kind { UNIFORM, LIPSCHITZ, CALLABLE } kind = UNIFORM;
  double k = 0.1;
  std::optional<double> boundary_size;
  const py::object* function = nullptr;

  Density_choice(const py::object& density, double lipschitz_k, const py::object& size) {
    if (density.is_none()) {
    } else if (py::isinstance<py::str>(density)) {
      const std::string name = density.cast<std::string>();
      if (name != "lipschitz" && name != "uniform")
        throw py::value_error("density must be None, 'uniform', 'lipschitz' or a callable, not '" +
                              name + "'");
      if (name == "lipschitz") kind = LIPSCHITZ;
    } else if (PyCallable_Check(density.ptr())) {
      kind = CALLABLE;
      function = &density;
    } else {
      throw py::type_error("density must be None, 'uniform', 'lipschitz' or a callable");
    }
    if (kind == LIPSCHITZ) {
      if (!(lipschitz_k > 0) || !std::isfinite(lipschitz_k))
        throw py::value_error("lipschitz_k must be positive and finite, not " +
                              std::to_string(lipschitz_k));
      k = lipschitz_k;
      if (!size.is_none()) {
        boundary_size = size.cast<double>();
        if (!(*boundary_size > 0) || !std::isfinite(*boundary_size))
          throw py::value_error("boundary_size must be positive and finite, not " +
                                std::to_string(*boundary_size));
      }
    } else if (!size.is_none()) {
      throw py::value_error("boundary_size needs density='lipschitz'");
    }
  }

  // The sizing of cvt2's --density lipschitz, from the triangulation before generators are
  // inserted: its default sizes are the input's boundary edges.
  std::optional<Sizing> sizing(const CDT& cdt) const {
    std::optional<Sizing> s;
    if (kind == LIPSCHITZ) s.emplace(cdt, k, boundary_size);
    return s;
  }

  // `count` random points in the domain of `cdt` that follow this density, as cvt2 draws them
  // (`np`: the seed, by_region); `s` is sizing(cdt).
  template <class NP>
  std::vector<Point_2> random_points(const CDT& cdt, const std::optional<Sizing>& s,
                                     std::size_t count, const NP& np) const {
    if (kind == LIPSCHITZ)
      return CVT_2::random_points_in_domain_2(cdt, count, np.sizing_field(std::cref(*s)));
    if (kind == CALLABLE)
      return CVT_2::random_points_in_domain_2(cdt, count,
                                              np.density(Python_density{function, true}));
    return CVT_2::random_points_in_domain_2(cdt, count, np);
  }
};

std::size_t checked_count(std::int64_t n, const char* name) {
  if (n < 0) throw py::value_error(std::string(name) + " must be >= 0, not " + std::to_string(n));
  return std::size_t(n);
}

Array random_points(const Domain& domain, std::int64_t n, std::uint64_t seed,
                    const py::object& density, double lipschitz_k, const py::object& boundary_size,
                    bool by_region) {
  const std::size_t count = checked_count(n, "n");
  const Density_choice choice(density, lipschitz_k, boundary_size);
  std::vector<Point_2> points;
  try {
    py::gil_scoped_release release;
    const CVT_2::internal::Interrupt_scope interruptible{Signal_check()};
    const auto cdt = domain.triangulation();
    const std::optional<Sizing> sizing = choice.sizing(*cdt);
    // dealt to the regions for cells=, and under a density as cvt2 -n deals them
    const bool dealt = by_region || choice.kind != Density_choice::UNIFORM;
    if (count > 0)
      points = choice.random_points(*cdt, sizing, count,
                                    CVT_2::parameters::random_seed(seed).by_region(dealt));
  } catch (const std::exception& e) {  // the points' reserve(): length_error or bad_alloc
    if (!dynamic_cast<const std::length_error*>(&e) && !dynamic_cast<const std::bad_alloc*>(&e))
      throw;
    PyErr_SetString(PyExc_MemoryError,
                    ("not enough memory for n = " + std::to_string(count) + " points").c_str());
    throw py::error_already_set();
  }
  return to_array(points);
}

// --- the diagram -------------------------------------------------------------------------------

// The input segments of a domain whose vertices a ConstraintEditor moves, as pieces. Outputs
// name a segment by walking from one end to the other along the constrained edges on it
// (internal::for_each_edge_on_input_segments()); a move of an end, or of a vertex inserted on
// it (a crack's end, a generator a moved wall passed through), bends it there, and the walk
// would stop. So before a move the pieces through p or ending at p are cut at the vertices on
// them, and each piece's ends then follow the moves.
struct Segment_pieces {
  std::vector<Point_2> ends;          // two a piece
  std::vector<std::int64_t> segment;  // the input segment of each piece

  explicit Segment_pieces(const std::vector<Point_2>& segment_ends) : ends(segment_ends) {
    for (std::size_t i = 0; i < ends.size() / 2; ++i) segment.push_back(std::int64_t(i));
  }

  void split_at(const CDT& cdt, const Point_2& p) {
    std::vector<Point_2> cut;
    std::vector<std::int64_t> of;
    for (std::size_t k = 0; k < segment.size(); ++k) {
      const Point_2 a = ends[2 * k], b = ends[2 * k + 1];
      std::vector<Point_2> chain{a};
      if (a == p || b == p || CVT_2::internal::is_bent_onto(p, a, a, b))  // on it, or snapped
        CVT_2::internal::for_each_edge_on_input_segments(
            cdt, std::vector<Point_2>{a, b},
            [&](CDT::Vertex_handle, CDT::Vertex_handle w, std::size_t) {
              chain.push_back(w->point());
            });
      if (chain.back() != b) chain.assign({a, b});  // not walked to its end: left as it is
      for (std::size_t j = 0; j + 1 < chain.size(); ++j)
        cut.push_back(chain[j]), cut.push_back(chain[j + 1]), of.push_back(segment[k]);
    }
    ends.swap(cut);
    segment.swap(of);
  }
};

// A bounded Voronoi diagram as a mesh, with the arrays Python reads, computed once. It keeps
// the triangulation, which the writers read through the mesh's generators.
struct Diagram {
  std::shared_ptr<CDT> cdt;
  std::shared_ptr<const Domain> domain;
  std::unique_ptr<BVD> bvd;
  std::unique_ptr<Mesh> mesh;
  std::vector<double> points, vertices, areas, centroids;
  std::vector<std::uint8_t> constrained, ridge_boundary, vertex_kinds;
  std::vector<std::int64_t> ridge_points, ridge_vertices, ridge_constraint;
  std::vector<std::int64_t> ridge_edit_constraint;  // a ConstraintEditor's snapshots only
  std::vector<std::string> notes;                   // the points moved onto the boundary
  std::optional<std::vector<Point_2>> given;  // the points of bounded_voronoi(), in their order
  // The input segments' ends where they are: the domain's; or, as a ConstraintEditor moved
  // them, the ends of their pieces (Segment_pieces) and the segment of each.
  std::vector<Point_2> segment_ends;
  std::vector<std::int64_t> segment_of_piece;  // empty: the pieces are the segments

  Diagram(std::shared_ptr<CDT> t, std::shared_ptr<const Domain> d, unsigned threads,
          const Segment_pieces* moved = nullptr)
      : cdt(std::move(t)),
        domain(std::move(d)),
        segment_ends(moved ? moved->ends : domain->segment_ends),
        segment_of_piece(moved ? moved->segment : std::vector<std::int64_t>()) {
    bvd = std::make_unique<BVD>(*cdt);
    mesh = std::make_unique<Mesh>(*bvd, threads);
    const std::vector<std::int64_t> input = input_segments();
    const Mesh& m = *mesh;
    const std::size_t n = m.number_of_cells();
    for (std::size_t k = 0; k < n; ++k) {
      CVT_2::internal::poll_interrupt_sometimes();
      const Point_2& p = m.generator(k)->point();
      points.push_back(p.x()), points.push_back(p.y());
      constrained.push_back(m.is_constrained(k) ? 1 : 0);
      areas.push_back(m.area(k));
      const Point_2 c = m.centroid(k);
      centroids.push_back(c.x()), centroids.push_back(c.y());
    }
    for (const Point_2& p : m.points()) vertices.push_back(p.x()), vertices.push_back(p.y());
    for (std::size_t i = 0; i < m.number_of_vertices(); ++i)
      vertex_kinds.push_back(std::uint8_t(m.vertex_type(i)));
    for (const Mesh::Edge& e : m.edges()) {
      CVT_2::internal::poll_interrupt_sometimes();
      const bool boundary = e.cells[1] == Mesh::none;
      ridge_points.push_back(e.cells[0]);
      ridge_points.push_back(boundary ? e.cells[0] : e.cells[1]);
      ridge_vertices.push_back(e.vertices[0]);
      ridge_vertices.push_back(e.vertices[1]);
      ridge_boundary.push_back(boundary ? 1 : 0);
      ridge_constraint.push_back(e.constraint == Mesh::none ? -1 : input[e.constraint]);
    }
  }

  // Where the given points and the domain's own (own_points()), numbered in this order, went:
  // `point_region`, the cell of each (-1: none); `input_index`, the first given point of each
  // cell (-1: none); `duplicates`, pairs (i, j) of points in one cell, j the first there.
  py::dict rows() const {
    std::vector<Point_2> all = given.value();  // bounded_voronoi()'s diagrams only
    const std::vector<Point_2> own = own_points(*domain);
    all.insert(all.end(), own.begin(), own.end());
    std::vector<std::int64_t> region(all.size()), input(mesh->number_of_cells(), -1), duplicates;
    {
      py::gil_scoped_release release;
      const CVT_2::internal::Interrupt_scope interruptible{Signal_check()};
      const std::vector<CDT::Vertex_handle> v = vertices_of(*cdt, all);
      std::vector<std::int64_t> first(mesh->number_of_cells(), -1);
      for (std::size_t i = 0; i < all.size(); ++i) {
        if (v[i] == CDT::Vertex_handle() || !bvd->has_cell(v[i])) {
          region[i] = -1;
          continue;
        }
        const std::size_t k = mesh->cell_of(v[i]);
        region[i] = std::int64_t(k);
        if (first[k] >= 0) {
          duplicates.push_back(std::int64_t(i)), duplicates.push_back(first[k]);
          continue;
        }
        first[k] = std::int64_t(i);
        if (i < given->size()) input[k] = std::int64_t(i);
      }
    }
    py::dict out;
    out["point_region"] = to_array(region);
    out["input_index"] = to_array(input);
    out["duplicates"] = to_array(duplicates, 2);
    return out;
  }

  // For each constraint of the mesh, the input segment it lies on, and that segment's item.
  std::vector<std::int64_t> input_segments() const {
    std::vector<std::int64_t> input =
        CVT_2::internal::input_segments_of_constraints(*cdt, *mesh, segment_ends);
    if (!segment_of_piece.empty())
      for (std::int64_t& i : input)
        if (i >= 0) i = segment_of_piece[std::size_t(i)];
    return input;
  }
  std::vector<std::int64_t> input_items() const {
    std::vector<std::int64_t> items = input_segments();
    for (std::int64_t& i : items)
      if (i >= 0) i = domain->segment_items[std::size_t(i)];
    return items;
  }

  // The mesh as a simulation grid: inner constraints barriers or slits, by the writer's choice
  // or a GeoJSON feature's "kind" where it says one.
  Grid grid(bool barriers) const {
    if (!domain->has_kinds()) return Grid(*mesh, barriers ? CVT_2::BARRIER : CVT_2::SLIT);
    const std::vector<std::int64_t> items = input_items();
    const std::string by_default = barriers ? "barrier" : "slit";
    return Grid(*mesh, [&](Grid::Index c) {
      return domain->kind(c < items.size() ? items[c] : -1, by_default) == "barrier";
    });
  }
  // Whether the writers need the grid: some constraint is a barrier.
  bool any_barrier(bool barriers) const {
    if (barriers) return true;
    const auto* w = std::get_if<1>(&domain->data.description);
    return w != nullptr &&
           std::count(w->item_kinds.begin(), w->item_kinds.end(), std::string("barrier")) > 0;
  }

  // Cells as lists of vertex indices: the cycles (slits walked there and back), the outlines
  // (slits dropped, lobes joined at the generator), or the valid polygons (a list of rings each).
  py::list cycles() const {
    py::list out;
    for (std::size_t k = 0; k < mesh->number_of_cells(); ++k) {
      py::list c;
      for (const Index i : mesh->cell(k)) c.append(i);
      out.append(c);
    }
    return out;
  }
  py::list outlines() const {
    py::list out;
    for (std::size_t k = 0; k < mesh->number_of_cells(); ++k) {
      py::list c;
      for (const Index i : mesh->outline(k)) c.append(i);
      out.append(c);
    }
    return out;
  }
  py::list polygons() const {
    py::list out;
    for (std::size_t k = 0; k < mesh->number_of_cells(); ++k) {
      py::list rings;
      for (const auto& ring : mesh->polygons(k)) {
        std::vector<std::int64_t> r(ring.begin(), ring.end());
        rings.append(to_array(r));
      }
      out.append(rings);
    }
    return out;
  }

  // The cells as one WKB GeometryCollection: what shapely reads in one call.
  py::bytes wkb() const {
    std::ostringstream os(std::ios::binary);
    {
      py::gil_scoped_release release;
      CVT_2::IO::write_wkb(os, *mesh);
    }
    return py::bytes(os.str());
  }

  template <class Writer>
  // As cvt2 writes: into path.tmp, renamed once complete, so that a failed writer (a bad
  // argument, a full disk) leaves an earlier file as it was.
  void write(const std::string& path, Writer writer) const {
    py::gil_scoped_release release;
    const std::string tmp = path + ".tmp";
    std::ofstream os(tmp, std::ios::binary);
    if (!os) throw std::ios_base::failure("cannot write '" + path + "'");
    try {
      writer(os);
      os.close();
      if (!os) throw std::ios_base::failure("error while writing '" + path + "'");
      if (std::rename(tmp.c_str(), path.c_str()) != 0)
        throw std::ios_base::failure("cannot write '" + path + "'");
    } catch (...) {
      os.close();
      std::remove(tmp.c_str());
      throw;
    }
  }
};

std::shared_ptr<Diagram> bounded_voronoi(const std::shared_ptr<const Domain>& domain,
                                         py::handle points_object, std::int64_t threads,
                                         std::optional<double> boundary_tolerance) {
  std::vector<Point_2> points = to_points(points_object, "points");
  const unsigned t = unsigned(checked_count(threads, "threads"));
  py::gil_scoped_release release;
  const CVT_2::internal::Interrupt_scope interruptible{Signal_check()};
  std::shared_ptr<CDT> cdt = domain->triangulation();
  std::vector<Point_2> where;
  std::vector<std::string> notes =
      insert_points(*cdt, points, "points", boundary_tolerance, &where);
  auto diagram = std::make_shared<Diagram>(std::move(cdt), domain, t);
  diagram->notes = std::move(notes);
  diagram->given = std::move(where);  // for point_region, found when asked for
  return diagram;
}

// --- constraint edits ---------------------------------------------------------------------------

// A diagram whose constraints change (Constraint_editor_2): each edit returns its report, with
// cells named by their generators' coordinates (a snapshot's numbering changes with each edit).
struct Editing {
  std::shared_ptr<const Domain> domain;
  std::shared_ptr<CDT> cdt;
  std::unique_ptr<BVD> bvd;
  std::unique_ptr<CVT_2::Constraint_editor_2<CDT>> editor;
  std::vector<Point_2> given;  // where the points given are, as relax() and move() move them
  Segment_pieces segments;     // the domain's input segments, as move() moves them
  std::vector<std::string> notes;

  Editing(const std::shared_ptr<const Domain>& d, py::handle points_object,
          std::optional<double> boundary_tolerance)
      : domain(d), segments(d->segment_ends) {
    cdt = domain->triangulation();
    notes = insert_points(*cdt, to_points(points_object, "points"), "points", boundary_tolerance,
                          &given);
    bvd = std::make_unique<BVD>(*cdt);
    editor = std::make_unique<CVT_2::Constraint_editor_2<CDT>>(*cdt, *bvd);
    editor->carry_weights(true);
  }

  py::dict report() const {
    const auto& r = editor->report();
    std::vector<Point_2> changed, added;
    for (const auto v : r.changed_cells) changed.push_back(v->point());
    for (const auto v : r.new_vertices) added.push_back(v->point());
    py::dict out;
    out["changed_cells"] = to_array(changed);
    out["new_vertices"] = to_array(added);
    out["retagged_faces"] = r.retagged_faces;
    // the carried weights in compressed rows: new vertex k's in [indptr[k], indptr[k + 1])
    std::vector<std::int64_t> indptr{0};
    std::vector<Point_2> nodes;
    std::vector<double> weights;
    for (const auto& row : r.carried_weights) {
      for (const auto& [v, w] : row) nodes.push_back(v->point()), weights.push_back(w);
      indptr.push_back(std::int64_t(nodes.size()));
    }
    out["weights_indptr"] = to_array(indptr);
    out["weights_nodes"] = to_array(nodes);
    out["weights"] = to_array(weights);
    // the same by lip, for the new vertices with two lips or more
    std::vector<Point_2> lip_vertex;
    std::vector<std::int64_t> lip, lip_indptr{0};
    nodes.clear();
    weights.clear();
    for (const auto& c : r.carried_lips) {
      lip_vertex.push_back(c.vertex->point());
      lip.push_back(c.lip);
      for (const auto& [v, w] : c.weights) nodes.push_back(v->point()), weights.push_back(w);
      lip_indptr.push_back(std::int64_t(nodes.size()));
    }
    out["lip_vertices"] = to_array(lip_vertex);
    out["lips"] = to_array(lip);
    out["lip_weights_indptr"] = to_array(lip_indptr);
    out["lip_weights_nodes"] = to_array(nodes);
    out["lip_weights"] = to_array(weights);
    return out;
  }
  std::int64_t insert(py::handle points_object) {
    return std::int64_t(editor->insert_constraint(to_points(points_object, "points")));
  }
  std::size_t id(std::int64_t id) const {
    if (id < 0) throw CVT_2::Domain_error("there is no constraint " + std::to_string(id));
    return std::size_t(id);
  }
  Point_2 point(py::handle object, const std::string& what) const {
    // numpy raises for what it cannot read; then one row of two numbers, finite
    const py::object rows =
        py::module_::import("numpy").attr("asarray")(object, "float64").attr("reshape")(-1, 2);
    const std::vector<Point_2> p = to_points(rows, what);
    if (p.size() != 1) throw py::value_error(what + " must be one point (x, y)");
    if (!CVT_2::internal::is_valid_point(p[0]))
      throw CVT_2::Domain_error(
          what + ": " +
          CVT_2::internal::invalid_point_message("point " + CVT_2::internal::to_string(p[0])));
    return p[0];
  }
  py::dict extend(std::int64_t c, py::handle tip, double spacing) {
    if (!(spacing >= 0) || !std::isfinite(spacing))
      throw py::value_error("spacing must be a finite number >= 0");
    editor->extend_constraint(id(c), point(tip, "tip"), spacing);
    return report();
  }
  // Lloyd iterations on the free generators within `rings` rings of the last edit's changed
  // cells (lloyd_optimize_2 with `region`); the generators that moved, from and to.
  py::dict relax(std::int64_t rings, std::int64_t iterations) {
    std::vector<Point_2> region, from, to;
    std::vector<CDT::Vertex_handle> seen;
    for (const auto v : editor->report().changed_cells) region.push_back(v->point());
    const auto np = CVT_2::parameters::region(region).region_rings(rings).move_ratio_bound(0);
    const auto movable = CVT_2::internal::region_vertices(*cdt, np);
    for (const auto v : *movable) seen.push_back(v), from.push_back(v->point());
    CVT_2::lloyd_optimize_2(*cdt, np.number_of_iterations(iterations));
    py::dict out;
    std::vector<Point_2> moved_from, moved_to;
    for (std::size_t k = 0; k < seen.size(); ++k)
      if (seen[k]->point() != from[k])
        moved_from.push_back(from[k]), moved_to.push_back(seen[k]->point());
    follow(given, moved_from, moved_to);
    out["moved_from"] = to_array(moved_from);
    out["moved_to"] = to_array(moved_to);
    return out;
  }
  // The `points` that were at `from[k]` are now at `to[k]`: the snapshots' point_region and
  // ridge_constraint follow the points given and the input segments' ends.
  static void follow(std::vector<Point_2>& points, const std::vector<Point_2>& from,
                     const std::vector<Point_2>& to) {
    if (from.empty()) return;
    std::map<std::pair<double, double>, Point_2> moved;
    for (std::size_t k = 0; k < from.size(); ++k)
      moved.emplace(std::pair(from[k].x(), from[k].y()), to[k]);
    for (Point_2& p : points) {
      const auto it = moved.find(std::pair(p.x(), p.y()));
      if (it != moved.end()) p = it->second;
    }
  }
  py::dict move(py::handle from, py::handle to) {
    const Point_2 p = point(from, "vertex"), q = point(to, "to");
    CDT::Locate_type lt;
    int li;
    const CDT::Face_handle f = cdt->locate(p, lt, li);
    if (lt != CDT::VERTEX)
      throw CVT_2::Domain_error("move_constrained_vertex: no vertex at " +
                                CVT_2::internal::to_string(p));
    segments.split_at(*cdt, p);  // a segment bends at p, or at a vertex inserted on it
    // the vertex where it went (a new one if it was removed and inserted there)
    const Point_2 now = editor->move_constrained_vertex(f->vertex(li), q)->point();
    follow(given, {p}, {now});
    follow(segments.ends, {p}, {now});
    return report();
  }
  py::dict remove(std::int64_t c) {
    editor->remove_constraint(id(c));
    return report();
  }
  Array constraint_vertices(std::int64_t c) const {
    std::vector<Point_2> p;
    for (const auto v : editor->vertices_in_constraint(id(c))) p.push_back(v->point());
    return to_array(p);
  }
  // A snapshot: the diagram of a copy of the triangulation, which later edits leave alone.
  std::shared_ptr<Diagram> diagram(std::int64_t threads) const {
    const unsigned t = unsigned(checked_count(threads, "threads"));
    auto copy = std::make_shared<CDT>(*cdt);
    auto d = std::make_shared<Diagram>(std::move(copy), domain, t, &segments);
    d->given = given;
    d->notes = notes;  // the points moved onto the boundary, as bounded_voronoi() says
    // the constraints inserted here by their ids, walked as the input segments are
    std::vector<Point_2> ends;
    std::vector<std::int64_t> ids;
    for (std::size_t c = 0; c < editor->number_of_constraints(); ++c) {
      if (editor->is_removed(c)) continue;
      const auto& chain = editor->vertices_in_constraint(c);
      for (std::size_t k = 0; k + 1 < chain.size(); ++k)
        ends.push_back(chain[k]->point()), ends.push_back(chain[k + 1]->point()),
            ids.push_back(std::int64_t(c));
    }
    const std::vector<std::int64_t> on =
        CVT_2::internal::input_segments_of_constraints(*d->cdt, *d->mesh, ends);
    for (const Mesh::Edge& e : d->mesh->edges())
      d->ridge_edit_constraint.push_back(e.constraint == Mesh::none || on[e.constraint] < 0
                                             ? -1
                                             : ids[std::size_t(on[e.constraint])]);
    return d;
  }
};

// --- natural-neighbour coordinates -------------------------------------------------------------

// The natural-neighbour coordinates of `queries` on the bounded Voronoi diagram of the domain and
// `nodes`, as natural_neighbor_matrix_2() computes them, in compressed rows (the arrays of
// scipy.sparse.csr_matrix) whose columns are the nodes, then the domain's own points
// (own_points()): a generator's weight goes to the first of them at it.
py::dict natural_neighbours(const std::shared_ptr<const Domain>& domain, py::handle nodes_object,
                            py::handle queries_object, const std::string& method,
                            std::int64_t threads, std::optional<double> boundary_tolerance,
                            bool lips) {
  std::vector<Point_2> nodes = to_points(nodes_object, "nodes");
  const std::vector<Point_2> queries = to_points(queries_object, "queries");
  if (method != "sibson" && method != "laplace")
    throw py::value_error("method must be 'sibson' or 'laplace', not '" + method + "'");
  for (std::size_t k = 0; k < queries.size(); ++k)
    if (!CVT_2::internal::is_valid_point(queries[k]))
      throw CVT_2::Domain_error("queries[" + std::to_string(k) + "]: " +
                                    CVT_2::internal::invalid_point_message(
                                        "query " + CVT_2::internal::to_string(queries[k])),
                                k);
  const unsigned t = unsigned(checked_count(threads, "threads"));
  std::vector<std::int64_t> indptr{0}, indices;
  std::vector<double> data;
  std::vector<std::uint8_t> inside;
  std::vector<std::int64_t> lip_columns;  // the column of the node each lip column splits
  std::size_t columns = 0;
  {
    py::gil_scoped_release release;
    const CVT_2::internal::Interrupt_scope interruptible{Signal_check()};
    const std::shared_ptr<CDT> cdt = domain->triangulation();
    std::vector<Point_2> where;
    insert_points(*cdt, nodes, "nodes", boundary_tolerance, &where);
    const BVD bvd(*cdt);
    const auto m =
        CVT_2::natural_neighbor_matrix_2(bvd, queries,
                                         CVT_2::parameters::natural_neighbor_method(
                                             method == "laplace" ? CVT_2::LAPLACE : CVT_2::SIBSON)
                                             .number_of_threads(t)
                                             .lips(lips));
    std::vector<Point_2> all = std::move(where);
    const std::vector<Point_2> own = own_points(*domain);
    all.insert(all.end(), own.begin(), own.end());
    columns = all.size();
    std::unordered_map<const void*, std::int64_t> column;
    {
      const std::vector<CDT::Vertex_handle> v = vertices_of(*cdt, all);
      column.reserve(v.size());
      for (std::size_t i = 0; i < v.size(); ++i)
        if (v[i] != CDT::Vertex_handle()) column.emplace(&*v[i], std::int64_t(i));
    }
    std::vector<std::int64_t> of_node(m.nodes.size());
    for (std::size_t j = 0; j < m.nodes.size(); ++j) {
      const auto it = column.find(&*m.nodes[j]);
      if (it == column.end())  // every vertex is a node or a point of the description
        throw std::logic_error("natural_neighbours: a generator that is no node");
      of_node[j] = it->second;
    }
    for (const std::size_t j : m.lip_nodes) {  // lip columns after all the others
      of_node.push_back(std::int64_t(columns + lip_columns.size()));
      lip_columns.push_back(of_node[j]);
    }
    std::vector<std::pair<std::int64_t, double>> row;
    indices.reserve(m.columns.size());
    data.reserve(m.values.size());
    for (std::size_t k = 0; k < queries.size(); ++k) {
      CVT_2::internal::poll_interrupt_sometimes();
      row.clear();
      for (std::size_t e = m.row_offsets[k]; e < m.row_offsets[k + 1]; ++e)
        row.emplace_back(of_node[m.columns[e]], m.values[e]);
      std::sort(row.begin(), row.end());  // distinct columns: by column
      for (const auto& [j, w] : row) indices.push_back(j), data.push_back(w);
      indptr.push_back(std::int64_t(indices.size()));
    }
    inside = m.inside;
  }
  py::dict out;
  out["indptr"] = to_array(indptr);
  out["indices"] = to_array(indices);
  out["data"] = to_array(data);
  out["shape"] = py::make_tuple(queries.size(), columns + lip_columns.size());
  out["inside"] = to_array(inside).attr("astype")("bool");
  out["lip_columns"] = to_array(lip_columns);
  return out;
}

// --- optimization ------------------------------------------------------------------------------

// What optimize() returns, with the optimized triangulation kept for its diagram.
struct Optimization {
  std::shared_ptr<CDT> cdt;
  std::shared_ptr<const Domain> domain;
  std::mutex mutex;  // one diagram built at a time: building one writes ids into the triangulation
  CVT_2::Optimization_result result;
  std::vector<Point_2> points;
  std::vector<std::uint8_t> constrained;
  std::vector<std::uint8_t> fixed;        // fixed_points and the conforming lines' pairs
  std::vector<std::int64_t> input_index;  // of each generator: its first input row, or -1
  std::vector<std::string> notes;         // the points moved onto the boundary, ...
  double density_response = std::numeric_limits<double>::quiet_NaN();  // density_response_2()
  bool redistributed = false;  // the points given replaced by points drawn from the density

  std::shared_ptr<Diagram> diagram(std::int64_t threads) {
    const unsigned t = unsigned(checked_count(threads, "threads"));
    py::gil_scoped_release release;
    const CVT_2::internal::Interrupt_scope interruptible{Signal_check()};
    const std::lock_guard<std::mutex> lock(mutex);
    return std::make_shared<Diagram>(cdt, domain, t);
  }
};

std::shared_ptr<Optimization> optimize(
    const std::shared_ptr<const Domain>& domain, py::handle points_object,
    const std::string& algorithm, const py::object& density, double move_ratio,
    std::int64_t max_iterations, double time_limit, std::int64_t threads,
    const py::object& callback, double lipschitz_k, const py::object& boundary_size,
    std::optional<double> boundary_tolerance, const py::object& fixed_object, bool slide,
    bool conforming, const std::string& redistribute, std::uint64_t seed,
    std::optional<std::int64_t> cells_asked, std::optional<double> size, double spacing_ratio) {
  if (slide && !domain->runs)
    throw py::value_error(
        "boundary='slide' needs a domain made by Domain.resample(): its vertices slide along the "
        "polylines it was resampled from");
  const std::vector<Point_2> points = to_points(points_object, "points");
  std::vector<Point_2> fixed =
      fixed_object.is_none() ? std::vector<Point_2>() : to_points(fixed_object, "fixed_points");
  if (algorithm != "lbfgs" && algorithm != "lloyd")
    throw py::value_error("algorithm must be 'lbfgs' or 'lloyd', not '" + algorithm + "'");
  if (redistribute != "auto" && redistribute != "always" && redistribute != "never")
    throw py::value_error("redistribute must be 'auto', True or False, not '" + redistribute + "'");
  if (!(move_ratio >= 0) || !std::isfinite(move_ratio))
    throw py::value_error("move_ratio must be a finite number >= 0, not " +
                          CVT_2::internal::number_to_string(move_ratio));
  if (!(time_limit >= 0) || std::isnan(time_limit))
    throw py::value_error("time_limit must be >= 0 seconds, not " + std::to_string(time_limit));
  const std::size_t iterations = checked_count(max_iterations, "max_iterations");
  const std::size_t thread_count = checked_count(threads, "threads");
  if (thread_count > 4096) throw py::value_error("threads must be at most 4096");
  if (!callback.is_none() && !PyCallable_Check(callback.ptr()))
    throw py::type_error("callback must be None or a callable");
  const Density_choice choice(density, lipschitz_k, boundary_size);
  auto out = std::make_shared<Optimization>();
  out->domain = domain;
  // The user's callback with the figures of a state; whether to go on.
  const auto call_back = [&callback](const CVT_2::Optimization_result& r) {
    py::dict info;
    info["iteration"] = r.number_of_iterations;
    info["evaluations"] = r.number_of_evaluations;
    info["energy"] = r.energy;
    info["max_move_ratio"] = r.max_move_ratio;
    info["mean_move_ratio"] = r.mean_move_ratio;
    info["seconds"] = r.seconds;
    const py::object go_on = callback(info);
    if (go_on.is_none()) return true;
    if (PyBool_Check(go_on.ptr()) ||
        py::isinstance(go_on, py::module_::import("numpy").attr("bool_")))
      return go_on.cast<bool>();
    throw py::type_error("the callback must return None, True or False, not " +
                         std::string(py::str(py::type::of(go_on).attr("__name__"))));
  };
  // At each state but the last (the library does not call it there): Ctrl-C, and the callback.
  const std::function<bool(const CVT_2::Optimization_result&)> progress =
      [&callback, &call_back](const CVT_2::Optimization_result& r) {
        const py::gil_scoped_acquire gil;
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        return callback.is_none() || call_back(r);
      };
  // Conforming lines: all with constraints="conforming", else those a GeoJSON "kind" names.
  std::vector<std::vector<Point_2>> lines;
  std::vector<std::int64_t> line_items;
  std::shared_ptr<Domain> lineless;
  if (domain->data.description.index() == 1)
    lineless =
        without_conforming_lines(*domain, conforming ? "conforming" : "slit", lines, line_items);
  if (lines.empty()) lineless = nullptr;
  if (conforming && !lineless)
    throw py::value_error(
        "constraints='conforming' makes the lines of a WKT, GeoJSON or shapely domain "
        "(LineStrings) conforming; this domain has none");
  if (lineless && slide)
    throw py::value_error(
        "boundary='slide' and conforming lines do not go together yet (the sliding vertices "
        "would not keep out of the lines' circles)");
  {
    py::gil_scoped_release release;
    const CVT_2::internal::Interrupt_scope interruptible{Signal_check()};
    std::shared_ptr<CDT> cdt = (lineless ? lineless : domain)->triangulation();
    const std::optional<Sizing> sizing = choice.sizing(*cdt);
    // cells= or size=: the count asked for, checked before any conforming site is placed
    const auto cells_wanted = [&] {
      const double wanted =
          cells_asked ? double(*cells_asked)
                      : std::round(CVT_2::cells_for_cell_size_2(*cdt, *size, spacing_ratio));
      const std::string asked = cells_asked ? "cells=" + std::to_string(*cells_asked)
                                            : "size=" + CVT_2::internal::number_text(*size) + " (" +
                                                  CVT_2::internal::number_text(wanted) + " cells)";
      if (!(wanted <= double(std::int64_t(1) << 53)))
        throw py::value_error(asked + " asks for too many cells");
      return std::pair(wanted, asked);
    };
    if (cells_asked || size) cells_wanted();
    std::vector<Point_2> where;  // of the points, as vertices_of() finds them below
    out->notes = insert_points(*cdt, points, "points", boundary_tolerance, &where);
    if (!fixed.empty()) {  // as cvt2 --fixed-points: inserted after the points
      const std::vector<std::string> notes = insert_points(*cdt, fixed, "fixed_points", {}, &fixed);
      out->notes.insert(out->notes.end(), notes.begin(), notes.end());
    }
    // The input row of each vertex (the first, for merged rows), kept as the vertices move.
    std::unordered_map<const void*, std::int64_t> row;
    {
      const std::vector<CDT::Vertex_handle> v = vertices_of(*cdt, where);
      row.reserve(v.size());
      for (std::size_t i = 0; i < v.size(); ++i)
        if (v[i] != CDT::Vertex_handle()) row.emplace(&*v[i], std::int64_t(i));
    }
    // As cvt2 --constraints conforming: the lines' pairs, fixed, at the cells' spacing.
    CVT_2::Conforming_disks<Point_2> disks;
    if (lineless) {
      // at the spacing of the cells asked for (cvt2 --cells, --size), else of those there are
      const std::size_t cells = cells_asked ? std::size_t(*cells_asked)
                                            : CVT_2::internal::number_of_vertices_in_domain(*cdt);
      std::size_t left_out = 0;
      // under a density, the size the cells take where the steps lie (cvt2's)
      const std::size_t count =
          cells_asked || size ? std::size_t(cells_wanted().first) : std::max<std::size_t>(cells, 1);
      const auto following = [&](const auto& np, const auto& size_at) {
        const double scale = CVT_2::cell_size_scale_2(*cdt, count, np);
        return CVT_2::insert_conforming_sites_2(
            *cdt, lines, [&](const Point_2& p) { return scale * size_at(p); }, disks, &left_out);
      };
      if (choice.kind == Density_choice::LIPSCHITZ) {
        lineless->conforming_pairs =
            following(CVT_2::parameters::sizing_field(std::cref(*sizing)),
                      [&](const Point_2& p) { return CGAL::to_double((*sizing)(p)); });
      } else if (choice.kind == Density_choice::CALLABLE) {
        const Python_density points_density{choice.function, true};  // sqrt(rho)
        lineless->conforming_pairs =
            following(CVT_2::parameters::density(points_density),
                      [&](const Point_2& p) { return 1 / std::sqrt(points_density(p)); });
      } else {
        const double spacing =
            size ? *size
                 : std::sqrt(2 * lineless->area /
                             (std::sqrt(3.0) * double(std::max<std::size_t>(cells, 1))));
        lineless->conforming_pairs =
            CVT_2::insert_conforming_sites_2(*cdt, lines, spacing, disks, &left_out);
      }
      lineless->conforming_items = line_items;
      for (const auto& p : lineless->conforming_pairs)
        fixed.push_back(p.left), fixed.push_back(p.right);
      const std::string note = CVT_2::internal::conforming_left_out_note(
          left_out, lineless->conforming_pairs, line_items);
      if (!note.empty()) out->notes.push_back(note);
      out->domain = lineless;
    }
    // cells= or size= (cvt2 --cells, --size): as many more drawn as make that many cells, the
    // points, the fixed ones and the conforming lines' counted.
    const bool counted = cells_asked || size;
    std::size_t to_draw = 0;
    if (counted) {
      const std::size_t present = CVT_2::internal::number_of_vertices_in_domain(*cdt);
      const auto [wanted, asked] = cells_wanted();
      if (wanted < double(present))
        throw py::value_error(asked + " asks for fewer cells than the " + std::to_string(present) +
                              " vertices of the domain and the points");
      to_draw = std::size_t(wanted) - present;
      // as cvt2 --cells: refused rather than killed after minutes of work
      const std::string shortfall =
          CVT_2::internal::memory_shortfall(double(to_draw), algorithm == "lbfgs");
      if (!shortfall.empty()) throw py::value_error(asked + ": " + shortfall);
    }
    // Points drawn as cvt2 draws them: none in the circles of conforming lines (drawn again in
    // their regions); with cells= or size=, or in place of generators redistributed, dealt to
    // the regions.
    const auto draw = [&](std::size_t count, bool dealt) {
      return choice.random_points(
          *cdt, sizing, count,
          CVT_2::parameters::random_seed(seed).by_region(dealt).keep_out(disks));
    };
    // As cvt2 --redistribute: with a density, the free generators given replaced by as many
    // drawn from it, always or if they do not follow it.
    // for the density's note (a density only): whether every free generator is drawn from it
    const bool none_given = choice.kind != Density_choice::UNIFORM &&
                            CVT_2::internal::movable_generators(*cdt, fixed).empty();
    if (redistribute == "always" && choice.kind == Density_choice::UNIFORM)
      out->notes.push_back(
          "redistribute=True: the density is uniform: the generators given are kept");
    if (redistribute != "never" && choice.kind != Density_choice::UNIFORM) {
      const bool always = redistribute == "always";
      CVT_2::Density_response response;
      const std::vector<CDT::Vertex_handle> given =
          choice.kind == Density_choice::LIPSCHITZ
              ? CVT_2::generators_to_redistribute_2(
                    *cdt, CVT_2::make_sizing_field_density_2<K>(*sizing), fixed, always, &response)
              : CVT_2::generators_to_redistribute_2(*cdt, Python_density{choice.function, false},
                                                    fixed, always, &response);
      if (!given.empty()) {
        for (const auto v : given) row.erase(&*v);  // before their addresses may be reused
        CVT_2::remove_generators_2(*cdt, given);
        if (counted)  // drawn with the others, below
          to_draw += given.size();
        else
          CVT_2::insert_generators_2(*cdt, draw(given.size(), true));
        out->redistributed = true;
        out->notes.push_back("the " + std::to_string(given.size()) +
                             " free generators (the points given and the domain's own) " +
                             (redistribute == "auto"
                                  ? "do not follow the density (" +
                                        CVT_2::internal::density_response_reason(response) + ")"
                                  : std::string("are redistributed (redistribute=True)")) +
                             ": replaced by as many drawn from the density (redistribute=False "
                             "keeps them)");
      }
    }
    if (to_draw > 0) CVT_2::insert_generators_2(*cdt, draw(to_draw, counted));
    std::optional<CVT_2::Sliding_runs_2<CDT>> runs;
    if (slide) {
      runs.emplace(*domain->runs);
      runs->relocate(*cdt);
    }
    // As cvt2 runs it.
    const auto np = CVT_2::parameters::number_of_iterations(iterations)
                        .move_ratio_bound(move_ratio)
                        .maximum_running_time(time_limit)
                        .number_of_threads(unsigned(thread_count))
                        .callback(progress)
                        .fixed_points(fixed)
                        .keep_out(disks)
                        .sliding_runs(runs ? &*runs : nullptr);
    const auto run = [&](const auto& parameters) {
      return algorithm == "lbfgs" ? CVT_2::lbfgs_optimize_2(*cdt, parameters)
                                  : CVT_2::lloyd_optimize_2(*cdt, parameters);
    };
    std::optional<CVT_2::Slid_vertices_2<CDT>> slid;  // where they were
    if (slide) slid.emplace(*cdt);
    if (choice.kind == Density_choice::LIPSCHITZ)
      out->result = run(np.sizing_field(*sizing));
    else if (choice.kind == Density_choice::CALLABLE)
      out->result = run(np.density(Python_density{choice.function, false}));
    else
      out->result = run(np);
    // Every generator in the order of cvt2's --points-out.
    const BVD bvd(*cdt);
    const std::set<Point_2> held(fixed.begin(), fixed.end());  // where they are, and stay
    bvd.for_each_cell([&](CDT::Vertex_handle v, const auto&) {
      out->points.push_back(v->point());
      out->constrained.push_back(bvd.is_free(v) ? 0 : 1);
      out->fixed.push_back(bvd.is_free(v) && held.count(v->point()) != 0 ? 1 : 0);
      const auto it = row.find(&*v);
      out->input_index.push_back(it == row.end() ? -1 : it->second);
    });
    out->density_response = out->result.density_response.slope;
    const std::string note = CVT_2::internal::density_response_note(
        out->result.density_response, out->redistributed || none_given);
    if (!note.empty()) out->notes.push_back(note);
    const std::string inside = CVT_2::internal::conforming_disks_note(*cdt, disks);
    if (!inside.empty()) out->notes.push_back(inside);  // as cvt2 says it
    if (slide) out->domain = slid_domain(*domain, *cdt, *runs, *slid);
    out->cdt = std::move(cdt);
  }
  // The final state, which the callback has not seen unless it stopped the run there.
  if (!callback.is_none() && out->result.stop_reason != CVT_2::CALLBACK_REQUESTED_STOP)
    call_back(out->result);
  return out;
}

#ifdef CVT_2_MODULE_BENCHMARKS
// The benchmark's C++ lambda: the density the benchmark's numpy callback computes,
// 1 + a exp(-|p - c|^2 / w), in Lloyd iteration as optimize() runs it.
std::shared_ptr<Optimization> optimize_lambda_density(const std::shared_ptr<const Domain>& domain,
                                                      py::handle points_object,
                                                      std::int64_t max_iterations,
                                                      double move_ratio, std::int64_t threads,
                                                      double a, double cx, double cy, double w) {
  const std::vector<Point_2> points = to_points(points_object, "points");
  auto out = std::make_shared<Optimization>();
  out->domain = domain;
  py::gil_scoped_release release;
  std::shared_ptr<CDT> cdt = domain->triangulation();
  insert_points(*cdt, points, "points");
  const auto rho = [=](const Point_2& p) {
    const double dx = p.x() - cx, dy = p.y() - cy;
    return 1 + a * std::exp(-(dx * dx + dy * dy) / w);
  };
  out->result = CVT_2::lloyd_optimize_2(
      *cdt, CVT_2::parameters::number_of_iterations(checked_count(max_iterations, "iterations"))
                .move_ratio_bound(move_ratio)
                .number_of_threads(unsigned(checked_count(threads, "threads")))
                .density(rho));
  out->cdt = std::move(cdt);
  return out;
}
#endif

}  // namespace

PYBIND11_MODULE(_cvt2, m) {
  m.doc() = "The compiled part of cvt2; use the cvt2 package, which documents it.";
  m.attr("__version__") = CVT_2_VERSION_STRING;
  parse_error_type = PyErr_NewException("cvt2.ParseError", PyExc_ValueError, nullptr);
  domain_error_type = PyErr_NewException("cvt2.DomainError", PyExc_ValueError, nullptr);
  m.add_object("ParseError", py::handle(parse_error_type));
  m.add_object("DomainError", py::handle(domain_error_type));
  py::register_exception_translator(&translate_exception);

  py::class_<Domain, std::shared_ptr<Domain>>(m, "Domain")
      .def_static("from_file", &domain_from_file, py::arg("path"))
      .def_static("from_arrays", &domain_from_arrays, py::arg("vertices"), py::arg("segments"),
                  py::arg("holes"))
      .def_static("from_shapely", &domain_from_shapely, py::arg("polygons"), py::arg("lines"),
                  py::arg("line_items"))
      .def_property_readonly("format", [](const Domain& d) { return d.format; })
      .def_property_readonly("source", [](const Domain& d) { return d.data.file.source; })
      .def_property_readonly("area", [](const Domain& d) { return d.area; })
      .def_property_readonly("own_cells", [](const Domain& d) { return d.own_cells; })
      .def_property_readonly("metadata", [](const Domain& d) { return d.metadata; })
      .def_property_readonly("has_kinds", &Domain::has_kinds)
      .def_property_readonly("bounds",
                             [](const Domain& d) {
                               return py::make_tuple(d.bounds[0], d.bounds[1], d.bounds[2],
                                                     d.bounds[3]);
                             })
      .def_property_readonly("notes", [](const Domain& d) { return d.notes; })
      .def("arrays", &domain_arrays)
      .def("resample", &domain_resample, py::arg("cells"), py::arg("size"),
           py::arg("deviation_bound"), py::arg("corner_angle"), py::arg("fixed_points"),
           py::arg("minimum_ring_area"), py::arg("spacing_ratio"))
      .def("cells_for_size", &domain_cells_for_size, py::arg("size"), py::arg("spacing_ratio"));

  py::class_<Diagram, std::shared_ptr<Diagram>>(m, "Diagram")
      .def_property_readonly("points", [](const Diagram& d) { return to_array(d.points, 2); })
      .def_property_readonly(
          "constrained",
          [](const Diagram& d) { return to_array(d.constrained).attr("astype")("bool"); })
      .def_property_readonly("vertices", [](const Diagram& d) { return to_array(d.vertices, 2); })
      .def_property_readonly("vertex_kinds",
                             [](const Diagram& d) { return to_array(d.vertex_kinds); })
      .def_property_readonly("areas", [](const Diagram& d) { return to_array(d.areas); })
      .def_property_readonly("centroids", [](const Diagram& d) { return to_array(d.centroids, 2); })
      .def_property_readonly("ridge_points",
                             [](const Diagram& d) { return to_array(d.ridge_points, 2); })
      .def_property_readonly("ridge_vertices",
                             [](const Diagram& d) { return to_array(d.ridge_vertices, 2); })
      .def_property_readonly("ridge_constraint",
                             [](const Diagram& d) { return to_array(d.ridge_constraint); })
      .def_property_readonly("ridge_edit_constraint",
                             [](const Diagram& d) { return to_array(d.ridge_edit_constraint); })
      .def_property_readonly(
          "ridge_boundary",
          [](const Diagram& d) { return to_array(d.ridge_boundary).attr("astype")("bool"); })
      .def_property_readonly("notes", [](const Diagram& d) { return d.notes; })
      .def("cycles", &Diagram::cycles)
      .def("rows", &Diagram::rows)
      .def("outlines", &Diagram::outlines)
      .def("polygons", &Diagram::polygons)
      .def("wkb", &Diagram::wkb)
      .def("write_geojson",
           [](const Diagram& d, const std::string& path, bool barriers,
              const CVT_2::IO::Metadata& metadata) {
             d.write(path, [&](std::ostream& os) {
               if (d.any_barrier(barriers))
                 CVT_2::IO::write_geojson(os, d.grid(barriers), metadata);
               else
                 CVT_2::IO::write_geojson(os, *d.mesh, metadata);
             });
           })
      .def("write_vtu",
           [](const Diagram& d, const std::string& path, bool barriers,
              const CVT_2::IO::Metadata& metadata) {
             d.write(path, [&](std::ostream& os) {
               if (d.any_barrier(barriers))
                 CVT_2::IO::write_vtu(os, d.grid(barriers), metadata);
               else
                 CVT_2::IO::write_vtu(os, *d.mesh, metadata);
             });
           })
      .def("write_disv",
           [](const Diagram& d, const std::string& path, const std::vector<double>& top,
              const std::vector<double>& bottom, bool barriers,
              const CVT_2::IO::Metadata& metadata) {
             d.write(path, [&](std::ostream& os) {
               CVT_2::IO::write_disv(os, d.grid(barriers), top, bottom, metadata);
             });
           })
      .def("write_cells_on_constraints",
           [](const Diagram& d, const std::string& path, bool barriers) {
             d.write(path, [&](std::ostream& os) {
               const Grid grid = d.grid(barriers);
               CVT_2::IO::write_cells_on_constraints(
                   os, grid, d.input_items(),
                   CVT_2::IO::conforming_line_pairs(*d.cdt, grid, d.domain->conforming_pairs,
                                                    d.domain->conforming_items));
             });
           });

  py::class_<Editing, std::shared_ptr<Editing>>(m, "ConstraintEditor")
      .def(py::init<const std::shared_ptr<const Domain>&, py::handle, std::optional<double>>(),
           py::arg("domain"), py::arg("points"), py::arg("boundary_tolerance"))
      .def("insert_constraint", &Editing::insert, py::arg("points"))
      .def("extend_constraint", &Editing::extend, py::arg("id"), py::arg("tip"), py::arg("spacing"))
      .def("move_constrained_vertex", &Editing::move, py::arg("vertex"), py::arg("to"))
      .def("remove_constraint", &Editing::remove, py::arg("id"))
      .def("relax", &Editing::relax, py::arg("rings"), py::arg("iterations"))
      .def("report", &Editing::report)
      .def("constraint_vertices", &Editing::constraint_vertices, py::arg("id"))
      .def("number_of_constraints",
           [](const Editing& e) { return e.editor->number_of_constraints(); })
      .def("is_removed",
           [](const Editing& e, std::int64_t c) { return e.editor->is_removed(e.id(c)); })
      .def("diagram", &Editing::diagram, py::arg("threads") = 0)
      .def_property_readonly("notes", [](const Editing& e) { return e.notes; });

  py::class_<Optimization, std::shared_ptr<Optimization>>(m, "Optimization")
      .def_property_readonly(
          "domain", [](const Optimization& o) { return std::const_pointer_cast<Domain>(o.domain); })
      .def_property_readonly("points", [](const Optimization& o) { return to_array(o.points); })
      .def_property_readonly(
          "constrained",
          [](const Optimization& o) { return to_array(o.constrained).attr("astype")("bool"); })
      .def_property_readonly(
          "fixed", [](const Optimization& o) { return to_array(o.fixed).attr("astype")("bool"); })
      .def_property_readonly("energy", [](const Optimization& o) { return o.result.energy; })
      .def_property_readonly("iterations",
                             [](const Optimization& o) { return o.result.number_of_iterations; })
      .def_property_readonly("evaluations",
                             [](const Optimization& o) { return o.result.number_of_evaluations; })
      .def_property_readonly(
          "stop_reason",
          [](const Optimization& o) { return std::string(CVT_2::to_string(o.result.stop_reason)); })
      .def_property_readonly(
          "energy_history", [](const Optimization& o) { return to_array(o.result.energy_history); })
      .def_property_readonly("max_move_ratio",
                             [](const Optimization& o) { return o.result.max_move_ratio; })
      .def_property_readonly("mean_move_ratio",
                             [](const Optimization& o) { return o.result.mean_move_ratio; })
      .def_property_readonly(
          "max_move_ratio_history",
          [](const Optimization& o) { return to_array(o.result.max_move_ratio_history); })
      .def_property_readonly(
          "mean_move_ratio_history",
          [](const Optimization& o) { return to_array(o.result.mean_move_ratio_history); })
      .def_property_readonly("seconds", [](const Optimization& o) { return o.result.seconds; })
      .def_property_readonly("input_index",
                             [](const Optimization& o) { return to_array(o.input_index); })
      .def_property_readonly("notes", [](const Optimization& o) { return o.notes; })
      .def_property_readonly("density_response",
                             [](const Optimization& o) { return o.density_response; })
      .def_property_readonly(
          "density_response_error",
          [](const Optimization& o) { return o.result.density_response.standard_error; })
      .def_property_readonly("density_response_cells",
                             [](const Optimization& o) { return o.result.density_response.cells; })
      .def_property_readonly(
          "density_count_excess",
          [](const Optimization& o) { return o.result.density_response.count_excess; })
      .def_property_readonly("redistributed", [](const Optimization& o) { return o.redistributed; })
      .def("diagram", &Optimization::diagram, py::arg("threads") = 0);

  m.def(
      "conforming_sites",
      [](py::handle line, double spacing) {
        const auto c = CVT_2::conforming_sites_2(to_points(line, "line"), spacing);
        py::dict out;
        out["sites"] = to_array(c.sites);
        out["nodes"] = to_array(c.nodes);
        out["radii"] = py::array_t<double>(py::ssize_t(c.radii.size()), c.radii.data());
        return out;
      },
      py::arg("line"), py::arg("spacing"));
  m.def("random_points", &random_points, py::arg("domain"), py::arg("n"), py::arg("seed"),
        py::arg("density"), py::arg("lipschitz_k"), py::arg("boundary_size"),
        py::arg("by_region") = false);
  m.def("optimize", &optimize, py::arg("domain"), py::arg("points"), py::arg("algorithm"),
        py::arg("density"), py::arg("move_ratio"), py::arg("max_iterations"), py::arg("time_limit"),
        py::arg("threads"), py::arg("callback"), py::arg("lipschitz_k"), py::arg("boundary_size"),
        py::arg("boundary_tolerance"), py::arg("fixed_points"), py::arg("slide") = false,
        py::arg("conforming") = false, py::arg("redistribute") = "auto", py::arg("seed") = 1,
        py::arg("cells") = py::none(), py::arg("size") = py::none(),
        py::arg("spacing_ratio") = 1.0);
  m.def("bounded_voronoi", &bounded_voronoi, py::arg("domain"), py::arg("points"),
        py::arg("threads"), py::arg("boundary_tolerance"));
  m.def("natural_neighbours", &natural_neighbours, py::arg("domain"), py::arg("nodes"),
        py::arg("queries"), py::arg("method"), py::arg("threads"), py::arg("boundary_tolerance"),
        py::arg("lips") = false);
#ifdef CVT_2_MODULE_BENCHMARKS
  m.def("_optimize_lambda_density", &optimize_lambda_density, py::arg("domain"), py::arg("points"),
        py::arg("max_iterations"), py::arg("move_ratio"), py::arg("threads"), py::arg("a"),
        py::arg("cx"), py::arg("cy"), py::arg("w"));
#endif
}
