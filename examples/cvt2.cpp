// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// cvt2 DOMAIN [options]: the centroidal Voronoi tessellation of a .poly or WKT domain by L-BFGS or
// Lloyd iteration, with pictures and cells out (SVG, text, GeoJSON, VTK, Triangle mesh). `cvt2 --help`.
#include <CVT_2/Boundary_lipschitz_sizing_2.h>
#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/Cvt_triangulation_2.h>
#include <CVT_2/insert_generators_2.h>
#include <CVT_2/IO/read_points.h>
#include <CVT_2/IO/read_poly.h>
#include <CVT_2/IO/read_wkt.h>
#include <CVT_2/IO/write_svg.h>
#include <CVT_2/lbfgs_optimize_2.h>
#include <CVT_2/lloyd_optimize_2.h>
#include <CVT_2/random_points_in_domain_2.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <new>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using CDT = CVT_2::Cvt_triangulation_2<K>;  // CGAL's CDT with Bvd_face_base_2 faces
using BVD = CVT_2::Bounded_voronoi_diagram_2<CDT>;
using Point_2 = K::Point_2;
using Sizing = CVT_2::Boundary_lipschitz_sizing_2<K>;

namespace {

// A mistake on the command line: reported with a pointer to --help.
struct Usage_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Options {
  std::string domain;
  std::optional<std::size_t> points;  // -n; by default from the domain file
  std::string points_in;
  std::uint64_t seed = 1;
  std::size_t iterations = 1000;
  double move_ratio = 0.01;
  bool lbfgs = true;  // L-BFGS reaches the stop in 2.4-3.6x less time than Lloyd
  bool lipschitz = false;
  double lipschitz_k = 0.1;
  std::optional<double> boundary_size;  // default: each boundary edge's length
  double time_limit = 0;
  std::string svg, points_out, cells_out, geojson, vtk, mesh_out;
  bool quiet = false;
  bool help = false;
};

void print_help(std::ostream& os) {
  os << "Usage: cvt2 DOMAIN [options]\n"
        "Centroidal Voronoi tessellation of DOMAIN by L-BFGS or Lloyd iteration. DOMAIN is a\n"
        "Triangle .poly file (segments are constraints, holes are seeds, free vertices are\n"
        "generators) or a .wkt file, one geometry a line: POLYGON/MULTIPOLYGON (the domain),\n"
        "LINESTRING/MULTILINESTRING (inner constraints), POINT/MULTIPOINT (generators).\n\n"
        "Generators:\n"
        "  -n, --points N         N random generators (default 1000 if DOMAIN has no free\n"
        "                         vertex and no --points-in is given, else 0)\n"
        "      --points-in FILE   generators from FILE, one 'x y' per line ('#' comments)\n"
        "      --seed S           seed of the random generators (default 1)\n"
        "Iteration:\n"
        "      --algorithm A      lbfgs | lloyd (default lbfgs: L-BFGS on the CVT energy, which\n"
        "                         starts with and falls back to Lloyd steps; it reaches the\n"
        "                         stop in 2.4-4.2x fewer evaluations, 1.8-3.0x less time)\n"
        "      --iterations N     at most N iterations (default 1000)\n"
        "      --move-ratio P     stop when every move ratio |x - x*| / diameter(cell) < P\n"
        "                         (default 0.01; 0 turns this stop off)\n"
        "      --density D        uniform | lipschitz (default uniform)\n"
        "      --lipschitz-k K    growth of the cell size away from the boundary (default 0.1)\n"
        "      --boundary-size S  cell size on the boundary (default: the local edge length)\n"
        "      --time-limit T     stop after T seconds (default 0: no limit)\n"
        "Outputs (written only when the optimization succeeded):\n"
        "      --svg FILE         picture: domain, cells, constraints, generators\n"
        "      --points-out FILE  one 'x y c' per generator, c = 1 if constrained\n"
        "      --cells-out FILE   one 'x y c k x1 y1 ... xk yk' per cell (bvd_cells format)\n"
        "      --geojson FILE     cells as GeoJSON polygons (constrained, generator, area)\n"
        "      --vtk FILE         cells as legacy VTK polydata (constrained, area)\n"
        "      --mesh-out PREFIX  the final triangulation: PREFIX.node and PREFIX.ele (Triangle)\n"
        "Other:\n"
        "      --quiet            no progress on standard error\n"
        "  -h, --help             this help\n\n"
        "Prints one summary line on standard output: algorithm= iterations= evaluations=\n"
        "stop= energy= normalized_energy= (1 for a hexagonal tiling, uniform density)\n"
        "max_move_ratio= mean_move_ratio= generators= seconds=\n";
}

// --- command line ------------------------------------------------------------------------------

double parse_real(const std::string& option, const std::string& text) {
  errno = 0;
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(x))
    throw Usage_error(option + " expects a number, not '" + text + "'");
  return x;
}

std::uint64_t parse_count(const std::string& option, const std::string& text) {
  errno = 0;
  char* end = nullptr;
  const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
  const unsigned long long x = std::strtoull(text.c_str(), &end, 10);
  if (!digits || *end != '\0' || errno == ERANGE)
    throw Usage_error(option + " expects a non-negative integer, not '" + text + "'");
  return x;
}

double parse_positive(const std::string& option, const std::string& text) {
  const double x = parse_real(option, text);
  if (!(x > 0)) throw Usage_error(option + " must be positive, not '" + text + "'");
  return x;
}

double parse_non_negative(const std::string& option, const std::string& text) {
  const double x = parse_real(option, text);
  if (!(x >= 0)) throw Usage_error(option + " must be >= 0, not '" + text + "'");
  return x;
}

// The options that take a value, by long name, with what to do with it.
using Setter = std::function<void(Options&, const std::string& option, const std::string& value)>;
const std::map<std::string, Setter>& valued_options() {
  static const std::map<std::string, Setter> table{
      {"--points", [](Options& o, auto& n, auto& v) { o.points = parse_count(n, v); }},
      {"--points-in", [](Options& o, auto&, auto& v) { o.points_in = v; }},
      {"--seed", [](Options& o, auto& n, auto& v) { o.seed = parse_count(n, v); }},
      {"--algorithm",
       [](Options& o, auto& n, auto& v) {
         if (v != "lbfgs" && v != "lloyd")
           throw Usage_error(n + " expects 'lbfgs' or 'lloyd', not '" + v + "'");
         o.lbfgs = v == "lbfgs";
       }},
      {"--iterations", [](Options& o, auto& n, auto& v) { o.iterations = parse_count(n, v); }},
      {"--move-ratio", [](Options& o, auto& n, auto& v) { o.move_ratio = parse_non_negative(n, v); }},
      {"--density",
       [](Options& o, auto& n, auto& v) {
         if (v != "uniform" && v != "lipschitz")
           throw Usage_error(n + " expects 'uniform' or 'lipschitz', not '" + v + "'");
         o.lipschitz = v == "lipschitz";
       }},
      {"--lipschitz-k", [](Options& o, auto& n, auto& v) { o.lipschitz_k = parse_positive(n, v); }},
      {"--boundary-size",
       [](Options& o, auto& n, auto& v) { o.boundary_size = parse_positive(n, v); }},
      {"--time-limit", [](Options& o, auto& n, auto& v) { o.time_limit = parse_non_negative(n, v); }},
      {"--svg", [](Options& o, auto&, auto& v) { o.svg = v; }},
      {"--points-out", [](Options& o, auto&, auto& v) { o.points_out = v; }},
      {"--cells-out", [](Options& o, auto&, auto& v) { o.cells_out = v; }},
      {"--geojson", [](Options& o, auto&, auto& v) { o.geojson = v; }},
      {"--vtk", [](Options& o, auto&, auto& v) { o.vtk = v; }},
      {"--mesh-out", [](Options& o, auto&, auto& v) { o.mesh_out = v; }},
  };
  return table;
}

// GNU style: --name VALUE, --name=VALUE, -n VALUE, -nVALUE; "--" ends the options.
Options parse_command_line(int argc, char* argv[]) {
  Options o;
  std::vector<std::string> positional;
  bool options_ended = false;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (options_ended || arg.size() < 2 || arg[0] != '-') {
      positional.push_back(arg);
      continue;
    }
    if (arg == "--") {
      options_ended = true;
      continue;
    }
    if (arg == "-h" || arg == "--help") {
      o.help = true;
      continue;
    }
    if (arg == "--quiet") {
      o.quiet = true;
      continue;
    }
    std::string name = arg;
    std::optional<std::string> value;
    if (arg.rfind("--", 0) == 0) {
      if (const auto eq = arg.find('='); eq != std::string::npos)
        name = arg.substr(0, eq), value = arg.substr(eq + 1);
    } else if (arg.rfind("-n", 0) == 0) {
      name = "--points";
      if (arg.size() > 2) value = arg.substr(2);
    }
    const auto it = valued_options().find(name);
    if (it == valued_options().end()) throw Usage_error("unknown option '" + arg + "'");
    if (!value) {
      if (i + 1 >= argc) throw Usage_error(arg + " expects a value");
      value = argv[++i];
    }
    it->second(o, name, *value);
  }
  if (o.help) return o;
  if (positional.empty()) throw Usage_error("no DOMAIN file given");
  if (positional.size() > 1) throw Usage_error("one DOMAIN file only, not also '" + positional[1] + "'");
  o.domain = positional[0];
  if (!o.lipschitz && o.boundary_size)
    throw Usage_error("--boundary-size needs --density lipschitz");
  return o;
}

// --- domain and generators ---------------------------------------------------------------------

double domain_area(const CDT& cdt) {
  double a = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->is_inside_domain()) a += CGAL::to_double(cdt.triangle(f).area());
  return a;
}

// The domain as read.
struct Domain {
  std::string source;
  std::size_t free_vertices = 0;  // generators that came with the domain file
};

