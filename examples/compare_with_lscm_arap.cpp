// Side by side with CGAL's LSCM and ARAP on one closed mesh: ours maps the whole mesh with no
// cut; LSCM and ARAP need a disk, so they run on the mesh cut by cut_to_disk() (a Seam_mesh).
// The same distortion measures are printed for the three.
//
// Usage: compare_with_lscm_arap [closed triangle mesh]

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_distortion.h>
#include <CGAL/Surface_mesh_parameterization/cut_to_disk.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/Seam_mesh.h>

#include <chrono>
#include <iomanip>
#include <iostream>
#include <string>

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Property_map<Mesh::Edge_index, bool> Seam_edge_map;
typedef Mesh::Property_map<Mesh::Vertex_index, bool> Seam_vertex_map;
typedef CGAL::Seam_mesh<Mesh, Seam_edge_map, Seam_vertex_map> Seam_mesh;

void print(const char* name, double seconds, const SMP::Parameterization_distortion& d)
{
  std::cout << std::left << std::setw(6) << name << std::right << std::setw(10) << seconds
            << std::setw(12) << d.edge_length_error << std::setw(12) << d.mean_angle_distortion
            << std::setw(12) << d.area_distortion << std::setw(9) << d.flipped_faces << '\n';
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A CGAL parameterizer on the seam mesh; every seam-mesh vertex of the disk gets a uv.
template <typename Parameterizer>
void run_on_disk(const char* name, Parameterizer parameterizer, Seam_mesh& seam_mesh,
                 const SMP::Disk_cut_result<Seam_mesh>& cut, Mesh& mesh)
{
  auto uvmap = mesh.add_property_map<Mesh::Halfedge_index, Kernel::Point_2>(std::string("h:uv_") + name).first;
  const auto start = std::chrono::steady_clock::now();
  if(SMP::parameterize(seam_mesh, parameterizer, cut.border_halfedge, uvmap) != SMP::OK)
  {
    std::cout << name << ": failed\n";
    return;
  }
  const double seconds = seconds_since(start);
  auto all = mesh.add_property_map<Mesh::Halfedge_index, bool>("h:all", true).first;
  print(name, seconds, SMP::measure_distortion(seam_mesh, uvmap, all));
}

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : std::string(NP_MESH_DIR) + "/cow.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(input, mesh) || is_empty(mesh) || !is_triangle_mesh(mesh))
  {
    std::cerr << "error: " << input << " is not a triangle mesh\n";
    return 1;
  }
  std::cout << input << ": " << num_vertices(mesh) << " vertices\n"
            << std::left << std::setw(6) << "method" << std::right << std::setw(10) << "seconds"
            << std::setw(12) << "edge error" << std::setw(12) << "angle (deg)" << std::setw(12) << "log area"
            << std::setw(9) << "flipped" << '\n';

  auto uvmap = mesh.add_property_map<Mesh::Vertex_index, Kernel::Point_2>("v:uv").first;
  auto has_uv = mesh.add_property_map<Mesh::Vertex_index, bool>("v:has_uv", false).first;
  SMP::Norm_preserving_parameterizer_3<Mesh> ours;
  const auto start = std::chrono::steady_clock::now();
  if(ours.parameterize(mesh, *halfedges(mesh).begin(), uvmap, get(CGAL::vertex_index, mesh), has_uv) != SMP::OK)
  {
    std::cerr << "error: " << ours.report().message << '\n';
    return 1;
  }
  print("ours", seconds_since(start), SMP::measure_distortion(mesh, uvmap, has_uv));

  Seam_edge_map seam_edges = mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
  Seam_vertex_map seam_vertices = mesh.add_property_map<Mesh::Vertex_index, bool>("v:seam", false).first;
  Seam_mesh seam_mesh(mesh, seam_edges, seam_vertices);
  const SMP::Disk_cut_result<Seam_mesh> cut = SMP::cut_to_disk(seam_mesh, *halfedges(mesh).begin());
  if(cut.status != SMP::OK)
  {
    std::cerr << "error: " << cut.message << '\n';
    return 1;
  }
  run_on_disk("LSCM", SMP::LSCM_parameterizer_3<Seam_mesh>(), seam_mesh, cut, mesh);
  run_on_disk("ARAP", SMP::ARAP_parameterizer_3<Seam_mesh>(), seam_mesh, cut, mesh);
  std::cout << "(LSCM and ARAP on the mesh cut along " << cut.seam_edges << " edges; ours needs no cut)\n";
  return 0;
}
