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
#include <mutex>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

using Sparse_matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// Below this many rows Eigen's simplicial factorizations are faster than CHOLMOD's, supernodal
// or simplicial (doc/performance.md, changes 7 and 25); the ADMM's Laplacian and the polish's
// system switch here.
constexpr std::size_t cholmod_minimum_rows = 25000;

#ifdef CGAL_NORM_PRESERVING_USE_CHOLMOD
// METIS draws from a random generator held in a global, seeded at each call: two orderings at
// once on two threads would interleave its draws and differ from run to run. This lock
// serializes the analyses of this package that may call METIS, not other METIS users.
inline std::mutex& metis_mutex()
{
  static std::mutex metis;
  return metis;
}

using Sparse_cholesky = Eigen::CholmodSupernodalLLT<Sparse_matrix, Eigen::Lower>;
#else
using Sparse_cholesky = Eigen::SimplicialLLT<Sparse_matrix, Eigen::Lower, Eigen::AMDOrdering<int> >;
#endif

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
