// Meshes for the tests: CGAL's collection from Debian's libcgal-demo (extracted by CMake
// into the build tree) and small solids made here.

#ifndef NP_TEST_MESHES_H
#define NP_TEST_MESHES_H

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/subdivision_method_3.h>

#include <stdexcept>
#include <string>

namespace np_test {

using Kernel = CGAL::Simple_cartesian<double>;
using Point_2 = Kernel::Point_2;
using Point_3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point_3>;

inline Mesh load_mesh(const std::string& name)
{
  Mesh mesh;
  const std::string path = std::string(NP_MESH_DIR) + "/" + name + ".off";
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || mesh.is_empty())
    throw std::runtime_error("cannot read " + path);
  return mesh;
}

inline Mesh tetrahedron()
{
  Mesh mesh;
  CGAL::make_tetrahedron(Point_3(0, 0, 0), Point_3(3, 0, 1), Point_3(1, 2, 0), Point_3(1, 1, 4), mesh);
  return mesh;
}

inline Mesh triangulated_cube()
{
  Mesh mesh;
  CGAL::make_hexahedron(Point_3(0, 0, 0), Point_3(2, 0, 0), Point_3(2, 3, 0), Point_3(0, 3, 0),
                        Point_3(0, 3, 1), Point_3(0, 0, 1), Point_3(2, 0, 1), Point_3(2, 3, 1), mesh);
  CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
  return mesh;
}

// Icosahedron refined once by Loop subdivision: 42 vertices.
inline Mesh icosphere()
{
  Mesh mesh;
  CGAL::make_icosahedron<Mesh, Point_3>(mesh, Point_3(0.1, 0.2, 0.3), 1.);
  CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(1));
  return mesh;
}

// A proper triangle (a, b, c) and, across its edge ab, a face (b, a, a) with a repeated
// vertex, built halfedge by halfedge (add_face refuses it).
inline Mesh triangle_and_face_with_a_repeated_vertex()
{
  Mesh mesh;
  const auto a = mesh.add_vertex(Point_3(0, 0, 0)), b = mesh.add_vertex(Point_3(1, 0, 0));
  const auto c = mesh.add_vertex(Point_3(0, 1, 0));
  mesh.add_face(a, b, c);
  const auto ab = mesh.halfedge(a, b);
  const auto ba = mesh.opposite(ab);
  const auto loop = mesh.add_edge(); // add_edge(a, a) asserts
  mesh.set_target(loop, a);
  mesh.set_target(mesh.opposite(loop), a);
  const auto f = mesh.add_face();
  mesh.set_face(ba, f); mesh.set_face(loop, f); mesh.set_face(mesh.opposite(loop), f);
  mesh.set_next(ba, loop); mesh.set_next(loop, mesh.opposite(loop)); mesh.set_next(mesh.opposite(loop), ba);
  mesh.set_halfedge(f, ba);
  return mesh;
}

} // namespace np_test

#endif
