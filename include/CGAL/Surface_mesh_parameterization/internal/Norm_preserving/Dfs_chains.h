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
// Section 4.3 of the paper (doc/decisions.md, 7): the depth-first search of the component's
// vertex-edge graph, longest edge first, and the decomposition of its tree into the chains
// along which the graph-based initial guess is interpolated.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_DFS_CHAINS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_DFS_CHAINS_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Norm_preserving_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Geometry.h>

#include <CGAL/assertions.h>

#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/graph/depth_first_search.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

// The depth-first search and its chains.
//
// `chains[0]` is the primary list P_1..P_n: the root, then first tree children down to a leaf.
// Each later chain starts at the tree parent of its first new vertex (a vertex of an earlier
// chain), descends through first children to a leaf and, when the leaf has an edge to a vertex
// of an earlier chain other than its parent, ends there: the longest such edge (lowest index
// on ties), a back edge of the search. Otherwise (every non-tree edge of the leaf goes back
// into its own chain) the chain ends at the leaf, which keeps the value it has.
// Every vertex is new (neither first nor closing vertex) in exactly one chain, and the chains
// come in the order in which their first new vertex was discovered, so both ends of a chain
// belong to chains before it.
struct Dfs_chains
{
  std::vector<std::size_t> order;  // vertices in discovery order
  std::vector<std::size_t> parent; // parent in the search tree; a root is its own parent
  std::vector<std::vector<std::size_t> > chains;
};

typedef boost::compressed_sparse_row_graph<boost::directedS> Longest_first_graph;

inline double squared_euclidean_distance(const std::array<double, 3>& p, const std::array<double, 3>& q)
{
  const double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
  return dx * dx + dy * dy + dz * dz;
}

// Both directions of every edge, each vertex's out-edges longest (3D Euclidean) first and
// lowest neighbour index on ties, so that the search takes the longest edge first (the paper).
// Rows are filled by counting and sorted one by one: O(m log d) for maximal degree d.
inline Longest_first_graph longest_first_graph(const Norm_preserving_geometry& geometry)
{
  const auto& points = geometry.points;
  const std::size_t n = points.size();
  std::vector<std::size_t> row_start(n + 1, 0);
  for(const auto& e : geometry.edges)
  {
    ++row_start[e[0] + 1];
    ++row_start[e[1] + 1];
  }
  for(std::size_t i = 0; i < n; ++i)
    row_start[i + 1] += row_start[i];

  std::vector<std::pair<std::size_t, std::size_t> > arcs(row_start[n]);
  std::vector<std::size_t> next(row_start.begin(), row_start.end() - 1);
  for(const auto& e : geometry.edges)
  {
    arcs[next[e[0]]++] = {e[0], e[1]};
    arcs[next[e[1]]++] = {e[1], e[0]};
  }
  // Sorting (-squared length, neighbour) pairs computes each length once.
  std::vector<std::pair<double, std::size_t> > row;
  for(std::size_t i = 0; i < n; ++i)
  {
    row.clear();
    for(std::size_t k = row_start[i]; k < row_start[i + 1]; ++k)
      row.emplace_back(-squared_euclidean_distance(points[i], points[arcs[k].second]), arcs[k].second);
    std::sort(row.begin(), row.end());
    for(std::size_t k = row_start[i]; k < row_start[i + 1]; ++k)
      arcs[k].second = row[k - row_start[i]].second;
  }
  return Longest_first_graph(boost::edges_are_sorted, arcs.begin(), arcs.end(), n, arcs.size());
}

// Builds the chains while the search runs. Boost copies visitors, so the state lives outside.
class Chain_recorder : public boost::default_dfs_visitor
{
public:
  static constexpr std::size_t none = (std::numeric_limits<std::size_t>::max)();

  struct State
  {
    explicit State(std::size_t n) : chain_of(n, none), closing(n, none), has_child(n, false) { }
    std::vector<std::size_t> chain_of; // the chain in which a vertex is new
    std::vector<std::size_t> closing;  // first back edge target that closes a chain, per vertex
    std::vector<bool> has_child;
  };

  Chain_recorder(Dfs_chains& result, State& state) : m_result(&result), m_state(&state) { }

  template <typename Edge, typename Graph>
  void tree_edge(Edge e, const Graph& graph) const
  {
    m_result->parent[target(e, graph)] = source(e, graph);
  }

  template <typename Vertex, typename Graph>
  void discover_vertex(Vertex v, const Graph&) const
  {
    auto& chains = m_result->chains;
    m_result->order.push_back(v);
    const std::size_t p = m_result->parent[v];
    if(p == v)
      chains.push_back({v});
    else if(!m_state->has_child[p])
    {
      // The first child is discovered right after its parent: its chain is the last one.
      CGAL_assertion(m_state->chain_of[p] + 1 == chains.size());
      chains.back().push_back(v);
    }
    else
      chains.push_back({p, v});
    if(p != v)
      m_state->has_child[p] = true;
    m_state->chain_of[v] = chains.size() - 1;
  }

  // Out-edges come longest first, so the first back edge into an earlier chain is the longest.
  template <typename Edge, typename Graph>
  void back_edge(Edge e, const Graph& graph) const
  {
    const std::size_t u = source(e, graph), w = target(e, graph);
    if(m_state->closing[u] == none && w != m_result->parent[u] &&
       m_state->chain_of[w] < m_state->chain_of[u])
      m_state->closing[u] = w;
  }

  // A leaf ends the last chain; a chain that begins at a root (its first vertex is new in it)
  // is the primary list of its component and stays open, as in the paper.
  template <typename Vertex, typename Graph>
  void finish_vertex(Vertex u, const Graph&) const
  {
    if(m_state->has_child[u])
      return;
    auto& chain = m_result->chains.back();
    const bool branch = m_state->chain_of[chain.front()] != m_state->chain_of[u];
    if(branch && m_state->closing[u] != none)
      chain.push_back(m_state->closing[u]);
  }

private:
  Dfs_chains* m_result;
  State* m_state;
};

// The search starts at the vertex of smallest x (lowest index on ties); should the geometry
// not be connected, each further component starts at its lowest index and has its own
// primary list. O(m log d) for the graph, O(n + m) for the search.
inline Dfs_chains dfs_chains(const Norm_preserving_geometry& geometry)
{
  const auto& points = geometry.points;
  const std::size_t n = points.size();
  Dfs_chains result;
  if(n == 0)
    return result;
  result.order.reserve(n);
  result.parent.resize(n);
  for(std::size_t i = 0; i < n; ++i)
    result.parent[i] = i;
  const std::size_t root = lowest_x_vertex(points);

  const Longest_first_graph graph = longest_first_graph(geometry);
  Chain_recorder::State state(n);
  boost::depth_first_search(graph, boost::visitor(Chain_recorder(result, state)).root_vertex(root));
  return result;
}

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
