// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Bvd_mesh_builder_2: the algorithm that builds a Bvd_mesh_2 from a bounded Voronoi diagram (the
// numbering of cells and circumcenters, the cells chunk by chunk, the merges of points a
// rounding apart, the conforming pass along constraints).
#ifndef CVT_2_INTERNAL_BVD_MESH_BUILDER_2_H
#define CVT_2_INTERNAL_BVD_MESH_BUILDER_2_H

#include <CVT_2/exceptions.h>
#include <CVT_2/internal/construct_cell.h>
#include <CVT_2/internal/layout/Handle_numbering.h>
#include <CVT_2/internal/layout/prefetch.h>
#include <CVT_2/internal/parallel/Face_chunks.h>
#include <CVT_2/internal/parallel/run_chunks.h>
#include <CVT_2/internal/to_string.h>
#include <CVT_2/mark_domain_2.h>

#include <CGAL/number_utils.h>

#include <boost/container_hash/hash.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CVT_2 {

template <class Diagram>
class Bvd_mesh_2;

namespace internal {

// Builds the mesh of a diagram into an empty Bvd_mesh_2, in passes:
// 1. number_cells_and_circumcenters(): one pass over the faces numbers the cells (the vertices
//    with one) and computes each circumcenter once;
// 2. add_cells(): each cell's cycle, chunk by chunk on the threads, as circumcenter numbers and
//    keys of the other points (generators, clip points), with the edge beyond each point and
//    the points a rounding apart (merges);
// 3. assemble(): the keys numbered, the cycles copied into the mesh, the merges made where
//    they take no cell's area (merge_vertices());
// 4. conform_constraints(): each side's edges along an inner constraint get the other side's
//    points, and pair_constraint_sides() names the cell beyond each such edge.
template <class Diagram>
class Bvd_mesh_builder_2 {
 public:
  using Mesh = Bvd_mesh_2<Diagram>;
  using Triangulation = typename Diagram::Triangulation;
  using Point_2 = typename Diagram::Point_2;
  using FT = typename Diagram::FT;
  using Vertex_handle = typename Diagram::Vertex_handle;
  using Cell_vertex = typename Diagram::Cell_vertex;
  using Vertex_type = typename Cell_vertex::Type;
  using Index = typename Mesh::Index;
  using Side = typename Mesh::Side;
  using Constraint = typename Mesh::Constraint;
  static constexpr Index none = Mesh::none;

  /// Builds the mesh of `bvd` into `mesh`, which is empty, its cells on `threads` threads.
  Bvd_mesh_builder_2(Mesh& mesh, const Diagram& bvd, unsigned threads);

 private:
  using Face_handle = typename Triangulation::Face_handle;
  using Tri_edge = typename Triangulation::Edge;

  // Algorithm 2's fan around a generator, its circumcenters the mesh's, computed once a face.
  struct Fan : Cdt_fan<Triangulation, typename Diagram::Geom_traits, Cell_vertex> {
    Fan(const Triangulation& cdt, const typename Diagram::Geom_traits& traits, Vertex_handle v,
        const Bvd_mesh_builder_2& mesh)
        : Cdt_fan<Triangulation, typename Diagram::Geom_traits, Cell_vertex>(cdt, traits, v),
          mesh(mesh) {}
    const Point_2& circumcenter(std::size_t j) const {
      return mesh.m_points[mesh.center_number(this->face(j))];
    }
    const Bvd_mesh_builder_2& mesh;
  };

  // The identity of a cell vertex other than a circumcenter: the generator (kind 1) by its
  // cell, a clip point (kind 2) by the cells of its bisector and of its constraint's ends.
  struct Key {
    int kind;
    std::array<Index, 4> cells;
    bool operator==(const Key& k) const { return kind == k.kind && cells == k.cells; }
  };
  struct Key_hash {
    std::size_t operator()(const Key& k) const {
      std::size_t h = boost::hash_value(k.kind);
      boost::hash_range(h, k.cells.begin(), k.cells.end());
      return h;
    }
  };
  // A cell vertex as the cells pass records it, and the edge that leaves it, in 8 bytes: with
  // the top bit clear a circumcenter's number and a neighbor's cell, with it set the position
  // of a key and of a constraint in the chunk's lists.
  static constexpr Index listed = Index(1) << 31;
  struct Entry {
    Index vertex;
    Index out;
  };
  // What a chunk of cells found, in the order of its cells.
  struct alignas(cache_line) Chunk_cells {
    std::vector<Index> sizes;
    std::vector<Entry> entries;
    std::vector<std::pair<Key, Point_2>> keys;
    std::vector<Constraint> constraints;
    std::vector<std::pair<Index, Index>> merges;  // vertices found at one point (as in Entry)
  };

