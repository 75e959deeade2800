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
// Lays the separately parameterized components of a mesh side by side, at their common
// scale, with disjoint bounding boxes (shelf packing, tallest first).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_COMPONENT_LAYOUT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_COMPONENT_LAYOUT_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

// `component[i]` is the component of vertex i, or `count` or more for a vertex in none (left
// as is).
// Components are translated only: the scale, hence the texel density, stays common.
inline void lay_out_components(std::vector<std::array<double, 2> >& uv,
                               const std::vector<std::size_t>& component, std::size_t count)
{
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<std::array<double, 2> > low(count, {inf, inf}), high(count, {-inf, -inf});
  for(std::size_t i = 0; i < uv.size(); ++i)
  {
    if(component[i] >= count) continue;
    for(int c = 0; c < 2; ++c)
    {
      low[component[i]][c] = (std::min)(low[component[i]][c], uv[i][c]);
      high[component[i]][c] = (std::max)(high[component[i]][c], uv[i][c]);
    }
  }
  std::vector<double> width(count), height(count);
  double largest = 0;
  for(std::size_t c = 0; c < count; ++c)
  {
    width[c] = high[c][0] - low[c][0];
    height[c] = high[c][1] - low[c][1];
    largest = (std::max)({largest, width[c], height[c]});
  }
  const double gap = largest > 0 ? 0.02 * largest : 1.;
  double area = 0, widest = 0;
  for(std::size_t c = 0; c < count; ++c)
  {
    area += (width[c] + gap) * (height[c] + gap);
    widest = (std::max)(widest, width[c]);
  }
  const double row_limit = (std::max)(widest, std::sqrt(area));

  std::vector<std::size_t> order(count);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return height[a] > height[b]; });
  std::vector<std::array<double, 2> > shift(count);
  double x = 0, y = 0, row_height = 0;
  for(std::size_t c : order)
  {
    if(x > 0 && x + width[c] > row_limit)
    {
      y += row_height + gap;
      x = 0;
      row_height = 0;
    }
    shift[c] = {x - low[c][0], y - low[c][1]};
    x += width[c] + gap;
    row_height = (std::max)(row_height, height[c]);
  }
  for(std::size_t i = 0; i < uv.size(); ++i)
    if(component[i] < count)
      for(int c = 0; c < 2; ++c)
        uv[i][c] += shift[component[i]][c];
}

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
