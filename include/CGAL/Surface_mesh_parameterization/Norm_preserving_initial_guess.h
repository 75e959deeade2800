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
/// \file Norm_preserving_initial_guess.h
/// \ingroup PkgNormPreservingParameterization
/// The component handed to an initial guess.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_INITIAL_GUESS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_INITIAL_GUESS_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/disable_warnings.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterizationTypes
/// The connected component handed to an initial guess: vertex positions, indexed
/// `0..n-1` in the mesh's vertex order, and every edge once as `{i, j}` with `i < j`,
/// sorted.
///
/// An initial guess is a model of the concept `NormPreservingInitialGuess`: a copyable
/// function object with
/// \code
/// Error_code operator()(const Norm_preserving_geometry& geometry,
///                       std::vector<std::array<double, 2> >& uv,
///                       std::string& message) const;
/// \endcode
/// that resizes `uv` to the number of vertices and fills it, or returns an error code and
/// a readable `message`. Only the order of the guessed values matters to the method (it
/// fixes the signs of Eq. 5); the guess is moved into place by a similarity transform.
struct Norm_preserving_geometry
{
  std::vector<std::array<double, 3> > points;      ///< vertex positions
  std::vector<std::array<std::size_t, 2> > edges;  ///< unique edges `{i, j}`, `i < j`, sorted
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif
