// The uvs of one file through each way in, as hashes of their bits, for the tests that check
// that the ways in agree bit for bit and that two builds (CGAL 5.5 + Eigen 3.4, CGAL 6 + Eigen 5)
// agree:
//   uv_bits MESH [--guess xy|combination|graph] [--obj TOOL_OUTPUT.obj] [--raw OUT.raw]
// prints `soup <hash>` (texture_polygon_soup() through np_examples::texture_with_settings(), the
// call of the command-line tool and of the Python module, with its defaults but for the
// initial guess; `soup_kept_apart <hash>` too with
// coincident vertices kept apart, where there are some), `parameterizer <hash>` on a triangle
// mesh of one component (Norm_preserving_parameterizer_3 with the automatic pair, the whole-soup
// call's; through CGAL's SMP::parameterize() when the mesh has a border), and `tool
// <hash>` for the vt lines of the command-line tool's OBJ (printed to round-trip). --raw writes
// the soup call's uvs as native doubles, u and v of each vertex in order (the Python module's
// tests compare bits with them).

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Surface_mesh_parameterization/texture_polygon_mesh.h>
#include <CGAL/property_map.h>

#include "obj_uvs.h"
#include "texture_settings.h"

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;

// FNV-1a over the bytes of the coordinates.
struct Hash
{
  std::uint64_t value = 1469598103934665603ull;
  void add(double x)
  {
    unsigned char bytes[sizeof x];
    std::memcpy(bytes, &x, sizeof x);
    for(unsigned char b : bytes)
      value = (value ^ b) * 1099511628211ull;
  }
};

void print(const char* way, const Hash& hash)
{
  std::printf("%s %016llx\n", way, static_cast<unsigned long long>(hash.value));
}

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: uv_bits MESH [--guess xy|combination|graph] [--obj TOOL_OUTPUT.obj] [--raw OUT.raw]\n";
    return 2;
  }
  std::string obj, raw;
  np_examples::Texture_settings settings;
  for(int i = 2; i < argc; i += 2)
  {
    const std::string option = argv[i];
    if(i + 1 == argc || (option != "--obj" && option != "--raw" && option != "--guess"))
    {
      std::cerr << "uv_bits: unknown option or no value: " << option << '\n';
      return 2;
    }
    (option == "--obj" ? obj : option == "--raw" ? raw : settings.guess) = argv[i + 1];
  }
  if(const auto problem = np_examples::settings_problem(settings))
  {
    std::cerr << "uv_bits: " << *problem << '\n';
    return 2;
  }
  std::vector<Kernel::Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  if(!CGAL::IO::read_polygon_soup(argv[1], points, polygons))
  {
    std::cerr << "cannot read " << argv[1] << '\n';
    return 1;
  }

  std::vector<Kernel::Point_2> uv(points.size(), Kernel::Point_2(0, 0));
  SMP::Texture_polygon_mesh_report report;
  auto soup_call = [&](bool weld, const char* way) {
    settings.keep_coincident = !weld;
    if(np_examples::texture_with_settings(points, polygons, CGAL::make_property_map(uv), settings, report,
                                          [](const SMP::Norm_preserving_progress&) { return true; }) != SMP::OK)
    {
      std::cerr << report.message << '\n';
      return false;
    }
    Hash soup;
    for(const Kernel::Point_2& p : uv)
    {
      soup.add(p.x());
      soup.add(p.y());
    }
    print(way, soup);
    return true;
  };
  if(!soup_call(true, "soup"))
    return 1;
  const std::vector<Kernel::Point_2> welded = uv;
  if(!raw.empty())
  {
    std::ofstream out(raw, std::ios::binary);
    for(const Kernel::Point_2& p : welded)
    {
      const double both[2] = {p.x(), p.y()};
      out.write(reinterpret_cast<const char*>(both), sizeof both);
    }
  }

  // The parameterizer keeps coincident vertices apart, as the whole-soup call does when told to.
  Mesh mesh;
  if(report.welded_vertices > 0 && !soup_call(false, "soup_kept_apart"))
    return 1;
  if(report.components == 1 && report.isolated_vertices == 0 &&
     CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
  {
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
    if(CGAL::is_triangle_mesh(mesh))
    {
      auto uvmap = mesh.add_property_map<Mesh::Vertex_index, Kernel::Point_2>("v:uv").first;
      SMP::Norm_preserving_parameterizer_3<Mesh> parameterizer;
      parameterizer.set_automatic_fixed_pair();
      Mesh::Halfedge_index border = *halfedges(mesh).begin();
      for(Mesh::Halfedge_index h : halfedges(mesh))
        if(is_border(h, mesh))
        {
          border = h;
          break;
        }
      const SMP::Error_code status =
        is_border(border, mesh) ? SMP::parameterize(mesh, parameterizer, border, uvmap) // CGAL's drop-in
                                : parameterizer.parameterize(mesh, border, uvmap, get(CGAL::vertex_index, mesh),
                                                             get(CGAL::dynamic_vertex_property_t<bool>(), mesh));
      if(status != SMP::OK)
        return 1;
      // The whole-soup call fits the layout into [0,1]^2 as the parameterizer fits its one
      // component: the same uvs.
      Hash parameterized;
      for(Mesh::Vertex_index v : vertices(mesh))
      {
        parameterized.add(get(uvmap, v).x());
        parameterized.add(get(uvmap, v).y());
      }
      print("parameterizer", parameterized);
    }
  }

  if(!obj.empty())
  {
    Hash tool;
    for(const std::array<double, 2>& p : np_test::read_obj_uvs(obj))
    {
      tool.add(p[0]);
      tool.add(p[1]);
    }
    print("tool", tool);
  }
  return 0;
}
