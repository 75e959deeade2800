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
// The sign-constrained QP (Eq. 5) by the alternating direction method of multipliers, split
// so that the only linear system is the graph Laplacian of the mesh, factored once
// (doc/performance.md, "The default solver").
//
// With a_e = su (u_i - u_j) and b_e = sv (v_i - v_j) the QP is
//   min sum_e (l1_e - a_e - b_e)^2  s.t.  a, b >= 0,  (a, b) = (Su D u, Sv D v),  fixed pair,
// with D the edge-vertex incidence matrix. An iteration is
//   - the mesh step: u and v nearest, in least squares, to the edge values: one solve with the
//     Laplacian D'D of the free vertices for both coordinates at once (S^2 = I);
//   - the edge step: per edge, a QP in (a_e, b_e) >= 0 of two variables, in closed form;
//   - the multiplier step.
// The objective decreases about geometrically, so a rule that extrapolates its decrease says
// when to stop, and a certificate (a duality gap, Dual_bound.h) confirms it. Where the decrease
// slows, the exact optimum on the set of constraints the iterations have made active
// (Active_set_polish.h) may end the solve sooner; a tail that does not settle goes to the
// interior point. The result is the last iterate swept onto the feasible set (or the polish's),
// so it satisfies every constraint exactly, with its certified distance to the optimum.
//
// On a TBB build the loops run in blocks that do not depend on the number of threads, and so
// neither does the result.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_SIGN_CONSTRAINED_ADMM_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_SIGN_CONSTRAINED_ADMM_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Interior_point_quadratic_program_traits.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_QP_solver.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Active_set_polish.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Admm_settings.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Dual_bound.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Free_vertex_laplacian.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Parallel_for.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sign_constrained_qp.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sign_feasible_projection.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Two_column_cholesky.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

// What one solve leaves to the next on the same mesh and fixed pair (the sign refinement's
// solves): the factored Laplacian, and the edge values and multipliers of a warm start.
struct Admm_state
{
  Two_column_cholesky cholesky;             // the free-vertex Laplacian, once factored
  bool factored = false;
  std::vector<std::array<double, 2> > z, w; // edge values and scaled multipliers; empty: a cold start
  Edge_signs signs;                         // the signs they belong to
};

// The edge step of one edge: argmin over a, b >= 0 of (l - a - b)^2 + rho/2 ((a - ca)^2 +
// (b - cb)^2), for l >= 0.
inline std::array<double, 2> edge_minimizer(double l, double ca, double cb, double rho)
{
  const double t = 2. * (l - ca - cb) / (rho + 4.);
  if(ca + t >= 0 && cb + t >= 0)
    return {ca + t, cb + t};
  // One of a, b is zero at the optimum: the better of the two one-variable minimizers.
  const double b_only = (std::max)(0., (2. * l + rho * cb) / (2. + rho));
  const double a_only = (std::max)(0., (2. * l + rho * ca) / (2. + rho));
  const double cost_b = (l - b_only) * (l - b_only) + rho / 2. * (ca * ca + (b_only - cb) * (b_only - cb));
  const double cost_a = (l - a_only) * (l - a_only) + rho / 2. * ((a_only - ca) * (a_only - ca) + cb * cb);
  if(cost_b <= cost_a)
    return {0., b_only};
  return {a_only, 0.};
}

// The stopping rule (performance.md, "Stopping rule"): fed the objective of the feasible point
// at successive checks, says when the decrease still to come, extrapolated geometrically from
// the last two decreases, has been at most the tolerance times the objective (or `floor`, if
// larger: an optimum of zero is approached geometrically without end) at two checks in a row,
// or at three once the objective has risen at a check (an objective that is not monotone can
// pause and swing, and a swing's bottom looks settled); and whether the certified gap then
// confirms the stop, the extrapolation being fooled by a pause in the decrease.
class Extrapolated_stop
{
public:
  Extrapolated_stop(double tolerance, double floor, const Admm_settings& settings = Admm_settings())
    : m_tolerance(tolerance), m_floor(floor), m_rise(settings.rise), m_two_check_gap_ratio(settings.two_check_gap_ratio),
      m_confirmed_gap_ratio(settings.confirmed_gap_ratio), m_risen_gap_ratio(settings.risen_gap_ratio)
  { }

  bool settled(double objective)
  {
    const double before = m_older - m_old, last = m_old - objective; // NaN at the first checks
    const double reference = (std::max)(objective, m_floor);
    m_risen = m_risen || last < -m_rise * reference;
    const double allowed = m_tolerance * reference;
    bool small = (last == 0 && before >= 0) || objective <= allowed;
    if(last > 0 && before > last)
    {
      const double ratio = last / before;
      const double remaining = last * ratio / (1. - ratio);
      small = small || remaining <= allowed;
      note_progress(remaining / allowed);
    }
    m_passed = small ? m_passed + 1 : 0;
    m_older = m_old;
    m_old = objective;
    return m_passed >= (m_risen ? 3 : 2);
  }

  // Whether the stop settled() allowed holds, given its certified (relative) gap; a gap that
  // no number of checks confirms forgets the checks passed.
  bool confirmed(double gap)
  {
    if(!(gap <= (m_risen ? m_risen_gap_ratio : m_confirmed_gap_ratio) * m_tolerance))
    {
      m_passed = 0;
      return false;
    }
    return m_passed >= 3 || gap <= m_two_check_gap_ratio * m_tolerance;
  }

  // An estimate of the share of the solve done, in [0, 1], never decreasing: the way from the
  // first extrapolated remainder to the tolerance, on a log scale.
  double fraction() const { return m_fraction; }

private:
  void note_progress(double excess)
  {
    if(!(m_first_excess > 0))
      m_first_excess = excess;
    if(m_first_excess > 1 && excess > 0)
      m_fraction = (std::max)(m_fraction, (std::min)(1., std::log(m_first_excess / excess) / std::log(m_first_excess)));
  }

  double m_tolerance, m_floor;
  double m_rise, m_two_check_gap_ratio, m_confirmed_gap_ratio, m_risen_gap_ratio;
  double m_older = std::numeric_limits<double>::quiet_NaN(), m_old = std::numeric_limits<double>::quiet_NaN();
  int m_passed = 0;
  bool m_risen = false;
  double m_first_excess = 0, m_fraction = 0;
};

// One solve of Eq. 5, phase by phase: set_up(), then iterate() until a check() ends it, then
// finish(). A check may confirm_stop(), polish(), hand the tail to the interior point or
// certify().
class Sign_constrained_admm
{
public:
  // The solve of the QP of `geometry`, `lengths`, `signs` and `fixed` from `uv`, which satisfies
  // its constraints, and which receives the solution. With a `state`, the solve reuses its
  // factorization and starts from its edge values and multipliers when it has them, and leaves
  // them there for the next solve. `order` (default `uv`) gives the values the signs were taken
  // from, whose order (with the tie rule of edge_signs()) is a topological order of the signs.
  // `progress`, if not null, is told the share done at each check and may stop the solve.
  Sign_constrained_admm(const Norm_preserving_geometry& geometry, const std::vector<double>& lengths,
                        const Edge_signs& signs, const std::array<Fixed_vertex, 2>& fixed,
                        const Admm_settings& settings, UV_vector& uv, Admm_state* state = nullptr,
                        const UV_vector* order = nullptr, const std::function<bool(double)>* progress = nullptr)
    : m_geometry(geometry), m_lengths(lengths), m_signs(signs), m_fixed(fixed), m_settings(settings), m_uv(uv),
      m_state(state), m_progress(progress), m_l1_norm(l1_norm(lengths)), m_scale(m_l1_norm * m_l1_norm),
      m_projection(geometry, signs, fixed, order ? *order : uv),
      m_stop(settings.certified ? settings.certified_rule_tolerance : settings.tolerance, gap_floor * m_scale, settings)
  { }

  // Solves, writes the solution to the iterate and fills `report` (status, iterations,
  // residuals, certified gap, timings). False, with the iterate in no particular state, if the
  // Laplacian cannot be factored or `progress` stopped the solve.
  bool solve(Norm_preserving_solve_report& report)
  {
    report = Norm_preserving_solve_report();
    report.has_statistics = true;
    if(!set_up(report))
    {
      report.message = "the graph Laplacian could not be factored";
      return false;
    }
    bool ended = false;
    for(int k = 1; k <= m_settings.max_iterations && !ended; ++k)
    {
      const bool check_now = k % m_settings.check_every == 0 || k == m_settings.max_iterations;
      iterate(check_now);
      if(check_now)
        ended = check(k);
    }
    if(m_interrupted)
    {
      report.interrupted = true;
      report.message = "interrupted";
      return false;
    }
    finish(report);
    return true;
  }

private:
  typedef std::chrono::steady_clock Clock;

  static double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

  // The Euclidean norm of the L1 lengths (at least the smallest double): the residuals' scale.
  static double l1_norm(const std::vector<double>& lengths)
  {
    double sum = 0;
    for(double l : lengths) sum += l * l;
    return (std::max)(std::sqrt(sum), std::numeric_limits<double>::min());
  }

  // ---- Set up: the factored Laplacian, the vertex numbering and the starting iterates.

  bool set_up(Norm_preserving_solve_report& report)
  {
    m_begin = Clock::now();
    const std::size_t n = m_geometry.points.size();
    m_free_index = free_vertex_indices(n, m_fixed);
    m_cholesky = m_state ? &m_state->cholesky : &m_own_cholesky;
    if(!(m_state && m_state->factored))
    {
      Clock::time_point start = Clock::now();
      const Sparse_matrix laplacian = free_vertex_laplacian(m_geometry, m_free_index);
      report.assembly_seconds = seconds_since(start);
      start = Clock::now();
      const bool factored = m_cholesky->compute(laplacian);
      report.factorization_seconds = seconds_since(start);
      if(!factored)
        return false;
      if(m_state)
        m_state->factored = true;
    }
    m_iterations_start = Clock::now();
    number_in_factor_order();
    start_iterates();
    m_polishes_left = m_settings.certified ? m_settings.certified_polish_tries : m_settings.polish_tries;
    if(!m_settings.certified)
    {
      const double first = (std::max)(double(m_settings.polish_first),
                                      m_settings.polish_first_per_work * m_cholesky->factorization_work_per_entry());
      m_next_polish = first < 1e9 ? int(first) : std::numeric_limits<int>::max();
    }
    return true;
  }

  // The mesh step's right-hand side is gathered, solved and read in the factor's order: the row
  // of each free vertex there (-1 at the fixed ones), the edges at each, and the edges with a
  // fixed end, whose wished differences also carry the fixed values to the right-hand side (so
  // that the loop over all edges reads no vertex data).
  void number_in_factor_order()
  {
    const std::size_t n = m_geometry.points.size(), m = m_geometry.edges.size();
    m_row.assign(n, -1);
    for(std::size_t i = 0; i < n; ++i)
      if(m_free_index[i] >= 0)
        m_row[i] = m_cholesky->positions()[std::size_t(m_free_index[i])];
    m_rhs.resize(m_cholesky->solve_size()); // u and v interleaved, then the solve's slots
    m_incidence = free_vertex_edges(m_geometry, m_row);
    m_edge_values.resize(m);
    for(std::size_t e = 0; e < m; ++e)
      if(m_free_index[m_geometry.edges[e][0]] < 0 || m_free_index[m_geometry.edges[e][1]] < 0)
        m_fixed_edges.push_back(e);
    m_block_primal.resize((m + m_settings.edge_block - 1) / m_settings.edge_block);
  }

  // Edge values z from the start point and multipliers w of zero, or those the state keeps for
  // the constraints whose sign it shares (a warm start).
  void start_iterates()
  {
    const std::size_t m = m_geometry.edges.size();
    m_z.resize(m);
    m_w.assign(m, {0., 0.});
    const bool warm = m_state && m_state->z.size() == m && m_state->w.size() == m && m_state->signs.size() == m;
    if(warm)
    {
      m_z.swap(m_state->z);
      m_w.swap(m_state->w);
    }
    for(std::size_t e = 0; e < m; ++e)
      for(int c = 0; c < 2; ++c)
        if(!warm || m_state->signs[e][c] != m_signs[e][c])
        {
          m_z[e][c] = (std::max)(0., sign_constraint_value(m_geometry, m_signs, m_uv, e, c));
          m_w[e][c] = 0.;
        }
  }

  // ---- Iterate: the mesh step, then the over-relaxed edge step and the multiplier step.

  void iterate(bool check_now)
  {
    mesh_step();
    edge_step(check_now);
  }

  // min |D u - Su (a - wa)|^2 and the same for v, the fixed vertices held.
  void mesh_step()
  {
    UV_vector& uv = m_uv;
    parallel_for_each_block(m_geometry.edges.size(), m_settings.edge_block, [&](std::size_t begin, std::size_t end) {
      for(std::size_t e = begin; e < end; ++e)
        for(int c = 0; c < 2; ++c)
          m_edge_values[e][c] = m_signs[e][c] * (m_z[e][c] - m_w[e][c]);
    });
    for(std::size_t e : m_fixed_edges)
      for(int c = 0; c < 2; ++c)
        m_edge_values[e][c] = free_edge_difference(m_free_index, m_geometry.edges[e][0], m_geometry.edges[e][1], c,
                                                   m_edge_values[e][c], uv);
    gather_edge_values(m_incidence, m_edge_values, m_rhs);
    m_cholesky->solve_in_order(m_rhs);
    for(std::size_t i = 0; i < uv.size(); ++i)
      if(m_row[i] >= 0)
        uv[i] = {m_rhs[2 * std::size_t(m_row[i])], m_rhs[2 * std::size_t(m_row[i]) + 1]};
  }

  // Per edge, the new (a, b) from the over-relaxed mesh values, and the multipliers; before a
  // check, also the primal residual and the changes of z (for the dual residual).
  void edge_step(bool check_now)
  {
    const UV_vector& uv = m_uv;
    const double rho = m_settings.penalty, relaxation = m_settings.relaxation;
    const std::size_t block = m_settings.edge_block;
    parallel_for_each_block(m_geometry.edges.size(), block, [&](std::size_t begin, std::size_t end) {
      double primal = 0;
      for(std::size_t e = begin; e < end; ++e)
      {
        std::array<double, 2> ax, h;
        for(int c = 0; c < 2; ++c)
        {
          ax[c] = sign_constraint_value(m_geometry, m_signs, uv, e, c);
          h[c] = relaxation * ax[c] + (1. - relaxation) * m_z[e][c];
        }
        const std::array<double, 2> next = edge_minimizer(m_lengths[e], h[0] + m_w[e][0], h[1] + m_w[e][1], rho);
        for(int c = 0; c < 2; ++c)
        {
          m_w[e][c] += h[c] - next[c];
          if(check_now)
          {
            primal += (ax[c] - next[c]) * (ax[c] - next[c]);
            m_edge_values[e][c] = m_signs[e][c] * (next[c] - m_z[e][c]);
          }
          m_z[e][c] = next[c];
        }
      }
      m_block_primal[begin / block] = primal;
    });
  }

  // ---- Check: the residuals, the feasible point and its objective, then what ends the solve.

  // Whether the solve ends at iteration k (with m_status set).
  bool check(int k)
  {
    measure(k);
    m_settled = m_stop.settled(m_objective) || (m_settled && m_settings.certified);
    if(m_progress && !(*m_progress)(m_stop.fraction()))
    {
      m_interrupted = true;
      return true;
    }
    if(!m_settings.certified && (confirm_stop() || polish_on_slow_tail(k)))
      return end(NORM_PRESERVING_SOLVER_CONVERGED);
    if(hand_to_interior_point(k))
      return true;
    if(m_settled && certify(k))
      return end(NORM_PRESERVING_SOLVER_CONVERGED);
    if(m_polishes_left == 0 && m_kkt_tries >= m_settings.precision_limit_tries)
      return end(NORM_PRESERVING_SOLVER_PRECISION_LIMIT);
    if(seconds_since(m_begin) > m_settings.time_limit)
      return end(NORM_PRESERVING_SOLVER_TIME_LIMIT);
    return false;
  }

  bool end(Norm_preserving_solver_status status)
  {
    m_status = status;
    return true;
  }

  // The residuals of iteration k, and its iterate swept onto the feasible set with its objective.
  void measure(int k)
  {
    const UV_vector& uv = m_uv;
    double primal = 0;
    for(double p : m_block_primal) primal += p;
    gather_edge_values(m_incidence, m_edge_values, m_rhs); // D' times the change of z
    double dual = 0;
    for(std::size_t i = 0; i < uv.size(); ++i) // in vertex order
      if(m_row[i] >= 0)
        for(int c = 0; c < 2; ++c)
        {
          const double change = m_rhs[2 * std::size_t(m_row[i]) + std::size_t(c)];
          dual += change * change;
        }
    m_iterations = k;
    m_primal_residual = std::sqrt(primal) / m_l1_norm;
    m_dual_residual = std::sqrt(dual) / m_l1_norm;
    m_feasible = uv;
    m_projection.apply(m_feasible);
    m_objective = sign_constrained_objective(m_geometry, m_lengths, m_signs, m_feasible);
    m_gap_is_current = false;
  }

  // ---- Confirm: the default mode's stop, once the rule has settled, needs its certificate.

  bool confirm_stop()
  {
    if(!m_settled)
      return false;
    certify_feasible();
    if(m_stop.confirmed(m_gap))
      return true;
    m_settled = false;
    return false;
  }

  // The certified gap of the feasible point, from the multipliers of the iterates.
  void certify_feasible()
  {
    m_gap = relative_gap(m_objective, dual_bound(m_feasible, multipliers()), m_scale);
    m_gap_is_current = true;
  }

  double dual_bound(const UV_vector& point, const std::vector<std::array<double, 2> >& y) const
  {
    return sign_constrained_dual_bound(m_geometry, m_lengths, m_signs, m_row, m_incidence, *m_cholesky, point, y);
  }

  // The multipliers of the constraints a, b >= 0, from the scaled ones.
  std::vector<std::array<double, 2> > multipliers() const
  {
    std::vector<std::array<double, 2> > y(m_w);
    for(auto& v : y)
      for(double& x : v) x *= m_settings.penalty;
    return y;
  }

  // ---- Polish: the exact optimum on the active set of z, corrected a few times.

  // The default mode tries the polish on a slow tail: from its first iteration on, each time the
  // iteration count has doubled, a few times.
  bool polish_on_slow_tail(int k)
  {
    if(k < m_next_polish || m_polishes_left <= 0)
      return false;
    m_next_polish = 2 * k;
    --m_polishes_left;
    return polish();
  }

  // True if a try certifies the tolerance: its point then replaces the feasible point. In the
  // certified mode a try that ends at a KKT point without certifying counts, and keeps its
  // point if its gap is the least so far.
  bool polish()
  {
    const std::size_t m = m_geometry.edges.size();
    Active_set active(m);
    for(std::size_t e = 0; e < m; ++e)
      for(int c = 0; c < 2; ++c)
        active[e][c] = m_z[e][c] == 0.;
    const std::vector<std::array<double, 2> > estimate = multipliers();
    const std::vector<std::size_t> order = elimination_order(m_free_index, m_cholesky->positions());
    Active_set_rounds rounds; // what the last round leaves to the next
    Active_set_corrections corrections;
    UV_vector candidate;
    std::vector<std::array<double, 2> > y;
    for(int round = 0; round < m_settings.polish_rounds; ++round)
    {
      const UV_vector start = round == 0 ? m_uv : candidate; // the last iterate, then the last candidate
      if(!solve_on_active_set(m_geometry, m_lengths, m_signs, m_fixed, order, active, start, rounds, estimate,
                              m_settings, candidate, y))
        return false;
      UV_vector projected = candidate;
      m_projection.apply(projected);
      const double f = sign_constrained_objective(m_geometry, m_lengths, m_signs, projected);
      const double gap = relative_gap(f, dual_bound(projected, y), m_scale);
      if(gap <= m_settings.tolerance)
      {
        m_feasible.swap(projected);
        m_objective = f;
        m_gap = gap;
        m_gap_is_current = true;
        return true;
      }
      if(!corrections.correct(m_geometry, m_lengths, m_signs, candidate, y, m_settings, round, active))
      {
        if(corrections.at_kkt_point() && m_settings.certified)
          keep_kkt_point(projected, gap);
        return false;
      }
    }
    return false;
  }

  void keep_kkt_point(UV_vector& point, double gap)
  {
    ++m_kkt_tries;
    if(gap < m_kkt_gap)
    {
      m_kkt_point.swap(point);
      m_kkt_gap = gap;
    }
  }

  // ---- Fallback: a tail that has not settled goes to the interior point.

  // Whether the solve ends at iteration k with the interior point's point (with m_status set):
  // tried once, from `interior_point_after` iterations on, on a mesh small enough, within the
  // time limit, for a tail that has not settled (in the certified mode also for one whose polish
  // tries are over, short of the precision limit).
  bool hand_to_interior_point(int k)
  {
    const bool tries_failed = m_polishes_left == 0 && m_kkt_tries < m_settings.precision_limit_tries;
    if(k < m_settings.interior_point_after || m_interior_point_tried ||
       m_geometry.points.size() > m_settings.interior_point_max_vertices || !(!m_settled || tries_failed) ||
       seconds_since(m_begin) > m_settings.time_limit)
      return false;
    m_interior_point_tried = true;
    const int kkt_before = m_kkt_tries;
    if(!solve_by_interior_point())
      return false;
    if(!m_settings.certified || m_gap <= m_settings.tolerance)
      return end(NORM_PRESERVING_SOLVER_CONVERGED);
    if(m_kkt_tries > kkt_before) // its polish ended at a KKT point
      return end(NORM_PRESERVING_SOLVER_PRECISION_LIMIT);
    return false;
  }

  // Solves the QP by the interior point, within what is left of the time limit, into the
  // iterate and the feasible point, with z from its constraint values (those at most
  // `interior_point_active_value` active) and y = -2 r; the polish from that active set then
  // tries to certify it. False, with nothing changed, if the interior point fails or runs out
  // of time.
  bool solve_by_interior_point()
  {
    typedef Interior_point_quadratic_program_traits<double> Traits;
    Traits traits;
    traits.set_time_limit(m_settings.time_limit - seconds_since(m_begin));
    UV_vector exact(m_uv);
    Norm_preserving_QP_solver<Traits>::State none;
    Norm_preserving_solve_report report;
    if(!Norm_preserving_QP_solver<Traits>(traits).solve(Norm_preserving_problem{m_geometry, m_lengths, m_signs, m_fixed},
                                                         exact, none, report))
      return false;
    m_uv.swap(exact);
    const UV_vector& uv = m_uv;
    for(std::size_t e = 0; e < m_geometry.edges.size(); ++e)
    {
      const double r = sign_constrained_residual(m_geometry, m_lengths, m_signs, uv, e);
      for(int c = 0; c < 2; ++c)
      {
        const double value = sign_constraint_value(m_geometry, m_signs, uv, e, c);
        m_z[e][c] = value > m_settings.interior_point_active_value ? value : 0.;
        m_w[e][c] = -2. * r / m_settings.penalty;
      }
    }
    m_feasible = uv;
    m_projection.apply(m_feasible);
    m_objective = sign_constrained_objective(m_geometry, m_lengths, m_signs, m_feasible);
    certify_feasible();
    if(m_gap > m_settings.tolerance)
      polish(); // replaces the feasible point and the gap if it certifies
    return true;
  }

  // ---- Certify: the certified mode's certificates, and its polish tries.

  // Every `certify_every` iterations once the rule has stopped: the certified gap, and a polish
  // try at the first certificate after the iteration count has grown by half. True if the
  // tolerance is certified.
  bool certify(int k)
  {
    if(k - m_certified_at < m_settings.certify_every)
      return false;
    m_certified_at = k;
    certify_feasible();
    if(m_gap <= m_settings.tolerance)
      return true;
    if(k < m_next_polish || m_polishes_left <= 0)
      return false;
    m_next_polish = k + k / 2;
    --m_polishes_left;
    return polish();
  }

  // ---- Finish: the feasible point of least certified gap, and the state for the next solve.

  void finish(Norm_preserving_solve_report& report)
  {
    if(m_feasible.empty()) // no iteration ran: the iterate is the feasible start
    {
      m_feasible = m_uv;
      m_objective = sign_constrained_objective(m_geometry, m_lengths, m_signs, m_feasible);
    }
    if(!m_gap_is_current)
      certify_feasible();
    if(m_kkt_gap < m_gap)
    {
      m_feasible.swap(m_kkt_point);
      m_gap = m_kkt_gap;
    }
    m_uv = m_feasible;
    if(m_state)
    {
      m_state->z.swap(m_z);
      m_state->w.swap(m_w);
      m_state->signs = m_signs;
    }
    report.status = m_status;
    report.iterations = m_iterations;
    report.kkt_residual = (std::max)(m_primal_residual, m_dual_residual);
    report.optimality_gap = m_gap;
    report.iteration_seconds = seconds_since(m_iterations_start);
    switch(m_status)
    {
      case NORM_PRESERVING_SOLVER_ITERATION_LIMIT: report.message = "iteration limit reached before the tolerance"; break;
      case NORM_PRESERVING_SOLVER_TIME_LIMIT: report.message = "time limit reached before the tolerance"; break;
      case NORM_PRESERVING_SOLVER_PRECISION_LIMIT:
        report.message = "the certified gap stopped above the tolerance at an optimal point (floating-point precision)";
        break;
      default: break;
    }
  }

  // The problem and how to solve it.
  const Norm_preserving_geometry& m_geometry;
  const std::vector<double>& m_lengths;
  const Edge_signs& m_signs;
  const std::array<Fixed_vertex, 2>& m_fixed;
  const Admm_settings& m_settings;
  UV_vector& m_uv; // the iterate: the start point, then the mesh steps, then the solution
  Admm_state* m_state;
  const std::function<bool(double)>* m_progress;
  const double m_l1_norm, m_scale; // the norm of the lengths, and its square (the zero map's objective)

  // Set up: the factored Laplacian and the vertices and edges in its order.
  Two_column_cholesky m_own_cholesky;
  Two_column_cholesky* m_cholesky = nullptr;
  std::vector<int> m_free_index, m_row;
  Free_vertex_edges m_incidence;
  std::vector<std::size_t> m_fixed_edges;
  Clock::time_point m_begin, m_iterations_start;

  // Iterate: edge values, scaled multipliers, the mesh step's edge values and right-hand side.
  std::vector<std::array<double, 2> > m_z, m_w, m_edge_values;
  std::vector<double> m_rhs, m_block_primal;

  // Check: the last feasible point, its objective and certified gap, the stopping rule.
  Sign_feasible_projection m_projection;
  UV_vector m_feasible;
  double m_objective = 0, m_gap = std::numeric_limits<double>::infinity();
  bool m_gap_is_current = false;
  Extrapolated_stop m_stop;
  bool m_settled = false; // the certified mode: the rule has stopped once
  int m_iterations = 0;
  double m_primal_residual = 0, m_dual_residual = 0;
  Norm_preserving_solver_status m_status = NORM_PRESERVING_SOLVER_ITERATION_LIMIT;
  bool m_interrupted = false;

  // Polish and certify: when the next try may come, how many are left, the last certificate.
  int m_next_polish = 0, m_polishes_left = 0, m_certified_at = 0;
  // The certified mode: the polished point of least gap among those that satisfy the KKT
  // conditions to round-off without certifying the tolerance, and how many tries ended so.
  UV_vector m_kkt_point;
  double m_kkt_gap = std::numeric_limits<double>::infinity();
  int m_kkt_tries = 0;
  bool m_interior_point_tried = false;
};

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
