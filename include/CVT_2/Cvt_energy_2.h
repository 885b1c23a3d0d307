// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Cvt_energy_2: the CVT energy of a bounded Voronoi diagram and what its gradient needs (cell
// masses, centroids, move ratios), evaluated for both optimizers.
#ifndef CVT_2_CVT_ENERGY_2_H
#define CVT_2_CVT_ENERGY_2_H

#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/Bvd_traits_2.h>
#include <CVT_2/Cell_moments_2.h>
#include <CVT_2/Concepts/CellQuadrature_2.h>
#include <CVT_2/Concepts/DensityFunction_2.h>
#include <CVT_2/Exact_quadrature_2.h>
#include <CVT_2/Gauss_quadrature_2.h>
#include <CVT_2/Midpoint_quadrature_2.h>
#include <CVT_2/Sizing_field_density_2.h>
#include <CVT_2/Sliding_runs_2.h>
#include <CVT_2/Uniform_density_2.h>
#include <CVT_2/exceptions.h>
#include <CVT_2/internal/Handle_set.h>
#include <CVT_2/internal/density_evaluation.h>
#include <CVT_2/internal/for_each_cell_in_faces.h>
#include <CVT_2/internal/move_generators.h>
#include <CVT_2/internal/parallel/Chunked_list.h>
#include <CVT_2/internal/parallel/Face_chunks.h>
#include <CVT_2/internal/parallel/run_chunks.h>
#include <CVT_2/internal/tag_blind_faces.h>
#include <CVT_2/internal/to_string.h>
#include <CVT_2/internal/valid_point.h>
#include <CVT_2/parameters.h>

#include <CGAL/Unique_hash_map.h>
#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

template <class K, class Density>
using Default_quadrature = std::conditional_t<is_uniform_density<Density>::value,
                                              Exact_quadrature_2<K>, Gauss_quadrature_2<K>>;

}  // namespace internal

/// \ingroup PkgCvt2Ref
/// The CVT energy \f$E(x) = \sum_i \int_{V_i} \rho(y)\|y - x_i\|^2 dy\f$ of the bounded
/// Voronoi diagram of a constrained Delaunay triangulation, and everything its gradient and the
/// paper's stop need: `evaluate()` builds the diagram of the generators where they are and
/// integrates every cell, giving the energy, and for each free generator \f$x\f$ the mass
/// \f$m\f$ and centroid \f$x^*\f$ of its cell (the gradient is \f$2\,m\,(x - x^*)\f$) and its
/// move ratio \f$mr(x) = \|x - x^*\| / \mathrm{diameter}(V)\f$.
///
/// Both optimizers evaluate through it and hold only their steps: `Lloyd_optimizer_2` moves the
/// generators to the centroids, `Lbfgs_optimizer_2` along its quasi-Newton direction. It reads
/// the triangulation and never moves a generator; the chunks of faces it visits
/// (`face_chunks()`) are those the optimizers' moves run by.
///
/// \tparam CDT as for `Bounded_voronoi_diagram_2`, with its domain marked.
/// \tparam Density a model of `DensityFunction_2`; one with the optional batch member is
///         evaluated once a chunk of cells (the same bits). One that restricts itself to disks
///         (`restrict_to_disk()`, as the automatic sizing field) is restricted to a disk around
///         each cell, and the restriction is kept for the next evaluations while the cell stays
///         in its disk: the same bits, at a few hundred bytes a generator. A restriction with
///         the batch member (the automatic sizing field's) is evaluated once a cell.
/// \tparam Quadrature a model of `CellQuadrature_2`; by default exact formulas for a uniform
///         density, `Gauss_quadrature_2` otherwise.
/// \tparam Traits a model of `BvdTraits_2` for the diagram; by default `Bvd_traits_2`.
template <class CDT, class Density = Uniform_density_2<typename CDT::Geom_traits>,
          class Quadrature = internal::Default_quadrature<typename CDT::Geom_traits, Density>,
          class Traits = Bvd_traits_2<typename CDT::Geom_traits>>
class Cvt_energy_2 {
 public:
  using Triangulation = CDT;                               ///< the triangulation type
  using Kernel = typename CDT::Geom_traits;                ///< its kernel
  using FT = typename Kernel::FT;                          ///< number type
  using Point_2 = typename Kernel::Point_2;                ///< point type
  using Vertex_handle = typename CDT::Vertex_handle;       ///< a generator
  using Diagram = Bounded_voronoi_diagram_2<CDT, Traits>;  ///< the diagram it iterates on
  using Density_function = Density;                        ///< the density policy
  using Cell_quadrature = Quadrature;                      ///< the quadrature policy

  static_assert(is_density_function_2<Density, Kernel>::value,
                "Density must model DensityFunction_2: FT operator()(const Point_2&) const");
  static_assert(is_cell_quadrature_2<Quadrature, Kernel, Density>::value,
                "Quadrature must model CellQuadrature_2: Cell_moments_2<K> operator()(const "
                "Point_2& x, const PointRange& cell, const Density& rho, std::size_t resolution) "
                "const");

