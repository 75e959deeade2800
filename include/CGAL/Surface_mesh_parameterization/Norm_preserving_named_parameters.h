// Copyright (c) 2026  The CGAL_norm_preserving_parameterization authors.
// All rights reserved.
//
// This file is part of the package Norm_preserving_parameterization for CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The CGAL_norm_preserving_parameterization authors
//
/// \file Norm_preserving_named_parameters.h
/// \ingroup PkgNormPreservingParameterization
/// The named parameters of the whole-mesh calls.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_NAMED_PARAMETERS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_NAMED_PARAMETERS_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/disable_warnings.h>

#include <CGAL/Surface_mesh_parameterization/Norm_preserving_quality.h>
#include <CGAL/Surface_mesh_parameterization/Texture_fit.h>

#include <CGAL/Named_function_parameters.h>

#include <array>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \cond SKIP_IN_MANUAL
// The package's own tags; CGAL's tags `vertex_point`, `point` and `geom_traits` are CGAL's.
namespace internal_np {
enum initial_guess_t { initial_guess };
enum solver_t { solver };
enum quality_t { quality };
enum texture_fit_t { texture_fit };
enum tiling_t { tiling };
enum fixed_pair_t { fixed_pair };
enum sign_refinement_t { sign_refinement };
enum euclidean_refinement_t { euclidean_refinement };
enum weld_coincident_vertices_t { weld_coincident_vertices };
enum report_t { report };
enum progress_t { progress };
} // namespace internal_np
/// \endcond

/// \cond SKIP_IN_MANUAL
namespace internal {
namespace Norm_preserving {

// Whether CGAL's named parameters have `combine()` (CGAL 6): the way CGAL lets a package
// outside it add parameters to a chain.
template <typename NP, typename = void>
struct Has_combine : std::false_type { };
template <typename NP>
struct Has_combine<NP, std::void_t<decltype(std::declval<const NP&>().combine(std::declval<const NP&>()))> >
  : std::true_type { };

// CGAL 5.5's named parameters, with the `combine()` that CGAL 6 has: on CGAL 5.5, a chain of
// this package's parameters (or of `vertex_point_map()`, `point_map()`, `geom_traits()` started
// here) is joined the way CGAL 6 joins them (doc/decisions.md, "Named parameters").
template <typename T, typename Tag, typename Base = CGAL::internal_np::No_property>
struct Combinable_named_parameters : CGAL::Named_function_parameters<T, Tag, Base>
{
  typedef CGAL::Named_function_parameters<T, Tag, Base> Cgal_parameters;
  typedef Combinable_named_parameters<T, Tag, Base> self;
  using Cgal_parameters::Cgal_parameters;

  template <typename OT, typename OTag>
  Combinable_named_parameters<OT, OTag, self> combine(const CGAL::Named_function_parameters<OT, OTag>& np) const
  {
    return Combinable_named_parameters<OT, OTag, self>(np.v, *this);
  }
  template <typename OT, typename OTag, typename... NPS>
  auto combine(const CGAL::Named_function_parameters<OT, OTag>& np, const NPS&... nps) const
  {
    return combine(np).combine(nps...);
  }
};

// CGAL's own named parameters where they combine, the class above otherwise.
template <typename T, typename Tag>
using Package_named_parameters = typename std::conditional<
  Has_combine<CGAL::parameters::Default_named_parameters>::value,
  CGAL::Named_function_parameters<T, Tag>, Combinable_named_parameters<T, Tag> >::type;

} // namespace Norm_preserving
} // namespace internal
/// \endcond

/// The named parameters of `texture_polygon_soup()`, `texture_polygon_mesh()` and
/// `texture_indexed_mesh()`, each a CGAL named parameter of its own. `combine()` joins them,
/// in any order, as CGAL 6 joins a package's parameters to CGAL's own:
/// `SMP::parameters::tiling(2, 2).combine(SMP::parameters::quality(SMP::NORM_PRESERVING_DRAFT_QUALITY))`,
/// or on CGAL 6 `CGAL::parameters::vertex_point_map(vpm).combine(SMP::parameters::tiling(2, 2))`.
/// A parameter left out takes its default.
namespace parameters {

/// \cond SKIP_IN_MANUAL
template <typename Tag, typename T>
internal::Norm_preserving::Package_named_parameters<T, Tag> start(const T& value)
{
  return internal::Norm_preserving::Package_named_parameters<T, Tag>(value);
}
/// \endcond

/// the initial guess of every component: a model of `NormPreservingInitialGuess`;
/// default `XY_min_max_initial_guess()`.
template <typename Guess>
auto initial_guess(const Guess& g) { return start<internal_np::initial_guess_t>(g); }

/// the QP solver: a model of `NormPreservingSolver` or of `QuadraticProgramTraits`; default the
/// `Norm_preserving_ADMM_solver` of `quality()`. Not together with `quality()`.
template <typename Solver>
auto solver(const Solver& s) { return start<internal_np::solver_t>(s); }

/// how close to the optimum the default solver goes, `Norm_preserving_ADMM_solver(q)`; default
/// `NORM_PRESERVING_DEFAULT_QUALITY`. Not together with `solver()`.
inline auto quality(Norm_preserving_quality q) { return start<internal_np::quality_t>(q); }

/// the fit into texture space; default `NORM_PRESERVING_UNIFORM_FIT`.
inline auto texture_fit(Texture_fit fit) { return start<internal_np::texture_fit_t>(fit); }

/// the `m x n` tiling: after the fit, `u` is scaled by `m` and `v` by `n`; both at least 1;
/// default 1 x 1.
inline auto tiling(int m, int n) { return start<internal_np::tiling_t>(std::array<int, 2>{m, n}); }

/// the fixed pair of the component that holds it: two adjacent vertices, `a` put at the origin
/// and `b` along the guessed direction; soup vertices (of `texture_polygon_soup()` and
/// `texture_indexed_mesh()`) as indices, mesh vertices (of `texture_polygon_mesh()`) as vertex
/// descriptors. Every other component, and all of them by default, takes an automatic pair.
template <typename Vertex>
auto fixed_pair(const Vertex& a, const Vertex& b) { return start<internal_np::fixed_pair_t>(std::make_pair(a, b)); }

/// sign refinement (beyond the paper; `Norm_preserving_parameterizer_3::set_sign_refinement()`):
/// at most `max_rounds` rounds (0: off, the default), stopping at a relative decrease of at
/// most `tolerance`.
inline auto sign_refinement(int max_rounds, double tolerance = 1e-3)
{
  return start<internal_np::sign_refinement_t>(std::make_pair(max_rounds, tolerance));
}

/// Euclidean refinement (beyond the paper;
/// `Norm_preserving_parameterizer_3::set_euclidean_refinement()`): at most `max_iterations`
/// steps (0: off, the default), stopping at a relative decrease of at most `tolerance`.
inline auto euclidean_refinement(int max_iterations, double tolerance = 1e-3)
{
  return start<internal_np::euclidean_refinement_t>(std::make_pair(max_iterations, tolerance));
}

/// whether vertices at exactly the same position are one vertex for the solve and get the same
/// uv (a file split along old seams then gets no seam there); default `true`.
inline auto weld_coincident_vertices(bool weld) { return start<internal_np::weld_coincident_vertices_t>(weld); }

/// receives what the call did: a `Texture_polygon_mesh_report`.
template <typename Report>
auto report(Report& r) { return start<internal_np::report_t>(&r); }

/// a callable `bool(const Norm_preserving_progress&)` called as the work goes on; returning
/// `false` stops the call (`Norm_preserving_progress`).
template <typename Callback>
auto progress(const Callback& f) { return start<internal_np::progress_t>(f); }

/// CGAL's `vertex_point_map` (of `texture_polygon_mesh()`), for a chain that `combine()` joins on
/// CGAL 5.5 too.
template <typename Map>
auto vertex_point_map(const Map& m) { return start<CGAL::internal_np::vertex_point_t>(m); }

/// CGAL's `point_map` (of `texture_polygon_soup()`), for a chain that `combine()` joins on
/// CGAL 5.5 too.
template <typename Map>
auto point_map(const Map& m) { return start<CGAL::internal_np::point_t>(m); }

/// CGAL's `geom_traits`, for a chain that `combine()` joins on CGAL 5.5 too.
template <typename Traits>
auto geom_traits(const Traits& t) { return start<CGAL::internal_np::geom_traits_t>(t); }

} // namespace parameters

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif
