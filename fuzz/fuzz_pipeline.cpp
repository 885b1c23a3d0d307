// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: the whole pipeline on a fuzzed domain in any of cvt2's formats (.poly, WKT,
// GeoJSON, told apart by the first byte that is not blank): the domain inserted, generators (the
// file's free vertices or points, else seeded random points), the bounded Voronoi diagram and
// one Lloyd step, with oracles: the cells tile the domain, so do the mesh's, the energy is
// finite and does not rise. Half the inputs get pairs of generators a hair from a constraint
// too (thin_pairs()), whose thin cells the mesh must keep.
#include "fuzz_support.h"

#include <CVT_2/IO/read_geojson.h>
#include <CVT_2/IO/read_poly.h>
#include <CVT_2/IO/read_wkt.h>
#include <CVT_2/Lloyd_optimizer_2.h>
#include <CVT_2/insert_generators_2.h>
#include <CVT_2/random_points_in_domain_2.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace {

constexpr std::size_t max_bytes = 8192, max_vertices = 300, random_generators = 20;

std::uint64_t fnv1a(const std::uint8_t* data, std::size_t size) {
  std::uint64_t h = 14695981039346656037ull;
  for (std::size_t i = 0; i < size; ++i) h = (h ^ data[i]) * 1099511628211ull;
  return h;
}

// The domain inserted into cdt, read as the format the text looks like: '{' or '[' starts
// JSON, a letter a WKT keyword, anything else (a digit, '#') a .poly file. Returns whether it
// gave generators, or nothing if it is too large for the pipeline.
std::optional<bool> insert_domain(fuzz::CDT& cdt, const std::string& text) {
  std::istringstream is(text);
  const std::size_t b = text.find_first_not_of(" \t\r\n");
  const char c = b == std::string::npos ? '\0' : text[b];
  if (c == '{' || c == '[' || std::isalpha(static_cast<unsigned char>(c))) {
    const auto w = c == '{' || c == '[' ? CVT_2::IO::read_geojson<fuzz::K>(is, "fuzz.geojson")
                                        : CVT_2::IO::read_wkt<fuzz::K>(is, "fuzz.wkt");
    std::size_t vertices = w.points.size();
    for (const auto& p : w.polygons) {
      vertices += p.outer_boundary().size();
      for (const auto& h : p.holes()) vertices += h.size();
    }
    for (const auto& l : w.polylines) vertices += l.size();
    if (vertices > max_vertices) return std::nullopt;
    CVT_2::IO::insert_wkt(cdt, w);
    return !w.points.empty();
  }
  const auto poly = CVT_2::IO::read_poly<fuzz::Point>(is, "fuzz.poly");
  if (poly.vertices.size() > max_vertices) return std::nullopt;
  CVT_2::IO::insert_poly(cdt, poly);
  std::vector<bool> on_segment(poly.vertices.size(), false);
  for (const auto& s : poly.segments) on_segment[s[0]] = on_segment[s[1]] = true;
  return std::find(on_segment.begin(), on_segment.end(), false) != on_segment.end();
}

// Pairs of generators a hair apart on a line across a constrained edge, 1e-16 to 1e-12 of its
// length inside the domain (the same x beside a horizontal edge): cells that thin, which the
// mesh must keep. Up to three edges, chosen and placed by the input's hash.
std::vector<fuzz::Point> thin_pairs(const fuzz::CDT& cdt, std::uint64_t h) {
  std::vector<fuzz::Point> pairs;
  std::vector<fuzz::CDT::Edge> edges;
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e)
    if (cdt.is_constrained(*e)) edges.push_back(*e);
  for (int i = 0; i < 3 && !edges.empty();
       ++i, h = h * 6364136223846793005ull + 1442695040888963407ull) {
    auto [f, j] = edges[(h >> 8) % edges.size()];
    if (!f->is_inside_domain() || cdt.is_infinite(f)) std::tie(f, j) = cdt.mirror_edge({f, j});
    if (!f->is_inside_domain() || cdt.is_infinite(f)) continue;
    const fuzz::Point& p = f->vertex(fuzz::CDT::ccw(j))->point();
    const fuzz::Point& q = f->vertex(fuzz::CDT::cw(j))->point();
    const double t = 0.1 + 0.8 * double((h >> 20) & 1023) / 1023;
    const double d = std::pow(10.0, -12.0 - 4.0 * double((h >> 40) & 255) / 255);
    const double dx = q.x() - p.x(), dy = q.y() - p.y();  // the domain is to its left
    const fuzz::Point m(p.x() + t * dx, p.y() + t * dy);
    for (const double s : {d, 2.5 * d}) {
      const fuzz::Point x(m.x() - s * dy, m.y() + s * dx);
      if (std::isfinite(x.x()) && std::isfinite(x.y()) && CVT_2::is_in_domain_2(cdt, x))
        pairs.push_back(x);
    }
  }
  return pairs;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > max_bytes) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  fuzz::expecting_documented_errors([&] {
    fuzz::CDT cdt;
    const std::optional<bool> has_generators = insert_domain(cdt, text);
    if (!has_generators) return;
    if (!*has_generators)
      CVT_2::insert_generators_2(
          cdt, CVT_2::random_points_in_domain_2(cdt, random_generators,
                                                CVT_2::parameters::random_seed(fnv1a(data, size))));
    if (fnv1a(data, size) % 2 == 0)
      CVT_2::insert_generators_2(cdt, thin_pairs(cdt, fnv1a(data, size)));

    fuzz::Bvd bvd(cdt);
    bvd.update();
    fuzz::check_cells_tile_domain(bvd);
    fuzz::check_mesh(bvd);

    // One Lloyd step with the default exact quadrature never raises the energy (beyond
    // rounding, on a well-conditioned triangulation).
    CVT_2::Lloyd_optimizer_2<fuzz::CDT> lloyd(cdt);
    const double e0 = lloyd.evaluate(10).energy;
    const bool well_conditioned = fuzz::is_well_conditioned(cdt);
    lloyd.move();
    const double e1 = lloyd.evaluate(10).energy;
    if (!std::isfinite(e0) || !std::isfinite(e1))
      fuzz::violated("the energy is not finite", e0, e1);
    if (well_conditioned && fuzz::is_well_conditioned(cdt) && e1 > e0 * (1 + 1e-12))
      fuzz::violated("the energy rose after one Lloyd step", e1, e0);
    fuzz::check_cells_tile_domain(lloyd.diagram());
  });
  return 0;
}