  /// What one evaluation found.
  struct Evaluation {
    double energy = 0;                          ///< of all cells
    double max_move_ratio = 0;                  ///< over the free and sliding generators
    double mean_move_ratio = 0;                 ///< over the free and sliding generators
    std::size_t number_of_free_generators = 0;  ///< that have a cell
    /// vertices of `Sliding_runs_2` that have a cell; their move ratios are to their
    /// constrained centroids
    std::size_t number_of_sliding_generators = 0;
    std::size_t resolution = 0;  ///< the quadrature resolution used
  };

  /// A free generator as the last evaluation found it: the gradient of the energy with respect
  /// to its position is \f$2\,m\,(x - x^*)\f$ (Du, Faber, Gunzburger 1999).
  struct Free_generator {
    Vertex_handle vertex;  ///< the generator \f$x\f$
    Point_2 centroid;      ///< \f$x^*\f$, the centroid of its cell
    FT mass;               ///< \f$m = \int_V \rho\f$
  };
  /// The free generators of an evaluation: a range of `Free_generator` with `size()`, `empty()`,
  /// `operator[]` and forward iterators, kept in the pieces the cells were computed in.
  using Free_generators = internal::Chunked_list<Free_generator>;

  /// Prepares the evaluations on `cdt` (nothing is computed yet).
  explicit Cvt_energy_2(CDT& cdt, const Density& rho = Density(),
                        const Quadrature& quadrature = Quadrature(),
                        const Traits& traits = Traits())
      : m_cdt(cdt),
        m_density(rho),
        m_quadrature(quadrature),
        m_diagram(cdt, traits, internal::Tags_as_they_are()),
        m_chunks(faces_a_chunk) {}

  /// Builds the diagram of the current generators and computes the energy, the centroids and
  /// the move ratios, integrating with `resolution` sub-triangles a cell (see
  /// `CellQuadrature_2`). \throws Domain_error if the density is not positive and finite at a
  /// point where it is evaluated, or if the moments overflow or the domain's underflow.
  const Evaluation& evaluate(std::size_t resolution);

  /// The number of threads that `evaluate()` builds cells and integrates them on; 0 (the
  /// default) means one per core. The results are the same, bit for bit, whatever the number.
  void set_number_of_threads(unsigned n) { m_number_of_threads = n; }
  unsigned number_of_threads() const { return m_number_of_threads; }  ///< as set; 0: one per core

  /// Fixes the generators `vertices` (vertices of the triangulation): their cells count in the
  /// energy, but they are not among `free_generators()` and do not slide, so that no optimizer
  /// moves them (a well, an observation point). Replaces the generators fixed before.
  void fix_generators(const std::vector<Vertex_handle>& vertices) {
    m_fixed.clear();
    m_fixed.insert(vertices.begin(), vertices.end());
  }
  /// whether `v` was fixed by `fix_generators()`
  bool is_fixed(Vertex_handle v) const { return !m_fixed.empty() && m_fixed.count(v) != 0; }

  /// Restricts the evaluations to a region: only the free generators among `vertices` are
  /// free, and only the cells that their moves can change are computed, theirs and those within
  /// two rings of them (a set that grows as moves bring others near). The faces around those
  /// cells are tagged (Algorithm 1) at the first evaluation, then again where the moves through
  /// `move_generators()` changed them, with the faces that the constrained edges there blind;
  /// the other faces keep their tags, which stay right if they were. An evaluation then costs
  /// the region, not the triangulation: a relaxation after a local change (a constraint edit).
  /// The energy is that of the cells computed; when a move brings a generator from farther
  /// than two rings next to the region, its cell joins them, and L-BFGS's line search may then
  /// fall back to a Lloyd step. Replaces the region set before.
  void set_region(const std::vector<Vertex_handle>& vertices) {
    clear_region();
    m_has_region = true;
    for (const Vertex_handle v : vertices)
      if (!m_cdt.is_infinite(v) && m_region.insert(v)) m_region_list.push_back(v);
  }
  /// Evaluates every cell again (the default).
  void clear_region() {
    m_has_region = false;
    m_region.clear();
    m_region_list.clear();
    m_cells.clear();
    m_cell_list.clear();
    m_changed_faces.clear();
  }
  bool has_region() const { return m_has_region; }  ///< whether `set_region()` restricts

  /// Lets the vertices of `runs` slide along their runs (`Sliding_runs_2`): each evaluation
  /// plans their constrained centroids, counted in the move ratios, and `slide_generators()`
  /// moves them. Not with a region (`set_region()`), whose vertices are free generators only.
  /// `runs` must outlive the evaluations; nullptr: none slide (the default). Vertices next to a
  /// chord that points inserted since split stop (`Sliding_runs_2::stop_at_split_chords()`), and
  /// so do those fixed by `fix_generators()`.
  void set_sliding_runs(Sliding_runs_2<CDT>* runs) {
    m_sliding = runs;
    if (runs) runs->stop_at_split_chords(m_cdt);
  }
  /// Moves the vertices of the sliding runs toward the constrained centroids that the last
  /// evaluation planned (`Sliding_runs_2::slide()`); returns how many moved.
  std::size_t slide_generators() {
    if (!sliding()) return 0;
    return m_sliding->slide(m_cdt);
  }

  /// \cond SKIP_IN_MANUAL
  // Moves the free generators vertex(i) toward target(i), for the i of `order`, in at most
  // `passes` passes (internal::move_free_vertices(), by the chunks of the last evaluation);
  // with a region, the moves are local and the faces they change are noted for the next
  // evaluation; with `keep_out` (and set_keep_out()), the targets are kept out first. Returns
  // how many did not reach their target.
  template <class OrderRange, class VertexAt, class TargetAt>
  std::size_t move_generators(const OrderRange& order, const VertexAt& vertex,
                              const TargetAt& target, std::size_t passes,
                              internal::Move_buffers<CDT>& buffers, bool keep_out = true) {
    buffers.changed = m_has_region ? &m_changed_faces : nullptr;
    if (!m_keep_out || !keep_out)
      return internal::move_free_vertices(m_cdt, m_chunks, m_number_of_threads, order, vertex,
                                          target, passes, buffers);
    std::size_t size = 0;
    for (const std::size_t i : order) size = std::max(size, i + 1);
    m_kept_out.resize(size);
    for (const std::size_t i : order) m_kept_out[i] = m_keep_out(vertex(i)->point(), target(i));
    return internal::move_free_vertices(
        m_cdt, m_chunks, m_number_of_threads, order, vertex,
        [this](std::size_t i) -> const Point_2& { return m_kept_out[i]; }, passes, buffers);
  }
  /// \endcond

  /// Keeps the moves of `move_generators()` out of places: a generator that would move from
  /// `x` to `t` moves to `keep_out(x, t)` instead (`Conforming_disks::outside()`: out of the
  /// circles of conforming lines). An empty function (the default) keeps nothing out.
  void set_keep_out(std::function<Point_2(const Point_2&, const Point_2&)> keep_out) {
    m_keep_out = std::move(keep_out);
  }

  const Evaluation& last_evaluation() const { return m_evaluation; }  ///< the last evaluation
  /// the number of calls of `evaluate()` so far
  std::size_t number_of_evaluations() const { return m_number_of_evaluations; }
  /// The free generators of the last evaluation, in the order the cells were visited.
  const Free_generators& free_generators() const { return m_moves; }
  /// Frees the list of free generators (a million take 32 MB) once its user has read it.
  void release_free_generators() { m_moves.clear(); }
  const Diagram& diagram() const { return m_diagram; }  ///< the diagram, as last evaluated
  const CDT& triangulation() const { return m_cdt; }    ///< the triangulation
  /// \cond SKIP_IN_MANUAL
  // The chunks of faces the last evaluation visited: moves run by the same chunks.
  const internal::Face_chunks<CDT>& face_chunks() const { return m_chunks; }
  /// \endcond

 private:
  using Cell_points = boost::container::small_vector<Point_2, 32>;
  using Edge = typename CDT::Edge;

  // What one cell adds to an evaluation.
  struct Cell_figures {
    double mass = 0, energy = 0;
    bool is_free = false;   // a constrained generator is a vertex of its own cell
    double move_ratio = 0;  // |x - x*| / diameter, for a free generator
    Free_generator generator;
  };

  // What a chunk of cells adds up to, in the order of its cells; its free generators go to its
  // list in m_moves. Written at every cell: on cache lines of its own.
  struct alignas(internal::cache_line) Chunk {
    double mass = 0, energy = 0, max_move_ratio = 0, sum_move_ratio = 0;
    std::vector<Free_generator>* moves = nullptr;
    void add(const Cell_figures& c) {
      mass += c.mass;
      energy += c.energy;
      if (!c.is_free) return;
      max_move_ratio = std::max(max_move_ratio, c.move_ratio);
      sum_move_ratio += c.move_ratio;
      // beyond the guess, an eighth more at a time: doubling would leave half a list unused
      if (moves->size() == moves->capacity())
        moves->reserve(moves->capacity() + moves->capacity() / 8 + 16);
      moves->push_back(c.generator);
    }
  };

  Cell_figures cell_figures(Vertex_handle v, const Cell_points& points, bool is_free,
                            const Cell_moments_2<Kernel>& m) const;
  bool sliding() const { return m_sliding != nullptr && !m_has_region; }
  template <class Face_iterator>
  void add_cells_in_batch(Face_iterator first, Face_iterator last, std::size_t resolution,
                          Chunk& sums) const;

  // A cell of a chunk evaluated in batch, by where its data begin in the buffers.
  struct Batch_cell {
    Vertex_handle v;
    bool is_free;
    std::size_t vertices, asked, nodes;
  };
  // What a chunk evaluated in batch keeps between its passes; reused from chunk to chunk. Each
  // thread holds one and writes it at every cell: on cache lines of its own.
  struct alignas(internal::cache_line) Batch_buffers {
    std::vector<Batch_cell> cells;
    std::vector<Point_2> vertices, asked;
    std::vector<FT> nodes, values;
    void clear() {
      cells.clear();
      vertices.clear();
      asked.clear();
      nodes.clear();
      values.clear();
    }
  };
  void reduce_chunks();
  const Evaluation& evaluate_region(std::size_t resolution);
  void tag_region();
  Cell_moments_2<Kernel> moments(Vertex_handle v, const Cell_points& points,
                                 std::size_t resolution) const;
  template <class Restriction>
  Cell_moments_2<Kernel> moments_under(const Restriction& rho, const Point_2& x,
                                       const Cell_points& points, std::size_t resolution) const;
  template <class VertexRange>
  void number_generators(const VertexRange& vertices);
  static std::string bad_moments_message(const Point_2& generator, const Cell_points& points,
                                         double mass, double energy, double first2);
  static double squared_diameter(const Cell_points& points);

  CDT& m_cdt;
  Density m_density;
  Quadrature m_quadrature;
  Diagram m_diagram;
  static constexpr std::size_t faces_a_chunk =
      std::is_same<Quadrature, Exact_quadrature_2<Kernel>>::value
          ? internal::Face_chunks<CDT>::default_chunk_size
          : internal::Face_chunks<CDT>::quadrature_chunk_size;
  internal::Face_chunks<CDT> m_chunks;  // the cells run on several threads by them
  Evaluation m_evaluation;
  unsigned m_number_of_threads = 0;
  std::size_t m_number_of_evaluations = 0;
  std::vector<Chunk> m_chunk_sums;
  Free_generators m_moves;  // a list for each chunk, not joined by a copy
  std::unordered_set<Vertex_handle> m_fixed;
  std::function<Point_2(const Point_2&, const Point_2&)> m_keep_out;
  std::vector<Point_2> m_kept_out;  // the targets kept out, by generator number
  Sliding_runs_2<CDT>* m_sliding = nullptr;
  // With a region: its free generators, the generators whose cells are computed, the faces the
  // moves changed since the last evaluation; scratch for the tags.
  bool m_has_region = false;
  internal::Handle_set<Vertex_handle> m_region, m_cells;
  std::vector<Vertex_handle> m_region_list, m_cell_list;
  std::vector<typename CDT::Face_handle> m_changed_faces, m_stack;
  internal::Handle_set<typename CDT::Face_handle> m_faces, m_seen;
  internal::Buffer_pool<Batch_buffers> m_batch_buffers;  // one in use per thread at most

  // With a density that restricts itself to disks (and is not evaluated in batches): the last
  // restriction of each generator's cell, to a disk a quarter wider than the cell needed, kept
  // between evaluations. A cell that is still within that disk reuses it: a restriction equals
  // the density on its disk, whichever cell it was made for, so the values are the same bits,
  // and the search for its candidates (a third of a cell's time along a finely cut boundary) is
  // done once every few iterations once the moves are small. The slots are numbered by
  // generator in a hash map (not in the vertices' ids, which are the user's).
  static constexpr bool keeps_restrictions =
      has_restrict_to_disk_v<Density, Kernel> && !has_batch_evaluation_v<Density, Kernel>;
  struct Kept_restriction;
  struct Kept_restrictions {
    CGAL::Unique_hash_map<Vertex_handle, std::size_t> slot_of{std::size_t(-1)};
    std::vector<Kept_restriction> slots;  // each written by the one thread of its cell
  };
  mutable std::conditional_t<keeps_restrictions, Kept_restrictions, std::nullptr_t>
      m_restrictions{};
};

template <class CDT, class Density, class Quadrature, class Traits>
struct Cvt_energy_2<CDT, Density, Quadrature, Traits>::Kept_restriction {
  using Restriction = typename internal::Restriction_type<Density, Point_2, FT>::type;
  double x = 0, y = 0, radius = -1;  // the disk
  std::optional<Restriction> restriction;
};

template <class CDT, class Density, class Quadrature, class Traits>
auto Cvt_energy_2<CDT, Density, Quadrature, Traits>::evaluate(std::size_t resolution)
    -> const Evaluation& {
  ++m_number_of_evaluations;
  m_chunks.update(m_cdt);
  if (m_has_region) return evaluate_region(resolution);
  m_diagram.update(m_chunks, m_number_of_threads);
  if constexpr (keeps_restrictions) number_generators(m_cdt.finite_vertex_handles());
  if (sliding()) m_sliding->begin_evaluation();
  // Cells in chunks, on several threads; each chunk sums its own cells in order, then the
  // chunks are summed in order: the same bits whatever the threads.
  m_chunk_sums.assign(m_chunks.size(), Chunk());
  m_moves.reset(m_chunks.size());
  for (std::size_t c = 0; c < m_chunks.size(); ++c) {
    // as many as last time, or as the chunk has vertices on average, and a little more
    std::size_t guess = m_moves.previous_size(c);
    if (guess == 0) guess = m_cdt.number_of_vertices() / m_chunks.size();
    m_moves.chunk(c).reserve(guess + guess / 16);
    m_chunk_sums[c].moves = &m_moves.chunk(c);
  }
  m_chunks.for_each(
      [&](std::size_t c, auto first, auto last) {
        if constexpr (has_batch_evaluation_v<Density, Kernel>) {
          add_cells_in_batch(first, last, resolution, m_chunk_sums[c]);
        } else {
          Cell_points points;
          internal::for_each_cell_points_in_faces(
              m_diagram, first, last, points,
              [&](Vertex_handle v, const Cell_points& cell, bool is_free) {
                m_chunk_sums[c].add(cell_figures(v, cell, is_free, moments(v, cell, resolution)));
              });
        }
      },
      m_number_of_threads);
  m_evaluation = Evaluation();
  m_evaluation.resolution = resolution;
  reduce_chunks();
  if (sliding()) {  // the sliding vertices' move ratios join the free generators'
    const auto plan = m_sliding->plan(m_cdt);
    Evaluation& e = m_evaluation;
    e.max_move_ratio = std::max(e.max_move_ratio, plan.max_move_ratio);
    e.number_of_sliding_generators = plan.sliders;
    const std::size_t n = e.number_of_free_generators + plan.sliders;
    if (n > 0)
      e.mean_move_ratio =
          (e.mean_move_ratio * double(e.number_of_free_generators) + plan.sum_move_ratio) /
          double(n);
  }
  return m_evaluation;
}

// evaluate() with a region: the tags around it, then its cells and their neighbours', one by
// one (a region is small).
template <class CDT, class Density, class Quadrature, class Traits>
auto Cvt_energy_2<CDT, Density, Quadrature, Traits>::evaluate_region(std::size_t resolution)
    -> const Evaluation& {
  tag_region();
  if constexpr (keeps_restrictions) number_generators(m_cell_list);
  m_chunk_sums.assign(1, Chunk());
  m_moves.reset(1);
  m_moves.chunk(0).reserve(m_region_list.size());
  m_chunk_sums[0].moves = &m_moves.chunk(0);
  Cell_points points;
  std::vector<typename Diagram::Cell_vertex> scratch;
  for (const Vertex_handle v : m_cell_list) {
    bool is_free = true;
    if (internal::cell_points(m_diagram, v, points, is_free, scratch))
      m_chunk_sums[0].add(
          cell_figures(v, points, is_free && m_region.contains(v), moments(v, points, resolution)));
  }
  m_evaluation = Evaluation();
  m_evaluation.resolution = resolution;
  if (m_cell_list.empty()) {  // no cell to compute
    m_moves.seal();
    return m_evaluation;
  }
  reduce_chunks();
  return m_evaluation;
}

// The cells to compute around the region, and the tags they need: the faces around the cells
// new to the list, the faces the moves changed (they all lie around moved generators or were
// flipped), and the faces that the constrained edges of those blind (an edge whose face a flip
// replaced is named by another face now, in the tags of the faces it blinds).
template <class CDT, class Density, class Quadrature, class Traits>
void Cvt_energy_2<CDT, Density, Quadrature, Traits>::tag_region() {
  m_faces.clear();
  const auto& faces = m_cdt.tds().faces();
  for (const auto f : m_changed_faces)
    if (faces.is_used(f)) m_faces.insert(f);
  m_changed_faces.clear();
  std::vector<Edge> edges;
  for (const auto f : m_faces)
    for (int i = 0; i < 3; ++i)
      if (f->is_constrained(i)) edges.emplace_back(f, i);
  for (const Edge& e : edges)
    internal::faces_blinded_by(m_cdt, m_diagram.geom_traits(), e, m_faces, m_seen, m_stack);
  // the region and the generators within two rings of it
  const std::size_t known = m_cell_list.size();
  const auto add_cell = [&](Vertex_handle v) {
    if (!m_cdt.is_infinite(v) && m_cells.insert(v)) m_cell_list.push_back(v);
  };
  for (const Vertex_handle v : m_region_list) add_cell(v);
  std::vector<Vertex_handle> front(m_region_list), next;
  internal::Handle_set<Vertex_handle> reached;
  for (const Vertex_handle v : front) reached.insert(v);
  for (int ring = 0; ring < 2 && m_cdt.dimension() == 2; ++ring) {
    next.clear();
    for (const Vertex_handle v : front) {
      auto vc = m_cdt.incident_vertices(v), done = vc;
      do
        if (!m_cdt.is_infinite(vc) && reached.insert(vc)) {
          next.push_back(vc);
          add_cell(vc);
        }
      while (++vc != done);
    }
    front.swap(next);
  }
  for (std::size_t k = known; k < m_cell_list.size(); ++k) {
    auto fc = m_cdt.incident_faces(m_cell_list[k]), done = fc;
    if (fc != nullptr) do
        m_faces.insert(fc);
      while (++fc != done);
  }
  internal::retag_faces(m_cdt, m_diagram.geom_traits(), m_faces, m_seen, m_stack);
}

// The cells of the faces [first, last) with a batch density (DensityFunction_2::evaluate()):
// their quadrature points listed in a first pass (by the quadrature's nodes() if it has them,
// else by running it with a density that records them), the density evaluated at all of them
// in one call, then the moments from those values (moments(), or the quadrature again). The
// same bits as point by point.
template <class CDT, class Density, class Quadrature, class Traits>
template <class Face_iterator>
void Cvt_energy_2<CDT, Density, Quadrature, Traits>::add_cells_in_batch(Face_iterator first,
                                                                        Face_iterator last,
                                                                        std::size_t resolution,
                                                                        Chunk& sums) const {
  constexpr bool with_nodes = has_quadrature_nodes_v<Quadrature, Kernel>;
  auto b = m_batch_buffers.take();  // freed, not given back, if an exception leaves
  b->clear();
  Cell_points cell;
  internal::for_each_cell_points_in_faces(
      m_diagram, first, last, cell, [&](Vertex_handle v, const Cell_points& points, bool is_free) {
        const Batch_cell c{v, is_free, b->vertices.size(), b->asked.size(), b->nodes.size()};
        if constexpr (with_nodes) {
          m_quadrature.nodes(v->point(), points, resolution, b->asked, b->nodes);
        } else {
          const internal::Recording_density<Point_2, FT> record{&b->asked};
          m_quadrature(v->point(), points, record, resolution);
        }
        b->vertices.insert(b->vertices.end(), points.begin(), points.end());
        b->cells.push_back(c);
      });
  internal::evaluate_in_batch(m_density, b->asked, b->values);
  std::size_t next = 0;
  const internal::Replaying_density<Point_2, FT> replay{&b->asked, &b->values, &next};
  for (std::size_t k = 0; k < b->cells.size(); ++k) {
    const Batch_cell& c = b->cells[k];
    const bool last_cell = k + 1 == b->cells.size();
    const std::size_t vertices_end = last_cell ? b->vertices.size() : b->cells[k + 1].vertices;
    const Cell_points points(b->vertices.begin() + std::ptrdiff_t(c.vertices),
                             b->vertices.begin() + std::ptrdiff_t(vertices_end));
    if constexpr (with_nodes) {
      const std::size_t asked_end = last_cell ? b->asked.size() : b->cells[k + 1].asked;
      sums.add(cell_figures(c.v, points, c.is_free,
                            m_quadrature.moments(b->nodes.data() + c.nodes,
                                                 b->values.data() + c.asked, asked_end - c.asked)));
    } else {
      sums.add(cell_figures(c.v, points, c.is_free,
                            m_quadrature(c.v->point(), points, replay, resolution)));
    }
  }
  if (!with_nodes && next != b->asked.size())
    throw std::logic_error(
        "a density evaluated in batches needs a quadrature that asks for the same points, in "
        "the same order, whatever the density's values");
  m_batch_buffers.give_back(b);
}

// The figures of the cell `points` of v from its moments m: checked, and for a free generator
// its centroid and move ratio.
template <class CDT, class Density, class Quadrature, class Traits>
auto Cvt_energy_2<CDT, Density, Quadrature, Traits>::cell_figures(
    Vertex_handle v, const Cell_points& points, bool is_free, const Cell_moments_2<Kernel>& m) const
    -> Cell_figures {
  Cell_figures f;
  f.is_free = is_free && !is_fixed(v);
  f.mass = CGAL::to_double(m.mass);
  f.energy = CGAL::to_double(m.energy);
  const double first2 = CGAL::to_double(m.first_moment.squared_length());
  if (!(f.mass >= 0) || !std::isfinite(f.mass) || !std::isfinite(f.energy) ||
      !std::isfinite(first2))
    throw Domain_error(bad_moments_message(v->point(), points, f.mass, f.energy, first2));
  if (!f.is_free) {
    if (sliding() && f.mass > 0 && !is_fixed(v)) {  // a sliding vertex: its centroid, for the plan
      const std::size_t k = m_sliding->slider(v);
      if (k != Sliding_runs_2<CDT>::none)
        m_sliding->set_cell(k, v->point() + m.first_moment / m.mass, squared_diameter(points));
    }
    return f;
  }
  // A cell whose mass underflows to 0 (a generator 1e-320 from another) stays put.
  const typename Kernel::Vector_2 shift =
      f.mass > 0 ? m.first_moment / m.mass : typename Kernel::Vector_2(CGAL::NULL_VECTOR);
  const double diameter2 = squared_diameter(points);
  // With circles to keep out of, the move they allow: a generator that a centroid inside one
  // holds on its rim is where it can be (measured to the centroid, it never met the stop).
  const double moved2 = m_keep_out && f.mass > 0
                            ? CGAL::to_double(CGAL::squared_distance(
                                  m_keep_out(v->point(), v->point() + shift), v->point()))
                            : CGAL::to_double(shift.squared_length());
  f.move_ratio = diameter2 > 0 ? std::sqrt(moved2 / diameter2) : 0;
  f.generator = {v, v->point() + shift, m.mass};
  return f;
}

// The chunks' sums, in the order of the chunks, into the evaluation; their moves joined.
template <class CDT, class Density, class Quadrature, class Traits>
void Cvt_energy_2<CDT, Density, Quadrature, Traits>::reduce_chunks() {
  m_moves.seal();
  double sum_ratio = 0, mass = 0;
  for (const Chunk& c : m_chunk_sums) {
    mass += c.mass;
    m_evaluation.energy += c.energy;
    m_evaluation.max_move_ratio = std::max(m_evaluation.max_move_ratio, c.max_move_ratio);
    sum_ratio += c.sum_move_ratio;
  }
  // One cell may underflow (a generator 1e-320 from another: it stays put), not the domain.
  if (!(mass >= std::numeric_limits<double>::min()) || !(m_evaluation.energy > 0))
    throw Domain_error("the domain's mass " + internal::number_to_string(mass) + " and energy " +
                       internal::number_to_string(m_evaluation.energy) +
                       " underflow: the moments do not fit in double precision (the domain's "
                       "size or the density's range is too extreme for Lloyd iteration)");
  m_evaluation.number_of_free_generators = m_moves.size();
  if (!m_moves.empty()) m_evaluation.mean_move_ratio = sum_ratio / double(m_moves.size());
}

// A slot for the kept restriction of each generator that has none (the only writes to the
// map: the cells then read it from several threads).
template <class CDT, class Density, class Quadrature, class Traits>
template <class VertexRange>
void Cvt_energy_2<CDT, Density, Quadrature, Traits>::number_generators(
    const VertexRange& vertices) {
  if constexpr (keeps_restrictions) {
    Kept_restrictions& k = m_restrictions;
    for (const Vertex_handle v : vertices)
      if (!k.slot_of.is_defined(v)) k.slot_of[v] = k.slots.size(), k.slots.emplace_back();
  }
}

// The moments of the cell `points` of v, under the density restricted to a disk around v that
// holds the cell if the density offers that (the same values, from fewer candidates).
template <class CDT, class Density, class Quadrature, class Traits>
Cell_moments_2<typename CDT::Geom_traits> Cvt_energy_2<CDT, Density, Quadrature, Traits>::moments(
    Vertex_handle v, const Cell_points& points, std::size_t resolution) const {
  const Point_2& x = v->point();
  if constexpr (has_restrict_to_disk_v<Density, Kernel>) {
    double r2 = 0;
    for (const Point_2& p : points)
      r2 = std::max(r2, CGAL::to_double(CGAL::squared_distance(x, p)));
    const double xd = CGAL::to_double(x.x()), yd = CGAL::to_double(x.y());
    // quadrature points are convex combinations of x and the cell's vertices, up to rounding
    const double r = std::sqrt(r2) * (1 + 1e-9) + 1e-12 * (std::abs(xd) + std::abs(yd));
    if constexpr (keeps_restrictions) {
      const Kept_restrictions& all = m_restrictions;
      CGAL_assertion(all.slot_of.is_defined(v));
      Kept_restriction& kept = m_restrictions.slots[all.slot_of[v]];
      const double dx = xd - kept.x, dy = yd - kept.y;
      // a new one when the cell leaves the disk, or fills less than half of it (a disk from
      // the early, larger moves would keep more segments than the cell needs)
      if (std::sqrt(dx * dx + dy * dy) + r > kept.radius * (1 - 1e-12) || 2.5 * r < kept.radius) {
        kept.restriction.reset();  // one restriction a generator at a time
        kept.radius = -1;          // none, if making it throws
        kept.restriction.emplace(m_density.restrict_to_disk(x, FT(1.25 * r)));
        kept.x = xd;
        kept.y = yd;
        kept.radius = 1.25 * r;
      }
      return moments_under(*kept.restriction, x, points, resolution);
    } else {
      return moments_under(m_density.restrict_to_disk(x, FT(r)), x, points, resolution);
    }
  } else {
    const internal::Checked_density<Density, Point_2> rho{m_density};
    return m_quadrature(x, points, rho, resolution);
  }
}

