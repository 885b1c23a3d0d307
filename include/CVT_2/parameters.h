// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// CVT_2::parameters: named parameters in CGAL's idiom (chained calls, get_parameter,
// choose_parameter).
#ifndef CVT_2_PARAMETERS_H
#define CVT_2_PARAMETERS_H

#include <type_traits>
#include <utility>

namespace CVT_2 {
namespace internal_np {

/// What `get_parameter()` returns for a parameter that was not given.
struct Param_not_found {};

#define CVT_2_add_named_parameter(TAG, NAME) \
  struct TAG {};
#ifndef DOXYGEN_RUNNING  // the options are documented where they are read
#include <CVT_2/internal/parameters_interface.h>
#endif
#undef CVT_2_add_named_parameter

}  // namespace internal_np

template <class T, class Tag, class Base>
struct Named_function_parameters;

// The chained calls, `np.density(rho).number_of_iterations(10)`: a member function a parameter,
// stamped in each chain type from the list.
#define CVT_2_add_named_parameter(TAG, NAME)                                       \
  template <class T_>                                                              \
  Named_function_parameters<T_, internal_np::TAG, SELF_> NAME(const T_& v) const { \
    return Named_function_parameters<T_, internal_np::TAG, SELF_>(v, *this);       \
  }

/// \ingroup PkgCvt2Ref
/// No named parameter: every option takes its default. `CVT_2::parameters::default_values()`.
struct No_named_parameters {
  using SELF_ = No_named_parameters;  ///< the chain type, for the chained calls
#ifndef DOXYGEN_RUNNING               // the options are documented where they are read
#include <CVT_2/internal/parameters_interface.h>
#endif
};

/// \ingroup PkgCvt2Ref
/// A chain of named parameters: the value `v` for option `Tag`, then the options of `Base`.
/// Made by the functions of `CVT_2::parameters` and chained with the same names.
template <class T, class Tag, class Base>
struct Named_function_parameters {
  using SELF_ = Named_function_parameters;  ///< the chain type, for the chained calls
  T v;                                      ///< the value
  Base base;                                ///< the rest of the chain
  /// `value` for `Tag`, before the options of `rest`
  Named_function_parameters(const T& value, const Base& rest) : v(value), base(rest) {}
#ifndef DOXYGEN_RUNNING  // the options are documented where they are read
#include <CVT_2/internal/parameters_interface.h>
#endif
};

#undef CVT_2_add_named_parameter

/// \ingroup PkgCvt2Ref
/// The named parameters of the library's functions; see each function for those it reads.
namespace parameters {

/// every option at its default
inline No_named_parameters default_values() { return {}; }

#define CVT_2_add_named_parameter(TAG, NAME)                                             \
  template <class T>                                                                     \
  Named_function_parameters<T, internal_np::TAG, No_named_parameters> NAME(const T& v) { \
    return Named_function_parameters<T, internal_np::TAG, No_named_parameters>(v, {});   \
  }
#ifndef DOXYGEN_RUNNING  // the options are documented where they are read
#include <CVT_2/internal/parameters_interface.h>
#endif
#undef CVT_2_add_named_parameter

}  // namespace parameters

namespace internal_np {

template <class Tag>
Param_not_found get_parameter(const No_named_parameters&, Tag) {
  return {};
}
template <class T, class Tag, class Base>
const T& get_parameter(const Named_function_parameters<T, Tag, Base>& np, Tag) {
  return np.v;
}
template <class T, class Tag, class Base, class Query>
decltype(auto) get_parameter(const Named_function_parameters<T, Tag, Base>& np, Query q) {
  return get_parameter(np.base, q);
}

/// the value given, or `default_value` if none was
template <class D>
D choose_parameter(Param_not_found, const D& default_value) {
  return default_value;
}
template <class T, class D>
const T& choose_parameter(const T& value, const D&) {
  return value;
}

/// whether `NP` holds a value for `Tag`
template <class NP, class Tag>
constexpr bool has_parameter =
    !std::is_same_v<std::decay_t<decltype(get_parameter(std::declval<const NP&>(), Tag()))>,
                    Param_not_found>;

}  // namespace internal_np
}  // namespace CVT_2

#endif  // CVT_2_PARAMETERS_H
