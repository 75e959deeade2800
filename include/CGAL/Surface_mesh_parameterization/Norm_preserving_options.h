// Copyright (c) 2026 The CGAL_norm_preserving_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
/// \file Norm_preserving_options.h
/// \ingroup PkgNormPreservingParameterization
/// The options shared by the parameterizer and the whole-soup calls.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_OPTIONS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_OPTIONS_H

#include <CGAL/Surface_mesh_parameterization/Texture_fit.h>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterizationTypes
/// The options of `Norm_preserving_parameterizer_3` (`set_options()`, or one setter each) and
/// of the whole-soup calls (the base of `Texture_polygon_mesh_options`). A call that finds one
/// out of range returns `ERROR_WRONG_PARAMETER` and writes nothing.
struct Norm_preserving_options
{
  Texture_fit texture_fit = NORM_PRESERVING_UNIFORM_FIT;        ///< the fit into texture space
  int tiles_u = 1;                              ///< `m` of the `m x n` tiling, at least 1
  int tiles_v = 1;                              ///< `n` of the `m x n` tiling, at least 1
  /// rounds of sign refinement (beyond the paper), at least 0; 0: off
  int sign_refinement_rounds = 0;
  double sign_refinement_tolerance = 1e-3;      ///< its stopping tolerance (relative), at least 0
  /// steps of Euclidean refinement (beyond the paper), at least 0; 0: off
  int euclidean_refinement_iterations = 0;
  double euclidean_refinement_tolerance = 1e-3; ///< its stopping tolerance (relative), at least 0
  /// whole-soup calls only: vertices at exactly the same position (a file split along old uv
  /// seams or normals) are one vertex for the solve and get the same uv, so the map has no
  /// seam there; `false` keeps them apart (the pieces they split are then mapped apart)
  bool weld_coincident_vertices = true;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
