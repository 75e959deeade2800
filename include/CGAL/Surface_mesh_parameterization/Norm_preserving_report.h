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
/// \file Norm_preserving_report.h
/// \ingroup PkgNormPreservingParameterization
/// What a call of the parameterizer did, and the messages of the error codes.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_REPORT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_REPORT_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/disable_warnings.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterizationEnums
/// How a solver of `Norm_preserving_parameterizer_3` ended.
enum Norm_preserving_solver_status
{
  NORM_PRESERVING_SOLVER_CONVERGED,       ///< the tolerance was met
  NORM_PRESERVING_SOLVER_ITERATION_LIMIT, ///< the iteration limit was hit: the best feasible point found is returned
  NORM_PRESERVING_SOLVER_TIME_LIMIT,      ///< the time limit was hit: the best feasible point found is returned
  /// the certified mode found a point that satisfies the optimality (KKT) conditions to
  /// round-off, but its certified gap, limited by the floating-point precision of the bound,
  /// is above the tolerance: the point of least gap found is returned with that gap
  NORM_PRESERVING_SOLVER_PRECISION_LIMIT,
  NORM_PRESERVING_SOLVER_FAILED           ///< no solution (the uv map is left untouched)
};

/// \ingroup PkgNormPreservingParameterizationTypes
/// What one solve of the QP did, as the solver (a model of `NormPreservingSolver`) reports it.
struct Norm_preserving_solve_report
{
  Norm_preserving_solver_status status = NORM_PRESERVING_SOLVER_FAILED; ///< how the solve ended
  /// the solver and its setting, such as "ADMM, default quality (stopping rule at 2.5e-05)"
  std::string method;
  bool has_statistics = false;      ///< whether the solver reported the two fields below
  int iterations = 0;               ///< iterations of the solver
  double kkt_residual = 0;          ///< largest residual the solver reports, on the normalized QP (edge lengths ~ 1)
  /// a certified upper bound on the relative distance `(f - f*) / f*` of the solution's
  /// objective `f` to the optimum `f*` of the QP (near a zero optimum, relative to `1e-12`
  /// times the objective of the zero map); 0 where there is nothing to solve, infinity for a
  /// solver that certifies nothing
  double optimality_gap = std::numeric_limits<double>::infinity();
  double assembly_seconds = 0;      ///< setting up the linear algebra (the Laplacian, for the ADMM solver)
  double factorization_seconds = 0; ///< factorizations done before iterating (the ADMM solver's Laplacian)
  double iteration_seconds = 0;     ///< the rest of the solve
  /// why the solve failed or stopped short of its tolerance (an iteration, time or precision
  /// limit: the solution is then the best feasible point found); empty if it converged
  std::string message;
  bool interrupted = false;         ///< whether `Norm_preserving_problem::progress` stopped the solve
};

/// \ingroup PkgNormPreservingParameterizationTypes
/// Where the time of one `Norm_preserving_parameterizer_3::parameterize()` call went, in
/// seconds, but for the QP solve's own steps (`Norm_preserving_solve_report`).
struct Norm_preserving_timings
{
  double extraction = 0;           ///< copying the component, choosing the fixed pair, normalizing
  double guess = 0;                ///< the initial guess, the similarity transform and the signs
  double solve = 0;                ///< the QP solve (`Norm_preserving_report::solver` splits it)
  double sign_refinement = 0;      ///< the rounds of sign refinement (their QP solves included)
  double euclidean_refinement = 0; ///< the Euclidean refinement (a factorization included for solvers other than ADMM)
  double write_back = 0;           ///< the rest: the final objective, the fit into texture space, the uv map
};

/// \ingroup PkgNormPreservingParameterizationTypes
/// What the last call of `Norm_preserving_parameterizer_3::parameterize()` did.
/// Lengths are in mesh units; objectives are the plain sum of Eq. 4 (no 1/2 factor).
struct Norm_preserving_report
{
  Error_code status = OK;              ///< result of the call
  std::string message;                 ///< readable reason of a failure, empty on success
  std::size_t vertices = 0;            ///< vertices of the parameterized component
  std::size_t edges = 0;               ///< edges of the component, one QP residual each
  /// the first fixed vertex: its index in the input for the whole-soup calls, in the
  /// component (in the mesh's vertex order) for the parameterizer, whose `fixed_vertices()`
  /// gives it as a vertex of the mesh
  std::size_t fixed_a = 0;
  std::size_t fixed_b = 0;             ///< the second fixed vertex, likewise
  double initial_objective = 0;        ///< Eq. 4 at the transformed initial guess
  /// Eq. 4 (equal to Eq. 3) at the solution of the QP, after the sign refinement and before
  /// the Euclidean refinement (which minimizes another objective)
  double objective = 0;
  double max_constraint_violation = 0; ///< largest violation of a sign constraint (of the final signs), at the same point
  std::size_t active_constraints = 0;  ///< sign constraints at equality (within 1e-8 mean edge length), at the same point
  std::size_t constraints = 0;         ///< sign constraints, two per edge
  /// what the QP solve did (the first solve, before the refinements): how it ended, its
  /// certified distance to the optimum, its iterations and timings
  Norm_preserving_solve_report solver;
  int sign_refinement_rounds = 0;      ///< rounds of sign refinement kept (each lowered Eq. 3)
  /// Eq. 3 at the QP solution, then after each round kept: non-increasing; empty when the
  /// sign refinement is off
  std::vector<double> sign_refinement_objectives;
  int euclidean_iterations = 0;        ///< stress-majorization steps of the Euclidean refinement
  /// the Euclidean objective `sum (||P_i - P_j||_2 - ||T_i - T_j||_2)^2` at the start of the
  /// Euclidean refinement (the QP solution scaled to fit), then after each step:
  /// non-increasing; empty when the refinement is off
  std::vector<double> euclidean_stress;
  double seconds = 0;                  ///< wall-clock time of the call
  Norm_preserving_timings timings;     ///< the same time, step by step
};

/// \ingroup PkgNormPreservingParameterizationFunctions
/// The message of each `Error_code` (CGAL 5.5's `get_error_message()` is off by one from
/// `ERROR_NO_TOPOLOGICAL_BALL` on).
inline const char* norm_preserving_error_message(Error_code code)
{
  switch(code)
  {
    case OK: return "Success";
    case ERROR_EMPTY_MESH: return "Input mesh is empty";
    case ERROR_NON_TRIANGULAR_MESH: return "Input mesh is not triangular";
    case ERROR_NO_TOPOLOGICAL_DISC: return "Input mesh is not a topological disc";
    case ERROR_NO_TOPOLOGICAL_BALL: return "Input mesh is not a topological ball";
    case ERROR_BORDER_TOO_SHORT: return "This border parameterization requires a longer border";
    case ERROR_NON_CONVEX_BORDER: return "This parameterization method requires a convex border";
    case ERROR_CANNOT_SOLVE_LINEAR_SYSTEM: return "Cannot solve linear system";
    case ERROR_NO_1_TO_1_MAPPING: return "Parameterization failed: no one-to-one mapping";
    case ERROR_WRONG_PARAMETER: return "A method received an unexpected parameter";
  }
  return "Unknown error";
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif
