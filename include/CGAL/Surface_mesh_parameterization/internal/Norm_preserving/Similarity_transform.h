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
// Steps 4-5 of the paper: the similarity M that moves the guessed positions of the fixed
// pair onto their targets, applied to the whole guess.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_SIMILARITY_TRANSFORM_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_SIMILARITY_TRANSFORM_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <array>
#include <complex>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

// M = [c -s r1; s c r2; 0 0 1] as the complex map z -> alpha z + beta, alpha = c + i s.
struct Similarity_2
{
  std::complex<double> alpha, beta;

  std::array<double, 2> operator()(const std::array<double, 2>& p) const
  {
    const std::complex<double> z = alpha * std::complex<double>(p[0], p[1]) + beta;
    return {z.real(), z.imag()};
  }
};

// The similarity mapping `from_a` to `to_a` and `from_b` to `to_b`; `from_a != from_b`.
inline Similarity_2 similarity_from_pairs(const std::array<double, 2>& from_a, const std::array<double, 2>& from_b,
                                          const std::array<double, 2>& to_a, const std::array<double, 2>& to_b)
{
  const std::complex<double> fa(from_a[0], from_a[1]), fb(from_b[0], from_b[1]);
  const std::complex<double> ta(to_a[0], to_a[1]), tb(to_b[0], to_b[1]);
  const std::complex<double> alpha = (tb - ta) / (fb - fa);
  return {alpha, ta - alpha * fa};
}

inline void transform(std::vector<std::array<double, 2> >& uv, const Similarity_2& M)
{
  for(auto& p : uv)
    p = M(p);
}

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
