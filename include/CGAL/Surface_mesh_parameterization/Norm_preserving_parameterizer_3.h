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
/// \file Norm_preserving_parameterizer_3.h
/// \ingroup PkgNormPreservingParameterization
/// The norm-preserving parameterizer, a model of `Parameterizer_3`.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_PARAMETERIZER_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_PARAMETERIZER_3_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/disable_warnings.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_ADMM_solver.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_concepts.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_report.h>
#include <CGAL/Surface_mesh_parameterization/XY_min_max_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Mesh_component.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Parallel_for.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Pipeline.h>

#include <CGAL/Default.h>
#include <CGAL/tags.h>
#include <CGAL/boost/graph/helpers.h>

#include <boost/concept/assert.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterizationMethods
/// Norm-preserving texture mapping of Lai & Cheng ("Texture Mapping on Surfaces of Arbitrary
/// Topology using Norm Preserving based Optimization"): every vertex of a connected triangle
/// mesh of any topology (disk, closed of any genus, many border loops) gets one uv, with no
/// cut, minimizing `sum_edges (||P_i - P_j||_1 - |u_i - u_j| - |v_i - v_j|)^2` with the signs
/// of the differences frozen from an initial guess, so that the problem is a convex QP
/// (Eq. 5), solved to optimality.
///
/// Closed meshes fold (front and back overlap in uv, the texture repeats): that is the method.
/// A border halfedge is not required: `parameterize()` accepts any halfedge of the component;
/// only CGAL's free function `parameterize(mesh, parameterizer, bhd, uvmap)` asks for a border
/// one.
///
/// \tparam TriangleMesh_ a model of `FaceGraph` with an internal `vertex_point` map
/// \tparam InitialGuess_ a model of `NormPreservingInitialGuess`;
///         default `XY_min_max_initial_guess`
/// \tparam SolverTraits_ a model of `NormPreservingSolver`: `Norm_preserving_ADMM_solver` (the
///         default: fast, to a tolerance) or `Norm_preserving_QP_solver`; or a model of
///         `QuadraticProgramTraits`, such as `Interior_point_quadratic_program_traits` (the
///         exact optimum) or `CGAL::OSQP_quadratic_program_traits`, which is wrapped in
///         `Norm_preserving_QP_solver`
/// \tparam ConcurrencyTag_ `CGAL::Sequential_tag` (the solver's loops on the calling thread),
///         `CGAL::Parallel_tag` (on TBB's threads; needs TBB) or `CGAL::Parallel_if_available_tag`
///         (the default); the uvs are the same, bit for bit
///
/// \cgalModels `Parameterizer_3`
template <typename TriangleMesh_,
          typename InitialGuess_ = Default,
          typename SolverTraits_ = Default,
          typename ConcurrencyTag_ = Parallel_if_available_tag>
class Norm_preserving_parameterizer_3
{

public:
  /// the mesh type
  typedef TriangleMesh_ Triangle_mesh;
  /// the mesh type (CGAL's other parameterizers name it so too)
  typedef TriangleMesh_ TriangleMesh;
  /// the initial-guess type
  typedef typename Default::Get<InitialGuess_, XY_min_max_initial_guess>::type Initial_guess;
  /// the QP solver type, as given
  typedef typename Default::Get<SolverTraits_, Norm_preserving_ADMM_solver>::type Solver_traits;
  /// the solver that solves: `Solver_traits` if it models `NormPreservingSolver`, otherwise
  /// `Norm_preserving_QP_solver<Solver_traits>`
  typedef typename internal::Norm_preserving::Solver_model<Solver_traits>::type Solver;
  /// \cond SKIP_IN_MANUAL
  BOOST_CONCEPT_ASSERT((concepts::NormPreservingInitialGuess<Initial_guess>));
  BOOST_CONCEPT_ASSERT((concepts::NormPreservingSolver<Solver>));
  /// \endcond
  /// the concurrency tag
  typedef ConcurrencyTag_ Concurrency_tag;
  /// halfedge handle of the mesh
  typedef typename boost::graph_traits<Triangle_mesh>::halfedge_descriptor halfedge_descriptor;
  /// vertex handle of the mesh
  typedef typename boost::graph_traits<Triangle_mesh>::vertex_descriptor vertex_descriptor;

  /// creates a parameterizer with the given initial guess and QP solver.
  explicit Norm_preserving_parameterizer_3(Initial_guess guess = Initial_guess(),
                                           Solver_traits solver = Solver_traits())
    : m_pipeline(guess, Solver(solver))
  { }

  /// fixes `source(bhd)` at the origin and `target(bhd)` along the guessed direction (default).
  void set_fixed_pair_from_halfedge() { m_pair_choice = Pair_choice::HALFEDGE; }
  /// fixes the vertex of smallest x (lowest index on ties) and its neighbour across the
  /// longest L1 edge (lowest index on ties) among those that the initial guess puts elsewhere.
  void set_automatic_fixed_pair() { m_pair_choice = Pair_choice::AUTOMATIC; }
  /// fixes `a` at the origin and `b` along the guessed direction; they must be adjacent
  /// vertices of the component being parameterized.
  void set_fixed_pair(vertex_descriptor a, vertex_descriptor b)
  {
    m_pair_choice = Pair_choice::EXPLICIT;
    m_a = a;
    m_b = b;
  }
  /// sets how the solution is fitted into texture space; default `NORM_PRESERVING_UNIFORM_FIT`.
  void set_texture_fit(Texture_fit fit) { m_pipeline.options().texture_fit = fit; }
  /// sets the `m x n` tiling: `u` is scaled by `m` and `v` by `n` after the fit; default 1 x 1.
  /// `parameterize()` returns `ERROR_WRONG_PARAMETER` unless both are at least 1.
  void set_tiling(int m, int n)
  {
    m_pipeline.options().tiles_u = m;
    m_pipeline.options().tiles_v = n;
  }
  /// sign refinement (beyond the paper): after the QP, up to `max_rounds` times, takes the
  /// signs from the solution, turning the zero differences the way Eq. 3 decreases, and
  /// solves again (warm-started with the default solver); stops when a round lowers Eq. 3 by
  /// at most `tolerance` (relative) or not at all. Eq. 3 never increases. Default: off (0).
  /// \param max_rounds at least 0; 0 turns it off
  /// \param tolerance at least 0
  void set_sign_refinement(int max_rounds, double tolerance = 1e-3)
  {
    m_pipeline.options().sign_refinement_rounds = max_rounds;
    m_pipeline.options().sign_refinement_tolerance = tolerance;
  }
  /// Euclidean refinement (beyond the paper): after the QP (and the sign refinement), minimizes
  /// the Euclidean objective `sum (||P_i - P_j||_2 - ||T_i - T_j||_2)^2` (Eq. 2 with q = 2) from
  /// the solution scaled to fit, the fixed pair held at its Euclidean distance, by stress
  /// majorization: at most `max_iterations` steps, each one solve with the Laplacian factored
  /// once, stopping when a step lowers the objective by at most `tolerance` (relative); it never
  /// increases. The result no longer satisfies the sign constraints. Default: off (0).
  /// The QP is then only its start: a loose solver tolerance (`Norm_preserving_ADMM_solver(1e-2)`)
  /// gives the same result faster (doc/refinement.md).
  /// \param max_iterations at least 0; 0 turns it off
  /// \param tolerance at least 0
  void set_euclidean_refinement(int max_iterations, double tolerance = 1e-3)
  {
    m_pipeline.options().euclidean_refinement_iterations = max_iterations;
    m_pipeline.options().euclidean_refinement_tolerance = tolerance;
  }

  /// what the last call of `parameterize()` did.
  const Norm_preserving_report& report() const { return m_report; }
  /// the vertices that the last successful call of `parameterize()` fixed.
  std::pair<vertex_descriptor, vertex_descriptor> fixed_vertices() const { return m_fixed; }

  /// assigns a uv to every vertex of the connected component of `bhd`, which may be any
  /// halfedge of it, border or not, and marks each in `vpmap`. Faces that share only a vertex
  /// (a non-manifold vertex) belong to the same component, and the vertex gets one uv. The
  /// component's vertices are numbered in the order of their indices in `vimap`, as CGAL's
  /// parameterizers number their linear systems: the uvs are those of a mesh whose vertices
  /// come in that order.
  ///
  /// On failure it returns `ERROR_EMPTY_MESH`, `ERROR_NON_TRIANGULAR_MESH` (a face that is
  /// not a triangle of three distinct vertices), `ERROR_WRONG_PARAMETER` (non-finite
  /// coordinates, zero extent, an undefined guess, a fixed pair that is not an edge of the
  /// component) or `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM`, explains it in `report().message`,
  /// and writes nothing to `uvmap` or `vpmap`.
  ///
  /// \tparam VertexUVmap a model of `ReadWritePropertyMap` from vertices to a 2D point type
  /// \tparam VertexIndexMap a model of `ReadablePropertyMap` from vertices to integers, distinct
  ///         on the component (CGAL's `parameterize()` makes one)
  /// \tparam VertexParameterizedMap a model of `ReadWritePropertyMap` from vertices to `bool`
  template <typename VertexUVmap, typename VertexIndexMap, typename VertexParameterizedMap>
  Error_code parameterize(Triangle_mesh& mesh,
                          halfedge_descriptor bhd,
                          VertexUVmap uvmap,
                          VertexIndexMap vimap,
                          VertexParameterizedMap vpmap)
  {
    typedef typename boost::property_traits<VertexUVmap>::value_type Point_2;
    namespace NP = internal::Norm_preserving;
    const auto start = std::chrono::steady_clock::now();
    m_report = Norm_preserving_report();
    NP::Mesh_component<Triangle_mesh> component;
    std::vector<std::array<double, 2> > uv;
    m_report.status = NP::extract_component(mesh, bhd, vimap, component, m_report.message);
    std::optional<std::pair<std::size_t, std::size_t> > pair;
    if(m_report.status == OK)
      m_report.status = explicit_pair(mesh, bhd, component, pair);
    m_report.timings.extraction = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if(m_report.status == OK)
      m_report.status = NP::run_with_concurrency<Concurrency_tag>(
        [&] { return m_pipeline.run(std::move(component.geometry), pair, uv, m_report); });
    if(m_report.status == OK)
      m_fixed = {component.vertices[m_report.fixed_a], component.vertices[m_report.fixed_b]};
    if(m_report.status == OK)
      for(std::size_t i = 0; i < uv.size(); ++i)
      {
        put(uvmap, component.vertices[i], Point_2(uv[i][0], uv[i][1]));
        put(vpmap, component.vertices[i], true);
      }
    m_report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const Norm_preserving_timings& t = m_report.timings;
    m_report.timings.write_back = (std::max)(0., m_report.seconds - t.extraction - t.guess - t.solve - t.sign_refinement
                                                   - t.euclidean_refinement);
    return m_report.status;
  }

private:
  enum class Pair_choice { HALFEDGE, AUTOMATIC, EXPLICIT };

  // The pair of the halfedge or the caller, as component indices; none for the automatic pair.
  Error_code explicit_pair(const Triangle_mesh& mesh, halfedge_descriptor bhd,
                           const internal::Norm_preserving::Mesh_component<Triangle_mesh>& component,
                           std::optional<std::pair<std::size_t, std::size_t> >& pair)
  {
    if(m_pair_choice == Pair_choice::AUTOMATIC)
      return OK;
    const vertex_descriptor va = m_pair_choice == Pair_choice::EXPLICIT ? m_a : source(bhd, mesh);
    const vertex_descriptor vb = m_pair_choice == Pair_choice::EXPLICIT ? m_b : target(bhd, mesh);
    if(!component.has(va) || !component.has(vb))
    {
      m_report.message = "a fixed vertex is not in the component of the halfedge";
      return ERROR_WRONG_PARAMETER;
    }
    pair = std::make_pair(std::size_t(get(component.index, va)), std::size_t(get(component.index, vb)));
    return OK;
  }

  internal::Norm_preserving::Pipeline<Initial_guess, Solver> m_pipeline;
  Pair_choice m_pair_choice = Pair_choice::HALFEDGE;
  vertex_descriptor m_a, m_b;
  std::pair<vertex_descriptor, vertex_descriptor> m_fixed;
  Norm_preserving_report m_report;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif
