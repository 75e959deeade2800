// A user's own mesh type, which is not a CGAL graph: plain vectors of points and of index
// triples, adapted through Indexed_mesh_traits. Here a torus (genus 1) made in the program is
// textured with no cut.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh_parameterization/texture_indexed_mesh.h>

#include <array>
#include <cmath>
#include <iostream>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double> Kernel;

// The user's type.
struct My_mesh
{
  std::vector<std::array<double, 3> > xyz;
  std::vector<std::array<int, 3> > triangles;
};

// What the package needs to read it.
template <>
struct CGAL::Surface_mesh_parameterization::Indexed_mesh_traits<My_mesh>
{
  static std::size_t number_of_vertices(const My_mesh& m) { return m.xyz.size(); }
  static Kernel::Point_3 point(const My_mesh& m, std::size_t i) { return {m.xyz[i][0], m.xyz[i][1], m.xyz[i][2]}; }
  static std::size_t number_of_faces(const My_mesh& m) { return m.triangles.size(); }
  static const std::array<int, 3>& face(const My_mesh& m, std::size_t f) { return m.triangles[f]; }
};

// An n x m torus of radii 3 and 1, each grid quad split in two.
My_mesh torus(int n, int m)
{
  const double pi = std::acos(-1.);
  My_mesh mesh;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j)
    {
      const double a = 2 * pi * i / n, b = 2 * pi * j / m;
      mesh.xyz.push_back({(3 + std::cos(b)) * std::cos(a), (3 + std::cos(b)) * std::sin(a), std::sin(b)});
    }
  auto at = [&](int i, int j) { return (i % n) * m + (j % m); };
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j)
    {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return mesh;
}

int main()
{
  const My_mesh mesh = torus(48, 16);
  std::vector<Kernel::Point_2> uv(mesh.xyz.size()); // uv[i] is the uv of vertex i
  SMP::Texture_polygon_mesh_report report;
  if(SMP::texture_indexed_mesh(mesh, CGAL::make_property_map(uv), SMP::parameters::report(report)) != SMP::OK)
  {
    std::cerr << "error: " << report.message << '\n';
    return 1;
  }
  std::size_t in_unit_square = 0;
  for(const Kernel::Point_2& p : uv)
    in_unit_square += p.x() >= 0 && p.x() <= 1 && p.y() >= 0 && p.y() <= 1;
  std::cout << "torus: " << mesh.xyz.size() << " vertices, " << mesh.triangles.size() << " triangles\n"
            << "objective (Eq. 3): " << report.objective << ", " << in_unit_square << "/" << uv.size()
            << " uvs in [0,1]^2\n";
  return 0;
}
