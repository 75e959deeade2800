// Google Benchmark timings of the norm-preserving parameterizer against CGAL's LSCM on the
// same real meshes (LSCM only where the mesh has a border).

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <benchmark/benchmark.h>

#include <string>

namespace SMP = CGAL::Surface_mesh_parameterization;
using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Vertex = Mesh::Vertex_index;

static Mesh load(const std::string& name)
{
  Mesh mesh;
  CGAL::IO::read_polygon_mesh(std::string(NP_MESH_DIR) + "/" + name + ".off", mesh);
  return mesh;
}

static void norm_preserving(benchmark::State& state, const std::string& name)
{
  Mesh mesh = load(name);
  auto uv = mesh.add_property_map<Vertex, Kernel::Point_2>("v:uv").first;
  auto has_uv = mesh.add_property_map<Vertex, bool>("v:has_uv", false).first;
  SMP::Norm_preserving_parameterizer_3<Mesh> parameterizer;
  for(auto _ : state)
    if(parameterizer.parameterize(mesh, *halfedges(mesh).begin(), uv, get(CGAL::vertex_index, mesh), has_uv) != SMP::OK)
      state.SkipWithError(parameterizer.report().message.c_str());
  state.counters["vertices"] = double(num_vertices(mesh));
}

static void lscm(benchmark::State& state, const std::string& name)
{
  Mesh mesh = load(name);
  auto uv = mesh.add_property_map<Vertex, Kernel::Point_2>("v:uv").first;
  Mesh::Halfedge_index border = Mesh::null_halfedge();
  for(auto h : halfedges(mesh))
    if(is_border(h, mesh)) { border = h; break; }
  for(auto _ : state)
    if(SMP::parameterize(mesh, SMP::LSCM_parameterizer_3<Mesh>(), border, uv) != SMP::OK)
      state.SkipWithError("LSCM failed");
  state.counters["vertices"] = double(num_vertices(mesh));
}

BENCHMARK_CAPTURE(norm_preserving, nefertiti, std::string("nefertiti"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(lscm, nefertiti, std::string("nefertiti"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(norm_preserving, mushroom, std::string("mushroom"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(lscm, mushroom, std::string("mushroom"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(norm_preserving, lion, std::string("lion"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(lscm, lion, std::string("lion"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(norm_preserving, cow, std::string("cow"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(norm_preserving, camel, std::string("camel"))->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
