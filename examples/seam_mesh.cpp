// The norm-preserving parameterizer on a Seam_mesh, for users who do want a cut (one uv per
// corner along the seam): a genus-2 mesh is cut to a disk by cut_to_disk(), then CGAL's
// parameterize() runs on the seam mesh, exactly as it would with LSCM or ARAP.
//
// Usage: seam_mesh [closed triangle mesh]

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/cut_to_disk.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/Seam_mesh.h>

#include <iostream>
#include <string>

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Property_map<Mesh::Edge_index, bool> Seam_edge_map;
typedef Mesh::Property_map<Mesh::Vertex_index, bool> Seam_vertex_map;
typedef CGAL::Seam_mesh<Mesh, Seam_edge_map, Seam_vertex_map> Seam_mesh;

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : std::string(NP_MESH_DIR) + "/eight.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(input, mesh) || is_empty(mesh) || !is_triangle_mesh(mesh))
  {
    std::cerr << "error: " << input << " is not a triangle mesh\n";
    return 1;
  }
  Seam_edge_map seam_edges = mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
  Seam_vertex_map seam_vertices = mesh.add_property_map<Mesh::Vertex_index, bool>("v:seam", false).first;
  Seam_mesh seam_mesh(mesh, seam_edges, seam_vertices);

  const SMP::Disk_cut_result<Seam_mesh> cut = SMP::cut_to_disk(seam_mesh, *halfedges(mesh).begin());
  if(cut.status != SMP::OK)
  {
    std::cerr << "error: " << cut.message << '\n';
    return 1;
  }

  // A seam-mesh vertex is a halfedge of the mesh: the uvs live on halfedges.
  const Kernel::Point_2 unset(-1, -1);
  auto uvmap = mesh.add_property_map<Mesh::Halfedge_index, Kernel::Point_2>("h:uv", unset).first;
  const SMP::Error_code status =
    SMP::parameterize(seam_mesh, SMP::Norm_preserving_parameterizer_3<Seam_mesh>(), cut.border_halfedge, uvmap);
  if(status != SMP::OK)
  {
    std::cerr << "error: " << SMP::norm_preserving_error_message(status) << '\n';
    return 1;
  }
  std::size_t mapped = 0;
  for(auto v : vertices(seam_mesh))
    mapped += get(uvmap, v) != unset;
  std::cout << input << ": genus " << cut.genus << ", cut along " << cut.seam_edges << " edges\n"
            << "the seam mesh has " << num_vertices(seam_mesh) << " vertices for the mesh's "
            << num_vertices(mesh) << "; " << (mapped == num_vertices(seam_mesh) ? "all" : "not all")
            << " have a uv\n";
  return 0;
}
