// Norm_preserving_parameterizer_3 itself: on real meshes of every topology (a feasible optimum
// with the fixed pair in place, the same bits again), its CGAL drop-in use, texture fitting and
// tiling, its fixed pair, a solver that fails, its answers to bad input, and two of it on two
// threads; and measure_distortion, which measures its maps, against values computed by hand.

#include "test_runs.h"

#include <CGAL/Surface_mesh_parameterization/Graph_based_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_distortion.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
using np_test::eq3;
using np_test::Exact_parameterizer;
using np_test::Halfedge;
using np_test::l1;
using np_test::Mapped_mesh;
using np_test::Mesh;
using np_test::Parameterizer;
using np_test::Point_2;
using np_test::Point_3;
using np_test::sentinel;
using np_test::Vertex;

double mean_edge_length(const Mesh& mesh)
{
  double sum = 0;
  for(auto e : edges(mesh))
    sum += std::sqrt(CGAL::squared_distance(mesh.point(source(e, mesh)), mesh.point(target(e, mesh))));
  return sum / double(num_edges(mesh));
}

class RealMesh : public ::testing::TestWithParam<std::string> { };

TEST_P(RealMesh, SolvesToAFeasibleOptimumWithTheFixedPairInPlace)
{
  Mapped_mesh run(np_test::load_mesh(GetParam()));
  Parameterizer parameterizer;
  parameterizer.set_texture_fit(SMP::NORM_PRESERVING_NO_FIT);
  const Halfedge h = *halfedges(run.mesh).begin();
  run.parameterize(parameterizer, h);
  ASSERT_EQ(run.status, SMP::OK) << run.report.message;

  // Every vertex of the component (all of these meshes are connected) is finite and marked.
  for(Vertex v : vertices(run.mesh))
  {
    ASSERT_TRUE(get(run.marked, v));
    ASSERT_TRUE(std::isfinite(get(run.uv, v).x()) && std::isfinite(get(run.uv, v).y()));
  }
  EXPECT_EQ(run.report.vertices, num_vertices(run.mesh));
  EXPECT_EQ(run.report.edges, num_edges(run.mesh));

  // Feasible exactly, hence no better than the optimum, which the exact interior-point
  // solver finds (KKT residual 1e-8); within the default tolerance's 1e-4 of it.
  EXPECT_EQ(run.report.solver.status, SMP::NORM_PRESERVING_SOLVER_CONVERGED);
  EXPECT_EQ(run.report.max_constraint_violation, 0.);
  EXPECT_LE(run.report.objective, run.report.initial_objective);
  EXPECT_NEAR(eq3(run), run.report.objective, 1e-9 * run.report.initial_objective);
  Mapped_mesh exact(np_test::load_mesh(GetParam()));
  Exact_parameterizer exact_parameterizer;
  exact_parameterizer.set_texture_fit(SMP::NORM_PRESERVING_NO_FIT);
  exact.parameterize(exact_parameterizer, h);
  ASSERT_EQ(exact.status, SMP::OK) << exact.report.message;
  EXPECT_LT(exact.report.solver.kkt_residual, 1e-8);
  EXPECT_LE(exact.report.max_constraint_violation, 1e-9 * mean_edge_length(run.mesh));
  EXPECT_GE(run.report.objective, exact.report.objective * (1 - 1e-8));
  EXPECT_LE(run.report.objective, exact.report.objective * (1 + 1e-4));
  // The certificate bounds that distance, and tells something.
  EXPECT_LE(run.report.objective, exact.report.objective * (1 + run.report.solver.optimality_gap) * (1 + 1e-12));
  EXPECT_LT(run.report.solver.optimality_gap, 1e-2);

  // The fixed pair: source(h) at the origin, target(h) along the XY-MinMax direction at L1
  // distance equal to the edge's 3D L1 length.
  const Vertex a = source(h, run.mesh), b = target(h, run.mesh);
  EXPECT_EQ(get(run.uv, a), Point_2(0, 0));
  double x_lo = std::numeric_limits<double>::max(), x_hi = -x_lo, y_lo = x_lo, y_hi = -x_lo;
  for(Vertex v : vertices(run.mesh))
  {
    x_lo = std::min(x_lo, run.mesh.point(v).x()); x_hi = std::max(x_hi, run.mesh.point(v).x());
    y_lo = std::min(y_lo, run.mesh.point(v).y()); y_hi = std::max(y_hi, run.mesh.point(v).y());
  }
  const double du = (run.mesh.point(b).x() - run.mesh.point(a).x()) / (x_hi - x_lo);
  const double dv = (run.mesh.point(b).y() - run.mesh.point(a).y()) / (y_hi - y_lo);
  const double t = l1(run.mesh.point(a), run.mesh.point(b)) / (std::abs(du) + std::abs(dv));
  const double tolerance = 1e-12 * l1(run.mesh.point(a), run.mesh.point(b));
  EXPECT_NEAR(get(run.uv, b).x(), t * du, tolerance);
  EXPECT_NEAR(get(run.uv, b).y(), t * dv, tolerance);

  // Same input, same output, bit for bit.
  Mapped_mesh again(np_test::load_mesh(GetParam()));
  again.parameterize(parameterizer, h);
  for(Vertex v : vertices(run.mesh))
    ASSERT_EQ(get(run.uv, v), get(again.uv, v));
}

INSTANTIATE_TEST_SUITE_P(Suite, RealMesh,
  ::testing::Values("nefertiti", "mushroom",        // disks
                    "cow", "camel",                 // closed, genus 0
                    "knot1", "eight", "elephant",   // genus 1, 2, 3
                    "holes", "lion"));              // several border loops

TEST(NormPreservingParameterizer, WorksThroughCGALParameterizeOnADisk)
{
  for(const std::string name : {"nefertiti", "mushroom"})
  {
    Mesh mesh = np_test::load_mesh(name);
    auto uv = mesh.add_property_map<Vertex, Point_2>("v:uv").first;
    Halfedge border = Mesh::null_halfedge();
    for(Halfedge h : halfedges(mesh))
      if(is_border(h, mesh)) { border = h; break; }
    ASSERT_EQ(SMP::parameterize(mesh, Parameterizer(), border, uv), SMP::OK);
    double lo = 1, hi = 0; // the default fit puts the map in [0,1]^2, touching both ends
    for(Vertex v : vertices(mesh))
    {
      lo = std::min({lo, get(uv, v).x(), get(uv, v).y()});
      hi = std::max({hi, get(uv, v).x(), get(uv, v).y()});
    }
    EXPECT_EQ(lo, 0.);
    EXPECT_EQ(hi, 1.);
  }
}

TEST(NormPreservingParameterizer, ParameterizesOnlyTheComponentOfTheHalfedge)
{
  Mapped_mesh run(np_test::load_mesh("knot2")); // two connected components
  Parameterizer parameterizer;
  run.parameterize(parameterizer, *halfedges(run.mesh).begin());
  ASSERT_EQ(run.status, SMP::OK) << run.report.message;
  std::size_t marked = 0;
  for(Vertex v : vertices(run.mesh))
  {
    if(get(run.marked, v)) ++marked;
    else EXPECT_EQ(get(run.uv, v), sentinel);
  }
  EXPECT_EQ(marked, run.report.vertices);
  EXPECT_GT(marked, 0u);
  EXPECT_LT(marked, num_vertices(run.mesh));
}

TEST(NormPreservingParameterizer, FitsAndTilesTextureSpace)
{
  Mapped_mesh raw(np_test::load_mesh("cow")), fitted(np_test::load_mesh("cow")), clamped(np_test::load_mesh("cow"));
  const Halfedge h = *halfedges(raw.mesh).begin();
  Parameterizer parameterizer;
  parameterizer.set_texture_fit(SMP::NORM_PRESERVING_NO_FIT);
  raw.parameterize(parameterizer, h);
  parameterizer.set_texture_fit(SMP::NORM_PRESERVING_UNIFORM_FIT);
  parameterizer.set_tiling(2, 3);
  fitted.parameterize(parameterizer, h);
  parameterizer.set_texture_fit(SMP::NORM_PRESERVING_CLAMP_FIT);
  parameterizer.set_tiling(1, 1);
  clamped.parameterize(parameterizer, h);

  double u_lo = 1e300, v_lo = 1e300, u_hi = -1e300, v_hi = -1e300;
  for(Vertex v : vertices(raw.mesh))
  {
    const Point_2 p = get(raw.uv, v);
    u_lo = std::min(u_lo, p.x()); u_hi = std::max(u_hi, p.x());
    v_lo = std::min(v_lo, p.y()); v_hi = std::max(v_hi, p.y());
  }
  const double scale = 1. / std::max(u_hi - u_lo, v_hi - v_lo);
  for(Vertex v : vertices(raw.mesh))
  {
    const Point_2 p = get(raw.uv, v), f = get(fitted.uv, v), c = get(clamped.uv, v);
    EXPECT_NEAR(f.x(), 2 * (p.x() - u_lo) * scale, 1e-12);
    EXPECT_NEAR(f.y(), 3 * (p.y() - v_lo) * scale, 1e-12);
    EXPECT_EQ(c.x(), std::min(1., std::max(0., p.x())));
    EXPECT_EQ(c.y(), std::min(1., std::max(0., p.y())));
  }
}

TEST(NormPreservingParameterizer, UsesTheAutomaticOrExplicitFixedPair)
{
  Mapped_mesh automatic(np_test::load_mesh("cow")), explicit_pair(np_test::load_mesh("cow"));
  Parameterizer parameterizer;
  parameterizer.set_texture_fit(SMP::NORM_PRESERVING_NO_FIT);
  parameterizer.set_automatic_fixed_pair();
  automatic.parameterize(parameterizer, *halfedges(automatic.mesh).begin());
  ASSERT_EQ(automatic.status, SMP::OK);

  // The automatic pair: the vertex of smallest x and its neighbour across the longest L1 edge.
  Vertex a = *vertices(automatic.mesh).begin();
  for(Vertex v : vertices(automatic.mesh))
    if(automatic.mesh.point(v).x() < automatic.mesh.point(a).x()) a = v;
  Vertex b = a;
  for(Vertex w : CGAL::vertices_around_target(a, automatic.mesh))
    if(b == a || l1(automatic.mesh.point(a), automatic.mesh.point(w)) > l1(automatic.mesh.point(a), automatic.mesh.point(b)))
      b = w;
  EXPECT_EQ(automatic.report.fixed_a, std::size_t(a));
  EXPECT_EQ(automatic.report.fixed_b, std::size_t(b));
  EXPECT_EQ(parameterizer.fixed_vertices(), std::make_pair(a, b));
  EXPECT_EQ(get(automatic.uv, a), Point_2(0, 0));

  // The same pair given explicitly gives the same map.
  parameterizer.set_fixed_pair(a, b);
  explicit_pair.parameterize(parameterizer, *halfedges(explicit_pair.mesh).begin());
  ASSERT_EQ(explicit_pair.status, SMP::OK);
  for(Vertex v : vertices(automatic.mesh))
    ASSERT_EQ(get(automatic.uv, v), get(explicit_pair.uv, v));
}

// three_peaks: the longest edge at the vertex of smallest x is vertical, so XY-MinMax maps its
// two ends to one point; the automatic pair takes the longest edge the guess does tell apart.
TEST(NormPreservingParameterizer, AutomaticPairSkipsEdgesTheGuessCollapses)
{
  Mapped_mesh run(np_test::load_mesh("three_peaks"));
  Parameterizer parameterizer;
  parameterizer.set_texture_fit(SMP::NORM_PRESERVING_NO_FIT);
  parameterizer.set_automatic_fixed_pair();
  run.parameterize(parameterizer, *halfedges(run.mesh).begin());
  ASSERT_EQ(run.status, SMP::OK) << run.report.message;

  const Vertex a(static_cast<Mesh::size_type>(run.report.fixed_a)), b(static_cast<Mesh::size_type>(run.report.fixed_b));
  const auto same_xy = [&](Vertex v, Vertex w) {
    return run.mesh.point(v).x() == run.mesh.point(w).x() && run.mesh.point(v).y() == run.mesh.point(w).y();
  };
  ASSERT_NE(a, b);
  EXPECT_FALSE(same_xy(a, b));
  double longest = 0, longest_separated = 0;
  for(Vertex w : CGAL::vertices_around_target(a, run.mesh))
  {
    const double length = l1(run.mesh.point(a), run.mesh.point(w));
    longest = std::max(longest, length);
    if(!same_xy(a, w)) longest_separated = std::max(longest_separated, length);
  }
  EXPECT_GT(longest, longest_separated); // the plain rule would have picked a collapsed edge
  EXPECT_EQ(l1(run.mesh.point(a), run.mesh.point(b)), longest_separated);
  EXPECT_EQ(get(run.uv, a), Point_2(0, 0));
}

// A model of NormPreservingSolver that finds no solution, as a factorization may fail.
struct Failing_solver
{
  struct State { };
  bool solve(const SMP::Norm_preserving_problem&, std::vector<std::array<double, 2> >&, State&,
             SMP::Norm_preserving_solve_report& report) const
  {
    report.message = "no factorization";
    return false;
  }
};

TEST(NormPreservingSolverConcept, AFailedSolveLeavesTheMapUntouchedAndTheParameterizerReusable)
{
  Mapped_mesh run(np_test::load_mesh("nefertiti"));
  SMP::Norm_preserving_parameterizer_3<Mesh, SMP::XY_min_max_initial_guess, Failing_solver> failing;
  run.parameterize(failing, *halfedges(run.mesh).begin());
  EXPECT_EQ(run.status, SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM);
  EXPECT_EQ(run.report.message, "the QP solver failed: no factorization");
  EXPECT_EQ(run.report.solver.status, SMP::NORM_PRESERVING_SOLVER_FAILED);
  EXPECT_TRUE(run.untouched());

  // A parameterizer that failed (a fixed pair that is not an edge) gives, once set right, the
  // bits of a fresh one.
  Parameterizer reused;
  reused.set_fixed_pair(Vertex(0), Vertex(200));
  Mapped_mesh failed(np_test::load_mesh("nefertiti"));
  failed.parameterize(reused, *halfedges(failed.mesh).begin());
  ASSERT_EQ(failed.status, SMP::ERROR_WRONG_PARAMETER);
  reused.set_fixed_pair_from_halfedge();
  Mapped_mesh again(np_test::load_mesh("nefertiti")), fresh(np_test::load_mesh("nefertiti"));
  again.parameterize(reused, *halfedges(again.mesh).begin());
  Parameterizer new_one;
  fresh.parameterize(new_one, *halfedges(fresh.mesh).begin());
  ASSERT_EQ(again.status, SMP::OK);
  for(Vertex v : vertices(again.mesh))
    EXPECT_EQ(get(again.uv, v), get(fresh.uv, v));
  EXPECT_EQ(again.report.objective, fresh.report.objective);
}

TEST(NormPreservingParameterizerErrors, TilingBelowOneByOne)
{
  for(const std::array<int, 2>& tiles : {std::array<int, 2>{0, 1}, std::array<int, 2>{2, -1}})
  {
    Mapped_mesh run(np_test::tetrahedron());
    Parameterizer parameterizer;
    parameterizer.set_tiling(tiles[0], tiles[1]);
    run.parameterize(parameterizer, *halfedges(run.mesh).begin());
    EXPECT_EQ(run.status, SMP::ERROR_WRONG_PARAMETER);
    EXPECT_NE(run.report.message.find("tiling"), std::string::npos);
    EXPECT_TRUE(run.untouched());
    np_test::Textured textured(np_test::tetrahedron(), SMP::parameters::tiling(tiles[0], tiles[1]));
    EXPECT_EQ(textured.status, SMP::ERROR_WRONG_PARAMETER);
    EXPECT_TRUE(textured.untouched());
  }
}

// Bad input: an error code, a readable message, and the uv map exactly as it was.
void expect_rejected(Mapped_mesh& run, Parameterizer& parameterizer, Halfedge h, SMP::Error_code code, const std::string& words)
{
  run.parameterize(parameterizer, h);
  EXPECT_EQ(run.status, code) << run.report.message;
  EXPECT_NE(run.report.message.find(words), std::string::npos) << run.report.message;
  EXPECT_TRUE(run.untouched());
}

TEST(NormPreservingParameterizerErrors, EmptyMesh)
{
  Mapped_mesh run{Mesh()};
  Parameterizer parameterizer;
  expect_rejected(run, parameterizer, Mesh::null_halfedge(), SMP::ERROR_EMPTY_MESH, "no face");
}

TEST(NormPreservingParameterizerErrors, NonTriangleMesh)
{
  Mesh cube;
  CGAL::make_hexahedron(Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(1, 1, 0), Point_3(0, 1, 0),
                        Point_3(0, 1, 1), Point_3(0, 0, 1), Point_3(1, 0, 1), Point_3(1, 1, 1), cube);
  Mapped_mesh run(cube);
  Parameterizer parameterizer;
  expect_rejected(run, parameterizer, *halfedges(run.mesh).begin(), SMP::ERROR_NON_TRIANGULAR_MESH, "4 vertices");
}

TEST(NormPreservingParameterizerErrors, FaceWithARepeatedVertex)
{
  Mapped_mesh run(np_test::triangle_and_face_with_a_repeated_vertex());
  Parameterizer parameterizer;
  expect_rejected(run, parameterizer, *halfedges(run.mesh).begin(), SMP::ERROR_NON_TRIANGULAR_MESH, "repeated vertex");
}

TEST(NormPreservingParameterizerErrors, NonFiniteCoordinates)
{
  for(double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
  {
    Mapped_mesh run(np_test::tetrahedron());
    run.mesh.point(*vertices(run.mesh).begin()) = Point_3(0, bad, 0);
    Parameterizer parameterizer;
    expect_rejected(run, parameterizer, *halfedges(run.mesh).begin(), SMP::ERROR_WRONG_PARAMETER, "non-finite");
  }
}

TEST(NormPreservingParameterizerErrors, AllVerticesWithTheSameXOrYAreGuessedInTheirPlane)
{
  for(int axis = 0; axis < 2; ++axis)
  {
    Mesh mesh;
    auto p = [axis](double s, double t) { return axis == 0 ? Point_3(0, s, t) : Point_3(s, 0, t); };
    CGAL::make_tetrahedron(p(0, 0), p(1, 0), p(0, 1), p(1, 1), mesh); // flat in x (or y)
    Mapped_mesh run(mesh);
    Parameterizer parameterizer;
    run.parameterize(parameterizer, *halfedges(run.mesh).begin());
    ASSERT_EQ(run.status, SMP::OK) << run.report.message;
    EXPECT_LE(run.report.objective, run.report.initial_objective + 1e-12); // both 0 here: a plane
    EXPECT_NE(get(run.uv, Vertex(0)), get(run.uv, Vertex(3)));              // not collapsed
  }
  // All at one position: no order at all.
  Mesh point;
  CGAL::make_tetrahedron(Point_3(1, 1, 1), Point_3(1, 1, 1), Point_3(1, 1, 1), Point_3(1, 1, 1), point);
  Mapped_mesh run(point);
  Parameterizer parameterizer;
  expect_rejected(run, parameterizer, *halfedges(run.mesh).begin(), SMP::ERROR_WRONG_PARAMETER, "zero length");
}

TEST(NormPreservingParameterizerErrors, FixedPairThatIsNotAnEdge)
{
  Mapped_mesh run(np_test::load_mesh("cow"));
  Parameterizer parameterizer;
  const Halfedge h = *halfedges(run.mesh).begin();
  const Vertex a = source(h, run.mesh);
  Vertex b = a;
  for(Vertex v : vertices(run.mesh)) // a vertex not adjacent to a
  {
    bool adjacent = (v == a);
    for(Vertex w : CGAL::vertices_around_target(a, run.mesh)) adjacent = adjacent || w == v;
    if(!adjacent) { b = v; break; }
  }
  parameterizer.set_fixed_pair(a, b);
  expect_rejected(run, parameterizer, h, SMP::ERROR_WRONG_PARAMETER, "not the two ends of an edge");
}

TEST(NormPreservingParameterizerErrors, FixedPairInAnotherComponent)
{
  Mapped_mesh run(np_test::load_mesh("knot2"));
  Parameterizer parameterizer;
  const Halfedge h = *halfedges(run.mesh).begin();
  auto component = run.mesh.add_property_map<Mesh::Face_index, std::size_t>("f:component").first;
  ASSERT_EQ(CGAL::Polygon_mesh_processing::connected_components(run.mesh, component), 2u);
  Halfedge other = h;
  for(auto f : faces(run.mesh))
    if(get(component, f) != get(component, face(h, run.mesh))) other = halfedge(f, run.mesh);
  parameterizer.set_fixed_pair(source(other, run.mesh), target(other, run.mesh));
  expect_rejected(run, parameterizer, h, SMP::ERROR_WRONG_PARAMETER, "not in the component");
}

TEST(NormPreservingParameterizerErrors, MessagesOfEveryErrorCode)
{
  EXPECT_STREQ(SMP::norm_preserving_error_message(SMP::ERROR_NO_TOPOLOGICAL_BALL), "Input mesh is not a topological ball");
  EXPECT_STREQ(SMP::norm_preserving_error_message(SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM), "Cannot solve linear system");
  EXPECT_STREQ(SMP::norm_preserving_error_message(SMP::ERROR_WRONG_PARAMETER), "A method received an unexpected parameter");
}

// Determinism and thread safety: the parameterizer keeps no shared state.
TEST(Threads, TwoParameterizersOnTwoThreadsGiveTheSequentialUvs)
{
  const Mesh meshes[2] = {np_test::load_mesh("nefertiti"), np_test::icosphere()};
  const auto run = [](const Mesh& mesh, std::vector<Point_2>& uv) {
    Mapped_mesh mapped(mesh);
    SMP::Norm_preserving_parameterizer_3<Mesh, SMP::Graph_based_initial_guess> parameterizer;
    mapped.parameterize(parameterizer, *halfedges(mapped.mesh).begin());
    uv.clear();
    if(mapped.status != SMP::OK) return;
    for(Vertex v : vertices(mapped.mesh)) uv.push_back(get(mapped.uv, v));
  };
  std::vector<Point_2> sequential[2], threaded[2];
  for(int i = 0; i < 2; ++i)
  {
    run(meshes[i], sequential[i]);
    ASSERT_EQ(sequential[i].size(), num_vertices(meshes[i]));
  }
  for(int round = 0; round < 2; ++round)
  {
    std::thread first(run, std::cref(meshes[0]), std::ref(threaded[0]));
    std::thread second(run, std::cref(meshes[1]), std::ref(threaded[1]));
    first.join();
    second.join();
    for(int i = 0; i < 2; ++i)
      EXPECT_TRUE(threaded[i] == sequential[i]) << "mesh " << i << ", round " << round;
  }
}

// ------------------------------------------------------------------------ measure_distortion

// measure_distortion against values computed by hand on small meshes: `Mapped` is a mesh built
// vertex by vertex, each with its uv, every vertex mapped unless a test says otherwise.
struct Mapped
{
  Mesh mesh;
  Mesh::Property_map<Vertex, Point_2> uv;
  Mesh::Property_map<Vertex, bool> all;
  std::vector<Vertex> v;

  Mapped()
  {
    uv = mesh.add_property_map<Vertex, Point_2>("v:uv").first;
    all = mesh.add_property_map<Vertex, bool>("v:all", true).first;
  }
  void add(double x, double y, double z, double u, double w)
  {
    v.push_back(mesh.add_vertex(Point_3(x, y, z)));
    put(uv, v.back(), Point_2(u, w));
  }
  SMP::Parameterization_distortion measure() { return SMP::measure_distortion(mesh, uv, all); }
};

TEST(Distortion, ASimilarityHasNoEdgeLengthError)
{
  Mapped m; // right triangle, uv = 2 * xy rotated by 90 degrees
  m.add(0, 0, 0, 0, 0); m.add(1, 0, 0, 0, 2); m.add(0, 1, 0, -2, 0);
  m.mesh.add_face(m.v[0], m.v[1], m.v[2]);
  const auto d = m.measure();
  EXPECT_EQ(d.faces, 1u);
  EXPECT_EQ(d.edges, 3u);
  EXPECT_NEAR(d.scale, 0.5, 1e-15);
  EXPECT_NEAR(d.edge_length_error, 0, 1e-15);
  EXPECT_NEAR(d.l1_objective, 0, 1e-28);
  EXPECT_NEAR(d.max_angle_distortion, 0, 1e-12);
  EXPECT_NEAR(d.area_distortion, 0, 1e-15);
  EXPECT_NEAR(d.l2_stretch, 1, 1e-15);
  EXPECT_NEAR(d.linf_stretch, 1, 1e-15);
  EXPECT_EQ(d.flipped_faces, 0u);
  EXPECT_EQ(d.degenerate_uv_faces, 0u);
}

TEST(Distortion, AnAffineStretchMatchesTheHandComputedError)
{
  Mapped m; // u = 2x, v = y: 3D lengths 1, 1, sqrt 2; uv lengths 2, 1, sqrt 5
  m.add(0, 0, 0, 0, 0); m.add(1, 0, 0, 2, 0); m.add(0, 1, 0, 0, 1);
  m.mesh.add_face(m.v[0], m.v[1], m.v[2]);
  const double L[3] = {1, 1, std::sqrt(2.)}, T[3] = {2, 1, std::sqrt(5.)};
  const double s = (3 + std::sqrt(10.)) / 10; // sum(L T) / sum(T^2)
  double squares = 0;
  for(int k = 0; k < 3; ++k) squares += (s * T[k] - L[k]) * (s * T[k] - L[k]);
  const double mean = (2 + std::sqrt(2.)) / 3;
  EXPECT_NEAR(m.measure().edge_length_error, std::sqrt(squares / 3) / mean, 1e-14);
  // L1: 3D lengths 1, 1, 2; uv L1 lengths 2, 1, 3; s = (2 + 1 + 6) / (4 + 1 + 9).
  const double s1 = 9. / 14, L1[3] = {1, 1, 2}, T1[3] = {2, 1, 3};
  double squares1 = 0;
  for(int k = 0; k < 3; ++k) squares1 += (s1 * T1[k] - L1[k]) * (s1 * T1[k] - L1[k]);
  EXPECT_NEAR(m.measure().l1_edge_length_error, std::sqrt(squares1 / 3) / (4. / 3), 1e-14);
  EXPECT_NEAR(m.measure().l1_objective, squares1, 1e-14);
}

TEST(Distortion, AnAffineStretchMatchesTheHandComputedAnglesAreasAndStretch)
{
  Mapped m; // u = 2x, v = y on a right isosceles triangle
  m.add(0, 0, 0, 0, 0); m.add(1, 0, 0, 2, 0); m.add(0, 1, 0, 0, 1);
  m.mesh.add_face(m.v[0], m.v[1], m.v[2]);
  const auto d = m.measure();
  const double s = (3 + std::sqrt(10.)) / 10;
  // Corner angles 90, 45, 45 become 90, atan(1/2), atan(2).
  const double pi = 3.14159265358979323846, off = 45 - std::atan(0.5) * 180 / pi;
  EXPECT_NEAR(d.max_angle_distortion, off, 1e-12);
  EXPECT_NEAR(d.mean_angle_distortion, 2 * off / 3, 1e-12);
  // Scaled uv area s^2 against 3D area 1/2.
  EXPECT_NEAR(d.area_distortion, std::abs(std::log(2 * s * s)), 1e-12);
  // The map uv -> 3D is diag(1 / 2s, 1 / s): singular values 1/s and 1/(2s).
  EXPECT_NEAR(d.linf_stretch, 1 / s, 1e-12);
  EXPECT_NEAR(d.l2_stretch, std::sqrt(5. / 8) / s, 1e-12);
}

TEST(Distortion, DoesNotDependOnTheScaleOfTheMeshOrOfTheMap)
{
  // The stretch above, away from the origin, its 3D positions and its uvs scaled by factors
  // whose squares (or their products) overflow or underflow a double.
  auto measure = [](double xyz, double uv) {
    Mapped m;
    m.add(3 * xyz, -xyz, 2 * xyz, 5 * uv, uv);
    m.add(4 * xyz, -xyz, 2 * xyz, 7 * uv, uv);
    m.add(3 * xyz, 0, 2 * xyz, 5 * uv, 2 * uv);
    m.mesh.add_face(m.v[0], m.v[1], m.v[2]);
    return m.measure();
  };
  const auto unit = measure(1, 1);
  EXPECT_NEAR(unit.linf_stretch, 10 / (3 + std::sqrt(10.)), 1e-12); // 1/s, as above
  const double factors[][2] = {{1e-200, 1}, {1e200, 1}, {1, 1e-250}, {1, 1e250},
                               {1e-180, 1e-150}, {1e180, 1e160}, {1e-100, 1e-100}};
  for(const auto& f : factors)
  {
    const auto d = measure(f[0], f[1]);
    EXPECT_NEAR(d.scale / (unit.scale * f[0] / f[1]), 1, 1e-14);
    EXPECT_NEAR(d.edge_length_error, unit.edge_length_error, 1e-14);
    EXPECT_NEAR(d.l1_edge_length_error, unit.l1_edge_length_error, 1e-14);
    EXPECT_NEAR(d.mean_angle_distortion, unit.mean_angle_distortion, 1e-12);
    EXPECT_NEAR(d.max_angle_distortion, unit.max_angle_distortion, 1e-12);
    EXPECT_NEAR(d.area_distortion, unit.area_distortion, 1e-12);
    EXPECT_NEAR(d.l2_stretch, unit.l2_stretch, 1e-12);
    EXPECT_NEAR(d.linf_stretch, unit.linf_stretch, 1e-12);
    EXPECT_EQ(d.degenerate_uv_faces, 0u);
    EXPECT_EQ(d.flipped_faces, 0u);
  }
  // Eq. 3 is in squared 3D units.
  EXPECT_NEAR(measure(1e-100, 1e-100).l1_objective / (unit.l1_objective * 1e-200), 1, 1e-14);
}

TEST(Distortion, CountsAFlippedFaceAndItsArea)
{
  Mapped m; // faces of 3D areas 1/2 and 1, oriented oppositely in uv: the smaller one is flipped
  m.add(0, 0, 0, 0, 0); m.add(1, 0, 0, 1, 0); m.add(0, 1, 0, 0, 1); m.add(0, -2, 0, 0, 0.5);
  m.mesh.add_face(m.v[0], m.v[1], m.v[2]);
  m.mesh.add_face(m.v[0], m.v[3], m.v[1]);
  const auto d = m.measure();
  EXPECT_EQ(d.faces, 2u);
  EXPECT_EQ(d.flipped_faces, 1u);
  EXPECT_NEAR(d.flipped_area_fraction, 1. / 3, 1e-15);
}

TEST(Distortion, CountsDegenerateUVFacesAndSkipsUnmappedVertices)
{
  Mapped m;
  m.add(0, 0, 0, 0, 0); m.add(1, 0, 0, 1, 1); m.add(0, 1, 0, 2, 2); m.add(1, 1, 1, 5, 5);
  m.mesh.add_face(m.v[0], m.v[1], m.v[2]);
  m.mesh.add_face(m.v[2], m.v[1], m.v[3]);
  put(m.all, m.v[3], false);
  const auto d = m.measure();
  EXPECT_EQ(d.faces, 1u);
  EXPECT_EQ(d.edges, 3u);
  EXPECT_EQ(d.degenerate_uv_faces, 1u);
}

} // namespace
