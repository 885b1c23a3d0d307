// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// lloyd_optimize_2(): Lloyd iteration with the paper's stopping rule, options as named parameters.
#ifndef CVT_2_LLOYD_OPTIMIZE_2_H
#define CVT_2_LLOYD_OPTIMIZE_2_H

#include <CVT_2/Lloyd_optimizer_2.h>
#include <CVT_2/Optimization_result.h>
#include <CVT_2/density_response_2.h>
#include <CVT_2/internal/run_optimization.h>
#include <CVT_2/parameters.h>

namespace CVT_2 {

/// \ingroup PkgCvt2Ref
/// Lloyd iteration (paper, Section 3): moves every free generator of `cdt` to the centroid of
/// its bounded Voronoi cell under a density \f$\rho\f$, and again, until every move ratio
/// \f$mr(x) = \|x - x^*\|/\mathrm{diameter}(V)\f$ is below `move_ratio_bound`, or another
/// limit is met. Constrained vertices stay (but for those of `sliding_runs`); a free generator
/// never crosses a constraint.
/// The result describes the generators as they are at the end (`Optimization_result`). Under a
/// density that is not uniform, a run over the whole domain measures how the final cells follow
/// it (`density_response_2()`): a stop with every move ratio below the bound whose cells do not
/// is `STALLED`, not `CONVERGED` (the move ratios see local moves only, and from points that do
/// not follow the density they fall below 1% long before the cells have the sizes it asks for;
/// nor do they see regions between constraints with too many points or too few).
///
/// \param cdt a constrained Delaunay triangulation with its domain marked (see
///        `Bounded_voronoi_diagram_2`); its free vertices are moved in place. If
///        `number_of_iterations` is 16 or more, faces that CGAL's own insertion left
///        scattered in memory (2^16 faces or more) are first laid out as
///        `insert_generators_2()` does (its time counts in the run's): face handles held
///        before the call then refer to other faces, and the results differ in the last
///        bits from those of a shorter run.
/// \param np optional named parameters among:
///   - `density(rho)`: a model of `DensityFunction_2` (a lambda works); default uniform.
///   - `sizing_field(mu)`: a sizing field \f$\mu\f$ instead, used as \f$\rho = 1/\mu^4\f$ (cell
///     size scales as \f$\rho^{-1/4}\f$); not together with `density`.
///   - `quadrature(q)`: a model of `CellQuadrature_2`; default `Exact_quadrature_2` for a
///     `Uniform_density_2`, `Gauss_quadrature_2` otherwise (`Midpoint_quadrature_2`: the
///     paper's rule).
///   - `minimum_quadrature_resolution(n)`, `maximum_quadrature_resolution(n)`: sub-triangles a
///     cell, raised from the first to the second as moves shrink; default 10 and 100 (only
///     quadratures with a resolution, as the midpoint rule, use them).
///   - `move_ratio_bound(p)`: stop when every move ratio is below `p`; default 0.01; 0 turns
///     this stop off.
///   - `number_of_iterations(n)`: at most `n` moves, an integer \f$\ge 0\f$; default 1000.
///   - `maximum_running_time(s)`: stop after `s` seconds (checked between iterations); default
///     0, no limit.
///   - `callback(f)`: `bool f(const Optimization_result&)`, called after each evaluation with the
///     figures so far; returning `false` stops.
///   - `verbose(b)`: a line a iteration on `std::clog`; default `false`.
///   - `number_of_threads(n)`: threads that build and integrate the cells; default 0, one per
///     core. The result is the same, bit for bit, whatever `n`.
///   - `fixed_points(r)`: a range of points, vertices of `cdt` (generators inserted before) that
///     never move: a well, an observation point (one on a constraint is a constrained vertex,
///     which never moves anyway). Their cells count in the energy.
///   - `region(r)`, `region_rings(k)`: a local relaxation. Only the free generators among
///     the points `r` (vertices of `cdt`: the changed cells of a `Constraint_editor_2` edit,
///     say) and within `k` rings of them (grown through free generators) move (`k` an integer
///     \f$\ge 0\f$, default 0), and only the cells their moves can change are evaluated
///     (`Cvt_energy_2::set_region()`): an iteration costs the region, not the triangulation, and
///     the faces' blind tags stay right everywhere if they were (a diagram of `cdt` needs no
///     `update()` after it). The energy and move ratios of the result are the region's. Faces are
///     not laid out.
///   - `keep_out(k)`: places no free generator may enter, as the circles of conforming lines
///     (`Conforming_disks`): an object with `bool empty()` and `Point_2 outside(from, to)`,
///     where a generator that would move from `from` to `to` goes instead.
///   - `sliding_runs(&runs)`: a pointer to a `Sliding_runs_2` of `cdt` (filled by
///     `resample_constraints_2()`): its vertices slide along the input polylines, each to its
///     constrained centroid after the free generators' move, and their move ratios count in
///     the stop. Not with `region`.
///   - `geom_traits(t)`: a model of `BvdTraits_2` for the diagram; default `Bvd_traits_2`.
/// \throws std::invalid_argument for a bad parameter value, naming it (a fixed or region point
///         that is not a vertex); Domain_error if the
///         density is not positive and finite at a point where it is evaluated.
template <class CDT, class NP = No_named_parameters>
Optimization_result lloyd_optimize_2(CDT& cdt, const NP& np = parameters::default_values()) {
  using Policies = internal::Energy_parameters<CDT, NP>;
  using Optimizer = Lloyd_optimizer_2<CDT, typename Policies::Density,
                                      typename Policies::Quadrature, typename Policies::Traits>;
  const internal::Run_options options = internal::read_run_options(np);
  const typename Policies::Density density = Policies::density(np);  // before the layout: may throw
  const auto region = internal::region_vertices(cdt, np);
  if (!region) internal::lay_out_faces(cdt, options);
  Optimizer lloyd(cdt, density, Policies::quadrature(np), Policies::traits(np));
  lloyd.set_number_of_threads(options.threads);
  const auto fixed = internal::fixed_vertices(cdt, np);
  lloyd.fix_generators(fixed);
  if (region) lloyd.set_region(*region);
  internal::set_keep_out(lloyd, np);
  internal::set_sliding_runs(lloyd, np);
  Optimization_result r =
      internal::run_optimization(internal::Lloyd_steps<Optimizer>{lloyd}, options, "lloyd");
  if (!region) internal::judge_density_response(cdt, Policies::traits(np), density, fixed, r);
  return r;
}

}  // namespace CVT_2

#endif  // CVT_2_LLOYD_OPTIMIZE_2_H
