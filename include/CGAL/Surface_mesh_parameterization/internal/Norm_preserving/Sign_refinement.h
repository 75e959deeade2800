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
// Beyond the paper: sign refinement. The QP (Eq. 5) freezes the signs of u_i - u_j and
// v_i - v_j from the initial guess. At its optimum some differences are zero (active sign
// constraints); there the true objective Eq. 3, sum (l1_e - |du| - |dv|)^2, does not care which
// sign the difference has, but the next QP does: with the other orientation the edge may open
// the other way. Each round takes the signs from the last solution, orients the zero
// differences the way Eq. 3 decreases, re-solves, and keeps the result only if Eq. 3 decreased.
//
// Orientation of the zero differences: the vertex values are moved against the gradient of the
// differentiable part of Eq. 3 (the active terms left out: |d| has a kink at 0), by at most
// `threshold` (1e-8 mean edge lengths), and the signs are those of the moved values with the
// tie rule of edge_signs(). The moved point, which has the fixed values, satisfies the new
// signs, so they are feasible and acyclic, and its order is a topological order of them; and
// where the gradient descends, Eq. 3 at the moved point is below Eq. 3 at the last solution,
// so the next QP's optimum is too. Only differences within 2 threshold of 0 can change sign.
//
// Eq. 3 never increases from round to round: the last solution satisfies the new signs, so
// the new optimum is at most its Eq. 3, and a round whose solver result is not strictly below
// it (a solver stopped at its tolerance) is discarded and ends the refinement.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_SIGN_REFINEMENT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_SIGN_REFINEMENT_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sign_constrained_qp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

struct Sign_refinement_settings
{
  int max_rounds;   // 0: off
  double tolerance; // stop when Eq. 3 decreased by at most this (relative) in a round
};

// `uv` moved against the gradient of the differentiable part of Eq. 3 (zero at the fixed
// vertices), by at most `threshold` per coordinate; the signs are taken from these values.
inline UV_vector sign_refinement_order(const Norm_preserving_geometry& geometry, const std::vector<double>& lengths,
                                       const std::array<Fixed_vertex, 2>& fixed, const UV_vector& uv,
                                       double threshold)
{
  const std::size_t n = uv.size();
  UV_vector gradient(n, {0., 0.});
  for(std::size_t e = 0; e < lengths.size(); ++e)
  {
    const std::size_t i = geometry.edges[e][0], j = geometry.edges[e][1];
    const double du = uv[i][0] - uv[j][0], dv = uv[i][1] - uv[j][1];
    const double r = lengths[e] - std::abs(du) - std::abs(dv);
    const std::array<double, 2> d = {du, dv};
    for(int c = 0; c < 2; ++c)
    {
      if(std::abs(d[c]) <= threshold) continue; // the kink of an active term
      const double g = -2. * r * (d[c] > 0 ? 1. : -1.); // d/d(w_i) of r^2
      gradient[i][c] += g;
      gradient[j][c] -= g;
    }
  }
  for(const Fixed_vertex& f : fixed)
    gradient[f.index] = {0., 0.};
  UV_vector order = uv;
  for(int c = 0; c < 2; ++c)
  {
    double largest = 0;
    for(const auto& g : gradient)
      largest = (std::max)(largest, std::abs(g[c]));
    if(!(largest > 0) || !std::isfinite(largest))
      continue;
    const double step = threshold / largest;
    for(std::size_t i = 0; i < n; ++i)
      order[i][c] -= step * gradient[i][c];
  }
  return order;
}

// Refines `signs` and `uv` (a solution of Eq. 5 with `signs`) for at most
// `settings.max_rounds` rounds. `solve(new_signs, order, uv)` solves Eq. 5 with `new_signs`
// (taken from `order`) starting from `uv`, writes the solution into it and returns whether it
// succeeded. Returns Eq. 3 at the start and after each accepted round: a non-increasing list.
template <typename Solve>
std::vector<double> refine_signs(const Norm_preserving_geometry& geometry, const std::vector<double>& lengths,
                                 const std::array<Fixed_vertex, 2>& fixed, const Sign_refinement_settings& settings,
                                 Edge_signs& signs, UV_vector& uv, Solve&& solve)
{
  const double threshold = 1e-8;
  std::vector<double> objectives = {l1_norm_objective(geometry, lengths, uv)};
  for(int round = 0; round < settings.max_rounds; ++round)
  {
    const UV_vector order = sign_refinement_order(geometry, lengths, fixed, uv, threshold);
    const Edge_signs next_signs = edge_signs(geometry, order);
    if(next_signs == signs)
      break; // no zero difference to turn: the solution is optimal for these signs too
    UV_vector candidate = uv;
    if(!solve(next_signs, order, candidate))
      break;
    const double objective = l1_norm_objective(geometry, lengths, candidate);
    const double previous = objectives.back();
    if(!(objective < previous))
      break;
    uv.swap(candidate);
    signs = next_signs;
    objectives.push_back(objective);
    if(previous - objective <= settings.tolerance * previous)
      break;
  }
  return objectives;
}

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
