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
// Step "extract" of the data flow: the connected component of a halfedge, indexed in the
// order of a vertex index map (or the mesh's own vertex order), with positions, unique edges,
// and validation of the input.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_MESH_COMPONENT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_MESH_COMPONENT_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_initial_guess.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/property_map.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

// The component as the algorithm sees it, plus the way back to the mesh's vertices.
template <typename TriangleMesh>
struct Mesh_component
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Vertex_index_map =
    typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<int> >::type;
  using Vertex_flag_map =
    typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<unsigned char> >::type;

  Norm_preserving_geometry geometry;
  std::vector<vertex_descriptor> vertices; // index -> vertex
  // vertex -> is in the component; a byte, not a bool, which OpenMesh stores as bits
  Vertex_flag_map contains;
  Vertex_index_map index;                  // vertex -> index, valid where `contains`

  bool has(vertex_descriptor v) const { return get(contains, v) != 0; }
};

// The faces around each vertex, over the whole mesh, as offsets into one list: faces that
// share only a vertex (a non-manifold vertex, a "bow tie") are neighbours too, which
// circulating around the vertex does not find where the mesh does not link its fans.
template <typename TriangleMesh>
struct Vertex_faces
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using Vertex_number_map =
    typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<std::size_t> >::const_type;

  Vertex_number_map number;          // vertex -> 0..n-1 in the mesh's vertex order
  std::vector<std::size_t> offset;   // faces of vertex k: incident[offset[k] .. offset[k + 1])
  std::vector<face_descriptor> incident;

  explicit Vertex_faces(const TriangleMesh& mesh)
    : number(get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh))
  {
    std::size_t n = 0;
    for(auto v : vertices(mesh))
      put(number, v, n++);
    offset.assign(n + 1, 0);
    for(face_descriptor f : faces(mesh))
      for(auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
        ++offset[get(number, v) + 1];
    for(std::size_t k = 0; k < n; ++k)
      offset[k + 1] += offset[k];
    incident.resize(offset[n]);
    std::vector<std::size_t> next(offset.begin(), offset.end() - 1);
    for(face_descriptor f : faces(mesh))
      for(auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
        incident[next[get(number, v)]++] = f;
  }
};

// Fills `component` with the component of the face incident to `h` (or to its opposite if
// `h` is a border halfedge), its vertices numbered in the order of `vimap` (ties in the mesh's
// vertex order). Returns OK or an error with a message.
template <typename TriangleMesh, typename VertexIndexMap>
Error_code extract_component(TriangleMesh& mesh,
                             typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h,
                             VertexIndexMap vimap,
                             Mesh_component<TriangleMesh>& component,
                             std::string& message)
{
  using GT = boost::graph_traits<TriangleMesh>;
  using face_descriptor = typename GT::face_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using vertex_descriptor = typename GT::vertex_descriptor;

  if(faces(mesh).empty())
  {
    message = "the mesh has no face";
    return ERROR_EMPTY_MESH;
  }
  if(h == GT::null_halfedge())
  {
    message = "the halfedge is null";
    return ERROR_WRONG_PARAMETER;
  }
  face_descriptor seed = face(h, mesh);
  if(seed == GT::null_face())
    seed = face(opposite(h, mesh), mesh);
  if(seed == GT::null_face())
  {
    message = "the halfedge has no incident face";
    return ERROR_WRONG_PARAMETER;
  }

  // Faces of the component, breadth first through shared vertices; each face validated as a
  // proper triangle.
  const Vertex_faces<TriangleMesh> around(mesh);
  auto in_component = get(CGAL::dynamic_face_property_t<unsigned char>(), mesh);
  component.contains = get(CGAL::dynamic_vertex_property_t<unsigned char>(), mesh);
  for(face_descriptor f : faces(mesh))
    put(in_component, f, 0);
  for(vertex_descriptor v : vertices(mesh))
    put(component.contains, v, 0);
  std::vector<face_descriptor> queue(1, seed);
  put(in_component, seed, 1);
  for(std::size_t k = 0; k < queue.size(); ++k)
  {
    const face_descriptor f = queue[k];
    std::array<vertex_descriptor, 3> corners;
    std::size_t degree = 0;
    for(halfedge_descriptor fh : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
    {
      const vertex_descriptor v = target(fh, mesh);
      if(degree < 3) corners[degree] = v;
      ++degree;
      if(get(component.contains, v))
        continue;
      put(component.contains, v, 1);
      const std::size_t number = get(around.number, v);
      for(std::size_t i = around.offset[number]; i < around.offset[number + 1]; ++i)
        if(!get(in_component, around.incident[i]))
        {
          put(in_component, around.incident[i], 1);
          queue.push_back(around.incident[i]);
        }
    }
    if(degree != 3)
    {
      message = "a face has " + std::to_string(degree) + " vertices; triangulate the mesh first";
      return ERROR_NON_TRIANGULAR_MESH;
    }
    if(corners[0] == corners[1] || corners[1] == corners[2] || corners[0] == corners[2])
    {
      message = "a face has a repeated vertex";
      return ERROR_NON_TRIANGULAR_MESH;
    }
  }

  component.index = get(CGAL::dynamic_vertex_property_t<int>(), mesh);
  component.vertices.clear();
  component.geometry.points.clear();
  std::vector<vertex_descriptor> ordered;
  for(vertex_descriptor v : vertices(mesh))
    if(component.has(v))
      ordered.push_back(v);
  std::stable_sort(ordered.begin(), ordered.end(),
                   [&](vertex_descriptor a, vertex_descriptor b) { return get(vimap, a) < get(vimap, b); });
  const auto ppmap = get(CGAL::vertex_point, mesh);
  for(vertex_descriptor v : ordered)
  {
    const auto& p = get(ppmap, v);
    const std::array<double, 3> xyz = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    if(!(std::isfinite(xyz[0]) && std::isfinite(xyz[1]) && std::isfinite(xyz[2])))
    {
      message = "vertex " + std::to_string(component.vertices.size()) + " of the component has a non-finite coordinate";
      return ERROR_WRONG_PARAMETER;
    }
    put(component.index, v, int(component.vertices.size()));
    component.vertices.push_back(v);
    component.geometry.points.push_back(xyz);
  }

  // Each edge once: from the halfedge whose source index is lower, or whose opposite is a border.
  auto& edges = component.geometry.edges;
  edges.clear();
  for(face_descriptor f : queue)
    for(halfedge_descriptor fh : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
    {
      const std::size_t i = std::size_t(get(component.index, source(fh, mesh)));
      const std::size_t j = std::size_t(get(component.index, target(fh, mesh)));
      if(i < j || is_border(opposite(fh, mesh), mesh))
        edges.push_back({(std::min)(i, j), (std::max)(i, j)});
    }
  std::sort(edges.begin(), edges.end());
  return OK;
}

// extract_component() with the vertices numbered in the mesh's vertex order.
template <typename TriangleMesh>
Error_code extract_component(TriangleMesh& mesh,
                             typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h,
                             Mesh_component<TriangleMesh>& component,
                             std::string& message)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  return extract_component(mesh, h, CGAL::Constant_property_map<vertex_descriptor, int>(0), component, message);
}

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
