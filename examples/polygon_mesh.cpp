// A polygon mesh (quads, pentagons) of genus 2, textured whole by texture_polygon_mesh():
// triangulated internally without adding a vertex, every component parameterized, the layout
// fitted into texture space and tiled 2 x 2. The mesh itself is not modified.
//
// Usage: polygon_mesh [polygon mesh]

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/texture_polygon_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <iostream>
#include <string>

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : std::string(NP_MESH_DIR) + "/double-torus-example.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(input, mesh) || is_empty(mesh))
  {
    std::cerr << "error: cannot read a polygon mesh from " << input << '\n';
    return 1;
  }
  std::size_t largest_face = 0;
  for(auto f : faces(mesh))
    largest_face = (std::max)(largest_face, std::size_t(degree(f, mesh)));

  auto uvmap = mesh.add_property_map<vertex_descriptor, Kernel::Point_2>("v:uv").first;
  SMP::Texture_polygon_mesh_report report;
  // The texture repeats twice along u and twice along v.
  if(SMP::texture_polygon_mesh(mesh, uvmap, SMP::parameters::tiling(2, 2).combine(SMP::parameters::report(report))) != SMP::OK)
  {
    std::cerr << "error: " << report.message << '\n';
    return 1;
  }

  double max_u = 0, max_v = 0;
  for(vertex_descriptor v : vertices(mesh))
  {
    max_u = (std::max)(max_u, get(uvmap, v).x());
    max_v = (std::max)(max_v, get(uvmap, v).y());
  }
  std::cout << input << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh)
            << " faces of up to " << largest_face << " sides, " << report.components << " component(s)\n"
            << "objective (Eq. 3): " << report.objective << ", " << report.seconds << " s\n"
            << "uvs span [0, " << max_u << "] x [0, " << max_v << "] (2 x 2 tiles)\n";
  return 0;
}
