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
// A certified lower bound on the optimum of the sign-constrained QP (Eq. 5), by Lagrangian
// duality (doc/decisions.md, "The QP and its solver"). With the edge values z = A x + c (A: su
// (u_i - u_j) and sv (v_i - v_j) of the free vertices, c: the fixed vertices' part) the QP is
//   min phi(z) = sum_e (l_e - a_e - b_e)^2  s.t.  z = A x + c,  z >= 0,
// and for any multiplier y with A'y = 0 the dual function
//   g(y) = y'c + sum_e min_{a, b >= 0} [(l_e - a - b)^2 - ya a - yb b]
// is at most the optimum. The inner minimum is in closed form: with t = max(ya, yb), the best
// a + b is s = max(0, l + t/2) and the minimum (l - s)^2 - t s. A multiplier estimate (the
// ADMM's) is made to satisfy A'y = 0 by one solve with the free-vertex Laplacian A'A, already
// factored (S^2 = I): y <- y - A (A'A)^-1 A'y. What rounding leaves of A'y is charged at the
// point `uv` (the term r'x of the Lagrangian), so the bound holds up to rounding.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_DUAL_BOUND_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_DUAL_BOUND_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Free_vertex_laplacian.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sign_constrained_qp.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Two_column_cholesky.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

// min over a, b >= 0 of (l - a - b)^2 - ya a - yb b.
inline double edge_dual_term(double l, double ya, double yb)
{
  const double t = (std::max)(ya, yb);
  const double s = (std::max)(0., l + t / 2.);
  return (l - s) * (l - s) - t * s;
}

// The dual function at the multiplier estimate `y` (per edge, for a and b) made feasible;
// `uv` holds the fixed vertices' values, and a point for the rounding term. `row` gives
// each free vertex's row in the order of the factored `laplacian` (-1 at the fixed ones), and
// `incidence` is numbered by it.
inline double sign_constrained_dual_bound(const Norm_preserving_geometry& geometry, const std::vector<double>& lengths,
                                          const Edge_signs& signs, const std::vector<int>& row,
                                          const Free_vertex_edges& incidence, const Two_column_cholesky& laplacian,
                                          const UV_vector& uv, std::vector<std::array<double, 2> > y)
{
  const std::size_t m = geometry.edges.size();
  const std::size_t free_count = incidence.first.size() - 1;
  std::vector<std::array<double, 2> > values(m);
  std::vector<double> t(laplacian.solve_size());
  auto free_value = [&](const std::vector<double>& x, std::size_t i, int c) {
    return row[i] >= 0 ? x[2 * std::size_t(row[i]) + std::size_t(c)] : 0.;
  };
  auto apply_transpose = [&](std::vector<double>& result) { // result = A'y, per free vertex
    for(std::size_t e = 0; e < m; ++e)
      for(int c = 0; c < 2; ++c)
        values[e][c] = signs[e][c] * y[e][c];
    gather_edge_values(incidence, values, result);
  };
  apply_transpose(t);
  laplacian.solve_in_order(t);
  for(std::size_t e = 0; e < m; ++e)
    for(int c = 0; c < 2; ++c)
      y[e][c] -= signs[e][c] * (free_value(t, geometry.edges[e][0], c) - free_value(t, geometry.edges[e][1], c));

  std::vector<double> residual(2 * free_count); // A'y left by rounding
  apply_transpose(residual);
  double bound = 0;
  for(std::size_t i = 0; i < uv.size(); ++i)
    if(row[i] >= 0)
      for(int c = 0; c < 2; ++c)
        bound += residual[2 * std::size_t(row[i]) + std::size_t(c)] * uv[i][c];
  for(std::size_t e = 0; e < m; ++e)
  {
    const std::size_t i = geometry.edges[e][0], j = geometry.edges[e][1];
    for(int c = 0; c < 2; ++c)
    {
      const double fixed_part = (row[i] < 0 ? uv[i][c] : 0.) - (row[j] < 0 ? uv[j][c] : 0.);
      bound += y[e][c] * signs[e][c] * fixed_part;
    }
    bound += edge_dual_term(lengths[e], y[e][0], y[e][1]);
  }
  return bound;
}

// An objective below `gap_floor` times the objective of the zero map (sum of l_e^2) counts as
// zero: gaps near a zero optimum are measured against that, not against the optimum itself.
constexpr double gap_floor = 1e-12;

// An upper bound on (f - f*) / max(f*, gap_floor * `scale`) from the objective f of a feasible
// point and a lower bound on the optimum f* (and 0, f being a sum of squares): 0 when they meet.
inline double relative_gap(double objective, double lower_bound, double scale)
{
  lower_bound = (std::max)(lower_bound, 0.);
  if(!(objective > lower_bound))
    return 0.;
  return (objective - lower_bound) / (std::max)(lower_bound, gap_floor * scale);
}

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
