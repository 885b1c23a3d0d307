// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// lbfgs_optimize_2(): L-BFGS on the CVT energy with Lloyd's stopping rule and named parameters.
#ifndef CVT_2_LBFGS_OPTIMIZE_2_H
#define CVT_2_LBFGS_OPTIMIZE_2_H

#include <CVT_2/Lbfgs_optimizer_2.h>
#include <CVT_2/Optimization_result.h>
#include <CVT_2/density_response_2.h>
#include <CVT_2/internal/run_optimization.h>
#include <CVT_2/parameters.h>

namespace CVT_2 {

/// \ingroup PkgCvt2Ref
/// L-BFGS on the CVT energy (Liu et al. 2009; see `Lbfgs_optimizer_2`): the same result as
/// `lloyd_optimize_2()`, a centroidal Voronoi tessellation of the domain under a density
/// \f$\rho\f$, in fewer evaluations of the diagram. It starts with a Lloyd step, and falls
/// back to one whenever its line search fails. It stops by the same rule as
/// `lloyd_optimize_2()`: every move ratio \f$mr(x) = \|x - x^*\|/\mathrm{diameter}(V)\f$ of
/// the last evaluation below `move_ratio_bound` (confirmed at the maximum quadrature
/// resolution), or another limit. Constrained vertices stay (but for those of `sliding_runs`);
/// a free generator never crosses a constraint. With an exact quadrature the energy never rises;
/// with an approximate quadrature the energy and the gradient are approximate, and a line search
/// that their error makes fail ends in a Lloyd step (see `Lbfgs_optimizer_2`).
///
/// The result describes the generators as they are at the end. An iteration is one step,
/// its line search included; `energy_history` and the move ratio histories have one entry a
/// step (the point it accepted), the first before any move. A step costs one evaluation when
/// its first trial point is accepted, which is the rule; `number_of_evaluations` counts them,
/// line-search trials included. Under a density that is not uniform, a stop whose cells do not
/// follow it is `STALLED`, as for `lloyd_optimize_2()`.
///
/// \param cdt a constrained Delaunay triangulation with its domain marked (see
///        `Bounded_voronoi_diagram_2`); its free vertices are moved in place. If
///        `number_of_iterations` is 16 or more, faces that CGAL's own insertion left
///        scattered in memory (2^16 faces or more) are first laid out as
///        `insert_generators_2()` does (its time counts in the run's): face handles held
///        before the call then refer to other faces, and the results differ in the last
///        bits from those of a shorter run.
/// \param np optional named parameters: those of `lloyd_optimize_2()` (`density`,
///        `sizing_field`, `quadrature`, `minimum_quadrature_resolution`,
///        `maximum_quadrature_resolution`, `move_ratio_bound`, `number_of_iterations` (at most
///        that many steps), `maximum_running_time`, `callback` (called after each step),
///        `verbose`, `number_of_threads`, `fixed_points`, `region`, `region_rings`, `keep_out`,
///        `sliding_runs`, `geom_traits`), with the same meanings and defaults, and
///   - `lbfgs_memory(m)`: the number of curvature pairs kept, an integer \f$\ge 0\f$;
///     default 7; 0 makes every step a Lloyd step.
/// \throws std::invalid_argument for a bad parameter value, naming it (a fixed point that is
///         not a vertex); Domain_error if the
///         density is not positive and finite at a point where it is evaluated.
template <class CDT, class NP = No_named_parameters>
Optimization_result lbfgs_optimize_2(CDT& cdt, const NP& np = parameters::default_values()) {
  using Policies = internal::Energy_parameters<CDT, NP>;
  using Optimizer = Lbfgs_optimizer_2<CDT, typename Policies::Density,
                                      typename Policies::Quadrature, typename Policies::Traits>;
  const internal::Run_options options = internal::read_run_options(np);
  const typename Policies::Density density = Policies::density(np);  // before the layout: may throw
  const auto region = internal::region_vertices(cdt, np);
  if (!region) internal::lay_out_faces(cdt, options);
  Optimizer lbfgs(cdt, density, Policies::quadrature(np), options.lbfgs_memory,
                  Policies::traits(np));
  lbfgs.set_number_of_threads(options.threads);
  const auto fixed = internal::fixed_vertices(cdt, np);
  lbfgs.fix_generators(fixed);
  if (region) lbfgs.set_region(*region);
  internal::set_keep_out(lbfgs, np);
  internal::set_sliding_runs(lbfgs, np);
  Optimization_result r = internal::run_optimization(lbfgs, options, "lbfgs");
  if (!region) internal::judge_density_response(cdt, Policies::traits(np), density, fixed, r);
  return r;
}

}  // namespace CVT_2

#endif  // CVT_2_LBFGS_OPTIMIZE_2_H
