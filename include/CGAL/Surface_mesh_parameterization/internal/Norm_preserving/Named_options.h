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
// The named parameters of the whole-mesh calls read into what a run takes: the options, the
// initial guess, the solver, the fixed pair and where the report goes.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_NAMED_OPTIONS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_NAMED_OPTIONS_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Norm_preserving_ADMM_solver.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_named_parameters.h>
#include <CGAL/Surface_mesh_parameterization/XY_min_max_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Call_progress.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Options.h>

#include <CGAL/Named_function_parameters.h>

#include <array>
#include <optional>
#include <utility>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

// The type of the parameter of `Tag` in `NamedParameters`, or `Default`.
template <typename Tag, typename NamedParameters, typename Default>
using Named_type = typename CGAL::internal_np::Lookup_named_param_def<Tag, NamedParameters, Default>::type;

template <typename NamedParameters>
using Named_guess = Named_type<Surface_mesh_parameterization::internal_np::initial_guess_t, NamedParameters,
                               XY_min_max_initial_guess>;
template <typename NamedParameters>
using Named_solver = Named_type<Surface_mesh_parameterization::internal_np::solver_t, NamedParameters,
                                Norm_preserving_ADMM_solver>;

template <typename NamedParameters>
Options named_options(const NamedParameters& np)
{
  namespace P = CGAL::parameters;
  namespace T = Surface_mesh_parameterization::internal_np;
  Options options;
  options.texture_fit = P::choose_parameter(P::get_parameter(np, T::texture_fit), options.texture_fit);
  const std::array<int, 2> tiles =
    P::choose_parameter(P::get_parameter(np, T::tiling), std::array<int, 2>{options.tiles_u, options.tiles_v});
  options.tiles_u = tiles[0];
  options.tiles_v = tiles[1];
  std::tie(options.sign_refinement_rounds, options.sign_refinement_tolerance) = P::choose_parameter(
    P::get_parameter(np, T::sign_refinement), std::make_pair(options.sign_refinement_rounds, options.sign_refinement_tolerance));
  std::tie(options.euclidean_refinement_iterations, options.euclidean_refinement_tolerance) =
    P::choose_parameter(P::get_parameter(np, T::euclidean_refinement),
                        std::make_pair(options.euclidean_refinement_iterations, options.euclidean_refinement_tolerance));
  options.weld_coincident_vertices =
    P::choose_parameter(P::get_parameter(np, T::weld_coincident_vertices), options.weld_coincident_vertices);
  return options;
}

template <typename NamedParameters>
Named_guess<NamedParameters> named_guess(const NamedParameters& np)
{
  return CGAL::parameters::choose_parameter<Named_guess<NamedParameters> >(
    CGAL::parameters::get_parameter(np, Surface_mesh_parameterization::internal_np::initial_guess));
}

// The solver given, or the default solver of the quality given: one or the other.
template <typename NamedParameters>
Named_solver<NamedParameters> named_solver(const NamedParameters& np)
{
  namespace T = Surface_mesh_parameterization::internal_np;
  constexpr bool has_solver = !CGAL::parameters::is_default_parameter<NamedParameters, T::solver_t>::value;
  constexpr bool has_quality = !CGAL::parameters::is_default_parameter<NamedParameters, T::quality_t>::value;
  static_assert(!(has_solver && has_quality), "quality() chooses the default solver: give it or solver(), not both");
  if constexpr(has_solver)
    return CGAL::parameters::get_parameter(np, T::solver);
  else
    return Norm_preserving_ADMM_solver(
      CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, T::quality), NORM_PRESERVING_DEFAULT_QUALITY));
}

// The fixed pair, if one is given, its vertices turned into soup indices by `index`.
template <typename NamedParameters, typename Index>
std::optional<std::pair<std::size_t, std::size_t> > named_fixed_pair(const NamedParameters& np, const Index& index)
{
  namespace T = Surface_mesh_parameterization::internal_np;
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, T::fixed_pair_t>::value)
    return std::nullopt;
  else
  {
    const auto pair = CGAL::parameters::get_parameter(np, T::fixed_pair);
    return std::make_pair(index(pair.first), index(pair.second));
  }
}

// Where the report goes, or null.
template <typename Report, typename NamedParameters>
Report* named_report(const NamedParameters& np)
{
  return CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, Surface_mesh_parameterization::internal_np::report),
                                            static_cast<Report*>(nullptr));
}

// The progress callback, or an empty one.
template <typename NamedParameters>
Progress_callback named_progress(const NamedParameters& np)
{
  namespace T = Surface_mesh_parameterization::internal_np;
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, T::progress_t>::value)
    return Progress_callback();
  else
    return CGAL::parameters::get_parameter(np, T::progress);
}

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
