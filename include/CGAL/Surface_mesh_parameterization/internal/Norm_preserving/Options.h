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
// The options of one run of the method, as the parameterizer's setters or the whole-mesh
// calls' named parameters leave them, and the check of their ranges.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_OPTIONS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_OPTIONS_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Texture_fit.h>

#include <string>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

struct Options
{
  Texture_fit texture_fit = NORM_PRESERVING_UNIFORM_FIT;
  int tiles_u = 1, tiles_v = 1;
  int sign_refinement_rounds = 0;
  double sign_refinement_tolerance = 1e-3;
  int euclidean_refinement_iterations = 0;
  double euclidean_refinement_tolerance = 1e-3;
  bool weld_coincident_vertices = true; // the whole-mesh calls only
};

// Why `options` cannot be used, or nothing.
inline std::string invalid_option(const Options& options)
{
  if(options.sign_refinement_rounds < 0 || !(options.sign_refinement_tolerance >= 0)
     || options.euclidean_refinement_iterations < 0 || !(options.euclidean_refinement_tolerance >= 0))
    return "a refinement has a negative iteration limit or tolerance";
  if(options.tiles_u < 1 || options.tiles_v < 1)
    return "the tiling must be at least 1 x 1";
  return std::string();
}

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
