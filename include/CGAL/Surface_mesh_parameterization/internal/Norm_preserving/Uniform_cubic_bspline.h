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
// The interpolating uniform cubic B-spline of the graph-based initial guess (Section 4.3 of
// the paper, doc/decisions.md, 7): the curve f(t), 0 <= t <= 1, through data points D_0..D_{N-1}
// at the uniform parameters t_k = k / (N - 1).
//
// End conditions: not-a-knot (the third derivative is continuous at t_1 and t_{N-2}), so the
// spline reproduces every cubic polynomial, not only straight lines as the natural end
// condition would, and needs no end derivative that the data do not give.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_UNIFORM_CUBIC_BSPLINE_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_UNIFORM_CUBIC_BSPLINE_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

class Uniform_cubic_bspline
{
public:
  typedef std::array<double, 2> Point;

  // Solves for the control points in O(N); needs N >= 4 data points (below that the
  // not-a-knot conditions overlap and do not fix a cubic).
  explicit Uniform_cubic_bspline(const std::vector<Point>& data)
  {
    CGAL_precondition(data.size() >= 4);
    const std::vector<Point> moments = not_a_knot_moments(data);
    // With knot spacing 1 (in s = t (N - 1)), a uniform cubic B-spline through D_k has control
    // point C_k = D_k - f''(s_k) / 6 at every knot; the two phantom control points C_{-1} and
    // C_N follow from the interpolation conditions at both ends.
    const std::size_t n = data.size();
    m_control.resize(n + 2);
    for(std::size_t k = 0; k < n; ++k)
      for(int c = 0; c < 2; ++c)
        m_control[k + 1][c] = data[k][c] - moments[k][c] / 6.;
    for(int c = 0; c < 2; ++c)
    {
      m_control[0][c] = 6. * data[0][c] - 4. * m_control[1][c] - m_control[2][c];
      m_control[n + 1][c] = 6. * data[n - 1][c] - 4. * m_control[n][c] - m_control[n - 1][c];
    }
  }

  // f(t), t clamped to [0, 1].
  Point operator()(double t) const
  {
    const std::size_t segments = m_control.size() - 3;
    const double s = (std::min)((std::max)(t, 0.), 1.) * double(segments);
    const std::size_t k = (std::min)(std::size_t(s), segments - 1);
    const double u = s - double(k), w = 1. - u;
    const double b0 = w * w * w / 6.;
    const double b1 = (3. * u * u * u - 6. * u * u + 4.) / 6.;
    const double b2 = (-3. * u * u * u + 3. * u * u + 3. * u + 1.) / 6.;
    const double b3 = u * u * u / 6.;
    Point f;
    for(int c = 0; c < 2; ++c)
      f[c] = b0 * m_control[k][c] + b1 * m_control[k + 1][c] + b2 * m_control[k + 2][c] +
             b3 * m_control[k + 3][c];
    return f;
  }

private:
  // The second derivatives M_k at the knots. Interpolation at the interior knots gives
  // M_{k-1} + 4 M_k + M_{k+1} = 6 (D_{k-1} - 2 D_k + D_{k+1}); not-a-knot sets
  // M_0 = 2 M_1 - M_2, which turns the first row into 6 M_1 = r_1 (and likewise the last),
  // so the system stays tridiagonal and strictly diagonally dominant: Thomas' algorithm
  // needs no pivoting.
  static std::vector<Point> not_a_knot_moments(const std::vector<Point>& data)
  {
    const std::size_t n = data.size(), m = n - 2; // unknowns M_1..M_{n-2}, row i for M_{i+1}
    const auto lower = [m](std::size_t i) { return i + 1 == m ? 0. : 1.; }; // coefficient of M_i
    const auto upper = [](std::size_t i) { return i == 0 ? 0. : 1.; };      // coefficient of M_{i+2}
    std::vector<double> diagonal(m);
    std::vector<Point> rhs(m);
    for(std::size_t i = 0; i < m; ++i)
    {
      diagonal[i] = (i == 0 || i + 1 == m) ? 6. : 4.;
      for(int c = 0; c < 2; ++c)
        rhs[i][c] = 6. * (data[i][c] - 2. * data[i + 1][c] + data[i + 2][c]);
    }

    for(std::size_t i = 1; i < m; ++i)
    {
      const double factor = lower(i) / diagonal[i - 1];
      diagonal[i] -= factor * upper(i - 1);
      for(int c = 0; c < 2; ++c)
        rhs[i][c] -= factor * rhs[i - 1][c];
    }
    std::vector<Point> moments(n);
    for(std::size_t i = m; i-- > 0;)
      for(int c = 0; c < 2; ++c)
        moments[i + 1][c] = (rhs[i][c] - (i + 1 < m ? upper(i) * moments[i + 2][c] : 0.)) / diagonal[i];
    for(int c = 0; c < 2; ++c)
    {
      moments[0][c] = 2. * moments[1][c] - moments[2][c];
      moments[n - 1][c] = 2. * moments[n - 2][c] - moments[n - 3][c];
    }
    return moments;
  }

  std::vector<Point> m_control; // C_{-1}..C_N
};

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
