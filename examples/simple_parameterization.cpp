// The simplest use: a mesh with one border (a disk), CGAL's parameterize() with the
// norm-preserving parameterizer in place of LSCM or ARAP, the uv map written as a 2D OFF. Then
// the same through the parameterizer's own parameterize(), which keeps the report: CGAL's
// parameterize() takes the parameterizer by value, so its report is lost with the copy.
//
// Usage: simple_parameterization [disk mesh] [output OFF]

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/IO/File_off.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <fstream>
#include <iostream>
#include <string>

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : std::string(NP_MESH_DIR) + "/nefertiti.off";
  const std::string output = argc > 2 ? argv[2] : "nefertiti_uv.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(input, mesh) || is_empty(mesh) || !is_triangle_mesh(mesh))
  {
    std::cerr << "error: " << input << " is not a triangle mesh\n";
    return 1;
  }

  // A border halfedge, as for every parameterizer of CGAL.
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  auto uvmap = mesh.add_property_map<vertex_descriptor, Kernel::Point_2>("v:uv").first;

  const SMP::Error_code status = SMP::parameterize(mesh, SMP::Norm_preserving_parameterizer_3<Mesh>(), bhd, uvmap);
  if(status != SMP::OK)
  {
    std::cerr << "error: " << SMP::norm_preserving_error_message(status) << '\n';
    return 1;
  }

  // The parameterizer's own call, on the same component, with the maps CGAL's call makes: the
  // same uvs, and the report (how the solve ended, its certified distance to the optimum).
  SMP::Norm_preserving_parameterizer_3<Mesh> parameterizer;
  auto again = mesh.add_property_map<vertex_descriptor, Kernel::Point_2>("v:uv_again").first;
  auto has_uv = mesh.add_property_map<vertex_descriptor, bool>("v:has_uv", false).first;
  if(parameterizer.parameterize(mesh, bhd, again, get(CGAL::vertex_index, mesh), has_uv) != SMP::OK)
  {
    std::cerr << "error: " << parameterizer.report().message << '\n';
    return 1;
  }
  bool same = true;
  for(vertex_descriptor v : vertices(mesh))
    same = same && get(again, v) == get(uvmap, v);
  std::cout << "the parameterizer's own call: " << (same ? "the same uvs" : "other uvs") << ", "
            << parameterizer.report().solver.method << ", certified within " << parameterizer.report().solver.optimality_gap
            << " (relative) of the optimum\n";

  // Fitted into the unit square by default.
  std::size_t inside = 0;
  for(vertex_descriptor v : vertices(mesh))
  {
    const Kernel::Point_2& p = get(uvmap, v);
    inside += p.x() >= 0 && p.x() <= 1 && p.y() >= 0 && p.y() <= 1;
  }
  std::ofstream out(output);
  SMP::IO::output_uvmap_to_off(mesh, bhd, uvmap, out);
  const std::size_t n = num_vertices(mesh);
  std::cout << input << ": " << (inside == n ? "all " : "only " + std::to_string(inside) + " of ") << n
            << " uvs in [0,1]^2\n"
            << "wrote " << output << '\n';
  return out ? 0 : 1;
}
