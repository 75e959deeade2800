// One run of the parameterizer, or of the whole-mesh call, on a mesh whose uv map starts
// filled with a sentinel, so that a test can tell whether the run wrote to it; and Eq. 3
// recomputed from a run's uvs.

#ifndef NP_TEST_RUNS_H
#define NP_TEST_RUNS_H

#include "test_meshes.h"

#include <CGAL/Surface_mesh_parameterization/Interior_point_quadratic_program_traits.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/texture_polygon_mesh.h>

#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace np_test {

namespace SMP = CGAL::Surface_mesh_parameterization;
using Vertex = Mesh::Vertex_index;
using Halfedge = Mesh::Halfedge_index;
using Parameterizer = SMP::Norm_preserving_parameterizer_3<Mesh>;
// The interior-point QP solver: the reference the ADMM's optima are compared with.
using Exact_parameterizer =
  SMP::Norm_preserving_parameterizer_3<Mesh, CGAL::Default, SMP::Interior_point_quadratic_program_traits<double> >;

const Point_2 sentinel(-123.5, 456.25);

// The parameterizer on `mesh`, its uvs and marks.
struct Mapped_mesh
{
  Mesh mesh;
  Mesh::Property_map<Vertex, Point_2> uv;
  Mesh::Property_map<Vertex, bool> marked;
  SMP::Error_code status = SMP::OK;
  SMP::Norm_preserving_report report;

  explicit Mapped_mesh(Mesh m) : mesh(std::move(m))
  {
    uv = mesh.add_property_map<Vertex, Point_2>("v:uv", sentinel).first;
    marked = mesh.add_property_map<Vertex, bool>("v:marked", false).first;
  }
  template <typename P>
  void parameterize(P& parameterizer, Halfedge h)
  {
    status = parameterizer.parameterize(mesh, h, uv, get(CGAL::vertex_index, mesh), marked);
    report = parameterizer.report();
  }
  bool untouched() const
  {
    for(Vertex v : vertices(mesh))
      if(get(uv, v) != sentinel || get(marked, v)) return false;
    return true;
  }
};

// `texture_polygon_mesh()` on `mesh`, with the package's named parameters `np` if given.
struct Textured
{
  Mesh mesh;
  Mesh::Property_map<Vertex, Point_2> uv;
  SMP::Texture_polygon_mesh_report report;
  SMP::Error_code status = SMP::OK;

  explicit Textured(Mesh m) : mesh(std::move(m))
  {
    uv = mesh.add_property_map<Vertex, Point_2>("v:uv", sentinel).first;
    status = SMP::texture_polygon_mesh(mesh, uv, SMP::parameters::report(report));
  }
  template <typename NamedParameters>
  Textured(Mesh m, const NamedParameters& np) : mesh(std::move(m))
  {
    uv = mesh.add_property_map<Vertex, Point_2>("v:uv", sentinel).first;
    status = SMP::texture_polygon_mesh(mesh, uv, np.combine(SMP::parameters::report(report)));
  }
  bool untouched() const
  {
    for(Vertex v : vertices(mesh))
      if(get(uv, v) != sentinel) return false;
    return true;
  }
};

using Polygons = std::vector<std::vector<std::size_t> >;

// `texture_polygon_soup()` on `points` and `polygons`, into a uv vector filled with the
// sentinel, with the package's named parameters `np` if given.
struct Textured_soup
{
  std::vector<Point_3> points;
  Polygons polygons;
  std::vector<Point_2> uv;
  SMP::Texture_polygon_mesh_report report;
  SMP::Error_code status = SMP::OK;

  Textured_soup(std::vector<Point_3> p, Polygons f)
    : points(std::move(p)), polygons(std::move(f)), uv(points.size(), sentinel)
  {
    status = SMP::texture_polygon_soup(points, polygons, CGAL::make_property_map(uv), SMP::parameters::report(report));
  }
  template <typename NamedParameters>
  Textured_soup(std::vector<Point_3> p, Polygons f, const NamedParameters& np)
    : points(std::move(p)), polygons(std::move(f)), uv(points.size(), sentinel)
  {
    status = SMP::texture_polygon_soup(points, polygons, CGAL::make_property_map(uv),
                                       np.combine(SMP::parameters::report(report)));
  }
  bool untouched() const
  {
    return std::all_of(uv.begin(), uv.end(), [](const Point_2& p) { return p == sentinel; });
  }
};

inline bool is_finite(const Point_2& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

inline double l1(const Point_3& p, const Point_3& q)
{
  return std::abs(p.x() - q.x()) + std::abs(p.y() - q.y()) + std::abs(p.z() - q.z());
}

// Eq. 3 recomputed from the written uvs (NORM_PRESERVING_NO_FIT: mesh units) over the edges of
// the marked component, independently of the solver.
inline double eq3(const Mapped_mesh& run)
{
  double sum = 0;
  for(auto e : edges(run.mesh))
  {
    const Vertex i = source(halfedge(e, run.mesh), run.mesh), j = target(halfedge(e, run.mesh), run.mesh);
    if(!get(run.marked, i)) continue;
    const Point_2 a = get(run.uv, i), b = get(run.uv, j);
    const double r = l1(run.mesh.point(i), run.mesh.point(j)) - std::abs(a.x() - b.x()) - std::abs(a.y() - b.y());
    sum += r * r;
  }
  return sum;
}

} // namespace np_test

#endif