bool has_suffix(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Said once per file: the triangulation merges points that repeat earlier ones.
void note_repeated(const std::string& file, const std::vector<std::array<std::size_t, 2>>& repeated,
                   const char* what) {
  if (repeated.empty()) return;
  std::cerr << "cvt2: note: " << file << ":" << repeated[0][0] << ": this " << what
            << " repeats the one on line " << repeated[0][1];
  if (repeated.size() > 1) std::cerr << " (and " << repeated.size() - 1 << " more repeat earlier ones)";
  std::cerr << "; merged\n";
}

Domain load_poly(const std::string& file, CDT& cdt) {
  const auto poly = CVT_2::IO::read_poly<Point_2>(file);
  note_repeated(file, poly.repeated_vertices, "vertex");
  CVT_2::IO::insert_poly(cdt, poly);
  std::vector<bool> on_segment(poly.vertices.size(), false);
  for (const auto& s : poly.segments) on_segment[s[0]] = on_segment[s[1]] = true;
  Domain d;
  d.source = file;
  for (const bool b : on_segment) d.free_vertices += b ? 0 : 1;
  return d;
}

// Polygon rings and linestrings as constraints, the domain marked from the polygons, then the
// points as generators.
Domain load_wkt(const std::string& file, CDT& cdt) {
  const auto w = CVT_2::IO::read_wkt<K>(file);
  note_repeated(file, w.repeated_points, "point");
  CVT_2::IO::insert_wkt(cdt, w);
  Domain d;
  d.source = file;
  d.free_vertices = w.points.size();
  return d;
}

Domain load_domain(const std::string& file, CDT& cdt) {
  if (!std::ifstream(file)) throw std::runtime_error("cannot open the domain file '" + file + "'");
  if (has_suffix(file, ".poly")) return load_poly(file, cdt);
  if (has_suffix(file, ".wkt")) return load_wkt(file, cdt);
  throw std::runtime_error(file + ": unknown domain format: expected a Triangle .poly or a .wkt file");
}

// The generators of --points-in, with errors that name the file and line.
void insert_points_file(const std::string& file, CDT& cdt) {
  if (!std::ifstream(file)) throw std::runtime_error("cannot open the points file '" + file + "'");
  const auto points = CVT_2::IO::read_points<Point_2>(file);
  note_repeated(file, points.repeated_points, "point");
  try {
    CVT_2::insert_generators_2(cdt, points.points);  // keeps the domain's marking
  } catch (const CVT_2::Domain_error& e) {
    if (e.index() >= points.lines.size()) throw;
    throw CVT_2::Domain_error(points.source + ":" + std::to_string(points.lines[e.index()]) + ": " +
                              e.what());
  }
}

void insert_random_points(std::size_t n, const Options& o, const std::optional<Sizing>& sizing,
                          CDT& cdt) {
  if (n == 0) return;
  // Peak memory a generator, measured at 4e6 (triangulation, cells, moves; L-BFGS's vectors):
  // refuse what memory cannot hold rather than be killed after minutes of work.
  const double needed = (o.lbfgs ? 750.0 : 280.0) * double(n);
  const double memory = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
  if (memory > 0 && needed > memory)
    throw Usage_error("--points " + std::to_string(n) + " needs about " +
                      std::to_string(static_cast<long long>(needed / 1e9)) + " GB; this machine has " +
                      std::to_string(static_cast<long long>(memory / 1e9)) + " GB");
  std::vector<Point_2> points;
  if (sizing) {  // a CVT of density 1/mu^4 has about 1/mu^2 points per unit area
    const auto density = [&sizing](const Point_2& p) {
      const double mu = (*sizing)(p);
      return 1 / (mu * mu);
    };
    points = CVT_2::random_points_in_domain_2(
        cdt, n, CVT_2::parameters::random_seed(o.seed).density(density));
  } else {
    points = CVT_2::random_points_in_domain_2(cdt, n, CVT_2::parameters::random_seed(o.seed));
  }
  CVT_2::insert_generators_2(cdt, points);
}

// --- optimization ------------------------------------------------------------------------------

volatile std::sig_atomic_t interrupted = 0;
// The first Ctrl-C ends the iteration early and keeps its result; a second one kills.
extern "C" void on_interrupt(int) {
  interrupted = 1;
  std::signal(SIGINT, SIG_DFL);
}

// Progress on standard error: one updating line on a terminal, a line every 10 iterations else.
class Progress {
 public:
  explicit Progress(bool quiet) : m_quiet(quiet), m_terminal(isatty(2)) {}
  bool operator()(const CVT_2::Optimization_result& r) {
    if (!m_quiet && (m_terminal || r.number_of_iterations % 10 == 0)) {
      std::ostringstream line;
      line << "cvt2: iteration " << r.number_of_iterations << "  energy " << std::setprecision(8)
           << r.energy << "  max move ratio " << std::setprecision(4) << r.max_move_ratio << "  "
           << std::fixed << std::setprecision(2) << r.seconds << " s";
      if (m_terminal)
        std::cerr << '\r' << line.str() << "\033[K" << std::flush, m_line_open = true;
      else
        std::cerr << line.str() << '\n';
    }
    return !interrupted;
  }
  void finish() {
    if (m_line_open) std::cerr << '\n';
    m_line_open = false;
  }

 private:
  bool m_quiet, m_terminal, m_line_open = false;
};

// The optimization, with progress on standard error; Ctrl-C ends it early.
CVT_2::Optimization_result optimize(CDT& cdt, const Options& o, const std::optional<Sizing>& sizing) {
  Progress progress(o.quiet);
  const std::function<bool(const CVT_2::Optimization_result&)> callback = std::ref(progress);
  const auto np = CVT_2::parameters::number_of_iterations(o.iterations)
                      .move_ratio_bound(o.move_ratio)
                      .maximum_running_time(o.time_limit)
                      .callback(callback);
  const auto run = [&o](CDT& t, const auto& parameters) {
    return o.lbfgs ? CVT_2::lbfgs_optimize_2(t, parameters) : CVT_2::lloyd_optimize_2(t, parameters);
  };
  std::signal(SIGINT, on_interrupt);
  try {
    const CVT_2::Optimization_result r = sizing ? run(cdt, np.sizing_field(*sizing)) : run(cdt, np);
    progress.finish();
    std::signal(SIGINT, SIG_DFL);
    return r;
  } catch (...) {
    progress.finish();
    throw;
  }
}

const char* stop_name(CVT_2::Stop_reason s) {
  switch (s) {
    case CVT_2::CONVERGED: return "converged";
    case CVT_2::MAX_ITERATIONS_REACHED: return "max_iterations";
    case CVT_2::TIME_LIMIT_REACHED: return "time_limit";
    case CVT_2::CALLBACK_REQUESTED_STOP: return "interrupted";
    case CVT_2::NO_FREE_GENERATOR: return "no_free_generator";
  }
  return "unknown";
}

// --- outputs -----------------------------------------------------------------------------------

// Shoelace, relative to the first vertex; a slit (there and back) adds nothing.
double cell_area(const std::vector<BVD::Cell_vertex>& cell) {
  double a = 0;
  const Point_2& o = cell.front().point;
  for (std::size_t i = 1; i + 1 < cell.size(); ++i)
    a += CGAL::to_double(CGAL::area(o, cell[i].point, cell[i + 1].point));
  return a;
}

void write_points(std::ostream& os, const BVD& bvd) {
  bvd.for_each_cell([&](CDT::Vertex_handle v, const auto&) {
    os << v->point() << ' ' << (bvd.is_free(v) ? 0 : 1) << '\n';
  });
}

void write_cells(std::ostream& os, const BVD& bvd) {
  bvd.for_each_cell([&](CDT::Vertex_handle v, const auto& cell) {
    os << v->point() << ' ' << (bvd.is_free(v) ? 0 : 1) << ' ' << cell.size();
    for (const auto& c : cell) os << ' ' << c.point;
    os << '\n';
  });
}

void write_geojson(std::ostream& os, const BVD& bvd) {
  const auto xy = [&os](const Point_2& p) { os << '[' << p.x() << ',' << p.y() << ']'; };
  os << "{\"type\":\"FeatureCollection\",\"features\":[";
  bool first = true;
  bvd.for_each_cell([&](CDT::Vertex_handle v, const auto& cell) {
    os << (first ? "\n" : ",\n") << "{\"type\":\"Feature\",\"properties\":{\"constrained\":"
       << (bvd.is_free(v) ? "false" : "true") << ",\"generator\":";
    xy(v->point());
    os << ",\"area\":" << cell_area(cell) << "},\"geometry\":{\"type\":\"Polygon\",\"coordinates\":[[";
    for (const auto& c : cell) xy(c.point), os << ',';
    xy(cell.front().point);  // GeoJSON closes a ring by repeating its first position
    os << "]]}}";
    first = false;
  });
  os << "\n]}\n";
}

void write_vtk(std::ostream& os, const BVD& bvd) {
  std::vector<std::vector<BVD::Cell_vertex>> cells;
  std::vector<int> constrained;
  std::size_t points = 0;
  bvd.for_each_cell([&](CDT::Vertex_handle v, const auto& cell) {
    cells.push_back(cell);
    constrained.push_back(bvd.is_free(v) ? 0 : 1);
    points += cell.size();
  });
  os << "# vtk DataFile Version 3.0\ncvt2 bounded Voronoi cells\nASCII\nDATASET POLYDATA\n"
     << "POINTS " << points << " double\n";
  for (const auto& cell : cells)
    for (const auto& c : cell) os << c.point << " 0\n";
  os << "POLYGONS " << cells.size() << ' ' << points + cells.size() << '\n';
  std::size_t next = 0;
  for (const auto& cell : cells) {
    os << cell.size();
    for (std::size_t i = 0; i < cell.size(); ++i) os << ' ' << next++;
    os << '\n';
  }
  os << "CELL_DATA " << cells.size() << "\nSCALARS constrained int 1\nLOOKUP_TABLE default\n";
  for (const int c : constrained) os << c << '\n';
  os << "SCALARS area double 1\nLOOKUP_TABLE default\n";
  for (const auto& cell : cells) os << cell_area(cell) << '\n';
}

// Triangle's .node (vertices from 1, boundary marker 1 on constrained vertices) and .ele.
void write_mesh(std::ostream& node, std::ostream& ele, const CDT& cdt) {
  std::map<CDT::Vertex_handle, std::size_t> index;
  std::size_t triangles = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_inside_domain()) continue;
    ++triangles;
    for (int i = 0; i < 3; ++i) index.emplace(f->vertex(i), 0);
  }
  node << index.size() << " 2 0 1\n";
  std::size_t n = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    const auto it = index.find(v);
    if (it == index.end()) continue;
    it->second = ++n;
    node << n << ' ' << v->point() << ' ' << (cdt.are_there_incident_constraints(v) ? 1 : 0) << '\n';
  }
  ele << triangles << " 3 0\n";
  std::size_t t = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->is_inside_domain())
      ele << ++t << ' ' << index[f->vertex(0)] << ' ' << index[f->vertex(1)] << ' '
          << index[f->vertex(2)] << '\n';
}

// Files written as FILE.tmp, renamed together once all were written: nothing half-written.
class Output_files {
 public:
  ~Output_files() {
    for (const auto& [file, tmp] : m_files) std::remove(tmp.c_str());
  }
  template <class Writer>
  void write(const std::string& file, Writer writer) {
    const std::string tmp = file + ".tmp";
    m_files.emplace_back(file, tmp);
    std::ofstream os(tmp);
    if (!os) throw std::runtime_error("cannot write '" + file + "': " + std::strerror(errno));
    os.precision(17);
    writer(os);
    os.close();
    if (!os) throw std::runtime_error("error while writing '" + file + "'");
  }
  void commit() {
    for (const auto& [file, tmp] : m_files)
      if (std::rename(tmp.c_str(), file.c_str()) != 0)
        throw std::runtime_error("cannot rename '" + tmp + "' to '" + file + "'");
    m_files.clear();
  }

 private:
  std::vector<std::pair<std::string, std::string>> m_files;
};

void write_outputs(const Options& o, const CDT& cdt, const BVD& bvd) {
  Output_files out;
  if (!o.svg.empty()) out.write(o.svg, [&](std::ostream& os) { CVT_2::IO::write_svg(os, bvd); });
  if (!o.points_out.empty()) out.write(o.points_out, [&](std::ostream& os) { write_points(os, bvd); });
  if (!o.cells_out.empty()) out.write(o.cells_out, [&](std::ostream& os) { write_cells(os, bvd); });
  if (!o.geojson.empty()) out.write(o.geojson, [&](std::ostream& os) { write_geojson(os, bvd); });
  if (!o.vtk.empty()) out.write(o.vtk, [&](std::ostream& os) { write_vtk(os, bvd); });
  if (!o.mesh_out.empty()) {
    std::ostringstream ele;
    ele.precision(17);
    out.write(o.mesh_out + ".node", [&](std::ostream& os) { write_mesh(os, ele, cdt); });
    out.write(o.mesh_out + ".ele", [&](std::ostream& os) { os << ele.str(); });
  }
  out.commit();
}

