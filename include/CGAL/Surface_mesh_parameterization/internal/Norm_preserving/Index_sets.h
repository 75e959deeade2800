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
// The package's one union-find: Boost's disjoint sets over the indices 0..n-1.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_INDEX_SETS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_INDEX_SETS_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <boost/pending/disjoint_sets.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

// Disjoint sets of the indices 0..n-1, each its own set at first. On iterator property maps,
// whose `get` is found by argument-dependent lookup: with raw pointers, `boost::detail::get` of
// the CSR graph hides it when that header comes first.
class Index_sets
{
  typedef boost::iterator_property_map<std::vector<std::size_t>::iterator, boost::identity_property_map> Index_map;
  std::vector<std::size_t> m_rank, m_parent;

public:
  explicit Index_sets(std::size_t n)
    : m_rank(n, 0), m_parent(n), sets(Index_map(m_rank.begin()), Index_map(m_parent.begin()))
  {
    for(std::size_t i = 0; i < n; ++i)
      sets.make_set(i);
  }
  Index_sets(const Index_sets&) = delete;
  Index_sets& operator=(const Index_sets&) = delete;

  std::size_t find(std::size_t i) { return sets.find_set(i); }
  void join(std::size_t i, std::size_t j) { sets.union_set(i, j); }

  boost::disjoint_sets<Index_map, Index_map> sets;
};

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