  void number_cells_and_circumcenters(const Diagram& bvd, const Face_chunks<Triangulation>& chunks,
                                      unsigned threads);
  bool add_free_cell(const Triangulation& cdt, Vertex_handle v, Chunk_cells& out) const;
  static bool is_one_point(const Point_2& p, const Point_2& q, const Point_2& generator);
  void add_repeated_points(const Entry* first, std::size_t n, const Point_2& generator,
                           Chunk_cells& out) const;
  void add_chain(const Diagram& bvd, Vertex_handle v, std::vector<Cell_vertex>& raw,
                 Chunk_cells& out) const;
  template <class Raw>
  void add_cell(Vertex_handle v, const Raw& raw, Chunk_cells& out) const;
  void add_cells(const Diagram& bvd, const Vertex_handle* generators, std::size_t n,
                 Chunk_cells& out) const;
  Index out_edge(Vertex_handle v, const Cell_vertex& a, const Cell_vertex& b,
                 Chunk_cells& out) const;
  Index vertex(Vertex_handle v, const Cell_vertex& c, Chunk_cells& out) const;
  Constraint constraint_cells(const Tri_edge& e) const;
  void assemble(std::vector<Chunk_cells>& chunks, unsigned threads);
  std::vector<Index> merge_groups(const std::vector<std::pair<Index, Index>>& same) const;
  bool keeps_area(std::size_t k, const std::vector<Index>& root) const;
  bool merge_vertices(std::vector<std::pair<Index, Index>> same);
  void drop_repeats();
  void conform_constraints();
  void pair_constraint_sides();

  // Circumcenters are numbered chunk by chunk in one pass, as the mesh numbers cells: a face's
  // id holds its chunk and its number in the chunk, the chunks' offsets make it global. A chunk
  // has at most 4096 faces.
  static constexpr int cell_bits = Mesh::cell_bits, center_bits = 12;
  Index cell_number(Vertex_handle v) const { return m_mesh.cell_number(v); }
  Index center_number(Face_handle f) const {
    const std::size_t id = m_circumcenter_of.get(f);
    return Index(m_center_offsets[id >> center_bits] + (id & ((1u << center_bits) - 1)));
  }

