// Step 1 of the paper for the whole-mesh call (DESIGN.md item 1): a polygon soup checked
// face by face, split into its connected components (polygons that share a vertex), and each
// component built as a triangle mesh of its own, its polygons triangulated, and parameterized,
// so that the work is linear in the size of the soup however many components it has.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_POLYGON_SOUP_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_POLYGON_SOUP_H

#include <CGAL/Surface_mesh_parameterization/Error_code.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

// What the mesh data structure and the triangulation do not check themselves: at least one
// face, faces of at least three distinct vertices that exist, finite positions on faces.
template <typename PointRange, typename PolygonRange>
Error_code check_polygon_soup(const PointRange& points, const PolygonRange& polygons, std::string& message)
{
  if(polygons.empty())
  {
    message = "the mesh has no face";
    return ERROR_EMPTY_MESH;
  }
  std::size_t k = 0;
  std::vector<std::size_t> sorted;
  for(const auto& polygon : polygons)
  {
    const std::string face = "face " + std::to_string(k++);
    sorted.assign(polygon.begin(), polygon.end());
    if(sorted.size() < 3)
    {
      message = face + " has " + std::to_string(sorted.size()) + " vertices";
      return ERROR_NON_TRIANGULAR_MESH;
    }
    for(std::size_t i : sorted)
    {
      if(i >= points.size())
      {
        message = face + " refers to vertex " + std::to_string(i) + " of " + std::to_string(points.size());
        return ERROR_WRONG_PARAMETER;
      }
      const auto& p = points[i];
      if(!(std::isfinite(CGAL::to_double(p.x())) && std::isfinite(CGAL::to_double(p.y())) &&
           std::isfinite(CGAL::to_double(p.z()))))
      {
        message = "vertex " + std::to_string(i) + " has a non-finite coordinate";
        return ERROR_WRONG_PARAMETER;
      }
    }
    std::sort(sorted.begin(), sorted.end());
    if(std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
    {
      message = face + " has a repeated vertex";
      return ERROR_NON_TRIANGULAR_MESH;
    }
  }
  return OK;
}

// Union-find over the vertices of a checked soup. Returns the number of components and fills
// the component of each polygon and of each vertex (the count itself for a vertex on no
// polygon), numbered in the order of their first polygon.
template <typename PolygonRange>
std::size_t soup_components(std::size_t point_count, const PolygonRange& polygons,
                            std::vector<std::size_t>& component_of_polygon,
                            std::vector<std::size_t>& component_of_vertex)
{
  std::vector<std::size_t> parent(point_count);
  for(std::size_t i = 0; i < point_count; ++i)
    parent[i] = i;
  const auto root = [&parent](std::size_t i) {
    while(parent[i] != i)
      i = parent[i] = parent[parent[i]];
    return i;
  };
  for(const auto& polygon : polygons)
    for(std::size_t i : polygon)
      parent[root(i)] = root(*polygon.begin());

  const std::size_t none = point_count; // no component can have this number before the end
  std::vector<std::size_t> number_of_root(point_count, none);
  std::size_t count = 0;
  component_of_polygon.clear();
  for(const auto& polygon : polygons)
  {
    std::size_t& number = number_of_root[root(*polygon.begin())];
    if(number == none)
      number = count++;
    component_of_polygon.push_back(number);
  }
  component_of_vertex.assign(point_count, count);
  for(std::size_t k = 0; k < component_of_polygon.size(); ++k)
    for(std::size_t i : polygons[k])
      component_of_vertex[i] = component_of_polygon[k];
  return count;
}

// Step 1 for one polygon, adding no vertex: a triangle as it is; a quad split along the
// diagonal whose two triangles' normals agree best (as Polygon_mesh_processing::
// triangulate_faces() does); a larger polygon by hole filling (triangulate_hole_polyline()) or,
// where that finds no complete triangulation (a degenerate outline), by a fan from its first
// vertex. Not triangulate_faces() itself: on a polygon whose projection crosses itself its
// constrained Delaunay triangulation inserts the crossings as new vertices, and its hole
// filling builds an incomplete patch into the mesh; in both cases CGAL 5.5 then reads past the
// end of the halfedges (found by the fuzzer).
template <typename PointRange, typename Polygon>
void triangulate_polygon(const PointRange& points, const Polygon& polygon,
                         std::vector<std::array<std::size_t, 3> >& triangles)
{
  // Exact predicates: hole filling searches a 3D Delaunay triangulation, which asserts (or
  // loops) on the rounding errors of inexact ones (found by the fuzzer).
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 Point_3;
  const std::vector<std::size_t> corner(polygon.begin(), polygon.end());
  const std::size_t n = corner.size();
  std::vector<Point_3> outline;
  for(std::size_t i : corner)
    outline.emplace_back(CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()), CGAL::to_double(points[i].z()));
  triangles.clear();
  if(n == 3)
  {
    triangles.push_back({corner[0], corner[1], corner[2]});
    return;
  }
  if(n == 4)
  {
    const auto normal = [&outline](int a, int b, int c) {
      return CGAL::cross_product(outline[b] - outline[a], outline[c] - outline[a]);
    };
    if(normal(0, 1, 2) * normal(0, 2, 3) > normal(1, 2, 3) * normal(1, 3, 0))
      triangles = {{corner[0], corner[1], corner[2]}, {corner[0], corner[2], corner[3]}};
    else
      triangles = {{corner[1], corner[2], corner[3]}, {corner[1], corner[3], corner[0]}};
    return;
  }
  std::vector<CGAL::Triple<int, int, int> > patch;
  CGAL::Polygon_mesh_processing::triangulate_hole_polyline(outline, std::back_inserter(patch));
  // Complete: n - 2 triangles that use every side of the outline once.
  std::vector<int> sides(n, 0);
  for(const auto& t : patch)
  {
    const std::array<std::size_t, 3> v = {std::size_t(t.first), std::size_t(t.second), std::size_t(t.third)};
    for(int e = 0; e < 3; ++e)
      if(v[(e + 1) % 3] == (v[e] + 1) % n) ++sides[v[e]];
  }
  if(patch.size() == n - 2 && std::all_of(sides.begin(), sides.end(), [](int used) { return used == 1; }))
    for(const auto& t : patch)
      triangles.push_back({corner[std::size_t(t.first)], corner[std::size_t(t.second)], corner[std::size_t(t.third)]});
  else
    for(std::size_t i = 1; i + 1 < n; ++i)
      triangles.push_back({corner[0], corner[i], corner[i + 1]});
}

// Builds the polygons `members` of one component as a mesh of the parameterizer's type, its
// vertices in increasing soup order (so that ties resolve as they would in the whole soup),
// each polygon triangulated, and parameterizes it with `fixed_pair` (soup indices) or the automatic
// pair. On success `uv` holds the uv of each of its vertices at their soup index.
template <typename PointRange, typename PolygonRange, typename Parameterizer>
Error_code parameterize_soup_component(const PointRange& points, const PolygonRange& polygons,
                                       const std::vector<std::size_t>& members,
                                       const std::optional<std::pair<std::size_t, std::size_t> >& fixed_pair,
                                       Parameterizer& parameterizer,
                                       std::vector<std::array<double, 2> >& uv,
                                       std::string& message)
{
  typedef typename Parameterizer::Triangle_mesh TM;
  typedef typename TM::Vertex_index Vertex;
  std::vector<std::size_t> soup_vertices;
  for(std::size_t k : members)
    soup_vertices.insert(soup_vertices.end(), polygons[k].begin(), polygons[k].end());
  std::sort(soup_vertices.begin(), soup_vertices.end());
  soup_vertices.erase(std::unique(soup_vertices.begin(), soup_vertices.end()), soup_vertices.end());
  const auto local = [&soup_vertices](std::size_t i) {
    return Vertex(typename TM::size_type(std::lower_bound(soup_vertices.begin(), soup_vertices.end(), i) -
                                         soup_vertices.begin()));
  };

  TM tm;
  for(std::size_t i : soup_vertices)
  {
    const auto& p = points[i];
    tm.add_vertex(typename TM::Point(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
  }
  std::vector<std::array<std::size_t, 3> > triangles;
  for(std::size_t k : members)
  {
    triangulate_polygon(points, polygons[k], triangles);
    for(const auto& t : triangles)
      if(tm.add_face(local(t[0]), local(t[1]), local(t[2])) == TM::null_face())
      {
        message = "face " + std::to_string(k) + " cannot be added: it makes an edge non-manifold (a third face"
                  " on it) or a vertex non-manifold, or is oriented against a neighbour";
        return ERROR_NON_TRIANGULAR_MESH;
      }
  }

  if(fixed_pair)
    parameterizer.set_fixed_pair(local(fixed_pair->first), local(fixed_pair->second));
  else
    parameterizer.set_automatic_fixed_pair();
  typedef typename CGAL::Kernel_traits<typename TM::Point>::Kernel::Point_2 Point_2;
  const auto tm_uv = tm.template add_property_map<Vertex, Point_2>("v:np_uv").first;
  const auto tm_done = tm.template add_property_map<Vertex, bool>("v:np_done", false).first;
  const Error_code status = parameterizer.parameterize(tm, halfedge(*faces(tm).begin(), tm), tm_uv,
                                                       get(CGAL::vertex_index, tm), tm_done);
  if(status != OK)
  {
    message = parameterizer.report().message;
    return status;
  }
  for(Vertex v : vertices(tm))
    uv[soup_vertices[v]] = {get(tm_uv, v).x(), get(tm_uv, v).y()};
  return OK;
}

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
