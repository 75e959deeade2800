// The main job: textures a real mesh (by default the cow of CGAL's collection) with the
// norm-preserving parameterizer, writes a textured OBJ (+ MTL + checkerboard PNG) and prints
// the objective, the time and a one-line distortion summary.
//
// Usage: texture_mesh [input mesh (OFF, OBJ, PLY, STL)] [output basename]

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_distortion.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include "textured_obj_writer.h"

#include <iostream>
#include <string>

namespace SMP = CGAL::Surface_mesh_parameterization;
using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : std::string(NP_MESH_DIR) + "/cow.off";
  const std::string output = argc > 2 ? argv[2] : "cow_textured";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(input, mesh) || is_empty(mesh))
  {
    std::cerr << "error: cannot read a polygon mesh from " << input << '\n';
    return 1;
  }
  if(!CGAL::is_triangle_mesh(mesh))
    CGAL::Polygon_mesh_processing::triangulate_faces(mesh); // step 1: adds no vertex
  auto component = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:component").first;
  const std::size_t components = CGAL::Polygon_mesh_processing::connected_components(mesh, component);

  auto uv = mesh.add_property_map<Mesh::Vertex_index, Kernel::Point_2>("v:uv").first;
  auto has_uv = mesh.add_property_map<Mesh::Vertex_index, bool>("v:has_uv", false).first;
  SMP::Norm_preserving_parameterizer_3<Mesh> parameterizer;
  parameterizer.set_automatic_fixed_pair();
  const SMP::Error_code status = parameterizer.parameterize(
    mesh, halfedge(*faces(mesh).begin(), mesh), uv, get(CGAL::vertex_index, mesh), has_uv);
  const SMP::Norm_preserving_report& report = parameterizer.report();
  if(status != SMP::OK)
  {
    std::cerr << "error: " << SMP::error_message(status) << ": " << report.message << '\n';
    return 1;
  }
  if(!np_examples::write_textured_obj(output, mesh, uv))
  {
    std::cerr << "error: cannot write " << output << ".obj/.mtl/.png\n";
    return 1;
  }

  const SMP::Parameterization_distortion d = SMP::measure_distortion(mesh, uv, has_uv);
  std::cout << input << ": " << report.vertices << " vertices, " << report.edges << " edges"
            << (components > 1 ? " (first of " + std::to_string(components) + " components)" : "") << '\n'
            << "objective (Eq. 3): " << report.initial_objective << " at the guess -> " << report.objective
            << ", " << report.active_constraints << "/" << report.constraints << " sign constraints active, "
            << report.solver_iterations << " solver iterations, KKT residual " << report.kkt_residual << '\n'
            << "time: " << report.seconds << " s\n"
            << "distortion: edge-length error " << d.edge_length_error << " (L1 " << d.l1_edge_length_error
            << "), flipped faces " << d.flipped_faces << "/" << d.faces << " ("
            << 100 * d.flipped_area_fraction << "% of the area)\n"
            << "wrote " << output << ".obj, " << output << ".mtl, " << output << ".png\n";
  return 0;
}
