// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Cell_moments_2: mass, first moment and energy of a cell under a density, relative to its
// generator.
#ifndef CVT_2_CELL_MOMENTS_2_H
#define CVT_2_CELL_MOMENTS_2_H

namespace CVT_2 {

/// \ingroup PkgCvt2Policies
/// The moments of a cell \f$V\f$ of generator \f$x\f$ under a density \f$\rho\f$, relative to
/// \f$x\f$ so that coordinates far from the origin do not cancel:
/// `mass` \f$= \int_V \rho\f$, `first_moment` \f$= \int_V \rho(y)(y - x)\,dy\f$,
/// `energy` \f$= \int_V \rho(y)\|y - x\|^2 dy\f$. The centroid is `x + first_moment / mass`.
template <class K>
struct Cell_moments_2 {
  typename K::FT mass = 0;                  ///< \f$\int_V \rho\f$
  typename K::Vector_2 first_moment{0, 0};  ///< \f$\int_V \rho(y)(y - x)\,dy\f$
  typename K::FT energy = 0;                ///< \f$\int_V \rho(y)\|y - x\|^2 dy\f$

  /// adds the moments of another part of the cell, relative to the same generator
  Cell_moments_2& operator+=(const Cell_moments_2& m) {
    mass += m.mass;
    first_moment = first_moment + m.first_moment;
    energy += m.energy;
    return *this;
  }
};

}  // namespace CVT_2

#endif  // CVT_2_CELL_MOMENTS_2_H
