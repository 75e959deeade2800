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
// The cut graph of `cut_to_disk()` by tree-cotree: a shortest-path tree T of the component's
// vertex-edge graph, a spanning tree C of its dual graph that avoids T (the greedy cotree of
// Erickson and Whittlesey, "Greedy optimal homotopy and homology generators", SODA 2005), and
// the cut made of every non-border edge outside C, pruned of its dangling branches. Cutting
// along all edges outside C leaves a tree of faces, which is a disk; pruning keeps it one. On a
// closed surface the cut is the 2g generator loops closed through T; with border loops it also
// holds the tree paths that join them.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_TREE_COTREE_CUT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_TREE_COTREE_CUT_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Index_sets.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Geometry.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

constexpr std::size_t no_index = (std::numeric_limits<std::size_t>::max)();

// The component with its vertices in the mesh's own vertex order and its edges sorted by the
// indices of their ends, so that the cut depends on the component, not on the halfedge that
// designates it.
template <typename TriangleMesh>
struct Indexed_surface
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;

  struct Edge
  {
    std::array<std::size_t, 2> ends;  // vertex indices, lower first
    std::array<std::size_t, 2> faces; // face of `halfedge`, then the other one or `no_index`
    halfedge_descriptor halfedge;     // the halfedge of the edge that has a face
    double length;

    bool is_border() const { return faces[1] == no_index; }
  };

  std::vector<vertex_descriptor> vertices;
  std::vector<Edge> edges;
  std::size_t faces = 0;
  std::size_t root = 0; // smallest x, lowest index on ties
};

template <typename TriangleMesh>
Indexed_surface<TriangleMesh>
index_surface(const TriangleMesh& mesh,
              typename boost::graph_traits<TriangleMesh>::face_descriptor seed)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::vertex_descriptor vertex_descriptor;

  std::vector<face_descriptor> faces;
  CGAL::Polygon_mesh_processing::connected_component(seed, mesh, std::back_inserter(faces));
  auto face_index = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  auto vertex_index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh);
  // First `no_index` off the component and 0 on it, then indices in the mesh's vertex order.
  for(vertex_descriptor v : vertices(mesh))
    put(vertex_index, v, no_index);
  for(std::size_t k = 0; k < faces.size(); ++k)
  {
    put(face_index, faces[k], k);
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(faces[k], mesh), mesh))
      put(vertex_index, v, 0);
  }

  Indexed_surface<TriangleMesh> surface;
  surface.faces = faces.size();
  std::vector<std::array<double, 3> > points;
  const auto ppmap = get(CGAL::vertex_point, mesh);
  for(vertex_descriptor v : vertices(mesh))
  {
    if(get(vertex_index, v) == no_index)
      continue;
    put(vertex_index, v, surface.vertices.size());
    surface.vertices.push_back(v);
    const auto& p = get(ppmap, v);
    points.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
  }
  surface.root = lowest_x_vertex(points);

  // Each edge once: from its halfedge of lower source index, or from its only halfedge with a face.
  for(face_descriptor f : faces)
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
    {
      const std::size_t i = get(vertex_index, source(h, mesh)), j = get(vertex_index, target(h, mesh));
      const face_descriptor g = face(opposite(h, mesh), mesh);
      if(g != GT::null_face() && i > j)
        continue;
      const double length = l2_distance(points[i], points[j]);
      surface.edges.push_back({{(std::min)(i, j), (std::max)(i, j)},
                               {get(face_index, f), g == GT::null_face() ? no_index : get(face_index, g)},
                               h, length});
    }
  std::stable_sort(surface.edges.begin(), surface.edges.end(),
                   [](const auto& a, const auto& b) { return a.ends < b.ends; });
  return surface;
}

// Both directions of every edge, for the shortest-path tree and for pruning.
struct Incidence
{
  std::size_t edge;
  double length;
};
typedef boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, Incidence> Incidence_graph;

template <typename Surface>
Incidence_graph incidence_graph(const Surface& surface)
{
  std::vector<std::pair<std::size_t, std::size_t> > arcs;
  std::vector<Incidence> incidences;
  for(std::size_t e = 0; e < surface.edges.size(); ++e)
    for(int side = 0; side < 2; ++side)
    {
      arcs.emplace_back(surface.edges[e].ends[side], surface.edges[e].ends[1 - side]);
      incidences.push_back({e, surface.edges[e].length});
    }
  return Incidence_graph(boost::edges_are_unsorted_multi_pass, arcs.begin(), arcs.end(),
                         incidences.begin(), surface.vertices.size());
}

struct Shortest_path_tree
{
  std::vector<double> distance;          // from the root, along edges
  std::vector<std::size_t> parent_edge;  // `no_index` at the root
};

// Shortest paths make the generator loops short (Erickson and Whittlesey).
inline Shortest_path_tree shortest_path_tree(const Incidence_graph& graph, std::size_t root)
{
  const std::size_t n = num_vertices(graph);
  Shortest_path_tree tree;
  tree.distance.resize(n);
  std::vector<Incidence_graph::edge_descriptor> parent_arc(n);
  boost::dijkstra_shortest_paths(
    graph, root,
    boost::weight_map(get(&Incidence::length, graph))
      .distance_map(boost::make_iterator_property_map(tree.distance.begin(), get(boost::vertex_index, graph)))
      .visitor(boost::make_dijkstra_visitor(boost::record_edge_predecessors(
        boost::make_iterator_property_map(parent_arc.begin(), get(boost::vertex_index, graph)),
        boost::on_edge_relaxed()))));
  tree.parent_edge.assign(n, no_index);
  for(std::size_t v = 0; v < n; ++v)
    if(v != root)
      tree.parent_edge[v] = graph[parent_arc[v]].edge;
  return tree;
}

// Kruskal on the dual graph (faces across non-border edges): edges outside the tree first,
// longest loop first, so that the edges left over close the shortest loops; tree edges only
// where the rest cannot connect the faces, which happens when the tree and the border
// separate the surface.
template <typename Surface>
std::vector<bool> cotree(const Surface& surface, const Shortest_path_tree& tree)
{
  const auto& edges = surface.edges;
  std::vector<bool> in_tree(edges.size(), false);
  for(std::size_t e : tree.parent_edge)
    if(e != no_index)
      in_tree[e] = true;
  auto loop_length = [&](std::size_t e) {
    return tree.distance[edges[e].ends[0]] + edges[e].length + tree.distance[edges[e].ends[1]];
  };
  std::vector<std::size_t> order;
  for(std::size_t e = 0; e < edges.size(); ++e)
    if(!edges[e].is_border())
      order.push_back(e);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) -> bool {
    if(in_tree[a] != in_tree[b])
      return in_tree[b];
    return loop_length(a) > loop_length(b);
  });

  std::vector<bool> in_cotree(edges.size(), false);
  Index_sets face_sets(surface.faces);
  for(std::size_t e : order)
  {
    const std::size_t f = face_sets.sets.find_set(edges[e].faces[0]);
    const std::size_t g = face_sets.sets.find_set(edges[e].faces[1]);
    if(f == g)
      continue;
    face_sets.sets.link(f, g);
    in_cotree[e] = true;
  }
  return in_cotree;
}

// Removes cut edges that end at a vertex touching no other cut or border edge: re-gluing such
// an edge from its free end keeps the cut surface a disk, unless it is the last cut edge of a
// closed surface, which this also removes (genus 0; the caller then cuts a slit).
template <typename Surface>
void prune_dangling_edges(const Surface& surface, const Incidence_graph& graph, std::vector<bool>& cut)
{
  const auto& edges = surface.edges;
  std::vector<std::size_t> degree(surface.vertices.size(), 0);
  for(std::size_t e = 0; e < edges.size(); ++e)
    if(cut[e] || edges[e].is_border())
    {
      ++degree[edges[e].ends[0]];
      ++degree[edges[e].ends[1]];
    }
  std::vector<std::size_t> tips;
  for(std::size_t v = 0; v < degree.size(); ++v)
    if(degree[v] == 1)
      tips.push_back(v);
  while(!tips.empty())
  {
    const std::size_t v = tips.back();
    tips.pop_back();
    if(degree[v] != 1)
      continue;
    for(auto arc : CGAL::make_range(out_edges(v, graph)))
    {
      const std::size_t e = graph[arc].edge;
      if(!cut[e])
        continue;
      cut[e] = false;
      --degree[v];
      const std::size_t w = target(arc, graph);
      if(--degree[w] == 1)
        tips.push_back(w);
      break;
    }
  }
}

