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

} // namespace np_test

#endif
