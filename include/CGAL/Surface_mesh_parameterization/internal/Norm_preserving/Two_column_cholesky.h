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
// Sparse Cholesky factorization L L' = P A P' of a symmetric positive definite matrix, kept
// in simplicial form with a solve for two right-hand sides at once, stored interleaved
// (x0 y0 x1 y1 ...): the ADMM solver's inner loop solves the same Laplacian for u and v in
// every iteration, and one pass over the factor for both is faster than two column solves
// (and than CHOLMOD's supernodal solve, whose BLAS calls are tiny for two columns). The
// factorization is CHOLMOD's from `cholmod_minimum_rows` rows when the package is configured
// with CHOLMOD (ordered by AMD, or by METIS where AMD's factor fills much), converted to LL' in
// simplicial form; otherwise the package's own simplicial LL', in AMD's order or, where AMD's
// elimination tree would leave most of a solve to one thread, a level-set dissection's
// (Level_set_dissection.h). Why each: doc/performance.md, "Sparse Cholesky".
//
// The solve goes through the factor by supernodes: runs of consecutive columns with the same
// rows below them, stored as a dense triangle and the rows below it, each row's entries side
// by side. A row's index and its two unknowns are then read once for four of the run's
// columns, not once per column, which matters where the solve is memory-bound.
//
// The triangular solves run on several threads (Parallel_for.h): the elimination tree is cut
// into `part_count` sets of whole subtrees of about equal work and a "top" holding the
// ancestors of the cuts. A column of a part only touches rows of its own part and of the top,
// so the parts are solved independently; their updates of top rows go to per-part slots,
// added to the top rows in part order. The split depends on the factor only, not on the
// number of threads, so the result is the same bit for bit on any number of threads.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_TWO_COLUMN_CHOLESKY_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_TWO_COLUMN_CHOLESKY_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/assertions.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Level_set_dissection.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Parallel_for.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sparse_cholesky.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>
#include <mutex>
#include <numeric>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

class Two_column_cholesky
{
public:
  // Factors the matrix whose lower triangle is `lower`; false if it is not positive definite
  // (then, or if it throws, the object is left as it was).
  bool compute(const Sparse_matrix& lower)
  {
    Two_column_cholesky result;
    Tree_split split;
    if(!result.factor(lower, split))
      return false;
    double work = 0;
    for(std::size_t j = 0; j < result.m_n; ++j)
    {
      const double count = double(result.factor_starts()[j + 1] - result.factor_starts()[j]);
      work += count * count;
    }
    result.m_work_per_entry = work / double((std::max)(result.factor_starts()[result.m_n], 1));
    result.form_supernodes(result.apply_split(split));
    *this = std::move(result);
    return true;
  }

  // Solves A X = B in place for the two interleaved columns of `b` (size 2n).
  void solve(std::vector<double>& b) const
  {
    std::vector<double>& y = m_work;
    y.resize(solve_size());
    for(std::size_t i = 0; i < m_n; ++i)
    {
      y[2 * std::size_t(m_position[i])] = b[2 * i];
      y[2 * std::size_t(m_position[i]) + 1] = b[2 * i + 1];
    }
    solve_in_order(y);
    for(std::size_t i = 0; i < m_n; ++i)
    {
      b[2 * i] = y[2 * std::size_t(m_position[i])];
      b[2 * i + 1] = y[2 * std::size_t(m_position[i]) + 1];
    }
  }

  // solve() for `y` given and returned in the factor's order (unknown i at row positions()[i]),
  // without the two passes that permute it: its first 2n entries are the columns; it is sized
  // to solve_size() (the parts' slots for the top follow the columns).
  void solve_in_order(std::vector<double>& y) const
  {
    const std::size_t top = m_top.size(), parts = split_parts();
    y.resize(solve_size());
    std::fill(y.begin() + std::ptrdiff_t(2 * m_n), y.end(), 0.);
    // L y = P b: the parts, their updates of the top gathered, then the top.
    parallel_for_each_index(parts, [&](std::size_t p) {
      for(int k = m_part_first[p]; k < m_part_first[p + 1]; ++k)
        forward_supernode(m_supernodes[std::size_t(m_part_supernodes[std::size_t(k)])], y);
    });
    for(std::size_t q = 0; q < top; ++q)
      for(std::size_t p = 0; p < parts; ++p)
        for(int c = 0; c < 2; ++c)
          y[2 * std::size_t(m_top[q]) + c] += y[2 * (m_n + p * top + q) + c];
    for(int k : m_top_supernodes)
      forward_supernode(m_supernodes[std::size_t(k)], y);
    // L' x = y: the top, its values copied to every part's slots, then the parts.
    for(std::size_t k = m_top_supernodes.size(); k-- > 0;)
      backward_supernode(m_supernodes[std::size_t(m_top_supernodes[k])], y);
    for(std::size_t q = 0; q < top; ++q)
      for(std::size_t p = 0; p < parts; ++p)
        for(int c = 0; c < 2; ++c)
          y[2 * (m_n + p * top + q) + c] = y[2 * std::size_t(m_top[q]) + c];
    parallel_for_each_index(parts, [&](std::size_t p) {
      for(int k = m_part_first[p + 1]; k-- > m_part_first[p];)
        backward_supernode(m_supernodes[std::size_t(m_part_supernodes[std::size_t(k)])], y);
    });
  }

  // The size solve_in_order() gives its vector: the two columns, then the parts' slots.
  std::size_t solve_size() const { return 2 * (m_n + split_parts() * m_top.size()); }

  // The position of each unknown in the order the factor eliminates them.
  const std::vector<int>& positions() const { return m_position; }

  // The work of factoring per entry of the factor: the sum over its columns of their squared
  // entry counts (proportional to the flops), over the entries.
  double factorization_work_per_entry() const { return m_work_per_entry; }

  // The number of columns solved on one thread (the top): all of them for a small factor.
  std::size_t sequential_columns() const { return m_top.size(); }

  // The share of the factor's entries on the longest path of a solve: those of the top and of
  // the most loaded part (all of them when the factor is not split).
  double longest_path_share() const { return m_longest_path_share; }

  // The number of supernodes (runs of columns solved together): at most the number of rows.
  std::size_t supernode_count() const { return m_supernodes.size(); }

private:
  static constexpr std::size_t part_count = Cholesky_settings::part_count;
  static_assert((std::size_t(1) << Cholesky_settings::dissection_levels) == part_count, "a piece for each part");

  // The cut of an elimination tree into the parts and the top (split_tree()).
  struct Tree_split
  {
    std::vector<char> in_top;
    std::vector<int> part;          // of each column not in the top
    double top = 0, heaviest = 0;   // the entries of the top and of the most loaded part
  };
  struct Supernode
  {
    int column, width;          // its first column, the number of its columns
    int rows_begin, rows_end;   // its rows below the triangle, in factor_rows()
    std::size_t values;         // the triangle by columns, then each row's `width` entries
  };

  // Factors the matrix and splits the factor's elimination tree (split_tree()).
  bool factor(const Sparse_matrix& lower, Tree_split& split)
  {
    m_n = std::size_t(lower.rows());
#ifdef CGAL_NORM_PRESERVING_USE_CHOLMOD
    if(m_n < Cholesky_settings::cholmod_minimum_rows)
      return factor_simplicial(lower, split);
    Cholmod_factor cholmod;
    cholmod_common& common = cholmod.common;
    common.print = 0; // a matrix that is not positive definite is an answer (false), not a message
    common.supernodal = CHOLMOD_SIMPLICIAL;
    common.nmethods = 1;
    common.method[0].ordering = CHOLMOD_AMD;
    cholmod_sparse view = cholmod_lower_view(lower);
    cholmod.factor = cholmod_analyze(&view, &common);
    if(cholmod.factor != nullptr && common.lnz >= Cholesky_settings::metis_fill_per_row * double(m_n))
    {
      cholmod_free_factor(&cholmod.factor, &common);
      common.supernodal = CHOLMOD_SUPERNODAL;
      common.method[0].ordering = CHOLMOD_METIS;
      std::lock_guard<std::mutex> lock(metis_mutex());
      cholmod.factor = cholmod_analyze(&view, &common);
    }
    cholmod_factor* factor = cholmod.factor;
    // A simplicial factorization is LDL' and stops only at a zero pivot: a negative one shows
    // when it is converted to LL' (a warning, the column left as it was), hence the checks after.
    if(factor == nullptr || !cholmod_factorize(&view, factor, &common) || common.status != CHOLMOD_OK
       || factor->minor != factor->n || !cholmod_change_factor(CHOLMOD_REAL, true, false, true, true, factor, &common)
       || common.status != CHOLMOD_OK || factor->minor != factor->n)
      return false;
    const int* first = static_cast<const int*>(factor->p);
    const int* rows = static_cast<const int*>(factor->i);
    const double* values = static_cast<const double*>(factor->x);
    const int* permutation = static_cast<const int*>(factor->Perm);
    // The supernodes' padding comes over as explicit zeros: leave them out (counted first, so
    // that the kept entries are allocated once: 1.48 GiB peak at 590k vertices, not 1.76).
    auto kept = [&](int j, int k) { return k == first[j] || values[k] != 0; };
    m_factor.reset(new Sparse_matrix(int(m_n), int(m_n)));
    int* kept_first = m_factor->outerIndexPtr();
    kept_first[0] = 0;
    for(std::size_t j = 0; j < m_n; ++j)
    {
      kept_first[j + 1] = kept_first[j];
      for(int k = first[j]; k < first[j + 1]; ++k)
        kept_first[j + 1] += kept(int(j), k) ? 1 : 0;
    }
    m_factor->resizeNonZeros(kept_first[m_n]);
    int* kept_rows = factor_rows();
    double* kept_values = factor_values();
    for(std::size_t j = 0; j < m_n; ++j)
    {
      std::size_t next = std::size_t(kept_first[j]);
      for(int k = first[j]; k < first[j + 1]; ++k)
        if(kept(int(j), k))
        {
          kept_rows[next] = rows[k];
          kept_values[next++] = values[k];
        }
    }
    m_position.resize(m_n);
    for(std::size_t k = 0; k < m_n; ++k)
      m_position[std::size_t(permutation[k])] = int(k);
    split = tree_split();
    return true;
#else
    return factor_simplicial(lower, split);
#endif
  }

  // The matrix of lower triangle `source`, put in the order `position` (unknown i at row
  // position[i]; null: as it is), written as the lower (`to_upper` false) or the upper
  // triangle of the result. Each column's entries come in the order the source's columns are
  // read, as in Eigen's twistedBy(): the up-looking factorization follows that order, so the
  // factor's bits do too.
  static void permute_symmetric(const Sparse_matrix& source, const int* position, bool to_upper, Sparse_matrix& result)
  {
    const int n = int(source.cols());
    const int* first = source.outerIndexPtr();
    const int* rows = source.innerIndexPtr();
    const double* values = source.valuePtr();
    auto at = [&](int i) { return position ? position[i] : i; };
    result.resize(n, n);
    int* start = result.outerIndexPtr(); // zeros
    for(int j = 0; j < n; ++j)
      for(int p = first[j]; p < first[j + 1]; ++p)
        ++start[(to_upper ? (std::max)(at(rows[p]), at(j)) : (std::min)(at(rows[p]), at(j))) + 1];
    std::partial_sum(start, start + n + 1, start);
    result.resizeNonZeros(start[n]);
    std::vector<int> next(start, start + n);
    for(int j = 0; j < n; ++j)
      for(int p = first[j]; p < first[j + 1]; ++p)
      {
        const int a = at(rows[p]), b = at(j);
        const int k = next[std::size_t(to_upper ? (std::max)(a, b) : (std::min)(a, b))]++;
        result.innerIndexPtr()[k] = to_upper ? (std::min)(a, b) : (std::max)(a, b);
        result.valuePtr()[k] = values[p];
      }
  }

  // The simplicial L L' of a matrix given as the upper triangle of it in its elimination order:
  // its elimination tree and the entries of each column of the factor, then the factor by rows
  // (up-looking, as in CSparse and Eigen's SimplicialLLT), diagonal first in each column. The
  // package's own rather than Eigen's, whose analysis (which decides the order and the split)
  // is not public (doc/decisions.md, "Other libraries' factors").
  class Ordered_llt
  {
  public:
    // Analyzes `upper`, kept for factor(). Returns the entries on the longest path of a solve:
    // the top and the most loaded part of `split`.
    double analyze(Sparse_matrix&& upper)
    {
      m_upper = std::move(upper);
      const std::size_t n = std::size_t(m_upper.cols());
      m_parent.assign(n, -1);
      m_count.assign(n, 1); // the diagonal
      std::vector<int> visited(n, -1);
      for(int k = 0; k < int(n); ++k)
      {
        visited[std::size_t(k)] = k;
        for(Sparse_matrix::InnerIterator entry(m_upper, k); entry; ++entry)
          for(int i = int(entry.index()); i < k && visited[std::size_t(i)] != k; i = m_parent[std::size_t(i)])
          {
            if(m_parent[std::size_t(i)] < 0)
              m_parent[std::size_t(i)] = k;
            ++m_count[std::size_t(i)]; // L(k, i)
            visited[std::size_t(i)] = k;
          }
      }
      entries = work = 0;
      for(int c : m_count)
      {
        entries += double(c);
        work += double(c) * double(c);
      }
      split = split_tree(n, m_parent, [&](std::size_t j) { return double(m_count[j]); });
      return split.top + split.heaviest;
    }

    // Factors the analyzed matrix into `factor`; false if it is not positive definite.
    bool factor(Sparse_matrix& factor)
    {
      const int n = int(m_upper.cols());
      factor.resize(n, n);
      int* start = factor.outerIndexPtr();
      for(int j = 0; j < n; ++j)
        start[j + 1] = start[j] + m_count[std::size_t(j)];
      factor.resizeNonZeros(start[n]);
      int* rows = factor.innerIndexPtr();
      double* values = factor.valuePtr();
      const std::size_t size = std::size_t(n);
      std::vector<int> filled(size, 0), visited(size, -1), pattern(size);
      std::vector<double> y(size, 0.);
      for(int k = 0; k < n; ++k)
      {
        // The pattern of row k of L in topological order, and A(:, k) scattered into y.
        int top = n;
        visited[std::size_t(k)] = k;
        for(Sparse_matrix::InnerIterator entry(m_upper, k); entry; ++entry)
        {
          int i = int(entry.index());
          y[std::size_t(i)] += entry.value();
          int length = 0;
          for(; visited[std::size_t(i)] != k; i = m_parent[std::size_t(i)])
          {
            pattern[std::size_t(length++)] = i;
            visited[std::size_t(i)] = k;
          }
          while(length > 0)
            pattern[std::size_t(--top)] = pattern[std::size_t(--length)];
        }
        // Row k of L by a sparse triangular solve, appended to its columns.
        double d = y[std::size_t(k)];
        y[std::size_t(k)] = 0;
        for(; top < n; ++top)
        {
          const int i = pattern[std::size_t(top)];
          const double l = y[std::size_t(i)] / values[start[i]];
          y[std::size_t(i)] = 0;
          const int end = start[i] + filled[std::size_t(i)];
          for(int p = start[i] + 1; p < end; ++p)
            y[std::size_t(rows[p])] -= values[p] * l;
          d -= l * l;
          rows[end] = k;
          values[end] = l;
          ++filled[std::size_t(i)];
        }
        if(!(d > 0))
          return false;
        rows[start[k]] = k;
        values[start[k]] = std::sqrt(d);
        filled[std::size_t(k)] = 1;
      }
      Sparse_matrix().swap(m_upper);
      return true;
    }

    double entries = 0, work = 0; // of the factor, and the work of factoring (factorization_work_per_entry())
    Tree_split split;

  private:
    Sparse_matrix m_upper;
    std::vector<int> m_parent, m_count;
  };

  // The simplicial factorization in AMD's order (Eigen's AMD, public) or, below
  // `cholmod_minimum_rows` rows where AMD's elimination tree splits so unevenly that the longest
  // path of a solve holds most of the factor, in a level-set dissection's (the conditions:
  // Cholesky_settings).
  bool factor_simplicial(const Sparse_matrix& lower, Tree_split& split)
  {
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> amd_order; // the k-th unknown eliminated at k
    Eigen::AMDOrdering<int>()(lower.selfadjointView<Eigen::Lower>(), amd_order); // the full pattern, sorted: as A' + A
    std::vector<int> amd_position(m_n);
    for(std::size_t k = 0; k < m_n; ++k)
      amd_position[std::size_t(amd_order.indices()[Eigen::Index(k)])] = int(k);
    Sparse_matrix upper;
    permute_symmetric(lower, amd_position.data(), true, upper);
    Ordered_llt by_amd;
    const double path = by_amd.analyze(std::move(upper));
    if(m_n < Cholesky_settings::cholmod_minimum_rows && by_amd.entries >= Cholesky_settings::dissection_smallest_factor &&
       path > Cholesky_settings::dissection_tried_above * by_amd.entries)
    {
      const std::vector<int> amd(amd_order.indices().data(), amd_order.indices().data() + m_n);
      const Level_set_dissection::Result dissection =
        Level_set_dissection::order(Sparse_matrix(lower.selfadjointView<Eigen::Lower>()), Cholesky_settings::dissection_levels, amd);
      if(dissection.separator_entries <= Cholesky_settings::dissection_separators * by_amd.entries)
      {
        std::vector<int> position(m_n);
        for(std::size_t k = 0; k < m_n; ++k)
          position[std::size_t(dissection.order[k])] = int(k);
        Sparse_matrix permuted;
        permute_symmetric(lower, position.data(), false, permuted);
        permute_symmetric(permuted, nullptr, true, upper);
        Ordered_llt by_dissection;
        if(by_dissection.analyze(std::move(upper)) < Cholesky_settings::dissection_kept_below * path &&
           by_dissection.work < Cholesky_settings::dissection_most_work * by_amd.work)
          return keep(by_dissection, std::move(position), split);
      }
    }
    return keep(by_amd, std::move(amd_position), split);
  }

  // Factors `llt` and keeps its factor (diagonal first in each column), the position of each
  // unknown and the tree's split.
  bool keep(Ordered_llt& llt, std::vector<int> position, Tree_split& split)
  {
    std::unique_ptr<Sparse_matrix> factor(new Sparse_matrix());
    if(!llt.factor(*factor))
      return false;
    split = std::move(llt.split);
    m_position = std::move(position);
    m_factor = std::move(factor);
    return true;
  }

  // The number of parts solved apart from the top: none for a small factor, which is all top
  // (its solve then has no slots for the parts).
  std::size_t split_parts() const { return m_part_supernodes.empty() ? 0 : part_count; }

  // The triangle (by columns) comes first in a supernode's entries, then its rows.
  static std::size_t triangle_size(int width) { return std::size_t(width) * std::size_t(width + 1) / 2; }

  void forward_supernode(const Supernode& s, std::vector<double>& y) const
  {
    const int w = s.width;
    const double* entry = &factor_values()[s.values];
    double* own = &y[2 * std::size_t(s.column)];
    for(int c = 0; c < w; ++c)
    {
      const double y0 = own[2 * c] /= *entry, y1 = own[2 * c + 1] /= *entry;
      ++entry;
      for(int r = c + 1; r < w; ++r, ++entry)
      {
        own[2 * r] -= *entry * y0;
        own[2 * r + 1] -= *entry * y1;
      }
    }
    for_column_groups(w, [&](auto width, int first) { forward_rows<decltype(width)::value>(s, first, y); });
  }

  void backward_supernode(const Supernode& s, std::vector<double>& y) const
  {
    const int w = s.width;
    for_column_groups(w, [&](auto width, int first) { backward_rows<decltype(width)::value>(s, first, y); });
    const double* triangle = &factor_values()[s.values];
    double* own = &y[2 * std::size_t(s.column)];
    for(int c = w; c-- > 0;)
    {
      const double* column = triangle + c * w - c * (c - 1) / 2; // the diagonal, then the rows below
      for(int r = c + 1; r < w; ++r)
      {
        own[2 * c] -= column[r - c] * own[2 * r];
        own[2 * c + 1] -= column[r - c] * own[2 * r + 1];
      }
      own[2 * c] /= column[0];
      own[2 * c + 1] /= column[0];
    }
  }

  // Calls f(width, first) on the supernode's columns in groups of at most four: a group's
  // unknowns and sums stay in registers while its rows are read.
  template <typename Function>
  static void for_column_groups(int width, const Function& f)
  {
    for(int first = 0; first < width; first += 4)
      switch((std::min)(4, width - first))
      {
        case 1: f(std::integral_constant<int, 1>(), first); break;
        case 2: f(std::integral_constant<int, 2>(), first); break;
        case 3: f(std::integral_constant<int, 3>(), first); break;
        default: f(std::integral_constant<int, 4>(), first); break;
      }
  }

  // The rows below the supernode minus its columns first, ..., first + W - 1 times their unknowns.
  template <int W>
  void forward_rows(const Supernode& s, int first, std::vector<double>& y) const
  {
    for_rows_of_group<W>(s, first, y, [](const double* entry, double& y0, double& y1, double (&x0)[W], double (&x1)[W]) {
      double d0 = 0, d1 = 0;
      for(int c = 0; c < W; ++c)
      {
        d0 += entry[c] * x0[c];
        d1 += entry[c] * x1[c];
      }
      y0 -= d0;
      y1 -= d1;
    });
  }

  // The unknowns of columns first, ..., first + W - 1 minus their rows below times theirs.
  template <int W>
  void backward_rows(const Supernode& s, int first, std::vector<double>& y) const
  {
    for_rows_of_group<W>(s, first, y, [](const double* entry, double& y0, double& y1, double (&x0)[W], double (&x1)[W]) {
      for(int c = 0; c < W; ++c)
      {
        x0[c] -= entry[c] * y0;
        x1[c] -= entry[c] * y1;
      }
    });
  }

  // Calls row(entries, y0, y1, x0, x1) on each row below the supernode: its entries in columns
  // first, ..., first + W - 1, its two unknowns, and those of the W columns, held in registers
  // and written back at the end.
  template <int W, typename Row>
  void for_rows_of_group(const Supernode& s, int first, std::vector<double>& y, const Row& row) const
  {
    double* own = &y[2 * std::size_t(s.column + first)];
    double x0[W], x1[W];
    for(int c = 0; c < W; ++c)
    {
      x0[c] = own[2 * c];
      x1[c] = own[2 * c + 1];
    }
    const double* entry = &factor_values()[s.values + triangle_size(s.width) + std::size_t(first)];
    const int* rows = factor_rows();
    for(int k = s.rows_begin; k < s.rows_end; ++k, entry += s.width)
    {
      const std::size_t i = std::size_t(rows[k]);
      row(entry, y[2 * i], y[2 * i + 1], x0, x1);
    }
    for(int c = 0; c < W; ++c)
    {
      own[2 * c] = x0[c];
      own[2 * c + 1] = x1[c];
    }
  }

  // The split of the tree of `n` columns given by each column's parent (-1 at a root; parents
  // come later) and its entries (`entries(j)`): the largest subtree goes to the top (its root)
  // and its children replace it, until the subtrees, dealt largest first to the least loaded
  // part, load no part more than `part_slack` times an even share, or the top would exceed
  // `top_share` of the work. Factors of under `smallest_split` entries are all top: a part
  // would take less time than handing it to another thread.
  template <typename Parents, typename Entries>
  static Tree_split split_tree(std::size_t n, const Parents& parent, const Entries& entries)
  {
    std::vector<double> work(n); // of the subtree
    for(std::size_t j = 0; j < n; ++j)
    {
      work[j] += entries(j);
      if(parent[j] >= 0)
        work[std::size_t(parent[j])] += work[j];
    }
    std::vector<int> child_first(n + 1, 0), children(n);
    for(std::size_t j = 0; j < n; ++j)
      if(parent[j] >= 0)
        ++child_first[std::size_t(parent[j]) + 1];
    std::partial_sum(child_first.begin(), child_first.end(), child_first.begin());
    std::vector<int> fill(child_first.begin(), child_first.end() - 1);
    std::vector<int> subtrees; // roots of the subtrees not in the top
    double total = 0;
    for(std::size_t j = 0; j < n; ++j)
    {
      total += entries(j);
      if(parent[j] >= 0)
        children[std::size_t(fill[std::size_t(parent[j])]++)] = int(j);
      else
        subtrees.push_back(int(j));
    }

    Tree_split split;
    split.in_top.assign(n, char(total < Cholesky_settings::smallest_split));
    split.part.assign(n, -1);
    while(total >= Cholesky_settings::smallest_split) // ends: the top's cap comes before the subtrees run out
    {
      std::sort(subtrees.begin(), subtrees.end(), [&](int a, int b) {
        return work[std::size_t(a)] > work[std::size_t(b)] || (work[std::size_t(a)] == work[std::size_t(b)] && a < b);
      });
      std::array<double, part_count> load{};
      for(int r : subtrees)
      {
        const std::size_t lightest = std::size_t(std::min_element(load.begin(), load.end()) - load.begin());
        load[lightest] += work[std::size_t(r)];
        split.part[std::size_t(r)] = int(lightest);
      }
      const double heaviest = *std::max_element(load.begin(), load.end());
      const std::size_t r = std::size_t(subtrees.front());
      if(heaviest <= Cholesky_settings::part_slack * (total - split.top) / double(part_count) || split.top + entries(r) > Cholesky_settings::top_share * total)
        break;
      split.in_top[r] = 1;
      split.top += entries(r);
      split.part[r] = -1;
      subtrees.erase(subtrees.begin());
      subtrees.insert(subtrees.end(), children.begin() + child_first[r], children.begin() + child_first[r + 1]);
    }
    std::array<double, part_count> load{};
    for(std::size_t j = n; j-- > 0;) // parents come later in the order
      if(!split.in_top[j])
      {
        if(split.part[j] < 0)
          split.part[j] = split.part[std::size_t(parent[j])];
        load[std::size_t(split.part[j])] += entries(j);
      }
    split.top = total < Cholesky_settings::smallest_split ? total : split.top;
    split.heaviest = *std::max_element(load.begin(), load.end());
    return split;
  }

  // split_tree() of the factor's elimination tree (parent: first row below the diagonal).
  Tree_split tree_split() const
  {
    const std::size_t n = m_n;
    const int* first = factor_starts();
    const int* rows = factor_rows();
    std::vector<int> parent(n, -1);
    for(std::size_t j = 0; j < n; ++j)
      for(int k = first[j] + 1; k < first[j + 1]; ++k) // the rows may come in any order
        if(parent[j] < 0 || rows[std::size_t(k)] < parent[j])
          parent[j] = rows[std::size_t(k)];
    return split_tree(n, parent, [&](std::size_t j) { return double(first[j + 1] - first[j]); });
  }

  // Applies the split: renumbers the rows in the top of the parts' columns to the parts' slots
  // (or puts all in the top, see below) and records the longest path's share. Returns the part
  // of each column, `part_count` for the top.
  std::vector<int> apply_split(Tree_split& split)
  {
    const std::size_t n = m_n;
    const int* first = factor_starts();
    int* rows = factor_rows();
    std::vector<char>& in_top = split.in_top;
    const std::vector<int>& bin = split.part;
    // The tree was read off the factor's nonzeros: were an entry to cancel exactly, a row could
    // lie outside its column's part and top. Then all goes to the top.
    bool separate = true;
    for(std::size_t j = 0; j < n && separate; ++j)
      if(!in_top[j])
        for(int k = first[j] + 1; k < first[j + 1]; ++k)
          separate = separate && (in_top[std::size_t(rows[k])] || bin[std::size_t(rows[k])] == bin[j]);
    if(!separate)
      std::fill(in_top.begin(), in_top.end(), char(1));
    m_longest_path_share = separate ? (split.top + split.heaviest) / double((std::max)(first[n], 1)) : 1.;

    // Rows in the top of a part's columns are renumbered to the part's slots.
    std::vector<int> top_index(n, -1);
    m_top.clear();
    for(std::size_t j = 0; j < n; ++j)
      if(in_top[j])
      {
        top_index[j] = int(m_top.size());
        m_top.push_back(int(j));
      }
    const std::size_t top = m_top.size();
    std::vector<int> part(n, int(part_count));
    for(std::size_t j = 0; j < n; ++j)
      if(!in_top[j])
      {
        part[j] = bin[j];
        for(int k = first[j] + 1; k < first[j + 1]; ++k)
          if(in_top[std::size_t(rows[k])])
            rows[k] = int(n + std::size_t(bin[j]) * top + std::size_t(top_index[std::size_t(rows[k])]));
      }
    return part;
  }

  // Groups the columns into supernodes within each part (and the top): column j + 1 joins
  // column j when it is j's parent and has j's rows below it; then stores the factor by
  // supernodes, in place (the entries of a supernode's columns are permuted, the rows of all
  // but its last column dropped).
  void form_supernodes(const std::vector<int>& part)
  {
    const std::size_t n = m_n;
    const int* first = factor_starts();
    int* rows = factor_rows();
    double* values = factor_values();
    auto extends = [&](std::size_t j) { // column j + 1 continues the supernode of column j
      const int count = first[j + 1] - first[j];
      if(j + 1 >= n || part[j + 1] != part[j] || count < 2 || rows[std::size_t(first[j]) + 1] != int(j + 1)
         || first[j + 2] - first[j + 1] != count - 1)
        return false;
      return std::equal(rows + first[j + 1] + 1, rows + first[j + 2], rows + first[j] + 2);
    };
    m_supernodes.clear();
    std::vector<double> rows_below; // one supernode's entries below its triangle, by rows
    int kept_rows = 0;
    for(std::size_t j = 0; j < n;)
    {
      std::size_t last = j;
      while(extends(last))
        ++last;
      const int width = int(last - j) + 1;
      const int below = first[last + 1] - first[last] - 1;
      Supernode s{int(j), width, kept_rows, kept_rows + below, std::size_t(first[j])};
      for(int k = first[last] + 1; k < first[last + 1]; ++k) // forward: kept_rows <= k
        rows[std::size_t(kept_rows++)] = rows[std::size_t(k)];
      rows_below.resize(std::size_t(width) * std::size_t(below));
      std::size_t triangle = s.values;
      for(int c = 0; c < width; ++c)
      {
        const std::size_t column = std::size_t(first[j + std::size_t(c)]);
        for(int r = 0; r < width - c; ++r)
          values[triangle++] = values[column + std::size_t(r)];
        for(int k = 0; k < below; ++k)
          rows_below[std::size_t(k) * std::size_t(width) + std::size_t(c)] = values[column + std::size_t(width - c + k)];
      }
      std::copy(rows_below.begin(), rows_below.end(), values + std::ptrdiff_t(triangle));
      m_supernodes.push_back(s);
      j = last + 1;
    }
    m_part_first.assign(part_count + 2, 0);
    for(const Supernode& s : m_supernodes)
      ++m_part_first[std::size_t(part[std::size_t(s.column)]) + 1];
    std::partial_sum(m_part_first.begin(), m_part_first.end(), m_part_first.begin());
    std::vector<int> fill(m_part_first.begin(), m_part_first.end() - 1);
    std::vector<int> grouped(m_supernodes.size());
    for(std::size_t k = 0; k < m_supernodes.size(); ++k)
      grouped[std::size_t(fill[std::size_t(part[std::size_t(m_supernodes[k].column)])]++)] = int(k);
    m_top_supernodes.assign(grouped.begin() + m_part_first[part_count], grouped.end());
    grouped.resize(std::size_t(m_part_first[part_count]));
    m_part_supernodes.swap(grouped);
    m_part_first.pop_back();
  }

  std::size_t m_n = 0;
  double m_work_per_entry = 0;
  double m_longest_path_share = 1;
  // The simplicial factor by columns, diagonal first, until form_supernodes() stores it by
  // supernodes in place (then the column starts, factor_starts(), are left unused).
  std::unique_ptr<Sparse_matrix> m_factor;
  int* factor_starts() { return m_factor->outerIndexPtr(); }
  const int* factor_starts() const { return m_factor->outerIndexPtr(); }
  int* factor_rows() { return m_factor->innerIndexPtr(); }
  const int* factor_rows() const { return m_factor->innerIndexPtr(); }
  double* factor_values() { return m_factor->valuePtr(); }
  const double* factor_values() const { return m_factor->valuePtr(); }
  std::vector<Supernode> m_supernodes;
  std::vector<int> m_position;      // position of each unknown in the factor's order
  std::vector<int> m_top;           // columns of the top, ascending
  std::vector<int> m_part_first, m_part_supernodes; // supernodes of each part, ascending
  std::vector<int> m_top_supernodes;
  mutable std::vector<double> m_work;
};

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
