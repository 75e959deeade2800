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
/// \file texture_polygon_mesh.h
/// \ingroup PkgNormPreservingParameterization
/// Texturing a whole polygon mesh or polygon soup in one call.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_TEXTURE_POLYGON_MESH_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_TEXTURE_POLYGON_MESH_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/disable_warnings.h>

#include <CGAL/Surface_mesh_parameterization/Norm_preserving_named_parameters.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Call_progress.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Component_layout.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Named_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Options.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Parallel_for.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Pipeline.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Soup_graph.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Texture_space_fit.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/concept/assert.hpp>
#include <boost/property_map/compose_property_map.hpp>
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

/// \ingroup PkgNormPreservingParameterizationTypes
/// What `texture_polygon_soup()`, `texture_polygon_mesh()` or `texture_indexed_mesh()` did
/// (named parameter `report`).
struct Texture_polygon_mesh_report
{
  Error_code status = OK;                         ///< result of the call
  std::string message;                            ///< readable reason of a failure
  std::size_t components = 0;                     ///< connected components textured
  std::size_t isolated_vertices = 0;              ///< vertices on no face: given no uv
  std::size_t welded_vertices = 0;                ///< vertices given the uv of a coincident one
  std::size_t repeated_corners = 0;               ///< face corners dropped as repeats of a vertex
  std::size_t point_components = 0;               ///< components of zero extent, mapped to a point
  double objective = 0;                           ///< sum of the components' Eq. 3 objectives
  /// the largest of the components' certified gaps, which bounds that of `objective` too
  double optimality_gap = 0;
  std::vector<Norm_preserving_report> reports;    ///< one per component
  double seconds = 0;                             ///< wall-clock time of the call
  bool interrupted = false;                       ///< whether the `progress` callback stopped the call
};

/// \cond SKIP_IN_MANUAL
namespace internal {
namespace Norm_preserving {

// texture_polygon_soup() on the positions of the soup's vertices, with its fixed pair, if any,
// as soup indices.
template <typename PolygonRange, typename VertexUVMap, typename InitialGuess, typename SolverTraits>
Error_code texture_soup(std::vector<std::array<double, 3> > positions, const PolygonRange& polygons, VertexUVMap uvmap,
                        const Options& options, const InitialGuess& guess, const SolverTraits& solver,
                        const std::optional<std::pair<std::size_t, std::size_t> >& requested_pair,
                        Texture_polygon_mesh_report* report, const Progress_callback& callback)
{
  typedef typename boost::property_traits<VertexUVMap>::value_type Point_2;
  const std::size_t none = Soup_graph::none, n = positions.size();

  const auto start = std::chrono::steady_clock::now();
  Texture_polygon_mesh_report local_report;
  Texture_polygon_mesh_report& r = report ? *report : local_report;
  r = Texture_polygon_mesh_report();
  auto finish = [&](Error_code status, const std::string& message) {
    r.status = status;
    r.message = message;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return status;
  };
  std::string message;
  Error_code status = check_polygon_soup(positions, polygons, message);
  if(status != OK)
    return finish(status, message);
  message = invalid_option(options);
  if(!message.empty())
    return finish(ERROR_WRONG_PARAMETER, message);

  const Soup_graph graph = build_soup_graph(std::move(positions), polygons, options.weld_coincident_vertices);
  r.components = graph.members.size();
  r.isolated_vertices = graph.unreferenced;
  r.welded_vertices = graph.welded;
  r.repeated_corners = graph.repeated_corners;

  // The fixed pair, as representatives, and its component.
  std::optional<std::pair<std::size_t, std::size_t> > fixed_pair;
  std::size_t pair_component = none;
  if(requested_pair)
  {
    const std::size_t a = requested_pair->first, b = requested_pair->second;
    if(a >= n || b >= n)
      return finish(ERROR_WRONG_PARAMETER, "a fixed vertex is not a vertex of the mesh");
    if(graph.representative[a] == none || graph.representative[b] == none)
      return finish(ERROR_WRONG_PARAMETER, "a fixed vertex lies on no face");
    fixed_pair = std::make_pair(graph.representative[a], graph.representative[b]);
    if(fixed_pair->first == fixed_pair->second && a != b)
      return finish(ERROR_WRONG_PARAMETER, "the fixed vertices are at the same position, welded into one");
    pair_component = graph.component[fixed_pair->first];
    if(graph.component[fixed_pair->second] != pair_component)
      return finish(ERROR_WRONG_PARAMETER, "the fixed vertices are not in the same connected component");
    const std::array<std::size_t, 2> edge = {(std::min)(fixed_pair->first, fixed_pair->second),
                                             (std::max)(fixed_pair->first, fixed_pair->second)};
    if(!std::binary_search(graph.edges.begin(), graph.edges.end(), edge))
      return finish(ERROR_WRONG_PARAMETER, "the fixed vertices are not the two ends of an edge");
  }

  // Every component in mesh units (NORM_PRESERVING_NO_FIT), then one layout and one fit for all.
  std::vector<std::array<double, 2> > uv(n, {0., 0.});
  typedef typename Solver_model<SolverTraits>::type Solver;
  BOOST_CONCEPT_ASSERT((concepts::NormPreservingInitialGuess<InitialGuess>));
  BOOST_CONCEPT_ASSERT((concepts::NormPreservingSolver<Solver>));
  Pipeline<InitialGuess, Solver> pipeline(guess, Solver(solver));
  pipeline.options() = options;
  pipeline.options().texture_fit = NORM_PRESERVING_NO_FIT; // the fit and the tiling come after the layout
  pipeline.options().tiles_u = pipeline.options().tiles_v = 1;
  const std::vector<std::vector<std::size_t> > edges_of = edges_by_component(graph);
  std::vector<std::size_t> local(n, none); // each component writes its own members
  std::vector<UV_vector> component_uv(r.components);
  std::vector<unsigned char> is_point(r.components, 0); // of zero extent
  r.reports.resize(r.components);
  Call_progress progress(callback, graph.members, start);
  // The components are independent: on a TBB build they run at once, each as it would alone,
  // so the bits do not depend on the number of threads (doc/decisions.md, the QP's solver).
  parallel_for_each_task(r.components, [&](std::size_t c) {
    const auto component_start = std::chrono::steady_clock::now();
    if(!progress.update(c, 0))
      return;
    const std::function<bool(double)> solve_progress = [&progress, c](double f) { return progress.update(c, f); };
    Norm_preserving_geometry geometry = component_geometry(graph, c, edges_of, local);
    Norm_preserving_report& component_report = r.reports[c];
    std::optional<std::pair<std::size_t, std::size_t> > pair;
    if(c == pair_component)
      pair = std::make_pair(local[fixed_pair->first], local[fixed_pair->second]);
    const bool has_extent = std::any_of(geometry.edges.begin(), geometry.edges.end(), [&](const auto& e) {
      return geometry.points[e[0]] != geometry.points[e[1]];
    });
    if(has_extent)
      component_report.status = pipeline.run(std::move(geometry), pair, component_uv[c], component_report,
                                             progress.active() ? &solve_progress : nullptr);
    else
    {
      // Every vertex at one position: the optimum of Eq. 5 is a point.
      component_report.vertices = geometry.points.size();
      component_report.edges = geometry.edges.size();
      component_report.solver.status = NORM_PRESERVING_SOLVER_CONVERGED;
      component_report.solver.optimality_gap = 0;
      component_uv[c].assign(geometry.points.size(), {0., 0.});
      is_point[c] = 1;
      component_report.status = pair && pair->first != pair->second ? ERROR_WRONG_PARAMETER : OK;
      component_report.message = component_report.status == OK ? "" : "the fixed vertices are at the same position";
    }
    component_report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - component_start).count();
    progress.finish(c);
  });
  if(progress.stopped())
  {
    r.interrupted = true;
    return finish(ERROR_CANNOT_SOLVE_LINEAR_SYSTEM, "interrupted by the progress callback");
  }

  // In component order: the first failure is the call's, whatever ran first.
  for(std::size_t c = 0; c < r.components; ++c)
  {
    Norm_preserving_report& component_report = r.reports[c];
    if(component_report.status != OK)
      return finish(component_report.status, "component " + std::to_string(c) + ": " + component_report.message);
    component_report.fixed_a = graph.members[c][component_report.fixed_a]; // the caller's indices
    component_report.fixed_b = graph.members[c][component_report.fixed_b];
    r.point_components += is_point[c];
    r.objective += component_report.objective;
    r.optimality_gap = (std::max)(r.optimality_gap, component_report.solver.optimality_gap);
    for(std::size_t k = 0; k < component_uv[c].size(); ++k)
      uv[graph.members[c][k]] = component_uv[c][k];
  }
  if(r.point_components == r.components)
    return finish(ERROR_WRONG_PARAMETER, "the mesh has zero extent: the vertices of each component are at one position");

  lay_out_components(uv, graph.component, r.components);
  std::vector<std::array<double, 2> > on_faces;
  for(std::size_t i = 0; i < n; ++i)
    if(graph.component[i] != none) on_faces.push_back(uv[i]);
  fit_to_texture_space(on_faces, options.texture_fit, options.tiles_u, options.tiles_v);
  std::size_t k = 0;
  for(std::size_t i = 0; i < n; ++i)
    if(graph.component[i] != none)
      uv[i] = on_faces[k++];
  for(std::size_t i = 0; i < n; ++i)
    if(graph.representative[i] != none)
    {
      const std::array<double, 2>& p = uv[graph.representative[i]];
      put(uvmap, i, Point_2(p[0], p[1]));
    }
  return finish(OK, std::string());
}

// The coordinates of `p` as doubles, through the traits' constructions.
template <typename Traits, typename Point>
std::array<double, 3> coordinates(const Traits& traits, const Point& p)
{
  return {CGAL::to_double(traits.compute_x_3_object()(p)), CGAL::to_double(traits.compute_y_3_object()(p)),
          CGAL::to_double(traits.compute_z_3_object()(p))};
}

// texture_soup() with what the named parameters say, on the threads that ConcurrencyTag allows.
template <typename ConcurrencyTag, typename PolygonRange, typename VertexUVMap, typename NamedParameters, typename Index>
Error_code texture_soup(std::vector<std::array<double, 3> > positions, const PolygonRange& polygons, VertexUVMap uvmap,
                        const NamedParameters& np, const Index& index)
{
  return run_with_concurrency<ConcurrencyTag>([&] {
    return texture_soup(std::move(positions), polygons, uvmap, named_options(np), named_guess(np), named_solver(np),
                        named_fixed_pair(np, index), named_report<Texture_polygon_mesh_report>(np), named_progress(np));
  });
}

} // namespace Norm_preserving
} // namespace internal
/// \endcond

/// \ingroup PkgNormPreservingParameterizationFunctions
/// textures a polygon soup: `points[i]` is vertex `i`, each element of `polygons` lists the
/// vertex indices of one face. Any soup is accepted as it is: the method needs only the edges
/// (paper Eq. 4), so faces need not form a manifold, be consistently oriented or orientable.
///
/// The edge graph is built from the faces, each triangulated on its own (adding no vertex); a
/// face that passes through a vertex more than once is split there (a repeat in a row is
/// dropped), and a face left with two distinct vertices adds its edge. Vertices at exactly the
/// same position are welded into one (unless `weld_coincident_vertices(false)`).
/// Each connected component of the graph is parameterized with `Norm_preserving_parameterizer_3`'s
/// method at one common scale (mesh units, so texel density is uniform), several at once on a
/// TBB build (with the same result as on one thread); a component of zero extent is mapped to
/// a point. The components are laid side by side with disjoint bounding boxes, the layout is
/// fitted into texture space and tiled, and the uv of every vertex on a face is written into
/// `uvmap` (a welded vertex gets the uv of its weld). Vertices on no face are left as they were.
///
/// On failure nothing is written, the report's `message` says why, and the code is:
/// - `ERROR_EMPTY_MESH`: no face;
/// - `ERROR_WRONG_PARAMETER`: a face that refers to a missing vertex, a non-finite coordinate
///   of a vertex on a face, all vertices at one position, an option out of range, a fixed pair
///   on no face, in two components, welded into one vertex or not an edge;
/// - or the error of a component, as `Norm_preserving_parameterizer_3::parameterize()` says.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (the package's loops on the calling thread),
///         `CGAL::Parallel_tag` (on TBB's threads; needs TBB) or `CGAL::Parallel_if_available_tag`
///         (the default: TBB's threads when the package is built with TBB); the uvs are the same,
///         bit for bit
/// \tparam PointRange a range of points (or of anything `point_map` maps to points)
/// \tparam PolygonRange a random-access range of ranges of integer indices
/// \tparam VertexUVMap a model of `WritablePropertyMap` from `std::size_t` to a 2D point type
/// \tparam NamedParameters a sequence of named parameters
/// \param points the vertex positions
/// \param polygons the faces, as vertex indices in order around each
/// \param uvmap receives the uv of vertex `i` as `put(uvmap, i, uv)`
/// \param np the named parameters of `CGAL::Surface_mesh_parameterization::parameters`, all
///        optional: `initial_guess`, `solver` or `quality`, `texture_fit`, `tiling`,
///        `fixed_pair` (two vertex indices), `sign_refinement`, `euclidean_refinement`,
///        `weld_coincident_vertices`, `report`, `progress`; and CGAL's `point_map` (default the identity)
///        and `geom_traits` (default the kernel of the point type), whose `Compute_x_3`,
///        `Compute_y_3` and `Compute_z_3` read the coordinates
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag,
          typename PointRange, typename PolygonRange, typename VertexUVMap,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code texture_polygon_soup(const PointRange& points, const PolygonRange& polygons, VertexUVMap uvmap,
                                const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  namespace P = CGAL::parameters;
  typedef CGAL_NP_CLASS NamedParameters;
  typedef typename GetPointMap<PointRange, NamedParameters>::const_type Point_map;
  const Point_map point_map = P::choose_parameter<Point_map>(P::get_parameter(np, CGAL::internal_np::point_map));
  typedef typename CGAL::Kernel_traits<typename boost::property_traits<Point_map>::value_type>::Kernel Default_traits;
  typedef internal::Norm_preserving::Named_type<CGAL::internal_np::geom_traits_t, NamedParameters, Default_traits> Traits;
  const Traits traits = P::choose_parameter<Traits>(P::get_parameter(np, CGAL::internal_np::geom_traits));
  std::vector<std::array<double, 3> > positions;
  for(const auto& element : points)
    positions.push_back(internal::Norm_preserving::coordinates(traits, get(point_map, element)));
  return internal::Norm_preserving::texture_soup<ConcurrencyTag>(std::move(positions), polygons, uvmap, np,
                                                                 [](const auto& i) { return std::size_t(i); });
}

/// \ingroup PkgNormPreservingParameterizationFunctions
/// textures a whole polygon mesh: `texture_polygon_soup()` on its faces, vertex `i` being the
/// `i`-th vertex of `vertices(mesh)`, and the uv of every vertex on a face written into
/// `uvmap`. Vertices on no face are left as they were. Fails as `texture_polygon_soup()`
/// does, writing nothing.
///
/// \tparam ConcurrencyTag as for `texture_polygon_soup()`
/// \tparam PolygonMesh a model of `FaceListGraph`
/// \tparam VertexUVMap a model of `WritablePropertyMap` from vertices to a 2D point type
/// \tparam NamedParameters a sequence of named parameters
/// \param mesh the mesh
/// \param uvmap receives the uvs
/// \param np the named parameters of `texture_polygon_soup()`, with `fixed_pair` given as two
///        vertex descriptors, and CGAL's `vertex_point_map` (default the mesh's internal map)
///        in place of `point_map`; `geom_traits` defaults to the kernel of its points
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag,
          typename PolygonMesh, typename VertexUVMap,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code texture_polygon_mesh(const PolygonMesh& mesh, VertexUVMap uvmap,
                                const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  namespace P = CGAL::parameters;
  typedef CGAL_NP_CLASS NamedParameters;
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  const auto vpm = P::choose_parameter(P::get_parameter(np, CGAL::internal_np::vertex_point),
                                       get_const_property_map(CGAL::vertex_point, mesh));
  typedef typename GetGeomTraits<PolygonMesh, NamedParameters>::type Traits;
  const Traits traits = P::choose_parameter<Traits>(P::get_parameter(np, CGAL::internal_np::geom_traits));

  // The soup in the input's vertex order, so that indices do not depend on the mesh type.
  std::vector<std::array<double, 3> > positions;
  std::vector<vertex_descriptor> original;
  auto index_of = get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh);
  for(vertex_descriptor v : vertices(mesh))
  {
    put(index_of, v, positions.size());
    positions.push_back(internal::Norm_preserving::coordinates(traits, get(vpm, v)));
    original.push_back(v);
  }
  std::vector<std::vector<std::size_t> > polygons;
  for(auto f : faces(mesh))
  {
    polygons.emplace_back();
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      polygons.back().push_back(get(index_of, v));
  }
  return internal::Norm_preserving::texture_soup<ConcurrencyTag>(
    std::move(positions), polygons, boost::make_compose_property_map(uvmap, CGAL::make_property_map(original)), np,
    [&](vertex_descriptor v) { return get(index_of, v); });
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif
