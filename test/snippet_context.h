// What the guides' C++ fragments take as given (test/extract_snippets.py): the usual types and,
// as the parameters of the function each fragment is compiled in, a mesh, its uv map, a border
// halfedge and the mesh as a polygon soup; and how each block is run on a mesh file.

#ifndef NP_SNIPPET_CONTEXT_H
#define NP_SNIPPET_CONTEXT_H

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <iostream>
#include <vector>

namespace np_snippets {

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_2 Point_2;
typedef Kernel::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef Mesh::Halfedge_index halfedge_descriptor;
typedef Mesh::Property_map<Mesh::Vertex_index, Point_2> UV_map;

#define NP_SNIPPET_CONTEXT                                                                                   \
  [[maybe_unused]] Mesh& mesh, [[maybe_unused]] UV_map uvmap, [[maybe_unused]] halfedge_descriptor border_halfedge, \
    [[maybe_unused]] std::vector<Point_3>& points, [[maybe_unused]] std::vector<std::vector<std::size_t> >& polygons

// Runs a whole program of a guide with `file` as its argument; 1 if it does not return 0.
inline int run_program(int (*program)(int, char**), const char* file, const char* where)
{
  char name[] = "snippet";
  std::vector<char> argument(file, file + std::char_traits<char>::length(file) + 1);
  char* argv[] = {name, argument.data(), nullptr};
  const int status = program(2, argv);
  if(status != 0)
    std::cerr << where << ": the program returned " << status << '\n';
  return status != 0 ? 1 : 0;
}

// Runs a fragment of a guide on the mesh of `file`, which has a border; 1 if it cannot be read.
inline int run_fragment(void (*fragment)(Mesh&, UV_map, halfedge_descriptor, std::vector<Point_3>&,
                                         std::vector<std::vector<std::size_t> >&),
                        const char* file, const char* where)
{
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh))
  {
    std::cerr << where << ": cannot read " << file << '\n';
    return 1;
  }
  UV_map uvmap = mesh.add_property_map<Mesh::Vertex_index, Point_2>("v:uv").first;
  halfedge_descriptor border = *halfedges(mesh).begin();
  for(halfedge_descriptor h : halfedges(mesh))
    if(is_border(h, mesh))
      border = h;
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  CGAL::Polygon_mesh_processing::polygon_mesh_to_polygon_soup(mesh, points, polygons);
  fragment(mesh, uvmap, border, points, polygons);
  return 0;
}

} // namespace np_snippets

#endif
