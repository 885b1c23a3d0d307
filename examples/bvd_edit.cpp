// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// bvd_edit DOMAIN POINTS EDITS [--cells-out FILE] [--relax-rings K --relax-iterations M]
//          [--verify]
// Edits the constraints of the bounded Voronoi diagram of a domain and points, one edit a line
// of EDITS ('#' starts a comment):
//   insert x1 y1 x2 y2 [x3 y3 ...]   a new polyline constraint (ids 0, 1, ... in order)
//   extend ID x y [h]                constraint ID grows from its last vertex to (x, y), with
//                                    vertices at most h apart on the way
//   remove ID                        constraint ID goes; its vertices stay as free generators
//   move x y x' y'                   the constrained vertex at (x, y) moves to (x', y')
// and prints a line an edit: edit=K changed_cells=C retagged_faces=F seconds=S. After the last
// edit it writes the cells in the format of bvd_cells to FILE. With --relax-rings K, after each
// edit M Lloyd iterations move the free generators within K rings of the changed cells, the
// diagram evaluated around them only.
// --verify compares, after each edit, the tags with those of a rebuild, and fails if they
// differ.
#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/Constraint_editor_2.h>
#include <CVT_2/Cvt_triangulation_2.h>
#include <CVT_2/IO/read_domain.h>
#include <CVT_2/IO/read_points.h>
#include <CVT_2/IO/write_cells.h>
#include <CVT_2/lloyd_optimize_2.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using CDT = CVT_2::Cvt_triangulation_2<K>;
using BVD = CVT_2::Bounded_voronoi_diagram_2<CDT>;
using Editor = CVT_2::Constraint_editor_2<CDT>;
using Point = K::Point_2;

namespace {

struct Edit {
  std::string verb;
  std::vector<double> numbers;
  std::size_t line;
};

std::vector<Edit> read_edits(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file + ": cannot open");
  std::vector<Edit> edits;
  std::string text;
  for (std::size_t line = 1; std::getline(in, text); ++line) {
    const auto hash = text.find('#');
    if (hash != std::string::npos) text.erase(hash);
    std::istringstream words(text);
    Edit e{{}, {}, line};
    if (!(words >> e.verb)) continue;
    const auto fail = [&](const std::string& what, const std::string& token = {}) {
      throw CVT_2::IO::Parse_error(file, line, what, token);
    };
    for (std::string w; words >> w;) {
      char* end = nullptr;
      const double x = std::strtod(w.c_str(), &end);
      if (end != w.c_str() + w.size() || !std::isfinite(x)) fail("not a finite number", w);
      e.numbers.push_back(x);
    }
    const std::size_t n = e.numbers.size();
    const auto is_id = [](double x) { return x >= 0 && x == std::floor(x) && x < 1e15; };
    if (e.verb == "insert") {
      if (n < 4 || n % 2 != 0) fail("'insert' takes two points or more: x1 y1 x2 y2 ...");
    } else if (e.verb == "extend") {
      if ((n != 3 && n != 4) || !is_id(e.numbers[0]))
        fail("'extend' takes a constraint id, a point and an optional spacing: ID x y [h]");
    } else if (e.verb == "remove") {
      if (n != 1 || !is_id(e.numbers[0])) fail("'remove' takes a constraint id: ID");
    } else if (e.verb == "move") {
      if (n != 4) fail("'move' takes two points: x y x' y'");
    } else {
      fail("unknown edit (insert, extend, remove, move)", e.verb);
    }
    edits.push_back(e);
  }
  return edits;
}

// Whether the tags of the faces are those a rebuild gives.
bool tags_as_rebuilt(const CDT& cdt, BVD& bvd) {
  std::vector<std::pair<CDT::Face_handle, CDT::Edge>> tags;
  std::vector<CDT::Face_handle> faces;
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) {
    faces.push_back(f);
    tags.emplace_back(f, f->is_blinded() ? f->blinding_edge() : CDT::Edge());
  }
  bvd.update();
  for (const auto& [f, e] : tags)
    if (f->is_blinded() != (e.first != CDT::Face_handle()) ||
        (f->is_blinded() && f->blinding_edge() != e))
      return false;
  return true;
}

// The value of a count option: an integer >= 0, or the program stops with a message.
int count(const std::string& option, const std::string& text) {
  char* end = nullptr;
  const long n = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || n < 0 || n > 1000000) {
    std::cerr << "bvd_edit: " << option << " takes an integer from 0 to 10^6, not '" << text
              << "'\n";
    std::exit(EXIT_FAILURE);
  }
  return int(n);
}

}  // namespace

int main(int argc, char* argv[]) {
  std::vector<std::string> files;
  std::string cells_out;
  int rings = -1, iterations = -1;  // -1: not given
  bool verify = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::cerr << "bvd_edit: " << a << " needs a value\n";
        std::exit(EXIT_FAILURE);
      }
      return argv[++i];
    };
    if (a == "--cells-out")
      cells_out = value();
    else if (a == "--relax-rings")
      rings = count(a, value());
    else if (a == "--relax-iterations")
      iterations = count(a, value());
    else if (a == "--verify")
      verify = true;
    else if (!a.empty() && a[0] == '-') {
      std::cerr << "bvd_edit: unknown option " << a << '\n';
      return EXIT_FAILURE;
    } else
      files.push_back(a);
  }
  if (files.size() != 3) {
    std::cerr << "usage: bvd_edit DOMAIN POINTS EDITS [--cells-out FILE] [--relax-rings K "
                 "--relax-iterations M] [--verify]\n";
    return EXIT_FAILURE;
  }
  if ((rings >= 0) != (iterations >= 0)) {
    std::cerr << "bvd_edit: --relax-rings and --relax-iterations go together\n";
    return EXIT_FAILURE;
  }
  if (!cells_out.empty()) {  // what would stop the output, found before the work
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::path out(cells_out);
    const fs::path folder = out.has_parent_path() ? out.parent_path() : fs::path(".");
    std::string problem;
    for (const std::string& input : files)
      if (fs::equivalent(out, input, error)) problem = "is the input " + input;
    if (fs::is_directory(out, error))
      problem = "is a directory";
    else if (!fs::is_directory(folder, error))
      problem = error ? "is in a directory that cannot be checked (" + error.message() + ")"
                      : "is in no directory";
    if (!problem.empty()) {
      std::cerr << "bvd_edit: --cells-out " << cells_out << ' ' << problem << '\n';
      return EXIT_FAILURE;
    }
  }
  try {
    const std::vector<Edit> edits = read_edits(files[2]);  // a bad line fails before any work
    CDT cdt;
    CVT_2::IO::read_domain(files[0], cdt);
    CVT_2::IO::insert_points(cdt, CVT_2::IO::read_points<Point>(files[1]));
    BVD bvd(cdt);
    Editor editor(cdt, bvd);
    std::size_t k = 0;
    for (const Edit& e : edits) {
      const auto& x = e.numbers;
      const auto start = std::chrono::steady_clock::now();
      try {
        if (e.verb == "insert") {
          std::vector<Point> points;
          for (std::size_t i = 0; i + 1 < x.size(); i += 2) points.emplace_back(x[i], x[i + 1]);
          editor.insert_constraint(points);
        } else if (e.verb == "extend") {
          editor.extend_constraint(std::size_t(x[0]), Point(x[1], x[2]), x.size() > 3 ? x[3] : 0);
        } else if (e.verb == "remove") {
          editor.remove_constraint(std::size_t(x[0]));
        } else {
          CDT::Locate_type lt;
          int li;
          const auto f = cdt.locate(Point(x[0], x[1]), lt, li);
          if (lt != CDT::VERTEX)
            throw CVT_2::Domain_error("move: no vertex at " +
                                      CVT_2::internal::to_string(Point(x[0], x[1])));
          editor.move_constrained_vertex(f->vertex(li), Point(x[2], x[3]));
        }
      } catch (const CVT_2::Domain_error& error) {
        throw CVT_2::IO::Parse_error(files[2], e.line, error.what());
      }
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const auto& report = editor.report();
      std::cout << "edit=" << k << " changed_cells=" << report.changed_cells.size()
                << " retagged_faces=" << report.retagged_faces << " seconds=" << seconds << '\n';
      if (verify && !tags_as_rebuilt(cdt, bvd)) {
        std::cerr << "bvd_edit: " << files[2] << ":" << e.line
                  << ": the tags after this edit are not those of a rebuild\n";
        return EXIT_FAILURE;
      }
      if (iterations > 0) {  // a local relaxation: the tags stay current
        std::vector<Point> changed;
        for (const auto v : report.changed_cells) changed.push_back(v->point());
        CVT_2::lloyd_optimize_2(cdt, CVT_2::parameters::number_of_iterations(iterations)
                                         .region(changed)
                                         .region_rings(rings)
                                         .move_ratio_bound(0));
        if (verify && !tags_as_rebuilt(cdt, bvd)) {
          std::cerr << "bvd_edit: " << files[2] << ":" << e.line
                    << ": the tags after the relaxation are not those of a rebuild\n";
          return EXIT_FAILURE;
        }
      }
      ++k;
    }
    if (!cells_out.empty()) {
      std::ofstream out(cells_out);
      CVT_2::IO::write_cells(out, bvd);
      if (!out) throw std::runtime_error(cells_out + ": cannot write");
    }
  } catch (const std::exception& error) {
    std::cerr << "bvd_edit: " << error.what() << '\n';
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
