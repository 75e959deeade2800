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
// The normal equations C'C x = C'd of a sparse least-squares problem sum_r (d_r - C_r x)^2
// whose rows each have a few terms: the one assembly behind the QP's matrices (the exact
// solvers' Hessian, the polish's systems on an active set, and the graph Laplacian of the mesh
// step; Sign_constrained_qp.h gives their rows). Written in compressed form, in two passes over
// the rows, without triplets: those took most of an assembly's time in fresh pages and copies.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_NORMAL_EQUATIONS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_NORMAL_EQUATIONS_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sparse_cholesky.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cstddef>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

struct Normal_equations
{
  Sparse_matrix lower; // the lower triangle of C'C, each column's diagonal first, its rows increasing
  Eigen::VectorXd rhs; // C'd
};

// The normal equations over `unknowns` unknowns of `rows` rows: `row(r, term)` calls
// `term(k, a)` for each term a x_k of row r (at most eight; an unknown may come twice) and
// returns d_r. Every unknown has a diagonal entry; a pair of unknowns that share a row has an
// entry even where the row's products cancel. The right-hand side sums each row's terms in
// order, row after row.
template <typename Row>
Normal_equations normal_equations(std::size_t rows, std::size_t unknowns, const Row& row)
{
  typedef std::array<std::pair<int, double>, 8> Terms;
  auto terms_of = [&](std::size_t r, Terms& terms, int& count) {
    count = 0;
    return row(r, [&](int k, double a) { terms[std::size_t(count++)] = {k, a}; });
  };
  Normal_equations result;
  Sparse_matrix& lower = result.lower;
  const int n = int(unknowns);
  lower.resize(n, n);
  int* start = lower.outerIndexPtr(); // zeros
  Terms terms;
  int count = 0;
  for(std::size_t r = 0; r < rows; ++r) // the entries below the diagonal, by column
  {
    terms_of(r, terms, count);
    for(int s = 0; s < count; ++s)
      for(int t = 0; t < count; ++t)
        if(terms[std::size_t(s)].first > terms[std::size_t(t)].first)
          ++start[terms[std::size_t(t)].first + 1];
  }
  for(int c = 0; c < n; ++c)
    start[c + 1] += start[c] + 1; // and the diagonal
  lower.resizeNonZeros(start[n]);
  int* index = lower.innerIndexPtr();
  double* value = lower.valuePtr();
  std::vector<int> next(start, start + n);
  for(int c = 0; c < n; ++c)
  {
    index[next[std::size_t(c)]] = c;
    value[next[std::size_t(c)]++] = 0.;
  }
  result.rhs = Eigen::VectorXd::Zero(n);
  for(std::size_t r = 0; r < rows; ++r)
  {
    const double d = terms_of(r, terms, count);
    for(int s = 0; s < count; ++s)
    {
      const auto& [k, a] = terms[std::size_t(s)];
      result.rhs[k] += a * d;
      for(int t = 0; t < count; ++t)
      {
        const auto& [l, b] = terms[std::size_t(t)];
        if(k == l)
          value[start[k]] += a * b;
        else if(k > l)
        {
          index[next[std::size_t(l)]] = k;
          value[next[std::size_t(l)]++] = a * b;
        }
      }
    }
  }
  // Each column's rows in increasing order, repeats summed.
  int kept = 0;
  std::vector<std::pair<int, double> > column;
  for(int c = 0; c < n; ++c)
  {
    const int begin = start[c], end = start[c + 1];
    start[c] = kept;
    index[kept] = c;
    value[kept++] = value[begin];
    if(!std::is_sorted(index + begin + 1, index + end, [](int i, int j) { return i <= j; })) // not strictly increasing
    {
      column.clear();
      for(int p = begin + 1; p < end; ++p)
        column.emplace_back(index[p], value[p]);
      std::stable_sort(column.begin(), column.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
      for(std::size_t p = 0; p < column.size(); ++p)
        if(p > 0 && column[p].first == column[p - 1].first)
          value[kept - 1] += column[p].second;
        else
        {
          index[kept] = column[p].first;
          value[kept++] = column[p].second;
        }
    }
    else
      for(int p = begin + 1; p < end; ++p, ++kept)
      {
        index[kept] = index[p];
        value[kept] = value[p];
      }
  }
  start[n] = kept;
  lower.resizeNonZeros(kept);
  return result;
}

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
