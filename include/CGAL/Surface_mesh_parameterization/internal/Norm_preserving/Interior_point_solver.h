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
// Primal-dual interior-point method (Mehrotra predictor-corrector) for the convex QP
//   min 1/2 x'Px + q'x   s.t.   G x <= h,
// with P positive semidefinite. Each iteration factors the normal matrix P + G'WG; its
// sparsity pattern is fixed, so the symbolic analysis is done once and the values are
// written in place through precomputed positions.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_INTERIOR_POINT_SOLVER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_INTERIOR_POINT_SOLVER_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sparse_cholesky.h>

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

using Row_sparse_matrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

// min 1/2 x'Px + q'x s.t. G x <= h; P holds both triangles.
struct Inequality_qp
{
  Sparse_matrix P;
  Eigen::VectorXd q;
  Row_sparse_matrix G;
  Eigen::VectorXd h;
};

struct Interior_point_result
{
  bool converged = false;
  bool factorization_failed = false;
  bool time_limit_reached = false;
  int iterations = 0;
  double primal_residual = 0; // ||Gx + s - h||_inf
  double dual_residual = 0;   // ||Px + q + G'z||_inf
  double complementarity = 0; // s'z / m
  Eigen::VectorXd x, z, s;
};

// The normal matrix P + G'WG + delta*I (lower triangle) with in-place value updates.
class Normal_matrix
{
public:
  Normal_matrix(const Sparse_matrix& P, const Row_sparse_matrix& G)
    : m_P(P), m_G(G)
  {
    const int n = static_cast<int>(P.rows());
    std::vector<Eigen::Triplet<double> > pattern;
    for(int c = 0; c < n; ++c)
    {
      pattern.emplace_back(c, c, 1.);
      for(Sparse_matrix::InnerIterator it(P, c); it; ++it)
        if(it.row() > c)
          pattern.emplace_back(it.row(), c, 1.);
    }
    for(int r = 0; r < G.outerSize(); ++r)
      for(Row_sparse_matrix::InnerIterator a(G, r); a; ++a)
        for(Row_sparse_matrix::InnerIterator b(G, r); b; ++b)
          if(a.col() >= b.col())
            pattern.emplace_back(a.col(), b.col(), 1.);
    m_N.resize(n, n);
    m_N.setFromTriplets(pattern.begin(), pattern.end());
    m_N.makeCompressed();

    m_diagonal_positions.resize(n);
    for(int c = 0; c < n; ++c)
      m_diagonal_positions[c] = position(c, c);
    for(int c = 0; c < n; ++c)
      for(Sparse_matrix::InnerIterator it(P, c); it; ++it)
        if(it.row() >= c)
          m_P_positions.push_back(position(it.row(), c));
    for(int r = 0; r < G.outerSize(); ++r)
      for(Row_sparse_matrix::InnerIterator a(G, r); a; ++a)
        for(Row_sparse_matrix::InnerIterator b(G, r); b; ++b)
          if(a.col() >= b.col())
            m_G_positions.push_back(position(a.col(), b.col()));
  }

  // Sets the values to P + G' diag(w) G + delta*I.
  const Sparse_matrix& assemble(const Eigen::VectorXd& w, double delta)
  {
    double* values = m_N.valuePtr();
    std::fill(values, values + m_N.nonZeros(), 0.);
    std::size_t k = 0;
    for(int c = 0; c < m_P.outerSize(); ++c)
      for(Sparse_matrix::InnerIterator it(m_P, c); it; ++it)
        if(it.row() >= c)
          values[m_P_positions[k++]] += it.value();
    k = 0;
    for(int r = 0; r < m_G.outerSize(); ++r)
      for(Row_sparse_matrix::InnerIterator a(m_G, r); a; ++a)
        for(Row_sparse_matrix::InnerIterator b(m_G, r); b; ++b)
          if(a.col() >= b.col())
            values[m_G_positions[k++]] += w[r] * a.value() * b.value();
    for(int p : m_diagonal_positions)
      values[p] += delta;
    return m_N;
  }

  const Sparse_matrix& matrix() const { return m_N; }

  double max_diagonal() const
  {
    double d = 0;
    for(int p : m_diagonal_positions)
      d = (std::max)(d, m_N.valuePtr()[p]);
    return d;
  }

private:
  int position(int row, int col) const
  {
    const int* begin = m_N.innerIndexPtr() + m_N.outerIndexPtr()[col];
    const int* end = m_N.innerIndexPtr() + m_N.outerIndexPtr()[col + 1];
    return static_cast<int>(std::lower_bound(begin, end, row) - m_N.innerIndexPtr());
  }

  const Sparse_matrix& m_P;
  const Row_sparse_matrix& m_G;
  Sparse_matrix m_N;
  std::vector<int> m_diagonal_positions, m_P_positions, m_G_positions;
};

// Largest step in (0, 1] along (ds, dz) keeping s and z nonnegative, damped by eta.
inline double interior_step(const Eigen::VectorXd& s, const Eigen::VectorXd& ds,
                            const Eigen::VectorXd& z, const Eigen::VectorXd& dz, double eta)
{
  double alpha = std::numeric_limits<double>::infinity();
  for(Eigen::Index i = 0; i < s.size(); ++i)
  {
    if(ds[i] < 0) alpha = (std::min)(alpha, -s[i] / ds[i]);
    if(dz[i] < 0) alpha = (std::min)(alpha, -z[i] / dz[i]);
  }
  return (std::min)(1., eta * alpha);
}

// Solves the QP to the relative tolerance `tolerance` on primal and dual residuals and on
// the duality gap. Converges to the analytic centre of the optimal face, which makes the
// optimum unique and deterministic when the QP has a continuum of minimizers. Stops before an
// iteration that would start after `deadline`.
inline Interior_point_result solve_inequality_qp(const Inequality_qp& qp,
                                                 double tolerance,
                                                 int max_iterations,
                                                 std::chrono::steady_clock::time_point deadline =
                                                   std::chrono::steady_clock::time_point::max())
{
  Interior_point_result result;
  const Eigen::Index n = qp.q.size();
  const Eigen::Index m = qp.h.size();
  Normal_matrix normal(qp.P, qp.G);
  Sparse_cholesky cholesky;
#ifdef CGAL_NORM_PRESERVING_USE_CHOLMOD
  cholesky.cholmod().print = 0; // a failed factorization is retried with more regularization
  {
    // CHOLMOD's default analysis tries METIS too where AMD fills much.
    std::lock_guard<std::mutex> lock(metis_mutex());
    cholesky.analyzePattern(normal.matrix());
  }
#else
  cholesky.analyzePattern(normal.matrix());
#endif

  normal.assemble(Eigen::VectorXd::Ones(m), 0.);
  const double delta_floor = 1e-13 * (std::max)(1., normal.max_diagonal());
  double delta = delta_floor;

  // Factors P + G'WG + delta*I, raising delta until the factorization succeeds.
  auto factor = [&](const Eigen::VectorXd& w) -> bool
  {
    for(int attempt = 0; attempt < 8; ++attempt, delta *= 100.)
    {
      cholesky.factorize(normal.assemble(w, delta));
      if(cholesky.info() == Eigen::Success)
        return true;
    }
    return false;
  };
  // Solves (P + G'WG) dx = rhs with the regularized factor plus one refinement step.
  auto solve = [&](const Eigen::VectorXd& rhs) -> Eigen::VectorXd
  {
    Eigen::VectorXd dx = cholesky.solve(rhs);
    Eigen::VectorXd residual = rhs - normal.matrix().selfadjointView<Eigen::Lower>() * dx + delta * dx;
    dx += cholesky.solve(residual);
    return dx;
  };

  // Starting point: minimizer of 1/2 x'Px + q'x + 1/2 ||Gx - h||^2, shifted into the interior.
  if(!factor(Eigen::VectorXd::Ones(m)))
  {
    result.factorization_failed = true;
    return result;
  }
  Eigen::VectorXd x = solve(-qp.q + qp.G.transpose() * qp.h);
  Eigen::VectorXd s = qp.h - qp.G * x;
  Eigen::VectorXd z = -s;
  if(m > 0)
  {
    const double shift_s = -s.minCoeff(), shift_z = -z.minCoeff();
    if(shift_s >= 0) s.array() += 1. + shift_s;
    if(shift_z >= 0) z.array() += 1. + shift_z;
  }

  const double h_scale = 1. + (m > 0 ? qp.h.lpNorm<Eigen::Infinity>() : 0.);
  const double q_scale = 1. + (n > 0 ? qp.q.lpNorm<Eigen::Infinity>() : 0.);
  auto inf_norm = [](const Eigen::VectorXd& v) { return v.size() > 0 ? v.lpNorm<Eigen::Infinity>() : 0.; };

  for(result.iterations = 0; ; ++result.iterations)
  {
    const Eigen::VectorXd r_d = qp.P * x + qp.q + qp.G.transpose() * z;
    const Eigen::VectorXd r_p = qp.G * x + s - qp.h;
    const double mu = m > 0 ? s.dot(z) / double(m) : 0.;
    const double objective = 0.5 * x.dot(qp.P * x) + qp.q.dot(x);
    result.primal_residual = inf_norm(r_p);
    result.dual_residual = inf_norm(r_d);
    result.complementarity = mu;
    if(result.primal_residual <= tolerance * h_scale &&
       result.dual_residual <= tolerance * q_scale &&
       s.dot(z) <= tolerance * (std::max)(1., std::abs(objective)))
    {
      result.converged = true;
      break;
    }
    if(result.iterations >= max_iterations)
      break;
    if(std::chrono::steady_clock::now() >= deadline)
    {
      result.time_limit_reached = true;
      break;
    }

    const Eigen::VectorXd w = z.cwiseQuotient(s);
    delta = delta_floor;
    if(!factor(w))
    {
      result.factorization_failed = true;
      break;
    }

    // Predictor (affine scaling) direction.
    Eigen::VectorXd dx = solve(-r_d - qp.G.transpose() * (w.cwiseProduct(r_p) - z));
    Eigen::VectorXd Gdx = qp.G * dx;
    Eigen::VectorXd dz = w.cwiseProduct(Gdx + r_p) - z;
    Eigen::VectorXd ds = -r_p - Gdx;
    const double alpha_affine = interior_step(s, ds, z, dz, 1.);
    const double mu_affine = m > 0 ? (s + alpha_affine * ds).dot(z + alpha_affine * dz) / double(m) : 0.;
    const double sigma = mu > 0 ? std::pow(mu_affine / mu, 3) : 0.;

    // Corrector with centring.
    const Eigen::VectorXd r_c = (s.cwiseProduct(z) + ds.cwiseProduct(dz)).array() - sigma * mu;
    const Eigen::VectorXd corr = r_c.cwiseQuotient(s);
    dx = solve(-r_d - qp.G.transpose() * (w.cwiseProduct(r_p) - corr));
    Gdx = qp.G * dx;
    dz = w.cwiseProduct(Gdx + r_p) - corr;
    ds = -r_p - Gdx;
    const double alpha = interior_step(s, ds, z, dz, 0.99);
    x += alpha * dx;
    s += alpha * ds;
    z += alpha * dz;
  }
  result.x = std::move(x);
  result.z = std::move(z);
  result.s = std::move(s);
  return result;
}

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
