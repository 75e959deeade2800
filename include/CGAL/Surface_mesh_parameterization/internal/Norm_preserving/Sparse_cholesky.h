// Copyright (c) 2026 The CGAL_norm_preserving_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Sparse Cholesky factorization used by the interior-point QP solver: CHOLMOD's supernodal
// factorization when the package was configured with it, Eigen's simplicial one otherwise.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_SPARSE_CHOLESKY_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_SPARSE_CHOLESKY_H

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef CGAL_NORM_PRESERVING_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <cstddef>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

using Sparse_matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// Below this many rows Eigen's simplicial factorizations are faster than CHOLMOD's supernodal
// one (doc/performance.md, change 7); the ADMM's Laplacian and the polish's system switch here.
constexpr std::size_t cholmod_minimum_rows = 25000;

#ifdef CGAL_NORM_PRESERVING_USE_CHOLMOD
using Sparse_cholesky = Eigen::CholmodSupernodalLLT<Sparse_matrix, Eigen::Lower>;
#else
using Sparse_cholesky = Eigen::SimplicialLLT<Sparse_matrix, Eigen::Lower, Eigen::AMDOrdering<int> >;
#endif

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
