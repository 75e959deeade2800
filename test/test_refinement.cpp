// Beyond the paper (issue 7): sign refinement and the Euclidean (q = 2) refinement by stress
// majorization. Every property is checked on values recomputed from the written uvs.

#include "test_runs.h"

#include <CGAL/Surface_mesh_parameterization/Interior_point_quadratic_program_traits.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_distortion.h>
#include <CGAL/property_map.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
using np_test::eq3;
using np_test::Exact_parameterizer;
using np_test::Halfedge;
using np_test::Mapped_mesh;
using np_test::Mesh;
using np_test::Parameterizer;
using np_test::Point_2;
using np_test::Point_3;
using np_test::Vertex;

double l2(const Point_3& p, const Point_3& q) { return std::sqrt(CGAL::squared_distance(p, q)); }
double l2(const Point_2& p, const Point_2& q) { return std::sqrt(CGAL::squared_distance(p, q)); }

// The Euclidean objective sum (||P_i - P_j|| - ||T_i - T_j||)^2 of uvs `uv` scaled by `s`.
template <typename UVMap>
double stress(const Mesh& mesh, UVMap uv, double s = 1.)
{
  double sum = 0;
  for(auto e : edges(mesh))
  {
    const Vertex i = source(e, mesh), j = target(e, mesh);
    const double r = s * l2(get(uv, i), get(uv, j)) - l2(mesh.point(i), mesh.point(j));
    sum += r * r;
  }
  return sum;
}

// Euclidean norm of the gradient of the stress over the vertices other than `a` and `b`.
template <typename UVMap>
double stress_gradient_norm(const Mesh& mesh, UVMap uv, Vertex a, Vertex b, double s = 1.)
{
  std::vector<std::array<double, 2> > gradient(num_vertices(mesh), {0., 0.});
  for(auto e : edges(mesh))
  {
    const Vertex i = source(e, mesh), j = target(e, mesh);
    const Point_2 p = get(uv, i), q = get(uv, j);
    const double t = s * l2(p, q), d = l2(mesh.point(i), mesh.point(j));
    if(!(t > 0)) continue; // the stress is not differentiable there; no such edge here
    const double factor = 2. * (t - d) / t * s;
    const std::array<double, 2> g = {factor * (p.x() - q.x()), factor * (p.y() - q.y())};
    for(int c = 0; c < 2; ++c)
    {
      gradient[std::size_t(i)][c] += g[c];
      gradient[std::size_t(j)][c] -= g[c];
    }
  }
  double sum = 0;
  for(Vertex v : vertices(mesh))
    if(v != a && v != b)
      sum += gradient[std::size_t(v)][0] * gradient[std::size_t(v)][0] + gradient[std::size_t(v)][1] * gradient[std::size_t(v)][1];
  return std::sqrt(sum);
}

// The stress where the Euclidean refinement starts: the QP solution `plain` scaled about `a`
// (at the origin) by the best factor `s`, and `b` moved to its 3D distance from `a`.
double start_stress(const Mapped_mesh& plain, Vertex a, Vertex b, double s)
{
  Mesh mesh = plain.mesh;
  auto uv = mesh.add_property_map<Vertex, Point_2>("v:start").first;
  for(Vertex v : vertices(mesh))
    put(uv, v, Point_2(s * get(plain.uv, v).x(), s * get(plain.uv, v).y()));
  const double d = l2(mesh.point(a), mesh.point(b)) / l2(get(uv, a), get(uv, b));
  put(uv, b, Point_2(d * get(uv, b).x(), d * get(uv, b).y()));
  return stress(mesh, uv);
}

// The least-squares factor that fits the uv lengths to the 3D ones.
template <typename UVMap>
double best_scale(const Mesh& mesh, UVMap uv)
{
  double fit = 0, norm = 0;
  for(auto e : edges(mesh))
  {
    const Vertex i = source(e, mesh), j = target(e, mesh);
    const double t = l2(get(uv, i), get(uv, j));
    fit += t * l2(mesh.point(i), mesh.point(j));
    norm += t * t;
  }
  return fit / norm;
}

Mapped_mesh run(const Mesh& mesh, int sign_rounds, int euclidean_iterations,
                double euclidean_tolerance = 1e-4)
{
  Mapped_mesh mapped(mesh);
  Parameterizer parameterizer;
  parameterizer.set_texture_fit(SMP::NORM_PRESERVING_NO_FIT);
  parameterizer.set_sign_refinement(sign_rounds);
  parameterizer.set_euclidean_refinement(euclidean_iterations, euclidean_tolerance);
  mapped.parameterize(parameterizer, *halfedges(mapped.mesh).begin());
  return mapped;
}

// Half a cylinder of radius 1 about the y axis, height 2: 13 x 7 vertices on its rulings and
// half circles, each quad split along a diagonal. Each quad is a planar rectangle, so the
// strip unrolls exactly: a planar map with every edge length of the mesh exists. (About the y
// axis, so that XY-MinMax, which drops z, sees the strip unfolded.)
Mesh cylinder_strip()
{
  Mesh mesh;
  const int around = 12, along = 6;
  std::vector<Vertex> v;
  for(int k = 0; k <= around; ++k)
    for(int l = 0; l <= along; ++l)
    {
      const double angle = 3.14159265358979323846 * k / around;
      v.push_back(mesh.add_vertex(Point_3(std::cos(angle), 2. * l / along, std::sin(angle))));
    }
  auto at = [&](int k, int l) { return v[std::size_t(k * (along + 1) + l)]; };
  for(int k = 0; k < around; ++k)
    for(int l = 0; l < along; ++l)
    {
      mesh.add_face(at(k, l), at(k + 1, l), at(k + 1, l + 1));
      mesh.add_face(at(k, l), at(k + 1, l + 1), at(k, l + 1));
    }
  return mesh;
}

// ---------------------------------------------------------------------------- sign refinement

class SignRefinement : public ::testing::TestWithParam<std::string> { };

// Eq. 3, recorded after every round, never increases; the rounds do lower it; the result
// satisfies its (final) signs exactly, and the reported objective is Eq. 3 of the written uvs.
TEST_P(SignRefinement, NeverIncreasesEq3FromRoundToRound)
{
  const Mesh mesh = np_test::load_mesh(GetParam());
  const Mapped_mesh plain = run(mesh, 0, 0), refined = run(mesh, 8, 0);
  ASSERT_EQ(plain.status, SMP::OK) << plain.report.message;
  ASSERT_EQ(refined.status, SMP::OK) << refined.report.message;
  const std::vector<double>& objectives = refined.report.sign_refinement_objectives;
  ASSERT_EQ(objectives.size(), std::size_t(refined.report.sign_refinement_rounds) + 1);
  EXPECT_LE(refined.report.sign_refinement_rounds, 8);
  EXPECT_GE(refined.report.sign_refinement_rounds, 1);
  EXPECT_EQ(objectives.front(), plain.report.objective); // the QP solution, the same as without
  for(std::size_t k = 1; k < objectives.size(); ++k)
    EXPECT_LE(objectives[k], objectives[k - 1]) << "round " << k;
  EXPECT_LT(objectives.back(), 0.99 * objectives.front());
  EXPECT_NEAR(refined.report.objective, objectives.back(), 1e-12 * objectives.front());
  EXPECT_NEAR(eq3(refined), refined.report.objective, 1e-9 * objectives.front());
  EXPECT_NEAR(eq3(plain), plain.report.objective, 1e-9 * objectives.front());
  EXPECT_EQ(refined.report.max_constraint_violation, 0.);
  EXPECT_TRUE(refined.report.euclidean_stress.empty());
}

INSTANTIATE_TEST_SUITE_P(Suite, SignRefinement,
  ::testing::Values("nefertiti", "mushroom", "three_peaks", "cow", "knot1", "holes"));

// With the exact solver (no warm start) too: each round at most the one before.
TEST(SignRefinementExact, NeverIncreasesEq3WithTheInteriorPointSolver)
{
  Mapped_mesh mapped(np_test::load_mesh("nefertiti"));
  Exact_parameterizer parameterizer;
  parameterizer.set_texture_fit(SMP::NORM_PRESERVING_NO_FIT);
  parameterizer.set_sign_refinement(4, 0.);
  mapped.parameterize(parameterizer, *halfedges(mapped.mesh).begin());
  ASSERT_EQ(mapped.status, SMP::OK) << mapped.report.message;
  const std::vector<double>& objectives = mapped.report.sign_refinement_objectives;
  ASSERT_GE(objectives.size(), 2u);
  for(std::size_t k = 1; k < objectives.size(); ++k)
    EXPECT_LE(objectives[k], objectives[k - 1]) << "round " << k;
  EXPECT_NEAR(eq3(mapped), objectives.back(), 1e-9 * objectives.front());
  EXPECT_LE(mapped.report.max_constraint_violation, 1e-8);
}

// A loose tolerance stops after the first round that lowers Eq. 3 by less than it.
TEST(SignRefinementStop, StopsWhenARoundGainsLessThanTheTolerance)
{
  Mapped_mesh mapped(np_test::load_mesh("cow"));
  Parameterizer parameterizer;
  parameterizer.set_sign_refinement(50, 0.5);
  mapped.parameterize(parameterizer, *halfedges(mapped.mesh).begin());
  ASSERT_EQ(mapped.status, SMP::OK) << mapped.report.message;
  const std::vector<double>& objectives = mapped.report.sign_refinement_objectives;
  ASSERT_EQ(objectives.size(), 2u); // no round of cow gains half of Eq. 3
  EXPECT_GT(objectives[0] - objectives[1], 0.);
  EXPECT_LE(objectives[0] - objectives[1], 0.5 * objectives[0]);
}

// ---------------------------------------------------------------------------- Euclidean refinement

class EuclideanRefinement : public ::testing::TestWithParam<std::string> { };

// The stress, recorded at every step, never increases; its last value is the stress of the
// written uvs; the fixed pair is held at its Euclidean distance; the measured Euclidean
// edge-length error falls below that of the QP solution.
TEST_P(EuclideanRefinement, NeverIncreasesTheStressAndLowersTheEdgeLengthError)
{
  const Mesh mesh = np_test::load_mesh(GetParam());
  const Mapped_mesh plain = run(mesh, 0, 0), refined = run(mesh, 0, 300);
  ASSERT_EQ(refined.status, SMP::OK) << refined.report.message;
  const std::vector<double>& history = refined.report.euclidean_stress;
  ASSERT_EQ(history.size(), std::size_t(refined.report.euclidean_iterations) + 1);
  EXPECT_GE(refined.report.euclidean_iterations, 10);
  for(std::size_t k = 1; k < history.size(); ++k)
    ASSERT_LE(history[k], history[k - 1]) << "step " << k;
  const Vertex a(Mesh::size_type(refined.report.fixed_a)), b(Mesh::size_type(refined.report.fixed_b));
  EXPECT_NEAR(history.front(), start_stress(plain, a, b, best_scale(plain.mesh, plain.uv)), 1e-9 * history.front());
  EXPECT_NEAR(history.back(), stress(refined.mesh, refined.uv), 1e-9 * history.front());
  EXPECT_LT(history.back(), 0.5 * history.front());

  EXPECT_EQ(get(refined.uv, a), Point_2(0, 0));
  EXPECT_NEAR(l2(get(refined.uv, a), get(refined.uv, b)), l2(mesh.point(a), mesh.point(b)),
              1e-12 * l2(mesh.point(a), mesh.point(b)));
  for(Vertex v : vertices(refined.mesh))
    ASSERT_TRUE(np_test::is_finite(get(refined.uv, v)));

  const CGAL::Constant_property_map<Vertex, bool> all(true);
  const double before = SMP::measure_distortion(plain.mesh, plain.uv, all).edge_length_error;
  const double after = SMP::measure_distortion(refined.mesh, refined.uv, all).edge_length_error;
  EXPECT_LT(after, 0.7 * before);
}

INSTANTIATE_TEST_SUITE_P(Suite, EuclideanRefinement,
  ::testing::Values("nefertiti", "mushroom", "three_peaks", "cow", "camel", "knot1", "holes"));

// On a developable strip the stress reaches 0: every edge length is recovered to 1e-6
// (measured: 3e-13, after some 19,000 steps; SMACOF converges linearly).
TEST(EuclideanRefinementDevelopable, RecoversTheEdgeLengthsOfACylinderStrip)
{
  const Mapped_mesh refined = run(cylinder_strip(), 0, 20000, 0.);
  ASSERT_EQ(refined.status, SMP::OK) << refined.report.message;
  double worst = 0;
  for(auto e : edges(refined.mesh))
  {
    const Vertex i = source(e, refined.mesh), j = target(e, refined.mesh);
    const double d = l2(refined.mesh.point(i), refined.mesh.point(j));
    worst = std::max(worst, std::abs(l2(get(refined.uv, i), get(refined.uv, j)) - d) / d);
  }
  EXPECT_LT(worst, 1e-6) << refined.report.euclidean_iterations << " steps, stress "
                         << refined.report.euclidean_stress.front() << " -> " << refined.report.euclidean_stress.back();
  const std::vector<double>& history = refined.report.euclidean_stress;
  for(std::size_t k = 1; k < history.size(); ++k)
    ASSERT_LE(history[k], history[k - 1]) << "step " << k;
}

// Converged, the result is a stationary point of the stress (over the free vertices): its
// gradient, computed here from the uvs, is a tiny fraction of the gradient at the start.
TEST(EuclideanRefinementFixedPoint, ConvergesToAStationaryPointOfTheStress)
{
  const Mesh mesh = np_test::load_mesh("nefertiti");
  const Mapped_mesh plain = run(mesh, 0, 0), refined = run(mesh, 0, 100000, 1e-15);
  ASSERT_EQ(refined.status, SMP::OK) << refined.report.message;
  const Vertex a(Mesh::size_type(refined.report.fixed_a)), b(Mesh::size_type(refined.report.fixed_b));
  const double start = stress_gradient_norm(plain.mesh, plain.uv, a, b, best_scale(plain.mesh, plain.uv));
  const double end = stress_gradient_norm(refined.mesh, refined.uv, a, b);
  EXPECT_LT(end, 1e-5 * start) << "start " << start << " end " << end;
}

// The QP is only the start of the refinement: solved loosely (1e-2), it leads to the same
// stress within 5%, as doc/refinement.md recommends.
TEST(EuclideanRefinementStart, ALooseQPLeadsToTheSameStress)
{
  for(const std::string name : {"mushroom", "cow"})
  {
    const Mesh mesh = np_test::load_mesh(name);
    const Mapped_mesh tight = run(mesh, 0, 1000, 1e-3);
    Mapped_mesh loose(mesh);
    Parameterizer parameterizer(SMP::XY_min_max_initial_guess(), SMP::Norm_preserving_ADMM_solver(1e-2));
    parameterizer.set_texture_fit(SMP::NORM_PRESERVING_NO_FIT);
    parameterizer.set_euclidean_refinement(1000);
    loose.parameterize(parameterizer, *halfedges(loose.mesh).begin());
    ASSERT_EQ(loose.status, SMP::OK) << loose.report.message;
    EXPECT_LT(loose.report.solver.iterations, tight.report.solver.iterations) << name;
    EXPECT_NEAR(stress(loose.mesh, loose.uv), stress(tight.mesh, tight.uv), 0.05 * stress(tight.mesh, tight.uv)) << name;
  }
}

// ---------------------------------------------------------------------------- both, and the API

// Both refinements together, on a disk and a closed mesh: the Euclidean refinement starts
// from the sign-refined solution and both histories are monotone; repeated runs are bit for
// bit the same.
TEST(Refinement, BothTogetherAreMonotoneAndDeterministic)
{
  for(const std::string name : {"nefertiti", "cow"})
  {
    const Mesh mesh = np_test::load_mesh(name);
    const Mapped_mesh both = run(mesh, 5, 200), again = run(mesh, 5, 200);
    ASSERT_EQ(both.status, SMP::OK) << both.report.message;
    const auto& objectives = both.report.sign_refinement_objectives;
    const auto& history = both.report.euclidean_stress;
    ASSERT_GE(objectives.size(), 2u) << name;
    ASSERT_GE(history.size(), 2u) << name;
    for(std::size_t k = 1; k < objectives.size(); ++k) EXPECT_LE(objectives[k], objectives[k - 1]) << name;
    for(std::size_t k = 1; k < history.size(); ++k) EXPECT_LE(history[k], history[k - 1]) << name;
    EXPECT_EQ(both.report.objective, objectives.back()) << name;
    EXPECT_EQ(again.report.sign_refinement_objectives, objectives) << name;
    EXPECT_EQ(again.report.euclidean_stress, history) << name;
    for(Vertex v : vertices(both.mesh))
      ASSERT_EQ(get(both.uv, v), get(again.uv, v)) << name;
  }
}

// Off by default, and 0 rounds or iterations is off: the output is bit for bit the plain QP's.
TEST(Refinement, ZeroIsOffAndOffIsTheDefault)
{
  for(const std::string name : {"nefertiti", "cow"})
  {
    Mapped_mesh by_default(np_test::load_mesh(name)), zero(np_test::load_mesh(name));
    Parameterizer plain, off;
    off.set_sign_refinement(0, 0.5);
    off.set_euclidean_refinement(0, 0.5);
    by_default.parameterize(plain, *halfedges(by_default.mesh).begin());
    zero.parameterize(off, *halfedges(zero.mesh).begin());
    ASSERT_EQ(by_default.status, SMP::OK);
    ASSERT_EQ(zero.status, SMP::OK);
    for(Vertex v : vertices(zero.mesh))
      ASSERT_EQ(get(by_default.uv, v), get(zero.uv, v)) << name;
    EXPECT_EQ(by_default.report.objective, zero.report.objective);
    EXPECT_EQ(by_default.report.sign_refinement_rounds, 0);
    EXPECT_TRUE(by_default.report.sign_refinement_objectives.empty());
    EXPECT_EQ(by_default.report.euclidean_iterations, 0);
    EXPECT_TRUE(by_default.report.euclidean_stress.empty());
  }
}

// Negative limits or tolerances are refused, the uv map untouched.
TEST(Refinement, RefusesNegativeLimitsAndTolerances)
{
  auto refused = [](auto configure) {
    Mapped_mesh mapped(np_test::tetrahedron());
    Parameterizer parameterizer;
    configure(parameterizer);
    mapped.parameterize(parameterizer, *halfedges(mapped.mesh).begin());
    return mapped.status == SMP::ERROR_WRONG_PARAMETER && mapped.untouched() && !mapped.report.message.empty();
  };
  EXPECT_TRUE(refused([](Parameterizer& p) { p.set_sign_refinement(-1); }));
  EXPECT_TRUE(refused([](Parameterizer& p) { p.set_sign_refinement(3, -1e-3); }));
  EXPECT_TRUE(refused([](Parameterizer& p) { p.set_euclidean_refinement(-1); }));
  EXPECT_TRUE(refused([](Parameterizer& p) { p.set_euclidean_refinement(10, std::nan("")); }));
}

// The whole-mesh call passes the options to every component.
TEST(Refinement, WholeMeshCallTakesTheOptions)
{
  const np_test::Textured textured(np_test::load_mesh("cow"),
                                   SMP::parameters::sign_refinement(3).combine(SMP::parameters::euclidean_refinement(50)));
  ASSERT_EQ(textured.status, SMP::OK) << textured.report.message;
  ASSERT_EQ(textured.report.reports.size(), 1u);
  EXPECT_GE(textured.report.reports[0].sign_refinement_rounds, 1);
  EXPECT_GE(textured.report.reports[0].euclidean_iterations, 1);
  EXPECT_EQ(textured.report.objective, textured.report.reports[0].objective);
}

} // namespace
