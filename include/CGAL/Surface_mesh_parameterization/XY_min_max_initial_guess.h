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
/// \file XY_min_max_initial_guess.h
/// \ingroup PkgNormPreservingParameterization
/// The XY-MinMax initial guess (Section 4.1 of the paper).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_XY_MIN_MAX_INITIAL_GUESS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_XY_MIN_MAX_INITIAL_GUESS_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/disable_warnings.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Geometry.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterizationMethods
/// The XY-MinMax initial guess of Lai & Cheng (Section 4.1): each vertex is guessed at
/// `((x - Xmin) / (Xmax - Xmin), (y - Ymin) / (Ymax - Ymin))`.
///
/// Where the paper divides by zero: if all vertices share the same x (or y), z takes the place
/// of that axis, so that a component lying in a plane orthogonal to XY is guessed in its own
/// plane; if they still share one value (a component along a coordinate axis), that
/// coordinate of the guess is 0. Only a component of one position returns
/// `ERROR_WRONG_PARAMETER`.
///
/// \cgalModels `NormPreservingInitialGuess`
class XY_min_max_initial_guess
{
public:
  /// computes the guess of every vertex of `geometry`.
  Error_code operator()(const Norm_preserving_geometry& geometry,
                        std::vector<std::array<double, 2> >& uv,
                        std::string& message) const
  {
    const auto& points = geometry.points;
    if(points.empty())
    {
      message = "no vertex to guess";
      return ERROR_EMPTY_MESH;
    }
    const auto [low, high] = internal::Norm_preserving::coordinate_bounds(points);
    // A component flat in x or y is seen in its own plane: z stands in for that axis.
    std::array<int, 2> axis = {0, 1};
    for(int c = 0; c < 2; ++c)
      if(!(high[c] > low[c]) && high[2] > low[2])
      {
        axis[c] = 2;
        break;
      }
    if(!(high[axis[0]] > low[axis[0]]) && !(high[axis[1]] > low[axis[1]]))
    {
      message = "all vertices are at the same position: the XY-MinMax guess is undefined";
      return ERROR_WRONG_PARAMETER;
    }
    uv.resize(points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
      for(int c = 0; c < 2; ++c)
      {
        const int a = axis[c];
        uv[i][c] = high[a] > low[a] ? (points[i][a] - low[a]) / (high[a] - low[a]) : 0.; // a line: v constant
      }
    return OK;
  }
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif
