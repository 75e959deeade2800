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
/// \file Combination_initial_guess.h
/// \ingroup PkgNormPreservingParameterization
/// The Combination initial guess (Section 4.2 of the paper).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_COMBINATION_INITIAL_GUESS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_COMBINATION_INITIAL_GUESS_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/disable_warnings.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/XY_min_max_initial_guess.h>

#include <CGAL/number_type_config.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterizationMethods
/// The combination initial guess of Lai & Cheng (Section 4.2), which brings z into the
/// XY-MinMax guess: the weighted mean of the XY-MinMax guesses (`XY_min_max_initial_guess`,
/// each in `[0,1]^2`) of copies of the model rotated about several axes and, optionally, with
/// its own weight, of the sphere map `S(u,v) = (cos v cos u, cos v sin u, sin v)` about the
/// centroid: `u = atan2(y - cy, x - cx)` in `[0, 2 pi)` and `v = asin((z - cz) / r)`, scaled to
/// `[0,1]^2` (a vertex at the centroid gets `u = v = 0`).
///
/// A rotated copy with zero extent in x or in y has no XY-MinMax guess: it is left out of the
/// mean. The guess fails if nothing is left.
///
/// The paper warns that symmetric rotations cancel each other: two rotations inverse of each
/// other (same axis and opposite angles, or opposite axes and the same angle) with equal
/// weights keep only what the unrotated model gives. Such a choice, like any other invalid
/// parameter, is reported by `validate()` and by the call operator, never thrown.
///
/// \cgalModels `NormPreservingInitialGuess`
class Combination_initial_guess
{
public:
  /// A rotation of the model by `angle` radians (right-handed) about `axis`, a direction that
  /// need not be of unit length, whose XY-MinMax guess enters the mean with `weight >= 0`.
  struct Rotation
  {
    std::array<double, 3> axis; ///< direction of the rotation axis, not zero
    double angle;               ///< in radians
    double weight;              ///< weight in the mean, non-negative
  };

  /// The default rotations: 0.3 rad about x, 0.7 rad about y and 1.1 rad about `(1, 1, 1)`,
  /// weight 1 each. No two axes are parallel and no two angles are equal or opposite, so no
  /// rotation undoes another.
  static std::vector<Rotation> default_rotations()
  {
    return {Rotation{{1., 0., 0.}, 0.3, 1.}, Rotation{{0., 1., 0.}, 0.7, 1.}, Rotation{{1., 1., 1.}, 1.1, 1.}};
  }

  /// combines the XY-MinMax guesses of `rotations` with the sphere map of weight
  /// `sphere_weight >= 0`; by default the three `default_rotations()` only. The sphere map is
  /// off by default because its seam (where `u` jumps from `2 pi` to 0) gives wrong signs to
  /// the edges that cross it: with weight 1 the solved objective was higher on 7 of the 9
  /// meshes of the tests. The parameters are checked by `validate()`.
  explicit Combination_initial_guess(std::vector<Rotation> rotations = default_rotations(),
                                     double sphere_weight = 0.)
    : m_rotations(std::move(rotations)), m_sphere_weight(sphere_weight)
  { }

  /// returns `OK` if the parameters define a guess, otherwise `ERROR_WRONG_PARAMETER` and why
  /// in `message`: a non-finite value, a negative weight, a zero axis, all weights zero (in
  /// particular no rotation and a zero sphere weight), or two rotations that undo each other
  /// with equal non-zero weights.
  Error_code validate(std::string& message) const
  {
    if(!std::isfinite(m_sphere_weight) || m_sphere_weight < 0)
      return wrong_parameter(message, "the sphere weight must be finite and non-negative");
    double total_weight = m_sphere_weight;
    for(std::size_t k = 0; k < m_rotations.size(); ++k)
    {
      const Rotation& r = m_rotations[k];
      const std::string which = "rotation " + std::to_string(k);
      if(!(std::isfinite(r.axis[0]) && std::isfinite(r.axis[1]) && std::isfinite(r.axis[2]) &&
           std::isfinite(r.angle) && std::isfinite(r.weight)))
        return wrong_parameter(message, which + " has a non-finite axis, angle or weight");
      if(r.weight < 0)
        return wrong_parameter(message, which + " has a negative weight");
      if(!(norm(r.axis) > 0))
        return wrong_parameter(message, which + " has a zero axis");
      total_weight += r.weight;
    }
    if(m_rotations.empty() && m_sphere_weight == 0)
      return wrong_parameter(message, "no rotation and a zero sphere weight: nothing to combine");
    if(!(total_weight > 0))
      return wrong_parameter(message, "all weights are zero: nothing to combine");
    for(std::size_t i = 0; i < m_rotations.size(); ++i)
      for(std::size_t j = i + 1; j < m_rotations.size(); ++j)
        if(undo_each_other(m_rotations[i], m_rotations[j]))
          return wrong_parameter(message, "rotations " + std::to_string(i) + " and " + std::to_string(j) +
                                 " undo each other with equal weights, so they cancel out"
                                 " (Lai & Cheng 4.2); change an angle, an axis or a weight");
    return OK;
  }

  /// computes the guess of every vertex of `geometry`.
  Error_code operator()(const Norm_preserving_geometry& geometry,
                        std::vector<std::array<double, 2> >& uv,
                        std::string& message) const
  {
    const Error_code status = validate(message);
    if(status != OK)
      return status;
    const auto& points = geometry.points;
    if(points.empty())
    {
      message = "no vertex to guess";
      return ERROR_EMPTY_MESH;
    }
    std::vector<std::array<double, 2> > sum(points.size(), {0., 0.});
    double used_weight = 0;

    Norm_preserving_geometry rotated;
    rotated.points.resize(points.size());
    std::vector<std::array<double, 2> > copy_guess;
    std::string copy_message;
    for(const Rotation& r : m_rotations)
    {
      if(r.weight == 0)
        continue;
      // About an axis through the origin: where the axis passes does not matter, as each
      // copy is rescaled to [0,1]^2.
      const Matrix_3 R = rotation_matrix(r.axis, r.angle);
      for(std::size_t i = 0; i < points.size(); ++i)
        for(int c = 0; c < 3; ++c)
          rotated.points[i][c] = R[c][0] * points[i][0] + R[c][1] * points[i][1] + R[c][2] * points[i][2];
      if(!has_xy_extent(rotated.points) || XY_min_max_initial_guess()(rotated, copy_guess, copy_message) != OK)
        continue; // zero extent in x or y: no guess from this copy
      add_weighted(copy_guess, r.weight, sum);
      used_weight += r.weight;
    }
    if(m_sphere_weight > 0)
    {
      add_weighted(sphere_map(points), m_sphere_weight, sum);
      used_weight += m_sphere_weight;
    }
    if(!(used_weight > 0))
      return wrong_parameter(message, "every rotated copy of the model has zero extent in x or y and the "
                                      "sphere map has weight zero: the combination guess is undefined");
    for(auto& p : sum)
      for(int c = 0; c < 2; ++c)
        p[c] /= used_weight;
    uv.swap(sum);
    return OK;
  }

private:
  static bool has_xy_extent(const std::vector<std::array<double, 3> >& points)
  {
    const auto [low, high] = internal::Norm_preserving::coordinate_bounds(points);
    return high[0] > low[0] && high[1] > low[1];
  }

  typedef std::array<std::array<double, 3>, 3> Matrix_3;

  static Error_code wrong_parameter(std::string& message, const std::string& why)
  {
    message = why;
    return ERROR_WRONG_PARAMETER;
  }

  static double norm(const std::array<double, 3>& a)
  {
    return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  }

  // Rodrigues: R = cos I + sin [a]x + (1 - cos) a a^T, a the unit axis.
  static Matrix_3 rotation_matrix(const std::array<double, 3>& axis, double angle)
  {
    const double length = norm(axis);
    const std::array<double, 3> a = {axis[0] / length, axis[1] / length, axis[2] / length};
    const double c = std::cos(angle), s = std::sin(angle), t = 1. - c;
    return {{{c + t * a[0] * a[0], t * a[0] * a[1] - s * a[2], t * a[0] * a[2] + s * a[1]},
             {t * a[1] * a[0] + s * a[2], c + t * a[1] * a[1], t * a[1] * a[2] - s * a[0]},
             {t * a[2] * a[0] - s * a[1], t * a[2] * a[1] + s * a[0], c + t * a[2] * a[2]}}};
  }

  // `q` is the inverse (the transpose) of a rotation `p` that is not its own inverse, with the
  // same non-zero weight: their rotated guesses differ only by the sign of the rotation, which
  // the mean cancels. The tolerance absorbs angles written as, e.g., `pi/5` and `-pi/5`.
  static bool undo_each_other(const Rotation& p, const Rotation& q)
  {
    const double tolerance = 1e-9;
    if(p.weight == 0 || std::abs(p.weight - q.weight) > tolerance * (std::max)(p.weight, q.weight))
      return false;
    const Matrix_3 P = rotation_matrix(p.axis, p.angle), Q = rotation_matrix(q.axis, q.angle);
    double from_transpose = 0, asymmetry = 0;
    for(int i = 0; i < 3; ++i)
      for(int j = 0; j < 3; ++j)
      {
        from_transpose = (std::max)(from_transpose, std::abs(Q[i][j] - P[j][i]));
        asymmetry = (std::max)(asymmetry, std::abs(P[i][j] - P[j][i]));
      }
    return from_transpose <= tolerance && asymmetry > tolerance;
  }

  // Each vertex's spherical angles about the centroid, scaled from [0, 2 pi) x [-pi/2, pi/2]
  // to [0, 1]^2. atan2 of the height over the horizontal distance is asin(dz / r), without the
  // rounding of dz / r past 1.
  static std::vector<std::array<double, 2> > sphere_map(const std::vector<std::array<double, 3> >& points)
  {
    std::array<double, 3> centroid = {0., 0., 0.};
    for(const auto& p : points)
      for(int c = 0; c < 3; ++c)
        centroid[c] += p[c];
    for(int c = 0; c < 3; ++c)
      centroid[c] /= double(points.size());
    std::vector<std::array<double, 2> > uv(points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      const double dx = points[i][0] - centroid[0], dy = points[i][1] - centroid[1], dz = points[i][2] - centroid[2];
      double u = std::atan2(dy, dx);
      if(u < 0)
        u += 2 * CGAL_PI;
      const double v = std::atan2(dz, std::hypot(dx, dy));
      uv[i] = {u / (2 * CGAL_PI), v / CGAL_PI + 0.5};
    }
    return uv;
  }

  static void add_weighted(const std::vector<std::array<double, 2> >& guess, double weight,
                           std::vector<std::array<double, 2> >& sum)
  {
    for(std::size_t i = 0; i < sum.size(); ++i)
      for(int c = 0; c < 2; ++c)
        sum[i][c] += weight * guess[i][c];
  }

  std::vector<Rotation> m_rotations;
  double m_sphere_weight;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif
