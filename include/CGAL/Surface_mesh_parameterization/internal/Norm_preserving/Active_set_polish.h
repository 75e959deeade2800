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
// The exact optimum of the sign-constrained QP (Eq. 5) on a guessed active set, for the
// certified mode of the ADMM solver (doc/decisions.md, "The QP and its solver"). An active
// constraint su (u_i - u_j) = 0 ties u_i to u_j: per coordinate, the active edges merge the
// vertices into clusters that share one value, and Eq. 5 with the active constraints as
// equalities is an unconstrained least-squares problem in the clusters' values (a cluster
// holding a fixed vertex takes its value). Its normal equations, coupled in u and v through
// the residuals, are factored once (Regularized_normal_cholesky, below); they are singular
// where the optimum is not unique, and proximal steps pick the optimum nearest the start. An
// active set that ties the same clusters as the last one has the same solution: it is kept;
// one whose clusters differ from those last factored by a few splits and joins is solved on
// that factorization, bordered by the differences.
//
// The multipliers follow from the solution: on an inactive constraint the gradient of the
// objective, y = -2 r_e; on the active edges of a cluster, the values that make A'y vanish at
// every free vertex, found on a spanning tree of the cluster from its leaves up (the other
// active edges keep the ADMM's estimate, clamped to a nonnegative multiplier). At the optimum
// with the right active set this y makes the dual bound of Dual_bound.h meet the objective; a
// wrong active set shows as a violated constraint or a negative multiplier mu = -2 r_e - y, and
// is corrected: violated constraints join it, those of negative multiplier leave it.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_ACTIVE_SET_POLISH_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_ACTIVE_SET_POLISH_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Admm_settings.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Free_vertex_laplacian.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Index_sets.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Normal_equations.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sign_constrained_qp.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sparse_cholesky.h>

#include <Eigen/LU>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

using Active_set = std::vector<std::array<char, 2> >; // per edge and coordinate: at equality

// The vertices in the order the factor of the free-vertex Laplacian eliminates them
// (`positions`, per free index), the fixed ones last. The polish numbers its unknowns in this
// order: every edge couples the u and v of both its ends, so the Laplacian's fill-reducing
// order, each vertex's two unknowns side by side, suits its normal equations too, and they
// are factored without an ordering of their own in each round.
inline std::vector<std::size_t> elimination_order(const std::vector<int>& free_index, const std::vector<int>& positions)
{
  std::vector<std::size_t> order(free_index.size());
  std::size_t fixed = positions.size();
  for(std::size_t i = 0; i < free_index.size(); ++i)
    order[free_index[i] >= 0 ? std::size_t(positions[std::size_t(free_index[i])]) : fixed++] = i;
  return order;
}

// The factorization of the polish's regularized normal equations, its unknowns already in a
// fill-reducing order: Eigen's simplicial L D L', or from `cholmod_minimum_rows` unknowns
// CHOLMOD's supernodal L L' when the package is configured with it (doc/performance.md,
// "Sparse Cholesky"); the border reads either factor in place.
class Regularized_normal_cholesky
{
public:
  // False if the matrix (lower triangle) is not positive definite.
  bool compute(const Sparse_matrix& lower)
  {
#ifdef CGAL_NORM_PRESERVING_USE_CHOLMOD
    m_large = std::size_t(lower.rows()) >= Cholesky_settings::cholmod_minimum_rows;
    if(m_large)
      return m_cholmod.compute(lower);
#endif
    m_ldlt.compute(lower);
    if(m_ldlt.info() != Eigen::Success)
      return false;
    m_d = m_ldlt.vectorD(); // a copy: once, not per use
    return (m_d.array() > 0).all();
  }

  Eigen::VectorXd solve(const Eigen::VectorXd& b) const
  {
#ifdef CGAL_NORM_PRESERVING_USE_CHOLMOD
    if(m_large)
      return m_cholmod.solve_system(CHOLMOD_A, b);
#endif
    return m_ldlt.solve(b);
  }

  // Solves with the factored matrix K bordered by sparse columns U, for the Schur complement
  // of [K U; U' X]: complement() = U' K^-1 U; per right-hand side b0, project(b0) = U' K^-1 b0,
  // then solve(t) = K^-1 (b0 - U t), one solve of K in all. The columns are kept as L^-1 U on
  // the rows it reaches (the ancestors of U's rows in the elimination tree), all at once, on
  // either factor.
  class Border
  {
  public:
    Border(const Regularized_normal_cholesky& cholesky, const Sparse_matrix& columns)
      : m_cholesky(cholesky)
    {
      // The reach: from each row of U up the elimination tree, numbered in elimination order.
      std::vector<Eigen::Index> row(std::size_t(cholesky.rows()), -1); // per row of L: its row of m_forward
      for(Eigen::Index k = 0; k < columns.outerSize(); ++k)
        for(Sparse_matrix::InnerIterator entry(columns, k); entry; ++entry)
          for(Eigen::Index j = cholesky.position(entry.index()); j >= 0 && row[std::size_t(j)] < 0;
              j = cholesky.parent(j))
            row[std::size_t(j)] = 0;
      for(std::size_t j = 0; j < row.size(); ++j)
        if(row[j] >= 0)
        {
          row[j] = Eigen::Index(m_reach.size());
          m_reach.push_back(Eigen::Index(j));
        }
      m_forward = Row_matrix::Zero(Eigen::Index(m_reach.size()), columns.cols());
      for(Eigen::Index k = 0; k < columns.outerSize(); ++k)
        for(Sparse_matrix::InnerIterator entry(columns, k); entry; ++entry)
          m_forward(row[std::size_t(cholesky.position(entry.index()))], k) += entry.value();
      m_inverse_d.resize(Eigen::Index(m_reach.size()));
      for(std::size_t r = 0; r < m_reach.size(); ++r)
      {
        const Eigen::Index i = Eigen::Index(r);
        m_inverse_d[i] = 1. / cholesky.for_each_below(m_reach[r], [&](double diagonal) {
          if(diagonal != 1.)
            m_forward.row(i) /= diagonal;
        }, [&](Eigen::Index below, double value) {
          m_forward.row(row[std::size_t(below)]).noalias() -= value * m_forward.row(i);
        });
      }
      m_complement = m_forward.transpose() * (m_inverse_d.asDiagonal() * m_forward);
    }

    const Eigen::MatrixXd& complement() const { return m_complement; }

    Eigen::VectorXd project(const Eigen::VectorXd& b0)
    {
      m_half = m_cholesky.forward(b0);
      Eigen::VectorXd reached(m_inverse_d.size());
      for(std::size_t r = 0; r < m_reach.size(); ++r)
        reached[Eigen::Index(r)] = m_inverse_d[Eigen::Index(r)] * m_half[m_reach[r]];
      return m_forward.transpose() * reached;
    }

    Eigen::VectorXd solve(const Eigen::VectorXd& t) const
    {
      Eigen::VectorXd x = m_half;
      const Eigen::VectorXd correction = m_forward * t;
      for(std::size_t r = 0; r < m_reach.size(); ++r)
        x[m_reach[r]] -= correction[Eigen::Index(r)];
      return m_cholesky.backward(x);
    }

  private:
    typedef Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> Row_matrix;

    const Regularized_normal_cholesky& m_cholesky;
    std::vector<Eigen::Index> m_reach; // per row of m_forward: its row of L
    Row_matrix m_forward;              // L^-1 U on the reached rows
    Eigen::VectorXd m_inverse_d;       // D^-1 on the reached rows
    Eigen::MatrixXd m_complement;      // U' K^-1 U
    Eigen::VectorXd m_half;            // L^-1 b0
  };

private:
  // K = P' L D L' P: Eigen's factor has P = I and a unit diagonal in L, CHOLMOD's D = I.

  Eigen::Index rows() const
  {
#ifdef CGAL_NORM_PRESERVING_USE_CHOLMOD
    if(m_large)
      return Eigen::Index(m_cholmod.factor().n);
#endif
    return m_ldlt.rows();
  }

  // The row of L (of P K P') of an unknown.
  Eigen::Index position(Eigen::Index unknown) const
  {
#ifdef CGAL_NORM_PRESERVING_USE_CHOLMOD
    if(m_large)
      return m_cholmod.position(unknown);
#endif
    return unknown;
  }

  // The parent of column j in the elimination tree (the row of its first entry below the
  // diagonal), or -1.
  Eigen::Index parent(Eigen::Index j) const
  {
#ifdef CGAL_NORM_PRESERVING_USE_CHOLMOD
    if(m_large)
      return m_cholmod.parent(j);
#endif
    const Sparse_matrix::InnerIterator first(m_ldlt.matrixL().nestedExpression(), j);
    return first ? first.index() : -1;
  }

  // Calls on_diagonal(L_jj), then below(i, L_ij) on the entries of column j below the
  // diagonal; returns D_j.
  template <typename On_diagonal, typename Below>
  double for_each_below(Eigen::Index j, On_diagonal&& on_diagonal, Below&& below) const
  {
#ifdef CGAL_NORM_PRESERVING_USE_CHOLMOD
    if(m_large)
    {
      m_cholmod.for_each_in_column(j, on_diagonal, below);
      return 1.;
    }
#endif
    on_diagonal(1.);
    for(Sparse_matrix::InnerIterator entry(m_ldlt.matrixL().nestedExpression(), j); entry; ++entry)
      below(entry.index(), entry.value());
    return m_d[j];
  }

  // L^-1 P b.
  Eigen::VectorXd forward(const Eigen::VectorXd& b) const
  {
#ifdef CGAL_NORM_PRESERVING_USE_CHOLMOD
    if(m_large)
      return m_cholmod.solve_system(CHOLMOD_L, m_cholmod.solve_system(CHOLMOD_P, b));
#endif
    Eigen::VectorXd x = b;
    m_ldlt.matrixL().solveInPlace(x);
    return x;
  }

  // P' L'^-1 D^-1 y.
  Eigen::VectorXd backward(const Eigen::VectorXd& y) const
  {
#ifdef CGAL_NORM_PRESERVING_USE_CHOLMOD
    if(m_large)
      return m_cholmod.solve_system(CHOLMOD_Pt, m_cholmod.solve_system(CHOLMOD_Lt, y));
#endif
    Eigen::VectorXd x = y.cwiseQuotient(m_d);
    m_ldlt.matrixU().solveInPlace(x);
    return x;
  }

  Eigen::SimplicialLDLT<Sparse_matrix, Eigen::Lower, Eigen::NaturalOrdering<int> > m_ldlt;
  Eigen::VectorXd m_d; // its D
#ifdef CGAL_NORM_PRESERVING_USE_CHOLMOD
  // CHOLMOD's supernodal factor, read in place: supernode s holds the columns super[s] to
  // super[s + 1] - 1, each with the rows s[pi[s]] to s[pi[s + 1] - 1] (ascending, the
  // supernode's own first: padding zeros included, the first row below the diagonal is the
  // parent), its values by columns from x[px[s]].
  class Supernodal
  {
  public:
    bool compute(const Sparse_matrix& lower)
    {
      cholmod_common& common = m_factor.common;
      common.print = 0;
      common.nmethods = 1;
      common.method[0].ordering = CHOLMOD_NATURAL; // postordered
      common.final_asis = 1;
      common.supernodal = CHOLMOD_SUPERNODAL;
      cholmod_free_factor(&m_factor.factor, &common);
      cholmod_sparse view = cholmod_lower_view(lower);
      m_factor.factor = cholmod_analyze(&view, &common);
      if(m_factor.factor == nullptr || !cholmod_factorize(&view, m_factor.factor, &common) ||
         common.status != CHOLMOD_OK || m_factor.factor->minor != m_factor.factor->n || !factor().is_super)
        return false;
      const int* super = static_cast<const int*>(factor().super);
      m_supernode.resize(factor().n);
      for(std::size_t s = 0; s < factor().nsuper; ++s)
        std::fill(m_supernode.begin() + super[s], m_supernode.begin() + super[s + 1], int(s));
      const int* permutation = static_cast<const int*>(factor().Perm);
      m_position.resize(factor().n);
      for(std::size_t k = 0; k < factor().n; ++k)
        m_position[std::size_t(permutation[k])] = int(k);
      return true;
    }

    const cholmod_factor& factor() const { return *m_factor.factor; }

    Eigen::Index position(Eigen::Index unknown) const { return m_position[std::size_t(unknown)]; }

    Eigen::Index parent(Eigen::Index j) const
    {
      const Column c = column(j);
      return c.below < c.end ? c.rows[c.below] : -1;
    }

    template <typename On_diagonal, typename Below>
    void for_each_in_column(Eigen::Index j, On_diagonal& on_diagonal, Below& below) const
    {
      const Column c = column(j);
      on_diagonal(c.values[c.below - 1]);
      for(int r = c.below; r < c.end; ++r)
        below(Eigen::Index(c.rows[r]), c.values[r]);
    }

    // Solves the system of CHOLMOD's code (CHOLMOD_A, CHOLMOD_L, CHOLMOD_P, ...) for b; NaN if
    // it fails.
    Eigen::VectorXd solve_system(int system, Eigen::VectorXd b) const
    {
      cholmod_dense view = cholmod_column_view(b.data(), std::size_t(b.size()));
      cholmod_dense* x = cholmod_solve(system, m_factor.factor, &view, &m_factor.common);
      if(x == nullptr)
        return Eigen::VectorXd::Constant(b.size(), std::numeric_limits<double>::quiet_NaN());
      b = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(x->x), b.size());
      cholmod_free_dense(&x, &m_factor.common);
      return b;
    }

  private:
    struct Column
    {
      const int* rows;     // the supernode's rows
      const double* values; // the column's values, aligned with `rows`
      int below, end;      // the entries below the diagonal: [below, end)
    };

    Column column(Eigen::Index j) const
    {
      const cholmod_factor& L = factor();
      const std::size_t s = std::size_t(m_supernode[std::size_t(j)]);
      const int first = static_cast<const int*>(L.super)[s], begin = static_cast<const int*>(L.pi)[s],
                height = static_cast<const int*>(L.pi)[s + 1] - begin, c = int(j) - first;
      return {static_cast<const int*>(L.s) + begin,
              static_cast<const double*>(L.x) + static_cast<const int*>(L.px)[s] + std::ptrdiff_t(c) * height, c + 1,
              height};
    }

    mutable Cholmod_factor m_factor; // CHOLMOD's solves write into its workspace
    std::vector<int> m_supernode, m_position; // per column its supernode; per unknown its row of L
  };

  Supernodal m_cholmod;
  bool m_large = false;
#endif
};

// Per coordinate and vertex, the root of its cluster (the vertices the active edges tie
// together): the cluster's lowest vertex, so that two active sets tie the same clusters if and
// only if their roots are equal.
typedef std::array<std::vector<std::size_t>, 2> Active_set_clusters;

