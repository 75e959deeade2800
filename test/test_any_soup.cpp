// Any polygon soup as it comes: every defect that real files have (non-manifold edges and
// vertices, inconsistent orientation, non-orientable surfaces, duplicate faces, repeated
// corners, unreferenced vertices, isolated edges, files split along old seams), generated
// small and at more than 50k vertices, and every mesh of CGAL's collection read as a soup.
// Each is textured with default options; the result has one finite uv in [0,1]^2 per vertex on
// a face, satisfies its sign constraints, is below the guess's objective, matches the exact
// solver and an objective recomputed here from the uvs, and is the same bit for bit twice.

#include "test_runs.h"

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Surface_mesh_parameterization/Interior_point_quadratic_program_traits.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
using np_test::Point_2;
using np_test::Point_3;
using np_test::Polygons;
using np_test::sentinel;
using np_test::Textured_soup;

const double pi = 3.14159265358979323846;

struct Soup
{
  std::vector<Point_3> points;
  Polygons polygons;
};

// A rolling grid of nx x ny vertices, two triangles a cell; `index(i, j)` may identify
// vertices (a periodic or twisted parameter domain), `at(i, j)` places them.
Soup parametric_grid(std::size_t nx, std::size_t ny, const std::function<std::size_t(std::size_t, std::size_t)>& index,
                     std::size_t vertices, const std::function<Point_3(std::size_t, std::size_t)>& at,
                     std::size_t cells_x, std::size_t cells_y)
{
  Soup soup;
  soup.points.resize(vertices);
  for(std::size_t i = 0; i < nx; ++i)
    for(std::size_t j = 0; j < ny; ++j)
      soup.points[index(i, j)] = at(i, j);
  for(std::size_t i = 0; i < cells_x; ++i)
    for(std::size_t j = 0; j < cells_y; ++j)
    {
      const std::size_t a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1), d = index(i, j + 1);
      soup.polygons.push_back({a, b, c});
      soup.polygons.push_back({a, c, d});
    }
  return soup;
}

// A height field over an n x n grid: a disk.
Soup grid(std::size_t n)
{
  return parametric_grid(n, n, [n](std::size_t i, std::size_t j) { return i * n + j; }, n * n,
                         [](std::size_t i, std::size_t j) {
                           return Point_3(double(i), double(j), 3 * std::sin(0.21 * double(i)) * std::cos(0.17 * double(j)));
                         }, n - 1, n - 1);
}

// A grid with a fin (a third triangle, to a new apex) on every seventh triangle's first edge.
Soup fins(std::size_t n)
{
  Soup soup = grid(n);
  const std::size_t count = soup.polygons.size();
  for(std::size_t k = 0; k < count; k += 7)
  {
    const std::vector<std::size_t> t = soup.polygons[k];
    const Point_3 &p = soup.points[t[0]], &q = soup.points[t[1]];
    soup.points.emplace_back((p.x() + q.x()) / 2, (p.y() + q.y()) / 2, std::max(p.z(), q.z()) + 0.8);
    soup.polygons.push_back({t[0], t[1], soup.points.size() - 1});
  }
  return soup;
}

// The cells of a checkerboard: every interior vertex is a bow tie of two cells.
Soup bow_ties(std::size_t n)
{
  Soup soup = grid(n);
  Polygons kept;
  for(std::size_t k = 0; k < soup.polygons.size(); k += 2)
  {
    const std::size_t cell = k / 2, i = cell / (n - 1), j = cell % (n - 1);
    if((i + j) % 2 == 0)
    {
      kept.push_back(soup.polygons[k]);
      kept.push_back(soup.polygons[k + 1]);
    }
  }
  soup.polygons = kept;
  return soup;
}

// Every third triangle reversed.
Soup misoriented(std::size_t n)
{
  Soup soup = grid(n);
  for(std::size_t k = 0; k < soup.polygons.size(); k += 3)
    std::reverse(soup.polygons[k].begin(), soup.polygons[k].end());
  return soup;
}

// Each face twice, the copy reversed.
Soup duplicated(std::size_t n)
{
  Soup soup = grid(n);
  const std::size_t count = soup.polygons.size();
  for(std::size_t k = 0; k < count; ++k)
    soup.polygons.emplace_back(soup.polygons[k].rbegin(), soup.polygons[k].rend());
  return soup;
}

// A Moebius strip of `around` x `across` vertices.
Soup moebius(std::size_t around, std::size_t across)
{
  const auto index = [=](std::size_t i, std::size_t j) {
    return i == around ? across - 1 - j : i * across + j; // going once around turns the strip over
  };
  return parametric_grid(around, across, index, around * across,
                         [=](std::size_t i, std::size_t j) {
                           const double u = 2 * pi * double(i) / double(around);
                           const double s = -0.4 + 0.8 * double(j) / double(across - 1);
                           return Point_3((1 + s * std::cos(u / 2)) * std::cos(u), (1 + s * std::cos(u / 2)) * std::sin(u),
                                          s * std::sin(u / 2));
                         }, around, across - 1);
}

// The figure-eight immersion of a Klein bottle, `n` x `m` vertices: closed, non-orientable.
Soup klein_bottle(std::size_t n, std::size_t m)
{
  const auto index = [=](std::size_t i, std::size_t j) {
    j %= m;
    return i == n ? (m - j) % m : i * m + j; // (u + 2 pi, v) is (u, -v)
  };
  return parametric_grid(n, m, index, n * m,
                         [=](std::size_t i, std::size_t j) {
                           const double u = 2 * pi * double(i) / double(n), v = 2 * pi * double(j) / double(m);
                           const double r = 3 + std::cos(u / 2) * std::sin(v) - std::sin(u / 2) * std::sin(2 * v);
                           return Point_3(r * std::cos(u), r * std::sin(u),
                                          std::sin(u / 2) * std::sin(v) + std::cos(u / 2) * std::sin(2 * v));
                         }, n, m);
}

// A grid whose middle column of vertices is duplicated for the cells on its right, as a file
// split along an old uv seam: coincident vertices.
Soup split_along_a_seam(std::size_t n)
{
  Soup soup = grid(n);
  const std::size_t middle = n / 2;
  std::vector<std::size_t> copy(n);
  for(std::size_t j = 0; j < n; ++j)
  {
    copy[j] = soup.points.size();
    soup.points.push_back(soup.points[middle * n + j]);
  }
  for(auto& polygon : soup.polygons)
  {
    const bool right = std::any_of(polygon.begin(), polygon.end(), [&](std::size_t v) { return v / n > middle; });
    if(right)
      for(auto& v : polygon)
        if(v / n == middle && v < n * n) v = copy[v % n];
  }
  return soup;
}

// Faces with repeated corners, isolated edges and unreferenced vertices around a grid.
Soup with_loose_parts(std::size_t n)
{
  Soup soup = grid(n);
  const std::size_t g = soup.points.size();
  soup.polygons[0] = {soup.polygons[0][0], soup.polygons[0][1], soup.polygons[0][1], soup.polygons[0][2]}; // repeat in a row
  soup.polygons[1] = {soup.polygons[1][0], soup.polygons[1][1], soup.polygons[1][2], soup.polygons[1][0]}; // closed twice
  soup.points.emplace_back(-3., -3., 0.);  // g: on a dangling edge from vertex 0
  soup.points.emplace_back(50., 50., 50.); // g + 1: unreferenced
  soup.points.emplace_back(-9., 4., 1.);   // g + 2, g + 3: an isolated edge of its own
  soup.points.emplace_back(-9., 7., 2.);
  soup.points.emplace_back(-20., 0., 0.);  // g + 4: a face of one distinct vertex (a point)
  soup.polygons.push_back({0, g});
  soup.polygons.push_back({g + 2, g + 3, g + 2});
  soup.polygons.push_back({g + 4, g + 4, g + 4});
  return soup;
}

// Eq. 3 recomputed from the uvs (mesh units) over the edges of the triangles, welded.
double recomputed_objective(const Soup& soup, const std::vector<Point_2>& uv)
{
  std::map<std::array<double, 3>, std::size_t> weld;
  std::vector<std::size_t> id(soup.points.size());
  for(std::size_t i = 0; i < soup.points.size(); ++i)
    id[i] = weld.emplace(std::array<double, 3>{soup.points[i].x(), soup.points[i].y(), soup.points[i].z()}, i).first->second;
  std::vector<std::array<std::size_t, 2> > edges;
  for(const auto& polygon : soup.polygons)
    for(std::size_t k = 0; k < polygon.size(); ++k)
    {
      const std::size_t i = id[polygon[k]], j = id[polygon[(k + 1) % polygon.size()]];
      if(i != j) edges.push_back({std::min(i, j), std::max(i, j)});
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  double sum = 0;
  for(const auto& e : edges)
  {
    const Point_3 &p = soup.points[e[0]], &q = soup.points[e[1]];
    const double l1 = std::abs(p.x() - q.x()) + std::abs(p.y() - q.y()) + std::abs(p.z() - q.z());
    const double r = l1 - std::abs(uv[e[0]].x() - uv[e[1]].x()) - std::abs(uv[e[0]].y() - uv[e[1]].y());
    sum += r * r;
  }
  return sum;
}

// The properties every textured soup has; `referenced[i]` tells whether vertex i is on a face.
void expect_textured(const Textured_soup& t, const std::vector<bool>& referenced)
{
  ASSERT_EQ(t.status, SMP::OK) << t.report.message;
  for(std::size_t i = 0; i < t.points.size(); ++i)
  {
    if(!referenced[i])
    {
      EXPECT_EQ(t.uv[i], sentinel) << "vertex " << i << " is on no face";
      continue;
    }
    const Point_2& p = t.uv[i];
    ASSERT_TRUE(np_test::is_finite(p) && p.x() >= 0 && p.x() <= 1 && p.y() >= 0 && p.y() <= 1)
      << "vertex " << i << ": " << p;
  }
  for(const SMP::Norm_preserving_report& r : t.report.reports)
  {
    EXPECT_EQ(r.status, SMP::OK);
    EXPECT_LE(r.max_constraint_violation, 1e-9);
    EXPECT_LE(r.objective, r.initial_objective * (1 + 1e-12) + 1e-12);
  }
}

std::vector<bool> referenced_vertices(const Soup& soup)
{
  std::vector<bool> referenced(soup.points.size(), false);
  for(const auto& polygon : soup.polygons)
    for(std::size_t i : polygon) referenced[i] = true;
  return referenced;
}

struct Defect
{
  std::string name;
  std::function<Soup(std::size_t)> make; // from a size parameter
  std::size_t components;                // expected, welded
};

const std::vector<Defect>& defects()
{
  static const std::vector<Defect> all = {
    {"fins", fins, 1},
    {"bow_ties", bow_ties, 1},
    {"misoriented", misoriented, 1},
    {"duplicated", duplicated, 1},
    {"moebius", [](std::size_t n) { return moebius(4 * n, n / 4 + 2); }, 1},
    {"klein_bottle", [](std::size_t n) { return klein_bottle(n, n); }, 1},
    {"split_along_a_seam", split_along_a_seam, 1},
    {"with_loose_parts", with_loose_parts, 3},
  };
  return all;
}

class SoupDefect : public ::testing::TestWithParam<Defect> { };

// Small: the properties, the exact optimum, the objective recomputed, the same bits twice.
TEST_P(SoupDefect, SmallIsTexturedAtTheOptimumAndDeterministically)
{
  const Soup soup = GetParam().make(12);
  Textured_soup t(soup.points, soup.polygons);
  expect_textured(t, referenced_vertices(soup));
  EXPECT_EQ(t.report.components, GetParam().components);
  Textured_soup again(soup.points, soup.polygons);
  ASSERT_EQ(again.status, SMP::OK);
  EXPECT_TRUE(std::equal(t.uv.begin(), t.uv.end(), again.uv.begin())) << "not the same bits";

  // Independent checks: the exact optimum (interior point), and Eq. 3 recomputed from uvs in
  // mesh units (one layout translation per component changes no difference).
  Textured_soup exact(soup.points, soup.polygons,
                      SMP::parameters::solver(SMP::Interior_point_quadratic_program_traits<>()));
  ASSERT_EQ(exact.status, SMP::OK) << exact.report.message;
  EXPECT_GE(t.report.objective, exact.report.objective * (1 - 1e-9) - 1e-12);
  EXPECT_LE(t.report.objective, exact.report.objective * (1 + 1e-4) + 1e-12);
  EXPECT_LE(t.report.objective, exact.report.objective * (1 + t.report.optimality_gap) + 1e-12); // the certificate
  Textured_soup mesh_units(soup.points, soup.polygons, SMP::parameters::texture_fit(SMP::NORM_PRESERVING_NO_FIT));
  ASSERT_EQ(mesh_units.status, SMP::OK);
  EXPECT_NEAR(recomputed_objective(soup, mesh_units.uv), mesh_units.report.objective,
              1e-9 * (1 + mesh_units.report.objective));
}

// More than 50k vertices: the properties.
TEST_P(SoupDefect, LargeIsTextured)
{
  const Soup soup = GetParam().make(230);
  ASSERT_GT(soup.points.size(), 50000u);
  Textured_soup t(soup.points, soup.polygons);
  expect_textured(t, referenced_vertices(soup));
  EXPECT_EQ(t.report.components, GetParam().components);
}

INSTANTIATE_TEST_SUITE_P(Defects, SoupDefect, ::testing::ValuesIn(defects()),
                         [](const ::testing::TestParamInfo<Defect>& info) { return info.param.name; });

TEST(AnySoup, WeldedVerticesShareTheirUvAndKeepingThemApartSplitsTheMesh)
{
  const Soup soup = split_along_a_seam(12);
  Textured_soup welded(soup.points, soup.polygons);
  ASSERT_EQ(welded.status, SMP::OK);
  EXPECT_EQ(welded.report.welded_vertices, 12u);
  EXPECT_EQ(welded.report.components, 1u);
  for(std::size_t j = 0; j < 12; ++j)
    EXPECT_EQ(welded.uv[6 * 12 + j], welded.uv[144 + j]) << "a seam at row " << j;

  Textured_soup kept(soup.points, soup.polygons, SMP::parameters::weld_coincident_vertices(false));
  ASSERT_EQ(kept.status, SMP::OK);
  EXPECT_EQ(kept.report.welded_vertices, 0u);
  EXPECT_EQ(kept.report.components, 2u);
  EXPECT_NE(kept.uv[6 * 12], kept.uv[144]);
}

TEST(AnySoup, LoosePartsAreCountedAndMapped)
{
  const Soup soup = with_loose_parts(12);
  Textured_soup t(soup.points, soup.polygons);
  ASSERT_EQ(t.status, SMP::OK) << t.report.message;
  EXPECT_EQ(t.report.isolated_vertices, 1u);
  EXPECT_EQ(t.report.point_components, 1u);
  EXPECT_EQ(t.report.repeated_corners, 5u); // one in face 0, one in face 1, one in the edge, two in the point
}

// The edge graph holds each edge of the triangles once, as {i, j} with i < j, in lexicographic
// order: on soups whose faces repeat (reversed), turn, or add fins to shared edges, against a
// set of the triangles' edges.
TEST(AnySoup, TheEdgeGraphHoldsEachEdgeOnceInOrder)
{
  namespace NP = SMP::internal::Norm_preserving;
  for(const Soup& soup : {duplicated(9), misoriented(9), fins(9)})
  {
    std::set<std::array<std::size_t, 2> > expected;
    for(const std::vector<std::size_t>& t : soup.polygons)
      for(std::size_t k = 0; k < 3; ++k)
        expected.insert({(std::min)(t[k], t[(k + 1) % 3]), (std::max)(t[k], t[(k + 1) % 3])});
    std::vector<std::array<double, 3> > positions;
    for(const Point_3& p : soup.points)
      positions.push_back({p.x(), p.y(), p.z()});
    const NP::Soup_graph graph = NP::build_soup_graph(positions, soup.polygons, true);
    const std::vector<std::array<std::size_t, 2> > sorted(expected.begin(), expected.end());
    EXPECT_EQ(graph.edges, sorted);
  }
}

TEST(AnySoup, AFixedPairThatIsNotAnEdgeFailsBeforeAnySolve)
{
  const Soup soup = grid(12);
  Textured_soup t(soup.points, soup.polygons, SMP::parameters::fixed_pair(0, 100));
  EXPECT_EQ(t.status, SMP::ERROR_WRONG_PARAMETER);
  EXPECT_NE(t.report.message.find("not the two ends of an edge"), std::string::npos) << t.report.message;
  EXPECT_TRUE(t.report.reports.empty());
  EXPECT_TRUE(t.untouched());
}

// Every mesh of CGAL's collection, read as a soup (non-manifold and polygonal files included).
class CollectionSoup : public ::testing::TestWithParam<std::string> { };

TEST_P(CollectionSoup, IsTextured)
{
  Soup soup;
  ASSERT_TRUE(CGAL::IO::read_polygon_soup(GetParam(), soup.points, soup.polygons));
  Textured_soup t(soup.points, soup.polygons);
  if(soup.polygons.empty()) // a point cloud (b9.ply)
  {
    EXPECT_EQ(t.status, SMP::ERROR_EMPTY_MESH);
    return;
  }
  expect_textured(t, referenced_vertices(soup));
}

// A manifold triangle mesh of one component gives the same edges through both paths, hence
// the same objective, bit for bit (coincident vertices kept apart, as a halfedge mesh keeps them).
TEST_P(CollectionSoup, GivesTheObjectiveOfTheMeshPath)
{
  np_test::Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(GetParam(), mesh) || faces(mesh).empty() || !CGAL::is_triangle_mesh(mesh))
    GTEST_SKIP() << "not a triangle mesh that a Surface_mesh reads";
  std::vector<Point_3> points(mesh.points().begin(), mesh.points().end());
  Polygons polygons;
  for(auto f : faces(mesh))
  {
    polygons.emplace_back();
    for(auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      polygons.back().push_back(std::size_t(v));
  }
  Textured_soup soup(points, polygons, SMP::parameters::weld_coincident_vertices(false));
  ASSERT_EQ(soup.status, SMP::OK) << soup.report.message;
  if(soup.report.components != 1 || soup.report.isolated_vertices != 0)
    GTEST_SKIP() << "several components";
  np_test::Mapped_mesh run(mesh);
  np_test::Parameterizer parameterizer;
  parameterizer.set_automatic_fixed_pair();
  run.parameterize(parameterizer, *halfedges(run.mesh).begin());
  ASSERT_EQ(run.status, SMP::OK) << run.report.message;
  EXPECT_EQ(run.report.edges, soup.report.reports[0].edges);
  EXPECT_EQ(run.report.objective, soup.report.objective);
  for(auto v : vertices(run.mesh))
    EXPECT_NEAR(get(run.uv, v).x(), soup.uv[std::size_t(v)].x(), 1e-12);
}

std::vector<std::string> collection_files()
{
  std::vector<std::string> files;
  for(const auto& entry : std::filesystem::directory_iterator(NP_MESH_DIR))
  {
    const std::string extension = entry.path().extension().string();
    if(extension == ".off" || extension == ".ply" || extension == ".stl")
      files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

INSTANTIATE_TEST_SUITE_P(Meshes, CollectionSoup, ::testing::ValuesIn(collection_files()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = std::filesystem::path(info.param).filename().string();
                           for(char& c : name)
                             if(!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

} // namespace
