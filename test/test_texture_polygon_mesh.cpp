// texture_polygon_mesh: polygon meshes of any topology and several components in one call.

#include "obj_uvs.h"
#include "test_runs.h"

#include <CGAL/Surface_mesh_parameterization/texture_polygon_mesh.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/version_macros.h>

#include <boost/property_map/function_property_map.hpp>

#include <gtest/gtest.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#endif

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
using np_test::Mesh;
using np_test::Point_2;
using np_test::Point_3;
using np_test::sentinel;
using np_test::Textured;
using np_test::Vertex;

// Bounding box of each connected component's uvs: {u_lo, v_lo, u_hi, v_hi}.
std::vector<std::array<double, 4> > component_boxes(const Textured& t)
{
  Mesh copy = t.mesh;
  auto id = copy.add_property_map<Mesh::Face_index, std::size_t>("f:id").first;
  const std::size_t n = CGAL::Polygon_mesh_processing::connected_components(copy, id);
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<std::array<double, 4> > boxes(n, {inf, inf, -inf, -inf});
  for(auto f : faces(copy))
    for(Vertex v : CGAL::vertices_around_face(halfedge(f, copy), copy))
    {
      auto& b = boxes[get(id, f)];
      const Point_2 p = get(t.uv, v);
      b = {std::min(b[0], p.x()), std::min(b[1], p.y()), std::max(b[2], p.x()), std::max(b[3], p.y())};
    }
  return boxes;
}

class PolygonMesh : public ::testing::TestWithParam<std::string> { };

TEST_P(PolygonMesh, CoversEveryComponentWithDisjointBoxesInTheUnitSquare)
{
  Textured t(np_test::load_mesh(GetParam()));
  ASSERT_EQ(t.status, SMP::OK) << t.report.message;
  for(Vertex v : vertices(t.mesh))
  {
    const Point_2 p = get(t.uv, v);
    ASSERT_TRUE(p.x() >= 0 && p.x() <= 1 && p.y() >= 0 && p.y() <= 1) << p;
  }
  const auto boxes = component_boxes(t);
  EXPECT_EQ(boxes.size(), t.report.components);
  for(std::size_t i = 0; i < boxes.size(); ++i)
    for(std::size_t j = i + 1; j < boxes.size(); ++j)
    {
      const bool apart = boxes[i][2] < boxes[j][0] || boxes[j][2] < boxes[i][0] ||
                         boxes[i][3] < boxes[j][1] || boxes[j][3] < boxes[i][1];
      EXPECT_TRUE(apart) << "components " << i << " and " << j << " overlap";
    }
  for(const auto& r : t.report.reports)
    EXPECT_LE(r.objective, r.initial_objective);
}

INSTANTIATE_TEST_SUITE_P(Suite, PolygonMesh,
  ::testing::Values("double-torus-example", "3torus", "torus_quad", "cube_quad", // polygonal
                    "knot2"));                                                 // two components

TEST(TexturePolygonMesh, KeepsEachComponentAtTheCommonScale)
{
  Textured whole(np_test::load_mesh("knot2"), SMP::parameters::texture_fit(SMP::NORM_PRESERVING_NO_FIT));
  ASSERT_EQ(whole.status, SMP::OK);
  ASSERT_EQ(whole.report.components, 2u);

  // Each component alone, with the same automatic pair, differs only by a translation.
  Mesh mesh = np_test::load_mesh("knot2");
  auto id = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:id").first;
  CGAL::Polygon_mesh_processing::connected_components(mesh, id);
  for(std::size_t c = 0; c < 2; ++c)
  {
    auto uv = mesh.add_property_map<Vertex, Point_2>("v:uv" + std::to_string(c)).first;
    auto done = mesh.add_property_map<Vertex, bool>("v:done" + std::to_string(c), false).first;
    SMP::Norm_preserving_parameterizer_3<Mesh> alone;
    alone.set_texture_fit(SMP::NORM_PRESERVING_NO_FIT);
    alone.set_automatic_fixed_pair();
    Mesh::Face_index seed;
    for(auto f : faces(mesh)) if(get(id, f) == c) { seed = f; break; }
    ASSERT_EQ(alone.parameterize(mesh, halfedge(seed, mesh), uv, get(CGAL::vertex_index, mesh), done), SMP::OK);
    std::optional<CGAL::Vector_2<np_test::Kernel> > shift;
    for(Vertex v : vertices(mesh))
    {
      if(!get(done, v)) continue;
      const auto d = get(whole.uv, v) - get(uv, v);
      if(!shift) shift = d;
      EXPECT_NEAR(d.x(), shift->x(), 1e-9);
      EXPECT_NEAR(d.y(), shift->y(), 1e-9);
    }
  }
}

// The components run at once on a TBB build: one thread and several give the same bits.
TEST(TexturePolygonMesh, GivesTheSameBitsOnOneThreadAsOnSeveral)
{
#ifdef CGAL_LINKED_WITH_TBB
  for(const std::string name : {"knot2", "blobby_3cc"})
  {
    std::optional<Textured> several, one;
    {
      // Four threads even on a machine with fewer cores.
      tbb::global_control four(tbb::global_control::max_allowed_parallelism, 4);
      tbb::task_arena arena(4);
      arena.execute([&] { several.emplace(np_test::load_mesh(name)); });
    }
    {
      tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
      one.emplace(np_test::load_mesh(name));
    }
    ASSERT_EQ(several->status, SMP::OK) << name << ": " << several->report.message;
    ASSERT_EQ(one->status, SMP::OK) << name << ": " << one->report.message;
    ASSERT_GT(several->report.components, 1u) << name;
    ASSERT_EQ(several->report.reports.size(), one->report.reports.size()) << name;
    for(std::size_t c = 0; c < one->report.reports.size(); ++c)
    {
      EXPECT_EQ(several->report.reports[c].solver.iterations, one->report.reports[c].solver.iterations) << name;
      EXPECT_EQ(several->report.reports[c].objective, one->report.reports[c].objective) << name;
    }
    for(Vertex v : vertices(one->mesh))
      ASSERT_EQ(get(several->uv, v), get(one->uv, v)) << name;
  }
#else
  GTEST_SKIP() << "built without TBB: one thread only";
#endif
}

TEST(TexturePolygonMesh, TilesTheFittedLayout)
{
  Textured t(np_test::load_mesh("torus_quad"), SMP::parameters::tiling(3, 2));
  ASSERT_EQ(t.status, SMP::OK);
  double u_hi = 0, v_hi = 0, lo = 1;
  for(Vertex v : vertices(t.mesh))
  {
    u_hi = std::max(u_hi, get(t.uv, v).x());
    v_hi = std::max(v_hi, get(t.uv, v).y());
    lo = std::min({lo, get(t.uv, v).x(), get(t.uv, v).y()});
  }
  EXPECT_EQ(lo, 0.);
  EXPECT_LE(u_hi, 3. * (1 + 1e-15));
  EXPECT_LE(v_hi, 2. * (1 + 1e-15));
  // the longer side of the layout fills its tiles (to rounding: extent times its inverse)
  EXPECT_TRUE(std::abs(u_hi - 3.) < 1e-14 || std::abs(v_hi - 2.) < 1e-14) << u_hi << ' ' << v_hi;
}

TEST(TexturePolygonMesh, NormPreservesTheExplicitFixedEdge)
{
  Mesh mesh = np_test::load_mesh("torus_quad");
  const auto h = *halfedges(mesh).begin();
  Textured t(mesh, SMP::parameters::texture_fit(SMP::NORM_PRESERVING_NO_FIT).combine(SMP::parameters::fixed_pair(source(h, mesh), target(h, mesh))));
  ASSERT_EQ(t.status, SMP::OK) << t.report.message;
  const Point_3 p = mesh.point(source(h, mesh)), q = mesh.point(target(h, mesh));
  const Point_2 a = get(t.uv, source(h, mesh)), b = get(t.uv, target(h, mesh));
  const double l1 = std::abs(p.x() - q.x()) + std::abs(p.y() - q.y()) + std::abs(p.z() - q.z());
  EXPECT_NEAR(std::abs(a.x() - b.x()) + std::abs(a.y() - b.y()), l1, 1e-12 * l1);
}

TEST(TexturePolygonMesh, LeavesIsolatedVerticesAlone)
{
  Mesh mesh = np_test::load_mesh("cube_quad");
  const Vertex lonely = mesh.add_vertex(Point_3(5, 5, 5));
  Textured t(mesh);
  ASSERT_EQ(t.status, SMP::OK);
  EXPECT_EQ(t.report.isolated_vertices, 1u);
  EXPECT_EQ(get(t.uv, lonely), sentinel);
  for(Vertex v : vertices(t.mesh))
    if(v != lonely) { EXPECT_NE(get(t.uv, v), sentinel); }
}

TEST(TexturePolygonMeshErrors, EmptyMesh)
{
  Textured t{Mesh()};
  EXPECT_EQ(t.status, SMP::ERROR_EMPTY_MESH);
  EXPECT_FALSE(t.report.message.empty());
}

// A guess that fails on components of four vertices, as a user's guess may.
struct No_guess_for_tetrahedra
{
  SMP::Error_code operator()(const SMP::Norm_preserving_geometry& geometry, std::vector<std::array<double, 2> >& uv,
                             std::string& message) const
  {
    if(geometry.points.size() == 4)
    {
      message = "no guess for a tetrahedron";
      return SMP::ERROR_WRONG_PARAMETER;
    }
    return SMP::XY_min_max_initial_guess()(geometry, uv, message);
  }
};

TEST(TexturePolygonMeshErrors, OneBadComponentLeavesTheWholeMapUntouched)
{
  Mesh mesh = np_test::load_mesh("cube_quad");
  Mesh tetrahedron; // a second component, after the cube
  CGAL::make_tetrahedron(Point_3(7, 0, 0), Point_3(7, 1, 0), Point_3(8, 0, 1), Point_3(7, 1, 1), tetrahedron);
  CGAL::copy_face_graph(tetrahedron, mesh);
  auto uv = mesh.add_property_map<Vertex, Point_2>("v:uv", sentinel).first;
  SMP::Texture_polygon_mesh_report report;
  const SMP::Error_code status =
    SMP::texture_polygon_mesh(mesh, uv, SMP::parameters::initial_guess(No_guess_for_tetrahedra()).combine(SMP::parameters::report(report)));
  EXPECT_EQ(status, SMP::ERROR_WRONG_PARAMETER);
  EXPECT_EQ(report.message, "component 1: no guess for a tetrahedron");
  for(Vertex v : vertices(mesh))
    EXPECT_EQ(get(uv, v), sentinel);
}

TEST(TexturePolygonMeshErrors, FixedPairOnNoFace)
{
  Mesh mesh = np_test::load_mesh("cube_quad");
  const Vertex lonely = mesh.add_vertex(Point_3(5, 5, 5));
  Textured t(mesh, SMP::parameters::fixed_pair(lonely, *vertices(mesh).begin()));
  EXPECT_EQ(t.status, SMP::ERROR_WRONG_PARAMETER);
  EXPECT_NE(t.report.message.find("no face"), std::string::npos);
  EXPECT_TRUE(t.untouched());
}

// Named parameters the CGAL way: a chain of the package's takes CGAL's point maps beside its own
// parameters in any order; a chain of CGAL's own (no parameter of the package) is read too; on
// CGAL 6 a chain of CGAL's can combine() one of the package's. The same options give the same
// uvs, bit for bit, however they are given.
TEST(NamedParameters, AreReadHoweverTheyAreGiven)
{
  const Mesh mesh = np_test::load_mesh("torus_quad");
  const Textured reference(mesh, SMP::parameters::tiling(3, 2));
  ASSERT_EQ(reference.status, SMP::OK);
  // The same points through a map of the caller's, and the options in another order.
  std::vector<Point_3> copy(mesh.points().begin(), mesh.points().end());
  const auto points = CGAL::make_property_map(copy);
  const auto by_index = [&](Vertex v) { return copy[std::size_t(v)]; };
  const auto mapped = boost::make_function_property_map<Vertex, Point_3>(by_index);
  const Textured reordered(mesh, SMP::parameters::vertex_point_map(mapped).combine(SMP::parameters::tiling(3, 2), SMP::parameters::weld_coincident_vertices(true)));
  EXPECT_EQ(reordered.status, SMP::OK);
  for(Vertex v : vertices(mesh))
    EXPECT_EQ(get(reordered.uv, v), get(reference.uv, v));
  // The whole-soup call on the same vertices through a point map.
  std::vector<std::size_t> indices(copy.size());
  std::iota(indices.begin(), indices.end(), std::size_t(0));
  std::vector<std::vector<std::size_t> > polygons;
  for(auto f : faces(mesh))
  {
    polygons.emplace_back();
    for(Vertex v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      polygons.back().push_back(std::size_t(v));
  }
  std::vector<Point_2> uv(copy.size());
  EXPECT_EQ(SMP::texture_polygon_soup(indices, polygons, CGAL::make_property_map(uv),
                                      SMP::parameters::point_map(points).combine(SMP::parameters::tiling(3, 2))),
            SMP::OK);
  for(Vertex v : vertices(mesh))
    EXPECT_EQ(uv[std::size_t(v)], get(reference.uv, v));
  // A chain of CGAL's: its vertex point map, the package's defaults.
  Mesh plain_mesh = mesh;
  auto plain_uv = plain_mesh.add_property_map<Vertex, Point_2>("v:uv").first;
  EXPECT_EQ(SMP::texture_polygon_mesh(plain_mesh, plain_uv, CGAL::parameters::vertex_point_map(mapped)), SMP::OK);
  const Textured defaults(mesh);
  for(Vertex v : vertices(mesh))
    EXPECT_EQ(get(plain_uv, v), get(defaults.uv, v));
#if CGAL_VERSION_MAJOR >= 6
  EXPECT_EQ(SMP::texture_polygon_mesh(plain_mesh, plain_uv,
                                      CGAL::parameters::vertex_point_map(mapped).combine(SMP::parameters::tiling(3, 2))),
            SMP::OK);
  for(Vertex v : vertices(mesh))
    EXPECT_EQ(get(plain_uv, v), get(reference.uv, v));
#endif
}

// The accuracy that the README and the manual state for each preset, through every way in: on
// every mesh of the benchmark suite and of both subdivision series (1 to 3 Loop steps of
// mushroom, a disk, and of cow, closed), the whole-soup call's default is within
// `default_excess` of the optimum that its exact mode certifies on the same call, and its draft
// within `draft_excess`. On the triangle meshes of the suite, the parameterizer (with the
// automatic pair the whole-soup call takes) gives the same objective bit for bit, and so the
// same excess; the command-line tool, given the same soup as an OFF file, gives the whole-soup
// call's uvs of each preset bit for bit, and so the same excess.
constexpr double default_excess = 1e-4, draft_excess = 2e-2; // doc/manual.md, "Quality presets"

struct Soup_of
{
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  bool triangle_mesh = false; // one component, manifold, triangles: the parameterizer's input
};

// A mesh of CGAL's collection by name, or "name*k" for k Loop subdivisions of it.
Soup_of soup_of(const std::string& spec)
{
  const std::size_t star = spec.find('*');
  Mesh mesh = np_test::load_mesh(spec.substr(0, star));
  if(star != std::string::npos)
    CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(std::stoi(spec.substr(star + 1))));
  Soup_of soup;
  CGAL::Polygon_mesh_processing::polygon_mesh_to_polygon_soup(mesh, soup.points, soup.polygons);
  soup.triangle_mesh = CGAL::is_triangle_mesh(mesh);
  return soup;
}

#ifdef NP_TEXTURE_MESH
// The uvs of the command-line tool (NP_TEXTURE_MESH) at `quality` on the OFF file `off`, read back
// from its OBJ, written beside `off`; empty if the tool fails.
std::vector<std::array<double, 2> > tool_uvs(const std::filesystem::path& off, const std::string& quality)
{
  const std::filesystem::path obj = off.parent_path() / (quality + ".obj");
  const std::string command = std::string("\"") + NP_TEXTURE_MESH + "\" --quiet --quality " + quality + " \"" +
                              off.string() + "\" \"" + obj.string() + "\"";
  if(std::system(command.c_str()) != 0)
    return {};
  return np_test::read_obj_uvs(obj.string());
}
#endif

class Accuracy : public ::testing::TestWithParam<std::string> { };

TEST_P(Accuracy, EachPresetIsWithinItsStatedDistanceOfTheOptimum)
{
  const Soup_of soup = soup_of(GetParam());
  const auto call = [&](SMP::Norm_preserving_quality quality) {
    np_test::Textured_soup t(soup.points, soup.polygons, SMP::parameters::quality(quality));
    EXPECT_EQ(t.status, SMP::OK) << t.report.message;
    return t;
  };
  const np_test::Textured_soup exact = call(SMP::NORM_PRESERVING_EXACT_QUALITY);
  const np_test::Textured_soup fine = call(SMP::NORM_PRESERVING_DEFAULT_QUALITY);
  const np_test::Textured_soup draft = call(SMP::NORM_PRESERVING_DRAFT_QUALITY);
  for(const SMP::Norm_preserving_report& r : exact.report.reports)
    EXPECT_TRUE(r.solver.optimality_gap <= 1e-9 || r.solver.status == SMP::NORM_PRESERVING_SOLVER_PRECISION_LIMIT)
      << r.solver.optimality_gap;
  const double optimum = exact.report.objective;
  const double tiny = 1e-12 * (1 + optimum); // an optimum of zero, to round-off
  for(const auto& [run, stated] : {std::make_pair(&fine, default_excess), std::make_pair(&draft, draft_excess)})
  {
    EXPECT_GE(run->report.objective, optimum * (1 - 1e-9) - tiny);
    EXPECT_LE(run->report.objective, optimum * (1 + stated) + tiny) << "above the optimum by "
                                                                   << run->report.objective / optimum - 1;
    EXPECT_LE(run->report.objective, optimum * (1 + run->report.optimality_gap) * (1 + 1e-9) + tiny); // its certificate
  }
#ifdef NP_TEXTURE_MESH
  // The tool on the same soup, written once as an OFF file whose coordinates round-trip.
  std::string name = GetParam();
  std::replace(name.begin(), name.end(), '*', 'x');
  const std::filesystem::path dir =
    std::filesystem::path(::testing::TempDir()) / ("np_accuracy_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::filesystem::path off = dir / "in.off";
  ASSERT_TRUE(CGAL::IO::write_polygon_soup(off.string(), soup.points, soup.polygons, CGAL::parameters::stream_precision(17)));
  for(const auto& [run, quality] : {std::make_pair(&fine, "default"), std::make_pair(&draft, "draft")})
  {
    const std::vector<std::array<double, 2> > tool = tool_uvs(off, quality);
    ASSERT_EQ(tool.size(), run->uv.size()) << "texture_mesh --quality " << quality << " failed";
    std::size_t differing = 0;
    for(std::size_t i = 0; i < tool.size(); ++i) // the tool writes vt 0 0 for a vertex on no face
    {
      const Point_2 expected = run->uv[i] == np_test::sentinel ? Point_2(0, 0) : run->uv[i];
      differing += tool[i][0] != expected.x() || tool[i][1] != expected.y();
    }
    EXPECT_EQ(differing, 0u) << "the tool's uvs at " << quality << " quality differ from the whole-soup call's";
  }
  std::filesystem::remove_all(dir);
#else
  ADD_FAILURE() << "texture_mesh is not built (it needs libpng-dev and libjpeg-dev): its accuracy is not checked";
#endif
  if(!soup.triangle_mesh)
    return;
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, mesh);
  np_test::Mapped_mesh run(mesh);
  np_test::Parameterizer parameterizer;
  parameterizer.set_automatic_fixed_pair();
  run.parameterize(parameterizer, *halfedges(run.mesh).begin());
  ASSERT_EQ(run.status, SMP::OK) << run.report.message;
  if(fine.report.components == 1 && fine.report.welded_vertices == 0 && fine.report.isolated_vertices == 0)
  {
    EXPECT_EQ(run.report.objective, fine.report.objective);
  }
}

INSTANTIATE_TEST_SUITE_P(SuiteAndSeries, Accuracy,
  ::testing::Values("nefertiti", "mushroom", "three_peaks", "lion-head", "mannequin-devil", "cow", "camel", "bunny00",
                    "armadillo", "bear", "man", "homer", "handle", "bull", "knot1", "elk", "eight", "femur",
                    "elephant", "refined_elephant", "double-torus-example", "3torus", "torus_quad", "cube_quad",
                    "lion", "holes", "mech-holes-shark", "pig", "head", "elephant-with-holes", "knot2",
                    "mushroom*1", "mushroom*2", "mushroom*3", "cow*1", "cow*2", "cow*3"),
  [](const ::testing::TestParamInfo<std::string>& info) {
    std::string name = info.param;
    std::replace(name.begin(), name.end(), '-', '_');
    std::replace(name.begin(), name.end(), '*', 'x');
    return name;
  });

} // namespace
