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
/// \file Norm_preserving_progress.h
/// \ingroup PkgNormPreservingParameterization
/// What a whole-mesh call tells its progress callback.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_PROGRESS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_PROGRESS_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/disable_warnings.h>

#include <cstddef>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterizationTypes
/// Where a whole-mesh call is, handed to the callback of the named parameter `progress`: a
/// callable `bool(const Norm_preserving_progress&)` that returns `false` to stop the call,
/// which then writes nothing and returns `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM` with the report's
/// `interrupted` set. The callback is called from the threads that do the work, one call at a
/// time; it is called at the start of every component and then every few iterations of the
/// default solver (others report only at the components).
struct Norm_preserving_progress
{
  std::size_t components = 0;       ///< connected components of the mesh
  std::size_t components_done = 0;  ///< of those, the ones finished
  /// an estimate of the share of the call's work done, in `[0, 1]`, never decreasing: the
  /// finished components by their vertices, and the convergence of the solves under way
  double fraction = 0;
  double seconds = 0;               ///< since the start of the call
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif
