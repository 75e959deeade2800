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
// The progress of a whole-mesh call, gathered from its components (which may run at once on
// several threads) and handed to the caller's callback one call at a time.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_CALL_PROGRESS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_CALL_PROGRESS_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Norm_preserving_progress.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <functional>
#include <mutex>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

using Progress_callback = std::function<bool(const Norm_preserving_progress&)>;

class Call_progress
{
public:
  // `members`: the vertices of each component, which weigh its share of the work.
  Call_progress(const Progress_callback& callback, const std::vector<std::vector<std::size_t> >& members,
                std::chrono::steady_clock::time_point start)
    : m_callback(callback), m_fraction(members.size(), 0.), m_start(start)
  {
    m_weight.reserve(members.size());
    double total = 0;
    for(const auto& m : members)
      total += double(m.size());
    for(const auto& m : members)
      m_weight.push_back(total > 0 ? double(m.size()) / total : 0.);
  }

  bool active() const { return bool(m_callback); }

  // Component `c` is `fraction` of the way; false once the callback has asked to stop.
  bool update(std::size_t c, double fraction)
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    if(m_stopped)
      return false;
    m_fraction[c] = (std::max)(m_fraction[c], fraction);
    return call();
  }

  void finish(std::size_t c)
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_fraction[c] = 1;
    ++m_done;
    if(!m_stopped)
      call();
  }

  bool stopped() const { return m_stopped; }

private:
  bool call()
  {
    if(!m_callback)
      return true;
    Norm_preserving_progress p;
    p.components = m_fraction.size();
    p.components_done = m_done;
    for(std::size_t c = 0; c < m_fraction.size(); ++c)
      p.fraction += m_weight[c] * m_fraction[c];
    p.fraction = (std::min)(1., p.fraction);
    p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    m_stopped = !m_callback(p);
    return !m_stopped;
  }

  const Progress_callback& m_callback;
  std::vector<double> m_fraction, m_weight;
  std::chrono::steady_clock::time_point m_start;
  std::mutex m_mutex;
  std::size_t m_done = 0;
  bool m_stopped = false;
};

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