  // The mesh, whose arrays the passes fill.
  Mesh& m_mesh;
  std::vector<Point_2>& m_points;
  std::vector<Vertex_type>& m_types;
  std::vector<std::size_t>& m_offsets;
  std::vector<Index>& m_cell_vertices;
  std::vector<Side>& m_sides;
  std::vector<Vertex_handle>& m_generators;
  std::vector<unsigned char>& m_constrained;
  std::vector<Constraint>& m_constraints;
  Handle_numbering<Vertex_handle>& m_cell_of;
  std::vector<std::size_t>& m_cell_offsets;  // of each chunk
  Handle_numbering<Face_handle> m_circumcenter_of;
  std::vector<std::size_t> m_center_offsets;  // of each chunk
  std::size_t m_number_of_circumcenters = 0;
  // The sides on constraints, by cell and position in m_sides: the few the last passes visit.
  std::vector<std::pair<Index, std::size_t>> m_on_constraints;
  void list_sides_on_constraints();
};

template <class Diagram>
Bvd_mesh_builder_2<Diagram>::Bvd_mesh_builder_2(Mesh& mesh, const Diagram& bvd, unsigned threads)
    : m_mesh(mesh),
      m_points(mesh.m_points),
      m_types(mesh.m_types),
      m_offsets(mesh.m_offsets),
      m_cell_vertices(mesh.m_cell_vertices),
      m_sides(mesh.m_sides),
      m_generators(mesh.m_generators),
      m_constrained(mesh.m_constrained),
      m_constraints(mesh.m_constraints),
      m_cell_of(mesh.m_cell_of),
      m_cell_offsets(mesh.m_cell_offsets) {
  const Triangulation& cdt = bvd.triangulation();
  if (cdt.dimension() < 2) return;
  const Face_chunks<Triangulation> chunks(cdt);
  number_cells_and_circumcenters(bvd, chunks, threads);
  // The cells, chunk by chunk, in the order of the numbering.
  std::vector<Chunk_cells> found(chunks.size());
  chunks.for_each(
      [&](std::size_t c, auto, auto) {
        add_cells(bvd, m_generators.data() + m_cell_offsets[c],
                  m_cell_offsets[c + 1] - m_cell_offsets[c], found[c]);
      },
      threads);
  assemble(found, threads);
  conform_constraints();
  pair_constraint_sides();
  // Cells a few ulps of their coordinates wide (a small domain far from the origin), or whose
  // squared lengths overflow (coordinates beyond about 1e154), can round to fewer than three
  // vertices: an empty polygon in every file, which no reader takes. A cell on a constraint
  // can keep three and lose a lobe: its polygons then cover less than its area, leaving a gap.
  const auto cannot_hold = [&](std::size_t k, const std::string& what) {
    return Domain_error("the cell of generator " + to_string(m_generators[k]->point()) + " " +
                        what +
                        ": double precision cannot hold the cells at their "
                        "coordinates (cells a few ulps wide: move the domain nearer the origin "
                        "or use fewer cells; squared lengths beyond 1e308: scale it down)");
  };
  for (std::size_t k = 0; k < m_generators.size(); ++k)
    if (m_offsets[k + 1] - m_offsets[k] < 3)
      throw cannot_hold(
          k, "rounds to " + std::to_string(m_offsets[k + 1] - m_offsets[k]) + " vertices");
  // the area of the cycle [begin, end) (three indices or more), its parts' sizes into `scale`
  const auto fan = [&](auto begin, auto end, FT& scale) {
    FT a = 0;
    for (auto j = begin + 1; j + 1 != end; ++j) {
      const FT part = CGAL::area(m_points[*begin], m_points[*j], m_points[*(j + 1)]);
      a += part, scale += CGAL::abs(part);
    }
    return a;
  };
  for (std::size_t k = 0; k < m_generators.size(); ++k) {
    // polygons() cuts a cycle into lobes where it passes through the generator twice or more
    const auto first = m_cell_vertices.begin() + std::ptrdiff_t(m_offsets[k]),
               last = m_cell_vertices.begin() + std::ptrdiff_t(m_offsets[k + 1]);
    if (std::count_if(first, last, [&](Index i) { return m_types[i] == Cell_vertex::GENERATOR; }) <
        2)
      continue;
    FT scale = 0;  // a fan's rounding: some 2^-52 of it
    const FT area = fan(first, last, scale);
    FT lobes = 0;
    for (const auto& ring : m_mesh.polygons(k)) lobes += fan(ring.begin(), ring.end(), scale);
    if (CGAL::abs(lobes - area) > CGAL::abs(area) * 0x1.0p-20 + scale * 0x1.0p-40)
      throw cannot_hold(k, "loses a part to rounding");
  }
}

// Cells are numbered in the order the cells pass visits them, circumcenters of the faces that
// see them in the order of the faces, in one pass over the faces, chunk by chunk.
template <class Diagram>
void Bvd_mesh_builder_2<Diagram>::number_cells_and_circumcenters(
    const Diagram& bvd, const Face_chunks<Triangulation>& chunks, unsigned threads) {
  const Triangulation& cdt = bvd.triangulation();
  if (chunks.chunk_size() > (std::size_t(1) << center_bits))
    throw std::logic_error("Bvd_mesh_2: chunks of more faces than the ids of faces can number");
  if (chunks.size() >= (std::size_t(1) << (29 - center_bits)))
    throw std::length_error("Bvd_mesh_2: more faces than the ids of faces can number");
  m_cell_offsets.assign(chunks.size() + 1, 0);
  m_center_offsets.assign(chunks.size() + 1, 0);
  std::vector<Chunk_vector<Vertex_handle>> generators(chunks.size());
  // Each circumcenter once (the cells pass would compute it in each of its three cells), while
  // the face and its vertices are at hand.
  std::vector<Chunk_vector<Point_2>> centers(chunks.size());
  const auto circumcenter = bvd.geom_traits().construct_circumcenter_2_object();
  // Hash maps are filled by one thread; the records' ids by all.
  const unsigned writers = m_cell_of.in_record && m_circumcenter_of.in_record ? threads : 1u;
  chunks.for_each(
      [&](std::size_t c, auto first, auto last) {
        std::size_t cells = 0;
        centers[c].reserve(chunks.chunk_size());
        auto ahead = first;  // its vertices fetched
        for (int i = 0; i < 8 && ahead != last; ++i) ++ahead;
        for (auto f = first; f != last; ++f) {
          if (ahead != last) {
            for (int i = 0; i < 3; ++i) prefetch(&*ahead->vertex(i));
            ++ahead;
          }
          if (!cdt.is_infinite(f) && f->is_inside_domain() && !f->is_blinded()) {
            m_circumcenter_of.set(f, (c << center_bits) | centers[c].size());
            centers[c].push_back(
                circumcenter(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()));
          }
          for (int i = 0; i < 3; ++i) {
            const Vertex_handle v = f->vertex(i);
            if (v->face() != f || cdt.is_infinite(v)) continue;
            if (!f->is_inside_domain() && !has_domain_face(cdt, v)) continue;
            m_cell_of.set(v, (c << cell_bits) | cells++);
            generators[c].push_back(v);
          }
        }
        m_cell_offsets[c + 1] = cells;
        m_center_offsets[c + 1] = centers[c].size();
      },
      writers);
  std::partial_sum(m_cell_offsets.begin(), m_cell_offsets.end(), m_cell_offsets.begin());
  std::partial_sum(m_center_offsets.begin(), m_center_offsets.end(), m_center_offsets.begin());
  if (m_cell_offsets.back() >= none || m_center_offsets.back() >= none)
    throw std::length_error("Bvd_mesh_2: more than 2^32 - 1 cells or vertices");
  m_number_of_circumcenters = m_center_offsets.back();
  // Room for the other vertices too (clip points, constrained generators: fewer than a
  // vertex a cell but in strange domains), so that adding them copies nothing.
  m_points.reserve(m_number_of_circumcenters + m_cell_offsets.back() / 2);
  m_points.resize(m_number_of_circumcenters);
  m_generators.resize(m_cell_offsets.back());
  run_chunks(chunks.size(), threads, [&](std::size_t c) {
    std::copy(centers[c].begin(), centers[c].end(), m_points.begin() + m_center_offsets[c]);
    std::copy(generators[c].begin(), generators[c].end(), m_generators.begin() + m_cell_offsets[c]);
    centers[c] = std::vector<Point_2>();
    generators[c] = std::vector<Vertex_handle>();
  });
}

template <class Diagram>
auto Bvd_mesh_builder_2<Diagram>::constraint_cells(const Tri_edge& e) const -> Constraint {
  const Index a = cell_number(e.first->vertex(Triangulation::ccw(e.second)));
  const Index b = cell_number(e.first->vertex(Triangulation::cw(e.second)));
  return {std::min(a, b), std::max(a, b)};
}

// Cell vertex c of the cell of v as an Entry's vertex: a circumcenter by its face's number, the
// generator or a clip point by its key, listed.
template <class Diagram>
auto Bvd_mesh_builder_2<Diagram>::vertex(Vertex_handle v, const Cell_vertex& c,
                                         Chunk_cells& out) const -> Index {
  if (c.type == Cell_vertex::CIRCUMCENTER) return center_number(c.face);
  Key k{1, {cell_number(v), 0, 0, 0}};
  if (c.type == Cell_vertex::CLIP_POINT) {
    const Index a = k.cells[0], b = cell_number(c.neighbor);
    const Constraint e = constraint_cells(c.constraint);
    k = {2, {std::min(a, b), std::max(a, b), e[0], e[1]}};
  }
  out.keys.emplace_back(k, c.point);
  return Index(out.keys.size() - 1) | listed;
}

// What lies beyond the cell edge from a to b, consecutive in the chain of v (before repeated
// points are merged), as an Entry's `out`: the constraint both lie on, or the bisector of v and
// the neighbor that a circumcenter at its start, or a clip point at either end, names.
template <class Diagram>
auto Bvd_mesh_builder_2<Diagram>::out_edge(Vertex_handle v, const Cell_vertex& a,
                                           const Cell_vertex& b, Chunk_cells& out) const -> Index {
  const auto has_end = [](const Tri_edge& e, Vertex_handle u) {
    return e.first->vertex(Triangulation::ccw(e.second)) == u ||
           e.first->vertex(Triangulation::cw(e.second)) == u;
  };
  const auto on = [&](const Cell_vertex& x, const Tri_edge& e) {
    if (x.type == Cell_vertex::GENERATOR) return has_end(e, v);
    return x.type == Cell_vertex::CLIP_POINT && is_same_constraint<Triangulation>(x.constraint, e);
  };
  const auto constraint = [&](const Tri_edge& e) {
    out.constraints.push_back(constraint_cells(e));
    return Index(out.constraints.size() - 1) | listed;
  };
  if (a.type == Cell_vertex::CLIP_POINT && on(b, a.constraint)) return constraint(a.constraint);
  if (b.type == Cell_vertex::CLIP_POINT && on(a, b.constraint)) return constraint(b.constraint);
  return cell_number(a.type == Cell_vertex::GENERATOR ? b.neighbor : a.neighbor);
}

// Most cells are Voronoi cells: v is on no constraint and all its faces see their
// circumcenters. Algorithm 2 then gives the cycle of their circumcenters, each edge on the
// bisector of v and the vertex the next face shares: read from the topology alone. False (and
// nothing added) for any other cell. Two faces at one circumcenter (cocircular points) are
// found later, by has_repeated_point(), when the points fetched here have arrived.
template <class Diagram>
bool Bvd_mesh_builder_2<Diagram>::add_free_cell(const Triangulation& cdt, Vertex_handle v,
                                                Chunk_cells& out) const {
  const std::size_t first = out.entries.size();
  auto f = cdt.incident_faces(v);
  const auto done = f;
  do {
    const int i = f->index(v);
    if (!f->is_inside_domain() || f->is_blinded() || f->is_constrained(Triangulation::ccw(i)) ||
        cdt.is_infinite(f)) {
      out.entries.resize(first);
      return false;
    }
    const Index center = center_number(f);
    prefetch(&m_points[center]);
    out.entries.push_back({center, cell_number(f->vertex(Triangulation::cw(i)))});
  } while (++f != done);
  out.sizes.push_back(Index(out.entries.size() - first));
  return true;
}

// Whether p and q, consecutive in the cell of `generator`, are one vertex: the same point, or
// within 2^-40 of their distance to the generator (the rounding of a circumcenter is some
// 2^-52 of it: two such points are one, in true numbers or nearly), or within 2^-49 of their
// largest coordinate, 8 to 16 units in its last place (a cell small against its coordinates:
// a point computed from others is rounded to those units; a right triangle's circumcenter and
// its hypotenuse's midpoint come 1 apart).
template <class Diagram>
bool Bvd_mesh_builder_2<Diagram>::is_one_point(const Point_2& p, const Point_2& q,
                                               const Point_2& generator) {
  if (p == q) return true;
  const double d2 = CGAL::to_double(CGAL::squared_distance(p, q));
  if (d2 <= 0x1.0p-80 * CGAL::to_double(CGAL::squared_distance(p, generator))) return true;
  const double size =
      std::max({std::abs(CGAL::to_double(p.x())), std::abs(CGAL::to_double(p.y())),
                std::abs(CGAL::to_double(q.x())), std::abs(CGAL::to_double(q.y()))});
  return std::sqrt(d2) <= 0x1.0p-49 * size;
}

// The circumcenters of the cycle [first, first + n) that are one point with the next, as merges.
template <class Diagram>
void Bvd_mesh_builder_2<Diagram>::add_repeated_points(const Entry* first, std::size_t n,
                                                      const Point_2& generator,
                                                      Chunk_cells& out) const {
  for (std::size_t j = 0; j < n; ++j) {
    const Index a = first[j].vertex, b = first[(j + 1) % n].vertex;
    if (is_one_point(m_points[a], m_points[b], generator)) out.merges.emplace_back(a, b);
  }
}

// The cell of v by Algorithm 2, its vertices in `raw`.
template <class Diagram>
void Bvd_mesh_builder_2<Diagram>::add_chain(const Diagram& bvd, Vertex_handle v,
                                            std::vector<Cell_vertex>& raw, Chunk_cells& out) const {
  raw.clear();
  fan_cell_chain<Cell_vertex>(Fan(bvd.triangulation(), bvd.geom_traits(), v, *this),
                              [&raw](const Cell_vertex& x) { raw.push_back(x); });
  add_cell(v, raw, out);
}

// The cells of generators[0, n) into `out`, in order. A free cell's circumcenters are fetched
// as its walk names them and compared some cells later, when they have arrived: the walks wait
// for no point.
template <class Diagram>
void Bvd_mesh_builder_2<Diagram>::add_cells(const Diagram& bvd, const Vertex_handle* generators,
                                            std::size_t n, Chunk_cells& out) const {
  const Triangulation& cdt = bvd.triangulation();
  std::vector<Cell_vertex> raw;
  std::vector<std::size_t> start(n);  // of each cell's entries
  std::vector<unsigned char> is_free(n, 0);
  const auto check = [&](std::size_t k) {
    if (is_free[k])
      add_repeated_points(out.entries.data() + start[k], out.sizes[k], generators[k]->point(), out);
  };
  constexpr std::size_t lag = 8;
  out.sizes.reserve(n);
  out.entries.reserve(7 * n);
  for_each_star_prefetched(
      n, [generators](std::size_t k) { return generators[k]; },
      [&](std::size_t k) {
        start[k] = out.entries.size();
        if (add_free_cell(cdt, generators[k], out))
          is_free[k] = 1;
        else
          add_chain(bvd, generators[k], raw, out);
        if (k >= lag) check(k - lag);
      });
  for (std::size_t k = n > lag ? n - lag : 0; k < n; ++k) check(k);
}

// The chain of v's cell into `out`, each point with the edge that leaves it; points that are
// one with the next (is_one_point()) recorded as merges, made (or not) when all cells are in.
template <class Diagram>
template <class Raw>
void Bvd_mesh_builder_2<Diagram>::add_cell(Vertex_handle v, const Raw& raw,
                                           Chunk_cells& out) const {
  const std::size_t m = raw.size(), first = out.entries.size();
  for (std::size_t j = 0; j < m; ++j)
    out.entries.push_back({vertex(v, raw[j], out), out_edge(v, raw[j], raw[(j + 1) % m], out)});
  for (std::size_t j = 0; j < m; ++j)
    if (is_one_point(raw[j].point, raw[(j + 1) % m].point, v->point()))
      out.merges.emplace_back(out.entries[first + j].vertex,
                              out.entries[first + (j + 1) % m].vertex);
  out.sizes.push_back(Index(m));
}

// The chunks' cells into the mesh's arrays: the vertices other than circumcenters numbered in
// the order of the cells that first meet them, constraints likewise (both few, serially), then
// the cells copied chunk by chunk; vertices found at one point are merged after the copy.
template <class Diagram>
void Bvd_mesh_builder_2<Diagram>::assemble(std::vector<Chunk_cells>& chunks, unsigned threads) {
  std::unordered_map<Key, Index, Key_hash> numbers;
  std::unordered_map<Constraint, Index, boost::hash<Constraint>> constraint_numbers;
  std::vector<std::pair<Index, Index>> same;
  std::vector<std::size_t> entries{0};  // before each chunk
  std::size_t keys = 0, on_constraint_sides = 0;
  for (const Chunk_cells& c : chunks) {
    keys += c.keys.size();
    on_constraint_sides += c.constraints.size();
  }
  m_points.reserve(m_points.size() + keys);  // a copy of all circumcenters, if room is short
  m_types.reserve(m_points.capacity());
  m_types.assign(m_number_of_circumcenters, Cell_vertex::CIRCUMCENTER);
  numbers.reserve(keys);
  for (Chunk_cells& c : chunks) {
    for (auto& [k, p] : c.keys) {  // the key's number replaces it, in cells[0]
      const auto [it, is_new] = numbers.emplace(k, Index(m_points.size()));
      if (is_new) {
        m_points.push_back(p);
        m_types.push_back(k.kind == 1 ? Cell_vertex::GENERATOR : Cell_vertex::CLIP_POINT);
      }
      k.cells[0] = it->second;
    }
    for (Constraint& k : c.constraints) {  // likewise, its number in k[0]
      const auto [it, is_new] = constraint_numbers.emplace(k, Index(m_constraints.size()));
      if (is_new) m_constraints.push_back(k);
      k[0] = it->second;
    }
    const auto number = [&c](Index i) {
      return i & listed ? c.keys[i & ~listed].first.cells[0] : i;
    };
    for (const auto& [a, b] : c.merges) same.emplace_back(number(a), number(b));
    entries.push_back(entries.back() + c.entries.size());
  }
  // Room for the vertices conform_constraints() adds along constraints, about one a side there.
  m_cell_vertices.reserve(entries.back() + 2 * on_constraint_sides);
  m_sides.reserve(entries.back() + 2 * on_constraint_sides);
  m_cell_vertices.resize(entries.back());
  m_sides.resize(entries.back());
  m_offsets.resize(m_generators.size() + 1);
  m_constrained.assign(m_generators.size(), 0);
  std::vector<Chunk_vector<std::pair<Index, std::size_t>>> on_constraints(chunks.size());
  run_chunks(chunks.size(), threads, [&](std::size_t ci) {
    Chunk_cells& c = chunks[ci];
    std::size_t e = entries[ci], cell = m_cell_offsets[ci];
    for (const Index size : c.sizes) {
      for (std::size_t j = 0; j < size; ++j, ++e) {
        const Entry& x = c.entries[e - entries[ci]];
        Index i = x.vertex;
        if (i & listed) {  // not a circumcenter
          const Key& key = c.keys[i & ~listed].first;
          if (key.kind == 1) m_constrained[cell] = 1;  // the generator itself
          i = key.cells[0];
        }
        m_cell_vertices[e] = i;
        if (x.out & listed) {
          m_sides[e] = Side{none, c.constraints[x.out & ~listed][0]};
          on_constraints[ci].emplace_back(Index(cell), e);
        } else {
          m_sides[e] = Side{x.out, none};
        }
      }
      m_offsets[++cell] = e;
    }
    c = Chunk_cells();  // one copy at a time
  });
  for (const auto& o : on_constraints)
    m_on_constraints.insert(m_on_constraints.end(), o.begin(), o.end());
  if (merge_vertices(std::move(same))) list_sides_on_constraints();
}

template <class Diagram>
void Bvd_mesh_builder_2<Diagram>::list_sides_on_constraints() {
  m_on_constraints.clear();
  for (std::size_t k = 0; k + 1 < m_offsets.size(); ++k)
    for (std::size_t e = m_offsets[k]; e < m_offsets[k + 1]; ++e)
      if (m_sides[e].constraint != none) m_on_constraints.emplace_back(Index(k), e);
}

// The groups of vertices that `same` makes one (union-find): the root of each vertex, which is
// the group's generator if it has one (an input point, exact, where the others are
// constructions rounded near it: the cell keeps its generator as a vertex), else its clip point
// on a constraint if it has one (so that a circumcenter a rounding off the domain's boundary
// does not move the boundary), else its smallest number. The same groups and roots whatever the
// order of `same`.
template <class Diagram>
auto Bvd_mesh_builder_2<Diagram>::merge_groups(
    const std::vector<std::pair<Index, Index>>& same) const -> std::vector<Index> {
  std::vector<Index> parent(m_points.size());
  std::iota(parent.begin(), parent.end(), Index(0));
  const auto root = [&](Index i) {  // halving the paths
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  const auto rank = [&](Index i) {  // the smallest rank in a group is its root
    const Vertex_type t = m_types[i];
    return std::make_pair(t == Cell_vertex::GENERATOR    ? 0
                          : t == Cell_vertex::CLIP_POINT ? 1
                                                         : 2,
                          i);
  };
  for (const auto& [a, b] : same) {
    const Index ra = root(a), rb = root(b);
    if (ra == rb) continue;
    if (rank(ra) < rank(rb))
      parent[rb] = ra;
    else
      parent[ra] = rb;
  }
  for (Index i = 0; i < parent.size(); ++i) parent[i] = root(i);
  return parent;
}

// Whether cell k, its vertices moved to their roots, keeps its area, to 2^-20 of it: merges
// make one the points of a cell that rounding set apart (which changes its area by some 2^-40 of
// it), never the corners of a thin cell, as a generator a hair from a constraint or from another
// generator has. A cell without area by its points has nothing to keep.
template <class Diagram>
bool Bvd_mesh_builder_2<Diagram>::keeps_area(std::size_t k, const std::vector<Index>& root) const {
  const std::size_t b = m_offsets[k], n = m_offsets[k + 1] - b;
  const auto area = [&](auto at) {
    FT a = 0;
    for (std::size_t j = 1; j + 1 < n; ++j)
      a += CGAL::area(m_points[at(0)], m_points[at(j)], m_points[at(j + 1)]);
    return a;
  };
  const FT before = area([&](std::size_t j) { return m_cell_vertices[b + j]; });
  if (!(before > 0)) return true;
  const FT after = area([&](std::size_t j) { return root[m_cell_vertices[b + j]]; });
  return CGAL::abs(after - before) <= before * 0x1.0p-20;
}

// Vertices found at one point are made one, in the cells' cycles too, but for those of cells
// that would lose their area: the merges of their vertices at different points are not made.
// Whether any vertex was merged.
template <class Diagram>
bool Bvd_mesh_builder_2<Diagram>::merge_vertices(std::vector<std::pair<Index, Index>> same) {
  if (same.empty()) return false;
  std::vector<Index> root = merge_groups(same);
  // The vertices of such cells, and those at their very points, keep their places.
  std::vector<unsigned char> kept(m_points.size(), 0);
  for (bool vetoed = true; vetoed;) {
    vetoed = false;
    for (std::size_t k = 0; k + 1 < m_offsets.size(); ++k) {
      bool moves = false;
      for (std::size_t e = m_offsets[k]; e < m_offsets[k + 1] && !moves; ++e)
        moves = root[m_cell_vertices[e]] != m_cell_vertices[e];
      if (!moves || keeps_area(k, root)) continue;
      for (std::size_t e = m_offsets[k]; e < m_offsets[k + 1]; ++e)
        if (!kept[m_cell_vertices[e]]) kept[m_cell_vertices[e]] = 1, vetoed = true;
    }
    for (bool spread = vetoed; spread;) {
      spread = false;
      for (const auto& [a, b] : same)
        if (kept[a] != kept[b] && m_points[a] == m_points[b]) kept[a] = kept[b] = 1, spread = true;
    }
    const auto apart = [&](const std::pair<Index, Index>& s) {
      return (kept[s.first] || kept[s.second]) && m_points[s.first] != m_points[s.second];
    };
    if (vetoed) {
      same.erase(std::remove_if(same.begin(), same.end(), apart), same.end());
      root = merge_groups(same);
    }
  }
  // The roots keep their places, the others go; the vertices closed up in order.
  std::vector<Index> renumber(m_points.size(), none);
  Index next = 0;
  for (Index i = 0; i < m_points.size(); ++i)
    if (root[i] == i) {
      m_points[next] = m_points[i];
      m_types[next] = m_types[i];
      renumber[i] = next++;
    }
  if (next == m_points.size()) return false;
  for (Index i = 0; i < root.size(); ++i) renumber[i] = renumber[root[i]];
  m_points.resize(next);
  m_types.resize(next);
  for (Index& i : m_cell_vertices) i = renumber[i];
  drop_repeats();
  return true;
}

// A merge can leave a cell with the same vertex twice in a row: one of them goes, the cycles
// compacted in place (a cell's first vertex kept aside: the last one's successor).
template <class Diagram>
void Bvd_mesh_builder_2<Diagram>::drop_repeats() {
  std::size_t kept = 0, b = 0;
  for (std::size_t k = 0; k + 1 < m_offsets.size(); ++k) {
    const std::size_t e = m_offsets[k + 1], n = e - b, start = kept;
    if (n == 0) {
      m_offsets[k] = start;
      continue;
    }
    const Index first = m_cell_vertices[b];
    const Side first_side = m_sides[b];
    for (std::size_t j = 0; j < n; ++j) {
      const Index v = m_cell_vertices[b + j];
      const Side s = m_sides[b + j];
      if (n > 1 && v == (j + 1 < n ? m_cell_vertices[b + j + 1] : first)) continue;
      m_cell_vertices[kept] = v;
      m_sides[kept++] = s;
    }
    if (kept == start) {  // all one point
      m_cell_vertices[kept] = first;
      m_sides[kept++] = first_side;
    }
    m_offsets[k] = start;
    b = e;
  }
  m_offsets.back() = kept;
  m_cell_vertices.resize(kept);
  m_sides.resize(kept);
}

// The cells on the two sides of an inner constraint end on it at different points: each side's
// edges along it get the other side's points as vertices too, so that both sides have the same
// edges there (a conforming mesh, whose cells meet edge to edge across the constraint).
template <class Diagram>
void Bvd_mesh_builder_2<Diagram>::conform_constraints() {
  const auto next = [&](std::size_t k, std::size_t e) {  // the position after e in cell k
    return e + 1 < m_offsets[k + 1] ? e + 1 : m_offsets[k];
  };
  // The vertices on each constraint, each once, in runs [first[c], last[c]) of `on` (a bucket
  // per constraint: a few vertices each). `along` has each run's vertices in their order along
  // the constraint, `position` each vertex's place there (none on a constraint with one edge on
  // each side that has one).
  const std::size_t constraints = m_constraints.size();
  std::vector<std::size_t> first(constraints + 1, 0), last(constraints);
  for (const auto& [k, e] : m_on_constraints) first[m_sides[e].constraint + 1] += 2;
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<Index> on(first.back());
  std::copy(first.begin(), first.end() - 1, last.begin());
  for (const auto& [k, e] : m_on_constraints) {
    const Index c = m_sides[e].constraint;
    on[last[c]++] = m_cell_vertices[e];
    on[last[c]++] = m_cell_vertices[next(k, e)];
  }
  std::vector<Index> along(on.size()), position(on.size(), none);
  std::vector<std::pair<Index, Index>> same;
  std::vector<std::pair<std::pair<FT, Index>, std::size_t>> t;
  for (Index c = 0; c < constraints; ++c) {
    const auto b = on.begin() + std::ptrdiff_t(first[c]);
    std::sort(b, on.begin() + std::ptrdiff_t(last[c]));
    last[c] = std::size_t(std::unique(b, on.begin() + std::ptrdiff_t(last[c])) - on.begin());
    if (last[c] - first[c] <= 2) continue;  // one edge, on each side that has one
    const Point_2& p = m_generators[m_constraints[c][0]]->point();
    const auto d = m_generators[m_constraints[c][1]]->point() - p;
    t.clear();  // (projection, vertex), and where the vertex is in `on`
    for (std::size_t i = first[c]; i < last[c]; ++i)
      t.push_back({{(m_points[on[i]] - p) * d, on[i]}, i});
    std::sort(t.begin(), t.end());
    // Points of the two sides that are one point (a bisector of each side meets the constraint
    // there, as at a circumcenter on it), up to the rounding of their constructions, are one
    // vertex: merged below, and the constraints visited again.
    const FT close = CGAL::to_double(d * d) * 0x1.0p-80;  // (2^-40 of its length)^2
    for (std::size_t i = 1; i < t.size(); ++i) {
      const Index u = t[i - 1].first.second, w = t[i].first.second;
      if (CGAL::squared_distance(m_points[u], m_points[w]) <= close) same.emplace_back(u, w);
    }
    for (std::size_t i = 0; i < t.size(); ++i) {
      along[first[c] + i] = t[i].first.second;
      position[t[i].second] = Index(i);
    }
  }
  if (merge_vertices(std::move(same))) {
    list_sides_on_constraints();
    return conform_constraints();
  }
  const auto at = [&](Index c, Index x) {  // the place of vertex x in the run of constraint c
    const auto b = on.begin() + std::ptrdiff_t(first[c]), e = on.begin() + std::ptrdiff_t(last[c]);
    return position[std::size_t(std::lower_bound(b, e, x) - on.begin())];
  };
  // The edges that skip vertices of their constraint, in the order of m_sides, with the
  // positions of their ends along it and where the constraint's run starts.
  struct Skipping {
    std::size_t e;
    Index from, to;
    std::size_t run;
  };
  std::vector<Skipping> skipping;
  for (const auto& [k, e] : m_on_constraints) {
    const Index c = m_sides[e].constraint;
    const Index from = at(c, m_cell_vertices[e]);
    if (from == none) continue;
    const Index to = at(c, m_cell_vertices[next(k, e)]);
    if (from + 1 < to || to + 1 < from) skipping.push_back({e, from, to, first[c]});
  }
  if (skipping.empty()) return;
  // The skipped vertices go in after each such edge, in place: the arrays grow, and the runs
  // between such edges move up, from the last, by what goes in before them.
  std::vector<std::size_t> added(skipping.size());  // after each such edge
  std::size_t total = 0;
  for (std::size_t i = 0; i < skipping.size(); ++i)
    total += added[i] = std::size_t(std::max(skipping[i].from, skipping[i].to) -
                                    std::min(skipping[i].from, skipping[i].to) - 1);
  const std::size_t old_size = m_cell_vertices.size();
  m_cell_vertices.resize(old_size + total);
  m_sides.resize(old_size + total);
  std::size_t end = old_size, shift = total;  // the run [e + 1, end) moves up by shift
  for (std::size_t i = skipping.size(); i-- > 0;) {
    const auto& [e, from, to, run] = skipping[i];
    const auto first = std::ptrdiff_t(e + 1), last = std::ptrdiff_t(end);
    std::move_backward(m_cell_vertices.begin() + first, m_cell_vertices.begin() + last,
                       m_cell_vertices.begin() + last + std::ptrdiff_t(shift));
    std::move_backward(m_sides.begin() + first, m_sides.begin() + last,
                       m_sides.begin() + last + std::ptrdiff_t(shift));
    shift -= added[i];
    std::size_t p = e + 1 + shift;
    for (Index j = from; j + 1 < to;)
      m_cell_vertices[p] = along[run + ++j], m_sides[p++] = m_sides[e];
    for (Index j = from; j > to + 1;)
      m_cell_vertices[p] = along[run + --j], m_sides[p++] = m_sides[e];
    end = e + 1;
  }
  // The offsets and the sides on constraints shifted by what went in before them.
  std::size_t a = 0;
  shift = 0;
  for (std::size_t& offset : m_offsets) {
    for (; a < skipping.size() && skipping[a].e < offset; ++a) shift += added[a];
    offset += shift;
  }
  std::vector<std::pair<Index, std::size_t>> on_constraints;
  on_constraints.reserve(m_on_constraints.size() + total);
  shift = a = 0;
  for (const auto& [k, e] : m_on_constraints) {
    for (; a < skipping.size() && skipping[a].e < e; ++a) shift += added[a];
    on_constraints.emplace_back(k, e + shift);
    if (a < skipping.size() && skipping[a].e == e)
      for (std::size_t i = 1; i <= added[a]; ++i) on_constraints.emplace_back(k, e + shift + i);
  }
  m_on_constraints.swap(on_constraints);
}

// An edge on a constraint inside the domain has a cell on each side: the same edge, walked the
// other way in the other cell (or in the same cell, for a slit).
template <class Diagram>
void Bvd_mesh_builder_2<Diagram>::pair_constraint_sides() {
  struct Occurrence {
    Index a, b;      // the edge's ends, the smaller first
    std::size_t at;  // its side's position in m_sides
    Index cell;
  };
  // In a bucket per constraint (its edges lie on it), sorted there.
  std::vector<std::size_t> first(m_constraints.size() + 1, 0);
  for (const auto& [k, e] : m_on_constraints) ++first[m_sides[e].constraint + 1];
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<Occurrence> on(first.back());
  std::vector<std::size_t> last(first.begin(), first.end() - 1);
  for (const auto& [k, e] : m_on_constraints) {
    const Index p = m_cell_vertices[e];
    const Index q = m_cell_vertices[e + 1 < m_offsets[k + 1] ? e + 1 : m_offsets[k]];
    on[last[m_sides[e].constraint]++] = {std::min(p, q), std::max(p, q), e, k};
  }
  for (std::size_t c = 0; c + 1 < first.size(); ++c) {
    std::sort(on.begin() + std::ptrdiff_t(first[c]), on.begin() + std::ptrdiff_t(first[c + 1]),
              [](const Occurrence& x, const Occurrence& y) {
                return std::tie(x.a, x.b, x.at) < std::tie(y.a, y.b, y.at);
              });
    for (std::size_t i = first[c]; i + 1 < first[c + 1]; ++i) {
      if (on[i].a != on[i + 1].a || on[i].b != on[i + 1].b) continue;
      m_sides[on[i].at].cell = on[i + 1].cell;
      m_sides[on[i + 1].at].cell = on[i].cell;
      ++i;
    }
  }
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_BVD_MESH_BUILDER_2_H
