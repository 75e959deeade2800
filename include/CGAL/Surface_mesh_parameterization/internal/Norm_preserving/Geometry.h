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
// The geometry every step shares: distances, the vertex of smallest x, coordinate bounds.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_GEOMETRY_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_GEOMETRY_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

using Point_3_array = std::array<double, 3>;

inline double l1_distance(const Point_3_array& p, const Point_3_array& q)
{
  return std::abs(p[0] - q[0]) + std::abs(p[1] - q[1]) + std::abs(p[2] - q[2]);
}

inline double l2_distance(const Point_3_array& p, const Point_3_array& q)
{
  return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
}

// The vertex of smallest x, lowest index on ties (the deterministic root of the fixed pair,
// the depth-first search and the cut); 0 for no vertex.
inline std::size_t lowest_x_vertex(const std::vector<Point_3_array>& points)
{
  return std::size_t(std::min_element(points.begin(), points.end(),
                                      [](const Point_3_array& p, const Point_3_array& q) { return p[0] < q[0]; }) -
                     points.begin());
}

// The smallest and largest value of each coordinate; `points` is not empty.
inline std::pair<Point_3_array, Point_3_array> coordinate_bounds(const std::vector<Point_3_array>& points)
{
  Point_3_array low = points[0], high = points[0];
  for(const auto& p : points)
    for(int c = 0; c < 3; ++c)
    {
      low[c] = (std::min)(low[c], p[c]);
      high[c] = (std::max)(high[c], p[c]);
    }
  return {low, high};
}

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
