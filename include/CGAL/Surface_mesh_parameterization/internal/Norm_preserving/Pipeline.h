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
// The method on one connected component given as vertices and edges, shared by the
// parameterizer (a component of a halfedge mesh) and the whole-soup calls (a component of the
// edge graph of a polygon soup): normalize, guess, fixed pair + similarity, solve, refine,
// fit. Nothing here needs faces: Eq. 4 is a sum over edges (doc/decisions.md, "Input and triangulation").

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_PIPELINE_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_PIPELINE_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_QP_solver.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_report.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Fixed_pair.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Options.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sign_constrained_qp.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sign_refinement.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Similarity_transform.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Stress_majorization.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Texture_space_fit.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

// Measures the steps: each call returns the seconds since the previous one.
class Lap_timer
{
public:
  double lap()
  {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - m_start).count();
    m_start = now;
    return seconds;
  }

private:
  std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
};

// `Solver` is a model of NormPreservingSolver.
template <typename InitialGuess, typename Solver>
class Pipeline
{
public:
  Pipeline(const InitialGuess& guess, const Solver& solver) : m_guess(guess), m_solver(solver) { }

  Options& options() { return m_options; }
  const Options& options() const { return m_options; }

  // Maps `geometry` (one connected component with at least one edge) to `uv`, with
  // `pair` (component indices, an edge) fixed, or an automatic pair. Fills `report` but for
  // `seconds`, the extraction time and the write-back time, which the caller measures.
  // `progress`, if not null, is handed to the solver (Norm_preserving_problem::progress).
  Error_code run(Norm_preserving_geometry geometry, const std::optional<std::pair<std::size_t, std::size_t> >& pair,
                 UV_vector& uv, Norm_preserving_report& report,
                 const std::function<bool(double)>* progress = nullptr) const
  {
    Run run(*this, geometry, uv, report, progress);
    Error_code status = run.check_settings();
    if(status == OK) status = run.choose_fixed_pair(pair);
    if(status == OK) status = run.normalize();
    if(status == OK) status = run.guess();
    if(status == OK) status = run.fix_pair_and_transform();
    if(status == OK) status = run.solve();
    if(status == OK) status = run.refine();
    if(status == OK) status = run.fit();
    return status;
  }

private:
  // The state of one run, step by step.
  struct Run
  {
    const Pipeline& pipeline;
    Norm_preserving_geometry& geometry;
    UV_vector& uv;
    Norm_preserving_report& report;
    const std::function<bool(double)>* progress;
    Lap_timer timer;
    std::size_t a = 0, b = 0;
    bool automatic = false;
    double unit = 0;
    std::vector<double> lengths;
    std::array<Fixed_vertex, 2> fixed;
    Edge_signs signs;
    typename Solver::State state; // what a solve leaves to the next (the refinements' solves)

    Run(const Pipeline& p, Norm_preserving_geometry& g, UV_vector& u, Norm_preserving_report& r,
        const std::function<bool(double)>* f)
      : pipeline(p), geometry(g), uv(u), report(r), progress(f)
    { }

    Error_code fail(Error_code code, const std::string& message)
    {
      report.message = message;
      return code;
    }

    Error_code check_settings()
    {
      const std::string invalid = invalid_option(pipeline.m_options);
      if(!invalid.empty())
        return fail(ERROR_WRONG_PARAMETER, invalid);
      report.vertices = geometry.points.size();
      report.edges = geometry.edges.size();
      return OK;
    }

    Error_code choose_fixed_pair(const std::optional<std::pair<std::size_t, std::size_t> >& pair)
    {
      automatic = !pair;
      std::tie(a, b) = pair ? *pair : automatic_fixed_pair(geometry);
      if(!is_edge(geometry, a, b))
        return fail(ERROR_WRONG_PARAMETER, "the fixed vertices are not the two ends of an edge");
      report.fixed_a = a;
      report.fixed_b = b;
      return OK;
    }

    // Units of the mean L1 edge length, relative to the first fixed vertex, so that the QP is
    // equally well conditioned at every model scale.
    Error_code normalize()
    {
      lengths = edge_l1_lengths(geometry);
      for(double l : lengths) unit += l;
      unit /= double(lengths.size());
      if(!std::isfinite(unit))
        return fail(ERROR_WRONG_PARAMETER, "the edge lengths overflow: the coordinates are too large");
      if(!(unit > 0))
        return fail(ERROR_WRONG_PARAMETER, "all edges have zero length");
      const std::array<double, 3> origin = geometry.points[a];
      for(auto& p : geometry.points)
        for(int c = 0; c < 3; ++c)
          p[c] = (p[c] - origin[c]) / unit;
      lengths = edge_l1_lengths(geometry);
      report.timings.extraction += timer.lap();
      return OK;
    }

    Error_code guess()
    {
      const Error_code status = pipeline.m_guess(geometry, uv, report.message);
      if(status != OK)
        return status;
      if(uv.size() != geometry.points.size())
        return fail(ERROR_WRONG_PARAMETER, "the initial guess did not give one value per vertex");
      for(const auto& p : uv)
        if(!std::isfinite(p[0]) || !std::isfinite(p[1]))
          return fail(ERROR_WRONG_PARAMETER, "the initial guess has a non-finite value");
      if(automatic && uv[a] == uv[b])
        report.fixed_b = b = automatic_partner(geometry, a, &uv); // the guess must tell a from b
      return OK;
    }

    Error_code fix_pair_and_transform()
    {
      fixed = {Fixed_vertex{a, {}}, Fixed_vertex{b, {}}};
      const double l1_ab = l1_distance(geometry.points[a], geometry.points[b]);
      if(!(l1_ab > 0))
        return fail(ERROR_WRONG_PARAMETER, "the fixed vertices are at the same position");
      if(!fixed_pair_targets(uv[a], uv[b], l1_ab, fixed[0].target, fixed[1].target))
        return fail(ERROR_WRONG_PARAMETER, "the initial guess puts both fixed vertices at the same point");
      transform(uv, similarity_from_pairs(uv[a], uv[b], fixed[0].target, fixed[1].target));
      uv[a] = fixed[0].target;
      uv[b] = fixed[1].target;
      signs = edge_signs(geometry, uv);
      report.initial_objective = sign_constrained_objective(geometry, lengths, signs, uv) * unit * unit;
      report.constraints = 2 * geometry.edges.size();
      report.timings.guess = timer.lap();
      return OK;
    }

    Error_code solve()
    {
      const Error_code status = solve_qp(signs, uv, nullptr, &report.solver);
      report.timings.solve = timer.lap();
      return status;
    }

    Error_code refine()
    {
      const Options& o = pipeline.m_options;
      if(o.sign_refinement_rounds > 0)
      {
        auto round = [&](const Edge_signs& next, const UV_vector& order, UV_vector& candidate) {
          return solve_qp(next, candidate, &order, nullptr) == OK;
        };
        const std::vector<double> objectives =
          refine_signs(geometry, lengths, fixed, {o.sign_refinement_rounds, o.sign_refinement_tolerance}, signs, uv, round);
        report.sign_refinement_rounds = int(objectives.size()) - 1;
        for(double objective : objectives)
          report.sign_refinement_objectives.push_back(objective * unit * unit);
        report.timings.sign_refinement = timer.lap();
      }

      report.objective = l1_norm_objective(geometry, lengths, uv) * unit * unit;
      const auto extent = sign_constraint_extent(geometry, signs, uv, 1e-8);
      report.max_constraint_violation = (std::max)(0., -extent.first) * unit;
      report.active_constraints = extent.second;
      if(o.euclidean_refinement_iterations > 0 && geometry.points.size() > fixed.size())
      {
        timer.lap();
        const Error_code status = refine_euclidean();
        report.timings.euclidean_refinement = timer.lap();
        return status;
      }
      return OK;
    }

    Error_code fit()
    {
      for(auto& p : uv)
        for(int c = 0; c < 2; ++c)
          p[c] *= unit;
      const Options& o = pipeline.m_options;
      fit_to_texture_space(uv, o.texture_fit, o.tiles_u, o.tiles_v);
      return OK;
    }

    // One QP solve with `qp_signs` from `result`, which satisfies them; `order` tells a warm
    // start the values the signs come from. The solver writes what it did into `solved` (the
    // report's, for the first solve; the refinement's solves report nothing).
    Error_code solve_qp(const Edge_signs& qp_signs, UV_vector& result, const UV_vector* order,
                        Norm_preserving_solve_report* solved)
    {
      Norm_preserving_solve_report unreported;
      Norm_preserving_solve_report& r = solved ? *solved : unreported;
      if(result.size() == fixed.size()) // an isolated edge: its two ends are the fixed pair
      {
        for(const Fixed_vertex& f : fixed)
          result[f.index] = f.target;
        r = Norm_preserving_solve_report();
        r.status = NORM_PRESERVING_SOLVER_CONVERGED;
        r.optimality_gap = 0;
        return OK;
      }
      if(!pipeline.m_solver.solve(Norm_preserving_problem{geometry, lengths, qp_signs, fixed, order, progress}, result,
                                  state, r))
        return solved ? fail(ERROR_CANNOT_SOLVE_LINEAR_SYSTEM, "the QP solver failed: " + r.message)
                      : ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
      return OK;
    }

    // Beyond the paper: the Euclidean objective by stress majorization, from the QP solution.
    Error_code refine_euclidean()
    {
      const std::vector<double> euclidean = edge_euclidean_lengths(geometry);
      std::array<Fixed_vertex, 2> held = fixed;
      if(!euclidean_start(geometry, euclidean, held, uv))
        return fail(ERROR_CANNOT_SOLVE_LINEAR_SYSTEM, "the Euclidean refinement failed: the solution has no extent");
      const Stress_majorization_result result =
        majorize_stress(geometry, euclidean, held,
                        {pipeline.m_options.euclidean_refinement_iterations, pipeline.m_options.euclidean_refinement_tolerance}, uv,
                        factored_laplacian(state));
      report.euclidean_iterations = result.iterations;
      for(double stress : result.stress)
        report.euclidean_stress.push_back(stress * unit * unit);
      if(!result.solved)
        return fail(ERROR_CANNOT_SOLVE_LINEAR_SYSTEM,
                    "the Euclidean refinement failed: the graph Laplacian could not be factored or a value overflowed");
      return OK;
    }
  };

  InitialGuess m_guess;
  Solver m_solver;
  Options m_options;
};

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
