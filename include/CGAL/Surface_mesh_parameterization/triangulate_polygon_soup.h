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
/// \file triangulate_polygon_soup.h
/// \ingroup PkgNormPreservingParameterization
/// The triangles that the whole-soup calls map.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_TRIANGULATE_POLYGON_SOUP_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_TRIANGULATE_POLYGON_SOUP_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/disable_warnings.h>

#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Polygon_triangulation.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterizationFunctions
/// triangulates each face of a polygon soup as `texture_polygon_soup()` does, adding no vertex:
/// a face is split where it passes through a vertex more than once (a repeat in a row is
/// dropped), each loop of three or more vertices is triangulated on its own, and a loop of two
/// vertices is an edge. Writes the triangles, as vertex indices, to `triangles`, and the edges of
/// two-vertex loops to `edges`, face after face. For a file writer that needs triangles (glTF)
/// and the same faces the map was made on.
///
/// \tparam PointRange a random-access range of 3D points (`x()`, `y()`, `z()`)
/// \tparam PolygonRange a range of ranges of integer indices
/// \tparam TriangleOutputIterator an output iterator of `std::array<std::size_t, 3>`
/// \tparam EdgeOutputIterator an output iterator of `std::array<std::size_t, 2>`
template <typename PointRange, typename PolygonRange, typename TriangleOutputIterator, typename EdgeOutputIterator>
void triangulate_polygon_soup(const PointRange& points, const PolygonRange& polygons, TriangleOutputIterator triangles,
                              EdgeOutputIterator edges)
{
  internal::Norm_preserving::Polygon_pieces pieces;
  std::vector<std::size_t> corners;
  for(const auto& polygon : polygons)
  {
    corners.assign(polygon.begin(), polygon.end());
    pieces.split(points, corners, [&](std::size_t i, std::size_t j) { *edges++ = std::array<std::size_t, 2>{i, j}; },
                 [&](const std::array<std::size_t, 3>& t) { *triangles++ = t; });
  }
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif
