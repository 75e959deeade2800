// cut_to_disk: every component becomes a topological disk of its Seam_mesh, usable by CGAL's
// parameterizers that need one.

#include "test_meshes.h"

#include <CGAL/Surface_mesh_parameterization/Interior_point_quadratic_program_traits.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_report.h>
#include <CGAL/Surface_mesh_parameterization/cut_to_disk.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/boost/graph/Seam_mesh.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
using np_test::Mesh;
using Seam_edge_map = Mesh::Property_map<Mesh::Edge_index, bool>;
using Seam_vertex_map = Mesh::Property_map<Mesh::Vertex_index, bool>;
using Seam_mesh = CGAL::Seam_mesh<Mesh, Seam_edge_map, Seam_vertex_map>;
using Seam_traits = boost::graph_traits<Seam_mesh>;

// A mesh, its seam mesh and the cut of the component of its first halfedge.
struct Cut_mesh
{
  explicit Cut_mesh(Mesh input) : mesh(std::move(input))
  {
    seam_edges = mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
    seam_vertices = mesh.add_property_map<Mesh::Vertex_index, bool>("v:seam", false).first;
    seam_mesh = std::make_unique<Seam_mesh>(mesh, seam_edges, seam_vertices);
  }

  SMP::Disk_cut_result<Seam_mesh> cut(Mesh::Halfedge_index h)
  {
    const auto start = std::chrono::steady_clock::now();
    const auto result = SMP::cut_to_disk(*seam_mesh, h);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  }

  Mesh mesh;
  Seam_edge_map seam_edges;
  Seam_vertex_map seam_vertices;
  std::unique_ptr<Seam_mesh> seam_mesh;
  double seconds = 0;
};

// Counts on the seam mesh through its BGL interface, over the faces reachable from the face
// of `opposite(bhd)`: the cut component.
struct Topology
{
  std::size_t vertices = 0, edges = 0, faces = 0, border_halfedges = 0, border_loops = 0;
  bool bhd_on_border = false;

  long euler_characteristic() const { return long(vertices) - long(edges) + long(faces); }
};

Topology component_topology(const Seam_mesh& sm, Seam_traits::halfedge_descriptor bhd)
{
  Topology t;
  t.bhd_on_border = is_border(bhd, sm);
  std::set<Seam_traits::face_descriptor> seen;
  std::vector<Seam_traits::face_descriptor> queue(1, face(opposite(bhd, sm), sm));
  seen.insert(queue[0]);
  std::set<Seam_traits::vertex_descriptor> vertices;
  std::set<Seam_traits::halfedge_descriptor> border;
  std::size_t face_halfedges = 0;
  for(std::size_t k = 0; k < queue.size(); ++k)
    for(auto h : CGAL::halfedges_around_face(halfedge(queue[k], sm), sm))
    {
      ++face_halfedges;
      vertices.insert(target(h, sm));
      const auto o = opposite(h, sm);
      if(is_border(o, sm))
        border.insert(o);
      else if(seen.insert(face(o, sm)).second)
        queue.push_back(face(o, sm));
    }
  t.vertices = vertices.size();
  t.edges = (face_halfedges + border.size()) / 2;
  t.faces = queue.size();
  t.border_halfedges = border.size();

  std::set<Seam_traits::halfedge_descriptor> walked;
  for(auto b : border)
  {
    if(walked.count(b))
      continue;
    ++t.border_loops;
    for(auto h = b; walked.insert(h).second && border.count(h); h = next(h, sm)) { }
  }
  return t;
}

struct Expected
{
  const char* name;
  std::size_t genus;
  std::size_t border_loops;
};

void PrintTo(const Expected& e, std::ostream* os) { *os << e.name; }

class CutToDisk : public ::testing::TestWithParam<Expected>
{
protected:
  void SetUp() override
  {
    m = std::make_unique<Cut_mesh>(np_test::load_mesh(GetParam().name));
    result = m->cut(*halfedges(m->mesh).begin());
    ASSERT_EQ(result.status, SMP::OK) << result.message;
    RecordProperty("seam_edges", std::to_string(result.seam_edges));
    RecordProperty("seam_length", std::to_string(result.seam_length));
    RecordProperty("seconds", std::to_string(m->seconds));
  }

  std::unique_ptr<Cut_mesh> m;
  SMP::Disk_cut_result<Seam_mesh> result;
};

TEST_P(CutToDisk, FindsTheGenusAndTheBorderLoopsOfTheComponent)
{
  EXPECT_EQ(result.genus, GetParam().genus);
  EXPECT_EQ(result.border_loops, GetParam().border_loops);
}

TEST_P(CutToDisk, LeavesOneBorderLoopThroughTheReturnedHalfedgeAndEulerCharacteristicOne)
{
  const Topology t = component_topology(*m->seam_mesh, result.border_halfedge);
  EXPECT_TRUE(t.bhd_on_border);
  EXPECT_EQ(t.border_loops, 1u);
  EXPECT_EQ(t.euler_characteristic(), 1);
  // Both sides of every seam edge, and every border edge of the mesh, bound the disk.
  std::size_t mesh_border_edges = 0;
  for(auto e : edges(m->mesh))
    mesh_border_edges += is_border(e, m->mesh) ? 1 : 0;
  EXPECT_EQ(t.border_halfedges, 2 * result.seam_edges + mesh_border_edges);
}

TEST_P(CutToDisk, KeepsTheSeamMeshCountsConsistent)
{
  const Seam_mesh& sm = *m->seam_mesh;
  EXPECT_EQ(sm.number_of_seam_edges(), result.seam_edges);
  // Only the cut component changes: its Euler characteristic goes from 2 - 2g - b to 1.
  const long mesh_euler = long(num_vertices(m->mesh)) - long(num_edges(m->mesh)) + long(num_faces(m->mesh));
  const long component_euler = 2 - 2 * long(GetParam().genus) - long(GetParam().border_loops);
  EXPECT_EQ(long(num_vertices(sm)) - long(num_edges(sm)) + long(num_faces(sm)),
            mesh_euler - component_euler + 1);
}

TEST_P(CutToDisk, ReportsTheNumberAndTotalLengthOfTheSeamEdges)
{
  std::size_t count = 0;
  double length = 0;
  for(auto e : edges(m->mesh))
    if(get(m->seam_edges, e))
    {
      ++count;
      length += CGAL::Polygon_mesh_processing::edge_length(halfedge(e, m->mesh), m->mesh);
    }
  EXPECT_EQ(result.seam_edges, count);
  EXPECT_NEAR(result.seam_length, length, 1e-12 * length);
}

TEST_P(CutToDisk, CutsClosedSurfacesAndLeavesDisksUncut)
{
  if(GetParam().border_loops == 0)
  {
    EXPECT_GT(result.seam_edges, 0u);
    EXPECT_GT(result.seam_length, 0);
  }
  if(GetParam().border_loops == 1 && GetParam().genus == 0)
  {
    EXPECT_EQ(result.seam_edges, 0u);
  }
}

// The surface is the disk plus the seam graph K and the border B, so
// chi(K + B) = chi(surface) - 1, and B, made of loops, contributes 0: the seam vertices off
// the border minus the seam edges make 1 - 2g - b. Pruning leaves no free end off the border,
// except the two ends of the slit of a sphere.
TEST_P(CutToDisk, LeavesAPrunedSeamGraphOfRankTwoGenusPlusBorderLoops)
{
  const Mesh& mesh = m->mesh;
  std::map<Mesh::Vertex_index, std::size_t> seam_degree;
  for(auto e : edges(mesh))
    if(get(m->seam_edges, e))
      for(auto v : {source(e, mesh), target(e, mesh)})
        ++seam_degree[v];
  long off_border = 0;
  std::size_t free_ends = 0;
  for(const auto& [v, degree] : seam_degree)
    if(!is_border(v, mesh))
    {
      ++off_border;
      free_ends += degree == 1 ? 1 : 0;
    }
  EXPECT_EQ(off_border - long(result.seam_edges),
            1 - 2 * long(GetParam().genus) - long(GetParam().border_loops));
  const bool sphere = GetParam().genus == 0 && GetParam().border_loops == 0;
  EXPECT_EQ(free_ends, sphere ? 2u : 0u);
}

TEST_P(CutToDisk, DependsOnTheComponentNotOnTheHalfedgeGiven)
{
  Cut_mesh other(np_test::load_mesh(GetParam().name));
  const auto h = *halfedges(other.mesh).begin();
  const auto again = other.cut(opposite(next(h, other.mesh), other.mesh));
  ASSERT_EQ(again.status, SMP::OK) << again.message;
  EXPECT_EQ(again.seam_edges, result.seam_edges);
  for(auto e : edges(m->mesh))
    ASSERT_EQ(get(other.seam_edges, e), get(m->seam_edges, e)) << e;
}

INSTANTIATE_TEST_SUITE_P(Suite, CutToDisk,
  ::testing::Values(Expected{"nefertiti", 0, 1}, Expected{"mushroom", 0, 1},
                    Expected{"cow", 0, 0}, Expected{"camel", 0, 0}, Expected{"bunny00", 0, 0},
                    Expected{"knot1", 1, 0}, Expected{"eight", 2, 0}, Expected{"elephant", 3, 0},
                    Expected{"holes", 0, 7}, Expected{"lion", 0, 5}, Expected{"knot2", 1, 0}),
  [](const ::testing::TestParamInfo<Expected>& info) { return std::string(info.param.name); });

class CutToDiskThenLscm : public ::testing::TestWithParam<const char*> { };

TEST_P(CutToDiskThenLscm, ParameterizesTheSeamMeshWithCgalLscm)
{
  Cut_mesh m(np_test::load_mesh(GetParam()));
  const auto result = m.cut(*halfedges(m.mesh).begin());
  ASSERT_EQ(result.status, SMP::OK) << result.message;
  auto uv = m.mesh.add_property_map<Mesh::Halfedge_index, np_test::Point_2>("h:uv").first;
  const SMP::Error_code status =
    SMP::parameterize(*m.seam_mesh, SMP::LSCM_parameterizer_3<Seam_mesh>(), result.border_halfedge, uv);
  ASSERT_EQ(status, SMP::OK) << SMP::norm_preserving_error_message(status);
  for(auto v : vertices(*m.seam_mesh))
  {
    const np_test::Point_2& p = get(uv, halfedge(v, *m.seam_mesh));
    ASSERT_TRUE(std::isfinite(p.x()) && std::isfinite(p.y()));
  }
}

INSTANTIATE_TEST_SUITE_P(Suite, CutToDiskThenLscm, ::testing::Values("cow", "knot1", "holes"),
  [](const ::testing::TestParamInfo<const char*>& info) { return std::string(info.param); });

// A closed genus-2 mesh through CGAL's framework on its seam mesh, with ours: every corner
// gets a finite uv in the unit square, the same bits as a direct call, and the exact optimum
// within 1e-4.
TEST(CutToDiskThenOurs, ParameterizesTheSeamMeshOfAClosedMeshThroughCgalsFramework)
{
  Cut_mesh m(np_test::load_mesh("eight"));
  const auto result = m.cut(*halfedges(m.mesh).begin());
  ASSERT_EQ(result.status, SMP::OK) << result.message;
  auto uv = m.mesh.add_property_map<Mesh::Halfedge_index, np_test::Point_2>("h:uv").first;
  ASSERT_EQ(SMP::parameterize(*m.seam_mesh, SMP::Norm_preserving_parameterizer_3<Seam_mesh>(), result.border_halfedge, uv),
            SMP::OK);

  auto direct = [&](auto parameterizer, auto uvmap) {
    auto index = get(CGAL::dynamic_vertex_property_t<int>(), *m.seam_mesh);
    auto marked = get(CGAL::dynamic_vertex_property_t<bool>(), *m.seam_mesh);
    EXPECT_EQ(parameterizer.parameterize(*m.seam_mesh, result.border_halfedge, uvmap, index, marked), SMP::OK)
      << parameterizer.report().message;
    return parameterizer.report().objective;
  };
  auto same = m.mesh.add_property_map<Mesh::Halfedge_index, np_test::Point_2>("h:same").first;
  auto exact_uv = m.mesh.add_property_map<Mesh::Halfedge_index, np_test::Point_2>("h:exact").first;
  const double ours = direct(SMP::Norm_preserving_parameterizer_3<Seam_mesh>(), same);
  const double exact = direct(SMP::Norm_preserving_parameterizer_3<Seam_mesh, SMP::XY_min_max_initial_guess,
                                                                   SMP::Interior_point_quadratic_program_traits<> >(),
                              exact_uv);
  EXPECT_GE(ours, exact * (1 - 1e-9));
  EXPECT_LE(ours, exact * (1 + 1e-4));
  for(auto v : vertices(*m.seam_mesh))
  {
    const np_test::Point_2& p = get(uv, halfedge(v, *m.seam_mesh));
    ASSERT_TRUE(p.x() >= 0 && p.x() <= 1 && p.y() >= 0 && p.y() <= 1) << p;
    ASSERT_EQ(p, get(same, halfedge(v, *m.seam_mesh)));
  }
}

TEST(CutToDisk, RefusesAComponentThatAlreadyHasSeams)
{
  Cut_mesh m(np_test::tetrahedron());
  const auto h = *halfedges(m.mesh).begin();
  m.seam_mesh->add_seam(source(h, m.mesh), target(h, m.mesh));
  const auto result = m.cut(h);
  EXPECT_EQ(result.status, SMP::ERROR_WRONG_PARAMETER);
  EXPECT_EQ(result.message, "the component already has seams");
  EXPECT_EQ(m.seam_mesh->number_of_seam_edges(), 1u);
}

TEST(CutToDisk, RefusesAnEmptyMeshAndANullHalfedge)
{
  Cut_mesh empty{Mesh()};
  EXPECT_EQ(empty.cut(Mesh::null_halfedge()).status, SMP::ERROR_EMPTY_MESH);
  Cut_mesh m(np_test::tetrahedron());
  const auto result = m.cut(Mesh::null_halfedge());
  EXPECT_EQ(result.status, SMP::ERROR_WRONG_PARAMETER);
  EXPECT_EQ(result.message, "the halfedge is null");
}

TEST(CutToDisk, RefusesANonFiniteCoordinate)
{
  Cut_mesh m(np_test::tetrahedron());
  m.mesh.point(Mesh::Vertex_index(2)) = np_test::Point_3(1, std::nan(""), 0);
  const auto result = m.cut(*halfedges(m.mesh).begin());
  EXPECT_EQ(result.status, SMP::ERROR_WRONG_PARAMETER);
  EXPECT_EQ(result.message, "a vertex of the component has a non-finite coordinate");
  EXPECT_EQ(m.seam_mesh->number_of_seam_edges(), 0u);
}

TEST(CutToDisk, SlitsATetrahedronAlongTheTreePathToTheFarthestVertex)
{
  // Vertex 0 has the smallest x; vertex 3, at distance sqrt(18), is the farthest from it.
  Cut_mesh m(np_test::tetrahedron());
  const auto result = m.cut(*halfedges(m.mesh).begin());
  ASSERT_EQ(result.status, SMP::OK) << result.message;
  ASSERT_EQ(result.seam_edges, 1u);
  EXPECT_NEAR(result.seam_length, std::sqrt(18.), 1e-15);
  const auto e = CGAL::edge(Mesh::Vertex_index(0), Mesh::Vertex_index(3), m.mesh);
  ASSERT_TRUE(e.second);
  EXPECT_TRUE(get(m.seam_edges, e.first));
  EXPECT_EQ(component_topology(*m.seam_mesh, result.border_halfedge).border_halfedges, 2u);
}

} // namespace
