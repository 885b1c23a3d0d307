// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Lbfgs_optimizer_2: L-BFGS on the CVT energy, preconditioned by Lloyd's step, one step at a time.
#ifndef CVT_2_LBFGS_OPTIMIZER_2_H
#define CVT_2_LBFGS_OPTIMIZER_2_H

#include <CVT_2/Bvd_traits_2.h>
#include <CVT_2/Cvt_energy_2.h>
#include <CVT_2/Uniform_density_2.h>
#include <CVT_2/internal/Lbfgs_history.h>
#include <CVT_2/internal/move_generators.h>
#include <CVT_2/internal/parallel/run_chunks.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

constexpr std::size_t default_lbfgs_memory = 7;  // curvature pairs kept

}  // namespace internal

/// \ingroup PkgCvt2Ref
/// L-BFGS on the CVT energy (Liu, Wang, Lévy, Yan, Lu, Yang 2009, *On centroidal Voronoi
/// tessellation — energy smoothness and fast computation*), usable step by step.
///
/// The energy \f$E(x) = \sum_i \int_{V_i} \rho(y)\|y - x_i\|^2 dy\f$ of the bounded Voronoi
/// diagram is \f$C^2\f$ almost everywhere, and its gradient for a free generator is
/// \f$\nabla_i E = 2\,m_i\,(x_i - x_i^*)\f$, with \f$m_i\f$ the mass and \f$x_i^*\f$ the
/// centroid of its cell: one `Cvt_energy_2::evaluate()` gives both. Constrained
/// generators are fixed, but for the vertices of sliding runs (`set_sliding_runs()`), which take
/// a step to their constrained centroids at the start of each step, evaluated with the free
/// generators' quasi-Newton step (block coordinate descent). The quasi-Newton direction comes from
/// the last `memory` pairs of position and gradient differences, with the Lloyd step as
/// preconditioner: the initial inverse Hessian is \f$\mathrm{diag}(1/(2m_i))\f$, so a step without
/// memory (the first, and every restart) aims where a Lloyd step does, \f$x_i \to x_i^*\f$.
///
/// A step moves the generators in place, as Lloyd iteration does: all at once, those of any
/// face that this folds within their stars instead (no edge is crossed, so no constraint),
/// then edge flips restore the constrained Delaunay property, and the generators that have not
/// arrived go on, for a few passes; the positions reached are the trial point. A backtracking
/// line search (Armijo's condition on the energy, with the displacement actually done) halves
/// the step twice at most; if the energy still does not decrease enough, the generators go
/// back to where the step started and take a Lloyd step, and the memory is cleared. Pairs with
/// \f$s \cdot y \le 0\f$ are skipped. With an exact quadrature (`Exact_quadrature_2`, uniform
/// density) the energy never rises, unless a generator cannot get back to where a failed step
/// started (the tests have not met one).
///
/// With an approximate quadrature (`Gauss_quadrature_2`, `Midpoint_quadrature_2`) the energy and
/// the centroids, and so the gradient, are approximations, whose error changes as the cells change
/// shape and as the resolution rises: the line search compares computed energies, and when their
/// error hides the decrease it fails and the step falls back to a Lloyd step. So the iteration goes
/// on where a line search on approximate energies gets stuck, at the cost of the failed trials
/// (`number_of_fallbacks()` counts them).
///
/// The free generators are numbered once, in the order of the first evaluation, so that the
/// vectors, and so the result, do not depend on the order in which cells are visited: the same
/// input gives the same bits.
///
/// \tparam CDT as for `Bounded_voronoi_diagram_2`, with its domain marked.
/// \tparam Density a model of `DensityFunction_2`: the energy's, see `Cvt_energy_2`.
/// \tparam Quadrature a model of `CellQuadrature_2`: the energy's, see `Cvt_energy_2`.
/// \tparam Traits a model of `BvdTraits_2`: the energy's, see `Cvt_energy_2`.
/// \sa `lbfgs_optimize_2()`, which drives it with the paper's stopping rule; `Lloyd_optimizer_2`.
template <class CDT, class Density = Uniform_density_2<typename CDT::Geom_traits>,
          class Quadrature = internal::Default_quadrature<typename CDT::Geom_traits, Density>,
          class Traits = Bvd_traits_2<typename CDT::Geom_traits>>
class Lbfgs_optimizer_2 {
 public:
  using Triangulation = CDT;                          ///< the triangulation type
  using Kernel = typename CDT::Geom_traits;           ///< its kernel
  using FT = typename Kernel::FT;                     ///< number type
  using Point_2 = typename Kernel::Point_2;           ///< point type
  using Vertex_handle = typename CDT::Vertex_handle;  ///< a generator
  using Density_function = Density;                   ///< the density policy
  using Cell_quadrature = Quadrature;                 ///< the quadrature policy
  /// the evaluator of energy, gradient and move ratios
  using Energy = Cvt_energy_2<CDT, Density, Quadrature, Traits>;
  using Evaluation = typename Energy::Evaluation;  ///< what an evaluation found
  using Diagram = typename Energy::Diagram;        ///< the diagram it iterates on

  /// Prepares the optimization of `cdt` with at most `memory` curvature pairs (0: every step is
  /// a Lloyd step). Nothing is computed yet.
  explicit Lbfgs_optimizer_2(CDT& cdt, const Density& rho = Density(),
                             const Quadrature& quadrature = Quadrature(),
                             std::size_t memory = internal::default_lbfgs_memory,
                             const Traits& traits = Traits())
      : m_cdt(cdt), m_energy(cdt, rho, quadrature, traits), m_history(memory) {}

  /// Evaluates the generators where they are (diagram, energy, centroids, move ratios, and so
  /// the gradient), with `resolution` sub-triangles a cell. The memory is kept if they are where
  /// the last `evaluate()` or `step()` left them (a new evaluation at a higher resolution, say),
  /// and cleared otherwise. \throws Domain_error as `Cvt_energy_2::evaluate()`.
  const Evaluation& evaluate(std::size_t resolution) {
    m_energy.evaluate(resolution);
    if (!gather(m_trial)) {  // other generators than before: number them again
      number_generators();
      gather(m_trial);
    } else if (m_has_current && !same_positions(m_trial, m_current)) {
      m_history.clear();
    }
    take_trial();
    m_has_current = true;
    return m_current.evaluation;
  }

  /// One step from the last evaluated point: the L-BFGS direction (a Lloyd step without
  /// memory), the line search, or a Lloyd step if it fails; every evaluation integrates with
  /// `resolution` sub-triangles a cell. Returns the evaluation of the new point.
  /// \pre `evaluate()` was called, and the generators have not moved since the last
  ///      `evaluate()` or `step()`.
  const Evaluation& step(std::size_t resolution) {
    CGAL_precondition(m_has_current);
    ++m_steps;
    // The sliding vertices first, to their constrained centroids, with the free generators'
    // step: the trial point has both moves, and the line search compares it with the energy
    // before them. Not evaluated in between: that would double a step's cost while vertices
    // slide (measured: 2.3-2.6x on Massachusetts and the world); the curvature pair then holds
    // the slide's effect on the free generators' gradient, which fades as the slides do.
    m_energy.slide_generators();
    if (m_vertices.empty()) return evaluate(resolution);
    const bool descent = m_history.size() > 0 && quasi_newton_direction();
    if (!descent) {
      if (m_history.size() > 0) ++m_restarts;
      m_history.clear();
      lloyd_step(resolution);
    } else if (!line_search(resolution)) {
      ++m_fallbacks;
      m_history.clear();
      go_back(resolution);
      lloyd_step(resolution);
    }
    return m_current.evaluation;
  }

  /// The number of threads that evaluations build cells and integrate them on, and that steps
  /// check the moved faces, flip most edges and update the history on; 0 (the default) means one
  /// per core. The results are the same, bit for bit, whatever the number.
  void set_number_of_threads(unsigned n) {
    m_energy.set_number_of_threads(n);
    m_history.set_number_of_threads(n);
  }
  unsigned number_of_threads() const { return m_energy.number_of_threads(); }  ///< as set
  /// Generators that never move: `Cvt_energy_2::fix_generators()`. Before the first evaluation.
  void fix_generators(const std::vector<Vertex_handle>& vertices) {
    m_energy.fix_generators(vertices);
  }
  /// Moves only the free generators among `vertices`, evaluating only around them:
  /// `Cvt_energy_2::set_region()`. Before the first evaluation.
  void set_region(const std::vector<Vertex_handle>& vertices) { m_energy.set_region(vertices); }
  /// Lets the vertices of `runs` slide along them: `Cvt_energy_2::set_sliding_runs()`.
  void set_sliding_runs(Sliding_runs_2<CDT>* runs) { m_energy.set_sliding_runs(runs); }
  /// Keeps the moves out of places: `Cvt_energy_2::set_keep_out()`.
  template <class KeepOut>
  void set_keep_out(const KeepOut& keep_out) {
    m_energy.set_keep_out(keep_out);
  }

  /// the evaluation of the current point
  const Evaluation& last_evaluation() const { return m_current.evaluation; }
  /// evaluations done so far
  std::size_t number_of_evaluations() const { return m_energy.number_of_evaluations(); }
  std::size_t number_of_steps() const { return m_steps; }  ///< done so far
  /// the steps whose line search failed and that were Lloyd steps instead
  std::size_t number_of_fallbacks() const { return m_fallbacks; }
  /// the steps whose quasi-Newton direction did not go downhill and that were Lloyd steps
  /// instead (with positive curvature pairs it always does, up to rounding)
  std::size_t number_of_restarts() const { return m_restarts; }
  std::size_t memory() const { return m_history.capacity(); }  ///< the most curvature pairs kept
  std::size_t number_of_curvature_pairs() const { return m_history.size(); }  ///< kept now
  const Energy& energy() const { return m_energy; }                           ///< the evaluator
  const Diagram& diagram() const { return m_energy.diagram(); }               ///< as last evaluated
  const CDT& triangulation() const { return m_cdt; }                          ///< the triangulation

 private:
  static constexpr std::size_t max_passes = 8;    // of moves and flips toward the targets
  static constexpr std::size_t max_halvings = 2;  // of the step, before a Lloyd step instead
  static constexpr double armijo = 1e-4;          // sufficient decrease: a fraction of g.s

  // A point of the iteration, generators in their fixed order: positions (kept apart from x
  // only if the number type is not double), the coordinates x and the gradient g (both 2 per
  // generator). The current point also has m_centroids and m_h; a trial point has them in the
  // evaluator's list until it is taken or dropped.
  static constexpr bool positions_in_x = std::is_same_v<FT, double>;
  struct Iterate {
    std::vector<Point_2> points;
    std::vector<double> x, g;
    Evaluation evaluation;
  };
  static Point_2 position(const Iterate& it, std::size_t i) {
    if constexpr (positions_in_x)
      return Point_2(it.x[2 * i], it.x[2 * i + 1]);
    else
      return it.points[i];
  }
  static bool same_positions(const Iterate& a, const Iterate& b) {
    if constexpr (positions_in_x)
      return a.x == b.x;
    else
      return a.points == b.points;
  }
  static bool by_address(Vertex_handle a, Vertex_handle b) { return &*a < &*b; }

  // Numbers the free generators in the order of the last evaluation, and sorts them by their
  // handles' addresses for the lookups gather() needs.
  void number_generators() {
    m_vertices.clear();
    m_order.clear();
    const std::size_t n = m_energy.free_generators().size();
    if (n > std::numeric_limits<std::uint32_t>::max())
      throw std::length_error("L-BFGS numbers its generators in 32 bits: " + std::to_string(n) +
                              " generators are too many");
    m_vertices.reserve(n);
    for (const auto& f : m_energy.free_generators()) m_vertices.push_back(f.vertex);
    m_numbers_by_address.resize(n);
    for (std::size_t i = 0; i < n; ++i) m_numbers_by_address[i] = std::uint32_t(i);
    std::sort(m_numbers_by_address.begin(), m_numbers_by_address.end(),
              [this](std::uint32_t i, std::uint32_t j) {
                return by_address(m_vertices[i], m_vertices[j]);
              });
    m_by_address.resize(n);
    for (std::size_t k = 0; k < n; ++k) m_by_address[k] = m_vertices[m_numbers_by_address[k]];
    m_history.clear();
  }

  // The quasi-Newton direction into m_direction, as floats times 2^m_direction_exponent (a
  // direction to search along needs no more: the line search measures what the moves did);
  // whether it goes downhill.
  bool quasi_newton_direction() {
    std::vector<double> d;
    if (!m_history.direction(m_current.g, m_h, d)) return false;
    const unsigned threads = m_energy.number_of_threads();
    const double largest = internal::max_of_blocks(d.size(), threads, m_partial,
                                                   [&](std::size_t first, std::size_t last) {
                                                     double l = 0;
                                                     for (std::size_t j = first; j < last; ++j)
                                                       l = std::max(l, std::abs(d[j]));
                                                     return l;
                                                   });
    std::frexp(largest, &m_direction_exponent);  // finite: the direction goes downhill
    const double scale = std::ldexp(1.0, -m_direction_exponent);
    m_direction.resize(d.size());
    internal::for_each_block(d.size(), threads,
                             [&](std::size_t, std::size_t first, std::size_t last) {
                               for (std::size_t j = first; j < last; ++j)
                                 m_direction[j] = float(d[j] * scale);
                             });
    return true;
  }

  // A mass that underflowed to 0 would make the preconditioner infinite.
  static double mass(const typename Energy::Free_generator& f) {
    return std::max(CGAL::to_double(f.mass), std::numeric_limits<double>::min());
  }

  // Calls visit(k, list) for each piece `list` of the last evaluation's free generators, k the
  // index of its first one, on the evaluator's threads: pieces may be visited at once.
  template <class Visit>
  void for_each_piece_of_free_generators(const Visit& visit) const {
    const auto& generators = m_energy.free_generators();
    internal::run_chunks(
        generators.number_of_chunks(), m_energy.number_of_threads(),
        [&](std::size_t c) { visit(generators.chunk_begin(c), generators.chunk(c)); });
  }

  // The last evaluation into `it`, by number; false if the free generators are not those numbered.
  // Records the visit order, the order of the next moves.
  bool gather(Iterate& it) {
    const std::size_t n = m_vertices.size();
    if (m_energy.free_generators().size() != n) return false;
    if constexpr (!positions_in_x) it.points.resize(n);
    it.x.resize(2 * n);
    it.g.resize(2 * n);
    // The visit order changes little from one evaluation to the next: each generator is first
    // looked for where the one before it in this order was in the last order, then at its own
    // place in the last order, and by its handle if at neither.
    m_previous_order.swap(m_order);
    const bool has_previous = m_previous_order.size() == n;
    m_position.resize(n);
    if (has_previous)
      internal::for_each_block(n, m_energy.number_of_threads(),
                               [&](std::size_t, std::size_t first, std::size_t last) {
                                 for (std::size_t k = first; k < last; ++k)
                                   m_position[m_previous_order[k]] = std::uint32_t(k);
                               });
    m_order.resize(n);
    // The number of the k-th generator v of this evaluation, n if none; `next` is one past where
    // the one before it was in the last order.
    const auto number = [&](std::size_t k, Vertex_handle v, std::size_t& next) -> std::size_t {
      if (has_previous)
        for (const std::size_t guess : {next, k})
          if (guess < n && m_vertices[m_previous_order[guess]] == v) {
            next = guess + 1;
            return m_previous_order[guess];
          }
      const auto found = std::lower_bound(m_by_address.begin(), m_by_address.end(), v, by_address);
      if (found == m_by_address.end() || *found != v) return n;
      const std::size_t i = m_numbers_by_address[std::size_t(found - m_by_address.begin())];
      if (has_previous) next = m_position[i] + std::size_t(1);
      return i;
    };
    std::atomic<bool> all_numbered{true};
    for_each_piece_of_free_generators([&](std::size_t k, const auto& list) {
      std::size_t next = n;
      for (const auto& f : list) {
        const std::size_t i = number(k, f.vertex, next);
        if (i == n) {
          all_numbered = false;
          return;
        }
        m_order[k++] = std::uint32_t(i);
        const Point_2& p = f.vertex->point();
        const double m = mass(f);
        if constexpr (!positions_in_x) it.points[i] = p;
        it.x[2 * i] = CGAL::to_double(p.x());
        it.x[2 * i + 1] = CGAL::to_double(p.y());
        it.g[2 * i] = 2 * m * CGAL::to_double(p.x() - f.centroid.x());
        it.g[2 * i + 1] = 2 * m * CGAL::to_double(p.y() - f.centroid.y());
      }
    });
    if (!all_numbered) return false;
    it.evaluation = m_energy.last_evaluation();
    return true;
  }

  // The trial point, just gathered, becomes the current one, with its centroids and
  // preconditioner 1/(2 m) from the evaluator's list; the list and the old point are dropped.
  void take_trial() {
    std::swap(m_current, m_trial);
    drop_trial();
    const std::size_t n = m_vertices.size();
    m_centroids.resize(n);
    m_h.resize(n);
    for_each_piece_of_free_generators([&](std::size_t k, const auto& list) {
      for (const auto& f : list) {
        const std::size_t i = m_order[k++];
        m_centroids[i] = f.centroid;
        m_h[i] = 1 / (2 * mass(f));
      }
    });
    m_energy.release_free_generators();
  }
  // Frees the trial point (at most one point and the evaluator's list are held besides the
  // current point: a million generators take 32 MB each).
  void drop_trial() { m_trial = Iterate(); }

  void evaluate_trial(std::size_t resolution) {
    m_energy.evaluate(resolution);
    const bool same = gather(m_trial);  // moves neither add nor remove generators
    CGAL_assertion(same);
    CGAL_USE(same);
  }

  // The trial point becomes the current one; its pair of differences joins the history if its
  // curvature is positive.
  void accept() {
    m_history.add(m_current.x, m_trial.x, m_current.g, m_trial.g);
    take_trial();
  }

  // Back to the start of a failed step, by the same moves with more passes (few generators are
  // still on their way after the first ones); if one cannot get there to the bit, the Lloyd step
  // that follows starts from an evaluation of where they are.
  void go_back(std::size_t resolution) {
    if (move_to_targets([this](std::size_t i) { return position(m_current, i); }, 4 * max_passes,
                        false) > 0)
      evaluate(resolution);
  }

  // Every free generator to its centroid (as far as the passes go), evaluated and accepted.
  void lloyd_step(std::size_t resolution) {
    move_to_targets([this](std::size_t i) -> const Point_2& { return m_centroids[i]; }, max_passes);
    evaluate_trial(resolution);
    accept();
  }

  // Moves each generator i toward target(i), in the last visit order; returns how many did not
  // get there in `passes` passes. The targets are computed when asked for, not stored; the
  // trial point and the evaluator's list are no longer needed.
  // With `keep_out` false, places kept out do not count (a move back to where a generator was).
  template <class Target>
  std::size_t move_to_targets(const Target& target, std::size_t passes, bool keep_out = true) {
    drop_trial();
    m_energy.release_free_generators();
    return m_energy.move_generators(
        m_order, [this](std::size_t i) { return m_vertices[i]; }, target, passes, m_buffers,
        keep_out);
  }

  // Backtracking from the full quasi-Newton step; true if a trial point was accepted.
  bool line_search(std::size_t resolution) {
    const double e0 = m_current.evaluation.energy;
    const std::size_t n = m_vertices.size();
    double step = 1;
    for (std::size_t attempt = 0; attempt <= max_halvings; ++attempt, step /= 2) {
      const double scaled_step = std::ldexp(step, m_direction_exponent);
      move_to_targets(
          [&](std::size_t i) {
            return Point_2(
                FT(m_current.x[2 * i] + scaled_step * double(m_direction[2 * i])),
                FT(m_current.x[2 * i + 1] + scaled_step * double(m_direction[2 * i + 1])));
          },
          max_passes);
      evaluate_trial(resolution);
      // g . s, with the displacement done
      const double slope = internal::sum_of_blocks(
          2 * n, m_energy.number_of_threads(), m_partial, [&](std::size_t first, std::size_t last) {
            double acc = 0;
            for (std::size_t j = first; j < last; ++j)
              acc += m_current.g[j] * (m_trial.x[j] - m_current.x[j]);
            return acc;
          });
      if (m_trial.evaluation.energy <= e0 + armijo * std::min(slope, 0.0)) {
        accept();
        return true;
      }
    }
    return false;
  }

  CDT& m_cdt;
  Energy m_energy;
  internal::Lbfgs_history<float> m_history;
  std::vector<Vertex_handle> m_vertices;            // the free generators, by number
  std::vector<Vertex_handle> m_by_address;          // the same, by_address
  std::vector<std::uint32_t> m_numbers_by_address;  // and their numbers
  Iterate m_current, m_trial;
  std::vector<Point_2> m_centroids;  // of the current point's cells, by number
  std::vector<double> m_h;           // and the preconditioner 1/(2 m)
  bool m_has_current = false;
  std::vector<float> m_direction;  // times 2^m_direction_exponent
  std::vector<double> m_partial;   // the blocks' sums of a dot product
  int m_direction_exponent = 0;
  // The numbers in the last evaluation's visit order, the order before, and its inverse (32
  // bits: four billion generators would take 600 GB).
  std::vector<std::uint32_t> m_order, m_previous_order, m_position;
  internal::Move_buffers<CDT> m_buffers;
  std::size_t m_steps = 0, m_fallbacks = 0, m_restarts = 0;
};

}  // namespace CVT_2

#endif  // CVT_2_LBFGS_OPTIMIZER_2_H
