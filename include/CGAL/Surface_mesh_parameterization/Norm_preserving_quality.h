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
/// \file Norm_preserving_quality.h
/// \ingroup PkgNormPreservingParameterization
/// How close to the optimum the default solver goes.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_QUALITY_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_QUALITY_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/disable_warnings.h>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterizationEnums
/// The presets of `Norm_preserving_ADMM_solver`: how close to the optimum of the QP (Eq. 5) a
/// solve goes, traded against its time (`doc/manual.md`, "Accuracy, speed and solvers").
enum Norm_preserving_quality
{
  NORM_PRESERVING_DRAFT_QUALITY,   ///< a quick map for previews: at most 2% above the optimum
  NORM_PRESERVING_DEFAULT_QUALITY, ///< at most 1e-4 above the optimum (the default)
  NORM_PRESERVING_EXACT_QUALITY    ///< the optimum, certified to `1e-9` (`Norm_preserving_ADMM_solver::certified()`)
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif
