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
/// \file Norm_preserving_QP_solver.h
/// \ingroup PkgNormPreservingParameterization
/// The sign-constrained QP solved by any model of `QuadraticProgramTraits`.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_QP_SOLVER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_QP_SOLVER_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/disable_warnings.h>

#include <CGAL/Surface_mesh_parameterization/Norm_preserving_concepts.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sign_constrained_qp.h>

#include <boost/concept/assert.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iterator>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \cond SKIP_IN_MANUAL
namespace internal {
namespace Norm_preserving {

template <typename T, typename = void>
struct Has_statistics : std::false_type { };
template <typename T>
struct Has_statistics<T, std::void_t<decltype(std::declval<const T&>().statistics())> > : std::true_type { };

} // namespace Norm_preserving
} // namespace internal
/// \endcond

/// \ingroup PkgNormPreservingParameterizationMethods
/// Solves the sign-constrained QP with any model of CGAL's `QuadraticProgramTraits`, such as
/// `Interior_point_quadratic_program_traits` (the exact optimum) or
/// `CGAL::OSQP_quadratic_program_traits`: Eq. 5 is written out as a general QP (variables
/// `u_i` at `2i`, `v_i` at `2i + 1`) into a copy of the traits object at every solve.
/// Where the traits object has a `statistics()` member with `iterations`, `primal_residual`,
/// `dual_residual`, `complementarity` and `message` (as `Interior_point_quadratic_program_traits`
/// has), the solve report carries them.
///
/// `Norm_preserving_parameterizer_3` wraps a `QuadraticProgramTraits` model given as its solver
/// in this class itself.
///
/// \tparam QuadraticProgramTraits a model of `QuadraticProgramTraits`
/// \cgalModels `NormPreservingSolver`
template <typename QuadraticProgramTraits>
class Norm_preserving_QP_solver
{
  BOOST_CONCEPT_ASSERT((concepts::QuadraticProgramTraits<QuadraticProgramTraits>));

public:
  /// nothing: every solve starts anew.
  struct State { };

  /// creates a solver that solves with copies of `qp`.
  explicit Norm_preserving_QP_solver(const QuadraticProgramTraits& qp = QuadraticProgramTraits()) : m_qp(qp) { }

  /// solves `problem` and writes the solution to `uv`; returns `false` if the traits' solve
  /// fails or returns a non-finite value. The start point in `uv` is not used.
  bool solve(const Norm_preserving_problem& problem, std::vector<std::array<double, 2> >& uv, State&,
             Norm_preserving_solve_report& report) const
  {
    namespace NP = internal::Norm_preserving;
    typedef std::chrono::steady_clock Clock;
    report = Norm_preserving_solve_report();
    report.method = "a QuadraticProgramTraits model";
    Clock::time_point start = Clock::now();
    QuadraticProgramTraits qp = m_qp;
    NP::assemble_sign_constrained_qp(problem.geometry, problem.lengths, problem.signs, problem.fixed, qp);
    report.assembly_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    start = Clock::now();
    std::vector<double> x;
    x.reserve(2 * uv.size());
    const bool solved = qp.solve(std::back_inserter(x));
    report.iteration_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if constexpr(NP::Has_statistics<QuadraticProgramTraits>::value)
    {
      const auto& statistics = qp.statistics();
      report.has_statistics = true;
      report.iterations = statistics.iterations;
      report.kkt_residual = (std::max)({statistics.primal_residual, statistics.dual_residual,
                                        statistics.complementarity});
      report.message = statistics.message;
    }
    if(!solved || x.size() != 2 * uv.size())
    {
      if(report.message.empty())
        report.message = "no solution";
      return false;
    }
    if(!std::all_of(x.begin(), x.end(), [](double value) { return std::isfinite(value); }))
    {
      report.message = "the quadratic program solver returned a non-finite value";
      return false;
    }
    for(std::size_t i = 0; i < uv.size(); ++i)
      uv[i] = {x[2 * i], x[2 * i + 1]};
    for(const Norm_preserving_fixed_vertex& f : problem.fixed)
      uv[f.index] = f.target;
    report.status = NORM_PRESERVING_SOLVER_CONVERGED;
    return true;
  }

private:
  QuadraticProgramTraits m_qp;
};

/// \cond SKIP_IN_MANUAL
namespace internal {
namespace Norm_preserving {

// Whether `Solver` has the types and the call of a `NormPreservingSolver`.
template <typename Solver, typename = void>
struct Is_norm_preserving_solver : std::false_type { };
template <typename Solver>
struct Is_norm_preserving_solver<Solver, std::void_t<typename Solver::State, decltype(std::declval<const Solver&>().solve(
  std::declval<const Norm_preserving_problem&>(), std::declval<std::vector<std::array<double, 2> >&>(),
  std::declval<typename Solver::State&>(), std::declval<Norm_preserving_solve_report&>()))> > : std::true_type { };

// A model of NormPreservingSolver as it is; anything else is taken for a model of
// QuadraticProgramTraits and wrapped (whose concept check then says what it lacks).
template <typename Solver>
struct Solver_model
{
  typedef typename std::conditional<Is_norm_preserving_solver<Solver>::value, Solver,
                                    Norm_preserving_QP_solver<Solver> >::type type;
};

class Two_column_cholesky;

// No factored Laplacian in a state that does not keep one.
template <typename State>
const Two_column_cholesky* factored_laplacian(const State&) { return nullptr; }

} // namespace Norm_preserving
} // namespace internal
/// \endcond

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif
