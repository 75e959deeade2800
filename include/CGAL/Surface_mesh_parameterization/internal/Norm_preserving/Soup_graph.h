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
// Step "extract" for a polygon soup: the edge graph the method works on, built from points
// and polygons with no halfedge structure, so that any soup is accepted as it is (non-manifold
// edges and vertices, inconsistent orientation, non-orientable surfaces, duplicate faces,
// repeated corners). Coincident vertices are welded (optionally), every polygon is triangulated
// on its own (paper step 1), the unique edges of the triangles are the graph, and its
// connected components are the pieces the pipeline maps (doc/decisions.md, "Input and triangulation").

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_SOUP_GRAPH_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_SOUP_GRAPH_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Index_sets.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Polygon_triangulation.h>

#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

// What the soup is made of, for the solve.
struct Soup_graph
{
  static constexpr std::size_t none = std::size_t(-1);

  // soup vertex -> the soup vertex it is welded to (the lowest index at its position; itself
  // if not welded), `none` if on no polygon
  std::vector<std::size_t> representative;
  std::vector<std::array<double, 3> > positions;          // of the vertices, by soup index
  std::vector<std::array<std::size_t, 2> > edges;         // representatives, {i, j} with i < j, sorted
  std::vector<std::size_t> component;                     // representative -> component, `none` if not one
  std::vector<std::vector<std::size_t> > members;         // component -> its representatives, increasing
  std::size_t welded = 0;                                 // vertices merged into another
  std::size_t unreferenced = 0;                           // vertices on no polygon
  std::size_t repeated_corners = 0;                       // polygon corners dropped as repeats
};

// Positions read as points, for the triangulation of the polygons.
struct Position_points
{
  const std::vector<std::array<double, 3> >& positions;
  CGAL::Simple_cartesian<double>::Point_3 operator[](std::size_t i) const
  {
    return {positions[i][0], positions[i][1], positions[i][2]};
  }
};

// What nothing downstream can take: no polygon, a polygon corner that is not a vertex, a
// non-finite position of a vertex on a polygon.
template <typename PolygonRange>
Error_code check_polygon_soup(const std::vector<std::array<double, 3> >& positions, const PolygonRange& polygons,
                              std::string& message)
{
  if(polygons.empty())
  {
    message = "the mesh has no face";
    return ERROR_EMPTY_MESH;
  }
  std::size_t k = 0;
  for(const auto& polygon : polygons)
  {
    for(const auto& corner : polygon)
    {
      const std::size_t i = std::size_t(corner);
      if(i >= positions.size())
      {
        message = "face " + std::to_string(k) + " refers to vertex " + std::to_string(i) + " of " +
                  std::to_string(positions.size());
        return ERROR_WRONG_PARAMETER;
      }
      const std::array<double, 3>& p = positions[i];
      if(!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])))
      {
        message = "vertex " + std::to_string(i) + " has a non-finite coordinate";
        return ERROR_WRONG_PARAMETER;
      }
    }
    ++k;
  }
  return OK;
}

// `representative` and `welded` of a checked soup: referenced vertices at exactly the same
// position share the lowest index among them if `weld`, otherwise each is its own.
inline void weld_vertices(Soup_graph& graph, bool weld)
{
  if(!weld)
    return;
  std::vector<std::size_t> referenced;
  for(std::size_t i = 0; i < graph.representative.size(); ++i)
    if(graph.representative[i] != Soup_graph::none)
      referenced.push_back(i);
  const auto& p = graph.positions;
  std::sort(referenced.begin(), referenced.end(), [&p](std::size_t i, std::size_t j) {
    return p[i] < p[j] || (p[i] == p[j] && i < j);
  });
  for(std::size_t k = 1; k < referenced.size(); ++k)
  {
    const std::size_t previous = referenced[k - 1], i = referenced[k];
    if(p[i] == p[previous])
    {
      graph.representative[i] = graph.representative[previous];
      ++graph.welded;
    }
  }
}

// Sorts `edges` ({i, j}, i < j < n) and removes repeats: bucketed by their first vertex, each
// bucket (a vertex's few higher neighbours) sorted on its own, faster than one sort of them
// all.
inline void sort_unique_edges(std::size_t n, std::vector<std::array<std::size_t, 2> >& edges)
{
  std::vector<std::size_t> first(n + 1, 0), second(edges.size());
  for(const std::array<std::size_t, 2>& e : edges)
    ++first[e[0] + 1];
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<std::size_t> next(first.begin(), first.end() - 1);
  for(const std::array<std::size_t, 2>& e : edges)
    second[next[e[0]]++] = e[1];
  edges.clear();
  for(std::size_t i = 0; i < n; ++i)
  {
    const auto begin = second.begin() + std::ptrdiff_t(first[i]), end = second.begin() + std::ptrdiff_t(first[i + 1]);
    std::sort(begin, end);
    for(auto j = begin; j != end; ++j)
      if(j == begin || *j != *(j - 1))
        edges.push_back({i, *j});
  }
}

// Builds the edge graph of a checked soup and its connected components, numbered in the
// order of their first polygon. Linear in the size of the soup but for the sorts.
template <typename PolygonRange>
Soup_graph build_soup_graph(std::vector<std::array<double, 3> > positions, const PolygonRange& polygons, bool weld)
{
  Soup_graph graph;
  const std::size_t n = positions.size();
  graph.positions = std::move(positions);
  graph.representative.assign(n, Soup_graph::none);
  for(const auto& polygon : polygons)
    for(const auto& corner : polygon)
      graph.representative[std::size_t(corner)] = std::size_t(corner);
  graph.unreferenced = std::size_t(std::count(graph.representative.begin(), graph.representative.end(), Soup_graph::none));
  weld_vertices(graph, weld);
  const Position_points points{graph.positions};

  // Each polygon through the weld, split into simple loops and triangulated.
  Index_sets connected(n);
  std::vector<std::size_t> corners;
  Polygon_pieces pieces;
  std::vector<std::size_t> first_corners; // a representative of each polygon, for the numbering
  const auto add_edge = [&](std::size_t i, std::size_t j) {
    graph.edges.push_back({(std::min)(i, j), (std::max)(i, j)});
    connected.join(i, j);
  };
  for(const auto& polygon : polygons)
  {
    corners.clear();
    for(const auto& corner : polygon)
      corners.push_back(graph.representative[std::size_t(corner)]);
    if(corners.empty())
      continue;
    first_corners.push_back(corners.front());
    const std::size_t kept = pieces.split(points, corners,
      [&](std::size_t i, std::size_t j) { add_edge(i, j); },
      [&](const std::array<std::size_t, 3>& t) {
        for(int e = 0; e < 3; ++e)
          add_edge(t[std::size_t(e)], t[std::size_t((e + 1) % 3)]);
      });
    graph.repeated_corners += corners.size() - kept;
  }
  sort_unique_edges(n, graph.edges);

  std::vector<std::size_t> number(n, Soup_graph::none);
  for(std::size_t i : first_corners)
  {
    std::size_t& c = number[connected.find(i)];
    if(c == Soup_graph::none)
    {
      c = graph.members.size();
      graph.members.emplace_back();
    }
  }
  graph.component.assign(n, Soup_graph::none);
  for(std::size_t i = 0; i < n; ++i)
    if(graph.representative[i] == i)
    {
      graph.component[i] = number[connected.find(i)];
      graph.members[graph.component[i]].push_back(i);
    }
  return graph;
}

// The geometry of component `c`: its representatives in increasing soup order, its edges in
// those indices, sorted. `local` maps a representative to its index (filled for this component).
inline Norm_preserving_geometry component_geometry(const Soup_graph& graph, std::size_t c,
                                                   const std::vector<std::vector<std::size_t> >& edges_of,
                                                   std::vector<std::size_t>& local)
{
  Norm_preserving_geometry geometry;
  const std::vector<std::size_t>& members = graph.members[c];
  geometry.points.reserve(members.size());
  for(std::size_t k = 0; k < members.size(); ++k)
  {
    local[members[k]] = k;
    geometry.points.push_back(graph.positions[members[k]]);
  }
  geometry.edges.reserve(edges_of[c].size());
  for(std::size_t e : edges_of[c])
    geometry.edges.push_back({local[graph.edges[e][0]], local[graph.edges[e][1]]});
  return geometry;
}

// The edges of each component, in the graph's (sorted) order.
inline std::vector<std::vector<std::size_t> > edges_by_component(const Soup_graph& graph)
{
  std::vector<std::vector<std::size_t> > edges_of(graph.members.size());
  for(std::size_t e = 0; e < graph.edges.size(); ++e)
    edges_of[graph.component[graph.edges[e][0]]].push_back(e);
  return edges_of;
}

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
