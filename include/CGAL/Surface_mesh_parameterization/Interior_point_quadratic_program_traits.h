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
/// \file Interior_point_quadratic_program_traits.h
/// \ingroup PkgNormPreservingParameterization
/// An exact interior-point solver, a model of `QuadraticProgramTraits`.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERIOR_POINT_QUADRATIC_PROGRAM_TRAITS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERIOR_POINT_QUADRATIC_PROGRAM_TRAITS_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/disable_warnings.h>

#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Interior_point_solver.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterizationTypes
/// Statistics of the last `Interior_point_quadratic_program_traits::solve()` call.
struct Interior_point_statistics
{
  bool converged = false;     ///< all three residuals met the tolerance
  int iterations = 0;         ///< predictor-corrector iterations
  double primal_residual = 0; ///< max violation of `l <= Ax <= u` (after eliminating fixed variables)
  double dual_residual = 0;   ///< max norm of the Lagrangian gradient `Px + q + A'y`
  double complementarity = 0; ///< mean product of slack and multiplier
  std::string message;        ///< why `solve()` returned `false`, empty on success
};

/// \ingroup PkgNormPreservingParameterizationMethods
/// Sparse primal-dual interior-point solver for convex quadratic programs
/// `min 1/2 x'Px + q'x + r  s.t.  l <= Ax <= u`.
///
/// The exact solver of `Norm_preserving_parameterizer_3` (through `Norm_preserving_QP_solver`),
/// and a replacement for `CGAL::OSQP_quadratic_program_traits` anywhere. It reaches the optimum
/// to a relative tolerance (default 1e-10) on residuals and duality gap; where the optimum is
/// not unique it returns (to tolerance) the analytic centre of the optimal set, a deterministic
/// choice.
///
/// Bounds of magnitude at least 1e30 (and infinities) are absent. A row with `l == u` must have
/// exactly one nonzero coefficient: it fixes that variable, which is then eliminated exactly.
/// `P` must be positive semidefinite; it is given by its upper triangle, as for OSQP.
///
/// \tparam FT a number type convertible to `double`
/// \cgalModels `QuadraticProgramTraits`
template <typename FT = double>
class Interior_point_quadratic_program_traits
{
public:
  /// creates an empty program with the given relative tolerance and iteration limit.
  explicit Interior_point_quadratic_program_traits(double tolerance = 1e-10, int max_iterations = 200)
    : m_tolerance(tolerance), m_max_iterations(max_iterations)
  { }

  /// removes every coefficient.
  void clear()
  {
    m_n = m_m = 0;
    m_P.clear(); m_A.clear(); m_q.clear(); m_l.clear(); m_u.clear();
    m_r = 0;
  }

  /// clears and sets the number of variables `n` and of constraints `m`.
  void resize(std::size_t n, std::size_t m = 0)
  {
    clear();
    m_n = n;
    m_m = m;
  }

  /// sets `P(i,j)` for `j >= i`; entries below the diagonal are ignored (`P` is symmetric).
  void set_P(std::size_t i, std::size_t j, const FT& value)
  {
    if(j < i) return;
    grow_variables(j + 1);
    m_P.emplace_back(i, j, CGAL::to_double(value));
  }
  /// sets `q(i)`.
  void set_q(std::size_t i, const FT& value) { grow_variables(i + 1); m_q[i] = CGAL::to_double(value); }
  /// sets the constant term `r`.
  void set_r(const FT& value) { m_r = CGAL::to_double(value); }
  /// sets `A(i,j)`.
  void set_A(std::size_t i, std::size_t j, const FT& value)
  {
    grow_variables(j + 1);
    grow_constraints(i + 1);
    m_A.emplace_back(i, j, CGAL::to_double(value));
  }
  /// sets the lower bound `l(i)`.
  void set_l(std::size_t i, const FT& value) { grow_constraints(i + 1); m_l[i] = CGAL::to_double(value); }
  /// sets the upper bound `u(i)`.
  void set_u(std::size_t i, const FT& value) { grow_constraints(i + 1); m_u[i] = CGAL::to_double(value); }

  /// solves the program and writes the `n` values of `x` to `solution`.
  /// \returns `false` if the program is malformed or infeasible, or the iteration or time limit was hit;
  ///          `statistics().message` then says why and nothing is written.
  template <typename OutputIterator>
  bool solve(OutputIterator solution)
  {
    m_statistics = Interior_point_statistics();
    std::vector<double> x;
    if(!solve_in_doubles(x))
      return false;
    for(double value : x)
      *solution++ = FT(value);
    return true;
  }

  /// the value of the objective `1/2 x'Px + q'x + r` at the last solution.
  double objective() const { return m_objective; }
  /// statistics of the last `solve()`.
  const Interior_point_statistics& statistics() const { return m_statistics; }
  /// the relative tolerance.
  double tolerance() const { return m_tolerance; }
  /// sets the relative tolerance on residuals and duality gap.
  void set_tolerance(double tolerance) { m_tolerance = tolerance; }
  /// sets the iteration limit.
  void set_max_iterations(int iterations) { m_max_iterations = iterations; }
  /// sets the time limit in seconds of each `solve()` (default: none), checked before each
  /// iteration (the setup and the iteration under way are not cut short); a solve that reaches
  /// it returns `false`. Zero or less stops before the first iteration; infinity, NaN or 1e9
  /// seconds or more mean no limit.
  void set_time_limit(double seconds) { m_time_limit = seconds; }

private:
  using Triplet = std::tuple<std::size_t, std::size_t, double>;

  static bool is_finite_bound(double b) { return std::isfinite(b) && std::abs(b) < 1e30; }

  void grow_variables(std::size_t n)
  {
    m_n = (std::max)(m_n, n);
    if(m_q.size() < m_n) m_q.resize(m_n, 0.);
  }
  void grow_constraints(std::size_t m)
  {
    m_m = (std::max)(m_m, m);
    if(m_l.size() < m_m) m_l.resize(m_m, -std::numeric_limits<double>::infinity());
    if(m_u.size() < m_m) m_u.resize(m_m, std::numeric_limits<double>::infinity());
  }

  bool fail(const std::string& message)
  {
    m_statistics.message = message;
    return false;
  }

  bool solve_in_doubles(std::vector<double>& x)
  {
    using namespace internal::Norm_preserving;
    typedef std::chrono::steady_clock Clock;
    const std::chrono::duration<double> limit((std::max)(m_time_limit, 0.));
    const Clock::time_point deadline = m_time_limit < 1e9 // beyond (or NaN): none, and no overflow
      ? Clock::now() + std::chrono::duration_cast<Clock::duration>(limit)
      : Clock::time_point::max();
    grow_variables(m_n);
    grow_constraints(m_m);
    const int n = static_cast<int>(m_n), m = static_cast<int>(m_m);

    std::vector<Eigen::Triplet<double> > a_triplets;
    for(const Triplet& t : m_A)
      a_triplets.emplace_back(int(std::get<0>(t)), int(std::get<1>(t)), std::get<2>(t));
    Row_sparse_matrix A(m, n);
    A.setFromTriplets(a_triplets.begin(), a_triplets.end());

    // Rows with l == u and one nonzero fix a variable.
    std::vector<bool> is_fixed(n, false), is_fixing_row(m, false);
    x.assign(n, 0.);
    for(int i = 0; i < m; ++i)
    {
      if(!(is_finite_bound(m_l[i]) && m_l[i] == m_u[i]))
        continue;
      if(A.row(i).nonZeros() != 1 || Row_sparse_matrix::InnerIterator(A, i).value() == 0.)
        return fail("equality row " + std::to_string(i) + " must have exactly one nonzero coefficient");
      Row_sparse_matrix::InnerIterator it(A, i);
      const double value = m_l[i] / it.value();
      if(is_fixed[it.col()] && x[it.col()] != value)
        return fail("variable " + std::to_string(it.col()) + " is fixed to two different values");
      is_fixed[it.col()] = true;
      is_fixing_row[i] = true;
      x[it.col()] = value;
    }
    std::vector<int> free_index(n, -1);
    int n_free = 0;
    for(int j = 0; j < n; ++j)
      if(!is_fixed[j]) free_index[j] = n_free++;
    const Eigen::Map<const Eigen::VectorXd> x_all(x.data(), n);

    // Reduced objective over the free variables.
    std::vector<Eigen::Triplet<double> > p_triplets;
    Inequality_qp qp;
    qp.q = Eigen::VectorXd::Zero(n_free);
    for(int j = 0; j < n; ++j)
      if(!is_fixed[j]) qp.q[free_index[j]] = m_q[j];
    for(const Triplet& t : m_P)
    {
      const int i = int(std::get<0>(t)), j = int(std::get<1>(t));
      const double v = std::get<2>(t);
      const int fi = free_index[i], fj = free_index[j];
      if(fi >= 0 && fj >= 0)
      {
        p_triplets.emplace_back(fi, fj, v);
        if(i != j) p_triplets.emplace_back(fj, fi, v);
      }
      else if(fi >= 0) qp.q[fi] += v * x_all[j];
      else if(fj >= 0) qp.q[fj] += v * x_all[i];
    }
    qp.P.resize(n_free, n_free);
    qp.P.setFromTriplets(p_triplets.begin(), p_triplets.end());

    // Inequalities G x <= h from the finite sides of the remaining rows.
    std::vector<Eigen::Triplet<double> > g_triplets;
    std::vector<double> h;
    const double feasibility_slack = m_tolerance * (1. + bound_scale());
    for(int i = 0; i < m; ++i)
    {
      if(is_fixing_row[i]) continue;
      double constant = 0;
      bool has_free = false;
      for(Row_sparse_matrix::InnerIterator it(A, i); it; ++it)
      {
        if(is_fixed[it.col()]) constant += it.value() * x_all[it.col()];
        else has_free = has_free || it.value() != 0.;
      }
      for(int side = 0; side < 2; ++side)
      {
        const double bound = side == 0 ? m_u[i] : m_l[i];
        if(!is_finite_bound(bound)) continue;
        const double sign = side == 0 ? 1. : -1.;
        if(!has_free)
        {
          if(sign * (constant - bound) > feasibility_slack)
            return fail("row " + std::to_string(i) + " is violated by the fixed variables");
          continue;
        }
        const int row = int(h.size());
        for(Row_sparse_matrix::InnerIterator it(A, i); it; ++it)
          if(!is_fixed[it.col()])
            g_triplets.emplace_back(row, free_index[it.col()], sign * it.value());
        h.push_back(sign * (bound - constant));
      }
    }
    qp.G.resize(int(h.size()), n_free);
    qp.G.setFromTriplets(g_triplets.begin(), g_triplets.end());
    qp.h = Eigen::Map<Eigen::VectorXd>(h.data(), Eigen::Index(h.size()));

    const Interior_point_result result = solve_inequality_qp(qp, m_tolerance, m_max_iterations, deadline);
    m_statistics.converged = result.converged;
    m_statistics.iterations = result.iterations;
    m_statistics.primal_residual = result.primal_residual;
    m_statistics.dual_residual = result.dual_residual;
    m_statistics.complementarity = result.complementarity;
    if(result.factorization_failed)
      return fail("the normal matrix could not be factored");
    if(result.time_limit_reached)
      return fail("time limit reached after " + std::to_string(result.iterations) + " iterations");
    if(!result.converged)
      return fail("no convergence within " + std::to_string(m_max_iterations) + " iterations");

    for(int j = 0; j < n; ++j)
      if(!is_fixed[j]) x[j] = result.x[free_index[j]];
    m_objective = m_r;
    for(const Triplet& t : m_P)
    {
      const std::size_t i = std::get<0>(t), j = std::get<1>(t);
      m_objective += (i == j ? 0.5 : 1.) * std::get<2>(t) * x[i] * x[j];
    }
    for(int j = 0; j < n; ++j)
      m_objective += m_q[j] * x[j];
    return true;
  }

  double bound_scale() const
  {
    double scale = 0;
    for(std::size_t i = 0; i < m_m; ++i)
    {
      if(is_finite_bound(m_l[i])) scale = (std::max)(scale, std::abs(m_l[i]));
      if(is_finite_bound(m_u[i])) scale = (std::max)(scale, std::abs(m_u[i]));
    }
    return scale;
  }

  double m_tolerance;
  int m_max_iterations;
  double m_time_limit = std::numeric_limits<double>::infinity();
  std::size_t m_n = 0, m_m = 0;
  std::vector<Triplet> m_P, m_A;
  std::vector<double> m_q, m_l, m_u;
  double m_r = 0;
  double m_objective = 0;
  Interior_point_statistics m_statistics;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif
