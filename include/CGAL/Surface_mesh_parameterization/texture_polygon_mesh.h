#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_TEXTURE_POLYGON_MESH_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_TEXTURE_POLYGON_MESH_H

#include <CGAL/Surface_mesh_parameterization/Norm_preserving_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Component_layout.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/property_map/property_map.hpp>

#include <chrono>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterization
/// The triangle mesh that `texture_polygon_mesh()` triangulates its input into.
typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Norm_preserving_triangle_mesh;

/// \ingroup PkgNormPreservingParameterization
/// Options of `texture_polygon_mesh()`.
///
/// CGAL 5.5's named parameters cannot be extended outside CGAL, so the options are a struct,
/// with the same names and defaults as the parameterizer's setters.
/// \tparam PolygonMesh the input mesh type
/// \tparam InitialGuess a model of `NormPreservingInitialGuess`
/// \tparam SolverTraits a model of `QuadraticProgramTraits`
template <typename PolygonMesh,
          typename InitialGuess = XY_min_max_initial_guess,
          typename SolverTraits = Interior_point_quadratic_program_traits<double> >
struct Texture_polygon_mesh_options
{
  /// vertex handle of the input mesh
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;

  InitialGuess initial_guess = InitialGuess(); ///< the initial guess used on every component
  SolverTraits solver = SolverTraits();        ///< the QP solver (carries its tolerance)
  Texture_fit texture_fit = UNIFORM_FIT;       ///< fit of the whole layout into texture space
  int tiles_u = 1;                             ///< `m` of the `m x n` tiling
  int tiles_v = 1;                             ///< `n` of the `m x n` tiling
  /// the fixed pair of the component that contains it (adjacent vertices); every other
  /// component, and all if empty, uses the automatic pair
  std::optional<std::pair<vertex_descriptor, vertex_descriptor> > fixed_pair;
};

/// \ingroup PkgNormPreservingParameterization
/// What `texture_polygon_mesh()` did.
struct Texture_polygon_mesh_report
{
  Error_code status = OK;                         ///< result of the call
  std::string message;                            ///< readable reason of a failure
  std::size_t components = 0;                     ///< connected components textured
  std::size_t isolated_vertices = 0;              ///< vertices on no face: given no uv
  double objective = 0;                           ///< sum of the components' Eq. 3 objectives
  std::vector<Norm_preserving_report> reports;    ///< one per component
  double seconds = 0;                             ///< wall-clock time of the call
};

/// \ingroup PkgNormPreservingParameterization
/// textures a whole polygon mesh: triangulates a copy (adding no vertex), parameterizes every
/// connected component with `Norm_preserving_parameterizer_3` at one common scale (mesh
/// units, so texel density is uniform), lays the components side by side with disjoint
/// bounding boxes, fits the layout into texture space, tiles it, and writes the uv of every
/// vertex on a face into `uvmap`. Vertices on no face are left as they were.
///
/// On failure (`ERROR_EMPTY_MESH`, a face that cannot be added or triangulated, or any
/// component's error) nothing is written and `report->message` says why.
///
/// \tparam PolygonMesh a model of `FaceListGraph` with an internal `vertex_point` map
/// \tparam VertexUVMap a model of `WritablePropertyMap` from vertices to a 2D point type
template <typename PolygonMesh, typename VertexUVMap,
          typename InitialGuess = XY_min_max_initial_guess,
          typename SolverTraits = Interior_point_quadratic_program_traits<double> >
Error_code texture_polygon_mesh(const PolygonMesh& mesh, VertexUVMap uvmap,
                                const Texture_polygon_mesh_options<PolygonMesh, InitialGuess, SolverTraits>& options = {},
                                Texture_polygon_mesh_report* report = nullptr)
{
  typedef Norm_preserving_triangle_mesh TM;
  typedef typename boost::property_traits<VertexUVMap>::value_type Point_2;
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  namespace NP = internal::Norm_preserving;

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
  if(faces(mesh).empty())
    return finish(ERROR_EMPTY_MESH, "the mesh has no face");

  // Step 1 on a copy with the input's vertex order, so that indices do not depend on the
  // mesh type.
  TM tm;
  auto copy_of = get(CGAL::dynamic_vertex_property_t<typename TM::Vertex_index>(), mesh);
  std::vector<vertex_descriptor> original;
  for(vertex_descriptor v : vertices(mesh))
  {
    const auto& p = get(CGAL::vertex_point, mesh, v);
    put(copy_of, v, tm.add_vertex(TM::Point(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()))));
    original.push_back(v);
  }
  std::vector<typename TM::Vertex_index> polygon;
  for(auto f : faces(mesh))
  {
    polygon.clear();
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      polygon.push_back(get(copy_of, v));
    if(tm.add_face(polygon) == TM::null_face())
      return finish(ERROR_NON_TRIANGULAR_MESH, "a face has a repeated vertex or makes the mesh non-manifold");
  }
  if(!CGAL::is_triangle_mesh(tm) && !CGAL::Polygon_mesh_processing::triangulate_faces(tm))
    return finish(ERROR_NON_TRIANGULAR_MESH, "a face could not be triangulated");

  auto component_of = tm.add_property_map<typename TM::Face_index, std::size_t>("f:np_component").first;
  r.components = CGAL::Polygon_mesh_processing::connected_components(tm, component_of);
  std::vector<typename TM::Halfedge_index> seeds(r.components, TM::null_halfedge());
  std::vector<std::size_t> component_of_vertex(num_vertices(tm), r.components); // isolated: none
  for(auto f : faces(tm))
  {
    const std::size_t c = get(component_of, f);
    if(seeds[c] == TM::null_halfedge())
      seeds[c] = halfedge(f, tm);
    for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm))
      component_of_vertex[v] = c;
  }
  std::size_t pair_component = r.components;
  if(options.fixed_pair)
  {
    pair_component = component_of_vertex[get(copy_of, options.fixed_pair->first)];
    if(pair_component == r.components)
      return finish(ERROR_WRONG_PARAMETER, "a fixed vertex lies on no face");
  }

  // Every component in mesh units (NO_FIT), then one layout and one fit for all.
  auto tm_uv = tm.add_property_map<typename TM::Vertex_index, Point_2>("v:np_uv").first;
  auto tm_done = tm.add_property_map<typename TM::Vertex_index, bool>("v:np_done", false).first;
  Norm_preserving_parameterizer_3<TM, InitialGuess, SolverTraits> parameterizer(options.initial_guess, options.solver);
  parameterizer.set_texture_fit(NO_FIT);
  for(std::size_t c = 0; c < r.components; ++c)
  {
    if(c == pair_component)
      parameterizer.set_fixed_pair(get(copy_of, options.fixed_pair->first), get(copy_of, options.fixed_pair->second));
    else
      parameterizer.set_automatic_fixed_pair();
    const Error_code status = parameterizer.parameterize(tm, seeds[c], tm_uv, get(CGAL::vertex_index, tm), tm_done);
    r.reports.push_back(parameterizer.report());
    if(status != OK)
      return finish(status, "component " + std::to_string(c) + ": " + parameterizer.report().message);
    r.objective += parameterizer.report().objective;
  }

  std::vector<std::array<double, 2> > uv(num_vertices(tm));
  for(auto v : vertices(tm))
    uv[v] = {get(tm_uv, v).x(), get(tm_uv, v).y()};
  NP::lay_out_components(uv, component_of_vertex, r.components);
  std::vector<std::array<double, 2> > on_faces;
  for(auto v : vertices(tm))
    if(get(tm_done, v)) on_faces.push_back(uv[v]);
  NP::fit_to_texture_space(on_faces, options.texture_fit, options.tiles_u, options.tiles_v);

  std::size_t k = 0;
  for(auto v : vertices(tm))
  {
    if(get(tm_done, v)) uv[v] = on_faces[k++];
    else ++r.isolated_vertices;
  }
  for(std::size_t i = 0; i < original.size(); ++i)
  {
    const auto v = get(copy_of, original[i]);
    if(get(tm_done, v))
      put(uvmap, original[i], Point_2(uv[v][0], uv[v][1]));
  }
  return finish(OK, std::string());
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
