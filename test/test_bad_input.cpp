// Bad input, as scans, CAD exports and broken files give it: every entry point answers with an
// error code and a readable message and leaves the caller's uv map bit for bit as it was, or,
// where the input can be handled, gives a finite result with the properties it should have.

#include "test_runs.h"

#include <CGAL/Surface_mesh_parameterization/Combination_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/Graph_based_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Polygon_triangulation.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/property_map.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
using np_test::Halfedge;
using np_test::Mapped_mesh;
using np_test::Mesh;
using np_test::Parameterizer;
using np_test::Point_2;
using np_test::Point_3;
using np_test::sentinel;
using np_test::Textured;
using np_test::Textured_soup;
using np_test::Vertex;
using np_test::Polygons;

using Epick_point_3 = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;

const double nan = std::numeric_limits<double>::quiet_NaN();
const double inf = std::numeric_limits<double>::infinity();

// A failure: the code, a message that says `words`, the uv map exactly as it was.
template <typename Run>
void expect_failure(const Run& run, SMP::Error_code code, const std::string& words)
{
  EXPECT_EQ(run.status, code) << run.report.message;
  EXPECT_NE(run.report.message.find(words), std::string::npos) << run.report.message;
  EXPECT_TRUE(run.untouched());
}

// A success of the whole-mesh call: every vertex on a face has a finite uv in the unit square.
void expect_in_unit_square(const Textured& t)
{
  ASSERT_EQ(t.status, SMP::OK) << t.report.message;
  EXPECT_TRUE(t.report.message.empty());
  for(Vertex v : vertices(t.mesh))
  {
    if(t.mesh.is_isolated(v)) continue;
    const Point_2 p = get(t.uv, v);
    ASSERT_TRUE(p.x() >= 0 && p.x() <= 1 && p.y() >= 0 && p.y() <= 1) << p;
  }
}

// A success of the parameterizer: every vertex of the (single) component marked with a finite
// uv, and the solution no worse than the transformed guess.
void expect_solved(const Mapped_mesh& run)
{
  ASSERT_EQ(run.status, SMP::OK) << run.report.message;
  for(Vertex v : vertices(run.mesh))
  {
    if(run.mesh.is_isolated(v)) continue;
    EXPECT_TRUE(get(run.marked, v));
    EXPECT_TRUE(np_test::is_finite(get(run.uv, v))) << get(run.uv, v);
  }
  // No worse than the guess, but for rounding: relative to the objective of all-zero uvs.
  double zero_uv_objective = 0;
  for(auto e : edges(run.mesh))
  {
    const Point_3 p = run.mesh.point(source(e, run.mesh)), q = run.mesh.point(target(e, run.mesh));
    zero_uv_objective += CGAL::square(std::abs(p.x() - q.x()) + std::abs(p.y() - q.y()) + std::abs(p.z() - q.z()));
  }
  EXPECT_TRUE(std::isfinite(run.report.objective));
  EXPECT_LE(run.report.objective, run.report.initial_objective + 1e-12 * zero_uv_objective);
}

Mesh mesh_of(const std::vector<Point_3>& points, const Polygons& polygons)
{
  Mesh mesh;
  for(const Point_3& p : points) mesh.add_vertex(p);
  for(const auto& polygon : polygons)
  {
    std::vector<Vertex> face;
    for(std::size_t i : polygon) face.push_back(Vertex(Mesh::size_type(i)));
    if(mesh.add_face(face) == Mesh::null_face()) throw std::runtime_error("mesh_of: a face cannot be added");
  }
  return mesh;
}

Mesh scaled(Mesh mesh, double s)
{
  for(Vertex v : vertices(mesh))
    mesh.point(v) = CGAL::ORIGIN + s * (mesh.point(v) - CGAL::ORIGIN);
  return mesh;
}

Halfedge first_halfedge(const Mesh& mesh) { return *halfedges(mesh).begin(); }

// Two triangles that share vertex 0 only.
const std::vector<Point_3> bow_tie_points = {Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(1, 1, 0),
                                             Point_3(-1, 0, 0.5), Point_3(-1, -1, 0.5)};
const Polygons bow_tie_faces = {{0, 1, 2}, {0, 3, 4}};

TEST(BadInput, EmptyMeshAtEveryEntryPoint)
{
  Mapped_mesh run{Mesh()};
  Parameterizer parameterizer;
  run.parameterize(parameterizer, Mesh::null_halfedge());
  expect_failure(run, SMP::ERROR_EMPTY_MESH, "no face");
  expect_failure(Textured(Mesh()), SMP::ERROR_EMPTY_MESH, "no face");
  expect_failure(Textured_soup({}, {}), SMP::ERROR_EMPTY_MESH, "no face");
  // Vertices but no face.
  Mesh points_only;
  points_only.add_vertex(Point_3(0, 0, 0));
  points_only.add_vertex(Point_3(1, 2, 3));
  expect_failure(Textured(points_only), SMP::ERROR_EMPTY_MESH, "no face");
}

