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
/// \file Texture_fit.h
/// \ingroup PkgNormPreservingParameterization
/// How a solution is fitted into texture space.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_TEXTURE_FIT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_TEXTURE_FIT_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/disable_warnings.h>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterizationEnums
/// How `Norm_preserving_parameterizer_3` fits its solution into texture space (step 8 of
/// Lai & Cheng) before the `m x n` tiling scales `u` by `m` and `v` by `n`.
enum Texture_fit
{
  NORM_PRESERVING_UNIFORM_FIT, ///< one scale and a translation into `[0,1]^2`, aspect ratio kept (default)
  NORM_PRESERVING_CLAMP_FIT,   ///< each coordinate clamped to `[0,1]`, as printed in the paper
  NORM_PRESERVING_NO_FIT       ///< raw solution in model units: texel density equals model scale
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif
