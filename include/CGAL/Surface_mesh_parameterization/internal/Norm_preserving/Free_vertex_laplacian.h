// The graph Laplacian D'D of the mesh restricted to its free vertices (the two fixed ones
// eliminated, Dirichlet), and the right-hand side of a least-squares fit of the mesh to wished
// edge differences with it: the one system of the ADMM solver's mesh step and of the stress
// majorization's step. Both hold the same fixed pair, so one factorization serves both.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_FREE_VERTEX_LAPLACIAN_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_FREE_VERTEX_LAPLACIAN_H

#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sign_constrained_qp.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sparse_cholesky.h>

#include <algorithm>
#include <array>
#include <cstddef>
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

// Lower triangle of the unit-weight graph Laplacian among the free vertices.
inline Sparse_matrix free_vertex_laplacian(const Norm_preserving_geometry& geometry, const std::vector<int>& free_index)
{
  const int free_count = int(std::count_if(free_index.begin(), free_index.end(), [](int i) { return i >= 0; }));
  std::vector<Eigen::Triplet<double> > triplets;
  triplets.reserve(3 * geometry.edges.size());
  for(const auto& e : geometry.edges)
  {
    const int fi = free_index[e[0]], fj = free_index[e[1]];
    if(fi >= 0) triplets.emplace_back(fi, fi, 1.);
    if(fj >= 0) triplets.emplace_back(fj, fj, 1.);
    if(fi >= 0 && fj >= 0) triplets.emplace_back((std::max)(fi, fj), (std::min)(fi, fj), -1.);
  }
  Sparse_matrix laplacian(free_count, free_count);
  laplacian.setFromTriplets(triplets.begin(), triplets.end());
  return laplacian;
}

// Adds to `rhs` (free vertices, u and v interleaved) edge (i, j)'s wished difference
// `difference` of w_i - w_j in coordinate c, for the least-squares system whose matrix is the
// Laplacian above: the values of fixed vertices, taken from `uv`, go to the right-hand side.
inline void add_edge_difference(std::vector<double>& rhs, const std::vector<int>& free_index, std::size_t i,
                                std::size_t j, int c, double difference, const UV_vector& uv)
{
  if(free_index[i] < 0) difference -= uv[i][c];
  if(free_index[j] < 0) difference += uv[j][c];
  if(free_index[i] >= 0) rhs[2 * std::size_t(free_index[i]) + c] += difference;
  if(free_index[j] >= 0) rhs[2 * std::size_t(free_index[j]) + c] -= difference;
}

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
