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
// Step 6 of the paper: signs of u_i - u_j and v_i - v_j from the transformed guess, and the
// QP of Eq. 5 written into a model of QuadraticProgramTraits.
//
// Variables: u_i at 2i, v_i at 2i+1. For edge e = (i, j) with signs (su, sv) the residual is
// r_e = l1_e - su (u_i - u_j) - sv (v_i - v_j) (Eq. 4) and the sign constraints are rows
// 2e: su (u_i - u_j) >= 0 and 2e+1: sv (v_i - v_j) >= 0. Rows 2E..2E+3 fix u_a, v_a, u_b, v_b.
// The objective sum r_e^2 is passed as 1/2 x'Px + q'x + r with P = 2 C'C, q = -2 C'd, r = d'd.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_SIGN_CONSTRAINED_QP_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_SIGN_CONSTRAINED_QP_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Norm_preserving_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Fixed_pair.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Normal_equations.h>

#include <Eigen/Sparse>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

using UV_vector = std::vector<std::array<double, 2> >;

// Sign (+1 or -1) per edge and coordinate: the sign of (w_i - w_j) in the guess, where
// w is u or v. A tie is oriented as if the vertex of higher index were the larger (-1, as
// i < j), a deterministic rule (doc/decisions.md, 4); the tied guess satisfies it with equality.
using Edge_signs = std::vector<std::array<double, 2> >;

inline Edge_signs edge_signs(const Norm_preserving_geometry& geometry, const UV_vector& guess)
{
  Edge_signs signs(geometry.edges.size());
  for(std::size_t e = 0; e < geometry.edges.size(); ++e)
    for(int c = 0; c < 2; ++c)
      signs[e][c] = guess[geometry.edges[e][0]][c] > guess[geometry.edges[e][1]][c] ? 1. : -1.;
  return signs;
}

// The length of every edge, in edge order, under `distance` (l1_distance, l2_distance).
template <typename Distance>
std::vector<double> edge_lengths(const Norm_preserving_geometry& geometry, Distance distance)
{
  std::vector<double> lengths;
  lengths.reserve(geometry.edges.size());
  for(const auto& e : geometry.edges)
    lengths.push_back(distance(geometry.points[e[0]], geometry.points[e[1]]));
  return lengths;
}

inline std::vector<double> edge_l1_lengths(const Norm_preserving_geometry& geometry)
{
  return edge_lengths(geometry, l1_distance);
}

// The value su du (c = 0) or sv dv (c = 1) of edge `e`, which its sign constraint keeps >= 0.
inline double sign_constraint_value(const Norm_preserving_geometry& geometry, const Edge_signs& signs,
                                    const UV_vector& uv, std::size_t e, int c)
{
  return signs[e][c] * (uv[geometry.edges[e][0]][c] - uv[geometry.edges[e][1]][c]);
}

// The residual l1_e - su du - sv dv of edge `e` in Eq. 4.
inline double sign_constrained_residual(const Norm_preserving_geometry& geometry, const std::vector<double>& lengths,
                                        const Edge_signs& signs, const UV_vector& uv, std::size_t e)
{
  return lengths[e] - sign_constraint_value(geometry, signs, uv, e, 0) - sign_constraint_value(geometry, signs, uv, e, 1);
}

// Eq. 4: sum over edges of (l1_e - su du - sv dv)^2.
inline double sign_constrained_objective(const Norm_preserving_geometry& geometry, const std::vector<double>& lengths,
                                         const Edge_signs& signs, const UV_vector& uv)
{
  double sum = 0;
  for(std::size_t e = 0; e < lengths.size(); ++e)
  {
    const double r = sign_constrained_residual(geometry, lengths, signs, uv, e);
    sum += r * r;
  }
  return sum;
}

// Eq. 3: sum over edges of (l1_e - |du| - |dv|)^2.
inline double l1_norm_objective(const Norm_preserving_geometry& geometry, const std::vector<double>& lengths,
                                const UV_vector& uv)
{
  double sum = 0;
  for(std::size_t e = 0; e < lengths.size(); ++e)
  {
    const auto& p = uv[geometry.edges[e][0]];
    const auto& q = uv[geometry.edges[e][1]];
    const double r = lengths[e] - std::abs(p[0] - q[0]) - std::abs(p[1] - q[1]);
    sum += r * r;
  }
  return sum;
}

// Smallest sign-constraint value su du, sv dv over all edges (negative if violated), and
// the number of constraints with value at most `active_threshold`.
inline std::pair<double, std::size_t> sign_constraint_extent(const Norm_preserving_geometry& geometry,
                                                            const Edge_signs& signs, const UV_vector& uv,
                                                            double active_threshold)
{
  double lowest = std::numeric_limits<double>::infinity();
  std::size_t active = 0;
  for(std::size_t e = 0; e < signs.size(); ++e)
    for(int c = 0; c < 2; ++c)
    {
      const double value = sign_constraint_value(geometry, signs, uv, e, c);
      lowest = (std::min)(lowest, value);
      if(value <= active_threshold) ++active;
    }
  return {lowest, active};
}

using Fixed_vertex = Norm_preserving_fixed_vertex;

// Row e of Eq. 5 as a row of least squares, sum_e (d_e - C_e x)^2, in unknowns of the caller's
// choosing: `unknowns(c, i, term, known)` calls term(k) for each unknown x_k that coordinate c
// of vertex i is made of (with coefficient 1) and known(v) for a part v of it that is known (a
// fixed value). Calls `term(k, a)` for each term a x_k of the row and returns d_e: the edge's
// length less the known parts. The one definition of the QP's rows, which its assemblies read.
template <typename Unknowns, typename Term>
double sign_constrained_row(const Norm_preserving_geometry& geometry, const std::vector<double>& lengths,
                            const Edge_signs& signs, std::size_t e, const Unknowns& unknowns, const Term& term)
{
  double d = lengths[e];
  for(int c = 0; c < 2; ++c)
    for(std::size_t end = 0; end < 2; ++end)
    {
      const double a = end == 0 ? signs[e][c] : -signs[e][c];
      unknowns(c, geometry.edges[e][end], [&](auto k) { term(k, a); }, [&](double v) { d -= a * v; });
    }
  return d;
}

// Eq. 5 written into a model of QuadraticProgramTraits: u_i at 2i, v_i at 2i + 1 (the fixed
// vertices too, held by equality rows), the objective as 1/2 x'Px + q'x + r with P = 2 C'C,
// q = -2 C'd and r = d'd, the sign constraints as rows 2e, 2e + 1 of A.
template <typename QuadraticProgramTraits>
void assemble_sign_constrained_qp(const Norm_preserving_geometry& geometry, const std::vector<double>& lengths,
                                  const Edge_signs& signs, const std::array<Fixed_vertex, 2>& fixed,
                                  QuadraticProgramTraits& qp)
{
  const std::size_t n = 2 * geometry.points.size();
  const std::size_t m = 2 * geometry.edges.size();
  const Normal_equations normal = normal_equations(m / 2, n, [&](std::size_t e, const auto& term) {
    return sign_constrained_row(geometry, lengths, signs, e,
                                [](int c, std::size_t i, const auto& unknown, const auto&) { unknown(int(2 * i) + c); },
                                term);
  });
  const Sparse_matrix upper = normal.lower.transpose(); // by columns, as P is written
  for(int c = 0; c < upper.outerSize(); ++c)
    for(Sparse_matrix::InnerIterator it(upper, c); it; ++it)
      qp.set_P(std::size_t(it.row()), std::size_t(it.col()), 2. * it.value());
  for(std::size_t k = 0; k < n; ++k)
    qp.set_q(k, -2. * normal.rhs[Eigen::Index(k)]);
  double r = 0;
  for(double l : lengths)
    r += l * l;
  qp.set_r(r);
  for(std::size_t e = 0; e < m / 2; ++e)
    for(int c = 0; c < 2; ++c)
    {
      qp.set_A(2 * e + c, 2 * geometry.edges[e][0] + c, signs[e][c]);
      qp.set_A(2 * e + c, 2 * geometry.edges[e][1] + c, -signs[e][c]);
      qp.set_l(2 * e + c, 0.);
      qp.set_u(2 * e + c, std::numeric_limits<double>::infinity());
    }
  for(std::size_t f = 0; f < 2; ++f)
    for(int c = 0; c < 2; ++c)
    {
      const std::size_t row = m + 2 * f + c;
      qp.set_A(row, 2 * fixed[f].index + c, 1.);
      qp.set_l(row, fixed[f].target[c]);
      qp.set_u(row, fixed[f].target[c]);
    }
}

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