// Number of border loops: connected components of the border edges (the mesh is a 2-manifold).
template <typename Surface>
std::size_t count_border_loops(const Surface& surface)
{
  Index_sets loops(surface.vertices.size());
  std::vector<bool> on_border(surface.vertices.size(), false);
  for(const auto& e : surface.edges)
    if(e.is_border())
    {
      loops.sets.union_set(e.ends[0], e.ends[1]);
      on_border[e.ends[0]] = on_border[e.ends[1]] = true;
    }
  std::size_t count = 0;
  for(std::size_t v = 0; v < on_border.size(); ++v)
    if(on_border[v] && loops.sets.find_set(v) == v)
      ++count;
  return count;
}

template <typename TriangleMesh>
struct Disk_cut
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> vertices; // of the component
  std::vector<halfedge_descriptor> seam;           // one halfedge per cut edge
  double seam_length = 0;
  std::size_t genus = 0;
  std::size_t border_loops = 0;
  halfedge_descriptor border = boost::graph_traits<TriangleMesh>::null_halfedge(); // of the mesh, if any
};

// The cut graph of the component of `seed`. A closed component of genus 0 has no cut graph
// (any tree would do); it is cut along the tree path from the root to the vertex farthest
// from it, a slit that leaves one border loop.
template <typename TriangleMesh>
Error_code tree_cotree_cut(const TriangleMesh& mesh,
                           typename boost::graph_traits<TriangleMesh>::face_descriptor seed,
                           Disk_cut<TriangleMesh>& result,
                           std::string& message)
{
  const Indexed_surface<TriangleMesh> surface = index_surface(mesh, seed);
  const auto& edges = surface.edges;
  for(const auto& e : edges)
    if(!std::isfinite(e.length))
    {
      message = "a vertex of the component has a non-finite coordinate";
      return ERROR_WRONG_PARAMETER;
    }
  result.vertices = surface.vertices;
  result.border_loops = count_border_loops(surface);
  const long euler = long(surface.vertices.size()) - long(edges.size()) + long(surface.faces);
  const long twice_genus = 2 - long(result.border_loops) - euler;
  if(twice_genus < 0 || twice_genus % 2 != 0)
  {
    message = "the component is not an orientable 2-manifold (Euler characteristic " +
              std::to_string(euler) + " with " + std::to_string(result.border_loops) + " border loops)";
    return ERROR_WRONG_PARAMETER;
  }
  result.genus = std::size_t(twice_genus / 2);

  const Incidence_graph graph = incidence_graph(surface);
  const Shortest_path_tree tree = shortest_path_tree(graph, surface.root);
  const std::vector<bool> in_cotree = cotree(surface, tree);
  std::vector<bool> cut(edges.size(), false);
  for(std::size_t e = 0; e < edges.size(); ++e)
    cut[e] = !edges[e].is_border() && !in_cotree[e];
  prune_dangling_edges(surface, graph, cut);

  if(result.border_loops == 0 && result.genus == 0)
  {
    const std::size_t farthest = std::size_t(
      std::max_element(tree.distance.begin(), tree.distance.end()) - tree.distance.begin());
    for(std::size_t v = farthest; v != surface.root; )
    {
      const std::size_t e = tree.parent_edge[v];
      cut[e] = true;
      v = edges[e].ends[0] == v ? edges[e].ends[1] : edges[e].ends[0];
    }
  }

  for(std::size_t e = 0; e < edges.size(); ++e)
  {
    if(cut[e])
    {
      result.seam.push_back(edges[e].halfedge);
      result.seam_length += edges[e].length;
    }
    if(edges[e].is_border() && result.border == boost::graph_traits<TriangleMesh>::null_halfedge())
      result.border = opposite(edges[e].halfedge, mesh);
  }
  return OK;
}

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
