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
/// \file Norm_preserving_concepts.h
/// \ingroup PkgNormPreservingParameterization
/// Compile-time checks of the package's concepts.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_CONCEPTS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_CONCEPTS_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/disable_warnings.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_solver.h>

#include <boost/concept/usage.hpp>
#include <boost/concept_check.hpp>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace concepts {

/// \ingroup PkgNormPreservingParameterizationConcepts
/// Checks that `Guess` models `NormPreservingInitialGuess`:
/// `BOOST_CONCEPT_ASSERT((concepts::NormPreservingInitialGuess<Guess>))`, which
/// `Norm_preserving_parameterizer_3` asserts of its guess.
template <typename Guess>
struct NormPreservingInitialGuess : boost::CopyConstructible<Guess>
{
  /// \cond SKIP_IN_MANUAL
  BOOST_CONCEPT_USAGE(NormPreservingInitialGuess)
  {
    const Guess& constant = guess;
    status = constant(*geometry, uv, message);
  }

private:
  Guess guess;
  const Norm_preserving_geometry* geometry;
  std::vector<std::array<double, 2> > uv;
  std::string message;
  Error_code status;
  /// \endcond
};

/// \ingroup PkgNormPreservingParameterizationConcepts
/// Checks that `Solver` models `NormPreservingSolver`:
/// `BOOST_CONCEPT_ASSERT((concepts::NormPreservingSolver<Solver>))`, which
/// `Norm_preserving_parameterizer_3` and the whole-mesh calls assert of their solver.
template <typename Solver>
struct NormPreservingSolver : boost::CopyConstructible<Solver>
{
  /// \cond SKIP_IN_MANUAL
  typedef typename Solver::State State;

  BOOST_CONCEPT_USAGE(NormPreservingSolver)
  {
    State fresh;
    const Solver& constant = solver;
    solved = constant.solve(*problem, uv, fresh, report);
  }

private:
  Solver solver;
  const Norm_preserving_problem* problem;
  std::vector<std::array<double, 2> > uv;
  Norm_preserving_solve_report report;
  bool solved;
  /// \endcond
};

/// \ingroup PkgNormPreservingParameterizationConcepts
/// Checks that `Traits` has what `Norm_preserving_QP_solver` uses of CGAL's concept
/// `QuadraticProgramTraits`: `BOOST_CONCEPT_ASSERT((concepts::QuadraticProgramTraits<Traits>))`.
template <typename Traits>
struct QuadraticProgramTraits : boost::CopyConstructible<Traits>
{
  /// \cond SKIP_IN_MANUAL
  BOOST_CONCEPT_USAGE(QuadraticProgramTraits)
  {
    traits.set_P(i, j, value);
    traits.set_q(i, value);
    traits.set_r(value);
    traits.set_A(i, j, value);
    traits.set_l(i, value);
    traits.set_u(i, value);
    solved = traits.solve(std::back_inserter(x));
  }

private:
  Traits traits;
  std::size_t i, j;
  double value;
  std::vector<double> x;
  bool solved;
  /// \endcond
};

} // namespace concepts
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif
