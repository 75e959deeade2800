// Copyright (c) 2026 The CGAL_norm_preserving_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sign-constrained QP (Eq. 5) by the alternating direction method of multipliers, split
// so that the only linear system is the graph Laplacian of the mesh, factored once.
//
// With a_e = su (u_i - u_j) and b_e = sv (v_i - v_j) the QP is
//   min sum_e (l1_e - a_e - b_e)^2  s.t.  a, b >= 0,  (a, b) = (Su D u, Sv D v),  fixed pair,
// with D the edge-vertex incidence matrix. ADMM alternates
//   - the mesh step: u and v nearest (in least squares) to the edge values, the Laplacian
//     D'D of the free vertices solved for both coordinates at once (S^2 = I);
//   - the edge step: per edge, a two-variable QP in (a_e, b_e) >= 0, solved in closed form;
//   - the multiplier step.
// The penalty rho = 1.5 is near the curvature 2 of the objective in edge units (the geometry
// is normalized to a mean L1 edge length of 1), with over-relaxation 1.9 (the measurements
// behind both: doc/performance.md, change 3). Every 5 iterations the mesh step is mapped onto
// the feasible set by Sign_feasible_projection and its objective f recorded. The decrease of f
// is close to geometric: the rule stops when the decrease still to come, extrapolated from the
// last two decreases (d2 r / (1 - r), r = d2 / d1), is at most the tolerance times f (or the
// gap's floor, Dual_bound.h, near a zero optimum) at two checks in a row (doc/performance.md,
// change 7; doc/decisions.md), and the certified gap then confirms it: at most
// `two_check_gap_ratio` times the tolerance, or `confirmed_gap_ratio` at three checks in a row
// (changes 27, 28 and 30); once f has risen at a check, three checks and `risen_gap_ratio`
// (change 29). On a slow tail the default
// mode tries the polish described below as well: from iteration 150 (later on a mesh whose
// factorization costs more per entry of its factor), then each time the iteration count has
// doubled, three times at most; a try that certifies the tolerance ends the solve
// (doc/performance.md, change 15). A tail that has not settled by iteration 1,000 (dense tubes
// seen end-on by the guess crept to the iteration limit) is handed to the interior point on a
// mesh of up to 200,000 vertices, within the time limit, and the polish then tries to certify
// its point (doc/performance.md, change 24); in the certified mode also a tail whose polish
// tries below are over by then, short of the precision limit (change 27). The returned point is
// the last feasible one (or the polish's), so it satisfies every constraint exactly, and its
// distance to the optimum is certified by a dual bound from the multipliers (Dual_bound.h).
// In the certified mode the solve goes on until that certificate itself is at most the
// tolerance: from the point where the default rule would stop, the bound is computed every 25
// iterations, and the exact optimum on the active set ADMM has found (Active_set_polish.h,
// whose multipliers make the bound tight) is tried then, and again at the first certificate
// after the iteration count has grown by half, five times at most (doc/performance.md, change
// 23): each try corrects the active set up to 24 times (one factorization each), turning only
// constraints violated, or of negative multiplier, beyond round-off, and fewer at a time once
// the corrections stop shrinking: it settles at the default's stopping point on 34 of the 35
// benchmark meshes of up to 50,000 vertices, and on cow x3 (doc/performance.md, changes 8 and
// 9). A try that ends at a KKT point (no constraint left to turn) whose gap, limited by the
// bound's rounding on a tiny optimum, stays above the tolerance is kept: when the tries are
// over and two of them ended so, or when the interior point's polish did, the solve ends at
// the point of least gap (a precision limit; change 27).
//
// Built with TBB, an iteration uses every core: the solve is split by Two_column_cholesky, the
// edge loops run in blocks of edges, the right-hand side is gathered per free vertex
// (Free_vertex_edges); the blocks do not depend on the number of threads, nor the result.
//
// Sign refinement re-solves with other signs on the same mesh and fixed pair: it passes an
// Admm_state, which keeps the factored Laplacian and the last edge values and multipliers
// (a warm start), and the order of the new signs (the vertex values they were taken from).
// Without a state the solve is the cold one above, unchanged.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_SIGN_CONSTRAINED_ADMM_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_SIGN_CONSTRAINED_ADMM_H

#include <CGAL/Surface_mesh_parameterization/Interior_point_quadratic_program_traits.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_QP_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Active_set_polish.h>
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
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

constexpr double admm_default_tolerance = 2.5e-5; // of Norm_preserving_ADMM_solver
// The active-set polish of the certified mode turns a constraint only when it is violated, or
// its multiplier negative, by more than `polish_turn_tolerance` (in units of the mean L1 edge
// length), and corrects the active set at most `polish_rounds` times a try. When a round
// wants more than `polish_shrink` times the turns the round before wanted, the turns a round
// are limited to half of those, the most wrong first; a try ends when a round wants more than
// `polish_growth_limit` times the fewest turns wanted so far plus `polish_growth_slack`
// (doc/performance.md, changes 9 and 18).
// The default mode tries the polish too, on a slow tail: from iteration
// `polish_default_minimum`, or later on a mesh whose factorization costs more per entry of the
// factor (a polish round factors a system of about twice the Laplacian's unknowns: about
// `polish_default_factor` times the factor's work per entry in iterations for the rounds of a
// try), then each time the iteration count has doubled (doc/performance.md, change 15), three
// times at most. The certified mode tries again each time the iteration count has grown by
// half, five times at most (doc/performance.md, change 23).
constexpr int polish_default_minimum = 150;
constexpr double polish_default_factor = 5;
constexpr int polish_default_tries = 3, polish_certified_tries = 5;
// A tail that has not settled by iteration `interior_point_after` (in the certified mode also
// one whose polish tries are over by then, short of the precision limit) is handed to the
// interior point, on a mesh of at most `interior_point_max_vertices` vertices (it needs about
// 6 KB a vertex), whose point is then polished on the constraints of value at most
// `interior_point_active_value` (doc/performance.md, changes 24 and 27).
constexpr int interior_point_after = 1000;
constexpr std::size_t interior_point_max_vertices = 200000;
constexpr double interior_point_active_value = 1e-6;
// The default mode's stop needs its certified gap at most `confirmed_gap_ratio` times the
// tolerance, a net for gross errors: a larger gap may mean the extrapolation was fooled (a fast
// first drop, then a slow tail; a pause in the decrease), and the iterations go on. The bound
// is loose, so right and wrong stops overlap in the ratio (on the benchmark meshes right stops
// reach 100 times, on CGAL's collection 180; wrong ones start at 60: doc/performance.md,
// changes 27 and 28). In that overlap, above `two_check_gap_ratio` times, the stop needs a
// third check in a row (a pause of two checks fooled the rule there: change 30; the wrong
// stops seen at 60 times and below had a rise before them). Once the objective has risen at a
// check, it needs three checks and at most `risen_gap_ratio` times the tolerance: of the 8
// traced components of more than 50 vertices the rule stopped after a rise, 4 were more than
// 1e-4 above their optimum (change 29).
constexpr double confirmed_gap_ratio = 150, two_check_gap_ratio = 60, risen_gap_ratio = 75;
// The certified mode ends at the precision limit, at its KKT point of least gap, when its
// tries are over and at least `precision_limit_tries` of them ended at a KKT point (later
// iterates led to it again), or when the interior point's polish ended at one (change 27).
constexpr int precision_limit_tries = 2;
constexpr double polish_turn_tolerance = 1e-9;
constexpr int polish_rounds = 24;
constexpr double polish_shrink = 0.7;
constexpr std::size_t polish_growth_limit = 2, polish_growth_slack = 16;

struct Admm_settings
{
  double tolerance;  // on the extrapolated relative error, or on the certified gap
  int max_iterations;
  double time_limit; // seconds
  bool certified;    // stop on the certified gap, not on the extrapolation
};

enum class Admm_outcome { CONVERGED, ITERATION_LIMIT, TIME_LIMIT, PRECISION_LIMIT, FACTORIZATION_FAILED };

struct Admm_result
{
  Admm_outcome outcome = Admm_outcome::FACTORIZATION_FAILED;
  int iterations = 0;
  double primal_residual = 0; // |Ax - z| / |l1|
  double dual_residual = 0;   // |A'(z - z_prev)| / |l1|, over the free vertices
  double gap = std::numeric_limits<double>::infinity(); // certified bound on (f - f*) / f* at the result
  double assembly_seconds = 0, factorization_seconds = 0, iteration_seconds = 0;
};

// What one solve leaves to the next on the same mesh and fixed pair.
struct Admm_state
{
  Two_column_cholesky cholesky;                // the free-vertex Laplacian, once factored
  bool factored = false;
  std::vector<std::array<double, 2> > z, w;    // edge values and scaled multipliers; empty: cold start
  Edge_signs signs;                            // the signs they belong to
};

// argmin over a, b >= 0 of (l - a - b)^2 + rho/2 ((a - ca)^2 + (b - cb)^2), for l >= 0.
inline std::array<double, 2> edge_step(double l, double ca, double cb, double rho)
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

// The stopping rule: fed the objective of the feasible point at successive checks, says when
// the decrease still to come, extrapolated geometrically from the last two decreases, has
// been at most `tolerance` times the objective (or `floor`, if larger: an optimum of zero is
// approached geometrically without end) at two checks in a row, or at three once the
// objective has risen at a check (an objective that is not monotone can pause and swing,
// and a swing's bottom looks settled: doc/performance.md, change 29); and whether the
// certified gap then confirms the stop (the ratios above).
class Extrapolated_stop
{
public:
  Extrapolated_stop(double tolerance, double floor) : m_tolerance(tolerance), m_floor(floor) { }

  bool settled(double objective)
  {
    const double before = m_older - m_old, last = m_old - objective; // NaN at the first checks
    const double reference = (std::max)(objective, m_floor);
    // a rise beyond round-off (those that fooled the rule were 5e-6 of the objective and more)
    m_risen = m_risen || last < -1e-9 * reference;
    const double allowed = m_tolerance * reference;
    bool small = (last == 0 && before >= 0) || objective <= allowed;
    if(last > 0 && before > last)
    {
      const double ratio = last / before;
      small = small || last * ratio / (1. - ratio) <= allowed;
    }
    m_passed = small ? m_passed + 1 : 0;
    m_older = m_old;
    m_old = objective;
    return m_passed >= (m_risen ? 3 : 2);
  }

  // whether the stop settled() allowed holds, given its certified (relative) gap; a gap that
  // no number of checks confirms forgets the checks passed.
  bool confirmed(double gap)
  {
    if(!(gap <= (m_risen ? risen_gap_ratio : confirmed_gap_ratio) * m_tolerance))
    {
      m_passed = 0;
      return false;
    }
    return m_passed >= 3 || gap <= two_check_gap_ratio * m_tolerance;
  }

private:
  double m_tolerance, m_floor;
  double m_older = std::numeric_limits<double>::quiet_NaN(), m_old = std::numeric_limits<double>::quiet_NaN();
  int m_passed = 0;
  bool m_risen = false;
};

// Solves Eq. 5 from `uv` (the transformed guess, which satisfies the constraints) and
// writes the solution to `uv`. With a `state`, reuses its factorization and starts from its
// edge values and multipliers when it has them, and leaves them there for the next solve;
// `order` (default `uv`) gives the values the signs were taken from, whose order (with the
// tie rule of edge_signs()) is a topological order of the signs.
inline Admm_result solve_sign_constrained_admm(const Norm_preserving_geometry& geometry,
                                               const std::vector<double>& lengths, const Edge_signs& signs,
                                               const std::array<Fixed_vertex, 2>& fixed,
                                               const Admm_settings& settings, UV_vector& uv,
                                               Admm_state* state = nullptr, const UV_vector* order = nullptr)
{
  typedef std::chrono::steady_clock Clock;
  auto seconds_since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  const Clock::time_point begin = Clock::now();
  Clock::time_point start = begin;
  const double rho = 1.5, relaxation = 1.9;
  const int check_every = 5, certify_every = 25;
  const std::size_t n = geometry.points.size(), m = geometry.edges.size();
  Admm_result result;
  const Sign_feasible_projection projection(geometry, signs, fixed, order ? *order : uv); // ordered by the guess

  // Free vertices and the Laplacian D'D among them.
  const std::vector<int> free_index = free_vertex_indices(n, fixed);
  Two_column_cholesky local_cholesky;
  Two_column_cholesky& cholesky = state ? state->cholesky : local_cholesky;
  if(!state || !state->factored)
  {
    const Sparse_matrix laplacian = free_vertex_laplacian(geometry, free_index);
    result.assembly_seconds = seconds_since(start);
    start = Clock::now();
    const bool factored = cholesky.compute(laplacian);
    result.factorization_seconds = seconds_since(start);
    if(!factored)
      return result;
    if(state)
      state->factored = true;
  }
  start = Clock::now();

  // Edge values z = (a, b), scaled multipliers w, from the guess (or the state).
  std::vector<std::array<double, 2> > z(m), w(m, {0., 0.});
  auto edge_value = [&](std::size_t e, int c) { return sign_constraint_value(geometry, signs, uv, e, c); };
  const bool warm = state && state->z.size() == m && state->w.size() == m && state->signs.size() == m;
  if(warm)
  {
    z.swap(state->z);
    w.swap(state->w);
  }
  for(std::size_t e = 0; e < m; ++e) // cold, or a turned sign: start over from the point
    for(int c = 0; c < 2; ++c)
      if(!warm || state->signs[e][c] != signs[e][c])
      {
        z[e][c] = (std::max)(0., edge_value(e, c));
        w[e][c] = 0.;
      }
  double l1_norm = 0;
  for(double l : lengths) l1_norm += l * l;
  l1_norm = (std::max)(std::sqrt(l1_norm), std::numeric_limits<double>::min());

  // The mesh step's right-hand side is gathered, solved and read in the factor's order: the
  // row of each free vertex there (-1 at the fixed ones).
  std::vector<int> row(n, -1);
  for(std::size_t i = 0; i < n; ++i)
    if(free_index[i] >= 0)
      row[i] = cholesky.positions()[std::size_t(free_index[i])];
  std::vector<double> rhs(cholesky.solve_size()); // u and v interleaved, then the solve's slots
  const Free_vertex_edges incidence = free_vertex_edges(geometry, row);
  std::vector<std::array<double, 2> > edge_values(m); // wished differences, then changes of z
  // The edges with a fixed end, whose wished differences also carry the fixed values to the
  // right-hand side (the mesh step's loop over all edges then reads no vertex data).
  std::vector<std::size_t> fixed_edges;
  for(std::size_t e = 0; e < m; ++e)
    if(free_index[geometry.edges[e][0]] < 0 || free_index[geometry.edges[e][1]] < 0)
      fixed_edges.push_back(e);
  // Edges a block: from about 1,000 vertices on, the loops run on all cores (doc/performance.md,
  // change 12).
  const std::size_t block = 1024;
  std::vector<double> block_primal((m + block - 1) / block);
  UV_vector feasible;          // the last iterate swept onto the feasible set
  double objective = 0;        // its objective
  const double scale = l1_norm * l1_norm;
  Extrapolated_stop stop(settings.certified ? admm_default_tolerance : settings.tolerance, gap_floor * scale);
  bool settled = false;        // the certified mode: the rule has stopped once
  int certified_at = 0;        // the iteration of the last certificate
  // The iteration of the next polish (the default mode's first: a slow tail), and how many more
  // may be tried.
  int next_polish = 0;
  int polishes_left = settings.certified ? polish_certified_tries : polish_default_tries;
  if(!settings.certified)
  {
    const double first =
      (std::max)(double(polish_default_minimum), polish_default_factor * cholesky.factorization_work_per_entry());
    next_polish = first < 1e9 ? int(first) : std::numeric_limits<int>::max();
  }
  bool gap_is_current = false; // result.gap is that of `feasible`
  // The certified mode: the polished point of least gap among those that satisfy the KKT
  // conditions to round-off (no constraint to turn) without certifying the tolerance, and how
  // many polish tries ended at such a point.
  UV_vector kkt_point;
  double kkt_gap = std::numeric_limits<double>::infinity();
  int kkt_tries = 0;
  auto multipliers = [&]() { // of the constraints a, b >= 0, from the scaled ones
    std::vector<std::array<double, 2> > y(w);
    for(auto& v : y)
      for(double& x : v) x *= rho;
    return y;
  };
  auto dual_bound = [&]() {
    return sign_constrained_dual_bound(geometry, lengths, signs, row, incidence, cholesky, feasible, multipliers());
  };
  // The optimum on the active set of z, corrected a few times; true if certified within the
  // tolerance, then it replaces `feasible`. In the certified mode a try that ends at a KKT
  // point without certifying counts, and keeps the point if its gap is the least so far.
  auto polish = [&]() {
    Active_set active(m);
    for(std::size_t e = 0; e < m; ++e)
      for(int c = 0; c < 2; ++c)
        active[e][c] = z[e][c] == 0.;
    UV_vector candidate;
    std::vector<std::array<double, 2> > y;
    const std::vector<std::array<double, 2> > estimate = multipliers();
    const std::vector<std::size_t> order = elimination_order(free_index, cholesky.positions());
    Active_set_rounds rounds; // what the last round leaves to the next
    std::vector<std::pair<double, std::size_t> > wrong; // (minus how wrong, 2 e + c)
    std::size_t wanted = 0, fewest = std::numeric_limits<std::size_t>::max(),
                limit = std::numeric_limits<std::size_t>::max(); // turns a round
    for(int round = 0; round < polish_rounds; ++round)
    {
      const UV_vector start = round == 0 ? uv : candidate; // the last ADMM iterate, then the last candidate
      if(!solve_on_active_set(geometry, lengths, signs, fixed, order, active, start, rounds, estimate, candidate, y))
        return false;
      UV_vector projected = candidate;
      projection.apply(projected);
      const double f = sign_constrained_objective(geometry, lengths, signs, projected);
      const double gap =
        relative_gap(f, sign_constrained_dual_bound(geometry, lengths, signs, row, incidence, cholesky, projected, y), scale);
      if(gap <= settings.tolerance)
      {
        feasible.swap(projected);
        objective = f;
        result.gap = gap;
        gap_is_current = true;
        return true;
      }
      // Violated constraints join the active set, negative multipliers leave it; both beyond
      // round-off, or degenerate constraints (zero value and multiplier at the optimum) turn
      // back and forth every round. Once the corrections stop shrinking, only the most wrong
      // turn; a try whose corrections grow is abandoned.
      wrong.clear();
      for(std::size_t e = 0; e < m; ++e)
      {
        const double r = sign_constrained_residual(geometry, lengths, signs, candidate, e);
        for(int c = 0; c < 2; ++c)
        {
          const double amount = active[e][c] ? 2. * r + y[e][c] : -sign_constraint_value(geometry, signs, candidate, e, c);
          if(amount > polish_turn_tolerance)
            wrong.emplace_back(-amount, 2 * e + std::size_t(c));
        }
      }
      if(wrong.empty() && settings.certified)
      {
        ++kkt_tries;
        if(gap < kkt_gap)
        {
          kkt_point.swap(projected);
          kkt_gap = gap;
        }
      }
      fewest = (std::min)(fewest, wrong.size());
      if(wrong.empty() || wrong.size() > polish_growth_limit * fewest + polish_growth_slack)
        return false;
      if(round > 0 && double(wrong.size()) > polish_shrink * double(wanted))
        limit = (std::max)(std::size_t(1), (std::min)(limit, wanted / 2));
      wanted = wrong.size();
      if(wanted > limit)
      {
        std::sort(wrong.begin(), wrong.end()); // the most wrong first, then by index
        wrong.resize(limit);
      }
      for(const auto& turn : wrong)
        active[turn.second / 2][turn.second % 2] ^= 1;
    }
    return false;
  };
  // Solves the QP by the interior point, within what is left of the time limit, into `uv` and
  // `feasible`, with z from its constraint values (those at most `interior_point_active_value`
  // active) and y = -2 r; the polish from that active set then tries to certify it. False,
  // with nothing changed, if the interior point fails or runs out of time.
  auto interior_point = [&]() {
    typedef Interior_point_quadratic_program_traits<double> Traits;
    typedef Norm_preserving_QP_solver<Traits> Exact_solver;
    Traits traits;
    traits.set_time_limit(settings.time_limit - seconds_since(begin));
    UV_vector exact(uv);
    Exact_solver::State none;
    Norm_preserving_solve_report report;
    if(!Exact_solver(traits).solve(Norm_preserving_problem{geometry, lengths, signs, fixed}, exact, none, report))
      return false;
    uv.swap(exact);
    for(std::size_t e = 0; e < m; ++e)
    {
      const double r = sign_constrained_residual(geometry, lengths, signs, uv, e);
      for(int c = 0; c < 2; ++c)
      {
        const double value = edge_value(e, c);
        z[e][c] = value > interior_point_active_value ? value : 0.;
        w[e][c] = -2. * r / rho;
      }
    }
    feasible = uv;
    projection.apply(feasible);
    objective = sign_constrained_objective(geometry, lengths, signs, feasible);
    result.gap = relative_gap(objective, dual_bound(), scale);
    gap_is_current = true;
    if(result.gap > settings.tolerance)
      polish(); // replaces `feasible` and the gap if it certifies
    return true;
  };
  bool interior_point_tried = false;
  result.outcome = Admm_outcome::ITERATION_LIMIT;
  for(int k = 1; k <= settings.max_iterations; ++k)
  {
    // Mesh step: min |D u - Su (a - wa)|^2 and the same for v, fixed vertices held.
    parallel_for_each_block(m, block, [&](std::size_t begin, std::size_t end) {
      for(std::size_t e = begin; e < end; ++e)
        for(int c = 0; c < 2; ++c)
          edge_values[e][c] = signs[e][c] * (z[e][c] - w[e][c]);
    });
    for(std::size_t e : fixed_edges)
      for(int c = 0; c < 2; ++c)
        edge_values[e][c] = free_edge_difference(free_index, geometry.edges[e][0], geometry.edges[e][1], c, edge_values[e][c], uv);
    gather_edge_values(incidence, edge_values, rhs);
    cholesky.solve_in_order(rhs);
    for(std::size_t i = 0; i < n; ++i)
      if(row[i] >= 0)
        uv[i] = {rhs[2 * std::size_t(row[i])], rhs[2 * std::size_t(row[i]) + 1]};

    // Edge step (over-relaxed) and multiplier step; at a check, the changes of z kept.
    const bool check = k % check_every == 0 || k == settings.max_iterations;
    parallel_for_each_block(m, block, [&](std::size_t begin, std::size_t end) {
      double primal = 0;
      for(std::size_t e = begin; e < end; ++e)
      {
        std::array<double, 2> ax, h;
        for(int c = 0; c < 2; ++c)
        {
          ax[c] = edge_value(e, c);
          h[c] = relaxation * ax[c] + (1. - relaxation) * z[e][c];
        }
        const std::array<double, 2> next = edge_step(lengths[e], h[0] + w[e][0], h[1] + w[e][1], rho);
        for(int c = 0; c < 2; ++c)
        {
          w[e][c] += h[c] - next[c];
          if(check)
          {
            primal += (ax[c] - next[c]) * (ax[c] - next[c]);
            edge_values[e][c] = signs[e][c] * (next[c] - z[e][c]);
          }
          z[e][c] = next[c];
        }
      }
      block_primal[begin / block] = primal;
    });
    if(!check)
      continue;
    double primal = 0;
    for(double p : block_primal) primal += p;
    gather_edge_values(incidence, edge_values, rhs); // D' times the change of z
    double dual = 0;
    for(std::size_t i = 0; i < n; ++i) // in vertex order
      if(row[i] >= 0)
        for(int c = 0; c < 2; ++c)
        {
          const double change = rhs[2 * std::size_t(row[i]) + std::size_t(c)];
          dual += change * change;
        }
    result.iterations = k;
    result.primal_residual = std::sqrt(primal) / l1_norm;
    result.dual_residual = std::sqrt(dual) / l1_norm;
    feasible = uv;
    projection.apply(feasible);
    objective = sign_constrained_objective(geometry, lengths, signs, feasible);
    gap_is_current = false;
    settled = stop.settled(objective) || (settled && settings.certified);
    if(settled && !settings.certified)
    {
      result.gap = relative_gap(objective, dual_bound(), scale);
      gap_is_current = true;
      if(stop.confirmed(result.gap))
      {
        result.outcome = Admm_outcome::CONVERGED;
        break;
      }
      settled = false;
    }
    if(!settings.certified && k >= next_polish && polishes_left > 0)
    {
      next_polish = 2 * k;
      --polishes_left;
      if(polish())
      {
        result.outcome = Admm_outcome::CONVERGED;
        break;
      }
    }
    // (the certified mode's tries over, short of the precision limit)
    const bool tries_failed = polishes_left == 0 && kkt_tries < precision_limit_tries;
    if(k >= interior_point_after && !interior_point_tried && n <= interior_point_max_vertices &&
       (!settled || tries_failed) && seconds_since(begin) <= settings.time_limit)
    {
      interior_point_tried = true;
      const int kkt_before = kkt_tries;
      if(interior_point())
      {
        if(!settings.certified || result.gap <= settings.tolerance)
        {
          result.outcome = Admm_outcome::CONVERGED;
          break;
        }
        if(kkt_tries > kkt_before) // its polish ended at a KKT point
        {
          result.outcome = Admm_outcome::PRECISION_LIMIT;
          break;
        }
      }
    }
    if(settled && k - certified_at >= certify_every)
    {
      certified_at = k;
      result.gap = relative_gap(objective, dual_bound(), scale);
      gap_is_current = true;
      bool certified = result.gap <= settings.tolerance;
      if(!certified && k >= next_polish && polishes_left > 0)
      {
        next_polish = k + k / 2;
        --polishes_left;
        certified = polish();
      }
      if(certified)
      {
        result.outcome = Admm_outcome::CONVERGED;
        break;
      }
    }
    if(polishes_left == 0 && kkt_tries >= precision_limit_tries)
    {
      result.outcome = Admm_outcome::PRECISION_LIMIT;
      break;
    }
    if(seconds_since(begin) > settings.time_limit)
    {
      result.outcome = Admm_outcome::TIME_LIMIT;
      break;
    }
  }
  if(feasible.empty()) // no iteration ran: `uv` is the feasible guess
  {
    feasible = uv;
    objective = sign_constrained_objective(geometry, lengths, signs, feasible);
  }
  if(!gap_is_current)
    result.gap = relative_gap(objective, dual_bound(), scale);
  if(kkt_gap < result.gap)
  {
    feasible.swap(kkt_point);
    result.gap = kkt_gap;
  }
  uv = feasible;
  if(state)
  {
    state->z.swap(z);
    state->w.swap(w);
    state->signs = signs;
  }
  result.iteration_seconds = seconds_since(start);
  return result;
}

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
