// The pictures of doc/pictures.md: textures one mesh with one method and writes a POV-Ray
// scene of the textured model (a checkerboard in uv) and an SVG of its uv layout.
//   ours: texture_polygon_mesh() on the whole mesh, no cut (closed meshes fold front/back);
//   lscm, arap: CGAL's LSCM_parameterizer_3 / ARAP_parameterizer_3 on the component of the
//         first face, cut to a disk by cut_to_disk() as the comparison harness does, the
//         layout fitted into [0,1]^2 with one scale. uvs then live on the seam mesh's
//         vertices, so the scene gives each face corner its own uv index.
// The scene is rendered by doc/figures/make_pictures.sh (povray +W640 +H480: the camera
// assumes a 4:3 image).
//
// Usage: render_pictures mesh ours|lscm|arap scene.pov layout.svg
//                        [--cells N] [--up x|y|z] [--view azimuth elevation]

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/cut_to_disk.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Surface_mesh_parameterization/texture_polygon_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Texture_space_fit.h>

#include "uv_layout_svg.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;
using Kernel = CGAL::Simple_cartesian<double>;
using Point_2 = Kernel::Point_2;
using Vector_3 = Kernel::Vector_3;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Vertex = Mesh::Vertex_index;
using Halfedge = Mesh::Halfedge_index;
using Seam_edge_map = Mesh::Property_map<Mesh::Edge_index, bool>;
using Seam_vertex_map = Mesh::Property_map<Vertex, bool>;
using Seam_mesh = CGAL::Seam_mesh<Mesh, Seam_edge_map, Seam_vertex_map>;

// What the scene needs: for each rendered face, its mesh vertices and the uv index of each
// corner.
struct Textured_faces
{
  std::vector<Point_2> uvs;
  std::vector<std::array<std::size_t, 3> > vertices, uv_indices;
};

struct View
{
  int up = 1;                          // index of the up axis
  double azimuth = 35, elevation = 20; // degrees, around the up axis
  int cells = 16;                      // checker cells across [0,1] in u and in v
};

// ---------------------------------------------------------------------------- the uvs

Textured_faces texture_ours(const Mesh& mesh, const std::string& svg)
{
  auto uv = get(CGAL::dynamic_vertex_property_t<Point_2>(), mesh);
  for(Vertex v : vertices(mesh)) put(uv, v, Point_2(0, 0));
  SMP::Texture_polygon_mesh_report report;
  if(SMP::texture_polygon_mesh(mesh, uv, SMP::parameters::report(report)) != SMP::OK)
    throw std::runtime_error("texture_polygon_mesh: " + report.message);
  if(!np_examples::write_uv_layout_svg(svg, mesh, uv))
    throw std::runtime_error("cannot write " + svg);
  Textured_faces t;
  for(Vertex v : vertices(mesh)) t.uvs.push_back(get(uv, v));
  for(auto f : faces(mesh))
  {
    std::array<std::size_t, 3> corner;
    std::size_t k = 0;
    for(Vertex v : vertices_around_face(halfedge(f, mesh), mesh)) corner[k++] = std::size_t(v);
    t.vertices.push_back(corner);
    t.uv_indices.push_back(corner);
  }
  return t;
}

template <typename Parameterizer>
Textured_faces texture_on_disk(Mesh& mesh, Parameterizer parameterizer, const std::string& svg)
{
  typedef boost::graph_traits<Seam_mesh>::vertex_descriptor seam_vertex;
  Seam_edge_map seam_edges = mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
  Seam_vertex_map seam_vertices = mesh.add_property_map<Vertex, bool>("v:seam", false).first;
  Seam_mesh seam_mesh(mesh, seam_edges, seam_vertices);
  const SMP::Disk_cut_result<Seam_mesh> cut = SMP::cut_to_disk(seam_mesh, halfedge(*faces(mesh).begin(), mesh));
  if(cut.status != SMP::OK) throw std::runtime_error("cut_to_disk: " + cut.message);
  std::cerr << "cut: genus " << cut.genus << ", " << cut.seam_edges << " seam edges\n";

  auto uv = mesh.add_property_map<Halfedge, Point_2>("h:uv", Point_2(0, 0)).first; // seam vertex -> uv
  if(SMP::parameterize(seam_mesh, parameterizer, cut.border_halfedge, uv) != SMP::OK)
    throw std::runtime_error("the parameterizer failed");

  // The disk only: other components (none on the meshes of the pictures) are not rendered.
  std::vector<boost::graph_traits<Seam_mesh>::face_descriptor> disk;
  CGAL::Polygon_mesh_processing::connected_component(face(opposite(cut.border_halfedge, seam_mesh), seam_mesh),
                                                     seam_mesh, std::back_inserter(disk));
  if(disk.size() < num_faces(mesh))
    std::cerr << "note: " << num_faces(mesh) - disk.size() << " faces outside the first component are not rendered\n";
  Textured_faces t;
  std::map<seam_vertex, std::size_t> index;
  std::vector<seam_vertex> order;
  for(auto f : disk)
  {
    std::array<std::size_t, 3> corner, uv_corner;
    std::size_t k = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, seam_mesh), seam_mesh))
    {
      const seam_vertex v = target(h, seam_mesh);
      const auto inserted = index.emplace(v, order.size());
      if(inserted.second) order.push_back(v);
      corner[k] = std::size_t(target(h.tmhd, mesh));
      uv_corner[k++] = inserted.first->second;
    }
    t.vertices.push_back(corner);
    t.uv_indices.push_back(uv_corner);
  }

  // Uniform fit into [0,1]^2, the package's own, as ours does by default.
  std::vector<std::array<double, 2> > fitted;
  for(seam_vertex v : order)
    fitted.push_back({get(uv, v).x(), get(uv, v).y()});
  SMP::internal::Norm_preserving::fit_to_texture_space(fitted, SMP::NORM_PRESERVING_UNIFORM_FIT, 1, 1);
  for(std::size_t k = 0; k < order.size(); ++k)
  {
    put(uv, order[k], Point_2(fitted[k][0], fitted[k][1]));
    t.uvs.push_back(get(uv, order[k]));
  }
  if(!np_examples::write_uv_layout_svg(svg, seam_mesh, uv))
    throw std::runtime_error("cannot write " + svg);
  return t;
}

// ---------------------------------------------------------------------------- the scene

std::vector<Vector_3> area_weighted_normals(const Mesh& mesh)
{
  std::vector<Vector_3> normals(num_vertices(mesh), CGAL::NULL_VECTOR);
  for(auto f : faces(mesh))
  {
    const Halfedge h = halfedge(f, mesh);
    const Vertex a = source(h, mesh), b = target(h, mesh), c = target(next(h, mesh), mesh);
    // The cross product's length is twice the area: the sum weighs each face by its area.
    const Vector_3 n = CGAL::cross_product(mesh.point(b) - mesh.point(a), mesh.point(c) - mesh.point(a));
    for(Vertex v : {a, b, c}) normals[std::size_t(v)] = normals[std::size_t(v)] + n;
  }
  for(Vector_3& n : normals)
  {
    const double length = std::sqrt(n.squared_length());
    n = length > 0 ? n / length : Vector_3(0, 0, 1);
  }
  return normals;
}

Vector_3 unit(const Vector_3& v) { return v / std::sqrt(v.squared_length()); }

std::ostream& operator<<(std::ostream& out, const Vector_3& v)
{
  return out << '<' << v.x() << ',' << v.y() << ',' << v.z() << '>';
}

// A camera for a 4:3 image looking at the mesh from `view`, the mesh filling about 90% of
// the frame; POV-Ray takes its explicit vectors as given, so the scene stays right-handed.
void write_camera_and_lights(std::ostream& pov, const Mesh& mesh, const View& view)
{
  const double pi = 3.14159265358979323846, az = view.azimuth * pi / 180, el = view.elevation * pi / 180;
  std::array<Vector_3, 3> axes = {Vector_3(1, 0, 0), Vector_3(0, 1, 0), Vector_3(0, 0, 1)};
  const Vector_3 up = axes[view.up], h1 = axes[(view.up + 2) % 3], h2 = axes[(view.up + 1) % 3];
  const Vector_3 toward_camera = std::cos(el) * (std::cos(az) * h1 + std::sin(az) * h2) + std::sin(el) * up;
  const Vector_3 right = unit(CGAL::cross_product(-toward_camera, up));
  const Vector_3 screen_up = CGAL::cross_product(right, -toward_camera);

  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  Vector_3 center((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2, (box.zmin() + box.zmax()) / 2);
  const double aspect = 4. / 3, fill = 0.9;
  double distance = 0;
  Vector_3 eye;
  // Perspective makes the near side look bigger: a few passes move the centre of the view to
  // the centre of the projected mesh, then back off until the mesh fits.
  for(int pass = 0;; ++pass)
  {
    distance = 0;
    for(Vertex v : vertices(mesh))
    {
      const Vector_3 p = mesh.point(v) - CGAL::ORIGIN - center;
      distance = std::max({distance, std::abs(p * right) / (fill * aspect / 2) + p * toward_camera,
                           std::abs(p * screen_up) / (fill / 2) + p * toward_camera});
    }
    eye = center + distance * toward_camera;
    if(pass == 3) break;
    double low_r = 1e300, high_r = -1e300, low_u = 1e300, high_u = -1e300;
    for(Vertex v : vertices(mesh))
    {
      const Vector_3 q = mesh.point(v) - CGAL::ORIGIN - eye;
      const double depth = -(q * toward_camera);
      low_r = std::min(low_r, q * right / depth); high_r = std::max(high_r, q * right / depth);
      low_u = std::min(low_u, q * screen_up / depth); high_u = std::max(high_u, q * screen_up / depth);
    }
    center = center + distance * ((low_r + high_r) / 2 * right + (low_u + high_u) / 2 * screen_up);
  }
  pov << "camera {\n  perspective\n  location " << eye << "\n  direction " << -toward_camera << "\n  right "
      << aspect * right << "\n  up " << screen_up << "\n}\n"
      << "light_source { " << eye + distance * (0.6 * screen_up - 0.5 * right) << " color rgb 0.85 }\n"
      << "light_source { " << eye + distance * (-0.3 * screen_up + 0.8 * right) << " color rgb 0.35 shadowless }\n";
}

void write_scene(const std::string& path, const Mesh& mesh, const Textured_faces& t, const View& view)
{
  std::ofstream pov(path);
  pov.precision(7);
  pov << "// " << t.vertices.size() << " faces; written by render_pictures\n"
      << "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\nbackground { color rgb 1 }\n";
  write_camera_and_lights(pov, mesh, view);
  pov << "mesh2 {\n  vertex_vectors { " << num_vertices(mesh);
  for(Vertex v : vertices(mesh)) pov << ",\n" << (mesh.point(v) - CGAL::ORIGIN);
  const std::vector<Vector_3> normals = area_weighted_normals(mesh);
  pov << " }\n  normal_vectors { " << normals.size();
  for(const Vector_3& n : normals) pov << ",\n" << n;
  pov << " }\n  uv_vectors { " << t.uvs.size();
  for(const Point_2& p : t.uvs) pov << ",\n<" << p.x() << ',' << p.y() << '>';
  auto write_indices = [&](const char* name, const std::vector<std::array<std::size_t, 3> >& indices) {
    pov << " }\n  " << name << " { " << indices.size();
    for(const auto& i : indices) pov << ",\n<" << i[0] << ',' << i[1] << ',' << i[2] << '>';
  };
  write_indices("face_indices", t.vertices);
  write_indices("uv_indices", t.uv_indices);
  // Checker cells are unit cubes: the z shift keeps the uv plane (z = 0) off their faces.
  pov << " }\n  uv_mapping\n  texture {\n    pigment { checker color srgb <0.157,0.235,0.549> color srgb <0.922,0.882,0.784>\n"
      << "              translate <0,0,0.5> scale <" << 1. / view.cells << ',' << 1. / view.cells << ",1> }\n"
      << "    finish { ambient 0.18 diffuse 0.8 specular 0.15 roughness 0.05 }\n  }\n}\n";
  if(!pov) throw std::runtime_error("cannot write " + path);
}

// ---------------------------------------------------------------------------- main

int main(int argc, char** argv)
{
  if(argc < 5)
  {
    std::cerr << "usage: render_pictures mesh ours|lscm|arap scene.pov layout.svg [--cells N] [--up x|y|z] "
                 "[--view azimuth elevation]\n";
    return 2;
  }
  const std::string input = argv[1], method = argv[2], pov = argv[3], svg = argv[4];
  View view;
  try
  {
    for(int i = 5; i < argc; ++i)
    {
      const std::string a = argv[i];
      if(a == "--cells" && i + 1 < argc) view.cells = std::max(1, std::stoi(argv[++i]));
      else if(a == "--up" && i + 1 < argc && std::string("x y z").find(argv[i + 1]) != std::string::npos
              && std::string(argv[i + 1]).size() == 1)
        view.up = argv[++i][0] - 'x';
      else if(a == "--view" && i + 2 < argc)
      {
        view.azimuth = std::stod(argv[++i]);
        view.elevation = std::stod(argv[++i]);
      }
      else throw std::runtime_error("unknown option " + a);
    }

    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(input, mesh) || is_empty(mesh))
      throw std::runtime_error("cannot read a polygon mesh from " + input);
    if(!CGAL::is_triangle_mesh(mesh)) CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
    mesh.collect_garbage(); // vertex indices must be 0..n-1 for the scene

    const auto start = std::chrono::steady_clock::now();
    Textured_faces t;
    if(method == "ours") t = texture_ours(mesh, svg);
    else if(method == "lscm") t = texture_on_disk(mesh, SMP::LSCM_parameterizer_3<Seam_mesh>(), svg);
    else if(method == "arap") t = texture_on_disk(mesh, SMP::ARAP_parameterizer_3<Seam_mesh>(), svg);
    else throw std::runtime_error("unknown method " + method + " (ours, lscm or arap)");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    write_scene(pov, mesh, t, view);
    std::cout << input << " (" << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces), " << method
              << ": " << seconds << " s; wrote " << pov << " and " << svg << '\n';
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
