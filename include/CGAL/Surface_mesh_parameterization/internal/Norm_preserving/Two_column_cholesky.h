// Sparse Cholesky factorization L L' = P A P' of a symmetric positive definite matrix, kept
// in simplicial form with a solve for two right-hand sides at once, stored interleaved
// (x0 y0 x1 y1 ...): the ADMM solver's inner loop solves the same Laplacian for u and v in
// every iteration, and one pass over the factor for both is about twice as fast as two
// column solves (and than CHOLMOD's supernodal solve, whose BLAS calls are tiny for two
// columns). The factorization itself is CHOLMOD's supernodal one when the package is
// configured with CHOLMOD (4x faster than Eigen's simplicial one at 150k vertices), converted
// to simplicial form; Eigen's SimplicialLLT otherwise.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_TWO_COLUMN_CHOLESKY_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_TWO_COLUMN_CHOLESKY_H

#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sparse_cholesky.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

class Two_column_cholesky
{
public:
  // Factors the matrix whose lower triangle is `lower`; false if it is not positive definite.
  bool compute(const Sparse_matrix& lower)
  {
    m_n = std::size_t(lower.rows());
#ifdef CGAL_NORM_PRESERVING_USE_CHOLMOD
    cholmod_common common;
    cholmod_start(&common);
    common.supernodal = CHOLMOD_SUPERNODAL;
    cholmod_sparse view = Eigen::viewAsCholmod(lower.selfadjointView<Eigen::Lower>());
    cholmod_factor* factor = cholmod_analyze(&view, &common);
    bool ok = factor != nullptr && cholmod_factorize(&view, factor, &common) && common.status == CHOLMOD_OK
              && factor->minor == factor->n
              && cholmod_change_factor(CHOLMOD_REAL, true, false, true, true, factor, &common);
    if(ok)
    {
      const int* first = static_cast<const int*>(factor->p);
      const int* rows = static_cast<const int*>(factor->i);
      const double* values = static_cast<const double*>(factor->x);
      const int* permutation = static_cast<const int*>(factor->Perm);
      // The supernodes' padding comes over as explicit zeros: leave them out.
      m_first.assign(1, 0);
      m_rows.clear();
      m_values.clear();
      for(std::size_t j = 0; j < m_n; ++j)
      {
        for(int k = first[j]; k < first[j + 1]; ++k)
          if(k == first[j] || values[k] != 0)
          {
            m_rows.push_back(rows[k]);
            m_values.push_back(values[k]);
          }
        m_first.push_back(int(m_rows.size()));
      }
      m_position.resize(m_n);
      for(std::size_t k = 0; k < m_n; ++k)
        m_position[std::size_t(permutation[k])] = int(k);
    }
    cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
    return ok;
#else
    Eigen::SimplicialLLT<Sparse_matrix, Eigen::Lower, Eigen::AMDOrdering<int> > llt(lower);
    if(llt.info() != Eigen::Success)
      return false;
    const Sparse_matrix& factor = llt.matrixL().nestedExpression(); // diagonal first in each column
    m_first.assign(factor.outerIndexPtr(), factor.outerIndexPtr() + m_n + 1);
    m_rows.assign(factor.innerIndexPtr(), factor.innerIndexPtr() + m_first[m_n]);
    m_values.assign(factor.valuePtr(), factor.valuePtr() + m_first[m_n]);
    m_position.assign(llt.permutationP().indices().data(), llt.permutationP().indices().data() + m_n);
    return true;
#endif
  }

  // Solves A X = B in place for the two interleaved columns of `b` (size 2n).
  void solve(std::vector<double>& b) const
  {
    m_work.resize(2 * m_n);
    std::vector<double>& y = m_work;
    for(std::size_t i = 0; i < m_n; ++i)
    {
      y[2 * std::size_t(m_position[i])] = b[2 * i];
      y[2 * std::size_t(m_position[i]) + 1] = b[2 * i + 1];
    }
    for(std::size_t j = 0; j < m_n; ++j) // L y = P b
    {
      const double y0 = y[2 * j] /= m_values[m_first[j]], y1 = y[2 * j + 1] /= m_values[m_first[j]];
      for(int k = m_first[j] + 1; k < m_first[j + 1]; ++k)
      {
        const std::size_t i = std::size_t(m_rows[k]);
        y[2 * i] -= m_values[k] * y0;
        y[2 * i + 1] -= m_values[k] * y1;
      }
    }
    for(std::size_t j = m_n; j-- > 0;) // L' x = y
    {
      double y0 = y[2 * j], y1 = y[2 * j + 1];
      for(int k = m_first[j] + 1; k < m_first[j + 1]; ++k)
      {
        const std::size_t i = std::size_t(m_rows[k]);
        y0 -= m_values[k] * y[2 * i];
        y1 -= m_values[k] * y[2 * i + 1];
      }
      y[2 * j] = y0 / m_values[m_first[j]];
      y[2 * j + 1] = y1 / m_values[m_first[j]];
    }
    for(std::size_t i = 0; i < m_n; ++i)
    {
      b[2 * i] = y[2 * std::size_t(m_position[i])];
      b[2 * i + 1] = y[2 * std::size_t(m_position[i]) + 1];
    }
  }

private:
  std::size_t m_n = 0;
  std::vector<int> m_first, m_rows; // the simplicial factor by columns, diagonal first
  std::vector<double> m_values;
  std::vector<int> m_position;      // position of each unknown in the factor's order
  mutable std::vector<double> m_work;
};

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
