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
// A cheap map onto the feasible set of the sign-constrained QP (Eq. 5), per coordinate w (u
// or v): the constraints s_e (w_i - w_j) >= 0 orient every edge from its lower to its higher
// end. The signs come from the transformed guess, so the orientation is acyclic and sorting by
// (guess value, vertex index) is a topological order (the tie rule of edge_signs()). The two
// fixed vertices bound what lies above and below them. A forward sweep that lifts each free
// vertex to the highest of its lower neighbours, after clamping it between the fixed values
// it must lie between, gives a feasible point that moves only the violating vertices.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_SIGN_FEASIBLE_PROJECTION_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_SIGN_FEASIBLE_PROJECTION_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sign_constrained_qp.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

class Sign_feasible_projection
{
public:
  Sign_feasible_projection(const Norm_preserving_geometry& geometry, const Edge_signs& signs,
                           const std::array<Fixed_vertex, 2>& fixed, const UV_vector& guess)
  {
    const std::size_t n = geometry.points.size();
    for(int c = 0; c < 2; ++c)
    {
      Coordinate& k = m_coordinates[c];
      k.order.resize(n);
      std::iota(k.order.begin(), k.order.end(), std::size_t(0));
      std::sort(k.order.begin(), k.order.end(), [&](std::size_t i, std::size_t j) {
        return guess[i][c] < guess[j][c] || (guess[i][c] == guess[j][c] && i < j);
      });
      std::vector<int> position(n);
      for(std::size_t p = 0; p < n; ++p)
        position[k.order[p]] = int(p);
      // Lower neighbours of each position, in compressed rows, in the order of the edges.
      k.first.assign(n + 1, 0);
      for(std::size_t e = 0; e < signs.size(); ++e)
        ++k.first[std::size_t(position[higher_end(geometry, signs, e, c)]) + 1];
      std::partial_sum(k.first.begin(), k.first.end(), k.first.begin());
      k.lower.resize(signs.size());
      std::vector<int> next(k.first.begin(), k.first.end() - 1);
      for(std::size_t e = 0; e < signs.size(); ++e)
      {
        const std::size_t high = higher_end(geometry, signs, e, c);
        k.lower[std::size_t(next[std::size_t(position[high])]++)] = position[geometry.edges[e][0] + geometry.edges[e][1] - high];
      }
      // Fixed values below (floor) and above (ceiling) each position in the orientation.
      k.floor.assign(n, -std::numeric_limits<double>::infinity());
      k.ceiling.assign(n, std::numeric_limits<double>::infinity());
      for(const Fixed_vertex& f : fixed)
        k.floor[std::size_t(position[f.index])] = k.ceiling[std::size_t(position[f.index])] = f.target[c];
      for(std::size_t p = 0; p < n; ++p)
        for(int l = k.first[p]; l < k.first[p + 1]; ++l)
          k.floor[p] = (std::max)(k.floor[p], k.floor[std::size_t(k.lower[std::size_t(l)])]);
      for(std::size_t p = n; p-- > 0;)
        for(int l = k.first[p]; l < k.first[p + 1]; ++l)
        {
          double& below = k.ceiling[std::size_t(k.lower[std::size_t(l)])];
          below = (std::min)(below, k.ceiling[p]);
        }
    }
  }

  // Replaces `uv` by a point that satisfies every sign constraint and the fixed vertices (a
  // fixed vertex lies between its floor and ceiling, which are both its value, and every lower
  // neighbour of a vertex lies under that vertex's ceiling, so the sweep never lifts it). The
  // sweep reads the values in topological order, where a vertex's lower neighbours are near it.
  void apply(UV_vector& uv) const
  {
    std::vector<double> values(uv.size()); // of one coordinate, by position
    for(int c = 0; c < 2; ++c)
    {
      const Coordinate& k = m_coordinates[c];
      for(std::size_t p = 0; p < k.order.size(); ++p)
      {
        double w = (std::min)((std::max)(uv[k.order[p]][c], k.floor[p]), k.ceiling[p]);
        for(int l = k.first[p]; l < k.first[p + 1]; ++l)
          w = (std::max)(w, values[std::size_t(k.lower[std::size_t(l)])]);
        values[p] = uv[k.order[p]][c] = w;
      }
    }
  }

private:
  struct Coordinate
  {
    std::vector<std::size_t> order;          // topological order of the orientation: the vertex at each position
    std::vector<int> first, lower;           // lower neighbours of position p: lower[first[p]..first[p+1]), as positions
    std::vector<double> floor, ceiling;      // fixed values the vertex at each position must lie between
  };

  static std::size_t higher_end(const Norm_preserving_geometry& geometry, const Edge_signs& signs,
                                std::size_t e, int c)
  {
    return signs[e][c] > 0 ? geometry.edges[e][0] : geometry.edges[e][1];
  }

  std::array<Coordinate, 2> m_coordinates;
};

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
