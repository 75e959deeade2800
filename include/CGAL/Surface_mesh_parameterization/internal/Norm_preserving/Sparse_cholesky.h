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
// What the package's sparse factorizations share: their settings, CHOLMOD reached through its
// own C API, and the factorization of the interior-point QP solver (CHOLMOD's supernodal one
// when the package is configured with it, Eigen's simplicial one otherwise).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_SPARSE_CHOLESKY_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_SPARSE_CHOLESKY_H

#include <CGAL/license/Surface_mesh_parameterization.h>

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

// Every threshold of the package's sparse factorizations (Two_column_cholesky.h and the
// polish's, Active_set_polish.h), in one place; the measurements that chose them are in
// doc/performance.md, "Sparse Cholesky".
struct Cholesky_settings
{
  // From this many rows CHOLMOD factors, when the package is configured with it (faster from
  // there; the simplicial factorization below).
  static constexpr std::size_t cholmod_minimum_rows = 25000;
  // CHOLMOD orders by METIS when AMD's factor would have this many entries a row or more, where
  // METIS's smaller factor repays its slower analysis.
  static constexpr double metis_fill_per_row = 47;
  // The solve's parts, solved on as many threads at once, and the top.
  static constexpr std::size_t part_count = 4;
  // A factor of fewer entries is all top: a part would take less time than handing it over.
  static constexpr double smallest_split = 1 << 14;
  // A part may be this much over an even share of the work; the top may hold this share of it.
  static constexpr double part_slack = 1.1, top_share = 0.1;
  // The level-set dissection: tried on a factor of at least `dissection_smallest_factor`
  // entries whose longest path holds over `dissection_tried_above` of them, kept when its
  // separators hold at most `dissection_separators` of AMD's entries, its longest path under
  // `dissection_kept_below` of AMD's and its factoring work under `dissection_most_work` times
  // AMD's; `dissection_levels` of bisection give a piece for each part.
  static constexpr double dissection_smallest_factor = 1 << 18, dissection_tried_above = 0.8,
                          dissection_separators = 0.15, dissection_kept_below = 0.75, dissection_most_work = 1.1;
  static constexpr int dissection_levels = 2;
};

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

// A CHOLMOD factor and its workspace, owned through CHOLMOD's own C API (not through Eigen's
// wrapper, whose factor is not public), both freed on every way out.
struct Cholmod_factor
{
  cholmod_common common;
  cholmod_factor* factor = nullptr;

  Cholmod_factor() { cholmod_start(&common); }
  ~Cholmod_factor()
  {
    cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }
  Cholmod_factor(const Cholmod_factor&) = delete;
  Cholmod_factor& operator=(const Cholmod_factor&) = delete;
};

// The symmetric matrix of lower triangle `lower` (compressed) as CHOLMOD reads it, in place.
inline cholmod_sparse cholmod_lower_view(const Sparse_matrix& lower)
{
  cholmod_sparse view = cholmod_sparse();
  view.nrow = view.ncol = std::size_t(lower.rows());
  view.nzmax = std::size_t(lower.nonZeros());
  view.p = const_cast<int*>(lower.outerIndexPtr()); // CHOLMOD's structs have no const
  view.i = const_cast<int*>(lower.innerIndexPtr());
  view.x = const_cast<double*>(lower.valuePtr());
  view.stype = -1;
  view.itype = CHOLMOD_INT;
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = 1;
  view.packed = 1;
  return view;
}

// A column of `size` doubles at `values` as CHOLMOD reads it, in place.
inline cholmod_dense cholmod_column_view(double* values, std::size_t size)
{
  cholmod_dense view = cholmod_dense();
  view.nrow = view.nzmax = view.d = size;
  view.ncol = 1;
  view.x = values;
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  return view;
}
#else
using Sparse_cholesky = Eigen::SimplicialLLT<Sparse_matrix, Eigen::Lower, Eigen::AMDOrdering<int> >;
#endif

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