TEST(BadInput, SingleTriangleIsLaidOutWithItsL1Lengths)
{
  // Each L1 edge length is reachable in the plane with the signs of the XY-MinMax guess.
  Mapped_mesh run(mesh_of({Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(0, 1, 0)}, {{0, 1, 2}}));
  Parameterizer parameterizer;
  parameterizer.set_texture_fit(SMP::NORM_PRESERVING_NO_FIT);
  run.parameterize(parameterizer, first_halfedge(run.mesh));
  expect_solved(run);
  EXPECT_NEAR(run.report.objective, 0., 1e-12);
  for(auto h : halfedges(run.mesh))
  {
    const Point_2 a = get(run.uv, source(h, run.mesh)), b = get(run.uv, target(h, run.mesh));
    const Point_3 p = run.mesh.point(source(h, run.mesh)), q = run.mesh.point(target(h, run.mesh));
    EXPECT_NEAR(std::abs(a.x() - b.x()) + std::abs(a.y() - b.y()),
                std::abs(p.x() - q.x()) + std::abs(p.y() - q.y()) + std::abs(p.z() - q.z()), 1e-9);
  }
  expect_in_unit_square(Textured(run.mesh));
}

TEST(BadInput, NonManifoldVertexIsOneVertexOfOneComponent)
{
  // Through a soup, and through a Surface_mesh, from a halfedge of either fan: both fans are
  // one component, and the vertex they share has one uv.
  Textured_soup soup(bow_tie_points, bow_tie_faces);
  ASSERT_EQ(soup.status, SMP::OK) << soup.report.message;
  EXPECT_EQ(soup.report.components, 1u);
  const Mesh mesh = mesh_of(bow_tie_points, bow_tie_faces);
  const Textured textured(mesh);
  expect_in_unit_square(textured);
  for(Vertex v : vertices(mesh))
    EXPECT_EQ(get(textured.uv, v), soup.uv[std::size_t(v)]);
  for(Halfedge h : halfedges(mesh))
  {
    if(is_border(h, mesh)) continue;
    Mapped_mesh run(mesh);
    Parameterizer parameterizer;
    parameterizer.set_automatic_fixed_pair();
    run.parameterize(parameterizer, h);
    expect_solved(run);
    EXPECT_EQ(run.report.vertices, 5u);
    for(Vertex v : vertices(mesh))
      EXPECT_TRUE(get(run.marked, v));
  }
}

TEST(BadInput, NonManifoldEdgeIsAnEdgeOfTheGraph)
{
  // Three triangles on the edge 0-1: five vertices, seven edges, one component.
  const std::vector<Point_3> points = {Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(0.5, 1, 0),
                                       Point_3(0.5, -1, 0), Point_3(0.5, 0, 1)};
  Textured_soup soup(points, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  ASSERT_EQ(soup.status, SMP::OK) << soup.report.message;
  ASSERT_EQ(soup.report.reports.size(), 1u);
  EXPECT_EQ(soup.report.reports[0].edges, 7u);
}

TEST(BadInput, DuplicateVerticesOnASeamAreWeldedOrKeptApart)
{
  // A square cut along its diagonal: the diagonal's two vertices are duplicated.
  const std::vector<Point_3> points = {Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(1, 1, 0), Point_3(0, 1, 0),
                                       Point_3(0, 0, 0), Point_3(1, 1, 0)};
  const Polygons faces = {{0, 1, 2}, {4, 5, 3}};
  Textured_soup welded(points, faces);
  ASSERT_EQ(welded.status, SMP::OK) << welded.report.message;
  EXPECT_EQ(welded.report.components, 1u);
  EXPECT_EQ(welded.report.welded_vertices, 2u);
  EXPECT_EQ(welded.uv[0], welded.uv[4]);
  EXPECT_EQ(welded.uv[2], welded.uv[5]);

  Textured_soup soup(points, faces, SMP::parameters::weld_coincident_vertices(false));
  ASSERT_EQ(soup.status, SMP::OK) << soup.report.message;
  EXPECT_EQ(soup.report.components, 2u);
  for(const Point_2& p : soup.uv)
    EXPECT_TRUE(p.x() >= 0 && p.x() <= 1 && p.y() >= 0 && p.y() <= 1) << p;
  // Laid apart: the two copies of a vertex get different uvs.
  EXPECT_NE(soup.uv[0], soup.uv[4]);
  EXPECT_NE(soup.uv[2], soup.uv[5]);
}

TEST(BadInput, ZeroLengthEdgeAndZeroAreaFacesAreSolved)
{
  // A tetrahedron whose fourth vertex is a duplicate of the first, joined to it by an edge:
  // two faces with a zero-length edge, and zero area.
  const Mesh tetrahedron = mesh_of({Point_3(0, 0, 0), Point_3(3, 0, 1), Point_3(1, 2, 0), Point_3(0, 0, 0)},
                                   {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {0, 2, 3}});
  Mapped_mesh duplicate(tetrahedron);
  Parameterizer parameterizer;
  parameterizer.set_texture_fit(SMP::NORM_PRESERVING_NO_FIT);
  parameterizer.set_automatic_fixed_pair();
  duplicate.parameterize(parameterizer, first_halfedge(duplicate.mesh));
  expect_solved(duplicate);
  // A disk with a face whose three distinct vertices are collinear.
  Mapped_mesh flat(mesh_of({Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(2, 0, 0), Point_3(1, 1, 0)},
                           {{0, 1, 3}, {1, 2, 3}, {0, 2, 1}}));
  flat.parameterize(parameterizer, first_halfedge(flat.mesh));
  expect_solved(flat);
  // The zero-length edge as the fixed pair cannot fix a direction.
  Mapped_mesh pair(tetrahedron);
  parameterizer.set_fixed_pair(Vertex(0), Vertex(3));
  pair.parameterize(parameterizer, first_halfedge(pair.mesh));
  expect_failure(pair, SMP::ERROR_WRONG_PARAMETER, "same position");
}

TEST(BadInput, NonFiniteCoordinatesAreRejected)
{
  for(double bad : {nan, inf, -inf})
  {
    Mesh mesh = np_test::tetrahedron();
    mesh.point(Vertex(2)) = Point_3(1, 2, bad);
    Mapped_mesh run(mesh);
    Parameterizer parameterizer;
    run.parameterize(parameterizer, first_halfedge(run.mesh));
    expect_failure(run, SMP::ERROR_WRONG_PARAMETER, "non-finite");
    expect_failure(Textured(mesh), SMP::ERROR_WRONG_PARAMETER, "vertex 2 has a non-finite coordinate");
  }
}

TEST(BadInput, NonFiniteIsolatedVertexIsLeftAlone)
{
  Mesh mesh = np_test::tetrahedron();
  const Vertex lonely = mesh.add_vertex(Point_3(nan, inf, 0));
  Textured t(mesh);
  expect_in_unit_square(t);
  EXPECT_EQ(t.report.isolated_vertices, 1u);
  EXPECT_EQ(get(t.uv, lonely), sentinel);
}

// `reference` and `run` at `s` times its scale, in mesh units: uvs and objective scaled by s.
void expect_scaled(const Mapped_mesh& reference, const Mapped_mesh& run, double s, double tolerance)
{
  double extent = 0;
  for(Vertex v : vertices(reference.mesh))
    extent = std::max({extent, std::abs(get(reference.uv, v).x()), std::abs(get(reference.uv, v).y())});
  EXPECT_NEAR(run.report.objective, s * s * reference.report.objective, tolerance * s * s * reference.report.objective);
  for(Vertex v : vertices(reference.mesh))
  {
    const Point_2 p = get(run.uv, v), q = get(reference.uv, v);
    ASSERT_NEAR(p.x(), s * q.x(), tolerance * s * extent) << "scale " << s;
    ASSERT_NEAR(p.y(), s * q.y(), tolerance * s * extent) << "scale " << s;
  }
}

TEST(BadInput, TinyAndHugeCoordinatesScaleTheResult)
{
  Parameterizer parameterizer;
  parameterizer.set_texture_fit(SMP::NORM_PRESERVING_NO_FIT);
  // Scaled by 2^-40 ~ 1e-12 and 2^40 ~ 1e12, rounding-free: the very same map, scaled,
  // even on a mesh whose symmetries make exact ties in the guess.
  const Mesh sphere = np_test::icosphere();
  Mapped_mesh reference(sphere);
  reference.parameterize(parameterizer, first_halfedge(reference.mesh));
  expect_solved(reference);
  const Textured fitted(sphere);
  for(double s : {std::ldexp(1., -40), std::ldexp(1., 40)})
  {
    Mapped_mesh run(scaled(sphere, s));
    run.parameterize(parameterizer, first_halfedge(run.mesh));
    expect_solved(run);
    expect_scaled(reference, run, s, 0.);
    const Textured t(scaled(sphere, s)); // fitted into the unit square, the scale is gone
    expect_in_unit_square(t);
    for(Vertex v : vertices(sphere))
      ASSERT_EQ(get(t.uv, v), get(fitted.uv, v));
  }
  // Scaled by 1e-12 and 1e12, with rounding, on a scan (no exact ties): the same map up to
  // the solver's tolerance.
  const Mesh scan = np_test::load_mesh("nefertiti");
  Mapped_mesh scan_reference(scan);
  scan_reference.parameterize(parameterizer, first_halfedge(scan_reference.mesh));
  expect_solved(scan_reference);
  for(double s : {1e-12, 1e12})
  {
    Mapped_mesh run(scaled(scan, s));
    run.parameterize(parameterizer, first_halfedge(run.mesh));
    expect_solved(run);
    expect_scaled(scan_reference, run, s, 1e-6);
  }
}

TEST(BadInput, CollinearVertices)
{
  // Along the x axis XY-MinMax has no y order: v is constant, and every L1 edge length is
  // kept along u (objective 0) (doc/decisions.md, 5).
  const Polygons strip = {{0, 1, 2}, {0, 2, 3}};
  Mapped_mesh on_x(mesh_of({Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(2, 0, 0), Point_3(3, 0, 0)}, strip));
  Parameterizer parameterizer;
  parameterizer.set_texture_fit(SMP::NORM_PRESERVING_NO_FIT);
  on_x.parameterize(parameterizer, first_halfedge(on_x.mesh));
  expect_solved(on_x);
  EXPECT_NEAR(on_x.report.objective, 0., 1e-12);
  // Along a diagonal it is defined, and every L1 edge length is kept (objective 0).
  Mapped_mesh diagonal(mesh_of({Point_3(0, 0, 0), Point_3(1, 1, 1), Point_3(2, 2, 2), Point_3(3, 3, 3)}, strip));
  diagonal.parameterize(parameterizer, first_halfedge(diagonal.mesh));
  expect_solved(diagonal);
  EXPECT_NEAR(diagonal.report.objective, 0., 1e-12);
}

TEST(BadInput, CoplanarVerticesInAPlaneOrthogonalToXY)
{
  // A closed box flattened onto the plane x = 0: XY-MinMax (and the Graph-based guess, which
  // starts from it) takes the plane's own axes, z and y, as the guess of a mesh in z = 0 would
  // take x and y; the combination guess rotates the plane out of its edge-on view.
  Mesh box = np_test::triangulated_cube();
  for(Vertex v : vertices(box))
    box.point(v) = Point_3(0, box.point(v).y(), box.point(v).z() + 0.5 * box.point(v).x());
  Mapped_mesh xy(box);
  Parameterizer parameterizer;
  xy.parameterize(parameterizer, first_halfedge(xy.mesh));
  expect_solved(xy);
  // The same as XY-MinMax on the box turned into the plane z = 0 (x <- z).
  Mesh turned = box;
  for(Vertex v : vertices(turned))
    turned.point(v) = Point_3(box.point(v).z(), box.point(v).y(), 0);
  Mapped_mesh reference(turned);
  reference.parameterize(parameterizer, first_halfedge(reference.mesh));
  expect_solved(reference);
  EXPECT_EQ(xy.report.objective, reference.report.objective);
  Mapped_mesh graph(box);
  SMP::Norm_preserving_parameterizer_3<Mesh, SMP::Graph_based_initial_guess> graph_based;
  graph.parameterize(graph_based, first_halfedge(graph.mesh));
  expect_solved(graph);
  Mapped_mesh combination(box);
  SMP::Norm_preserving_parameterizer_3<Mesh, SMP::Combination_initial_guess> combined;
  combination.parameterize(combined, first_halfedge(combination.mesh));
  expect_solved(combination);
}

TEST(BadInput, FixedPairThatIsNotAnEdgeOrSpansComponents)
{
  // Through the parameterizer.
  Mapped_mesh run(np_test::triangulated_cube());
  Parameterizer parameterizer;
  Vertex a = Vertex(0), far = a;
  for(Vertex v : vertices(run.mesh))
    if(CGAL::squared_distance(run.mesh.point(v), run.mesh.point(a)) >
       CGAL::squared_distance(run.mesh.point(far), run.mesh.point(a))) far = v;
  parameterizer.set_fixed_pair(a, far); // opposite corners of the box: no edge
  run.parameterize(parameterizer, first_halfedge(run.mesh));
  expect_failure(run, SMP::ERROR_WRONG_PARAMETER, "not the two ends of an edge");

  // Through the whole-mesh call, on two tetrahedra (which share the origin: kept apart).
  Mesh two = np_test::tetrahedron();
  CGAL::copy_face_graph(scaled(np_test::tetrahedron(), 2), two);
  const auto apart = SMP::parameters::weld_coincident_vertices(false);
  expect_failure(Textured(two, apart.combine(SMP::parameters::fixed_pair(Vertex(0), Vertex(5)))),
                 SMP::ERROR_WRONG_PARAMETER, "not in the same connected component");
  expect_failure(Textured(two, apart.combine(SMP::parameters::fixed_pair(Vertex(0), Vertex(0)))),
                 SMP::ERROR_WRONG_PARAMETER, "not the two ends of an edge");
  Textured_soup soup({Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(0, 1, 0)}, {{0, 1, 2}}, SMP::parameters::fixed_pair(0, 7));
  expect_failure(soup, SMP::ERROR_WRONG_PARAMETER, "not a vertex of the mesh");
}

TEST(BadInput, IsolatedVerticesAreLeftAlone)
{
  Mesh mesh = np_test::tetrahedron();
  const Vertex lonely = mesh.add_vertex(Point_3(-10, 0, 0)); // smallest x of all
  Mapped_mesh run(mesh);
  Parameterizer parameterizer;
  parameterizer.set_automatic_fixed_pair();
  run.parameterize(parameterizer, first_halfedge(run.mesh));
  expect_solved(run);
  EXPECT_EQ(run.report.vertices, 4u);
  EXPECT_EQ(get(run.uv, lonely), sentinel);
  EXPECT_FALSE(get(run.marked, lonely));

  std::vector<Point_3> points = {Point_3(5, 5, 5), Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(0, 1, 0)};
  Textured_soup soup(points, {{1, 2, 3}});
  ASSERT_EQ(soup.status, SMP::OK) << soup.report.message;
  EXPECT_EQ(soup.report.isolated_vertices, 1u);
  EXPECT_EQ(soup.uv[0], sentinel);
  for(std::size_t i = 1; i < 4; ++i)
    EXPECT_TRUE(np_test::is_finite(soup.uv[i]) && soup.uv[i] != sentinel);
}

TEST(BadInput, TenThousandDisconnectedTrianglesAreLaidOutApart)
{
  // An STL-like soup: every triangle with its own three vertices, in a random-looking order.
  const std::size_t n = 10000;
  std::vector<Point_3> points;
  Polygons polygons;
  for(std::size_t k = 0; k < n; ++k)
  {
    const double x = double((k * 7919) % 100), y = double((k * 104729) % 97), z = double(k % 13);
    points.insert(points.end(), {Point_3(x, y, z), Point_3(x + 0.9, y, z + 0.1), Point_3(x, y + 0.8, z + 0.3)});
    polygons.push_back({3 * k, 3 * k + 1, 3 * k + 2});
  }
  Textured_soup soup(points, polygons);
  ASSERT_EQ(soup.status, SMP::OK) << soup.report.message;
  EXPECT_EQ(soup.report.components, n);
  ASSERT_EQ(soup.report.reports.size(), n);

  // Each triangle's box in the unit square, and no two boxes overlap (sweep along u).
  std::vector<std::array<double, 4> > boxes(n);
  for(std::size_t k = 0; k < n; ++k)
  {
    const Point_2 a = soup.uv[3 * k], b = soup.uv[3 * k + 1], c = soup.uv[3 * k + 2];
    boxes[k] = {std::min({a.x(), b.x(), c.x()}), std::min({a.y(), b.y(), c.y()}),
                std::max({a.x(), b.x(), c.x()}), std::max({a.y(), b.y(), c.y()})};
    ASSERT_TRUE(boxes[k][0] >= 0 && boxes[k][1] >= 0 && boxes[k][2] <= 1 && boxes[k][3] <= 1) << k;
    ASSERT_GT(boxes[k][2], boxes[k][0]);
  }
  std::sort(boxes.begin(), boxes.end());
  std::size_t overlaps = 0;
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = i + 1; j < n && boxes[j][0] < boxes[i][2]; ++j)
      if(boxes[j][1] < boxes[i][3] && boxes[i][1] < boxes[j][3]) ++overlaps;
  EXPECT_EQ(overlaps, 0u);
}

TEST(BadInput, PolygonWithARepeatedVertexIsSplitThere)
{
  // 0-1-2-1-3 is the edge 1-2 and the triangle 0-1-3, as the whole-mesh calls read it; the
  // parameterizer, which takes triangles, refuses a face with a repeated vertex.
  const std::vector<Point_3> square = {Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(1, 1, 0), Point_3(0, 1, 0)};
  Textured_soup soup(square, {{0, 1, 2, 1, 3}});
  ASSERT_EQ(soup.status, SMP::OK) << soup.report.message;
  ASSERT_EQ(soup.report.reports.size(), 1u);
  EXPECT_EQ(soup.report.reports[0].edges, 4u);
  expect_in_unit_square(Textured(np_test::triangle_and_face_with_a_repeated_vertex()));
  Mapped_mesh run(np_test::triangle_and_face_with_a_repeated_vertex());
  Parameterizer parameterizer;
  run.parameterize(parameterizer, first_halfedge(run.mesh));
  expect_failure(run, SMP::ERROR_NON_TRIANGULAR_MESH, "repeated vertex");
}

// A triangulation of one polygon `outline` (step 1), checked without the method that made it:
// n - 2 triangles, each side of the outline in exactly one and in its direction, each triangle
// facing like the outline (its normal along the outline's Newell normal), so that none
// overlaps another in projection; for a `flat` outline also their areas adding up to its area.
void expect_triangulates(const std::vector<Epick_point_3>& outline, const std::vector<std::array<std::size_t, 3> >& triangles,
                         bool flat)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3 Vector_3;
  const std::size_t n = outline.size();
  ASSERT_EQ(triangles.size(), n - 2);
  Vector_3 newell = CGAL::NULL_VECTOR;
  for(std::size_t k = 0; k < n; ++k)
    newell = newell + CGAL::cross_product(outline[k] - outline[0], outline[(k + 1) % n] - outline[0]);
  std::vector<int> sides(n, 0);
  double covered = 0;
  for(const auto& t : triangles)
  {
    for(std::size_t e = 0; e < 3; ++e)
      if(t[(e + 1) % 3] == (t[e] + 1) % n) ++sides[t[e]];
    const Vector_3 normal = CGAL::cross_product(outline[t[1]] - outline[t[0]], outline[t[2]] - outline[t[0]]);
    EXPECT_GT(normal * newell, 0.);
    covered += std::sqrt(normal.squared_length());
  }
  EXPECT_TRUE(std::all_of(sides.begin(), sides.end(), [](int used) { return used == 1; }));
  if(flat)
  {
    EXPECT_NEAR(covered, std::sqrt(newell.squared_length()), 1e-9 * std::sqrt(newell.squared_length()));
  }
}

// A gear-like outline of n corners (radius 1 or 0.6 alternating, plus noise up to 0.05) at
// (x, y) = r (cos, turn sin) of its angle, placed in 3D by `place(x, y)`.
template <typename Place>
std::vector<Epick_point_3> gear(std::size_t n, double turn, Place place)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> noise(0, 0.05);
  std::vector<Epick_point_3> outline;
  for(std::size_t k = 0; k < n; ++k)
  {
    const double angle = 2 * CGAL_PI * double(k) / double(n), radius = (k % 2 ? 1. : 0.6) + noise(random);
    outline.push_back(place(radius * std::cos(angle), turn * radius * std::sin(angle)));
  }
  return outline;
}

// Step 1 on `outline` as one polygon, its corners in order.
std::vector<std::array<std::size_t, 3> > step_1(const std::vector<Epick_point_3>& outline)
{
  std::vector<std::size_t> polygon(outline.size());
  std::iota(polygon.begin(), polygon.end(), std::size_t(0));
  std::vector<std::array<std::size_t, 3> > triangles;
  SMP::internal::Norm_preserving::triangulate_polygon(outline, polygon, triangles);
  return triangles;
}

TEST(BadInput, LargeFlatPolygonIsTriangulatedInItsPlane)
{
  // CAD caps: a gear of 2,000 corners both ways round at z = 0.1, in a tilted plane far from
  // the origin and in a plane x = const (hole filling's 3D search takes seconds on each,
  // doc/performance-log.md, "Step 1 on large polygons"); a house of 5 corners; a square with
  // corners along its sides (three or more in a row); all in the plane, and step 1 takes that
  // triangulation.
  namespace NP = SMP::internal::Norm_preserving;
  std::vector<std::vector<Epick_point_3> > outlines;
  for(double turn : {1., -1.})
  {
    outlines.push_back(gear(2000, turn, [](double x, double y) { return Epick_point_3(x, y, 0.1); }));
    outlines.push_back(gear(2000, turn, [](double x, double y) { return Epick_point_3(1000 + x, 0.3 * x + y, 0.5 * y); }));
    outlines.push_back(gear(2000, turn, [](double x, double y) { return Epick_point_3(2, x, y); }));
  }
  outlines.push_back({{0, 0, 0}, {2, 0, 0}, {2, 0, 1}, {1, 0, 2}, {0, 0, 1}});
  outlines.emplace_back();
  for(int side = 0; side < 4; ++side)
    for(int k = 0; k < 10; ++k)
    {
      const double t = side < 2 ? k : 10 - k;
      outlines.back().emplace_back(side % 2 ? (side < 2 ? 10 : 0) : t, side % 2 ? t : (side < 2 ? 0 : 10), 3);
    }
  for(const auto& outline : outlines)
  {
    std::vector<std::array<std::size_t, 3> > in_plane;
    ASSERT_TRUE(NP::triangulate_in_plane(outline, in_plane)) << outline.size() << " corners from " << outline[0];
    expect_triangulates(outline, in_plane, true);
    EXPECT_EQ(step_1(outline), in_plane);
  }
  // Scaled by 2^500 or 2^-500 (exactly): the same triangles, no overflow or underflow.
  const auto& cap = outlines.front();
  std::vector<std::array<std::size_t, 3> > reference, scaled;
  NP::triangulate_in_plane(cap, reference);
  for(int exponent : {500, -500})
  {
    std::vector<Epick_point_3> outline;
    for(const Epick_point_3& p : cap)
      outline.emplace_back(std::ldexp(p.x(), exponent), std::ldexp(p.y(), exponent), std::ldexp(p.z(), exponent));
    EXPECT_TRUE(NP::triangulate_in_plane(outline, scaled)) << exponent;
    EXPECT_EQ(scaled, reference) << exponent;
  }
}

TEST(BadInput, LargeWavyPolygonIsTriangulatedInProjection)
{
  // A gear whose z waves by +-0.3 (not flat): of 1,000 corners, both ways round, triangulated
  // along its normal (hole filling's search would take seconds); of 100 corners, hole-filled.
  namespace NP = SMP::internal::Norm_preserving;
  for(std::size_t n : {1000, 100})
    for(double turn : {1., -1.})
    {
      const auto outline = gear(n, turn, [](double x, double y) { return Epick_point_3(x, y, 0.3 * std::sin(3 * std::atan2(y, x))); });
      std::vector<std::array<std::size_t, 3> > in_plane;
      ASSERT_EQ(NP::triangulate_in_plane(outline, in_plane), n > NP::projected_outline_corners) << n << " corners";
      const auto triangles = step_1(outline);
      expect_triangulates(outline, triangles, false);
      if(n > NP::projected_outline_corners)
      {
        EXPECT_EQ(triangles, in_plane);
      }
    }
}

TEST(BadInput, NonFlatOrSelfTouchingPolygonIsHoleFilledIn3D)
{
  // Not flat: a crown (z = +-0.3 alternating on a unit circle), also scaled by 10^90. Flat but
  // not simple in projection: a pentagram, a corner on another side, two corners one above the
  // other. None is triangulated in the plane; step 1 gives hole filling's triangles for the
  // crown, and n - 2 triangles for each.
  namespace NP = SMP::internal::Norm_preserving;
  std::vector<Epick_point_3> crown, huge_crown, pentagram;
  for(std::size_t k = 0; k < 12; ++k)
  {
    crown.emplace_back(std::cos(CGAL_PI * double(k) / 6), std::sin(CGAL_PI * double(k) / 6), k % 2 ? 0.3 : -0.3);
    huge_crown.emplace_back(1e90 * crown.back().x(), 1e90 * crown.back().y(), 1e90 * crown.back().z());
  }
  for(std::size_t k = 0; k < 5; ++k)
    pentagram.emplace_back(std::cos(4 * CGAL_PI * double(k) / 5), std::sin(4 * CGAL_PI * double(k) / 5), 0.);
  std::vector<Epick_point_3> touching = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {2, 0, 0}, {0, 4, 0}};
  std::vector<Epick_point_3> stacked = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {2, 2, 0.01}, {2, 2, 0}, {0, 4, 0}};
  std::vector<std::array<std::size_t, 3> > patch;
  for(const auto* outline : {&crown, &huge_crown, &pentagram, &touching, &stacked})
  {
    EXPECT_FALSE(NP::triangulate_in_plane(*outline, patch)) << outline->size() << " corners from " << outline->front();
    EXPECT_TRUE(patch.empty());
    EXPECT_EQ(step_1(*outline).size(), outline->size() - 2);
  }
  std::vector<CGAL::Triple<int, int, int> > filled;
  CGAL::Polygon_mesh_processing::triangulate_hole_polyline(crown, std::back_inserter(filled));
  std::vector<std::array<std::size_t, 3> > expected;
  for(const auto& t : filled)
    expected.push_back({std::size_t(t.first), std::size_t(t.second), std::size_t(t.third)});
  EXPECT_EQ(step_1(crown), expected);
}

TEST(BadInput, PrismWithLargeFlatCapsIsOneComponent)
{
  // A prism whose two caps are flat gears of 500 corners: 1,000 vertices, one component, and
  // no vertex added: its edges are the 2 x 500 sides of the caps, the 2 x 497 diagonals of
  // their triangulations, and the 500 upright sides and 500 diagonals of the quads.
  const std::size_t n = 500;
  const auto cap = gear(n, 1., [](double x, double y) { return Epick_point_3(x, y, 0); });
  std::vector<Point_3> points;
  for(double z : {0., 2.})
    for(const Epick_point_3& p : cap)
      points.emplace_back(p.x(), p.y(), z);
  Polygons polygons(2);
  for(std::size_t k = 0; k < n; ++k)
  {
    polygons[0].push_back(n - 1 - k);
    polygons[1].push_back(n + k);
    polygons.push_back({k, (k + 1) % n, n + (k + 1) % n, n + k});
  }
  const Textured_soup soup(points, polygons);
  ASSERT_EQ(soup.status, SMP::OK) << soup.report.message;
  ASSERT_EQ(soup.report.reports.size(), 1u);
  EXPECT_EQ(soup.report.reports[0].edges, 2 * n + 2 * (n - 3) + 2 * n);
  EXPECT_TRUE(std::none_of(soup.uv.begin(), soup.uv.end(), [](const Point_2& p) { return p == sentinel; }));
}

TEST(BadInput, SoupFacesOfTwoVerticesAreEdgesAndMissingVerticesAreRefused)
{
  const std::vector<Point_3> square = {Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(1, 1, 0), Point_3(0, 1, 0)};
  Textured_soup soup(square, {{0, 1, 2}, {2, 3}});
  ASSERT_EQ(soup.status, SMP::OK) << soup.report.message;
  EXPECT_EQ(soup.report.components, 1u);
  EXPECT_NE(soup.uv[3], sentinel);
  expect_failure(Textured_soup(square, {{0, 1, 2}, {0, 2, 4}}), SMP::ERROR_WRONG_PARAMETER,
                 "face 1 refers to vertex 4 of 4");
  expect_failure(Textured_soup({Point_3(1, 2, 3), Point_3(1, 2, 3), Point_3(1, 2, 3)}, {{0, 1, 2}}),
                 SMP::ERROR_WRONG_PARAMETER, "zero extent");
}

// Inputs from the fuzzer (fuzz/fuzz_texture_off.cpp), read as it reads them: hexagons that
// CGAL's triangulate_faces(), or its hole filling with inexact predicates, cannot triangulate
// safely, and that step 1 triangulates.
Textured_soup soup_of_off(const std::string& off)
{
  std::vector<Point_3> points;
  Polygons polygons;
  std::istringstream in(off);
  if(!CGAL::IO::read_OFF(in, points, polygons)) throw std::runtime_error("soup_of_off: not OFF");
  return Textured_soup(points, polygons);
}

TEST(FuzzRegression, HexagonsWhoseProjectionCrossesItself)
{
  // The constrained Delaunay triangulation of triangulate_faces() inserts the crossings of
  // these hexagons as vertices and reads past the halfedges (an assertion, or out of bounds).
  const Textured_soup soup = soup_of_off("OFF\n12 8 0\n0 0 1\n6 2 1\n2 0 1\n0 2 1\n2 2 1\n2 0 1\n"
                                         "1 1 1\n1 1 1\n1 1 1\n0 1 1\n1 0 5\n1 0 1\n3 0 1 4\n"
                                         "6 8 6 10 2 1 0\n4 9 8 0 3\n6 9 3 4 5 11 7\n4 5 4 1 2\n"
                                         "4 9 7 6 8\n4 11 5 2 0\n4 11 0 6 7\n");
  EXPECT_EQ(soup.status, SMP::OK) << soup.report.message; // non-manifold, as the faces are
}

TEST(FuzzRegression, HexagonWhoseHoleFillingIsIncomplete)
{
  // The hole filling of triangulate_faces() leaves an incomplete patch in the mesh, whose
  // halfedges then point past the end.
  const Textured_soup soup = soup_of_off("OFF\n12 8 0\n0 2 1\n1 2 1\n2 0 1\n0 2 21\n2 2 -1\n2 0 -1\n"
                                         "1 1 1\n1 0 -1\n3 1 1\n0 1 -1\n1 0 5\n1 0 -1\n4 3 0 1 4\n"
                                         "6 8 6 10 2 1 0\n4 9 8 0 3\n6 9 3 4 5 11 7\n4 5 4 1 2\n"
                                         "4 9 7 6 8\n4 11 5 2 10\n4 11 10 6 7\n");
  EXPECT_EQ(soup.status, SMP::OK) << soup.report.message;
}

TEST(FuzzRegression, HugeCoordinateInAHexagon)
{
  // The 3D Delaunay triangulation that hole filling searches asserts on the rounding errors
  // of inexact predicates around a coordinate of 6.7e97: step 1 uses exact ones.
  const Textured_soup soup = soup_of_off("OFF\n12 8 0\n0" + std::string(98, '6') + " 2 1\n2 2 1\n2 0 1\n0 2 21\n"
                                         "0 2 -2\n2 0 -1\n3 1 1\n1 1 -1\n1 0 1\n0 1 -1\n1 0 5\n1 0 -0\n"
                                         "4 3 0 1 4\n6 8 6 10 2 1 0\n4 9 8 0 3\n6 9 3 4 5 11 7\n4 5 4 1 2\n"
                                         "4 9 7 6 8\n4 11 5 2 10\n4 11 10 6 7\n");
  EXPECT_EQ(soup.status, SMP::OK) << soup.report.message;
}

} // namespace
