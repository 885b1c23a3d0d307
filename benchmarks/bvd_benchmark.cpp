// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// bvd_benchmark: our BVD and CGAL's Constrained_voronoi_diagram_2, timed against a CDT build,
// and the mesh of our diagram against the cell pass it is built from.
#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/Bvd_mesh_2.h>
#include <CVT_2/Cvt_triangulation_2.h>
#include <CVT_2/IO/read_poly.h>
#include <CVT_2/insert_generators_2.h>
#include <CVT_2/internal/parallel/Face_chunks.h>
#include <CVT_2/mark_domain_2.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_voronoi_diagram_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <random>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Itag = CGAL::No_constraint_intersection_requiring_constructions_tag;
using Vb = CGAL::Triangulation_vertex_base_2<K>;
using CDT = CVT_2::Cvt_triangulation_2<K>;  // ours: ids in the vertices, Bvd_face_base_2 faces
using Tds = CDT::Triangulation_data_structure;
using Bvd = CVT_2::Bounded_voronoi_diagram_2<CDT>;
using Mesh = CVT_2::Bvd_mesh_2<Bvd>;
// CGAL's diagram keeps its tags in CGAL's constrained Delaunay face base.
using Tds2 = CGAL::Triangulation_data_structure_2<Vb, CGAL::Delaunay_mesh_face_base_2<K>>;
using CDT2 = CGAL::Constrained_Delaunay_triangulation_2<K, Tds2, Itag>;
using Cvd = CGAL::Constrained_voronoi_diagram_2<CDT2>;
// The baseline: CGAL's constrained Delaunay triangulation with its default face base.
using Tds0 =
    CGAL::Triangulation_data_structure_2<Vb,
                                         CGAL::Constrained_Delaunay_triangulation_face_base_2<K>>;
using CDT0 = CGAL::Constrained_Delaunay_triangulation_2<K, Tds0, Itag>;
using Poly = CVT_2::IO::Poly_data<K::Point_2>;
using Clock = std::chrono::steady_clock;

namespace {

struct Row {
  std::string domain;
  std::size_t n, vertices, cgal_cells;
  double build, tag, cells, cells2, cgal_tag, cgal_cells_s, bytes;
  double mesh, mesh2, mesh_bytes;  // the mesh on 1 and 2 threads; its bytes per generator
};
std::vector<Row> rows;  // for the table printed after the run

double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

// Uniform in the domain: rejection against its bounding box, fixed seed.
std::vector<K::Point_2> random_points(const Poly& poly, std::size_t n) {
  CDT domain;
  CVT_2::IO::insert_poly(domain, poly);
  const CGAL::Bbox_2 box = CGAL::bbox_2(poly.vertices.begin(), poly.vertices.end());
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> x(box.xmin(), box.xmax()), y(box.ymin(), box.ymax());
  std::vector<K::Point_2> points;
  points.reserve(n);
  while (points.size() < n) {
    const K::Point_2 p(x(rng), y(rng));
    if (CVT_2::is_in_domain_2(domain, p)) points.push_back(p);
  }
  return points;
}

void bm_bvd(benchmark::State& state, const std::string& file) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  Poly poly;
  std::vector<K::Point_2> points;
  try {
    poly = CVT_2::IO::read_poly<K::Point_2>(CVT_2_DATA_DIR "/" + file);
    points = random_points(poly, n);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  // CGAL's diagram has no domain: it gets the same vertices, constraints and points.
  CDT2 cdt2;
  std::vector<CDT2::Vertex_handle> poly_vertices;
  for (const auto& p : poly.vertices) poly_vertices.push_back(cdt2.insert(p));
  for (const auto& s : poly.segments)
    cdt2.insert_constraint(poly_vertices[s[0]], poly_vertices[s[1]]);
  cdt2.insert(points.begin(), points.end());
  Cvd cvd(cdt2);

  std::vector<double> build, mark, tag, cells, cells2, cgal_tag, cgal_cells, mesh, mesh2;
  double mesh_bytes = 0;
  std::size_t vertices = 0, faces = 0, ours_built = 0, cgal_built = 0;
  for (auto _ : state) {
    auto t = Clock::now();
    {
      CDT0 cdt0;  // what a user of plain CGAL builds: vertices, constraints, points
      std::vector<CDT0::Vertex_handle> vh;
      for (const auto& p : poly.vertices) vh.push_back(cdt0.insert(p));
      for (const auto& s : poly.segments) cdt0.insert_constraint(vh[s[0]], vh[s[1]]);
      cdt0.insert(points.begin(), points.end());
      build.push_back(since(t));
    }

    CDT cdt;  // ours, the same way
    CVT_2::IO::insert_poly(cdt, poly);
    cdt.insert(points.begin(), points.end());

    t = Clock::now();
    CVT_2::mark_domain_2(cdt, poly.holes);  // the points made new faces, outside until marked
    mark.push_back(since(t));

    t = Clock::now();
    const Bvd bvd(cdt);
    tag.push_back(since(t));

    t = Clock::now();
    std::size_t total = 0;
    ours_built = 0;
    bvd.for_each_cell([&](Bvd::Vertex_handle, const std::vector<Bvd::Cell_vertex>& cell) {
      total += cell.size();
      ++ours_built;
    });
    benchmark::DoNotOptimize(total);
    cells.push_back(since(t));

    t = Clock::now();  // the same cells on two threads, in the chunks Lloyd iteration uses
    const CVT_2::internal::Face_chunks<CDT> chunks(cdt);
    std::vector<std::size_t> chunk_totals(chunks.size(), 0);
    chunks.for_each(
        [&](std::size_t c, auto first, auto last) {
          CVT_2::internal::for_each_cell_in_faces(
              bvd, first, last, [&](Bvd::Vertex_handle, const std::vector<Bvd::Cell_vertex>& cell) {
                chunk_totals[c] += cell.size();
              });
        },
        2);
    benchmark::DoNotOptimize(chunk_totals.data());
    cells2.push_back(since(t));

    for (const unsigned threads : {1u, 2u}) {
      t = Clock::now();
      const Mesh m(bvd, threads);
      (threads == 1 ? mesh : mesh2).push_back(since(t));
      // What the mesh keeps: points, cycles with their sides, per cell an offset, a generator,
      // a flag; the constraints.
      std::size_t entries = 0;
      for (std::size_t k = 0; k < m.number_of_cells(); ++k) entries += m.cell(k).size();
      mesh_bytes =
          (double(m.number_of_vertices()) * (sizeof(Mesh::Point_2) + 1) +
           double(entries) * (sizeof(Mesh::Index) + sizeof(Mesh::Side)) +
           double(m.number_of_cells()) * (sizeof(std::size_t) + sizeof(Mesh::Vertex_handle) + 1) +
           double(m.constraints().size()) * sizeof(Mesh::Constraint)) /
          double(m.number_of_cells());
    }

    t = Clock::now();
    cvd.tag_faces_blind();
    cgal_tag.push_back(since(t));

    t = Clock::now();
    std::size_t cgal_total = 0;
    cgal_built = 0;
    for (auto v = cdt2.finite_vertices_begin(); v != cdt2.finite_vertices_end(); ++v) {
      const auto cell = cvd.cvd_cell(v);
      cgal_total += cell.number_of_vertices();
      cgal_built += !cell.is_empty();
    }
    benchmark::DoNotOptimize(cgal_total);
    cgal_cells.push_back(since(t));

    state.SetIterationTime(build.back() + tag.back() + cells.back() + cgal_tag.back() +
                           cgal_cells.back() + mesh.back() + mesh2.back());
    vertices = cdt.number_of_vertices();
    faces = cdt.number_of_faces();
  }

  Row r{
      file.substr(0, file.rfind('.')),
      n,
      vertices,
      cgal_built,
      median(build),
      median(tag),
      median(cells),
      median(cells2),
      median(cgal_tag),
      median(cgal_cells),
      (double(sizeof(Tds::Face)) - double(sizeof(Tds0::Face))) * double(faces) / double(vertices) +
          double(sizeof(Tds::Vertex)) - double(sizeof(Tds0::Vertex)),
      median(mesh),
      median(mesh2),
      mesh_bytes};
  auto& c = state.counters;
  c["N"] = double(n);
  c["vertices"] = double(vertices);
  c["cdt_build_s"] = r.build;
  c["ours_mark_s"] = median(mark);
  c["ours_tag_s"] = r.tag;
  c["ours_cells_s"] = r.cells;
  c["ours_cells_2_threads_s"] = r.cells2;
  c["cgal_tag_s"] = r.cgal_tag;
  c["cgal_cells_s"] = r.cgal_cells_s;
  c["ours/cdt"] = (r.tag + r.cells) / r.build;
  c["cgal/cdt"] = (r.cgal_tag + r.cgal_cells_s) / r.build;
  c["ours_cells/vertices"] = double(ours_built) / double(vertices);
  c["cgal_cells/vertices"] = double(cgal_built) / double(vertices);
  c["bytes/vertex"] = r.bytes;
  c["mesh_s"] = r.mesh;
  c["mesh_2_threads_s"] = r.mesh2;
  c["mesh/cells"] = r.mesh / r.cells;
  c["mesh_bytes/generator"] = r.mesh_bytes;
  const auto same = [&r](const Row& x) { return x.domain == r.domain && x.n == r.n; };
  const auto it = std::find_if(rows.begin(), rows.end(), same);
  if (it == rows.end())
    rows.push_back(r);
  else
    *it = r;
}

}  // namespace

int main(int argc, char* argv[]) {
  for (const std::string file : {"us_massachusetts_counties.poly", "earcut_eberly6.poly"})
    for (const long n : {10000L, 100000L, 1000000L})
      benchmark::RegisterBenchmark(("bvd/" + file.substr(0, file.rfind('.'))).c_str(), bm_bvd, file)
          ->Arg(n)
          ->Iterations(n < 1000000 ? 5 : 3)
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();

  std::printf(
      "\n| domain | N | cdt build s | ours tag s | ours cells s | cells on 2 threads s "
      "(speed-up) | ours/cdt | cgal tag s | cgal cells s | cgal/cdt | cgal cells / "
      "vertices | bytes/vertex |\n"
      "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n");
  for (const Row& r : rows)
    std::printf(
        "| %s | %zu | %.4f | %.4f | %.4f | %.4f (%.2fx) | %.3f | %.4f | %.4f | %.3f | "
        "%zu / %zu | %.1f |\n",
        r.domain.c_str(), r.n, r.build, r.tag, r.cells, r.cells2, r.cells / r.cells2,
        (r.tag + r.cells) / r.build, r.cgal_tag, r.cgal_cells_s,
        (r.cgal_tag + r.cgal_cells_s) / r.build, r.cgal_cells, r.vertices, r.bytes);
  std::printf(
      "\n| domain | N | ours cells s | mesh s | mesh / cells | mesh on 2 threads s | "
      "mesh on 2 threads / cells | mesh bytes/generator |\n"
      "|---|--:|--:|--:|--:|--:|--:|--:|\n");
  for (const Row& r : rows)
    std::printf("| %s | %zu | %.4f | %.4f | %.2f | %.4f | %.2f | %.0f |\n", r.domain.c_str(), r.n,
                r.cells, r.mesh, r.mesh / r.cells, r.mesh2, r.mesh2 / r.cells, r.mesh_bytes);
  return 0;
}
