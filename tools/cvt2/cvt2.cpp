// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// cvt2 DOMAIN [options]: the centroidal Voronoi tessellation of a .poly, .wkt or .geojson domain
// by L-BFGS or Lloyd iteration, written as GeoJSON, VTU, MODFLOW 6 DISV, Triangle files, text
// and SVG. `cvt2 --help` says how. The optimization is a unit of its own, optimize.cpp.
#include "cvt2.h"

#include <CVT_2/Boundary_lipschitz_sizing_2.h>
#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/Bvd_mesh_2.h>
#include <CVT_2/Cvt_triangulation_2.h>
#include <CVT_2/IO/read_domain.h>
#include <CVT_2/IO/read_points.h>
#include <CVT_2/IO/write_cells.h>
#include <CVT_2/IO/write_cells_on_constraints.h>
#include <CVT_2/IO/write_disv.h>
#include <CVT_2/IO/write_geojson.h>
#include <CVT_2/IO/write_poly.h>
#include <CVT_2/IO/write_svg.h>
#include <CVT_2/IO/write_triangle.h>
#include <CVT_2/IO/write_vtu.h>
#include <CVT_2/Point_refinement_sizing_2.h>
#include <CVT_2/Simulation_grid_2.h>
#include <CVT_2/Sizing_field_density_2.h>
#include <CVT_2/Sliding_runs_2.h>
#include <CVT_2/cell_size_scale_2.h>
#include <CVT_2/conforming_sites_2.h>
#include <CVT_2/density_response_2.h>
#include <CVT_2/insert_generators_2.h>
#include <CVT_2/internal/memory_estimate.h>
#include <CVT_2/mark_domain_2.h>
#include <CVT_2/random_points_in_domain_2.h>
#include <CVT_2/resample_constraints_2.h>
#include <CVT_2/version.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
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

using BVD = CVT_2::Bounded_voronoi_diagram_2<CDT>;
using Mesh = CVT_2::Bvd_mesh_2<BVD>;
using Grid = CVT_2::Simulation_grid_2<Mesh>;
using Segments = CVT_2::IO::Domain_segments<K>;
using cvt2_program::Options;
using cvt2_program::Sizing_choice;

namespace {

// A mistake on the command line: reported with a pointer to --help.
struct Usage_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void print_help(std::ostream& os) {
  os << "Usage: cvt2 DOMAIN [options]\n"
        "Centroidal Voronoi tessellation of DOMAIN by L-BFGS or Lloyd iteration. DOMAIN is\n"
        "  a Triangle .poly file: segments are constraints, holes are seeds, vertices on no\n"
        "    segment are generators;\n"
        "  a .wkt file, one geometry a line, or a .geojson file: POLYGON/MULTIPOLYGON (the\n"
        "    domain), LINESTRING/MULTILINESTRING (inner constraints), POINT/MULTIPOINT\n"
        "    (generators). Coordinates are planar: project geographic data first.\n\n"
        "Generators:\n"
        "  -n, --points N         N random generators (default 1000 if DOMAIN has none and no\n"
        "                         --points-in is given, else 0)\n"
        "      --points-in FILE   generators from FILE, one 'x y' per line ('#' comments), or\n"
        "                         --points-out's 'x y c' (c = 1, the domain's own: skipped)\n"
        "      --boundary-tolerance T  a point of FILE outside DOMAIN by at most T goes onto\n"
        "                         its boundary, a constrained generator (default 2^-50 of the\n"
        "                         largest coordinate: a rounding; 0: none)\n"
        "      --fixed-points FILE  generators that never move (wells, observation points),\n"
        "                         one 'x y' per line\n"
        "      --refine X Y SIZE RADIUS  cells of spacing SIZE at (X, Y), growing to the\n"
        "                         background size (that of -n, --cells or --size uniform cells)\n"
        "                         at distance RADIUS; repeatable (a well: with --fixed-points)\n"
        "      --seed S           seed of the random generators (default 1)\n"
        "      --cells N          N cells in all, the domain's vertices and the points given\n"
        "                         included (instead of -n); with --constraints barrier the\n"
        "                         grid files split each cell on a barrier in two\n"
        "      --size H           cells of spacing H: H apart in a hexagonal tiling, a cell of\n"
        "                         area sqrt(3)/2 H^2 (instead of -n), the boundary's cells\n"
        "                         counted as if H apart (with --boundary keep too, however\n"
        "                         few its vertices). With --cells and --size\n"
        "                         each region between constraints (a county, an island) gets\n"
        "                         the points its area (its mass, with a density) asks for,\n"
        "                         less the cells of the generators on its boundary and in it:\n"
        "                         no generator crosses a constraint, so these counts stay\n"
        "                         as drawn; -n's points are dealt so too under a density\n"
        "Boundary:\n"
        "      --boundary B       keep | resample | slide (default keep). keep: every vertex of\n"
        "                         DOMAIN is a generator. resample: the polylines are cut at\n"
        "                         junctions, ends and corners and resampled between them, two\n"
        "                         cell sizes (from --size, --cells or -n) apart, on the input to\n"
        "                         rounding. slide: resample, then the new vertices slide along\n"
        "                         the input during the optimization, features fixed\n"
        "      --boundary-spacing R  resample: the new points R cell sizes apart (default 2:\n"
        "                         a generator on the boundary has half a cell, which then has\n"
        "                         an inner cell's area; fewer generators on lines, less energy)\n"
        "      --deviation-bound D  resample: a chord leaves the input by at most D (default a\n"
        "                         quarter of the cell size)\n"
        "      --corner-angle A   resample: a vertex where the polyline turns by more than A\n"
        "                         degrees, seen a cell size away on either side, stays (30)\n"
        "      --minimum-ring-area A  resample: an island or hole enclosing less than A goes,\n"
        "                         with what is inside it (default 0: none)\n"
        "Iteration:\n"
        "      --algorithm A      lbfgs | lloyd (default lbfgs: L-BFGS on the CVT energy, which\n"
        "                         starts with and falls back to Lloyd steps, and reaches the\n"
        "                         same stop in fewer evaluations)\n"
        "      --iterations N     at most N iterations (default 1000)\n"
        "      --move-ratio P     stop when every move ratio |x - x*| / diameter(cell) < P\n"
        "                         (default 0.01; 0 turns this stop off)\n"
        "      --density D        uniform | lipschitz (default uniform)\n"
        "      --lipschitz-k K    growth of the cell size away from the boundary (default 0.1)\n"
        "      --boundary-size S  cell size on the boundary (default: the local edge length)\n"
        "      --redistribute R   auto | always | never (default auto): with a density\n"
        "                         (lipschitz, --refine), replace the points of --points-in and\n"
        "                         DOMAIN by as many drawn from the density (--seed): always, or\n"
        "                         (auto) if their cells do not follow it (areas scaling as\n"
        "                         density^s, s > -1/4; a centroidal tessellation's: -1/2), or\n"
        "                         the regions between constraints hold counts that cost over\n"
        "                         2% of the energy: the iteration would stop far from the\n"
        "                         optimum\n"
        "      --time-limit T     stop after T seconds (default 0: no limit)\n"
        "      --threads N        threads (default 0: one per core); the result is the same\n"
        "Outputs (written only when the optimization succeeded; an existing file is replaced,\n"
        "never an input, and none twice):\n"
        "      --geojson FILE     the cells as GeoJSON features, valid polygons (QGIS, GDAL,\n"
        "                         shapely): cell, generator, constrained, area, neighbors\n"
        "      --vtu FILE         the cells as a VTK XML grid with shared points (ParaView,\n"
        "                         meshio): cell, constrained, area, generator\n"
        "      --disv FILE        the cells as a MODFLOW 6 DISV grid, one layer (flopy)\n"
        "      --top T, --bottom B  the DISV layer's top and bottom (default 1 and 0): a number,\n"
        "                         or a file of one a cell in the DISV's order\n"
        "      --cells-on-constraints FILE  CSV 'constraint,cell,length,other_cell': the\n"
        "                         cells along each input line, for boundary conditions\n"
        "                         (constraint: the .poly segment's row from 0, the .wkt line,\n"
        "                         the .geojson feature from 1; cell and other_cell: the DISV's\n"
        "                         numbers, from 1 (the GeoJSON's and VTU's cell + 1),\n"
        "                         other_cell -1 on the boundary; with --boundary\n"
        "                         resample or slide, a new chord is named by the input line\n"
        "                         it replaces)\n"
        "      --constraints C    slit | barrier | conforming (default slit): what the inner\n"
        "                         constraints are. slit: cells cross them (a constrained\n"
        "                         generator's cell lies on both sides). barrier: a wall; a cell\n"
        "                         on it is split into one cell per side (each centered at the\n"
        "                         generator), no face across it. conforming: a line water\n"
        "                         crosses (a river; the LINESTRINGs of a .wkt or .geojson file),\n"
        "                         not a constraint: generators mirrored across it, fixed, so that\n"
        "                         faces lie on it, perpendicular to the line between the cells\n"
        "                         beside it, a cell size apart (the size a density asks for\n"
        "                         where they lie, with --refine or --density lipschitz).\n"
        "                         A GeoJSON feature's \"kind\" property (slit,\n"
        "                         barrier, conforming) says it for its own lines\n"
        "      --mesh-out PREFIX  the final triangulation: PREFIX.node, .ele, .edge (Triangle)\n"
        "      --domain-out FILE  the domain (resampled with --boundary resample, where its\n"
        "                         vertices slid to with slide) and its own generators as a\n"
        "                         Triangle .poly file\n"
        "      --cells-out FILE   one 'x y c k x1 y1 ... xk yk' per cell (bvd_cells format)\n"
        "      --points-out FILE  one 'x y c' per generator, c = 1 if constrained\n"
        "      --svg FILE         picture: domain, cells, constraints, generators\n"
        "Other:\n"
        "      --quiet            no progress on standard error (notes and errors still)\n"
        "  -h, --help             this help\n"
        "      --version          the version\n\n"
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

bool is_number(const std::string& text) {
  char* end = nullptr;
  std::strtod(text.c_str(), &end);
  return !text.empty() && *end == '\0';
}

// Throws unless `path` names a file that can be read (a directory opens, then reads as empty).
void require_readable(const std::string& what, const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw std::runtime_error("cannot open the " + what + " file '" + path + "': a directory");
  if (!std::ifstream(path))
    throw std::runtime_error("cannot open the " + what + " file '" + path + "'");
}

// --top, --bottom: a number, or the file of one a cell.
std::vector<double> number_or_values(const std::string& option, const std::string& text) {
  if (is_number(text)) return {parse_real(option, text)};
  require_readable(option.substr(2), text);
  return CVT_2::IO::read_values(text);
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

std::string parse_choice(const std::string& option, const std::string& text, const char* a,
                         const char* b, const char* c = nullptr) {
  if (text != a && text != b && (c == nullptr || text != c))
    throw Usage_error(option + " expects '" + a + "'" + (c ? ", '" : " or '") + b + "'" +
                      (c ? std::string(" or '") + c + "'" : std::string()) + ", not '" + text +
                      "'");
  return text;
}

// The options that take a value, by long name, with what to do with it.
using Setter = std::function<void(Options&, const std::string& option, const std::string& value)>;
const std::map<std::string, Setter>& valued_options() {
  static const std::map<std::string, Setter> table{
      {"--points", [](Options& o, auto& n, auto& v) { o.points = parse_count(n, v); }},
      {"--points-in", [](Options& o, auto&, auto& v) { o.points_in = v; }},
      {"--cells",
       [](Options& o, auto& n, auto& v) {
         o.cells = parse_count(n, v);
         if (*o.cells == 0) throw Usage_error(n + " must be positive, not '" + v + "'");
       }},
      {"--size", [](Options& o, auto& n, auto& v) { o.size = parse_positive(n, v); }},
      {"--boundary",
       [](Options& o, auto& n, auto& v) {
         const std::string mode = parse_choice(n, v, "keep", "resample", "slide");
         o.resample = mode != "keep";
         o.slide = mode == "slide";
       }},
      {"--constraints",
       [](Options& o, auto& n, auto& v) {
         const std::string kind = parse_choice(n, v, "slit", "barrier", "conforming");
         o.barriers = kind == "barrier";
         o.conforming = kind == "conforming";
       }},
      {"--minimum-ring-area",
       [](Options& o, auto& n, auto& v) { o.minimum_ring_area = parse_non_negative(n, v); }},
      {"--corner-angle",
       [](Options& o, auto& n, auto& v) { o.corner_angle = parse_non_negative(n, v); }},
      {"--deviation-bound",
       [](Options& o, auto& n, auto& v) { o.deviation_bound = parse_non_negative(n, v); }},
      {"--boundary-spacing",
       [](Options& o, auto& n, auto& v) { o.spacing_ratio = parse_positive(n, v); }},
      {"--boundary-tolerance",
       [](Options& o, auto& n, auto& v) { o.boundary_tolerance = parse_non_negative(n, v); }},
      {"--seed", [](Options& o, auto& n, auto& v) { o.seed = parse_count(n, v); }},
      {"--algorithm", [](Options& o, auto& n,
                         auto& v) { o.lbfgs = parse_choice(n, v, "lbfgs", "lloyd") == "lbfgs"; }},
      {"--iterations", [](Options& o, auto& n, auto& v) { o.iterations = parse_count(n, v); }},
      {"--move-ratio",
       [](Options& o, auto& n, auto& v) { o.move_ratio = parse_non_negative(n, v); }},
      {"--density",
       [](Options& o, auto& n, auto& v) {
         o.lipschitz = parse_choice(n, v, "uniform", "lipschitz") == "lipschitz";
       }},
      {"--redistribute",
       [](Options& o, auto& n, auto& v) {
         o.redistribute = parse_choice(n, v, "auto", "always", "never");
       }},
      {"--lipschitz-k", [](Options& o, auto& n, auto& v) { o.lipschitz_k = parse_positive(n, v); }},
      {"--boundary-size",
       [](Options& o, auto& n, auto& v) { o.boundary_size = parse_positive(n, v); }},
      {"--time-limit",
       [](Options& o, auto& n, auto& v) { o.time_limit = parse_non_negative(n, v); }},
      {"--threads",
       [](Options& o, auto& n, auto& v) {
         const std::uint64_t t = parse_count(n, v);
         if (t > 4096) throw Usage_error(n + " expects at most 4096, not '" + v + "'");
         o.threads = static_cast<unsigned>(t);
       }},
      {"--svg", [](Options& o, auto&, auto& v) { o.svg = v; }},
      {"--points-out", [](Options& o, auto&, auto& v) { o.points_out = v; }},
      {"--cells-out", [](Options& o, auto&, auto& v) { o.cells_out = v; }},
      {"--geojson", [](Options& o, auto&, auto& v) { o.geojson = v; }},
      {"--vtu", [](Options& o, auto&, auto& v) { o.vtu = v; }},
      {"--disv", [](Options& o, auto&, auto& v) { o.disv = v; }},
      {"--fixed-points", [](Options& o, auto&, auto& v) { o.fixed_points = v; }},
      {"--cells-on-constraints", [](Options& o, auto&, auto& v) { o.cells_on_constraints = v; }},
      {"--mesh-out", [](Options& o, auto&, auto& v) { o.mesh_out = v; }},
      {"--domain-out", [](Options& o, auto&, auto& v) { o.domain_out = v; }},
      {"--top", [](Options& o, auto&, auto& v) { o.top = v; }},
      {"--bottom", [](Options& o, auto&, auto& v) { o.bottom = v; }},
      {"--vtk",
       [](Options&, auto&, auto&) {
         throw Usage_error(
             "--vtk (legacy VTK) is gone: use --vtu FILE (VTK XML with shared "
             "points, read by ParaView and meshio)");
       }},
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
    } else if (arg == "--") {
      options_ended = true;
    } else if (arg == "-h" || arg == "--help") {
      o.help = true;
    } else if (arg == "--version") {
      o.version = true;
    } else if (arg == "--quiet") {
      o.quiet = true;
    } else if (arg == "--refine") {
      if (i + 4 >= argc) throw Usage_error("--refine expects four values: X Y SIZE RADIUS");
      std::array<double, 4> r{};
      for (int j = 0; j < 4; ++j) r[std::size_t(j)] = parse_real("--refine", argv[++i]);
      if (!(r[2] > 0) || !(r[3] > 0))
        throw Usage_error("--refine's SIZE and RADIUS must be positive, not " +
                          std::string(argv[i - 1]) + " and " + argv[i]);
      o.refine.push_back(r);
    } else {
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
  }
  if (o.help || o.version) return o;
  if (positional.empty()) throw Usage_error("no DOMAIN file given");
  if (positional.size() > 1)
    throw Usage_error("one DOMAIN file only, not also '" + positional[1] + "'");
  o.domain = positional[0];
  if (o.lipschitz && !o.refine.empty())
    throw Usage_error("give one of --density lipschitz and --refine");
  if (!o.lipschitz && o.boundary_size)
    throw Usage_error("--boundary-size needs --density lipschitz");
  if (!o.lipschitz && o.lipschitz_k) throw Usage_error("--lipschitz-k needs --density lipschitz");
  if (int(o.points.has_value()) + int(o.cells.has_value()) + int(o.size.has_value()) > 1)
    throw Usage_error("give one of -n, --cells and --size");
  for (const auto& [name, text] : {std::pair("--top", &o.top), std::pair("--bottom", &o.bottom)})
    if (!is_number(*text) && !std::ifstream(*text))
      throw Usage_error(std::string(name) + " expects a number or a file of one a cell, not '" +
                        *text + "'");
  if (is_number(o.top) && is_number(o.bottom) &&
      !(parse_real("--bottom", o.bottom) < parse_real("--top", o.top)))
    throw Usage_error("--bottom must be below --top, not " + o.bottom + " >= " + o.top);
  if (o.deviation_bound && !o.resample)
    throw Usage_error("--deviation-bound needs --boundary resample");
  if (o.spacing_ratio && !o.resample)
    throw Usage_error("--boundary-spacing needs --boundary resample");
  if (o.minimum_ring_area > 0 && !o.resample)
    throw Usage_error("--minimum-ring-area needs --boundary resample");
  if (o.boundary_tolerance && o.points_in.empty())
    throw Usage_error("--boundary-tolerance needs --points-in");
  return o;
}

// --- domain and generators ---------------------------------------------------------------------

// Said once per file: the triangulation merges points that repeat earlier ones.
// The first of `notes` and how many more there are, which `others` says ("repeat earlier
// ones"), then `end`.
void note_first(const std::vector<std::string>& notes, const char* others, const char* end = "") {
  if (notes.empty()) return;
  std::cerr << "cvt2: note: " << notes[0];
  if (notes.size() > 1) std::cerr << " (and " << notes.size() - 1 << " more " << others << ")";
  std::cerr << end << '\n';
}

void note_repeated(const std::vector<std::string>& notes) {
  note_first(notes, "repeat earlier ones", "; merged");
}

// The lines of the points file `file` whose points repeat earlier ones, merged into one.
template <class ReadPoints>
void note_repeated_points(const std::string& file, const ReadPoints& points) {
  std::vector<std::string> notes;
  for (const auto& [line, earlier] : points.repeated_points)
    notes.push_back(file + ":" + std::to_string(line) + ": this point repeats the one on line " +
                    std::to_string(earlier));
  note_repeated(notes);
}

// The conforming lines (--constraints conforming, or a feature's "kind"), their input items and
// the pairs of generators mirrored across their steps.
struct Conforming {
  std::vector<std::vector<Point_2>> lines;
  std::vector<std::int64_t> items;
  std::vector<CVT_2::Conforming_pair_2<Point_2>> pairs;
};

void insert_random_points(std::size_t n, const Options& o, const Sizing_choice& sizing, CDT& cdt,
                          const CVT_2::Conforming_disks<Point_2>& keep_out, bool dealt) {
  if (n == 0) return;
  // What memory cannot hold is refused rather than killed after minutes of work.
  const std::string shortfall = CVT_2::internal::memory_shortfall(double(n), o.lbfgs);
  if (!shortfall.empty())
    throw Usage_error(std::string(o.cells  ? "--cells"
                                  : o.size ? "--size"
                                           : "--points") +
                      ": " + shortfall);
  // --cells and --size, in place of generators redistributed (`dealt`), or under a density:
  // cells of one size (of the density's), region by region; -n with a uniform density: n
  // points, as before. None in the circles of conforming lines: drawn again in its region.
  const bool by_region = o.cells.has_value() || o.size.has_value() || dealt || !sizing.is_uniform();
  CVT_2::insert_generators_2(
      cdt,
      sizing.apply(CVT_2::parameters::random_seed(o.seed).by_region(by_region).keep_out(keep_out),
                   [&](const auto& np) { return CVT_2::random_points_in_domain_2(cdt, n, np); }));
}

// --redistribute: with a density, the free generators given (--points-in, the domain file's;
// not the fixed ones) removed, always or (auto) if their cells do not follow it. Returns how
// many, to draw as many from the density.
std::size_t redistribute(const Options& o, const Sizing_choice& sizing,
                         const std::vector<Point_2>& fixed, CDT& cdt) {
  if (o.redistribute == "always" && sizing.is_uniform())
    std::cerr << "cvt2: note: --redistribute always: the density is uniform (no --density "
                 "lipschitz, no --refine): the generators given are kept\n";
  if (o.redistribute == "never" || sizing.is_uniform()) return 0;
  const bool always = o.redistribute == "always";
  CVT_2::Density_response response;
  const auto to_replace = [&](const auto& mu) {
    return CVT_2::generators_to_redistribute_2(cdt, CVT_2::make_sizing_field_density_2<K>(mu),
                                               fixed, always, &response);
  };
  const auto given =
      sizing.lipschitz ? to_replace(*sizing.lipschitz) : to_replace(*sizing.refinement);
  if (given.empty()) return 0;
  CVT_2::remove_generators_2(cdt, given);
  std::cerr << "cvt2: note: the " << given.size()
            << " free generators (--points-in's and the domain's own) "
            << (o.redistribute == "auto"
                    ? "do not follow the density (" +
                          CVT_2::internal::density_response_reason(response) + ")"
                    : std::string("are redistributed (--redistribute always)"))
            << ": replaced by as many drawn from the density (--redistribute never keeps them)\n";
  return given.size();
}

// --- outputs -----------------------------------------------------------------------------------

// The output files, written beside their names and renamed once all are written, so that a run
// that fails leaves every file as it was. A temporary name is one no file has; an existing
// output that is not a regular file (a named pipe, /dev/stdout) is written directly, and a
// symbolic link is written through, to the file it names.
class Output_files {
 public:
  ~Output_files() {
    for (const auto& [file, tmp] : m_files)
      if (!tmp.empty()) std::remove(tmp.c_str());
  }
  template <class Writer>
  void write(const std::string& name, Writer writer) {
    namespace fs = std::filesystem;
    std::error_code ec;
    // (what the name leads to, links followed: /dev/stdout may be a pipe, whose name in /proc
    // is no path)
    const bool direct = fs::exists(name, ec) && !fs::is_regular_file(name, ec);
    const std::string file =
        !direct && fs::is_symlink(name, ec) ? fs::weakly_canonical(name, ec).string() : name;
    std::string tmp;
    if (!direct)
      for (int k = 0; tmp.empty() || fs::exists(tmp, ec); ++k)
        tmp = file + ".cvt2-" + std::to_string(process_id()) + "-" + std::to_string(k) + ".tmp";
    m_files.emplace_back(file, tmp);
    std::ofstream os(direct ? file : tmp, std::ios::binary);
    if (!os) throw std::runtime_error("cannot write '" + name + "': " + std::strerror(errno));
    writer(os);
    os.close();
    if (!os) throw std::runtime_error("error while writing '" + name + "'");
  }
  void commit() {
    for (const auto& [file, tmp] : m_files)
      if (!tmp.empty() && std::rename(tmp.c_str(), file.c_str()) != 0)
        throw std::runtime_error("cannot rename '" + tmp + "' to '" + file + "'");
    m_files.clear();
  }

 private:
  static long process_id() {
#ifdef CVT2_POSIX
    return long(getpid());
#else
    return 0;
#endif
  }
  std::vector<std::pair<std::string, std::string>> m_files;  // (file, temporary or empty)
};

// The outputs checked before any work: each in a directory that exists, none a directory, none
// one of the input files (it would be replaced: "--geojson in.poly"), no two the same file.
void check_output_paths(const Options& o) {
  namespace fs = std::filesystem;
  std::vector<std::pair<std::string, std::string>> outputs;  // (option, path)
  const auto output = [&](const char* option, const std::string& path) {
    if (!path.empty()) outputs.emplace_back(option, path);
  };
  output("--svg", o.svg);
  output("--points-out", o.points_out);
  output("--cells-out", o.cells_out);
  output("--geojson", o.geojson);
  output("--vtu", o.vtu);
  output("--disv", o.disv);
  output("--cells-on-constraints", o.cells_on_constraints);
  output("--domain-out", o.domain_out);
  if (!o.mesh_out.empty())
    for (const char* e : {".node", ".ele", ".edge"}) output("--mesh-out", o.mesh_out + e);
  std::vector<std::pair<std::string, std::string>> inputs{{"the domain file", o.domain}};
  if (!o.points_in.empty()) inputs.emplace_back("--points-in", o.points_in);
  if (!o.fixed_points.empty()) inputs.emplace_back("--fixed-points", o.fixed_points);
  if (!is_number(o.top)) inputs.emplace_back("--top", o.top);
  if (!is_number(o.bottom)) inputs.emplace_back("--bottom", o.bottom);
  std::error_code ec;
  // The same file: both exist and are one, or neither does and their paths are one.
  const auto same = [&ec](const std::string& a, const std::string& b) {
    if (fs::exists(a, ec) || fs::exists(b, ec)) return fs::equivalent(a, b, ec);
    return fs::weakly_canonical(a, ec) == fs::weakly_canonical(b, ec);
  };
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const auto& [option, path] = outputs[i];
    if (fs::is_directory(path, ec)) throw Usage_error(option + " '" + path + "' is a directory");
    const fs::path parent = fs::path(path).parent_path();
    if (!parent.empty() && !fs::is_directory(parent, ec))
      throw Usage_error(option + " '" + path + "': there is no directory '" + parent.string() +
                        "'");
    for (const auto& [what, input] : inputs)
      if (same(path, input))
        throw Usage_error(option + " '" + path + "' would replace " + what + " '" + input + "'");
    for (std::size_t j = 0; j < i; ++j)
      if (same(path, outputs[j].second))
        throw Usage_error(option + " and " + outputs[j].first + " name the same file '" + path +
                          "'");
  }
}

// What each inner constraint is, by the input item its lines come from: the GeoJSON features'
// "kind" properties, --constraints for the others.
struct Kinds {
  std::vector<std::string> of_item;  // by item from 1; empty: --constraints
  std::string by_default;            // --constraints
  const std::string& of(std::int64_t item) const {
    if (item >= 1 && std::size_t(item) <= of_item.size() && !of_item[std::size_t(item - 1)].empty())
      return of_item[std::size_t(item - 1)];
    return by_default;
  }
  bool barrier(std::int64_t item) const { return of(item) == "barrier"; }
  bool any_barrier() const {
    return by_default == "barrier" || std::count(of_item.begin(), of_item.end(), "barrier") > 0;
  }
};

// Whether --top and --bottom have one value or one a cell of the DISV, `cells` (`known`: as
// --cells asks for, before the work), with the message for the first that has not.
void check_layer_cells(const std::vector<double>& top, const std::vector<double>& bottom,
                       std::size_t cells, bool known) {
  for (const auto& [values, name] : {std::pair(&top, "--top"), std::pair(&bottom, "--bottom")})
    if (values->size() != 1 && values->size() != cells)
      throw Usage_error(name + std::string(" has ") + std::to_string(values->size()) +
                        (known ? " values for --cells " + std::to_string(cells)
                               : " values, the DISV " + std::to_string(cells) +
                                     " cells (a cell that a barrier crosses is two)") +
                        " (one, or one a cell)");
}

void write_outputs(const Options& o, const CDT& cdt, const BVD& bvd,
                   const CVT_2::IO::Metadata& metadata, const CDT& domain, const Segments& segments,
                   const Kinds& kinds, const Conforming& conforming, const std::vector<double>& top,
                   const std::vector<double>& bottom) {
  using namespace CVT_2::IO;
  Output_files out;
  if (!o.svg.empty()) out.write(o.svg, [&](std::ostream& os) { write_svg(os, bvd); });
  if (!o.points_out.empty())
    out.write(o.points_out, [&](std::ostream& os) { write_points(os, bvd); });
  if (!o.cells_out.empty()) out.write(o.cells_out, [&](std::ostream& os) { write_cells(os, bvd); });
  if (!o.geojson.empty() || !o.vtu.empty() || !o.disv.empty() || !o.cells_on_constraints.empty()) {
    const Mesh mesh(bvd, o.threads);
    const std::vector<std::int64_t> items = segments.ends.empty()
                                                ? std::vector<std::int64_t>()
                                                : CVT_2::IO::constraint_items(cdt, mesh, segments);
    // The grid, only where it differs from the mesh or a file needs it (it costs a pass).
    std::optional<Grid> grid_if;
    if (kinds.any_barrier() || !o.disv.empty() || !o.cells_on_constraints.empty()) {
      if (kinds.of_item.empty())
        grid_if.emplace(mesh, o.barriers ? CVT_2::BARRIER : CVT_2::SLIT);
      else
        grid_if.emplace(
            mesh, [&](Grid::Index c) { return kinds.barrier(c < items.size() ? items[c] : -1); });
    }
    const auto write = [&](const auto& cells) {
      if (!o.geojson.empty())
        out.write(o.geojson, [&](std::ostream& os) { write_geojson(os, cells, metadata); });
      if (!o.vtu.empty())
        out.write(o.vtu, [&](std::ostream& os) { write_vtu(os, cells, metadata); });
    };
    if (kinds.any_barrier())
      write(*grid_if);
    else
      write(mesh);  // the mesh's own cells and vertices, bit for bit
    if (!o.disv.empty()) {
      check_layer_cells(top, bottom, grid_if->number_of_cells(), false);
      out.write(o.disv, [&](std::ostream& os) { write_disv(os, *grid_if, top, bottom, metadata); });
    }
    if (!o.cells_on_constraints.empty())
      out.write(o.cells_on_constraints, [&](std::ostream& os) {
        write_cells_on_constraints(
            os, *grid_if, items,
            conforming_line_pairs(cdt, *grid_if, conforming.pairs, conforming.items));
      });
  }
  if (!o.domain_out.empty())
    out.write(o.domain_out, [&](std::ostream& os) { write_poly(os, domain); });
  if (!o.mesh_out.empty()) {
    std::ostringstream ele, edge;
    out.write(o.mesh_out + ".node", [&](std::ostream& os) { write_triangle(os, ele, edge, cdt); });
    out.write(o.mesh_out + ".ele", [&](std::ostream& os) { os << ele.str(); });
    out.write(o.mesh_out + ".edge", [&](std::ostream& os) { os << edge.str(); });
  }
  out.commit();
}

double domain_area(const CDT& cdt) {
  double a = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->is_inside_domain()) a += CGAL::to_double(cdt.triangle(f).area());
  return a;
}

void print_summary(const Options& o, const CVT_2::Optimization_result& r, const BVD& bvd,
                   double area) {
  std::size_t generators = 0;
  bvd.for_each_cell([&](CDT::Vertex_handle, const auto&) { ++generators; });
  // E N / A^2 over its value for the regular hexagonal tiling, 5 / (18 sqrt 3) (Gersho).
  const double hexagon = 5 / (18 * std::sqrt(3.0));
  const double normalized = r.energy * double(generators) / (area * area) / hexagon;
  const char* stop = r.stop_reason == CVT_2::CALLBACK_REQUESTED_STOP
                         ? "interrupted"
                         : CVT_2::to_string(r.stop_reason);
  std::cout << std::setprecision(8) << "algorithm=" << (o.lbfgs ? "lbfgs" : "lloyd")
            << " iterations=" << r.number_of_iterations
            << " evaluations=" << r.number_of_evaluations << " stop=" << stop
            << " energy=" << r.energy << " normalized_energy=" << normalized
            << " max_move_ratio=" << r.max_move_ratio << " mean_move_ratio=" << r.mean_move_ratio
            << " generators=" << generators << " seconds=" << std::setprecision(3) << r.seconds
            << '\n';
}

// --boundary-spacing, or resample_constraints_2()'s default; with keep, 1 (the input's vertices
// stay; the number of cells that --size asks for as before).
double spacing_ratio(const Options& o) {
  return o.resample ? o.spacing_ratio.value_or(CVT_2::default_spacing_ratio) : 1.0;
}

// --boundary resample (and slide): the constraints resampled to the cell size that --size, --cells
// or the number of free generators asks for; a note of what changed on standard error.
void resample(const Options& o, std::size_t free_generators, CDT& cdt,
              CVT_2::IO::Metadata& metadata, CVT_2::Sliding_runs_2<CDT>& runs, Segments* segments) {
  const double area = domain_area(cdt);
  const double h =
      o.size    ? *o.size
      : o.cells ? CVT_2::cell_size_for_cells_2(cdt, *o.cells, spacing_ratio(o))
                : std::sqrt(2 * area /
                            (std::sqrt(3.0) * double(std::max<std::size_t>(free_generators, 1))));
  // The input line of each constrained edge, for the chords that replace them.
  const auto edge_items = CVT_2::IO::constrained_edge_items(cdt, segments ? *segments : Segments());
  std::vector<CVT_2::Resampled_chord<Point_2>> chords;
  const auto np = CVT_2::parameters::corner_angle(o.corner_angle)
                      .spacing_ratio(spacing_ratio(o))
                      .minimum_ring_area(o.minimum_ring_area)
                      .sliding_runs(&runs)
                      .resampled_chords(&chords);
  const auto r = o.deviation_bound
                     ? CVT_2::resample_constraints_2(cdt, h, np.deviation_bound(*o.deviation_bound))
                     : CVT_2::resample_constraints_2(cdt, h, np);
  // As the Python module holds a resampled domain, as Triangle's description: its triangulation
  // from that, so that both draw the same random points.
  CDT described;
  CVT_2::IO::insert_poly(described, CVT_2::IO::domain_poly_data(cdt));
  cdt.swap(described);
  runs.relocate(cdt);
  if (segments) *segments = CVT_2::IO::resampled_segments<K>(chords, edge_items);
  using CVT_2::internal::number_text;
  metadata.emplace_back("cell_size", number_text(h));
  metadata.emplace_back("spacing_ratio", number_text(spacing_ratio(o)));
  metadata.emplace_back("deviation_bound",
                        number_text(o.deviation_bound ? *o.deviation_bound : h / 4));
  metadata.emplace_back("max_deviation", number_text(r.max_deviation));
  if (o.quiet) return;
  std::cerr << std::setprecision(4) << "cvt2: boundary resampled to the cell size " << h << ": "
            << r.input_vertices << " vertices on constraints -> " << r.output_vertices << " ("
            << r.features << " features, " << r.corners << " of them corners; kept "
            << r.kept_for_deviation << " for the deviation bound, " << r.kept_for_topology
            << " for the topology); " << r.rings_dropped << " rings and " << r.generators_dropped
            << " generators below the minimum ring area dropped; largest deviation "
            << r.max_deviation << ", area " << r.area_before << " -> " << r.area_after << '\n';
}

// --boundary slide, after the optimization: the domain's lines where the vertices slid to (the
// named segments' ends follow the vertices of `constrained`, as they were before), for
// --cells-on-constraints and --domain-out (with the file's own generators where they were given,
// those still strictly inside), the largest deviation from the input in the metadata, and a
// note of it.
void slid_domain(const Options& o, const CDT& cdt, const CVT_2::Sliding_runs_2<CDT>& runs,
                 const CVT_2::Slid_vertices_2<CDT>& slid, Segments& segments, CDT& domain_alone,
                 CVT_2::IO::Metadata& metadata) {
  const auto lines = CVT_2::IO::domain_poly_data(cdt, "<triangulation>", false);
  slid.follow(segments.ends);
  // the resampling's bound the chords that did not slide
  CVT_2::IO::raise_metadata_number(metadata, "max_deviation", runs.max_deviation());
  if (!o.domain_out.empty()) {
    CDT out;
    CVT_2::IO::insert_poly(out, lines);
    std::vector<Point_2> generators;
    for (auto v = domain_alone.finite_vertices_begin(); v != domain_alone.finite_vertices_end();
         ++v) {
      if (domain_alone.are_there_incident_constraints(v)) continue;
      CDT::Locate_type lt;
      int li = 0;
      const CDT::Face_handle f = out.locate(v->point(), lt, li);
      if (lt == CDT::FACE && f->is_inside_domain()) generators.push_back(v->point());
    }
    CVT_2::insert_generators_2(out, generators);
    domain_alone.swap(out);
  }
  if (!o.quiet)
    std::cerr << std::setprecision(4) << "cvt2: " << runs.number_of_sliding_vertices()
              << " boundary vertices slid along " << runs.number_of_runs()
              << " runs; largest deviation from the input now " << runs.max_deviation() << '\n';
}

// The background cell size: that of -n, --cells or --size uniform cells in the domain.
double background_size(const Options& o, std::size_t cells, const CDT& cdt) {
  if (o.size) return *o.size;
  return std::sqrt(2 * domain_area(cdt) /
                   (std::sqrt(3.0) * double(std::max<std::size_t>(cells, 1))));
}

// --constraints conforming: the pairs of generators mirrored across each line, fixed, those of
// a step whose pair is not both strictly inside the domain, or that lies along a constraint,
// left out (noted). Their steps are the size of the `cells` cells: uniform (that of --size if
// given), or where they lie under a sizing (--refine, --density lipschitz).
void insert_conforming_sites(const Options& o, std::size_t cells, const Sizing_choice& sizing,
                             CDT& cdt, std::vector<Point_2>& fixed, Conforming& conforming,
                             CVT_2::Conforming_disks<Point_2>& disks) {
  std::size_t left_out = 0;
  const auto following = [&](const auto& mu) {
    const double scale =
        CVT_2::cell_size_scale_2(cdt, cells, CVT_2::parameters::sizing_field(std::cref(mu)));
    return CVT_2::insert_conforming_sites_2(
        cdt, conforming.lines, [&](const Point_2& p) { return scale * CGAL::to_double(mu(p)); },
        disks, &left_out);
  };
  conforming.pairs = sizing.refinement  ? following(*sizing.refinement)
                     : sizing.lipschitz ? following(*sizing.lipschitz)
                                        : CVT_2::insert_conforming_sites_2(
                                              cdt, conforming.lines, background_size(o, cells, cdt),
                                              disks, &left_out);
  for (const auto& p : conforming.pairs) fixed.push_back(p.left), fixed.push_back(p.right);
  const std::string note =
      CVT_2::internal::conforming_left_out_note(left_out, conforming.pairs, conforming.items);
  if (!note.empty()) std::cerr << "cvt2: note: " << note << '\n';
}

// What can be checked of --top and --bottom before the work: their counts against each other,
// each bottom below its top. Their counts against the cells: check_layer_cells(), before the
// work where barriers split no cell (--cells), else against the grid.
void check_layer(const std::vector<double>& top, const std::vector<double>& bottom) {
  if (top.size() != 1 && bottom.size() != 1 && top.size() != bottom.size())
    throw Usage_error("--top has " + std::to_string(top.size()) + " values and --bottom " +
                      std::to_string(bottom.size()) + " (one, or one a cell each)");
  const std::string bad =
      CVT_2::internal::layer_error(top, bottom, std::max(top.size(), bottom.size()));
  if (!bad.empty()) throw Usage_error(bad);  // as write_disv() says it
}

// Notes that the vertices of the boundary and the lines are generators too, where they are
// many and much closer than --boundary resample would space them (2 cell sizes): a finely
// digitised coast, not the file's free generators nor a domain resampled before.
void note_dense_lines(const CDT& cdt, std::size_t cells) {
  std::size_t on_lines = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    on_lines += cdt.are_there_incident_constraints(v) && CVT_2::internal::has_domain_face(cdt, v);
  if (on_lines <= 100 || on_lines <= cells / 10) return;
  double length = 0;  // of the lines in the domain
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e)
    if (cdt.is_constrained(*e) &&
        (e->first->is_inside_domain() || e->first->neighbor(e->second)->is_inside_domain()))
      length += std::sqrt(CGAL::to_double(cdt.segment(*e).squared_length()));
  if (on_lines > 1.5 * length / (2 * CVT_2::cell_size_for_cells_2(cdt, cells)))
    std::cerr << "cvt2: note: the domain's " << on_lines << " vertices are generators too, "
              << cells << " cells in all; --boundary resample spaces them to the cell size\n";
}

int run(const Options& o) {
  require_readable("domain", o.domain);
  check_output_paths(o);
  CDT cdt;
  // The DISV's top and bottom read first: a bad file fails before the optimization.
  const std::vector<double> top = number_or_values("--top", o.top);
  const std::vector<double> bottom = number_or_values("--bottom", o.bottom);
  if (!o.disv.empty()) check_layer(top, bottom);
  auto data = CVT_2::IO::read_domain_data<K>(o.domain);
  // Conforming lines (--constraints conforming, or a GeoJSON feature's "kind") are not
  // constraints, only where faces will lie.
  Kinds kinds;
  kinds.by_default = o.barriers ? "barrier" : o.conforming ? "conforming" : "slit";
  Conforming conforming;
  if (auto* w = std::get_if<1>(&data.description)) {
    kinds.of_item = w->item_kinds;
    if (std::all_of(kinds.of_item.begin(), kinds.of_item.end(),
                    [](const std::string& k) { return k.empty(); }))
      kinds.of_item.clear();
    std::size_t kept = 0;
    for (std::size_t i = 0; i < w->polylines.size(); ++i) {
      const std::size_t item = w->polyline_lines[i];
      if (kinds.of(std::int64_t(item)) == "conforming") {
        conforming.lines.push_back(std::move(w->polylines[i]));
        conforming.items.push_back(std::int64_t(item));
      } else {
        if (kept != i) w->polylines[kept] = std::move(w->polylines[i]);
        w->polyline_lines[kept++] = item;
      }
    }
    w->polylines.resize(kept);
    w->polyline_lines.resize(kept);
    if (!conforming.lines.empty() && o.slide)
      throw Usage_error(
          "--boundary slide and conforming lines do not go together yet (the sliding vertices "
          "would not keep out of the lines' circles): use --boundary resample");
  } else if (o.conforming) {
    throw Usage_error(
        "--constraints conforming takes its lines from a .wkt or .geojson file (LINESTRING), "
        "not from a .poly file");
  }
  if (!o.disv.empty() && o.cells && !kinds.any_barrier())
    check_layer_cells(top, bottom, *o.cells, true);
  CVT_2::IO::insert_domain(cdt, data);
  const CVT_2::IO::Domain_file& domain = data.file;
  note_repeated(domain.repeated);
  const bool counted = o.cells || o.size;
  const std::size_t default_n =
      o.points ? *o.points : (domain.number_of_generators == 0 && o.points_in.empty() ? 1000 : 0);
  CVT_2::IO::Metadata metadata{{"program", std::string("cvt2 ") + CVT_2_VERSION_STRING},
                               {"domain", o.domain},
                               {"boundary", o.slide      ? "slide"
                                            : o.resample ? "resample"
                                                         : "keep"}};
  // The input lines that --cells-on-constraints and the features' kinds name, by the file's
  // items (a resampled domain's chords named by the lines they replace).
  Segments segments;
  const bool named = !o.cells_on_constraints.empty() || !kinds.of_item.empty();
  if (named) {
    segments = CVT_2::IO::domain_segments(data);
    std::vector<std::string> on_earlier = CVT_2::IO::segments_on_earlier_ones(cdt, segments);
    if (!on_earlier.empty()) on_earlier[0] = o.domain + ": " + on_earlier[0];
    note_first(on_earlier, "lie on others");
  }
  CVT_2::Sliding_runs_2<CDT> runs;  // --boundary slide: the runs the resampled vertices slide on
  if (o.resample) resample(o, default_n, cdt, metadata, runs, named ? &segments : nullptr);
  if (o.barriers || o.conforming)
    metadata.emplace_back("constraints", o.barriers ? "barrier" : "conforming");
  if (!kinds.of_item.empty()) metadata.emplace_back("constraint_kinds", "by feature");
  CDT domain_alone;  // for --domain-out: the domain and the file's own generators, no others
  if (!o.domain_out.empty()) domain_alone = cdt;
  // The sizing's default sizes are the boundary edges, before generators split any.
  Sizing_choice sizing;
  if (o.lipschitz)
    sizing.lipschitz.emplace(
        cdt, o.lipschitz_k.value_or(0.1),
        o.boundary_size ? std::optional<K::FT>(*o.boundary_size) : std::nullopt);
  // Points given outside a resampled domain: inside the input's, where a chord cut a corner?
  const auto resampled_hint = [&o](const auto& insert) {
    try {
      return insert();
    } catch (const CVT_2::Domain_error& e) {
      if (!o.resample || std::string(e.what()).find("outside") == std::string::npos) throw;
      throw CVT_2::Domain_error(std::string(e.what()) +
                                    " (the domain as --boundary resample left it, whose chords "
                                    "cut corners by up to the deviation bound; points in the "
                                    "domain file, as POINT, are kept inside; --boundary-"
                                    "tolerance T puts points given within T onto the boundary)",
                                e.index());
    }
  };
  if (!o.points_in.empty()) {
    require_readable("points", o.points_in);
    const auto points = CVT_2::IO::read_points<Point_2>(o.points_in);
    if (points.constrained_skipped > 0)
      std::cerr << "cvt2: note: " << o.points_in << ": " << points.constrained_skipped
                << " constrained generators ('x y 1') skipped: the domain gives them\n";
    note_repeated_points(o.points_in, points);
    const auto moved = resampled_hint([&] {
      return o.boundary_tolerance
                 ? CVT_2::IO::insert_points(
                       cdt, points, CVT_2::parameters::boundary_tolerance(*o.boundary_tolerance))
                 : CVT_2::IO::insert_points(cdt, points);
    });
    const std::string note = CVT_2::IO::moved_points_note(points, moved);
    if (!note.empty()) std::cerr << "cvt2: note: " << note << '\n';
  }
  // --fixed-points: generators that never move, where they are given (or where the boundary
  // tolerance moved them).
  std::vector<Point_2> fixed;
  if (!o.fixed_points.empty()) {
    require_readable("fixed points", o.fixed_points);
    const auto points = CVT_2::IO::read_points<Point_2>(o.fixed_points);
    note_repeated_points(o.fixed_points, points);
    const auto moved = resampled_hint([&] { return CVT_2::IO::insert_points(cdt, points); });
    fixed = points.points;
    for (std::size_t i = 0; i < moved.moved.size(); ++i) fixed[moved.moved[i]] = moved.moved_to[i];
    const std::string note = CVT_2::IO::moved_points_note(points, moved);
    if (!note.empty()) std::cerr << "cvt2: note: " << note << '\n';
  }
  // --cells, --size: the count asked for, checked before any conforming site is placed
  const auto cells_wanted = [&] {
    const double wanted =
        o.cells ? double(*o.cells)
                : std::round(CVT_2::cells_for_cell_size_2(cdt, *o.size, spacing_ratio(o)));
    if (!(wanted <= double(std::int64_t(1) << 53)))
      throw Usage_error(std::string(o.cells ? "--cells" : "--size") + " asks for " +
                        CVT_2::internal::number_text(wanted) + " cells: too many");
    return wanted;
  };
  if (counted) cells_wanted();
  // --refine, before the conforming lines' steps, which follow it. The background: uniform
  // cells, as many as asked for (--cells, --size: the lines' pairs among them; -n: the N points
  // and the domain's vertices, the pairs not yet placed).
  const std::size_t cells_asked =
      counted ? std::size_t(cells_wanted())
              : default_n + CVT_2::internal::number_of_vertices_in_domain(cdt);
  if (!o.refine.empty()) {
    const double background = background_size(o, cells_asked, cdt);
    sizing.refinement.emplace(background);
    for (const auto& [x, y, size, radius] : o.refine) {
      if (size >= background)  // the background is the largest size: nothing to refine
        std::cerr << "cvt2: note: --refine " << x << ' ' << y << ' ' << size << ' ' << radius
                  << ": the size is not below the background cells' (" << background
                  << "): no finer cells there\n";
      sizing.refinement->add_point(Point_2(x, y), std::min(size, background), radius);
    }
  }
  CVT_2::Conforming_disks<Point_2> disks;
  if (!conforming.lines.empty())
    insert_conforming_sites(o, cells_asked, sizing, cdt, fixed, conforming, disks);
  const std::size_t present = CVT_2::internal::number_of_vertices_in_domain(cdt);
  std::size_t n = default_n;
  if (counted) {
    const double wanted = cells_wanted();
    // (the conforming lines' generators: two a step, a step for each of their segments at least)
    const std::size_t paired = 2 * CVT_2::internal::number_of_steps(conforming.pairs);
    if (wanted < double(present))
      throw Usage_error(
          std::string(o.cells ? "--cells" : "--size") + " asks for " +
          std::to_string(static_cast<long long>(wanted)) + " cells, fewer than the " +
          std::to_string(present) + " vertices of the domain and the points" +
          (paired > present / 2
               ? " (" + std::to_string(paired) +
                     " of them the conforming lines' pairs, two for each of their segments at "
                     "least: simplify the lines for fewer)"
           : o.resample ? ""
                        : " (--boundary resample spaces the domain's vertices)"));
    n = static_cast<std::size_t>(wanted) - present;
  }
  if (!o.resample) note_dense_lines(cdt, present + n);
  // for the density's note (a density only): whether every free generator is drawn from it
  const bool none_given =
      !sizing.is_uniform() && CVT_2::internal::movable_generators(cdt, fixed).empty();
  const std::size_t redistributed = redistribute(o, sizing, fixed, cdt);
  n += redistributed;
  const bool drawn = redistributed > 0 || none_given;
  const std::size_t before = cdt.number_of_vertices();
  insert_random_points(n, o, sizing, cdt, disks, redistributed > 0);
  // Where the coordinates are coarse for the domain (a double near 1e15 is an eighth), drawn
  // points can fall on one another, and are merged.
  const std::size_t added = cdt.number_of_vertices() - before;
  if (added < n)
    std::cerr << "cvt2: note: " << n - added << " of the " << n
              << " random points fell on others, their coordinates rounded to doubles (the "
                 "domain is small for its coordinates' magnitude), and were merged: "
              << n - added << " cells fewer\n";
  // --boundary slide: where each constrained vertex was, to follow the named lines' ends
  std::optional<CVT_2::Slid_vertices_2<CDT>> slid;
  if (o.slide) slid.emplace(cdt);
  const CVT_2::Optimization_result r =
      cvt2_program::optimize(cdt, o, sizing, fixed, disks, o.slide ? &runs : nullptr);
  if (o.slide) slid_domain(o, cdt, runs, *slid, segments, domain_alone, metadata);
  // what breaks the faces on the lines, if any
  const std::string inside = CVT_2::internal::conforming_disks_note(cdt, disks);
  if (!inside.empty()) std::cerr << "cvt2: note: " << inside << '\n';
  // a stop far from the optimum: stop=stalled
  const std::string far = CVT_2::internal::density_response_note(r.density_response, drawn);
  if (!far.empty()) std::cerr << "cvt2: note: " << far << '\n';
  const BVD bvd(cdt);
  write_outputs(o, cdt, bvd, metadata, domain_alone, segments, kinds, conforming, top, bottom);
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
    if (o.version) {
      std::cout << "cvt2 " << CVT_2_VERSION_STRING << '\n';
      return EXIT_SUCCESS;
    }
    return run(o);
  } catch (const Usage_error& e) {
    std::cerr << "cvt2: " << e.what() << "\ncvt2: try 'cvt2 --help'\n";
  } catch (const std::bad_alloc&) {
    std::cerr << "cvt2: out of memory: a generator needs up to "
              << CVT_2::internal::peak_bytes_per_generator(Options().lbfgs)
              << " bytes during the optimization (--points, the input files)\n";
  } catch (const std::exception& e) {
    std::cerr << "cvt2: " << e.what() << '\n';
  }
  return EXIT_FAILURE;
}
