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
// Steps 8-9 of the paper: fitting the solution into texture space (doc/decisions.md, 8) and
// m x n tiling.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_TEXTURE_SPACE_FIT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_TEXTURE_SPACE_FIT_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Texture_fit.h>

#include <algorithm>
#include <array>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

inline void fit_to_texture_space(std::vector<std::array<double, 2> >& uv, Texture_fit fit,
                                 int tiles_u, int tiles_v)
{
  if(uv.empty()) return;
  if(fit == NORM_PRESERVING_UNIFORM_FIT)
  {
    std::array<double, 2> low = uv[0], high = uv[0];
    for(const auto& p : uv)
      for(int c = 0; c < 2; ++c)
      {
        low[c] = (std::min)(low[c], p[c]);
        high[c] = (std::max)(high[c], p[c]);
      }
    // Divided, not multiplied by 1 / extent: the farthest point lands on 1 exactly.
    const double extent = (std::max)(high[0] - low[0], high[1] - low[1]);
    const double divisor = extent > 0 ? extent : 1.;
    for(auto& p : uv)
      for(int c = 0; c < 2; ++c)
        p[c] = (p[c] - low[c]) / divisor;
  }
  else if(fit == NORM_PRESERVING_CLAMP_FIT)
  {
    for(auto& p : uv)
      for(int c = 0; c < 2; ++c)
        p[c] = (std::min)(1., (std::max)(0., p[c]));
  }
  for(auto& p : uv)
  {
    p[0] *= tiles_u;
    p[1] *= tiles_v;
  }
}

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
