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
// Step 2 of the paper: the fixed adjacent pair (doc/decisions.md, 2) and its target positions.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_FIXED_PAIR_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_FIXED_PAIR_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Norm_preserving_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Geometry.h>

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

inline bool is_edge(const Norm_preserving_geometry& geometry, std::size_t a, std::size_t b)
{
  const std::array<std::size_t, 2> e = {(std::min)(a, b), (std::max)(a, b)};
  return a != b && std::binary_search(geometry.edges.begin(), geometry.edges.end(), e);
}

// The neighbour of `a` across the longest L1 edge, lowest index on ties, among those that
// `guess` (if given) does not put on the point of `a`; `a` itself if there is none.
inline std::size_t automatic_partner(const Norm_preserving_geometry& geometry, std::size_t a,
                                     const std::vector<std::array<double, 2> >* guess = nullptr)
{
  const auto& points = geometry.points;
  std::size_t b = a;
  double longest = -1;
  for(const auto& e : geometry.edges)
  {
    if(e[0] != a && e[1] != a) continue;
    const std::size_t other = e[0] == a ? e[1] : e[0];
    if(guess != nullptr && (*guess)[other] == (*guess)[a]) continue;
    const double length = l1_distance(points[a], points[other]);
    if(length > longest || (length == longest && other < b))
    {
      longest = length;
      b = other;
    }
  }
  return b;
}

// `a`: the vertex of smallest x, lowest index on ties; `b`: its automatic partner before any
// guess. Where every edge at `a` has zero length (coincident vertices kept apart), the longest
// edge instead (lowest indices on ties). The component has at least one edge.
inline std::pair<std::size_t, std::size_t> automatic_fixed_pair(const Norm_preserving_geometry& geometry)
{
  const std::size_t a = lowest_x_vertex(geometry.points);
  std::pair<std::size_t, std::size_t> pair(a, automatic_partner(geometry, a));
  double longest = l1_distance(geometry.points[pair.first], geometry.points[pair.second]);
  if(longest > 0)
    return pair;
  for(const auto& e : geometry.edges)
  {
    const double length = l1_distance(geometry.points[e[0]], geometry.points[e[1]]);
    if(length > longest)
    {
      longest = length;
      pair = {e[0], e[1]};
    }
  }
  return pair;
}

// Targets (doc/decisions.md, 2): `a` at the origin, `b` along the guessed direction from `a` to
// `b`, at L1 distance (|du| + |dv|) equal to the 3D L1 length of the edge.
// Returns false if the guess puts `a` and `b` at the same point.
inline bool fixed_pair_targets(const std::array<double, 2>& guess_a,
                               const std::array<double, 2>& guess_b,
                               double l1_length,
                               std::array<double, 2>& target_a,
                               std::array<double, 2>& target_b)
{
  const double du = guess_b[0] - guess_a[0], dv = guess_b[1] - guess_a[1];
  const double l1_guess = std::abs(du) + std::abs(dv);
  if(!(l1_guess > 0))
    return false;
  const double t = l1_length / l1_guess;
  target_a = {0., 0.};
  target_b = {t * du, t * dv};
  return true;
}

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
