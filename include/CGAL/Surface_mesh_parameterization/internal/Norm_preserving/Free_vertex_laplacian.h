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
// The graph Laplacian D'D of the mesh restricted to its free vertices (the two fixed ones
// eliminated, Dirichlet), and the right-hand side of a least-squares fit of the mesh to wished
// edge differences with it: the one system of the ADMM solver's mesh step and of the stress
// majorization's step. Both hold the same fixed pair, so one factorization serves both.
// The ADMM solver assembles its right-hand side by gathering per-edge values at each free
// vertex (Free_vertex_edges), in edge order, on several threads: the same sums as adding
// edge by edge, bit for bit.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_FREE_VERTEX_LAPLACIAN_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_FREE_VERTEX_LAPLACIAN_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/assertions.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Normal_equations.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Parallel_for.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sign_constrained_qp.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sparse_cholesky.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

// Index of each vertex among the free ones, in vertex order; -1 for the two fixed vertices.
inline std::vector<int> free_vertex_indices(std::size_t n, const std::array<Fixed_vertex, 2>& fixed)
{
  std::vector<int> free_index(n, -1);
  int free_count = 0;
  for(std::size_t i = 0; i < n; ++i)
    if(i != fixed[0].index && i != fixed[1].index)
      free_index[i] = free_count++;
  return free_index;
}

// Lower triangle of the unit-weight graph Laplacian among the free vertices (`free_index` of
// free_vertex_indices()): the normal matrix of the mesh step's least squares, whose rows are the
// edges' differences w_i - w_j with the fixed ends' values known.
inline Sparse_matrix free_vertex_laplacian(const Norm_preserving_geometry& geometry, const std::vector<int>& free_index)
{
  const std::size_t free_count = std::size_t(std::count_if(free_index.begin(), free_index.end(), [](int i) { return i >= 0; }));
  return normal_equations(geometry.edges.size(), free_count, [&](std::size_t e, const auto& term) {
           for(std::size_t end = 0; end < 2; ++end)
             if(free_index[geometry.edges[e][end]] >= 0)
               term(free_index[geometry.edges[e][end]], end == 0 ? 1. : -1.);
           return 0.;
         }).lower;
}

// Edge (i, j)'s wished difference `difference` of w_i - w_j in coordinate c, for the
// least-squares system whose matrix is the Laplacian above, with the values of its fixed
// ends (taken from `uv`) moved to the right-hand side.
inline double free_edge_difference(const std::vector<int>& free_index, std::size_t i, std::size_t j, int c,
                                   double difference, const UV_vector& uv)
{
  if(free_index[i] < 0) difference -= uv[i][c];
  if(free_index[j] < 0) difference += uv[j][c];
  return difference;
}

// Adds edge (i, j)'s wished difference to `rhs` (free vertices, u and v interleaved).
inline void add_edge_difference(std::vector<double>& rhs, const std::vector<int>& free_index, std::size_t i,
                                std::size_t j, int c, double difference, const UV_vector& uv)
{
  difference = free_edge_difference(free_index, i, j, c, difference, uv);
  if(free_index[i] >= 0) rhs[2 * std::size_t(free_index[i]) + c] += difference;
  if(free_index[j] >= 0) rhs[2 * std::size_t(free_index[j]) + c] -= difference;
}

// The edges at each free vertex in edge order, those of free vertex f from first[f] to
// first[f + 1]: ends[k] = 2 e for edge e where the vertex is its first end (sign(k) = +1),
// 2 e + 1 where its second (-1), in 32 bits: these lists are read every iteration, and on
// small meshes their pages are a share of a call's time (doc/performance.md, "Memory").
// free_vertex_edges() numbers the free vertices by `free_index`, which may be any one-to-one
// numbering of them from 0 (the ADMM's is their rows in the factor's order); with every
// vertex free (free_index[i] == i), the edges at each vertex of the mesh.
struct Free_vertex_edges
{
  std::vector<std::uint32_t> first;
  std::vector<std::uint32_t> ends;

  std::size_t edge(std::size_t k) const { return ends[k] >> 1; }
  double sign(std::size_t k) const { return 1. - 2. * double(ends[k] & 1); } // exact, without a branch
};

// Needs fewer than 2^31 edges (the Laplacian's 32-bit indices need fewer still).
inline Free_vertex_edges free_vertex_edges(const Norm_preserving_geometry& geometry, const std::vector<int>& free_index)
{
  CGAL_precondition(geometry.edges.size() < (std::size_t(1) << 31));
  const std::size_t free_count = std::size_t(std::count_if(free_index.begin(), free_index.end(), [](int i) { return i >= 0; }));
  Free_vertex_edges result;
  result.first.assign(free_count + 1, 0);
  for(const auto& e : geometry.edges)
    for(std::size_t end : e)
      if(free_index[end] >= 0)
        ++result.first[std::size_t(free_index[end]) + 1];
  for(std::size_t f = 0; f < free_count; ++f)
    result.first[f + 1] += result.first[f];
  result.ends.resize(result.first[free_count]);
  std::vector<std::uint32_t> fill(result.first.begin(), result.first.end() - 1);
  for(std::size_t e = 0; e < geometry.edges.size(); ++e)
    for(std::size_t end = 0; end < 2; ++end)
    {
      const int f = free_index[geometry.edges[e][end]];
      if(f >= 0)
        result.ends[fill[std::size_t(f)]++] = std::uint32_t(2 * e + end);
    }
  return result;
}

// rhs = D' values over the free vertices (u and v interleaved): at each free vertex, the
// values of its edges, added where it is the first end, subtracted where the second (a
// product by -1 is exact: the same sums as with a branch, without its mispredictions).
inline void gather_edge_values(const Free_vertex_edges& incidence, const std::vector<std::array<double, 2> >& values,
                               std::vector<double>& rhs)
{
  const std::size_t block = 512; // free vertices a block (doc/performance.md, "Parallel loops")
  parallel_for_each_block(incidence.first.size() - 1, block, [&](std::size_t begin, std::size_t end) {
    for(std::size_t f = begin; f < end; ++f)
    {
      double u = 0, v = 0;
      for(std::size_t k = incidence.first[f]; k < incidence.first[f + 1]; ++k)
      {
        const std::array<double, 2>& value = values[incidence.edge(k)];
        const double sign = incidence.sign(k);
        u += sign * value[0];
        v += sign * value[1];
      }
      rhs[2 * f] = u;
      rhs[2 * f + 1] = v;
    }
  });
}

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
