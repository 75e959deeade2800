// Copyright (c) 2026 The CGAL_norm_preserving_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
/// \file Norm_preserving_solver.h
/// \ingroup PkgNormPreservingParameterization
/// The problem and the report of a model of `NormPreservingSolver`.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_SOLVER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_SOLVER_H

#include <CGAL/Surface_mesh_parameterization/Norm_preserving_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_report.h>

#include <array>
#include <limits>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterizationTypes
/// A vertex held at `target` by the sign-constrained QP.
struct Norm_preserving_fixed_vertex
{
  std::size_t index;             ///< the vertex, an index into `Norm_preserving_geometry::points`
  std::array<double, 2> target;  ///< its uv
};

/// \ingroup PkgNormPreservingParameterizationTypes
/// The sign-constrained QP of one component (the paper's Eq. 5), as handed to a model of
/// `NormPreservingSolver`: minimize `sum_e (lengths[e] - su_e (u_i - u_j) - sv_e (v_i - v_j))^2`
/// over the uvs, subject to `su_e (u_i - u_j) >= 0`, `sv_e (v_i - v_j) >= 0` for every edge
/// `e = {i, j}` with signs `{su_e, sv_e} = signs[e]`, and the two fixed vertices at their targets.
/// The geometry is normalized (mean L1 edge length 1).
struct Norm_preserving_problem
{
  const Norm_preserving_geometry& geometry;          ///< vertices and edges
  const std::vector<double>& lengths;                ///< the L1 length of each edge
  const std::vector<std::array<double, 2> >& signs;  ///< `+1` or `-1` per edge and coordinate
  std::array<Norm_preserving_fixed_vertex, 2> fixed; ///< the fixed pair
  /// the vertex values the signs were taken from (with ties oriented as if the vertex of
  /// higher index were the larger), if not the start point handed to `solve()`
  const std::vector<std::array<double, 2> >* order = nullptr;
};

/// \ingroup PkgNormPreservingParameterizationTypes
/// What one solve of a model of `NormPreservingSolver` did.
struct Norm_preserving_solve_report
{
  Norm_preserving_solver_status status = NORM_PRESERVING_SOLVER_FAILED; ///< how the solve ended
  bool has_statistics = false;      ///< whether the solver reported the two fields below
  int iterations = 0;               ///< iterations of the solver
  double kkt_residual = 0;          ///< largest residual the solver reports
  /// a certified upper bound on `(f - f*) / max(f*, 1e-12 f0)`, `f` the objective of the
  /// solution, `f*` the optimum and `f0` that of the zero map (from a duality gap); infinity
  /// if the solver certifies nothing
  double optimality_gap = std::numeric_limits<double>::infinity();
  double assembly_seconds = 0;      ///< setting up the linear algebra
  double factorization_seconds = 0; ///< factorizations done before iterating
  double iteration_seconds = 0;     ///< the rest of the solve
  std::string message;              ///< why the solve failed or stopped short; empty if it converged
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
