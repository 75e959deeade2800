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
// Beyond the paper: the Euclidean (q = 2) norm-preserving objective, the stress
//   sigma(T) = sum over edges (||T_i - T_j||_2 - ||P_i - P_j||_2)^2,
// minimized from the QP solution by stress majorization (SMACOF, de Leeuw 1977). With unit
// weights the majorizer of sigma at Y is, up to a constant, tr(T'LT) - 2 tr(T'B(Y)Y), L the
// graph Laplacian and B(Y) the Laplacian weighted by d_e / ||Y_i - Y_j|| (0 on a zero-length
// edge); its minimum over the free vertices, the fixed pair held (Dirichlet), solves
// L_ff T_f = (B(Y)Y)_f - L_fF T_F: one solve with the Laplacian factored once, for u and v at
// once, per step, and sigma never increases.
//
// Start: the QP solution is in L1 units (|du| + |dv| ~ L1 length, which overestimates the
// Euclidean length); it is scaled about the first fixed vertex (at the origin) by the factor
// that best fits the Euclidean lengths in least squares, and the second fixed vertex is put at
// its Euclidean distance from the first, in the direction the solution gives it.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_STRESS_MAJORIZATION_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_STRESS_MAJORIZATION_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Free_vertex_laplacian.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Two_column_cholesky.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

struct Stress_majorization_settings
{
  int max_iterations; // 0: off
  double tolerance;   // stop when the stress decreased by at most this (relative) in a step
};

struct Stress_majorization_result
{
  bool solved = false;        // false: no factorization, or a non-finite value
  int iterations = 0;         // steps taken (each decreased the stress)
  std::vector<double> stress; // at the start, then after each step: non-increasing
};

inline std::vector<double> edge_euclidean_lengths(const Norm_preserving_geometry& geometry)
{
  return edge_lengths(geometry, l2_distance);
}

// Not std::hypot, which is several times slower: the uvs are in units of the mean edge
// length, far from overflow.
inline double uv_distance(const std::array<double, 2>& p, const std::array<double, 2>& q)
{
  return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]));
}

// Scales `uv` (the QP solution, `fixed[0]` at the origin) to fit the Euclidean `lengths` and
// sets the targets of the fixed pair (see above); false if `uv` has no extent.
inline bool euclidean_start(const Norm_preserving_geometry& geometry, const std::vector<double>& lengths,
                            std::array<Fixed_vertex, 2>& fixed, UV_vector& uv)
{
  double fit = 0, norm = 0;
  for(std::size_t e = 0; e < lengths.size(); ++e)
  {
    const double t = uv_distance(uv[geometry.edges[e][0]], uv[geometry.edges[e][1]]);
    fit += t * lengths[e];
    norm += t * t;
  }
  if(!(norm > 0) || !(fit > 0) || !std::isfinite(fit / norm))
    return false;
  const double scale = fit / norm;
  const std::array<double, 2> a = uv[fixed[0].index];
  for(auto& p : uv)
    for(int c = 0; c < 2; ++c)
      p[c] = a[c] + scale * (p[c] - a[c]);
  const std::array<double, 2> b = uv[fixed[1].index];
  const double distance = uv_distance(a, b);
  const double target = l2_distance(geometry.points[fixed[0].index], geometry.points[fixed[1].index]);
  if(!(distance > 0) || !(target > 0))
    return false;
  fixed[0].target = a;
  fixed[1].target = {a[0] + target / distance * (b[0] - a[0]), a[1] + target / distance * (b[1] - a[1])};
  uv[fixed[1].index] = fixed[1].target;
  return true;
}

// The stress at `uv` (the Euclidean objective, Eq. 2 with q = 2) and, in `rhs`, the right-hand
// side of the SMACOF step from `uv`: (B(uv) uv)_f - L_fF uv_F over the free vertices, u and v
// interleaved. One pass over the edges.
inline double stress_and_step_rhs(const Norm_preserving_geometry& geometry, const std::vector<double>& lengths,
                                  const std::vector<int>& free_index, const UV_vector& uv, std::vector<double>& rhs)
{
  std::fill(rhs.begin(), rhs.end(), 0.);
  double stress = 0;
  for(std::size_t e = 0; e < lengths.size(); ++e)
  {
    const std::size_t i = geometry.edges[e][0], j = geometry.edges[e][1];
    const double distance = uv_distance(uv[i], uv[j]);
    stress += (distance - lengths[e]) * (distance - lengths[e]);
    const double weight = distance > 0 ? lengths[e] / distance : 0.; // B(Y)'s weight
    for(int c = 0; c < 2; ++c)
      add_edge_difference(rhs, free_index, i, j, c, weight * (uv[i][c] - uv[j][c]), uv);
  }
  return stress;
}

// SMACOF from `uv`, whose fixed vertices are at their targets. `factored` is the free-vertex
// Laplacian for this fixed pair, already factored, or null (then it is factored here).
// A step is kept only if it lowers the stress (in exact arithmetic every step does; at the
// fixed point rounding may not), so the recorded stress never increases.
inline Stress_majorization_result majorize_stress(const Norm_preserving_geometry& geometry,
                                                  const std::vector<double>& lengths,
                                                  const std::array<Fixed_vertex, 2>& fixed,
                                                  const Stress_majorization_settings& settings, UV_vector& uv,
                                                  const Two_column_cholesky* factored)
{
  Stress_majorization_result result;
  const std::size_t n = uv.size();
  const std::vector<int> free_index = free_vertex_indices(n, fixed);
  Two_column_cholesky own;
  if(factored == nullptr)
  {
    if(!own.compute(free_vertex_laplacian(geometry, free_index)))
      return result;
    factored = &own;
  }
  std::vector<double> rhs(2 * (n - 2)), next_rhs(rhs.size());
  result.stress.push_back(stress_and_step_rhs(geometry, lengths, free_index, uv, rhs));
  if(!std::isfinite(result.stress.back()))
    return result;
  UV_vector next = uv;
  for(int k = 0; k < settings.max_iterations && result.stress.back() > 0; ++k)
  {
    factored->solve(rhs);
    for(std::size_t i = 0; i < n; ++i)
      if(free_index[i] >= 0)
        next[i] = {rhs[2 * std::size_t(free_index[i])], rhs[2 * std::size_t(free_index[i]) + 1]};
    const double stress = stress_and_step_rhs(geometry, lengths, free_index, next, next_rhs);
    if(!std::isfinite(stress))
      return result;
    const double previous = result.stress.back();
    if(!(stress < previous))
      break; // the fixed point, up to rounding
    uv.swap(next); // `next` keeps the fixed targets; its free values are overwritten next step
    rhs.swap(next_rhs);
    ++result.iterations;
    result.stress.push_back(stress);
    if(previous - stress <= settings.tolerance * previous)
      break;
  }
  result.solved = true;
  return result;
}

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
