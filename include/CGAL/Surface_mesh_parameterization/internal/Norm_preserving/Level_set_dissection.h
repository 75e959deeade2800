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
// A fill-reducing elimination order whose elimination tree splits into balanced subtrees:
// nested dissection by breadth-first level sets for the first levels, the pieces in AMD's
// order. AMD alone orders some mesh Laplacians so that one subtree of the tree holds most of
// the factor, and the triangular solves, run on one thread per part of the tree
// (Two_column_cholesky.h), then run mostly on one thread. Dissection
// puts a separator last: among the levels of a breadth-first search from a pseudo-peripheral
// vertex that leave at least `least_side` of the piece on each side, the one of fewest
// vertices, less those with no neighbour in the next level (they go to the near side). The
// levels of a breadth-first search are only joined by edges between consecutive levels, so
// the two sides share no edge and their subtrees are disjoint (doc/performance.md, "Sparse
// Cholesky").

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_LEVEL_SET_DISSECTION_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_LEVEL_SET_DISSECTION_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/assertions.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sparse_cholesky.h>

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

class Level_set_dissection
{
public:
  struct Result
  {
    std::vector<int> order;         // the k-th unknown eliminated at k
    // The entries the separators' columns would have in the factor if each separator were a
    // clique joined to the separators around it: at most what those columns hold.
    double separator_entries = 0;
  };

  // The order of the matrix whose whole symmetric pattern is `pattern`, dissected `levels`
  // times (into 2^levels pieces at most), each piece and separator in the order they have in
  // `fill_reducing` (an elimination order of the whole, AMD's).
  static Result order(const Sparse_matrix& pattern, int levels, const std::vector<int>& fill_reducing)
  {
    const std::size_t n = fill_reducing.size();
    CGAL_precondition(n == std::size_t(pattern.rows()));
    Level_set_dissection d(pattern);
    std::vector<int> all(n);
    for(std::size_t i = 0; i < n; ++i)
      all[i] = int(i);
    d.dissect(all, levels, 0);
    // The pieces in the order they were closed, each in the order of `fill_reducing`.
    std::vector<std::size_t> next(std::size_t(d.m_pieces) + 1, 0);
    for(int p : d.m_piece)
      ++next[std::size_t(p) + 1];
    std::partial_sum(next.begin(), next.end(), next.begin());
    d.m_result.order.resize(n);
    for(int v : fill_reducing)
      d.m_result.order[next[std::size_t(d.m_piece[std::size_t(v)])]++] = v;
    return std::move(d.m_result);
  }

private:
  // Pieces smaller than this are not dissected; a separator leaves at least this share of the
  // piece on each side.
  static constexpr std::size_t smallest_dissected = 200;
  static constexpr double least_side = 0.4;

  explicit Level_set_dissection(const Sparse_matrix& pattern)
    : m_pattern(pattern), m_stamp(std::size_t(pattern.rows()), 0), m_level(std::size_t(pattern.rows()), -1),
      m_piece(std::size_t(pattern.rows()), 0)
  { }

  template <typename Function>
  void for_neighbours(int v, const Function& f) const
  {
    for(Sparse_matrix::InnerIterator it(m_pattern, v); it; ++it)
      if(it.index() != v)
        f(int(it.index()));
  }

  // Breadth-first levels within the piece (the vertices of stamp `stamp`) from `start` (-1:
  // not reached); returns the last vertex reached.
  int levels_from(const std::vector<int>& piece, int start, int stamp)
  {
    for(int v : piece)
      m_level[std::size_t(v)] = -1;
    std::vector<int> queue(1, start);
    m_level[std::size_t(start)] = 0;
    for(std::size_t h = 0; h < queue.size(); ++h)
      for_neighbours(queue[h], [&](int j) {
        if(m_stamp[std::size_t(j)] == stamp && m_level[std::size_t(j)] < 0)
        {
          m_level[std::size_t(j)] = m_level[std::size_t(queue[h])] + 1;
          queue.push_back(j);
        }
      });
    return queue.back();
  }

  // Dissects the piece `levels` times; `around`: the vertices of the separators around it.
  void dissect(const std::vector<int>& piece, int levels, std::size_t around)
  {
    if(levels == 0 || piece.size() < smallest_dissected)
      return close(piece);
    const int s = ++m_last_stamp;
    for(int v : piece)
      m_stamp[std::size_t(v)] = s;
    levels_from(piece, levels_from(piece, piece.front(), s), s); // from a pseudo-peripheral vertex
    int deepest = 0;
    for(int v : piece)
      deepest = (std::max)(deepest, m_level[std::size_t(v)]);
    std::vector<std::size_t> count(std::size_t(deepest) + 1, 0); // the unreached are beyond
    for(int v : piece)
      if(m_level[std::size_t(v)] >= 0)
        ++count[std::size_t(m_level[std::size_t(v)])];
    const double size = double(piece.size());
    int separator = -1;
    std::size_t below = 0;
    for(int l = 0; l <= deepest; ++l)
    {
      const std::size_t above = piece.size() - below - count[std::size_t(l)];
      if(double(below) >= least_side * size && double(above) >= least_side * size &&
         (separator < 0 || count[std::size_t(l)] < count[std::size_t(separator)]))
        separator = l;
      below += count[std::size_t(l)];
    }
    if(separator < 0) // no level splits it evenly
      return close(piece);
    std::vector<int> near, far, middle;
    for(int v : piece)
    {
      const int l = m_level[std::size_t(v)];
      bool beyond = false; // a neighbour in the next level
      if(l == separator)
        for_neighbours(v, [&](int j) {
          beyond = beyond || (m_stamp[std::size_t(j)] == s && m_level[std::size_t(j)] == l + 1);
        });
      if(l == separator && beyond)
        middle.push_back(v);
      else if(l >= 0 && l <= separator)
        near.push_back(v);
      else // beyond the separator, or not reached
        far.push_back(v);
    }
    const double width = double(middle.size());
    m_result.separator_entries += width * (width + 1) / 2 + width * double(around);
    dissect(near, levels - 1, around + middle.size());
    dissect(far, levels - 1, around + middle.size());
    close(middle);
  }

  // The piece comes next in the order.
  void close(const std::vector<int>& piece)
  {
    for(int v : piece)
      m_piece[std::size_t(v)] = m_pieces;
    ++m_pieces;
  }

  const Sparse_matrix& m_pattern;
  std::vector<int> m_stamp, m_level;
  int m_last_stamp = 0;
  std::vector<int> m_piece; // of each vertex, numbered in the order the pieces were closed
  int m_pieces = 0;
  Result m_result;
};

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
