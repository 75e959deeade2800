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
/// \file Graph_based_initial_guess.h
/// \ingroup PkgNormPreservingParameterization
/// The Graph-based initial guess (Section 4.3 of the paper).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_GRAPH_BASED_INITIAL_GUESS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_GRAPH_BASED_INITIAL_GUESS_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/disable_warnings.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/XY_min_max_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Dfs_chains.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Uniform_cubic_bspline.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterizationMethods
/// The graph-based initial guess of Lai & Cheng (Section 4.3), which takes the edge lengths,
/// hence z, into account and suits surfaces with many handles.
///
/// A depth-first search of the vertex-edge graph, from the vertex of smallest x (lowest index
/// on ties) and along the longest edge first (lowest neighbour index on ties), is cut into
/// chains: the first root-to-leaf branch, then every later branch from the vertex it leaves,
/// down to a leaf, and back along the leaf's longest edge to a vertex of an earlier chain
/// other than its parent. Every vertex starts at its XY-MinMax value
/// (`XY_min_max_initial_guess`); chain by chain, the interpolating uniform cubic B-spline
/// `f(t)` through the values of the chain at `t_k = k / (N - 1)` (not-a-knot ends; the
/// piecewise linear interpolant when `N < 4`) resets each interior vertex to `f(L_i / L_N)`,
/// `L_i` the 3D length of the chain up to it. The ends of a chain keep their values, so each
/// chain bends between two already placed vertices.
///
/// Decisions the paper leaves open:
/// - a leaf whose every other edge goes back into its own chain has no earlier vertex to
///   return to: its chain ends at the leaf, which keeps its XY-MinMax value;
/// - a chain of zero 3D length keeps its values.
///
/// Deterministic, `O(n log n)`. Fails exactly when the XY-MinMax guess does (all vertices with
/// the same x or the same y), with its error code and message.
///
/// \cgalModels `NormPreservingInitialGuess`
class Graph_based_initial_guess
{
public:
  /// computes the guess of every vertex of `geometry`.
  Error_code operator()(const Norm_preserving_geometry& geometry,
                        std::vector<std::array<double, 2> >& uv,
                        std::string& message) const
  {
    const Error_code status = XY_min_max_initial_guess()(geometry, uv, message);
    if(status != OK)
      return status;
    for(const auto& chain : internal::Norm_preserving::dfs_chains(geometry).chains)
      reset_interior_by_length(geometry.points, chain, uv);
    return OK;
  }

private:
  typedef std::array<double, 2> Point_2;

  static void reset_interior_by_length(const std::vector<std::array<double, 3> >& points,
                                       const std::vector<std::size_t>& chain,
                                       std::vector<Point_2>& uv)
  {
    namespace NP = internal::Norm_preserving;
    const std::size_t n = chain.size();
    if(n < 3)
      return;
    std::vector<double> length(n, 0.);
    for(std::size_t k = 1; k < n; ++k)
      length[k] = length[k - 1] + std::sqrt(NP::squared_euclidean_distance(points[chain[k - 1]], points[chain[k]]));
    if(!(length.back() > 0))
      return;
    std::vector<Point_2> data(n);
    for(std::size_t k = 0; k < n; ++k)
      data[k] = uv[chain[k]];

    if(n == 3)
    {
      uv[chain[1]] = piecewise_linear(data, length[1] / length[2]);
      return;
    }
    const NP::Uniform_cubic_bspline f(data);
    for(std::size_t k = 1; k + 1 < n; ++k)
      uv[chain[k]] = f(length[k] / length.back());
  }

  // The interpolant of degree 1 through `data` at uniform parameters: what the B-spline
  // becomes on a chain too short for a cubic.
  static Point_2 piecewise_linear(const std::vector<Point_2>& data, double t)
  {
    const std::size_t segments = data.size() - 1;
    const double s = t * double(segments);
    const std::size_t k = s < double(segments) ? std::size_t(s) : segments - 1;
    const double u = s - double(k);
    return {data[k][0] + u * (data[k + 1][0] - data[k][0]), data[k][1] + u * (data[k + 1][1] - data[k][1])};
  }
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif
