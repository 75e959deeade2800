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
/// \file Norm_preserving_solver.h
/// \ingroup PkgNormPreservingParameterization
/// The problem and the report of a model of `NormPreservingSolver`.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_SOLVER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_SOLVER_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/disable_warnings.h>

#include <CGAL/Surface_mesh_parameterization/Norm_preserving_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_report.h>

#include <array>
#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterizationTypes
/// A vertex held at `target` by the sign-constrained QP.
struct Norm_preserving_fixed_vertex
{
  std::size_t index;             ///< the vertex, an index into `Norm_preserving_geometry::points`
  std::array<double, 2> target;  ///< its uv
};

/// \ingroup PkgNormPreservingParameterizationTypes
/// The sign-constrained QP of one component (the paper's Eq. 5), as handed to a model of
/// `NormPreservingSolver`: minimize `sum_e (lengths[e] - su_e (u_i - u_j) - sv_e (v_i - v_j))^2`
/// over the uvs, subject to `su_e (u_i - u_j) >= 0`, `sv_e (v_i - v_j) >= 0` for every edge
/// `e = {i, j}` with signs `{su_e, sv_e} = signs[e]`, and the two fixed vertices at their targets.
/// The geometry is normalized (mean L1 edge length 1).
struct Norm_preserving_problem
{
  const Norm_preserving_geometry& geometry;          ///< vertices and edges
  const std::vector<double>& lengths;                ///< the L1 length of each edge
  const std::vector<std::array<double, 2> >& signs;  ///< `+1` or `-1` per edge and coordinate
  std::array<Norm_preserving_fixed_vertex, 2> fixed; ///< the fixed pair
  /// the vertex values the signs were taken from (with ties oriented as if the vertex of
  /// higher index were the larger), if not the start point handed to `solve()`
  const std::vector<std::array<double, 2> >* order = nullptr;
  /// if not null, a solver that can tells it an estimate of the share of the solve done, in
  /// `[0, 1]`, every few iterations; when it returns `false` the solver stops and fails
  /// (`solve()` returns `false`, with `Norm_preserving_solve_report::interrupted` set)
  const std::function<bool(double)>* progress = nullptr;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif
