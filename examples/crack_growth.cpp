// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// crack_growth [N] [STEPS] [OUT.txt]: a crack grown step by step through a converged CVT of N
// generators (default 10^5) in the unit square. It starts on the left side at y = 0.3 and grows
// toward (1, 0.4) by one cell size h = 1/sqrt(N) a step (STEPS steps, default 60), with a
// vertex every h: a Constraint_editor_2 keeps the bounded Voronoi diagram current, then five
// Lloyd iterations relax the free generators within two rings of the changed cells
// (lloyd_optimize_2 with `region`), evaluated around them only.
//
// After the last step, the crack-opening displacement u = sqrt(r) sin(theta / 2) around the
// tip, which jumps by 2 sqrt(r) across the crack, is interpolated near the crack with Sibson's
// coordinates on the diagram: with lips (natural_neighbor_matrix_2 with `lips(true)`: a node
// on the crack has one value per side) and without (one value, the mean of the sides). Prints
// the median times of a step's parts against a rebuild of the diagram, and the largest errors;
// writes the samples to OUT.txt, one a line: `x y exact with_lips without_lips`.
#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/Constraint_editor_2.h>
#include <CVT_2/Cvt_triangulation_2.h>
#include <CVT_2/IO/read_poly.h>
#include <CVT_2/insert_generators_2.h>
#include <CVT_2/lbfgs_optimize_2.h>
#include <CVT_2/lloyd_optimize_2.h>
#include <CVT_2/natural_neighbor_coordinates_2.h>
#include <CVT_2/random_points_in_domain_2.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using Vector = K::Vector_2;
using CDT = CVT_2::Cvt_triangulation_2<K>;
using BVD = CVT_2::Bounded_voronoi_diagram_2<CDT>;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double median(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  return x.empty() ? 0 : x[x.size() / 2];
}

// The crack-opening displacement around `tip`, the crack behind it along -direction: theta is
// measured from `direction`, so the crack's faces are theta = +pi (left) and -pi (right), where
// u = +-sqrt(r).
struct Opening {
  Point tip;
  Vector direction;  // unit
  double at(const Point& p) const {
    const Vector d = p - tip;
    return std::sqrt(std::sqrt(d.squared_length())) *
           std::sin(std::atan2(CGAL::determinant(direction, d), d * direction) / 2);
  }
  double on_face(const Point& p, int side) const {
    return side * std::sqrt(std::sqrt(CGAL::squared_distance(p, tip)));
  }
};

}  // namespace

int main(int argc, char* argv[]) {
  try {
    const std::size_t n = argc > 1 ? std::stoul(argv[1]) : 100000;
    const int steps = argc > 2 ? std::stoi(argv[2]) : 60;
    if (steps < 1) throw std::invalid_argument("STEPS must be at least 1");
    const std::string out = argc > 3 ? argv[3] : "crack_growth.txt";
    CVT_2::IO::Poly_data<Point> poly;
    poly.vertices = {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)};
    poly.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
    poly.vertex_lines.assign(4, 0);
    poly.segment_lines.assign(4, 0);
    CDT cdt;
    CVT_2::IO::insert_poly(cdt, poly);
    CVT_2::insert_generators_2(
        cdt, CVT_2::random_points_in_domain_2(cdt, n, CVT_2::parameters::random_seed(1)));
    auto start = Clock::now();
    CVT_2::lbfgs_optimize_2(cdt);
    std::cout << "crack_growth: a CVT of " << n << " generators in " << seconds_since(start)
              << " s\n";

    BVD bvd(cdt);
    CVT_2::Constraint_editor_2<CDT> editor(cdt, bvd);
    const double h = 1 / std::sqrt(double(n));
    const Vector direction = Vector(1, 0.4) / std::sqrt(1.16);
    Point tip(0, 0.3);
    const auto crack = editor.insert_constraint(std::vector<Point>{tip, tip + h * direction});
    tip = tip + h * direction;
    std::vector<double> edit_time, relax_time, changed;
    for (int step = 0; step < steps && tip.x() + h < 1 && tip.y() + h < 1; ++step) {
      tip = tip + h * direction;
      start = Clock::now();
      editor.extend_constraint(crack, tip, h);
      edit_time.push_back(seconds_since(start));
      changed.push_back(double(editor.report().changed_cells.size()));
      std::vector<Point> region;
      for (const auto v : editor.report().changed_cells) region.push_back(v->point());
      start = Clock::now();
      CVT_2::lloyd_optimize_2(cdt, CVT_2::parameters::region(region)
                                       .region_rings(2)
                                       .number_of_iterations(5)
                                       .move_ratio_bound(0));
      relax_time.push_back(seconds_since(start));
    }
    // a rebuild of the same diagram: Algorithm 1 on every face, then every cell
    std::vector<double> rebuild_time;
    for (int k = 0; k < 3; ++k) {
      start = Clock::now();
      const BVD rebuilt(cdt);
      std::size_t cells = 0;
      rebuilt.for_each_cell([&](auto, const auto&) { ++cells; });
      rebuild_time.push_back(seconds_since(start));
      if (cells == 0) throw std::logic_error("no cell");
    }
    const double rebuild = median(rebuild_time);
    std::cout << "crack_growth: " << edit_time.size() << " steps of " << h
              << "; median changed cells " << median(changed) << "; median times: edit "
              << median(edit_time) * 1e6 << " us, relaxation (5 Lloyd iterations, 2 rings) "
              << median(relax_time) * 1e6 << " us; a rebuild " << rebuild * 1e3 << " ms ("
              << rebuild / median(edit_time) << "x an edit, " << rebuild / median(relax_time)
              << "x a relaxation)\n";

    // The field at the nodes: on a node along the crack, one value for each lip, the field's
    // limit from the side that lip faces (found by looking from a point just off the crack).
    const Opening field{tip, direction};
    const Vector left(-direction.y(), direction.x());
    std::vector<Point> queries;
    for (double s = 0.1; s < 0.9; s += 0.0125)
      for (double t = -3; t <= 3; t += 0.25) {
        const Point q = Point(0, 0.3) + s * (tip - Point(0, 0.3)) + t * h * left;
        if (t != 0) queries.push_back(q);
      }
    const auto m = CVT_2::natural_neighbor_matrix_2(bvd, queries, CVT_2::parameters::lips(true));
    const std::size_t nodes = m.nodes.size();
    const auto& on_crack = editor.vertices_in_constraint(crack);
    const auto is_on_crack = [&](CDT::Vertex_handle v) {
      return std::find(on_crack.begin(), on_crack.end(), v) != on_crack.end();
    };
    std::vector<double> lipped(nodes + m.lip_nodes.size()), plain(nodes);
    for (std::size_t j = 0; j < nodes; ++j)  // without lips, a crack node has the sides' mean
      lipped[j] = plain[j] = is_on_crack(m.nodes[j]) ? 0 : field.at(m.nodes[j]->point());
    for (std::size_t k = 0, first = 0; k < m.lip_nodes.size(); ++k) {
      if (k > 0 && m.lip_nodes[k] != m.lip_nodes[k - 1]) first = k;  // a node's lips in a row
      const auto v = m.nodes[m.lip_nodes[k]];
      const int up = CVT_2::node_lip_2(bvd, v, v->point() + 1e-3 * h * left);
      lipped[nodes + k] = field.on_face(v->point(), int(k - first) == up ? 1 : -1);
    }
    std::ofstream os(out);
    if (!os) throw std::runtime_error("cannot write " + out);
    os.precision(10);
    double worst_lips = 0, worst_plain = 0;
    for (std::size_t r = 0; r < queries.size(); ++r) {
      double with = 0, without = 0;
      for (std::size_t e = m.row_offsets[r]; e < m.row_offsets[r + 1]; ++e) {
        const std::size_t c = m.columns[e];
        with += m.values[e] * lipped[c];
        without += m.values[e] * plain[c < nodes ? c : m.lip_nodes[c - nodes]];
      }
      const double exact = field.at(queries[r]);
      worst_lips = std::max(worst_lips, std::abs(with - exact));
      worst_plain = std::max(worst_plain, std::abs(without - exact));
      os << queries[r].x() << ' ' << queries[r].y() << ' ' << exact << ' ' << with << ' ' << without
         << '\n';
    }
    std::cout << "crack_growth: the opening displacement at " << queries.size()
              << " points near the crack, largest error: with lips " << worst_lips << ", without "
              << worst_plain << "; samples in " << out << '\n';
  } catch (const std::exception& e) {
    std::cerr << "crack_growth: " << e.what() << '\n';
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
