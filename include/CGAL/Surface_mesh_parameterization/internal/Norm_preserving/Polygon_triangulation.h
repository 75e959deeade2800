// Copyright (c) 2026 The CGAL_norm_preserving_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Step 1 of the paper for one polygon of a soup, adding no vertex: a polygon that passes
// through a vertex twice split into simple polygons, and each of them triangulated.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_POLYGON_TRIANGULATION_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_POLYGON_TRIANGULATION_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

// Splits the closed corner sequence `corners` into polygons of distinct corners: repeats in a
// row (a zero-length side) are dropped, and a corner met again further on cuts the loop
// between its two visits off as a polygon of its own (a figure-eight becomes two loops).
// Appends to `loops`; each loop has 1 corner (a point: only for a polygon of one distinct
// corner), 2 (an edge) or more (a polygon).
inline void simple_loops(std::vector<std::size_t> corners, std::vector<std::vector<std::size_t> >& loops)
{
  const std::size_t first = loops.size();
  std::vector<std::size_t> rest;
  while(!corners.empty())
  {
    rest.clear();
    std::size_t cut = corners.size(), from = 0;
    for(std::size_t k = 0; k < corners.size() && cut == corners.size(); ++k)
    {
      const auto seen = std::find(rest.begin(), rest.end(), corners[k]);
      if(seen == rest.end())
        rest.push_back(corners[k]);
      else
      {
        from = std::size_t(seen - rest.begin());
        cut = k;
      }
    }
    if(cut == corners.size())
    {
      if(rest.size() > 1 || loops.size() == first)
        loops.push_back(rest);
      return;
    }
    // corners[from .. cut) is a loop that starts and ends at corners[cut]; a loop of one
    // corner is a repeat in a row and adds nothing.
    if(cut - from > 1)
      loops.emplace_back(corners.begin() + std::ptrdiff_t(from), corners.begin() + std::ptrdiff_t(cut));
    corners.erase(corners.begin() + std::ptrdiff_t(from), corners.begin() + std::ptrdiff_t(cut));
  }
}

// Step 1 for one polygon, adding no vertex: a triangle as it is; a quad split along the
// diagonal whose two triangles' normals agree best (as Polygon_mesh_processing::
// triangulate_faces() does); a larger polygon by hole filling (triangulate_hole_polyline()) or,
// where that finds no complete triangulation (a degenerate outline), by a fan from its first
// vertex. Not triangulate_faces() itself: on a polygon whose projection crosses itself its
// constrained Delaunay triangulation inserts the crossings as new vertices, and its hole
// filling builds an incomplete patch into the mesh; in both cases CGAL 5.5 then reads past the
// end of the halfedges (found by the fuzzer).
template <typename PointRange, typename Polygon>
void triangulate_polygon(const PointRange& points, const Polygon& polygon,
                         std::vector<std::array<std::size_t, 3> >& triangles)
{
  // Exact predicates: hole filling searches a 3D Delaunay triangulation, which asserts (or
  // loops) on the rounding errors of inexact ones (found by the fuzzer).
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 Point_3;
  const std::vector<std::size_t> corner(polygon.begin(), polygon.end());
  const std::size_t n = corner.size();
  std::vector<Point_3> outline;
  for(std::size_t i : corner)
    outline.emplace_back(CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()), CGAL::to_double(points[i].z()));
  triangles.clear();
  if(n == 3)
  {
    triangles.push_back({corner[0], corner[1], corner[2]});
    return;
  }
  if(n == 4)
  {
    const auto normal = [&outline](int a, int b, int c) {
      return CGAL::cross_product(outline[b] - outline[a], outline[c] - outline[a]);
    };
    if(normal(0, 1, 2) * normal(0, 2, 3) > normal(1, 2, 3) * normal(1, 3, 0))
      triangles = {{corner[0], corner[1], corner[2]}, {corner[0], corner[2], corner[3]}};
    else
      triangles = {{corner[1], corner[2], corner[3]}, {corner[1], corner[3], corner[0]}};
    return;
  }
  std::vector<CGAL::Triple<int, int, int> > patch;
  CGAL::Polygon_mesh_processing::triangulate_hole_polyline(outline, std::back_inserter(patch));
  // Complete: n - 2 triangles that use every side of the outline once.
  std::vector<int> sides(n, 0);
  for(const auto& t : patch)
  {
    const std::array<std::size_t, 3> v = {std::size_t(t.first), std::size_t(t.second), std::size_t(t.third)};
    for(int e = 0; e < 3; ++e)
      if(v[(e + 1) % 3] == (v[e] + 1) % n) ++sides[v[e]];
  }
  if(patch.size() == n - 2 && std::all_of(sides.begin(), sides.end(), [](int used) { return used == 1; }))
    for(const auto& t : patch)
      triangles.push_back({corner[std::size_t(t.first)], corner[std::size_t(t.second)], corner[std::size_t(t.third)]});
  else
    for(std::size_t i = 1; i + 1 < n; ++i)
      triangles.push_back({corner[0], corner[i], corner[i + 1]});
}

// One polygon of a soup, in pieces: a proper triangle as it is; otherwise its simple loops,
// each of two corners handed to `edge(i, j)`, each larger one triangulated and its triangles
// handed to `triangle(t)`. Returns how many corners the loops kept (the rest were repeats).
// Keeps its buffers from one polygon to the next.
class Polygon_pieces
{
public:
  template <typename PointRange, typename Edge, typename Triangle>
  std::size_t split(const PointRange& points, const std::vector<std::size_t>& corners, Edge edge, Triangle triangle)
  {
    if(corners.size() == 3 && corners[0] != corners[1] && corners[1] != corners[2] && corners[0] != corners[2])
    {
      triangle({corners[0], corners[1], corners[2]});
      return 3;
    }
    m_loops.clear();
    simple_loops(corners, m_loops);
    std::size_t kept = 0;
    for(const auto& loop : m_loops)
    {
      kept += loop.size();
      if(loop.size() == 2)
        edge(loop[0], loop[1]);
      else if(loop.size() > 2)
      {
        triangulate_polygon(points, loop, m_triangles);
        for(const auto& t : m_triangles)
          triangle(t);
      }
    }
    return kept;
  }

private:
  std::vector<std::vector<std::size_t> > m_loops;
  std::vector<std::array<std::size_t, 3> > m_triangles;
};

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