inline Active_set_clusters active_set_clusters(const Norm_preserving_geometry& geometry, const Active_set& active)
{
  const std::size_t n = geometry.points.size(), none = std::size_t(-1);
  Active_set_clusters cluster;
  for(int c = 0; c < 2; ++c)
  {
    Index_sets tied(n);
    for(std::size_t e = 0; e < geometry.edges.size(); ++e)
      if(active[e][c])
        tied.join(geometry.edges[e][0], geometry.edges[e][1]);
    std::vector<std::size_t> lowest(n, none); // of each set, by its representative
    cluster[c].resize(n);
    for(std::size_t i = 0; i < n; ++i)
    {
      std::size_t& first = lowest[tied.find(i)];
      if(first == none)
        first = i;
      cluster[c][i] = first;
    }
  }
  return cluster;
}

// Eq. 5 with the constraints of an active set as equalities, given its clusters: the regularized
// normal equations in the values of the clusters that hold no fixed vertex.
struct Active_set_system
{
  std::array<std::vector<int>, 2> unknown;         // per cluster root: its unknown, -1 if fixed
  std::array<std::vector<double>, 2> value;        // per cluster root: its value if fixed
  Sparse_matrix normal;                            // lower triangle, eps added to the diagonal
  Eigen::VectorXd rhs;
  double eps = 0;
};

// The system of the active set of `clusters`, its unknowns numbered along `order` (every vertex
// once: elimination_order()); false if the active set ties the two fixed vertices to
// different values.
inline bool active_set_system(const Norm_preserving_geometry& geometry, const std::vector<double>& lengths,
                              const Edge_signs& signs, const std::array<Fixed_vertex, 2>& fixed,
                              const std::vector<std::size_t>& order, const Active_set_clusters& clusters,
                              Active_set_system& system)
{
  const std::size_t n = geometry.points.size(), m = geometry.edges.size();
  const Active_set_clusters& cluster = clusters;
  std::array<std::vector<int>, 2>& unknown = system.unknown;
  std::array<std::vector<double>, 2>& value = system.value;
  for(int c = 0; c < 2; ++c)
  {
    unknown[c].assign(n, -2); // -2: not numbered yet
    value[c].assign(n, 0.);
    for(const Fixed_vertex& f : fixed)
    {
      const std::size_t r = cluster[c][f.index];
      if(unknown[c][r] == -1 && value[c][r] != f.target[c])
        return false;
      unknown[c][r] = -1;
      value[c][r] = f.target[c];
    }
  }
  // The unknowns follow `order`, each vertex's u then v; a cluster takes the place of its
  // member eliminated last: it couples the neighbours of all its members, and eliminated at
  // its first member it would fill the factor several times over.
  int unknowns = 0;
  for(int c = 0; c < 2; ++c)
    for(std::size_t i = 0; i < n; ++i)
      unknowns += cluster[c][i] == i && unknown[c][i] == -2 ? 1 : 0;
  int next = unknowns;
  for(std::size_t k = order.size(); k-- > 0;)
    for(int c = 2; c-- > 0;)
      if(unknown[c][cluster[c][order[k]]] == -2)
        unknown[c][cluster[c][order[k]]] = --next;

  // Normal equations of sum_e (d_e - C_e x)^2 in the clusters' unknowns. The optimum is not
  // unique where a vertex can slide along a diagonal without changing any L1 length: the system
  // is singular there. Proximal steps from the start point (the ADMM's),
  // x <- (H + eps I)^-1 (b + eps x), converge to the optimum nearest to it.
  Normal_equations normal = normal_equations(m, std::size_t(unknowns), [&](std::size_t e, const auto& term) {
    return sign_constrained_row(geometry, lengths, signs, e,
                                [&](int c, std::size_t i, const auto& unknown_term, const auto& known) {
                                  const std::size_t r = cluster[c][i];
                                  if(unknown[c][r] < 0)
                                    known(value[c][r]);
                                  else
                                    unknown_term(unknown[c][r]);
                                },
                                term);
  });
  const int* start = normal.lower.outerIndexPtr();
  double* diagonal = normal.lower.valuePtr();
  double diagonal_sum = 0;
  for(int k = 0; k < unknowns; ++k)
    diagonal_sum += diagonal[start[k]];
  system.eps = 1e-9 * diagonal_sum / (std::max)(1, unknowns);
  for(int k = 0; k < unknowns; ++k)
    diagonal[start[k]] += system.eps;
  system.normal = std::move(normal.lower);
  system.rhs = std::move(normal.rhs);
  return true;
}

// A polish round's factored system, kept for the rounds after it (their active sets tie
// clusters that differ from its own by a few splits and joins: solved bordered on it).
struct Active_set_factorization
{
  Active_set_clusters clusters; // those the system is built on; empty: nothing factored yet
  Active_set_system system;
  Regularized_normal_cholesky cholesky;
};

// What a polish round leaves to the next: the clusters of its active set, and the last
// factorization.
struct Active_set_rounds
{
  Active_set_clusters clusters; // empty before the first round
  Active_set_factorization factored;
};

// Builds and factors the system of the active set of `clusters` in `factored`; false if the
// active set ties the two fixed vertices to different values, or the system is not positive
// definite. `order` as for active_set_system().
inline bool factor_active_set(const Norm_preserving_geometry& geometry, const std::vector<double>& lengths,
                              const Edge_signs& signs, const std::array<Fixed_vertex, 2>& fixed,
                              const std::vector<std::size_t>& order, const Active_set_clusters& clusters,
                              Active_set_factorization& factored)
{
  factored.clusters = Active_set_clusters();
  if(!active_set_system(geometry, lengths, signs, fixed, order, clusters, factored.system) ||
     !factored.cholesky.compute(factored.system.normal))
    return false;
  factored.clusters = clusters;
  return true;
}

// Proximal steps x <- argmin |d - C x|^2 + eps |x - x_prev|^2 from `x`: at most four, fewer
// once a step moves x by at most `round_off` of its size (Admm_settings::
// polish_proximal_round_off): with eps 1e-9 of the mean diagonal a solve's round-off is about
// 1e-7 of x, and the steps after the first move x by about that much along directions of zero
// curvature without converging. `step` takes x_prev and returns the next x. False if a step is
// not finite.
template <typename Step>
bool proximal_steps(const Step& step, double round_off, Eigen::VectorXd& x)
{
  for(int k = 0; k < 4; ++k)
  {
    const Eigen::VectorXd next = step(x);
    if(!next.allFinite())
      return false;
    const bool still = (next - x).lpNorm<Eigen::Infinity>() <= round_off * (1. + x.lpNorm<Eigen::Infinity>());
    x = next;
    if(still)
      break;
  }
  return true;
}

// The solution on the factored system's own clusters nearest to `start`, written to `uv`.
inline bool solve_factored(const Active_set_factorization& factored, const UV_vector& start, double round_off,
                           UV_vector& uv)
{
  const std::size_t n = start.size();
  const Active_set_clusters& cluster = factored.clusters;
  const Active_set_system& system = factored.system;
  const Eigen::Index unknowns = system.normal.rows();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(unknowns), members = Eigen::VectorXd::Zero(unknowns);
  for(int c = 0; c < 2; ++c)
    for(std::size_t i = 0; i < n; ++i)
      if(system.unknown[c][cluster[c][i]] >= 0)
      {
        x[system.unknown[c][cluster[c][i]]] += start[i][c];
        members[system.unknown[c][cluster[c][i]]] += 1;
      }
  x = x.cwiseQuotient(members);
  if(!proximal_steps([&](const Eigen::VectorXd& at) { return factored.cholesky.solve(system.rhs + system.eps * at); },
                     round_off, x))
    return false;
  uv.resize(n);
  for(int c = 0; c < 2; ++c)
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::size_t r = cluster[c][i];
      uv[i][c] = system.unknown[c][r] < 0 ? system.value[c][r] : x[system.unknown[c][r]];
    }
  return true;
}

// The solution on `clusters` nearest to `start`, written to `uv`, solved on the factorization of
// other clusters bordered by their differences: per coordinate, each base cluster is cut into
// pieces by the new clusters; the piece holding its fixed vertex (or else its lowest vertex)
// keeps the base unknown, every other piece gets an offset from it, and the pieces of a new
// cluster are tied by equality constraints (to its fixed value, if it has one). The border,
// offsets and constraints, is solved by its Schur complement (Regularized_normal_cholesky::
// Border). False if the border would have more than `max_border` columns, or a solve is not
// finite.
inline bool solve_bordered(const Norm_preserving_geometry& geometry, const std::vector<double>& lengths,
                           const Edge_signs& signs, const std::array<Fixed_vertex, 2>& fixed,
                           const Active_set_factorization& factored, const Active_set_clusters& clusters,
                           const UV_vector& start, std::size_t max_border, double round_off, UV_vector& uv)
{
  const std::size_t n = geometry.points.size(), m = geometry.edges.size();
  const Active_set_clusters& base = factored.clusters;
  const Active_set_system& system = factored.system;
  const Eigen::Index unknowns = system.normal.rows();
  typedef std::pair<std::size_t, std::size_t> Piece; // (base root, new root)
  struct Tie { int c; Piece piece, other; bool to_value; double value; }; // piece = other, or = value
  std::array<std::vector<Eigen::Index>, 2> offset_of; // per vertex: its piece's offset column, or -1
  std::array<std::vector<std::size_t>, 2> anchor;     // per base root: the vertex whose piece keeps its unknown
  std::array<std::vector<double>, 2> fixed_value;     // per new root: its fixed value, or NaN
  std::array<std::map<Piece, Eigen::Index>, 2> offset; // per piece off its base unknown: its column
  std::vector<Tie> ties;
  Eigen::Index offsets = 0;
  for(int c = 0; c < 2; ++c)
  {
    anchor[c].resize(n);
    std::iota(anchor[c].begin(), anchor[c].end(), std::size_t(0));
    fixed_value[c].assign(n, std::numeric_limits<double>::quiet_NaN());
    for(const Fixed_vertex& f : fixed)
    {
      anchor[c][base[c][f.index]] = f.index;
      double& value = fixed_value[c][clusters[c][f.index]];
      if(!std::isnan(value) && value != f.target[c])
        return false; // infeasible: left to the factorization to say
      value = f.target[c];
    }
    offset_of[c].assign(n, -1);
    std::set<Piece> tied;
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::size_t b = base[c][i], r = clusters[c][i];
      const bool kept = clusters[c][anchor[c][b]] == r;
      const Piece piece(b, r);
      if(!kept)
      {
        const auto added = offset[c].emplace(piece, unknowns + offsets);
        offsets += added.second ? 1 : 0;
        offset_of[c][i] = added.first->second;
      }
      const bool constant = kept && system.unknown[c][b] < 0, to_value = !std::isnan(fixed_value[c][r]);
      if(constant && to_value && system.value[c][b] != fixed_value[c][r])
        return false;
      if((to_value ? !constant : b != base[c][r]) && tied.insert(piece).second)
        ties.push_back(Tie{c, piece, Piece(base[c][r], r), to_value, fixed_value[c][r]});
      if(std::size_t(offsets) + ties.size() > max_border)
        return false;
    }
  }
  if(offsets == 0 && ties.empty())
    return false;

  // The border: U couples the base unknowns to the offsets and the ties' multipliers, X holds
  // the offsets' normal equations and the ties' rows among them; b1 their right-hand side.
  const Eigen::Index p = offsets + Eigen::Index(ties.size());
  std::vector<Eigen::Triplet<double> > border;
  Eigen::MatrixXd X = Eigen::MatrixXd::Zero(p, p);
  Eigen::VectorXd b1 = Eigen::VectorXd::Zero(p);
  auto column_of = [&](int c, std::size_t b) { return Eigen::Index(system.unknown[c][b]); }; // -1 if fixed
  for(std::size_t e = 0; e < m; ++e)
  {
    const std::array<std::size_t, 2>& ends = geometry.edges[e];
    if(offset_of[0][ends[0]] < 0 && offset_of[0][ends[1]] < 0 && offset_of[1][ends[0]] < 0 && offset_of[1][ends[1]] < 0)
      continue;
    std::array<Eigen::Index, 8> index;
    std::array<double, 8> coefficient;
    int count = 0;
    const double d = sign_constrained_row(geometry, lengths, signs, e,
      [&](int c, std::size_t i, const auto& unknown, const auto& known) { // the piece's base unknown and offset
        const std::size_t b = base[c][i];
        if(column_of(c, b) < 0)
          known(system.value[c][b]);
        else
          unknown(column_of(c, b));
        if(offset_of[c][i] >= 0)
          unknown(offset_of[c][i]);
      },
      [&](Eigen::Index k, double a) {
        index[std::size_t(count)] = k;
        coefficient[std::size_t(count++)] = a;
      });
    for(int s = 0; s < count; ++s)
    {
      const Eigen::Index row = index[std::size_t(s)] - unknowns;
      if(row < 0)
        continue;
      b1[row] += coefficient[std::size_t(s)] * d;
      for(int t = 0; t < count; ++t)
      {
        const double product = coefficient[std::size_t(s)] * coefficient[std::size_t(t)];
        if(index[std::size_t(t)] < unknowns)
          border.emplace_back(index[std::size_t(t)], row, product);
        else
          X(index[std::size_t(t)] - unknowns, row) += product;
      }
    }
  }
  for(Eigen::Index k = 0; k < offsets; ++k)
    X(k, k) += system.eps;
  // A tie's row: the value of its piece minus the other's, or minus its fixed value.
  auto add_piece = [&](int c, const Piece& piece, double sign, Eigen::Index row) {
    const std::size_t b = piece.first;
    if(column_of(c, b) < 0)
      b1[row] -= sign * system.value[c][b];
    else
      border.emplace_back(column_of(c, b), row, sign);
    if(clusters[c][anchor[c][b]] != piece.second)
      X(offset[c].at(piece) - unknowns, row) += sign;
  };
  for(std::size_t t = 0; t < ties.size(); ++t)
  {
    const Eigen::Index row = offsets + Eigen::Index(t);
    add_piece(ties[t].c, ties[t].piece, 1., row);
    if(ties[t].to_value)
      b1[row] += ties[t].value;
    else
      add_piece(ties[t].c, ties[t].other, -1., row);
    X.row(row) = X.col(row).transpose();
  }

  // Schur complement S = X - U' K^-1 U: for residuals (r0, r1), a step's change solves
  // S t = r1 - U' K^-1 r0 and x = K^-1 (r0 - U t).
  Sparse_matrix U(unknowns, p);
  U.setFromTriplets(border.begin(), border.end());
  Regularized_normal_cholesky::Border bordered(factored.cholesky, U);
  if(!bordered.complement().allFinite())
    return false;
  const Eigen::PartialPivLU<Eigen::MatrixXd> schur(X - bordered.complement());
  const Eigen::Index size = unknowns + offsets;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(size), members = Eigen::VectorXd::Zero(size);
  for(int c = 0; c < 2; ++c)
    for(std::size_t i = 0; i < n; ++i)
    {
      const Eigen::Index k = column_of(c, base[c][i]);
      if(k >= 0)
      {
        x[k] += start[i][c];
        members[k] += 1;
      }
    }
  for(Eigen::Index k = 0; k < unknowns; ++k)
    x[k] /= members[k];
  for(int c = 0; c < 2; ++c)
    for(std::size_t i = 0; i < n; ++i)
      if(offset_of[c][i] >= 0)
      {
        const std::size_t b = base[c][i];
        const Eigen::Index k = offset_of[c][i];
        x[k] += start[i][c] - (column_of(c, b) < 0 ? system.value[c][b] : x[column_of(c, b)]);
        members[k] += 1;
      }
  for(Eigen::Index k = unknowns; k < size; ++k)
    x[k] /= members[k];
  // Each step solves for its change from the residual of the whole bordered system, whose sparse
  // parts give it to round-off: the complement's own round-off (it grows as 1/eps) then slows
  // the steps instead of biasing where they end.
  Eigen::VectorXd multipliers = Eigen::VectorXd::Zero(p - offsets); // the ties'
  const bool solved = proximal_steps(
    [&](const Eigen::VectorXd& at) {
      Eigen::VectorXd t(p);
      t.head(offsets) = at.tail(offsets);
      t.tail(p - offsets) = multipliers;
      const Eigen::VectorXd base_values = at.head(unknowns);
      const Eigen::VectorXd r0 = system.rhs + system.eps * base_values -
                                 system.normal.selfadjointView<Eigen::Lower>() * base_values - U * t;
      Eigen::VectorXd r1 = b1 - U.transpose() * base_values - X * t;
      r1.head(offsets) += system.eps * at.tail(offsets);
      const Eigen::VectorXd change = schur.solve(r1 - bordered.project(r0));
      Eigen::VectorXd next(size);
      next.head(unknowns) = base_values + bordered.solve(change);
      next.tail(offsets) = at.tail(offsets) + change.head(offsets);
      multipliers += change.tail(p - offsets);
      return next;
    },
    round_off, x);
  if(!solved)
    return false;
  // Every vertex takes the value of its new cluster's root (or the cluster's fixed value).
  uv.resize(n);
  for(int c = 0; c < 2; ++c)
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::size_t r = clusters[c][i], b = base[c][r];
      const double value = column_of(c, b) < 0 ? system.value[c][b] : x[column_of(c, b)];
      uv[i][c] = !std::isnan(fixed_value[c][r]) ? fixed_value[c][r]
                                                 : value + (offset_of[c][r] >= 0 ? x[offset_of[c][r]] : 0.);
    }
  return true;
}

// The solution of Eq. 5 with the constraints of `active` as equalities nearest to `start`,
// written to `uv`, and its multipliers to `y` (per edge, for a and b), those of the active
// edges off the spanning trees taken from `estimate`; false if the active set ties the two
// fixed vertices to different values. `rounds` holds what the round `start` comes from left
// (or nothing) and receives this round's: when the active set ties the clusters of the round
// before (the constraints that left it were on cycles of active edges, those that joined it
// tied vertices already tied), `start` is the solution on `active` too, and nothing is solved
// (performance.md, "Active-set polish"); when its clusters differ from those of the last
// factorization in at most `settings.polish_border` splits and joins, they are solved bordered
// on it; else factored anew. `order` as for active_set_system().
inline bool solve_on_active_set(const Norm_preserving_geometry& geometry, const std::vector<double>& lengths,
                                const Edge_signs& signs, const std::array<Fixed_vertex, 2>& fixed,
                                const std::vector<std::size_t>& order, const Active_set& active, const UV_vector& start,
                                Active_set_rounds& rounds, const std::vector<std::array<double, 2> >& estimate,
                                const Admm_settings& settings, UV_vector& uv, std::vector<std::array<double, 2> >& y)
{
  const std::size_t n = geometry.points.size(), m = geometry.edges.size();
  Active_set_clusters tied = active_set_clusters(geometry, active);
  if(tied == rounds.clusters)
    uv = start;
  else
  {
    rounds.clusters.swap(tied);
    const bool bordered = !rounds.factored.clusters[0].empty() &&
                          solve_bordered(geometry, lengths, signs, fixed, rounds.factored, rounds.clusters, start,
                                         settings.polish_border, settings.polish_proximal_round_off, uv);
    if(!bordered && !(factor_active_set(geometry, lengths, signs, fixed, order, rounds.clusters, rounds.factored) &&
                      solve_factored(rounds.factored, start, settings.polish_proximal_round_off, uv)))
      return false;
  }

  // Multipliers: -2 r_e, then the active edges of a spanning tree of each cluster, from the
  // leaves up, so that A'y vanishes at every free vertex.
  y.resize(m);
  for(std::size_t e = 0; e < m; ++e)
  {
    const double r = sign_constrained_residual(geometry, lengths, signs, uv, e);
    for(int c = 0; c < 2; ++c) // an estimate clamped to a nonnegative multiplier -2 r_e - y
      y[e][c] = active[e][c] ? (std::min)(estimate[e][c], -2. * r) : -2. * r;
  }
  std::vector<int> every_vertex(n);
  std::iota(every_vertex.begin(), every_vertex.end(), 0);
  const Free_vertex_edges incident = free_vertex_edges(geometry, every_vertex);
  std::vector<char> is_fixed_vertex(n, 0);
  for(const Fixed_vertex& f : fixed)
    is_fixed_vertex[f.index] = 1;
  for(int c = 0; c < 2; ++c)
  {
    // A breadth-first tree of each cluster's active edges, rooted at a fixed vertex if it has one.
    std::vector<std::ptrdiff_t> tree_edge(n, -1); // the edge to the parent
    std::vector<char> seen(n, 0);
    std::vector<std::size_t> order;
    order.reserve(n);
    auto grow = [&](std::size_t root) {
      seen[root] = 1;
      order.push_back(root);
      for(std::size_t k = order.size() - 1; k < order.size(); ++k)
        for(std::size_t l = incident.first[order[k]]; l < incident.first[order[k] + 1]; ++l)
        {
          const std::size_t e = incident.edge(l);
          const std::size_t other = geometry.edges[e][0] + geometry.edges[e][1] - order[k];
          if(active[e][c] && !seen[other])
          {
            seen[other] = 1;
            tree_edge[other] = std::ptrdiff_t(e);
            order.push_back(other);
          }
        }
    };
    for(const Fixed_vertex& f : fixed)
      if(!seen[f.index])
        grow(f.index);
    for(std::size_t i = 0; i < n; ++i)
      if(!seen[i])
        grow(i);
    // (A'y)_i from the edges of known multiplier, then each tree edge set to cancel it.
    auto contribution = [&](std::size_t e, std::size_t at) {
      return (at == geometry.edges[e][0] ? signs[e][c] : -signs[e][c]) * y[e][c];
    };
    std::vector<double> total(n, 0.);
    for(std::size_t e = 0; e < m; ++e)
      if(tree_edge[geometry.edges[e][0]] != std::ptrdiff_t(e) && tree_edge[geometry.edges[e][1]] != std::ptrdiff_t(e))
        for(std::size_t end : geometry.edges[e])
          total[end] += contribution(e, end);
    for(std::size_t k = order.size(); k-- > 0;)
    {
      const std::size_t i = order[k];
      if(tree_edge[i] < 0 || is_fixed_vertex[i])
        continue;
      const std::size_t e = std::size_t(tree_edge[i]);
      y[e][c] = -total[i] / (i == geometry.edges[e][0] ? signs[e][c] : -signs[e][c]);
      const std::size_t parent = geometry.edges[e][0] + geometry.edges[e][1] - i;
      total[parent] += contribution(e, parent);
    }
  }
  return true;
}

// The corrections of a polish try's active set from one round to the next: violated constraints
// join it, those of negative multiplier leave it, both beyond round-off (degenerate constraints,
// of zero value and multiplier at the optimum, would turn back and forth every round). Once the
// corrections stop shrinking, only the most wrong turn, fewer each round; a try whose
// corrections grow is abandoned (performance.md, "Active-set polish").
class Active_set_corrections
{
public:
  // Corrects `active` after round `round` of a try, whose solution is `candidate` with
  // multipliers `y`. False if the try ends: at a KKT point (nothing to turn: at_kkt_point()),
  // or on corrections that grow.
  bool correct(const Norm_preserving_geometry& geometry, const std::vector<double>& lengths, const Edge_signs& signs,
               const UV_vector& candidate, const std::vector<std::array<double, 2> >& y, const Admm_settings& settings,
               int round, Active_set& active)
  {
    m_wrong.clear();
    for(std::size_t e = 0; e < geometry.edges.size(); ++e)
    {
      const double r = sign_constrained_residual(geometry, lengths, signs, candidate, e);
      for(int c = 0; c < 2; ++c)
      {
        const double amount = active[e][c] ? 2. * r + y[e][c] : -sign_constraint_value(geometry, signs, candidate, e, c);
        if(amount > settings.polish_turn_tolerance)
          m_wrong.emplace_back(-amount, 2 * e + std::size_t(c));
      }
    }
    m_fewest = (std::min)(m_fewest, m_wrong.size());
    if(m_wrong.empty() || m_wrong.size() > settings.polish_growth_limit * m_fewest + settings.polish_growth_slack)
      return false;
    if(round > 0 && double(m_wrong.size()) > settings.polish_shrink * double(m_wanted))
      m_limit = (std::max)(std::size_t(1), (std::min)(m_limit, m_wanted / 2));
    m_wanted = m_wrong.size();
    if(m_wanted > m_limit)
    {
      std::sort(m_wrong.begin(), m_wrong.end()); // the most wrong first, then by index
      m_wrong.resize(m_limit);
    }
    for(const auto& turn : m_wrong)
      active[turn.second / 2][turn.second % 2] ^= 1;
    return true;
  }

  bool at_kkt_point() const { return m_wrong.empty(); }

private:
  std::vector<std::pair<double, std::size_t> > m_wrong; // (minus how wrong, 2 e + c)
  std::size_t m_wanted = 0;                                // turns the last round wanted
  std::size_t m_fewest = std::numeric_limits<std::size_t>::max(), m_limit = std::numeric_limits<std::size_t>::max();
};

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
