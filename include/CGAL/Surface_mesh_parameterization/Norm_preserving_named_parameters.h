// Copyright (c) 2026 The CGAL_norm_preserving_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
/// \file Norm_preserving_named_parameters.h
/// \ingroup PkgNormPreservingParameterization
/// The named parameters of the whole-mesh calls.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_NAMED_PARAMETERS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_NAMED_PARAMETERS_H

#include <CGAL/Surface_mesh_parameterization/Norm_preserving_quality.h>
#include <CGAL/Surface_mesh_parameterization/Texture_fit.h>

#include <CGAL/Named_function_parameters.h>

#include <array>
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

/// \ingroup PkgNormPreservingParameterizationTypes
/// A pack of named parameters of the whole-mesh calls: CGAL's `Named_function_parameters`,
/// which CGAL's `get_parameter()` and `choose_parameter()` read, with a member for each of the
/// package's parameters so that they chain in any order, as CGAL's own do. Made by the
/// functions of `CGAL::Surface_mesh_parameterization::parameters`, never directly.
///
/// CGAL 5.5's named parameters cannot be extended outside CGAL: a chain started by
/// `CGAL::parameters::` takes no parameter of this package. Start it here instead
/// (`SMP::parameters::vertex_point_map(vpm).tiling(2, 2)`); on CGAL 6, a chain of CGAL's can also
/// take one of these through its `combine()`.
template <typename T, typename Tag, typename Base = CGAL::internal_np::No_property>
struct Norm_preserving_named_parameters : CGAL::Named_function_parameters<T, Tag, Base>
{
  /// \cond SKIP_IN_MANUAL
  typedef CGAL::Named_function_parameters<T, Tag, Base> Cgal_parameters;
  typedef Norm_preserving_named_parameters<T, Tag, Base> self;
  using Cgal_parameters::Cgal_parameters;

  template <typename K, typename KTag>
  Norm_preserving_named_parameters<K, KTag, self> add(const K& k) const
  {
    return Norm_preserving_named_parameters<K, KTag, self>(k, *this);
  }

  template <typename Guess> auto initial_guess(const Guess& g) const { return add<Guess, internal_np::initial_guess_t>(g); }
  template <typename Solver> auto solver(const Solver& s) const { return add<Solver, internal_np::solver_t>(s); }
  auto quality(Norm_preserving_quality q) const { return add<Norm_preserving_quality, internal_np::quality_t>(q); }
  auto texture_fit(Texture_fit fit) const { return add<Texture_fit, internal_np::texture_fit_t>(fit); }
  auto tiling(int m, int n) const { return add<std::array<int, 2>, internal_np::tiling_t>({m, n}); }
  template <typename Vertex>
  auto fixed_pair(const Vertex& a, const Vertex& b) const
  {
    return add<std::pair<Vertex, Vertex>, internal_np::fixed_pair_t>({a, b});
  }
  auto sign_refinement(int max_rounds, double tolerance = 1e-3) const
  {
    return add<std::pair<int, double>, internal_np::sign_refinement_t>({max_rounds, tolerance});
  }
  auto euclidean_refinement(int max_iterations, double tolerance = 1e-3) const
  {
    return add<std::pair<int, double>, internal_np::euclidean_refinement_t>({max_iterations, tolerance});
  }
  auto weld_coincident_vertices(bool weld) const { return add<bool, internal_np::weld_coincident_vertices_t>(weld); }
  template <typename Report> auto report(Report& r) const { return add<Report*, internal_np::report_t>(&r); }
  template <typename Callback> auto progress(const Callback& f) const { return add<Callback, internal_np::progress_t>(f); }
  template <typename Map> auto vertex_point_map(const Map& m) const { return add<Map, CGAL::internal_np::vertex_point_t>(m); }
  template <typename Map> auto point_map(const Map& m) const { return add<Map, CGAL::internal_np::point_t>(m); }
  template <typename Traits> auto geom_traits(const Traits& t) const { return add<Traits, CGAL::internal_np::geom_traits_t>(t); }
  /// \endcond
};

/// The named parameters of `texture_polygon_soup()`, `texture_polygon_mesh()` and
/// `texture_indexed_mesh()`. Each function starts a chain; the same names as members continue
/// it, in any order: `SMP::parameters::tiling(2, 2).quality(SMP::NORM_PRESERVING_DRAFT_QUALITY)`.
/// A parameter left out takes its default.
namespace parameters {

/// \cond SKIP_IN_MANUAL
template <typename Tag, typename T>
Norm_preserving_named_parameters<T, Tag> start(const T& value)
{
  return Norm_preserving_named_parameters<T, Tag>(value);
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

/// CGAL's `vertex_point_map` (of `texture_polygon_mesh()`), starting a chain of this package.
template <typename Map>
auto vertex_point_map(const Map& m) { return start<CGAL::internal_np::vertex_point_t>(m); }

/// CGAL's `point_map` (of `texture_polygon_soup()`), starting a chain of this package.
template <typename Map>
auto point_map(const Map& m) { return start<CGAL::internal_np::point_t>(m); }

/// CGAL's `geom_traits`, starting a chain of this package.
template <typename Traits>
auto geom_traits(const Traits& t) { return start<CGAL::internal_np::geom_traits_t>(t); }

} // namespace parameters

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
