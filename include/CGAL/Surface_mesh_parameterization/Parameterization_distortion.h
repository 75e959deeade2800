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
/// \file Parameterization_distortion.h
/// \ingroup PkgNormPreservingParameterization
/// Distortion measures of a uv map.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_PARAMETERIZATION_DISTORTION_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_PARAMETERIZATION_DISTORTION_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/disable_warnings.h>

#include <CGAL/Surface_mesh_parameterization/triangulate_polygon_soup.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Soup_graph.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterizationTypes
/// Distortion of a uv map of a triangle mesh, over the faces and edges whose vertices all have
/// a uv. Every measure but the flip counts is taken after scaling the uv map by the one factor
/// that best fits the 3D edge lengths (least squares; the L1 measures use the factor that best
/// fits the L1 lengths). Every measure but `scale` and `l1_objective` (in squared 3D units) is
/// thus independent of the scales of the mesh and of the map, within the range of a double.
struct Parameterization_distortion
{
  std::size_t faces = 0;               ///< faces measured
  std::size_t edges = 0;               ///< edges measured
  double scale = 0;                    ///< the best-fitting factor applied to the uvs
  double edge_length_error = 0;        ///< RMS of (s ||uv_i - uv_j||_2 - ||P_i - P_j||_2) over the mean 3D length
  double l1_edge_length_error = 0;     ///< RMS of (s1 (|du| + |dv|) - ||P_i - P_j||_1) over the mean 3D L1 length
  double l1_objective = 0;             ///< the paper's Eq. 3, sum of (s1 (|du| + |dv|) - ||P_i - P_j||_1)^2
  double mean_angle_distortion = 0;    ///< mean |3D angle - uv angle| over face corners, in degrees
  double max_angle_distortion = 0;     ///< largest |3D angle - uv angle|, in degrees
  double area_distortion = 0;          ///< RMS over faces of log(uv area / 3D area), non-degenerate faces
  double l2_stretch = 0;               ///< Sander et al.'s L2 stretch (1 is ideal), non-degenerate faces
  double linf_stretch = 0;             ///< Sander et al.'s L-infinity stretch (1 is ideal)
  std::size_t flipped_faces = 0;       ///< faces oriented against the orientation of most of the 3D area
  double flipped_area_fraction = 0;    ///< 3D area of those faces over the total 3D area
  std::size_t degenerate_uv_faces = 0; ///< faces of zero uv area
};

namespace internal {
namespace Norm_preserving {

using Vec3 = std::array<double, 3>;
inline Vec3 minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double angle_between(const Vec3& a, const Vec3& b)
{
  return std::atan2(std::sqrt(dot(cross(a, b), cross(a, b))), dot(a, b));
}

// Least-squares factor s minimizing sum (s t - l)^2 and the resulting RMS error over the mean l.
struct Scale_fit
{
  double ll = 0, lt = 0, tt = 0, l = 0;
  std::size_t count = 0;
  void add(double length, double uv_length)
  {
    ll += length * length; lt += length * uv_length; tt += uv_length * uv_length; l += length; ++count;
  }
  double scale() const { return tt > 0 ? lt / tt : 0.; }
  double sum_of_squares() const { const double s = scale(); return (std::max)(0., ll - 2 * s * lt + s * s * tt); }
  double relative_rms() const
  {
    return count > 0 && l > 0 ? std::sqrt(sum_of_squares() / double(count)) / (l / double(count)) : 0.;
  }
};

} // namespace Norm_preserving
} // namespace internal

namespace internal {
namespace Norm_preserving {

// The largest coordinate difference along `edges` of the positions `position(v)`, or 1 if that
// is zero or not finite: the unit in which the measures are taken, so that their squares and
// products neither overflow nor underflow at any scale of the input.
template <typename Vertex, typename Position>
double measure_unit(const std::vector<std::array<Vertex, 2> >& edges, Position position)
{
  double unit = 0;
  for(const auto& e : edges)
  {
    const Vec3 p = minus(position(e[0]), position(e[1]));
    for(double x : p)
      unit = (std::max)(unit, std::abs(x));
  }
  return unit > 0 && std::isfinite(unit) ? unit : 1.;
}

inline Vec3 divided(const Vec3& a, double unit) { return {a[0] / unit, a[1] / unit, a[2] / unit}; }

// The measures over `edges` and `triangles` (arrays of vertex handles, all with a uv; every
// side of a triangle among the edges), with `xyz(v)` and `uv(v)` the 3D and uv positions as
// `Vec3`.
template <typename Vertex, typename Xyz, typename Uv>
Parameterization_distortion measure_distortion(const std::vector<std::array<Vertex, 2> >& edges,
                                               const std::vector<std::array<Vertex, 3> >& triangles,
                                               Xyz xyz, Uv uv)
{
  Parameterization_distortion d;
  const double unit = measure_unit(edges, xyz), uv_unit = measure_unit(edges, uv);
  Scale_fit l2_fit, l1_fit;
  for(const auto& e : edges)
  {
    const auto i = e[0], j = e[1];
    const Vec3 p = divided(minus(xyz(i), xyz(j)), unit), t = divided(minus(uv(i), uv(j)), uv_unit);
    l2_fit.add(std::sqrt(dot(p, p)), std::sqrt(dot(t, t)));
    l1_fit.add(std::abs(p[0]) + std::abs(p[1]) + std::abs(p[2]), std::abs(t[0]) + std::abs(t[1]));
  }
  d.edges = l2_fit.count;
  d.scale = l2_fit.scale() * (unit / uv_unit);
  d.edge_length_error = l2_fit.relative_rms();
  d.l1_edge_length_error = l1_fit.relative_rms();
  d.l1_objective = l1_fit.sum_of_squares() * unit * unit;

  const double s = l2_fit.scale(); // from uv in units of `uv_unit` to 3D in units of `unit`
  double positive_area = 0, negative_area = 0, total_area = 0, angle_sum = 0;
  double log_area_squares = 0, stretch_squares = 0, uv_area_sum = 0;
  std::size_t positive = 0, negative = 0, measured = 0;
  for(const auto& v : triangles)
  {
    std::array<Vec3, 3> q, t; // relative to the first corner, in units of `unit`
    for(int k = 0; k < 3; ++k)
    {
      q[k] = divided(minus(xyz(v[k]), xyz(v[0])), unit);
      t[k] = divided(minus(uv(v[k]), uv(v[0])), uv_unit);
      for(int c = 0; c < 2; ++c) t[k][c] *= s;
    }
    const Vec3 n = cross(minus(q[1], q[0]), minus(q[2], q[0]));
    const double area = 0.5 * std::sqrt(dot(n, n));
    const double uv_area = 0.5 * cross(minus(t[1], t[0]), minus(t[2], t[0]))[2];
    ++d.faces;
    total_area += area;
    if(uv_area > 0) { ++positive; positive_area += area; }
    else if(uv_area < 0) { ++negative; negative_area += area; }
    else { ++d.degenerate_uv_faces; continue; }

    for(int k = 0; k < 3; ++k)
    {
      const int a = (k + 1) % 3, b = (k + 2) % 3;
      const double difference = std::abs(angle_between(minus(q[a], q[k]), minus(q[b], q[k])) -
                                         angle_between(minus(t[a], t[k]), minus(t[b], t[k])));
      const double degrees = difference * 180. / 3.14159265358979323846;
      angle_sum += degrees;
      d.max_angle_distortion = (std::max)(d.max_angle_distortion, degrees);
    }
    if(area > 0)
    {
      const double log_ratio = std::log(std::abs(uv_area) / area);
      log_area_squares += log_ratio * log_ratio;
    }
    // Sander et al. 2001: singular values of the Jacobian of the map uv -> 3D.
    const double two_a = 2 * uv_area;
    Vec3 Ss, St;
    for(int c = 0; c < 3; ++c)
    {
      Ss[c] = (q[0][c] * (t[1][1] - t[2][1]) + q[1][c] * (t[2][1] - t[0][1]) + q[2][c] * (t[0][1] - t[1][1])) / two_a;
      St[c] = (q[0][c] * (t[2][0] - t[1][0]) + q[1][c] * (t[0][0] - t[2][0]) + q[2][c] * (t[1][0] - t[0][0])) / two_a;
    }
    const double a = dot(Ss, Ss), b = dot(Ss, St), c = dot(St, St);
    const double largest = std::sqrt(0.5 * ((a + c) + std::sqrt((a - c) * (a - c) + 4 * b * b)));
    stretch_squares += 0.5 * (a + c) * std::abs(uv_area);
    uv_area_sum += std::abs(uv_area);
    d.linf_stretch = (std::max)(d.linf_stretch, largest);
    ++measured;
  }
  if(measured > 0)
  {
    d.mean_angle_distortion = angle_sum / double(3 * measured);
    d.area_distortion = std::sqrt(log_area_squares / double(measured));
    d.l2_stretch = std::sqrt(stretch_squares / uv_area_sum);
  }
  const bool positive_is_reference = positive_area >= negative_area;
  d.flipped_faces = positive_is_reference ? negative : positive;
  d.flipped_area_fraction = total_area > 0 ? (positive_is_reference ? negative_area : positive_area) / total_area : 0.;
  return d;
}

} // namespace Norm_preserving
} // namespace internal

/// \ingroup PkgNormPreservingParameterizationFunctions
/// measures the distortion of `uvmap` on `mesh`; `vpmap` tells which vertices have a uv.
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam VertexUVMap a model of `ReadablePropertyMap` from vertices to a 2D point type
/// \tparam VertexParameterizedMap a model of `ReadablePropertyMap` from vertices to `bool`
/// \param mesh the mesh
/// \param uvmap the uv of each vertex
/// \param vpmap `true` for the vertices that have a uv
/// \param np optional `vertex_point_map` (default: the internal point map of `mesh`)
template <typename TriangleMesh, typename VertexUVMap, typename VertexParameterizedMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Parameterization_distortion measure_distortion(const TriangleMesh& mesh, VertexUVMap uvmap,
                                               VertexParameterizedMap vpmap,
                                               const NamedParameters& np = CGAL::parameters::default_values())
{
  namespace NP = internal::Norm_preserving;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  const auto ppmap = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, mesh));
  auto xyz = [&](auto v) -> NP::Vec3 {
    const auto& p = get(ppmap, v);
    return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  };
  auto uv = [&](auto v) -> NP::Vec3 {
    const auto& p = get(uvmap, v);
    return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), 0.};
  };

  std::vector<std::array<vertex_descriptor, 2> > measured_edges;
  for(auto e : edges(mesh))
  {
    const halfedge_descriptor h = halfedge(e, mesh);
    const vertex_descriptor i = source(h, mesh), j = target(h, mesh);
    if(get(vpmap, i) && get(vpmap, j))
      measured_edges.push_back({i, j});
  }
  std::vector<std::array<vertex_descriptor, 3> > triangles;
  for(auto f : faces(mesh))
  {
    const halfedge_descriptor h = halfedge(f, mesh);
    const std::array<vertex_descriptor, 3> v = {source(h, mesh), target(h, mesh), target(next(h, mesh), mesh)};
    if(get(vpmap, v[0]) && get(vpmap, v[1]) && get(vpmap, v[2]))
      triangles.push_back(v);
  }
  return NP::measure_distortion(measured_edges, triangles, xyz, uv);
}

/// \ingroup PkgNormPreservingParameterizationFunctions
/// measures the distortion of the uv map of a polygon soup, such as `texture_polygon_soup()`
/// computes: each face is triangulated as that function does, and the faces and edges whose
/// vertices all have a uv are measured.
/// \tparam PointRange a random-access range of 3D points (`x()`, `y()`, `z()`)
/// \tparam PolygonRange a random-access range of ranges of integer indices
/// \tparam VertexUVMap a model of `ReadablePropertyMap` from `std::size_t` to a 2D point type
/// \tparam VertexParameterizedMap a model of `ReadablePropertyMap` from `std::size_t` to `bool`
/// \param points the vertex positions
/// \param polygons the faces, as vertex indices in order around each
/// \param uvmap the uv of each vertex
/// \param vpmap `true` for the vertices that have a uv
template <typename PointRange, typename PolygonRange, typename VertexUVMap, typename VertexParameterizedMap>
Parameterization_distortion measure_soup_distortion(const PointRange& points, const PolygonRange& polygons,
                                                    VertexUVMap uvmap, VertexParameterizedMap vpmap)
{
  namespace NP = internal::Norm_preserving;
  std::vector<std::array<std::size_t, 3> > all, triangles;
  triangulate_polygon_soup(points, polygons, std::back_inserter(all), CGAL::Emptyset_iterator());
  std::vector<std::array<std::size_t, 2> > measured_edges;
  for(const std::array<std::size_t, 3>& t : all)
    if(get(vpmap, t[0]) && get(vpmap, t[1]) && get(vpmap, t[2]))
    {
      triangles.push_back(t);
      for(int e = 0; e < 3; ++e)
        measured_edges.push_back({(std::min)(t[e], t[(e + 1) % 3]), (std::max)(t[e], t[(e + 1) % 3])});
    }
  NP::sort_unique_edges(points.size(), measured_edges);
  auto xyz = [&](std::size_t i) -> NP::Vec3 {
    return {CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()), CGAL::to_double(points[i].z())};
  };
  auto uv = [&](std::size_t i) -> NP::Vec3 {
    const auto& p = get(uvmap, i);
    return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), 0.};
  };
  return NP::measure_distortion(measured_edges, triangles, xyz, uv);
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif
