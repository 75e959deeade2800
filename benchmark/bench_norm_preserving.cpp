// Google Benchmark on the scaling series: mushroom (a disk) and cow (closed) after 1 to 4
// steps of Loop subdivision (about 10k, 40k, 150k and 600k vertices). For each mesh, in the
// same run: ours (default solver, with the time of each step as counters), CGAL's LSCM (cow
// cut to a disk by cut_to_disk, outside the timing) and, as the yardstick of issue 8, one
// factorization plus one solve of the mesh's n x n graph Laplacian with the package's sparse
// Cholesky (CHOLMOD when configured).
//
//   bench_norm_preserving [--benchmark_filter=mushroom/2] ...
// The names are <method>/<mesh>/<subdivision steps>. `soup` is the whole-soup call
// (texture_polygon_soup) on the same vertices and triangles as `ours` (the parameterizer on
// the Surface_mesh), for the comparison of the two paths:
//   bench_norm_preserving --benchmark_filter='(ours|soup)/(cow/(0|3)|bunny00/0|mushroom/3)/'
// `polygon/corners:<n>/wave:<0|1>` is step 1 on one large polygon, flat or not,
// `hole_filling/corners:<n>/wave:<0|1>` CGAL's 3D hole filling on the same outline (what step 1
// did before it triangulated polygons in their plane).

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/property_map.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/cut_to_disk.h>
#include <CGAL/Surface_mesh_parameterization/texture_polygon_mesh.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Polygon_triangulation.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sparse_cholesky.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;
using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Vertex = Mesh::Vertex_index;
using Seam_edge_map = Mesh::Property_map<Mesh::Edge_index, bool>;
using Seam_vertex_map = Mesh::Property_map<Vertex, bool>;
using Seam_mesh = CGAL::Seam_mesh<Mesh, Seam_edge_map, Seam_vertex_map>;

// The subdivided meshes, made once per process.
static const Mesh& subdivided(const std::string& name, int steps)
{
  static std::map<std::pair<std::string, int>, std::unique_ptr<Mesh> > cache;
  std::unique_ptr<Mesh>& mesh = cache[{name, steps}];
  if(!mesh)
  {
    mesh = std::make_unique<Mesh>();
    CGAL::IO::read_polygon_mesh(std::string(NP_MESH_DIR) + "/" + name + ".off", *mesh);
    CGAL::Subdivision_method_3::Loop_subdivision(*mesh, CGAL::parameters::number_of_iterations(steps));
  }
  return *mesh;
}

static void ours(benchmark::State& state, const std::string& name)
{
  Mesh mesh = subdivided(name, int(state.range(0)));
  auto uv = mesh.add_property_map<Vertex, Kernel::Point_2>("v:uv").first;
  auto has_uv = mesh.add_property_map<Vertex, bool>("v:has_uv", false).first;
  SMP::Norm_preserving_parameterizer_3<Mesh> parameterizer;
  SMP::Norm_preserving_timings sum;
  for(auto _ : state)
  {
    if(parameterizer.parameterize(mesh, *halfedges(mesh).begin(), uv, get(CGAL::vertex_index, mesh), has_uv) != SMP::OK)
      state.SkipWithError(parameterizer.report().message.c_str());
    const SMP::Norm_preserving_timings& t = parameterizer.report().timings;
    sum.extraction += t.extraction;
    sum.guess += t.guess;
    sum.assembly += t.assembly;
    sum.factorization += t.factorization;
    sum.iterations += t.iterations;
    sum.write_back += t.write_back;
  }
  const auto per_run = benchmark::Counter::kAvgIterations;
  state.counters["vertices"] = double(num_vertices(mesh));
  state.counters["solver_iterations"] = parameterizer.report().solver_iterations;
  state.counters["s_extract"] = benchmark::Counter(sum.extraction, per_run);
  state.counters["s_guess"] = benchmark::Counter(sum.guess, per_run);
  state.counters["s_assemble"] = benchmark::Counter(sum.assembly, per_run);
  state.counters["s_factor"] = benchmark::Counter(sum.factorization, per_run);
  state.counters["s_iterate"] = benchmark::Counter(sum.iterations, per_run);
  state.counters["s_write"] = benchmark::Counter(sum.write_back, per_run);
}

// The whole-soup call on the mesh's vertices and triangles (read outside the timing).
static void soup(benchmark::State& state, const std::string& name)
{
  const Mesh& mesh = subdivided(name, int(state.range(0)));
  std::vector<Kernel::Point_3> points(mesh.points().begin(), mesh.points().end());
  std::vector<std::array<std::size_t, 3> > triangles;
  for(auto f : faces(mesh))
  {
    const auto h = halfedge(f, mesh);
    triangles.push_back({std::size_t(source(h, mesh)), std::size_t(target(h, mesh)),
                         std::size_t(target(next(h, mesh), mesh))});
  }
  std::vector<Kernel::Point_2> uv(points.size());
  SMP::Texture_polygon_mesh_report report;
  for(auto _ : state)
    if(SMP::texture_polygon_soup(points, triangles, CGAL::make_property_map(uv), {}, &report) != SMP::OK)
      state.SkipWithError(report.message.c_str());
  state.counters["vertices"] = double(points.size());
  state.counters["components"] = double(report.components);
}

static void lscm(benchmark::State& state, const std::string& name)
{
  Mesh mesh = subdivided(name, int(state.range(0)));
  Seam_edge_map seam_edges = mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
  Seam_vertex_map seam_vertices = mesh.add_property_map<Vertex, bool>("v:seam", false).first;
  Seam_mesh seam_mesh(mesh, seam_edges, seam_vertices);
  typename boost::graph_traits<Seam_mesh>::halfedge_descriptor border;
  bool has_border = false;
  for(auto h : halfedges(mesh))
    if(is_border(h, mesh)) { border = {h, false}; has_border = true; break; }
  if(!has_border)
  {
    const auto cut = SMP::cut_to_disk(seam_mesh, *halfedges(mesh).begin());
    if(cut.status != SMP::OK) { state.SkipWithError(cut.message.c_str()); return; }
    border = cut.border_halfedge;
  }
  auto uv = mesh.add_property_map<Mesh::Halfedge_index, Kernel::Point_2>("h:uv").first;
  for(auto _ : state)
    if(SMP::parameterize(seam_mesh, SMP::LSCM_parameterizer_3<Seam_mesh>(), border, uv) != SMP::OK)
      state.SkipWithError("LSCM failed");
  state.counters["vertices"] = double(num_vertices(mesh));
}

// One factorization and one solve of the graph Laplacian, its first vertex held.
static void laplacian(benchmark::State& state, const std::string& name)
{
  namespace NP = SMP::internal::Norm_preserving;
  const Mesh& mesh = subdivided(name, int(state.range(0)));
  const int n = int(num_vertices(mesh)) - 1;
  std::vector<Eigen::Triplet<double> > triplets;
  for(auto e : edges(mesh))
  {
    const int i = int(source(e, mesh)) - 1, j = int(target(e, mesh)) - 1;
    if(i >= 0) triplets.emplace_back(i, i, 1.);
    if(j >= 0) triplets.emplace_back(j, j, 1.);
    if(i >= 0 && j >= 0) triplets.emplace_back(std::max(i, j), std::min(i, j), -1.);
  }
  NP::Sparse_matrix matrix(n, n);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::VectorXd rhs = Eigen::VectorXd::Ones(n);
  for(auto _ : state)
  {
    NP::Sparse_cholesky cholesky(matrix);
    if(cholesky.info() != Eigen::Success) state.SkipWithError("factorization failed");
    Eigen::VectorXd x = cholesky.solve(rhs);
    benchmark::DoNotOptimize(x.data());
  }
  state.counters["vertices"] = double(num_vertices(mesh));
}

// One run per size (the largest take minutes with LSCM); --benchmark_repetitions=N repeats.
static void series(benchmark::internal::Benchmark* b)
{
  b->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1)->DenseRange(1, 4);
}

BENCHMARK_CAPTURE(ours, mushroom, std::string("mushroom"))->Apply(series);
BENCHMARK_CAPTURE(lscm, mushroom, std::string("mushroom"))->Apply(series);
BENCHMARK_CAPTURE(laplacian, mushroom, std::string("mushroom"))->Apply(series);
BENCHMARK_CAPTURE(ours, cow, std::string("cow"))->Apply(series);
BENCHMARK_CAPTURE(lscm, cow, std::string("cow"))->Apply(series);
BENCHMARK_CAPTURE(laplacian, cow, std::string("cow"))->Apply(series);
// The soup path against the mesh path.
static void paths(benchmark::internal::Benchmark* b)
{
  b->Unit(benchmark::kSecond)->UseRealTime();
}
BENCHMARK_CAPTURE(ours, cow, std::string("cow"))->Apply(paths)->Arg(0);
BENCHMARK_CAPTURE(ours, bunny00, std::string("bunny00"))->Apply(paths)->Arg(0);
BENCHMARK_CAPTURE(soup, cow, std::string("cow"))->Apply(paths)->Arg(0)->Arg(3);
BENCHMARK_CAPTURE(soup, bunny00, std::string("bunny00"))->Apply(paths)->Arg(0);
BENCHMARK_CAPTURE(soup, mushroom, std::string("mushroom"))->Apply(paths)->Arg(3);

// A CAD cap: a gear-like outline of n corners at z = 0.1 (radius 1 or 0.6 alternating, plus
// uniform noise up to 0.05), flat or (`wave`) with z waving by +-0.1 three times around.
static std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> cap(std::size_t n, bool wave)
{
  std::mt19937 random(1);
  std::uniform_real_distribution<double> noise(0, 0.05);
  std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> outline;
  for(std::size_t k = 0; k < n; ++k)
  {
    const double angle = 2 * CGAL_PI * double(k) / double(n), radius = (k % 2 ? 1. : 0.6) + noise(random);
    outline.emplace_back(radius * std::cos(angle), radius * std::sin(angle), 0.1 + (wave ? 0.1 * std::sin(3 * angle) : 0.));
  }
  return outline;
}

static void polygon(benchmark::State& state)
{
  const auto outline = cap(std::size_t(state.range(0)), state.range(1) != 0);
  std::vector<std::size_t> corners(outline.size());
  for(std::size_t k = 0; k < corners.size(); ++k)
    corners[k] = k;
  std::vector<std::array<std::size_t, 3> > triangles;
  for(auto _ : state)
    SMP::internal::Norm_preserving::triangulate_polygon(outline, corners, triangles);
  state.counters["triangles"] = double(triangles.size());
}
BENCHMARK(polygon)->Unit(benchmark::kMillisecond)->ArgNames({"corners", "wave"})->ArgsProduct({{400, 3200, 20000}, {0, 1}});

static void hole_filling(benchmark::State& state)
{
  const auto outline = cap(std::size_t(state.range(0)), state.range(1) != 0);
  std::vector<CGAL::Triple<int, int, int> > triangles;
  for(auto _ : state)
  {
    triangles.clear();
    CGAL::Polygon_mesh_processing::triangulate_hole_polyline(outline, std::back_inserter(triangles));
  }
  state.counters["triangles"] = double(triangles.size());
}
BENCHMARK(hole_filling)->Unit(benchmark::kMillisecond)->ArgNames({"corners", "wave"})->ArgsProduct({{100, 400, 1600}, {0, 1}});

BENCHMARK_MAIN();
