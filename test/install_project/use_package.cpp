// Textures an icosahedron (closed) through the installed package.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/texture_polygon_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/version.h>

#include <Eigen/Core>

#include <iostream>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;

int main()
{
  Mesh mesh;
  CGAL::make_icosahedron<Mesh, Kernel::Point_3>(mesh);
  auto uv = mesh.add_property_map<Mesh::Vertex_index, Kernel::Point_2>("v:uv", Kernel::Point_2(-1, -1)).first;
  namespace SMP = CGAL::Surface_mesh_parameterization;
  SMP::Texture_polygon_mesh_report report;
  if(SMP::texture_polygon_mesh(mesh, uv, SMP::parameters::report(report)) != SMP::OK)
  {
    std::cerr << report.message << '\n';
    return 1;
  }
  std::size_t inside = 0;
  for(auto v : vertices(mesh))
    inside += get(uv, v).x() >= 0 && get(uv, v).x() <= 1 && get(uv, v).y() >= 0 && get(uv, v).y() <= 1;
  std::cout << "installed package: " << inside << " of " << num_vertices(mesh) << " uvs in [0,1]^2\n"
            << "built with CGAL " << CGAL_VERSION_STR << ", Eigen "
#ifdef EIGEN_PATCH_VERSION // Eigen 5 keeps EIGEN_WORLD_VERSION at 3 and counts its release from EIGEN_MAJOR_VERSION on
            << EIGEN_MAJOR_VERSION << '.' << EIGEN_MINOR_VERSION << '.' << EIGEN_PATCH_VERSION << '\n';
#else
            << EIGEN_WORLD_VERSION << '.' << EIGEN_MAJOR_VERSION << '.' << EIGEN_MINOR_VERSION << '\n';
#endif
  return inside == num_vertices(mesh) ? 0 : 1;
}
