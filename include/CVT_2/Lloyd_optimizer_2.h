// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Lloyd_optimizer_2: Lloyd iteration on a bounded Voronoi diagram, one evaluation or move at a
// time.
#ifndef CVT_2_LLOYD_OPTIMIZER_2_H
#define CVT_2_LLOYD_OPTIMIZER_2_H

#include <CVT_2/Bvd_traits_2.h>
#include <CVT_2/Cvt_energy_2.h>
#include <CVT_2/Uniform_density_2.h>
#include <CVT_2/internal/move_generators.h>

#include <boost/range/irange.hpp>

#include <cstddef>

namespace CVT_2 {

/// \ingroup PkgCvt2Ref
/// Lloyd iteration on the bounded Voronoi diagram of a constrained Delaunay triangulation,
/// usable step by step: `evaluate()` computes the diagram, the moments of every cell, the
/// energy and the move ratios \f$mr(x) = \|x - x^*\| / \mathrm{diameter}(V)\f$ of the free
/// generators (a `Cvt_energy_2` evaluation); `move()` moves every free generator to the centroid
/// \f$x^*\f$ of its cell. `lloyd_optimize_2()` drives it with the paper's stopping rule.
///
/// The triangulation is updated in place, in the structure the user sees: the generators move
/// at once, those of any face that this folds go back and move within their stars instead (the
/// faces around them keep their orientation, so no edge and so no constraint is crossed; a
/// target beyond the star is approached in several iterations), then edge flips restore the
/// constrained Delaunay property (user manual, "Updating the triangulation"). Vertex handles
/// stay valid; constrained vertices never move, but for those of sliding runs
/// (`set_sliding_runs()`).
///
/// \tparam CDT as for `Bounded_voronoi_diagram_2`, with its domain marked.
/// \tparam Density a model of `DensityFunction_2`: the energy's, see `Cvt_energy_2`.
/// \tparam Quadrature a model of `CellQuadrature_2`: the energy's, see `Cvt_energy_2`.
/// \tparam Traits a model of `BvdTraits_2`: the energy's, see `Cvt_energy_2`.
template <class CDT, class Density = Uniform_density_2<typename CDT::Geom_traits>,
          class Quadrature = internal::Default_quadrature<typename CDT::Geom_traits, Density>,
          class Traits = Bvd_traits_2<typename CDT::Geom_traits>>
class Lloyd_optimizer_2 {
 public:
  using Energy = Cvt_energy_2<CDT, Density, Quadrature, Traits>;  ///< what it evaluates
  using Triangulation = CDT;                                      ///< the triangulation type
  using Kernel = typename CDT::Geom_traits;                       ///< its kernel
  using FT = typename Kernel::FT;                                 ///< number type
  using Point_2 = typename Kernel::Point_2;                       ///< point type
  using Vertex_handle = typename CDT::Vertex_handle;              ///< a generator
  using Diagram = typename Energy::Diagram;                       ///< the diagram it iterates on
  using Density_function = Density;                               ///< the density policy
  using Cell_quadrature = Quadrature;                             ///< the quadrature policy
  using Evaluation = typename Energy::Evaluation;                 ///< what one evaluation found
  using Free_generator = typename Energy::Free_generator;         ///< as `Cvt_energy_2`'s
  using Free_generators = typename Energy::Free_generators;       ///< as `Cvt_energy_2`'s

  /// Prepares the iteration on `cdt` (nothing is computed yet).
  explicit Lloyd_optimizer_2(CDT& cdt, const Density& rho = Density(),
                             const Quadrature& quadrature = Quadrature(),
                             const Traits& traits = Traits())
      : m_cdt(cdt), m_energy(cdt, rho, quadrature, traits) {}

  /// Evaluates the generators where they are: `Cvt_energy_2::evaluate()`.
  const Evaluation& evaluate(std::size_t resolution) { return m_energy.evaluate(resolution); }

  /// The number of threads that `evaluate()` builds cells and integrates them on, and that
  /// `move()` checks the moved faces and flips most edges on; 0 (the default) means one per
  /// core. The results are the same, bit for bit, whatever the number.
  void set_number_of_threads(unsigned n) { m_energy.set_number_of_threads(n); }
  /// Generators that never move: `Cvt_energy_2::fix_generators()`. Before the first evaluation.
  void fix_generators(const std::vector<Vertex_handle>& vertices) {
    m_energy.fix_generators(vertices);
  }
  /// Moves only the free generators among `vertices`, evaluating only around them:
  /// `Cvt_energy_2::set_region()`. Before the first evaluation.
  void set_region(const std::vector<Vertex_handle>& vertices) { m_energy.set_region(vertices); }
  /// Keeps the moves out of places: `Cvt_energy_2::set_keep_out()`.
  template <class KeepOut>
  void set_keep_out(const KeepOut& keep_out) {
    m_energy.set_keep_out(keep_out);
  }
  /// Lets the vertices of `runs` slide along them: `Cvt_energy_2::set_sliding_runs()`.
  void set_sliding_runs(Sliding_runs_2<CDT>* runs) { m_energy.set_sliding_runs(runs); }
  unsigned number_of_threads() const { return m_energy.number_of_threads(); }  ///< as set

  /// Moves every free generator to the centroid that the last `evaluate()` computed (or, if
  /// that would fold a face, as far toward it as its star allows), then restores the
  /// constrained Delaunay property; then the sliding vertices, if any, to their constrained
  /// centroids (`Sliding_runs_2`). Returns the number of free generators that reached their
  /// centroid.
  /// \pre the triangulation has not changed since the last `evaluate()`.
  std::size_t move() {
    const Free_generators& moves = m_energy.free_generators();
    const std::size_t n = moves.size();
    const std::size_t missed = m_energy.move_generators(
        boost::irange(std::size_t(0), n), [&moves](std::size_t k) { return moves[k].vertex; },
        [&moves](std::size_t k) -> const Point_2& { return moves[k].centroid; }, 1, m_buffers);
    m_energy.release_free_generators();
    m_energy.slide_generators();
    return n - missed;
  }

  /// the last evaluation
  const Evaluation& last_evaluation() const { return m_energy.last_evaluation(); }
  /// the number of calls of `evaluate()` so far
  std::size_t number_of_evaluations() const { return m_energy.number_of_evaluations(); }
  /// The free generators of the last evaluation, in the order the cells were visited (a
  /// `move()` empties it).
  const Free_generators& free_generators() const { return m_energy.free_generators(); }
  const Diagram& diagram() const { return m_energy.diagram(); }  ///< as last evaluated
  const Energy& energy() const { return m_energy; }              ///< the evaluator
  const CDT& triangulation() const { return m_cdt; }             ///< the triangulation

 private:
  CDT& m_cdt;
  Energy m_energy;
  internal::Move_buffers<CDT> m_buffers;
};

}  // namespace CVT_2

#endif  // CVT_2_LLOYD_OPTIMIZER_2_H
