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
/// \file Norm_preserving_ADMM_solver.h
/// \ingroup PkgNormPreservingParameterization
/// The default solver of the sign-constrained QP.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_ADMM_SOLVER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_ADMM_SOLVER_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/disable_warnings.h>

#include <CGAL/Surface_mesh_parameterization/Norm_preserving_quality.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_report.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sign_constrained_admm.h>

#include <array>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterizationMethods
/// The default solver of `Norm_preserving_parameterizer_3`: solves the sign-constrained QP
/// (the paper's Eq. 5) by the alternating direction method of multipliers, split so that the
/// only linear system is the mesh's graph Laplacian, factored once (CHOLMOD when the package
/// is configured with it). Each iteration costs one two-column triangular solve and a
/// closed-form step per edge. The result satisfies every sign constraint exactly, so its
/// objective is never below the optimum, and every solve reports a certified bound on its
/// distance to the optimum (a duality gap, `Norm_preserving_solve_report::optimality_gap`).
///
/// Two modes:
/// - by default, the solve stops when the decrease of the objective still to come,
///   extrapolated from the last iterations, is at most `tolerance` (relative to the
///   objective) at consecutive checks, and the certified gap confirms it; a tail that has not
///   stopped by iteration 1,000 is finished by the interior point
///   (`Interior_point_quadratic_program_traits`) on meshes of up to 200,000 vertices;
/// - `certified()`, the exact mode: the solve stops when the certified gap is at most
///   `tolerance` (default 1e-9), reached by the exact optimum on the set of constraints the
///   iterations have made active. Where the optimum is a tiny share of the zero map's objective,
///   the rounding of the bound can keep the gap of the optimum itself above `tolerance`: the
///   solve then ends at the optimality (KKT) point of least gap it found, with
///   `NORM_PRESERVING_SOLVER_PRECISION_LIMIT`.
///
/// The presets `Norm_preserving_quality` choose among these. With the default time limit (none)
/// the result depends on the input only, bit for bit.
///
/// \cgalModels `NormPreservingSolver`
class Norm_preserving_ADMM_solver
{
public:
  /// what a solve leaves to the next on the same geometry and fixed pair: the factored
  /// Laplacian, the edge values and the multipliers (a warm start).
  typedef internal::Norm_preserving::Admm_state State;

  /// creates a solver that stops when the extrapolated remaining decrease of the objective is
  /// at most `tolerance` times the objective and its certificate confirms it, or after
  /// `max_iterations` iterations or `time_limit` seconds.
  explicit Norm_preserving_ADMM_solver(double tolerance = internal::Norm_preserving::admm_default_tolerance,
                                       int max_iterations = 20000,
                                       double time_limit = std::numeric_limits<double>::infinity())
  {
    m_settings.tolerance = tolerance;
    m_settings.max_iterations = max_iterations;
    m_settings.time_limit = time_limit;
  }

  /// a solver of the preset `quality`, stopping after `time_limit` seconds at the latest:
  /// `Norm_preserving_ADMM_solver(preset_tolerance(quality))`, or `certified()` for
  /// `NORM_PRESERVING_EXACT_QUALITY`.
  explicit Norm_preserving_ADMM_solver(Norm_preserving_quality quality,
                                       double time_limit = std::numeric_limits<double>::infinity())
    : Norm_preserving_ADMM_solver(quality == NORM_PRESERVING_EXACT_QUALITY
                                    ? certified(preset_tolerance(quality), 200000, time_limit)
                                    : Norm_preserving_ADMM_solver(preset_tolerance(quality), 20000, time_limit))
  { }

  /// the tolerance of the preset `quality`: of the stopping rule, or for
  /// `NORM_PRESERVING_EXACT_QUALITY` of the certified gap.
  static double preset_tolerance(Norm_preserving_quality quality)
  {
    switch(quality)
    {
      case NORM_PRESERVING_DRAFT_QUALITY: return internal::Norm_preserving::admm_draft_tolerance;
      case NORM_PRESERVING_EXACT_QUALITY: return internal::Norm_preserving::admm_exact_gap;
      default: return internal::Norm_preserving::admm_default_tolerance;
    }
  }

  /// the exact mode: a solver that stops when its certified gap to the optimum (relative) is
  /// at most `gap`, at an optimality (KKT) point whose gap the bound's rounding keeps above
  /// `gap` (`NORM_PRESERVING_SOLVER_PRECISION_LIMIT`), or after `max_iterations` iterations or
  /// `time_limit` seconds.
  static Norm_preserving_ADMM_solver certified(double gap = internal::Norm_preserving::admm_exact_gap,
                                               int max_iterations = 200000,
                                               double time_limit = std::numeric_limits<double>::infinity())
  {
    Norm_preserving_ADMM_solver solver(gap, max_iterations, time_limit);
    solver.m_settings.certified = true;
    return solver;
  }

  /// solves `problem` from `uv`, which satisfies its sign constraints, writes the solution to
  /// `uv` and what the solve did to `report`; returns `false` if there is none (the Laplacian
  /// cannot be factored) or `problem.progress` stopped it. `report.kkt_residual` is the larger
  /// of the relative primal residual `|Ax - z| / |l1|` and dual residual
  /// `|A'(z - z_prev)| / |l1|`; `report.optimality_gap` the certified bound.
  bool solve(const Norm_preserving_problem& problem, std::vector<std::array<double, 2> >& uv, State& state,
             Norm_preserving_solve_report& report) const
  {
    internal::Norm_preserving::Sign_constrained_admm admm(problem.geometry, problem.lengths, problem.signs, problem.fixed,
                                                          m_settings, uv, &state, problem.order, problem.progress);
    const bool solved = admm.solve(report);
    report.method = method();
    return solved;
  }

  /// the solver and its setting in words, such as "ADMM, default quality (stopping rule at
  /// 2.5e-05)": a preset's name where the settings are a preset's.
  std::string method() const
  {
    namespace NP = internal::Norm_preserving;
    const NP::Admm_settings& s = m_settings;
    std::ostringstream out;
    out << "ADMM, ";
    if(s.certified)
      out << (s.tolerance == NP::admm_exact_gap && s.max_iterations == 200000 ? "exact quality (" : "(")
          << "certified gap " << s.tolerance << ")";
    else
      out << (s.max_iterations != 20000                  ? "("
              : s.tolerance == NP::admm_draft_tolerance   ? "draft quality ("
              : s.tolerance == NP::admm_default_tolerance ? "default quality ("
                                                          : "(")
          << "stopping rule at " << s.tolerance << ")";
    if(s.time_limit < std::numeric_limits<double>::infinity())
      out << ", time limit " << s.time_limit << " s";
    return out.str();
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

#include <CGAL/enable_warnings.h>

#endif
