// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// lbfgs_optimize_2(): L-BFGS on the CVT energy with Lloyd's stopping rule and named parameters.
#ifndef CVT_2_LBFGS_OPTIMIZE_2_H
#define CVT_2_LBFGS_OPTIMIZE_2_H

#include <CVT_2/Lbfgs_optimizer_2.h>
#include <CVT_2/Lloyd_optimizer_2.h>
#include <CVT_2/internal/run_optimization.h>
#include <CVT_2/parameters.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace CVT_2 {

/// \ingroup PkgCvt2Ref
/// L-BFGS on the CVT energy (Liu et al. 2009; see `Lbfgs_optimizer_2`): the same result as
/// `lloyd_optimize_2()`, a centroidal Voronoi tessellation of the domain under a density
/// \f$\rho\f$, in fewer evaluations of the diagram. It starts with a Lloyd step, and falls
/// back to one whenever its line search fails. It stops by the same rule as
/// `lloyd_optimize_2()`: every move ratio \f$mr(x) = \|x - x^*\|/\mathrm{diameter}(V)\f$ of
/// the last evaluation below `move_ratio_bound` (confirmed at the maximum quadrature
/// resolution), or another limit. Constrained vertices stay; a free generator never crosses
/// a constraint. With an exact quadrature the energy never rises; with the midpoint rule the
/// energy and the gradient are approximate, and a line search that their error makes fail
/// ends in a Lloyd step (see `Lbfgs_optimizer_2`).
///
/// The result describes the generators as they are at the end. An iteration is one step,
/// its line search included; `energy_history` and the move ratio histories have one entry a
/// step (the point it accepted), the first before any move. A step costs one evaluation when
/// its first trial point is accepted, which is the rule; `Lbfgs_optimizer_2` counts
/// evaluations (`Lloyd_result` has no field for them).
///
/// \param cdt a constrained Delaunay triangulation with its domain marked (see
///        `Bounded_voronoi_diagram_2`); its free vertices are moved in place.
/// \param np optional named parameters: those of `lloyd_optimize_2()` (`density`,
///        `sizing_field`, `quadrature`, `minimum_quadrature_resolution`,
///        `maximum_quadrature_resolution`, `move_ratio_bound`, `number_of_iterations` (at most
///        that many steps), `maximum_running_time`, `callback` (called after each step),
///        `verbose`, `number_of_threads`), with the same meanings and defaults, and
///   - `lbfgs_memory(m)`: the number of curvature pairs kept, an integer \f$\ge 0\f$;
///     default 7; 0 makes every step a Lloyd step.
/// \throws std::invalid_argument for a bad parameter value, naming it; Domain_error if the
///         density is not positive and finite at a point where it is evaluated.
template <class CDT, class NP = No_named_parameters>
Lloyd_result lbfgs_optimize_2(CDT& cdt, const NP& np = parameters::default_values()) {
  using namespace internal_np;
  using K = typename CDT::Geom_traits;
  static_assert(!(has_parameter<NP, density_t> && has_parameter<NP, sizing_field_t>),
                "lbfgs_optimize_2: give either density() or sizing_field(), not both");
  const internal::Run_options options = internal::read_run_options(np);
  const auto memory = choose_parameter(get_parameter(np, lbfgs_memory_t()), 7);
  static_assert(std::is_integral_v<std::decay_t<decltype(memory)>>,
                "lbfgs_memory(m): m must be an integer");
  if constexpr (std::is_signed_v<std::decay_t<decltype(memory)>>) {
    if (memory < 0) throw std::invalid_argument("lbfgs_memory must be >= 0, not " + std::to_string(memory));
  }
  return internal::with_density_and_quadrature<K>(np, [&](const auto& rho, const auto& quadrature) {
    Lbfgs_optimizer_2<CDT, std::decay_t<decltype(rho)>, std::decay_t<decltype(quadrature)>> lbfgs(
        cdt, rho, quadrature, static_cast<std::size_t>(memory));
    lbfgs.set_number_of_threads(options.threads);
    return internal::run_optimization(lbfgs, options, "lbfgs");
  });
}

}  // namespace CVT_2

#endif  // CVT_2_LBFGS_OPTIMIZE_2_H
