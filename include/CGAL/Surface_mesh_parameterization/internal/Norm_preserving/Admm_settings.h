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
// Every setting of the default solver (Sign_constrained_admm.h) and of its active-set polish
// (Active_set_polish.h), in one place. The measurements that chose each value are in
// doc/performance.md, under the heading named with it.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_ADMM_SETTINGS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_ADMM_SETTINGS_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <cstddef>
#include <limits>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

// The stopping rule's tolerance of the three presets (performance.md, "Quality presets").
constexpr double admm_draft_tolerance = 1e-2;
constexpr double admm_default_tolerance = 2.5e-5;
constexpr double admm_exact_gap = 1e-9;

struct Admm_settings
{
  // What the caller chooses.
  double tolerance = admm_default_tolerance; // relative: of the stopping rule, or of the certified gap if `certified`
  int max_iterations = 20000;
  double time_limit = std::numeric_limits<double>::infinity(); // seconds
  bool certified = false;                    // stop on the certified gap instead of the stopping rule

  // "Penalty and over-relaxation"
  double penalty = 1.5;    // rho, in the normalized units where the objective's curvature per edge is 2
  double relaxation = 1.9; // over-relaxation of the edge step

  // "Stopping rule"
  int check_every = 5;                                 // iterations between two checks
  double certified_rule_tolerance = admm_default_tolerance; // the rule's tolerance in the certified mode, where certificates start
  double rise = 1e-9;                // a rise of the objective at a check by more than this share of it counts as a rise
  double two_check_gap_ratio = 60;   // a stop after two checks: certified gap at most this times the tolerance
  double confirmed_gap_ratio = 150;  // a stop after three checks: at most this times the tolerance
  double risen_gap_ratio = 75;       // after a rise, three checks and at most this times the tolerance

  // "Certificates of the exact mode"
  int certify_every = 25; // iterations between two certified gaps, once the rule has stopped

  // "Active-set polish"
  int polish_first = 150;                   // default mode: the first try at this iteration or later,
  double polish_first_per_work = 5;         // at least this many iterations per unit of factoring work per factor entry
  int polish_tries = 3;                     // default mode: tries, each at twice the iteration of the last
  int certified_polish_tries = 5;           // exact mode: tries, each at 1.5 times the iteration of the last
  int polish_rounds = 24;                   // corrections of the active set in one try
  double polish_turn_tolerance = 1e-9;      // a constraint violated, or of negative multiplier, by more turns (mean L1 edge lengths)
  double polish_shrink = 0.7;               // a round that wants more than this share of the last round's turns halves them
  std::size_t polish_growth_limit = 2;      // a try ends when a round wants more than this times the fewest turns
  std::size_t polish_growth_slack = 16;     //   plus this many
  std::size_t polish_border = 64;           // a round differing by at most this many splits and joins is solved bordered
  double polish_proximal_round_off = 1e-5;  // proximal steps end once a step moves the solution by at most this share
  int precision_limit_tries = 2;            // exact mode: tries ending at an optimal point before the precision limit

  // "Interior-point fallback"
  int interior_point_after = 1000;                   // iteration from which a tail that has not settled is handed over
  std::size_t interior_point_max_vertices = 200000;  // on meshes of at most this many vertices (about 6 KB a vertex)
  double interior_point_active_value = 1e-6;         // its constraints at most this value are active for its polish

  // "Parallel loops"
  std::size_t edge_block = 1024; // edges in a block of the parallel edge loops
};

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