// The moments of the cell `points` of x under rho, a restriction of the density: the
// restriction's values at all the cell's quadrature points at once if it can (the same bits,
// in a loop without the branches of one point at a time), else point by point.
template <class CDT, class Density, class Quadrature, class Traits>
template <class Restriction>
Cell_moments_2<typename CDT::Geom_traits>
Cvt_energy_2<CDT, Density, Quadrature, Traits>::moments_under(const Restriction& rho,
                                                              const Point_2& x,
                                                              const Cell_points& points,
                                                              std::size_t resolution) const {
  if constexpr (has_batch_evaluation_v<Restriction, Kernel> &&
                has_quadrature_nodes_v<Quadrature, Kernel>) {
    // one cell at a time on each thread: its buffers kept from cell to cell (a restriction must
    // not evaluate cells itself, as no density does)
    thread_local std::vector<Point_2> asked;
    thread_local std::vector<FT> nodes, values;
    asked.clear();
    nodes.clear();
    const std::size_t n = m_quadrature.nodes(x, points, resolution, asked, nodes);
    internal::evaluate_in_batch(rho, asked, values);
    return m_quadrature.moments(nodes.data(), values.data(), n);
  } else {
    return m_quadrature(x, points, internal::Checked_density<Restriction, Point_2>{rho},
                        resolution);
  }
}

// Why a cell's moments cannot be used: overflow (too large a domain or density: a finite cell
// whose moments are not all finite, NaN included, from inf - inf), or a bug to report: a cell
// vertex that is not finite, or finite moments with a negative mass.
template <class CDT, class Density, class Quadrature, class Traits>
std::string Cvt_energy_2<CDT, Density, Quadrature, Traits>::bad_moments_message(
    const Point_2& generator, const Cell_points& points, double mass, double energy,
    double first2) {
  const bool finite_cell = std::all_of(points.begin(), points.end(), [](const Point_2& p) {
    return std::isfinite(CGAL::to_double(p.x())) && std::isfinite(CGAL::to_double(p.y()));
  });
  const bool overflow =
      finite_cell && !(std::isfinite(mass) && std::isfinite(energy) && std::isfinite(first2));
  std::string what = "the cell of generator " + internal::to_string(generator) + " has mass " +
                     internal::number_to_string(mass) + " and energy " +
                     internal::number_to_string(energy);
  if (overflow)
    return what +
           ": its moments do not fit in double precision (the domain's size or the "
           "density's range is too extreme for Lloyd iteration)";
  return what + ": its " + std::to_string(points.size()) +
         " vertices do not make a polygon with finite moments (a bug in CVT_2: please report "
         "it with the input)";
}

template <class CDT, class Density, class Quadrature, class Traits>
double Cvt_energy_2<CDT, Density, Quadrature, Traits>::squared_diameter(const Cell_points& points) {
  double d = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j)
      d = std::max(d, CGAL::to_double(CGAL::squared_distance(points[i], points[j])));
  return d;
}

namespace internal {

// The density of `np`: `density`, or `sizing_field` as 1/mu^4, or uniform.
template <class K, class NP>
auto read_density(const NP& np) {
  using namespace internal_np;
  static_assert(!(has_parameter<NP, density_t> && has_parameter<NP, sizing_field_t>),
                "give either density() or sizing_field(), not both");
  if constexpr (has_parameter<NP, sizing_field_t>)
    return make_sizing_field_density_2<K>(get_parameter(np, sizing_field_t()));
  else
    return choose_parameter(get_parameter(np, density_t()), Uniform_density_2<K>());
}

// The energy's policies from the named parameters of lloyd_optimize_2() and lbfgs_optimize_2(),
// with their types: `density` (or `sizing_field`), `quadrature`, `geom_traits`.
template <class CDT, class NP>
struct Energy_parameters {
  using K = typename CDT::Geom_traits;
  using Density = decltype(read_density<K>(std::declval<const NP&>()));
  using Quadrature = std::decay_t<decltype(internal_np::choose_parameter(
      internal_np::get_parameter(std::declval<const NP&>(), internal_np::quadrature_t()),
      Default_quadrature<K, Density>()))>;
  using Traits = std::decay_t<decltype(internal_np::choose_parameter(
      internal_np::get_parameter(std::declval<const NP&>(), internal_np::geom_traits_t()),
      Bvd_traits_2<K>()))>;

  static Density density(const NP& np) { return read_density<K>(np); }
  static Quadrature quadrature(const NP& np) {
    return internal_np::choose_parameter(
        internal_np::get_parameter(np, internal_np::quadrature_t()), Quadrature());
  }
  static Traits traits(const NP& np) {
    return internal_np::choose_parameter(
        internal_np::get_parameter(np, internal_np::geom_traits_t()), Traits());
  }
};

}  // namespace internal

}  // namespace CVT_2

#endif  // CVT_2_CVT_ENERGY_2_H
