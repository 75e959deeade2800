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
// Runs independent pieces of work on several threads when the package is built with TBB
// (CGAL_LINKED_WITH_TBB), one after the other otherwise. The callers split their work into
// a number of pieces that does not depend on the number of threads and combine the pieces'
// results in a fixed order, so a run on one thread gives the same bits as a run on many.
// (CGAL::for_each calls its functor through a std::function per element; the loops here are
// over blocks and parts, with a plain call.)

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_PARALLEL_FOR_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_PARALLEL_FOR_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/assertions.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cstddef>
#include <type_traits>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

// Returns f(): with `CGAL::Sequential_tag`, every loop below that f() runs stays on the calling
// thread (a TBB arena of one thread); with `CGAL::Parallel_tag` they may use all of TBB's.
// Both give the same bits.
template <typename ConcurrencyTag, typename Function>
auto run_with_concurrency(const Function& f)
{
  static_assert(std::is_same<ConcurrencyTag, CGAL::Sequential_tag>::value ||
                std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "ConcurrencyTag: CGAL::Sequential_tag, CGAL::Parallel_tag or CGAL::Parallel_if_available_tag");
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr(std::is_same<ConcurrencyTag, CGAL::Sequential_tag>::value)
  {
    tbb::task_arena one_thread(1);
    return one_thread.execute(f);
  }
  else
    return f();
#else
  static_assert(!std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "Parallel_tag is enabled but TBB is unavailable.");
  return f();
#endif
}

// Calls f(0), ..., f(count - 1), in any order and possibly at once (one piece alone runs on
// the calling thread).
template <typename Function>
void parallel_for_each_index(std::size_t count, const Function& f)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(count > 1)
  {
    tbb::parallel_for(std::size_t(0), count, f);
    return;
  }
#endif
  for(std::size_t i = 0; i < count; ++i)
    f(i);
}

// Calls f(0), ..., f(count - 1) like parallel_for_each_index(), for pieces that run parallel
// loops of their own: a thread that waits inside one piece's loop helps only that piece (it
// does not start another piece, which would hold up the loop it waits on).
template <typename Function>
void parallel_for_each_task(std::size_t count, const Function& f)
{
#ifdef CGAL_LINKED_WITH_TBB
  parallel_for_each_index(count, [&](std::size_t i) { tbb::this_task_arena::isolate([&] { f(i); }); });
#else
  parallel_for_each_index(count, f);
#endif
}

// Calls f(begin, end) on consecutive blocks of [0, size) of `block` indices (the last one
// shorter), in any order and possibly at once.
template <typename Function>
void parallel_for_each_block(std::size_t size, std::size_t block, const Function& f)
{
  parallel_for_each_index((size + block - 1) / block, [&](std::size_t b) {
    f(b * block, (std::min)(size, (b + 1) * block));
  });
}

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
