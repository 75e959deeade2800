// The main job: textures a real mesh (by default the cow of CGAL's collection) with the
// norm-preserving parameterizer, writes a textured OBJ (+ MTL + checkerboard PNG) and prints
// the objective, the time and a one-line distortion summary.
//
// Usage: texture_mesh [input mesh (OFF, OBJ, PLY, STL)] [output basename]

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_distortion.h>
#include <CGAL/Surface_mesh_parameterization/texture_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include "textured_obj_writer.h"

#include <algorithm>
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

  auto uv = mesh.add_property_map<Mesh::Vertex_index, Kernel::Point_2>("v:uv").first;
  SMP::Texture_polygon_mesh_report report;
  const SMP::Error_code status = SMP::texture_polygon_mesh(mesh, uv, SMP::Texture_polygon_mesh_options<Mesh>(), &report);
  if(status != SMP::OK)
  {
    std::cerr << "error: " << SMP::error_message(status) << ": " << report.message << '\n';
    return 1;
  }
  const std::size_t faces = num_faces(mesh);
  if(!np_examples::write_textured_obj(output, mesh, uv))
  {
    std::cerr << "error: cannot write " << output << ".obj/.mtl/.png\n";
    return 1;
  }

  std::size_t active = 0, constraints = 0, iterations = 0;
  double initial = 0, kkt = 0;
  for(const SMP::Norm_preserving_report& r : report.reports)
  {
    active += r.active_constraints;
    constraints += r.constraints;
    iterations = std::max<std::size_t>(iterations, std::size_t(r.solver_iterations));
    initial += r.initial_objective;
    kkt = std::max(kkt, r.kkt_residual);
  }
  // Distortion is measured on triangles; triangulating adds no vertex, so uvs stay valid.
  CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
  auto on_face = mesh.add_property_map<Mesh::Vertex_index, bool>("v:on_face", true).first;
  for(auto v : vertices(mesh))
    put(on_face, v, !mesh.is_isolated(v));
  const SMP::Parameterization_distortion d = SMP::measure_distortion(mesh, uv, on_face);
  std::cout << input << ": " << num_vertices(mesh) << " vertices, " << faces << " faces, "
            << report.components << " component(s)\n"
            << "objective (Eq. 3): " << initial << " at the guess -> " << report.objective << ", "
            << active << "/" << constraints << " sign constraints active, " << iterations
            << " solver iterations, KKT residual " << kkt << '\n'
            << "time: " << report.seconds << " s\n"
            << "distortion: edge-length error " << d.edge_length_error << " (L1 " << d.l1_edge_length_error
            << "), flipped faces " << d.flipped_faces << "/" << d.faces << " ("
            << 100 * d.flipped_area_fraction << "% of the area)\n"
            << "wrote " << output << ".obj, " << output << ".mtl, " << output << ".png\n";
  return 0;
}
