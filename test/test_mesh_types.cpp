// One typed suite over every mesh type a user may hold: the same mesh gives the same uvs, bit
// for bit, as a Surface_mesh, a Polyhedron_3, a cut Seam_mesh, an OpenMesh PolyMesh and a
// user's own indexed mesh adapted through Indexed_mesh_traits.

#include "test_meshes.h"

#include <CGAL/Surface_mesh_parameterization/cut_to_disk.h>
#include <CGAL/Surface_mesh_parameterization/texture_indexed_mesh.h>
#include <CGAL/Surface_mesh_parameterization/texture_polygon_mesh.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>
#include <CGAL/IO/polygon_soup_io.h>

// OpenMesh's PropertyT::push_back() copies a default-constructed (uninitialized) VectorT, which
// GCC's -Wmaybe-uninitialized reports once inlined; the value is overwritten right after.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#pragma GCC diagnostic pop
#include <CGAL/boost/graph/graph_traits_PolyMesh_ArrayKernelT.h>

#include <gtest/gtest.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
using np_test::Kernel;
using np_test::Mesh;
using Point_3 = Kernel::Point_3;
using Point_2 = Kernel::Point_2;
using UVs = std::vector<std::array<double, 2> >;

// Vertices and faces: what every mesh type is built from, and what each result is indexed by.
struct Soup
{
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > faces;
};

Soup read_soup(const std::string& name)
{
  Soup soup;
  const std::string path = std::string(NP_MESH_DIR) + "/" + name + ".off";
  if(!CGAL::IO::read_polygon_soup(path, soup.points, soup.faces) || soup.faces.empty())
    throw std::runtime_error("cannot read " + path);
  return soup;
}

bool is_triangle_soup(const Soup& soup)
{
  for(const auto& f : soup.faces)
    if(f.size() != 3) return false;
  return true;
}

// A graph mesh from the soup, vertex i being the i-th of vertices(mesh).
template <typename Graph>
void build_graph(const Soup& soup, Graph& mesh)
{
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup.points, soup.faces, mesh);
  ASSERT_EQ(num_vertices(mesh), soup.points.size());
}

// Runs both entry points on a CGAL graph and returns the uvs by vertex order:
// the whole-mesh call, and the parameterizer on the component of the first face.
template <typename Graph>
struct Graph_runs
{
  static UVs texture(const Graph& mesh, SMP::Texture_polygon_mesh_report& report)
  {
    auto uv = unset_uvs(mesh);
    const SMP::Error_code status = SMP::texture_polygon_mesh(mesh, uv, SMP::parameters::report(report));
    EXPECT_EQ(status, SMP::OK) << report.message;
    return by_vertex_order(mesh, uv);
  }
  static UVs parameterize(Graph& mesh, SMP::Norm_preserving_report& report)
  {
    auto uv = unset_uvs(mesh);
    auto marked = get(CGAL::dynamic_vertex_property_t<unsigned char>(), mesh); // OpenMesh: no bool
    auto index = get(CGAL::dynamic_vertex_property_t<int>(), mesh); // the vertex order, as CGAL's parameterize()
    int next = 0;
    for(auto v : vertices(mesh))
      put(index, v, next++);
    SMP::Norm_preserving_parameterizer_3<Graph> parameterizer;
    parameterizer.set_automatic_fixed_pair(); // halfedges are not comparable across types
    const SMP::Error_code status = parameterizer.parameterize(mesh, halfedge(*faces(mesh).begin(), mesh), uv, index, marked);
    EXPECT_EQ(status, SMP::OK) << parameterizer.report().message;
    report = parameterizer.report();
    return by_vertex_order(mesh, uv);
  }
  static auto unset_uvs(const Graph& mesh)
  {
    auto uv = get(CGAL::dynamic_vertex_property_t<Point_2>(), mesh);
    for(auto v : vertices(mesh))
      put(uv, v, Point_2(-1, -1));
    return uv;
  }
  template <typename Map>
  static UVs by_vertex_order(const Graph& mesh, const Map& uv)
  {
    UVs result;
    for(auto v : vertices(mesh))
      result.push_back({get(uv, v).x(), get(uv, v).y()});
    return result;
  }
};

// ---- The mesh types, each behind the same small interface --------------------------------

struct Surface_mesh_type
{
  Mesh mesh;
  Soup soup;
  void build(const Soup& s) { soup = s; build_graph(soup, mesh); }
  UVs texture(SMP::Texture_polygon_mesh_report& r) { return Graph_runs<Mesh>::texture(mesh, r); }
  UVs parameterize(SMP::Norm_preserving_report& r) { return Graph_runs<Mesh>::parameterize(mesh, r); }
};

struct Polyhedron_type
{
  typedef CGAL::Polyhedron_3<Kernel> Polyhedron;
  Polyhedron mesh;
  Soup soup;
  void build(const Soup& s) { soup = s; build_graph(soup, mesh); }
  UVs texture(SMP::Texture_polygon_mesh_report& r) { return Graph_runs<Polyhedron>::texture(mesh, r); }
  UVs parameterize(SMP::Norm_preserving_report& r) { return Graph_runs<Polyhedron>::parameterize(mesh, r); }
};

// OpenMesh with double coordinates (its default is float, which would round the input).
struct Double_traits : public OpenMesh::DefaultTraits
{
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};

struct OpenMesh_type
{
  typedef OpenMesh::PolyMesh_ArrayKernelT<Double_traits> Open_mesh;
  Open_mesh mesh;
  Soup soup;
  void build(const Soup& s)
  {
    soup = s; // OpenMesh's points are not CGAL points: built by hand, in the soup's order
    std::vector<Open_mesh::VertexHandle> handles;
    for(const Point_3& p : soup.points)
      handles.push_back(mesh.add_vertex(Open_mesh::Point(p.x(), p.y(), p.z())));
    for(const auto& f : soup.faces)
    {
      std::vector<Open_mesh::VertexHandle> corners;
      for(std::size_t i : f) corners.push_back(handles[i]);
      ASSERT_TRUE(mesh.add_face(corners).is_valid());
    }
  }
  UVs texture(SMP::Texture_polygon_mesh_report& r) { return Graph_runs<Open_mesh>::texture(mesh, r); }
  UVs parameterize(SMP::Norm_preserving_report& r) { return Graph_runs<Open_mesh>::parameterize(mesh, r); }
};

// The mesh held as a Seam_mesh, the component of its first face cut to a disk by
// cut_to_disk: its soup is the cut mesh, one vertex per seam-mesh vertex, in the seam mesh's
// vertex order.
struct Seam_mesh_type
{
  typedef Mesh::Property_map<Mesh::Edge_index, bool> Seam_edges;
  typedef Mesh::Property_map<Mesh::Vertex_index, bool> Seam_vertices;
  typedef CGAL::Seam_mesh<Mesh, Seam_edges, Seam_vertices> Seam;
  typedef boost::graph_traits<Seam>::vertex_descriptor seam_vertex;
  Mesh underlying;
  std::unique_ptr<Seam> mesh;
  Soup soup;
  std::size_t seam_edges = 0;

  void build(const Soup& s)
  {
    build_graph(s, underlying);
    auto edges_map = underlying.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
    auto vertices_map = underlying.add_property_map<Mesh::Vertex_index, bool>("v:seam", false).first;
    mesh = std::make_unique<Seam>(underlying, edges_map, vertices_map);
    const auto result = SMP::cut_to_disk(*mesh, halfedge(*faces(underlying).begin(), underlying));
    ASSERT_EQ(result.status, SMP::OK) << result.message;
    seam_edges = result.seam_edges;
    std::map<seam_vertex, std::size_t> index;
    const auto ppmap = get(CGAL::vertex_point, *mesh);
    for(seam_vertex v : vertices(*mesh))
    {
      index.emplace(v, soup.points.size());
      soup.points.push_back(get(ppmap, v));
    }
    for(auto f : faces(*mesh))
    {
      soup.faces.emplace_back();
      for(seam_vertex v : CGAL::vertices_around_face(halfedge(f, *mesh), *mesh))
        soup.faces.back().push_back(index.at(v));
    }
  }
  UVs texture(SMP::Texture_polygon_mesh_report& r) { return Graph_runs<Seam>::texture(*mesh, r); }
  UVs parameterize(SMP::Norm_preserving_report& r) { return Graph_runs<Seam>::parameterize(*mesh, r); }
};

// A user's own type: plain vectors, no CGAL in sight.
struct Indexed_triangle_mesh
{
  std::vector<std::array<double, 3> > xyz;
  std::vector<std::array<int, 3> > triangles;
};

} // namespace

template <>
struct CGAL::Surface_mesh_parameterization::Indexed_mesh_traits<Indexed_triangle_mesh>
{
  static std::size_t number_of_vertices(const Indexed_triangle_mesh& m) { return m.xyz.size(); }
  static np_test::Point_3 point(const Indexed_triangle_mesh& m, std::size_t i) { return {m.xyz[i][0], m.xyz[i][1], m.xyz[i][2]}; }
  static std::size_t number_of_faces(const Indexed_triangle_mesh& m) { return m.triangles.size(); }
  static const std::array<int, 3>& face(const Indexed_triangle_mesh& m, std::size_t f) { return m.triangles[f]; }
};

namespace {

struct Indexed_mesh_type
{
  Indexed_triangle_mesh mesh;
  Soup soup;
  void build(const Soup& s)
  {
    soup = s;
    for(const Point_3& p : soup.points)
      mesh.xyz.push_back({p.x(), p.y(), p.z()});
    for(const auto& f : soup.faces)
      mesh.triangles.push_back({int(f[0]), int(f[1]), int(f[2])});
  }
  UVs texture(SMP::Texture_polygon_mesh_report& report)
  {
    std::vector<Point_2> uv(mesh.xyz.size(), Point_2(-1, -1));
    const SMP::Error_code status = SMP::texture_indexed_mesh(mesh, CGAL::make_property_map(uv), SMP::parameters::report(report));
    EXPECT_EQ(status, SMP::OK) << report.message;
    UVs result;
    for(const Point_2& p : uv) result.push_back({p.x(), p.y()});
    return result;
  }
};

template <typename Type>
class MeshTypes : public ::testing::Test
{ };

using Types = ::testing::Types<Surface_mesh_type, Polyhedron_type, OpenMesh_type, Seam_mesh_type, Indexed_mesh_type>;
class Type_names
{
public:
  template <typename T>
  static std::string GetName(int)
  {
    if(std::is_same<T, Surface_mesh_type>::value) return "Surface_mesh";
    if(std::is_same<T, Polyhedron_type>::value) return "Polyhedron_3";
    if(std::is_same<T, OpenMesh_type>::value) return "OpenMesh";
    if(std::is_same<T, Seam_mesh_type>::value) return "Seam_mesh";
    return "Indexed_mesh";
  }
};
TYPED_TEST_SUITE(MeshTypes, Types, Type_names);

// A disk, a closed genus-0 mesh, a genus-2 mesh, a mesh with holes, three components.
const char* const triangle_meshes[] = {"nefertiti", "cow", "eight", "holes", "blobby_3cc"};

void expect_same_bits(const UVs& expected, const UVs& actual, const std::string& what)
{
  ASSERT_EQ(expected.size(), actual.size()) << what;
  std::size_t different = 0;
  for(std::size_t i = 0; i < expected.size(); ++i)
    different += expected[i] != actual[i];
  EXPECT_EQ(different, 0u) << what << ": uvs that differ from the Surface_mesh built from the same soup";
}

// Not all at one point, and finite: the reference is a real map.
void expect_real_map(const UVs& uv, const std::string& what)
{
  double spread = 0;
  for(const auto& p : uv)
  {
    ASSERT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1])) << what;
    spread = (std::max)(spread, std::abs(p[0] - uv[0][0]) + std::abs(p[1] - uv[0][1]));
  }
  EXPECT_GT(spread, 0.1) << what;
}

// Holds `soup` as a `Type`, runs `run(held, report)` on it and on a Surface_mesh built from
// the held mesh's own soup, and expects the same uvs, bit for bit, and the same objective.
template <typename Type, typename Report, typename Run>
void expect_same_as_surface_mesh(const Soup& soup, const std::string& name, Run run)
{
  Type held;
  held.build(soup);
  Report report, reference_report;
  const UVs uv = run(held, report);
  Surface_mesh_type reference;
  reference.build(held.soup);
  const UVs expected = run(reference, reference_report);
  expect_real_map(expected, name);
  expect_same_bits(expected, uv, name);
  EXPECT_EQ(report.objective, reference_report.objective) << name;
}

const auto whole_mesh_call = [](auto& held, SMP::Texture_polygon_mesh_report& report) { return held.texture(report); };
const auto parameterizer_call = [](auto& held, SMP::Norm_preserving_report& report) { return held.parameterize(report); };

// The whole-mesh call: same uvs as on a Surface_mesh built from the type's own soup.
TYPED_TEST(MeshTypes, WholeMeshCallGivesTheSameBits)
{
  for(const char* name : triangle_meshes)
    expect_same_as_surface_mesh<TypeParam, SMP::Texture_polygon_mesh_report>(read_soup(name), name, whole_mesh_call);
}

// The CGAL graphs also take the parameterizer itself, and polygon faces.
template <typename Type>
class GraphMeshTypes : public ::testing::Test
{ };
using Graph_types = ::testing::Types<Surface_mesh_type, Polyhedron_type, OpenMesh_type, Seam_mesh_type>;
TYPED_TEST_SUITE(GraphMeshTypes, Graph_types, Type_names);

// The parameterizer on one component: same uvs, same objective.
TYPED_TEST(GraphMeshTypes, ParameterizerGivesTheSameBits)
{
  for(const char* name : triangle_meshes)
    expect_same_as_surface_mesh<TypeParam, SMP::Norm_preserving_report>(read_soup(name), name, parameterizer_call);
}

// Polygon faces (quads) through the whole-mesh call.
TYPED_TEST(GraphMeshTypes, PolygonMeshGivesTheSameBits)
{
  const Soup soup = read_soup("cube_quad");
  ASSERT_FALSE(is_triangle_soup(soup));
  expect_same_as_surface_mesh<TypeParam, SMP::Texture_polygon_mesh_report>(soup, "cube_quad", whole_mesh_call);
}

// The seam mesh is really cut: more vertices than the mesh, one border per component.
TEST(MeshTypesSeam, CutAddsSeamVertices)
{
  Seam_mesh_type held;
  const Soup soup = read_soup("eight");
  held.build(soup);
  EXPECT_GT(held.seam_edges, 0u);
  EXPECT_GT(held.soup.points.size(), soup.points.size());
  EXPECT_EQ(held.soup.faces.size(), soup.faces.size());
}

// The parameterizer numbers the component in the order of the vertex index map it is given: with
// the vertices' indices reversed, the uvs are those of the mesh built with its vertices in the
// reversed order, bit for bit, and (the order reaching the solve) not those of the mesh's own order.
TEST(VertexIndexMap, NumbersTheComponentInItsOrder)
{
  const Soup soup = read_soup("nefertiti");
  const std::size_t n = soup.points.size();
  Soup reversed;
  for(std::size_t k = 0; k < n; ++k)
    reversed.points.push_back(soup.points[n - 1 - k]);
  for(const auto& f : soup.faces)
  {
    reversed.faces.emplace_back();
    for(std::size_t i : f)
      reversed.faces.back().push_back(n - 1 - i);
  }
  Mesh mesh, reordered;
  build_graph(soup, mesh);
  build_graph(reversed, reordered);
  typedef Mesh::Vertex_index Vertex;
  const auto h = halfedge(*faces(mesh).begin(), mesh);
  const auto image = [&](Vertex v) { return Vertex(Mesh::size_type(n - 1 - std::size_t(v))); };
  const auto h_image = halfedge(image(source(h, mesh)), image(target(h, mesh)), reordered).first;

  const auto run = [](Mesh& m, Mesh::Halfedge_index bhd, auto index) {
    auto uv = m.add_property_map<Vertex, Point_2>("v:uv", Point_2(-1, -1)).first;
    auto marked = m.add_property_map<Vertex, bool>("v:marked", false).first;
    SMP::Norm_preserving_parameterizer_3<Mesh> parameterizer;
    EXPECT_EQ(parameterizer.parameterize(m, bhd, uv, index, marked), SMP::OK) << parameterizer.report().message;
    std::vector<Point_2> result;
    for(Vertex v : vertices(m))
      result.push_back(get(uv, v));
    m.remove_property_map(uv);
    m.remove_property_map(marked);
    return result;
  };
  auto reversed_index = mesh.add_property_map<Vertex, int>("v:reversed").first;
  for(Vertex v : vertices(mesh))
    put(reversed_index, v, int(n - 1 - std::size_t(v)));
  const std::vector<Point_2> by_map = run(mesh, h, reversed_index);
  const std::vector<Point_2> by_reordered_mesh = run(reordered, h_image, get(CGAL::vertex_index, reordered));
  const std::vector<Point_2> by_mesh_order = run(mesh, h, get(CGAL::vertex_index, mesh));
  std::size_t different = 0, moved = 0;
  for(std::size_t k = 0; k < n; ++k)
  {
    different += by_map[k] != by_reordered_mesh[n - 1 - k];
    moved += by_map[k] != by_mesh_order[k];
  }
  EXPECT_EQ(different, 0u);
  EXPECT_GT(moved, 0u) << "the order of the vertices does not reach the solve: the test cannot tell";
}

// CGAL::Sequential_tag keeps every loop of a call on the calling thread, and gives the same uvs
// as the default, bit for bit; so does the parameterizer's tag.
TEST(ConcurrencyTag, SequentialGivesTheSameBitsOnOneThread)
{
  Mesh mesh;
  build_graph(read_soup("cow"), mesh);
  typedef Mesh::Vertex_index Vertex;
  auto sequential_uv = mesh.add_property_map<Vertex, Point_2>("v:sequential").first;
  auto default_uv = mesh.add_property_map<Vertex, Point_2>("v:default").first;
  int threads = 0; // the most threads the call's work could use, seen from inside it
  const auto count_threads = [&threads](const SMP::Norm_preserving_progress&) {
#ifdef CGAL_LINKED_WITH_TBB
    threads = (std::max)(threads, tbb::this_task_arena::max_concurrency());
#else
    threads = 1;
#endif
    return true;
  };
  ASSERT_EQ(SMP::texture_polygon_mesh<CGAL::Sequential_tag>(mesh, sequential_uv, SMP::parameters::progress(count_threads)),
            SMP::OK);
  EXPECT_EQ(threads, 1);
  ASSERT_EQ(SMP::texture_polygon_mesh(mesh, default_uv), SMP::OK);
  for(Vertex v : vertices(mesh))
    ASSERT_EQ(get(sequential_uv, v), get(default_uv, v));

  const auto parameterize = [&mesh](auto& parameterizer, auto uv) {
    auto marked = mesh.add_property_map<Vertex, bool>("v:marked", false).first;
    EXPECT_EQ(parameterizer.parameterize(mesh, halfedge(*faces(mesh).begin(), mesh), uv,
                                         get(CGAL::vertex_index, mesh), marked), SMP::OK);
    mesh.remove_property_map(marked);
  };
  SMP::Norm_preserving_parameterizer_3<Mesh, CGAL::Default, CGAL::Default, CGAL::Sequential_tag> sequential;
  SMP::Norm_preserving_parameterizer_3<Mesh> parallel_if_available;
  parameterize(sequential, sequential_uv);
  parameterize(parallel_if_available, default_uv);
  for(Vertex v : vertices(mesh))
    ASSERT_EQ(get(sequential_uv, v), get(default_uv, v));
}

} // namespace
