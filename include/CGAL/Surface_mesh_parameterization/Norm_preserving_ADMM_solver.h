// Copyright (c) 2026 The CGAL_norm_preserving_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
/// \file Norm_preserving_ADMM_solver.h
/// \ingroup PkgNormPreservingParameterization
/// The default solver of the sign-constrained QP.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_ADMM_SOLVER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_ADMM_SOLVER_H

#include <CGAL/Surface_mesh_parameterization/Norm_preserving_report.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sign_constrained_admm.h>

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterizationMethods
/// The default solver of `Norm_preserving_parameterizer_3`: solves the sign-constrained QP
/// (the paper's Eq. 5) by the alternating direction method of multipliers, split so that the
/// only linear system is the mesh's graph Laplacian, factored once (CHOLMOD when the package
/// is configured with it). Each iteration costs one two-column triangular solve and a
/// closed-form step per edge. The result satisfies every sign constraint exactly (the last
/// iterate is swept onto the feasible set), so its objective is never below the optimum, and
/// every solve reports a certified bound on its distance to the optimum (a duality gap,
/// `Norm_preserving_solve_report::optimality_gap`).
///
/// Two modes:
/// - by default, the solve stops when the decrease of the objective still to come,
///   extrapolated from the last iterations, is at most `tolerance` (relative to the
///   objective, or near a zero optimum to 1e-12 times the objective of the zero map) at two
///   checks in a row and the certified gap at most 60 times `tolerance`, or at three checks in
///   a row and 150 times (three checks and 75 times once the objective has risen at a check);
///   a solve that has not stopped by iteration 1,000, on a mesh of at most 200,000 vertices
///   and within the time limit, is finished by the interior point
///   (`Interior_point_quadratic_program_traits`, within what is left of the time limit), whose
///   point the exact mode's active-set optimum then certifies within `tolerance` when it can
///   (otherwise the reported bound is looser);
/// - `certified()`, the exact mode: the solve stops when the certified gap is at most
///   `tolerance` (default 1e-9); from where the default would stop, it also tries the exact
///   optimum on the set of constraints the iterations have made active, corrected a few
///   times, which certifies there on 34 of the 35 benchmark meshes of up to 50,000 vertices
///   (at 150,000 vertices and more the interior point can be faster: doc/benchmarks.md); a tail not
///   settled by iteration 1,000, or whose tries are over by then without ending at the
///   optimum, goes to the interior point as in the default mode. Where the optimum is a tiny share of the zero map's
///   objective, the bound's rounding can keep the gap of the optimum itself above `tolerance`:
///   the solve then ends at the optimality (KKT) point of least gap its tries found, with
///   `NORM_PRESERVING_SOLVER_PRECISION_LIMIT` (its iterations and residuals are the ADMM's).
///
/// With the default time limit (none) the result depends on the input only, bit for bit.
///
/// \cgalModels `NormPreservingSolver`
class Norm_preserving_ADMM_solver
{
public:
  /// what a solve leaves to the next on the same geometry and fixed pair: the factored
  /// Laplacian, the edge values and the multipliers (a warm start).
  typedef internal::Norm_preserving::Admm_state State;

  /// creates a solver that stops when the extrapolated remaining decrease of the objective is
  /// at most `tolerance` times the objective (and the certified gap at most 60 times
  /// `tolerance` at two checks, 150 at three, 75 after a rise), or after
  /// `max_iterations` iterations or `time_limit` seconds. The default puts the objective
  /// within 1e-4 of the optimum on the test suite, the benchmark meshes, CGAL's data meshes of
  /// nonzero optimum and 102 of them subdivided (doc/benchmarks.md; doc/performance.md,
  /// changes 29 and 30).
  explicit Norm_preserving_ADMM_solver(double tolerance = internal::Norm_preserving::admm_default_tolerance,
                                       int max_iterations = 20000,
                                       double time_limit = std::numeric_limits<double>::infinity())
    : m_settings{tolerance, max_iterations, time_limit, false}
  { }

  /// the exact mode: a solver that stops when its certified gap to the optimum (relative) is
  /// at most `gap`, at an optimality (KKT) point whose gap the bound's rounding keeps above
  /// `gap` (`NORM_PRESERVING_SOLVER_PRECISION_LIMIT`), or after `max_iterations` iterations or
  /// `time_limit` seconds.
  static Norm_preserving_ADMM_solver certified(double gap = 1e-9, int max_iterations = 200000,
                                               double time_limit = std::numeric_limits<double>::infinity())
  {
    Norm_preserving_ADMM_solver solver(gap, max_iterations, time_limit);
    solver.m_settings.certified = true;
    return solver;
  }

  /// solves `problem` from `uv`, which satisfies its sign constraints, and writes the
  /// solution to `uv`; returns `false` if there is none (the Laplacian cannot be factored).
  /// `report.kkt_residual` is the larger of the relative primal residual `|Ax - z| / |l1|` and
  /// dual residual `|A'(z - z_prev)| / |l1|`; `report.optimality_gap` the certified bound.
  bool solve(const Norm_preserving_problem& problem, std::vector<std::array<double, 2> >& uv, State& state,
             Norm_preserving_solve_report& report) const
  {
    namespace NP = internal::Norm_preserving;
    const NP::Admm_result result = NP::solve_sign_constrained_admm(problem.geometry, problem.lengths, problem.signs,
                                                                   problem.fixed, m_settings, uv, &state,
                                                                   problem.order);
    report = Norm_preserving_solve_report();
    report.has_statistics = true;
    report.iterations = result.iterations;
    report.kkt_residual = (std::max)(result.primal_residual, result.dual_residual);
    report.optimality_gap = result.gap;
    report.assembly_seconds = result.assembly_seconds;
    report.factorization_seconds = result.factorization_seconds;
    report.iteration_seconds = result.iteration_seconds;
    switch(result.outcome)
    {
      case NP::Admm_outcome::CONVERGED: report.status = NORM_PRESERVING_SOLVER_CONVERGED; break;
      case NP::Admm_outcome::ITERATION_LIMIT:
        report.status = NORM_PRESERVING_SOLVER_ITERATION_LIMIT;
        report.message = "iteration limit reached before the tolerance";
        break;
      case NP::Admm_outcome::TIME_LIMIT:
        report.status = NORM_PRESERVING_SOLVER_TIME_LIMIT;
        report.message = "time limit reached before the tolerance";
        break;
      case NP::Admm_outcome::PRECISION_LIMIT:
        report.status = NORM_PRESERVING_SOLVER_PRECISION_LIMIT;
        report.message = "the certified gap stopped above the tolerance at an optimal point (floating-point precision)";
        break;
      case NP::Admm_outcome::FACTORIZATION_FAILED:
        report.message = "the graph Laplacian could not be factored";
        return false;
    }
    return true;
  }

private:
  internal::Norm_preserving::Admm_settings m_settings;
};

/// \cond SKIP_IN_MANUAL
namespace internal {
namespace Norm_preserving {
// The graph Laplacian of the free vertices, if a solve left it factored in `state`.
inline const Two_column_cholesky* factored_laplacian(const Admm_state& state)
{
  return state.factored ? &state.cholesky : nullptr;
}
} // namespace Norm_preserving
} // namespace internal
/// \endcond

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
