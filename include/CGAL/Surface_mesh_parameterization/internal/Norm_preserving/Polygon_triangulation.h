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
// Step 1 of the paper for one polygon of a soup, adding no vertex: a polygon that passes
// through a vertex twice split into simple polygons, and each of them triangulated.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_POLYGON_TRIANGULATION_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_POLYGON_TRIANGULATION_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/centroid.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

// Splits the closed corner sequence `corners` into polygons of distinct corners: repeats in a
// row (a zero-length side) are dropped, and a corner met again further on cuts the loop
// between its two visits off as a polygon of its own (a figure-eight becomes two loops).
// Appends to `loops`; each loop has 1 corner (a point: only for a polygon of one distinct
// corner), 2 (an edge) or more (a polygon). One pass: a cut leaves the corners before the loop
// as they were.
inline void simple_loops(const std::vector<std::size_t>& corners, std::vector<std::vector<std::size_t> >& loops)
{
  const std::size_t first = loops.size();
  std::vector<std::size_t> rest;
  std::unordered_map<std::size_t, std::size_t> position; // of each corner of `rest` in it
  for(std::size_t c : corners)
  {
    const auto seen = position.find(c);
    if(seen == position.end())
    {
      position.emplace(c, rest.size());
      rest.push_back(c);
      continue;
    }
    // rest[from ..] is a loop that starts and ends at c; a loop of one corner is a repeat in a
    // row and adds nothing.
    const std::size_t from = seen->second;
    if(rest.size() - from > 1)
      loops.emplace_back(rest.begin() + std::ptrdiff_t(from), rest.end());
    for(std::size_t k = from + 1; k < rest.size(); ++k)
      position.erase(rest[k]);
    rest.resize(from + 1);
  }
  if(rest.size() > 1 || (loops.size() == first && !rest.empty()))
    loops.push_back(rest);
}

// The outline projected along the dominant axis of its Newell normal, the coordinates as they
// are: the two other coordinates, in cyclic order (x, y for z; y, z for x; z, x for y).
// Returns false where the normal is zero or, with `flat_only`, where a corner lies farther than
// 1% of the outline's bounding-box diagonal from the plane through its centroid normal to it.
inline bool projection_along_normal(const std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>& outline,
                                    bool flat_only,
                                    std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_2>& projection)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3 Vector_3;
  const std::size_t n = outline.size();
  if(n < 3)
    return false;
  const CGAL::Bbox_3 box = CGAL::bbox_3(outline.begin(), outline.end());
  const double diagonal = std::hypot(box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin());
  if(!(diagonal > 0) || !std::isfinite(diagonal))
    return false;
  // Relative to the centroid and scaled by a power of two (exact) to a diagonal in [1, 2), so
  // that no product overflows or underflows, whatever the coordinates' magnitude.
  const double scale = std::ldexp(1., -std::ilogb(diagonal));
  const auto centroid = CGAL::centroid(outline.begin(), outline.end());
  std::vector<Vector_3> offset;
  offset.reserve(n);
  for(const auto& p : outline)
    offset.push_back(scale * (p - centroid));
  Vector_3 normal = CGAL::NULL_VECTOR;
  for(std::size_t i = 0; i < n; ++i)
    normal = normal + CGAL::cross_product(offset[i], offset[(i + 1) % n]);
  const double length = std::sqrt(normal.squared_length());
  if(!(length > 0) || !std::isfinite(length))
    return false;
  if(flat_only)
    for(const Vector_3& d : offset)
      if(!(std::abs(d * normal) <= 0.01 * scale * diagonal * length))
        return false;
  int axis = 0;
  for(int k = 1; k < 3; ++k)
    if(std::abs(normal[k]) > std::abs(normal[axis])) axis = k;
  projection.clear();
  for(const auto& p : outline)
    projection.emplace_back(p[(axis + 1) % 3], p[(axis + 2) % 3]);
  return true;
}

// Outlines of more corners than this are triangulated in projection even where they are not
// flat: hole filling's search grows as n^3 on them (decisions.md, "Step 1 in the plane of a
// flat polygon").
constexpr std::size_t projected_outline_corners = 100;

// The triangulation of an outline in its plane, as triples of indices into `outline`, each
// oriented like the outline: where projection_along_normal() applies (the outline flat, or of
// more than projected_outline_corners corners) and the projection is a simple polygon (exact
// predicates: distinct points, no side touching another), the constrained Delaunay
// triangulation of the projection inside it. Returns false, with `patch` empty, where that
// does not apply.
inline bool triangulate_in_plane(const std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>& outline,
                                 std::vector<std::array<std::size_t, 3> >& patch)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K> Vb;
  typedef CGAL::Constrained_triangulation_face_base_2<K, CGAL::Triangulation_face_base_with_info_2<bool, K> > Fb;
  typedef CGAL::Constrained_Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<Vb, Fb>,
                                                     CGAL::No_constraint_intersection_tag> Cdt;
  patch.clear();
  std::vector<K::Point_2> projection;
  if(!projection_along_normal(outline, outline.size() <= projected_outline_corners, projection) ||
     !CGAL::is_simple_2(projection.begin(), projection.end(), K()))
    return false;
  const std::size_t n = outline.size();
  const bool clockwise = CGAL::orientation_2(projection.begin(), projection.end(), K()) == CGAL::CLOCKWISE;
  // Every point before any side: a constraint then never meets a new point, so with a simple
  // outline No_constraint_intersection_tag never throws.
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> vertex(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    vertex[i] = cdt.insert(projection[i], i == 0 ? Cdt::Face_handle() : vertex[i - 1]->face());
    vertex[i]->info() = i;
  }
  for(std::size_t i = 0; i < n; ++i)
    cdt.insert_constraint(vertex[i], vertex[(i + 1) % n]);
  // Outside: the faces reached from the infinite one without crossing a side of the outline.
  for(Cdt::Face_handle f : cdt.all_face_handles())
    f->info() = false;
  std::vector<Cdt::Face_handle> stack(1, cdt.infinite_face());
  stack.front()->info() = true;
  while(!stack.empty())
  {
    const Cdt::Face_handle f = stack.back();
    stack.pop_back();
    for(int e = 0; e < 3; ++e)
      if(!f->is_constrained(e) && !f->neighbor(e)->info())
      {
        f->neighbor(e)->info() = true;
        stack.push_back(f->neighbor(e));
      }
  }
  for(Cdt::Face_handle f : cdt.finite_face_handles())
    if(!f->info())
    {
      const std::size_t a = f->vertex(0)->info(), b = f->vertex(1)->info(), c = f->vertex(2)->info();
      patch.push_back(clockwise ? std::array<std::size_t, 3>{a, c, b} : std::array<std::size_t, 3>{a, b, c});
    }
  return true;
}

// Step 1 for one polygon, adding no vertex: a triangle as it is; a quad split along the
// diagonal whose two triangles' normals agree best (as Polygon_mesh_processing::
// triangulate_faces() does); a larger polygon in its plane where that applies
// (triangulate_in_plane()), otherwise by hole filling (triangulate_hole_polyline()) or, where
// neither finds a complete triangulation (a degenerate outline), by a fan from its first
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
  // Complete: n - 2 triangles that use every side of the outline once.
  const auto complete = [n](const std::vector<std::array<std::size_t, 3> >& patch) {
    std::vector<int> sides(n, 0);
    for(const auto& v : patch)
      for(int e = 0; e < 3; ++e)
        if(v[(e + 1) % 3] == (v[e] + 1) % n) ++sides[v[e]];
    return patch.size() == n - 2 && std::all_of(sides.begin(), sides.end(), [](int used) { return used == 1; });
  };
  std::vector<std::array<std::size_t, 3> > patch;
  if(!triangulate_in_plane(outline, patch) || !complete(patch))
  {
    std::vector<CGAL::Triple<int, int, int> > filled;
    CGAL::Polygon_mesh_processing::triangulate_hole_polyline(outline, std::back_inserter(filled));
    patch.clear();
    for(const auto& t : filled)
      patch.push_back({std::size_t(t.first), std::size_t(t.second), std::size_t(t.third)});
  }
  if(complete(patch))
    for(const auto& t : patch)
      triangles.push_back({corner[t[0]], corner[t[1]], corner[t[2]]});
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
