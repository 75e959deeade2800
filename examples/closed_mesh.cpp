// A closed mesh, parameterized whole, with no cut and no seam: every vertex gets one uv. The
// map folds (front and back overlap in uv), which measure_distortion() reports as flips.
//
// Usage: closed_mesh [closed triangle mesh]

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_distortion.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <iostream>
#include <string>

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : std::string(NP_MESH_DIR) + "/cow.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(input, mesh) || is_empty(mesh) || !is_triangle_mesh(mesh))
  {
    std::cerr << "error: " << input << " is not a triangle mesh\n";
    return 1;
  }
  std::cout << input << ": " << num_vertices(mesh) << " vertices, "
            << (CGAL::is_closed(mesh) ? "closed" : "with a border") << '\n';

  auto uvmap = mesh.add_property_map<vertex_descriptor, Kernel::Point_2>("v:uv").first;
  auto has_uv = mesh.add_property_map<vertex_descriptor, bool>("v:has_uv", false).first;
  SMP::Norm_preserving_parameterizer_3<Mesh> parameterizer;
  // Any halfedge of the component: no border is needed.
  const SMP::Error_code status =
    parameterizer.parameterize(mesh, *halfedges(mesh).begin(), uvmap, get(CGAL::vertex_index, mesh), has_uv);
  if(status != SMP::OK)
  {
    std::cerr << "error: " << SMP::norm_preserving_error_message(status) << ": " << parameterizer.report().message << '\n';
    return 1;
  }

  std::size_t mapped = 0;
  for(vertex_descriptor v : vertices(mesh))
    mapped += get(has_uv, v);
  const SMP::Norm_preserving_report& report = parameterizer.report();
  const SMP::Parameterization_distortion d = SMP::measure_distortion(mesh, uvmap, has_uv);
  const std::size_t n = num_vertices(mesh);
  std::cout << (mapped == n ? "all " : "only " + std::to_string(mapped) + " of ") << n
            << " vertices have a uv, seam edges: 0\n"
            << "objective (Eq. 3): " << report.initial_objective << " at the initial guess, "
            << report.objective << " at the solution (" << report.solver.iterations << " iterations, "
            << report.seconds << " s)\n"
            << "edge-length error " << d.edge_length_error << ", flipped faces " << d.flipped_faces << "/"
            << d.faces << '\n';
  return 0;
}
