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
// `quality/<draft|default|exact>/<mesh>/<steps>` is the quality ladder (benchmark/quality_ladder.py
// prints it as a table); `polygon/corners:<n>/wave:<0|1>` is step 1 on one large polygon, flat or not,
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
  SMP::Norm_preserving_solve_report solve_sum;
  for(auto _ : state)
  {
    if(parameterizer.parameterize(mesh, *halfedges(mesh).begin(), uv, get(CGAL::vertex_index, mesh), has_uv) != SMP::OK)
      state.SkipWithError(parameterizer.report().message.c_str());
    const SMP::Norm_preserving_timings& t = parameterizer.report().timings;
    sum.extraction += t.extraction;
    sum.guess += t.guess;
    const SMP::Norm_preserving_solve_report& solved = parameterizer.report().solver;
    solve_sum.assembly_seconds += solved.assembly_seconds;
    solve_sum.factorization_seconds += solved.factorization_seconds;
    solve_sum.iteration_seconds += solved.iteration_seconds;
    sum.write_back += t.write_back;
  }
  const auto per_run = benchmark::Counter::kAvgIterations;
  state.counters["vertices"] = double(num_vertices(mesh));
  state.counters["solver_iterations"] = parameterizer.report().solver.iterations;
  state.counters["s_extract"] = benchmark::Counter(sum.extraction, per_run);
  state.counters["s_guess"] = benchmark::Counter(sum.guess, per_run);
  state.counters["s_assemble"] = benchmark::Counter(solve_sum.assembly_seconds, per_run);
  state.counters["s_factor"] = benchmark::Counter(solve_sum.factorization_seconds, per_run);
  state.counters["s_iterate"] = benchmark::Counter(solve_sum.iteration_seconds, per_run);
  state.counters["s_write"] = benchmark::Counter(sum.write_back, per_run);
}

// The vertices and triangles of a subdivided mesh, as a soup.
struct Triangle_soup
{
  std::vector<Kernel::Point_3> points;
  std::vector<std::array<std::size_t, 3> > triangles;
};

static Triangle_soup triangle_soup(const std::string& name, int steps)
{
  const Mesh& mesh = subdivided(name, steps);
  Triangle_soup soup;
  soup.points.assign(mesh.points().begin(), mesh.points().end());
  for(auto f : faces(mesh))
  {
    const auto h = halfedge(f, mesh);
    soup.triangles.push_back({std::size_t(source(h, mesh)), std::size_t(target(h, mesh)),
                              std::size_t(target(next(h, mesh), mesh))});
  }
  return soup;
}

// The whole-soup call on the mesh's vertices and triangles (read outside the timing).
static void soup(benchmark::State& state, const std::string& name)
{
  const Triangle_soup soup_of_mesh = triangle_soup(name, int(state.range(0)));
  const std::vector<Kernel::Point_3>& points = soup_of_mesh.points;
  const auto& triangles = soup_of_mesh.triangles;
  std::vector<Kernel::Point_2> uv(points.size());
  SMP::Texture_polygon_mesh_report report;
  for(auto _ : state)
    if(SMP::texture_polygon_soup(points, triangles, CGAL::make_property_map(uv), SMP::parameters::report(report)) != SMP::OK)
      state.SkipWithError(report.message.c_str());
  state.counters["vertices"] = double(points.size());
  state.counters["components"] = double(report.components);
}

// The quality ladder: the whole-soup call of each preset, with counters for its distance to the
// exact mode's optimum: `excess`, (f - f*) / f* of Eq. 3, and `uv_distance`, the largest
// distance of a vertex's uv from the exact map's (texture space, both fitted into [0,1]^2).
// The exact map is made once per mesh, outside the timing. benchmark/quality_ladder.py sets
// each beside one Laplacian factorization of the same run.
struct Textured_soup
{
  std::vector<Kernel::Point_2> uv;
  SMP::Texture_polygon_mesh_report report;
};

static Textured_soup texture(const Triangle_soup& soup, SMP::Norm_preserving_quality quality)
{
  Textured_soup result;
  result.uv.resize(soup.points.size());
  if(SMP::texture_polygon_soup(soup.points, soup.triangles, CGAL::make_property_map(result.uv),
                               SMP::parameters::quality(quality).combine(SMP::parameters::report(result.report))) != SMP::OK)
    result.uv.clear();
  return result;
}

static void quality(benchmark::State& state, const std::string& name, SMP::Norm_preserving_quality preset)
{
  const int steps = int(state.range(0));
  const Triangle_soup soup = triangle_soup(name, steps);
  static std::map<std::pair<std::string, int>, Textured_soup> exact_of;
  auto cached = exact_of.find({name, steps});
  if(cached == exact_of.end())
    cached = exact_of.emplace(std::make_pair(name, steps), texture(soup, SMP::NORM_PRESERVING_EXACT_QUALITY)).first;
  const Textured_soup& exact = cached->second;
  Textured_soup run;
  for(auto _ : state)
    run = texture(soup, preset);
  if(run.uv.empty() || exact.uv.empty())
  {
    state.SkipWithError("the whole-soup call failed");
    return;
  }
  double distance = 0;
  for(std::size_t i = 0; i < run.uv.size(); ++i)
    distance = (std::max)(distance, std::sqrt(CGAL::squared_distance(run.uv[i], exact.uv[i])));
  int iterations = 0;
  for(const SMP::Norm_preserving_report& r : run.report.reports)
    iterations = (std::max)(iterations, r.solver.iterations);
  state.counters["vertices"] = double(soup.points.size());
  state.counters["excess"] = run.report.objective / exact.report.objective - 1;
  state.counters["certified_gap"] = run.report.optimality_gap;
  state.counters["uv_distance"] = distance;
  state.counters["solver_iterations"] = iterations;
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
// The quality ladder on the series up to 150k-190k vertices (the exact mode takes minutes beyond),
// with the `laplacian` benchmarks above for the ratios.
static void ladder(benchmark::internal::Benchmark* b)
{
  b->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1)->DenseRange(1, 3);
}
BENCHMARK_CAPTURE(quality, draft/mushroom, std::string("mushroom"), SMP::NORM_PRESERVING_DRAFT_QUALITY)->Apply(ladder);
BENCHMARK_CAPTURE(quality, default/mushroom, std::string("mushroom"), SMP::NORM_PRESERVING_DEFAULT_QUALITY)->Apply(ladder);
BENCHMARK_CAPTURE(quality, exact/mushroom, std::string("mushroom"), SMP::NORM_PRESERVING_EXACT_QUALITY)->Apply(ladder);
BENCHMARK_CAPTURE(quality, draft/cow, std::string("cow"), SMP::NORM_PRESERVING_DRAFT_QUALITY)->Apply(ladder);
BENCHMARK_CAPTURE(quality, default/cow, std::string("cow"), SMP::NORM_PRESERVING_DEFAULT_QUALITY)->Apply(ladder);
BENCHMARK_CAPTURE(quality, exact/cow, std::string("cow"), SMP::NORM_PRESERVING_EXACT_QUALITY)->Apply(ladder);
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