void print_summary(const Options& o, const CVT_2::Optimization_result& r, const BVD& bvd, double area) {
  std::size_t generators = 0;
  bvd.for_each_cell([&](CDT::Vertex_handle, const auto&) { ++generators; });
  // E N / A^2 over its value for the regular hexagonal tiling, 5 / (18 sqrt 3) (Gersho).
  const double hexagon = 5 / (18 * std::sqrt(3.0));
  const double normalized = r.energy * double(generators) / (area * area) / hexagon;
  std::cout << std::setprecision(8) << "algorithm=" << (o.lbfgs ? "lbfgs" : "lloyd")
            << " iterations=" << r.number_of_iterations << " evaluations=" << r.number_of_evaluations
            << " stop=" << stop_name(r.stop_reason) << " energy=" << r.energy
            << " normalized_energy=" << normalized << " max_move_ratio=" << r.max_move_ratio
            << " mean_move_ratio=" << r.mean_move_ratio << " generators=" << generators
            << " seconds=" << std::setprecision(3) << r.seconds << '\n';
}

int run(const Options& o) {
  CDT cdt;
  const Domain domain = load_domain(o.domain, cdt);
  // The sizing's default sizes are the boundary edges of the input, before generators split any.
  std::optional<Sizing> sizing;
  if (o.lipschitz)
    sizing.emplace(cdt, o.lipschitz_k,
                   o.boundary_size ? std::optional<K::FT>(*o.boundary_size) : std::nullopt);
  if (!o.points_in.empty()) insert_points_file(o.points_in, cdt);
  const std::size_t n =
      o.points ? *o.points : (domain.free_vertices == 0 && o.points_in.empty() ? 1000 : 0);
  insert_random_points(n, o, sizing, cdt);
  const CVT_2::Optimization_result r = optimize(cdt, o, sizing);
  const BVD bvd(cdt);
  write_outputs(o, cdt, bvd);
  print_summary(o, r, bvd, domain_area(cdt));
  return EXIT_SUCCESS;
}

}  // namespace

int main(int argc, char* argv[]) {
  try {
    const Options o = parse_command_line(argc, argv);
    if (o.help) {
      print_help(std::cout);
      return EXIT_SUCCESS;
    }
    return run(o);
  } catch (const Usage_error& e) {
    std::cerr << "cvt2: " << e.what() << "\ncvt2: try 'cvt2 --help'\n";
  } catch (const std::bad_alloc&) {
    std::cerr << "cvt2: out of memory: each generator needs about 200 bytes during the "
                 "optimization (--points, the input files)\n";
  } catch (const std::exception& e) {
    std::cerr << "cvt2: " << e.what() << '\n';
  }
  return EXIT_FAILURE;
}
