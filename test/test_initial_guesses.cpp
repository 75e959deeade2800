// The combination and graph-based initial guesses of Lai & Cheng (Sections 4.2 and 4.3): the
// interpolating B-spline, the depth-first chains, the guesses on real meshes, and the
// parameterizer run with each.

#include "test_meshes.h"

#include <CGAL/Surface_mesh_parameterization/Combination_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/Graph_based_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/Interior_point_quadratic_program_traits.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/XY_min_max_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Dfs_chains.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Mesh_component.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Uniform_cubic_bspline.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace NP = SMP::internal::Norm_preserving;
using np_test::Mesh;
using UV = std::array<double, 2>;
using Rotation = SMP::Combination_initial_guess::Rotation;

const double pi = CGAL_PI;

// The geometry a guess receives: the component of the first halfedge, loaded once per mesh.
const SMP::Norm_preserving_geometry& geometry_of(const std::string& name)
{
  static std::map<std::string, SMP::Norm_preserving_geometry> cache;
  auto found = cache.find(name);
  if(found == cache.end())
  {
    Mesh mesh = np_test::load_mesh(name);
    NP::Mesh_component<Mesh> component;
    std::string message;
    if(NP::extract_component(mesh, *halfedges(mesh).begin(), component, message) != SMP::OK)
      throw std::runtime_error(name + ": " + message);
    found = cache.emplace(name, component.geometry).first;
  }
  return found->second;
}

// A geometry given by its points and the edges {i, j} listed in any order.
SMP::Norm_preserving_geometry make_geometry(std::vector<std::array<double, 3> > points,
                                            std::vector<std::array<std::size_t, 2> > edges)
{
  for(auto& e : edges)
    if(e[0] > e[1]) std::swap(e[0], e[1]);
  std::sort(edges.begin(), edges.end());
  return {std::move(points), std::move(edges)};
}

// A straight polyline 0-1-2-...-(n-1) in 3D with the given distances from its first point.
SMP::Norm_preserving_geometry straight_polyline(const std::vector<double>& positions)
{
  std::vector<std::array<double, 3> > points;
  std::vector<std::array<std::size_t, 2> > edges;
  for(double s : positions)
    points.push_back({s, 2 * s, -3 * s});
  for(std::size_t i = 0; i + 1 < positions.size(); ++i)
    edges.push_back({i, i + 1});
  return make_geometry(points, edges);
}

template <typename Guess>
SMP::Error_code run_guess(const Guess& guess, const SMP::Norm_preserving_geometry& geometry,
                          std::vector<UV>& uv, std::string& message)
{
  message.clear();
  return guess(geometry, uv, message);
}

// --- The interpolating uniform cubic B-spline ------------------------------------------------

template <typename Curve>
std::vector<UV> sample_at_knots(std::size_t n, Curve curve)
{
  std::vector<UV> data(n);
  for(std::size_t k = 0; k < n; ++k)
    data[k] = curve(double(k) / double(n - 1));
  return data;
}

TEST(UniformCubicBSpline, PassesThroughItsDataPoints)
{
  for(std::size_t n : {4, 5, 6, 7, 10, 101})
  {
    // Rough data, far from any polynomial.
    const std::vector<UV> data = sample_at_knots(n, [n](double t) {
      const double k = t * double(n - 1);
      return UV{3 * std::sin(1.7 * k * k), std::cos(0.9 * k) - 0.01 * k};
    });
    const NP::Uniform_cubic_bspline f(data);
    for(std::size_t k = 0; k < n; ++k)
    {
      const UV p = f(double(k) / double(n - 1));
      EXPECT_NEAR(p[0], data[k][0], 1e-12) << "n = " << n << ", k = " << k;
      EXPECT_NEAR(p[1], data[k][1], 1e-12) << "n = " << n << ", k = " << k;
    }
  }
}

TEST(UniformCubicBSpline, ReproducesAStraightLine)
{
  const auto line = [](double t) { return UV{0.25 - 3 * t, 7 + 0.5 * t}; };
  for(std::size_t n : {4, 5, 13})
  {
    const NP::Uniform_cubic_bspline f(sample_at_knots(n, line));
    for(int i = 0; i <= 1000; ++i)
    {
      const double t = i / 1000.;
      EXPECT_NEAR(f(t)[0], line(t)[0], 1e-12);
      EXPECT_NEAR(f(t)[1], line(t)[1], 1e-12);
    }
  }
}

// Not-a-knot ends: a cubic polynomial is its own interpolant (natural ends would bend it).
TEST(UniformCubicBSpline, ReproducesACubicWithNotAKnotEnds)
{
  const auto cubic = [](double t) { return UV{1 - 2 * t + 5 * t * t * t, t * t - 4 * t * t * t}; };
  for(std::size_t n : {4, 5, 9, 50})
  {
    const NP::Uniform_cubic_bspline f(sample_at_knots(n, cubic));
    for(int i = 0; i <= 1000; ++i)
    {
      const double t = i / 1000.;
      EXPECT_NEAR(f(t)[0], cubic(t)[0], 1e-12) << "n = " << n << ", t = " << t;
      EXPECT_NEAR(f(t)[1], cubic(t)[1], 1e-12) << "n = " << n << ", t = " << t;
    }
  }
}

// --- The depth-first search and its chains ---------------------------------------------------

class DfsChainsOnRealMesh : public ::testing::TestWithParam<std::string>
{
protected:
  void SetUp() override
  {
    geometry = &geometry_of(GetParam());
    result = NP::dfs_chains(*geometry);
    const std::size_t n = geometry->points.size();
    position.assign(n, 0);
    for(std::size_t k = 0; k < result.order.size(); ++k)
      position[result.order[k]] = k;
    neighbours.assign(n, {});
    for(const auto& e : geometry->edges)
    {
      neighbours[e[0]].push_back(e[1]);
      neighbours[e[1]].push_back(e[0]);
    }
    // Subtree sizes: a vertex's descendants are the next subtree_size - 1 in discovery order.
    subtree_size.assign(n, 1);
    for(std::size_t k = n; k-- > 1;)
      subtree_size[result.parent[result.order[k]]] += subtree_size[result.order[k]];
  }

  bool is_ancestor(std::size_t a, std::size_t d) const
  {
    return position[a] <= position[d] && position[d] < position[a] + subtree_size[a];
  }

  // Longer first, then lower index: the order in which the search must take edges from `v`.
  bool before(std::size_t v, std::size_t a, std::size_t b) const
  {
    const double la = NP::squared_euclidean_distance(geometry->points[v], geometry->points[a]);
    const double lb = NP::squared_euclidean_distance(geometry->points[v], geometry->points[b]);
    return la > lb || (la == lb && a < b);
  }

  const SMP::Norm_preserving_geometry* geometry = nullptr;
  NP::Dfs_chains result;
  std::vector<std::size_t> position, subtree_size;
  std::vector<std::vector<std::size_t> > neighbours;
};

TEST_P(DfsChainsOnRealMesh, StartsAtTheVertexOfSmallestXAndVisitsEveryVertexOnce)
{
  const auto& points = geometry->points;
  ASSERT_EQ(result.order.size(), points.size());
  std::vector<std::size_t> sorted = result.order;
  std::sort(sorted.begin(), sorted.end());
  for(std::size_t i = 0; i < sorted.size(); ++i)
    ASSERT_EQ(sorted[i], i);
  const std::size_t root = result.order[0];
  EXPECT_EQ(result.parent[root], root);
  for(std::size_t i = 0; i < points.size(); ++i)
    EXPECT_TRUE(points[root][0] < points[i][0] || (points[root][0] == points[i][0] && root <= i)) << i;
}

TEST_P(DfsChainsOnRealMesh, IsADepthFirstSearchTree)
{
  for(std::size_t k = 1; k < result.order.size(); ++k)
  {
    const std::size_t v = result.order[k], p = result.parent[v];
    ASSERT_NE(p, v) << "a second root in a connected component";
    ASSERT_TRUE(std::find(neighbours[v].begin(), neighbours[v].end(), p) != neighbours[v].end());
    ASSERT_LT(position[p], position[v]);
  }
  // In a depth-first search of an undirected graph every edge joins an ancestor and a descendant.
  for(const auto& e : geometry->edges)
    ASSERT_TRUE(is_ancestor(e[0], e[1]) || is_ancestor(e[1], e[0])) << e[0] << " " << e[1];
}

TEST_P(DfsChainsOnRealMesh, TakesTheLongestEdgeFirst)
{
  std::vector<std::vector<std::size_t> > children(geometry->points.size());
  for(std::size_t k = 1; k < result.order.size(); ++k)
    children[result.parent[result.order[k]]].push_back(result.order[k]);
  std::size_t branching = 0;
  for(std::size_t v = 0; v < children.size(); ++v)
  {
    // The first child is the longest edge to a vertex not yet discovered when v was.
    std::size_t longest = v;
    for(std::size_t w : neighbours[v])
      if(position[w] > position[v] && (longest == v || before(v, w, longest)))
        longest = w;
    if(children[v].empty())
    {
      ASSERT_EQ(longest, v) << "leaf " << v << " has an undiscovered neighbour";
      continue;
    }
    ASSERT_EQ(children[v][0], longest) << "vertex " << v;
    // Later children were taken in the same order.
    for(std::size_t c = 1; c < children[v].size(); ++c)
      ASSERT_TRUE(before(v, children[v][c - 1], children[v][c])) << "vertex " << v;
    branching += children[v].size() > 1;
  }
  EXPECT_GT(branching, 0u) << "the order of later children was never checked";
}

TEST_P(DfsChainsOnRealMesh, EveryVertexIsNewInExactlyOneChain)
{
  const std::size_t n = geometry->points.size();
  std::vector<int> listed(n, 0);
  ASSERT_FALSE(result.chains.empty());
  for(std::size_t c = 0; c < result.chains.size(); ++c)
  {
    const auto& chain = result.chains[c];
    const std::size_t first_new = (c == 0 ? 0 : 1);
    const bool closed = c > 0 && chain.size() > 2 && listed[chain.back()] > 0;
    for(std::size_t k = first_new; k + (closed ? 1 : 0) < chain.size(); ++k)
      ++listed[chain[k]];
  }
  for(std::size_t i = 0; i < n; ++i)
    ASSERT_EQ(listed[i], 1) << "vertex " << i;
}

TEST_P(DfsChainsOnRealMesh, FollowsFirstChildrenFromTheRootOrABranchingVertex)
{
  std::vector<bool> has_child(geometry->points.size(), false);
  for(std::size_t k = 1; k < result.order.size(); ++k)
    has_child[result.parent[result.order[k]]] = true;
  std::vector<bool> listed(geometry->points.size(), false);
  for(std::size_t c = 0; c < result.chains.size(); ++c)
  {
    const auto& chain = result.chains[c];
    const std::size_t last_new = (c > 0 && chain.size() > 2 && listed[chain.back()]) ? chain.size() - 2
                                                                                     : chain.size() - 1;
    if(c == 0)
    {
      ASSERT_EQ(chain[0], result.order[0]) << "the primary list starts at the root";
    }
    for(std::size_t k = 1; k <= last_new; ++k)
    {
      ASSERT_EQ(result.parent[chain[k]], chain[k - 1]);
      // The first new vertex of a later chain is a later child; below it come first children.
      const std::size_t next = position[chain[k - 1]] + 1;
      ASSERT_EQ(result.order[next] == chain[k], c == 0 || k > 1);
    }
    ASSERT_FALSE(has_child[chain[last_new]]) << "chain " << c << " stops before a leaf";
    for(std::size_t k = (c == 0 ? 0 : 1); k <= last_new; ++k)
      listed[chain[k]] = true;
  }
}

// Both ends of a later chain are already placed: its branching vertex, and the far end of
// the leaf's longest edge to an earlier chain (other than its parent) when it has one.
TEST_P(DfsChainsOnRealMesh, LaterChainsStartAndEndAtListedVertices)
{
  std::vector<bool> listed(geometry->points.size(), false);
  for(std::size_t v : result.chains[0])
    listed[v] = true;
  std::size_t closed = 0, open = 0;
  for(std::size_t c = 1; c < result.chains.size(); ++c)
  {
    const auto& chain = result.chains[c];
    ASSERT_GE(chain.size(), 2u);
    ASSERT_TRUE(listed[chain.front()]) << "chain " << c << " starts at an unplaced vertex";
    const bool is_closed = chain.size() > 2 && listed[chain.back()];
    const std::size_t leaf = is_closed ? chain[chain.size() - 2] : chain.back();
    std::size_t expected = leaf;
    for(std::size_t w : neighbours[leaf])
      if(listed[w] && w != result.parent[leaf] && (expected == leaf || before(leaf, w, expected)))
        expected = w;
    if(is_closed)
    {
      ++closed;
      ASSERT_EQ(chain.back(), expected) << "chain " << c;
    }
    else
    {
      ++open;
      ASSERT_EQ(expected, leaf) << "chain " << c << " could have been closed";
    }
    for(std::size_t v : chain)
      listed[v] = true;
  }
  EXPECT_GT(closed, open) << "most later chains should be closed by a back edge";
}

INSTANTIATE_TEST_SUITE_P(Suite, DfsChainsOnRealMesh,
  ::testing::Values("nefertiti", "cow", "knot1", "eight", "holes"));

TEST(DfsChains, DisconnectedGeometryGetsOneRootPerComponent)
{
  // Two triangles: {0, 2, 4} and {1, 3, 5}; vertex 4 has the smallest x.
  const auto g = make_geometry({{1, 0, 0}, {5, 0, 0}, {2, 1, 0}, {6, 1, 0}, {0, 2, 0}, {7, 0, 1}},
                               {{0, 2}, {2, 4}, {0, 4}, {1, 3}, {3, 5}, {1, 5}});
  const NP::Dfs_chains result = NP::dfs_chains(g);
  ASSERT_EQ(result.order.size(), 6u);
  EXPECT_EQ(result.order[0], 4u);
  EXPECT_EQ(result.order[3], 1u); // the lowest index of the other component
  std::size_t roots = 0;
  for(std::size_t v = 0; v < 6; ++v)
    roots += result.parent[v] == v;
  EXPECT_EQ(roots, 2u);
  ASSERT_EQ(result.chains.size(), 2u);
  EXPECT_EQ(result.chains[0].size(), 3u);
  EXPECT_EQ(result.chains[1].size(), 3u);
}

// --- The guesses on real meshes ---------------------------------------------------------------

class GuessOnRealMesh : public ::testing::TestWithParam<std::string> { };

template <typename Guess>
void expect_finite_value_for_every_vertex(const Guess& guess, const std::string& name)
{
  const auto& geometry = geometry_of(name);
  std::vector<UV> uv;
  std::string message;
  ASSERT_EQ(run_guess(guess, geometry, uv, message), SMP::OK) << message;
  ASSERT_EQ(uv.size(), geometry.points.size());
  for(std::size_t i = 0; i < uv.size(); ++i)
    ASSERT_TRUE(std::isfinite(uv[i][0]) && std::isfinite(uv[i][1])) << "vertex " << i;
}

TEST_P(GuessOnRealMesh, GraphBasedGuessGivesEveryVertexAFiniteValue)
{
  expect_finite_value_for_every_vertex(SMP::Graph_based_initial_guess(), GetParam());
}

TEST_P(GuessOnRealMesh, CombinationGuessGivesEveryVertexAFiniteValue)
{
  expect_finite_value_for_every_vertex(SMP::Combination_initial_guess(), GetParam());
  expect_finite_value_for_every_vertex(SMP::Combination_initial_guess(SMP::Combination_initial_guess::default_rotations(), 1.),
                                       GetParam());
  expect_finite_value_for_every_vertex(SMP::Combination_initial_guess({}, 1.), GetParam());
}

INSTANTIATE_TEST_SUITE_P(Suite, GuessOnRealMesh,
  ::testing::Values("nefertiti", "cow", "camel", "knot1", "eight", "elephant", "holes", "lion", "mushroom"));

template <typename Guess>
void expect_deterministic(const Guess& guess, const std::string& name)
{
  std::vector<UV> first, second;
  std::string message;
  ASSERT_EQ(run_guess(guess, geometry_of(name), first, message), SMP::OK) << message;
  ASSERT_EQ(run_guess(guess, geometry_of(name), second, message), SMP::OK) << message;
  ASSERT_EQ(first.size(), second.size());
  for(std::size_t i = 0; i < first.size(); ++i)
    ASSERT_TRUE(first[i] == second[i]) << "vertex " << i; // bit for bit: exact comparison
}

TEST(GraphBasedGuess, IsDeterministic)
{
  expect_deterministic(SMP::Graph_based_initial_guess(), "camel");
}

TEST(CombinationGuess, IsDeterministic)
{
  expect_deterministic(SMP::Combination_initial_guess(), "camel");
}

// --- The graph-based guess --------------------------------------------------------------------

// The spline resets only chain interiors: the ends of open chains keep their XY-MinMax value
// exactly, and interiors move.
TEST(GraphBasedGuess, ResetsOnlyChainInteriors)
{
  const auto& geometry = geometry_of("cow");
  std::vector<UV> xy, graph;
  std::string message;
  ASSERT_EQ(run_guess(SMP::XY_min_max_initial_guess(), geometry, xy, message), SMP::OK);
  ASSERT_EQ(run_guess(SMP::Graph_based_initial_guess(), geometry, graph, message), SMP::OK);
  const NP::Dfs_chains result = NP::dfs_chains(geometry);
  std::vector<bool> interior(geometry.points.size(), false);
  for(const auto& chain : result.chains)
    for(std::size_t k = 1; k + 1 < chain.size(); ++k)
      interior[chain[k]] = true;
  std::size_t moved = 0;
  for(std::size_t i = 0; i < xy.size(); ++i)
  {
    if(!interior[i])
    {
      ASSERT_TRUE(graph[i] == xy[i]) << "vertex " << i << " is no chain interior but moved";
    }
    else
      moved += !(graph[i] == xy[i]);
  }
  EXPECT_GT(moved, xy.size() / 2);
}

// On an evenly spaced straight polyline the path length is the uniform parameter and the
// XY-MinMax values lie on a line, which the spline reproduces: the guess is XY-MinMax.
TEST(GraphBasedGuess, IsXYMinMaxOnAnEvenlySpacedStraightPolyline)
{
  for(std::size_t n : {3, 4, 9})
  {
    std::vector<double> positions;
    for(std::size_t k = 0; k < n; ++k)
      positions.push_back(0.5 * double(k));
    const auto geometry = straight_polyline(positions);
    std::vector<UV> xy, graph;
    std::string message;
    ASSERT_EQ(run_guess(SMP::XY_min_max_initial_guess(), geometry, xy, message), SMP::OK);
    ASSERT_EQ(run_guess(SMP::Graph_based_initial_guess(), geometry, graph, message), SMP::OK) << message;
    for(std::size_t i = 0; i < n; ++i)
    {
      EXPECT_NEAR(graph[i][0], xy[i][0], 1e-12);
      EXPECT_NEAR(graph[i][1], xy[i][1], 1e-12);
    }
  }
}

// On an unevenly spaced polyline, vertex i moves to f(L_i / L_n): with three points, f is the
// linear interpolant through the values at t = 0, 1/2, 1.
TEST(GraphBasedGuess, PlacesAShortChainByPathLength)
{
  const auto geometry = straight_polyline({0., 1., 4.});
  std::vector<UV> graph;
  std::string message;
  ASSERT_EQ(run_guess(SMP::Graph_based_initial_guess(), geometry, graph, message), SMP::OK) << message;
  // Values 0, 1/4, 1 at t = 0, 1/2, 1; L_1 / L_2 = 1/4, so f(1/4) = 1/8.
  EXPECT_NEAR(graph[1][0], 0.125, 1e-15);
  EXPECT_NEAR(graph[1][1], 0.125, 1e-15);
  EXPECT_EQ(graph[0], (UV{0., 0.}));
  EXPECT_EQ(graph[2], (UV{1., 1.}));
}

TEST(GraphBasedGuess, TakesZLikeXYMinMaxWhenAllVerticesShareAnXOrAY)
{
  for(int axis = 0; axis < 2; ++axis)
  {
    std::vector<std::array<double, 3> > points = {{0, 0, 0}, {1, 1, 0}, {2, 0, 1}};
    for(auto& p : points) p[axis] = 3.;
    const auto geometry = make_geometry(points, {{0, 1}, {1, 2}, {0, 2}});
    std::vector<UV> xy, graph;
    std::string xy_message, graph_message;
    ASSERT_EQ(run_guess(SMP::XY_min_max_initial_guess(), geometry, xy, xy_message), SMP::OK) << xy_message;
    // z in place of the degenerate axis: the third vertex, alone at z = 1, is at 1.
    EXPECT_EQ(xy[2][axis], 1.);
    EXPECT_EQ(xy[0][axis], 0.);
    ASSERT_EQ(run_guess(SMP::Graph_based_initial_guess(), geometry, graph, graph_message), SMP::OK) << graph_message;
  }
}

// --- The combination guess --------------------------------------------------------------------

void expect_wrong_parameter(const SMP::Combination_initial_guess& guess, const std::string& words)
{
  std::string message;
  EXPECT_EQ(guess.validate(message), SMP::ERROR_WRONG_PARAMETER) << words;
  EXPECT_NE(message.find(words), std::string::npos) << message;
  std::vector<UV> uv;
  EXPECT_EQ(run_guess(guess, geometry_of("nefertiti"), uv, message), SMP::ERROR_WRONG_PARAMETER) << words;
  EXPECT_NE(message.find(words), std::string::npos) << message;
  EXPECT_TRUE(uv.empty());
}

TEST(CombinationGuess, RejectsSymmetricRotations)
{
  const std::array<double, 3> x = {1, 0, 0}, minus_x = {-2, 0, 0}, y = {0, 1, 0};
  // Same axis, opposite angles; opposite axes, same angle; opposite angles written differently.
  expect_wrong_parameter(SMP::Combination_initial_guess({{x, 0.3, 1.}, {x, -0.3, 1.}}), "cancel");
  expect_wrong_parameter(SMP::Combination_initial_guess({{x, 0.3, 1.}, {minus_x, 0.3, 1.}}), "cancel");
  expect_wrong_parameter(SMP::Combination_initial_guess({{y, 0.5, 2.}, {x, 1.1, 1.}, {y, 2 * pi - 0.5, 2.}}, 0.),
                         "rotations 0 and 2");
}

TEST(CombinationGuess, AcceptsRotationsThatDoNotCancel)
{
  const std::array<double, 3> x = {1, 0, 0};
  std::string message;
  for(const auto& rotations : {std::vector<Rotation>{{x, 0.3, 1.}, {x, -0.3, 2.}},  // unequal weights
                               std::vector<Rotation>{{x, 0.3, 1.}, {x, 0.4, 1.}},   // not opposite
                               std::vector<Rotation>{{x, pi, 1.}, {x, pi, 1.}},     // each its own inverse
                               std::vector<Rotation>{{x, 0.3, 0.}, {x, -0.3, 0.}, {x, 1., 1.}}}) // weight 0
  {
    const SMP::Combination_initial_guess guess(rotations, 0.);
    EXPECT_EQ(guess.validate(message), SMP::OK) << message;
  }
  EXPECT_EQ(SMP::Combination_initial_guess().validate(message), SMP::OK) << message;
}

TEST(CombinationGuess, RejectsInvalidParameters)
{
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const std::array<double, 3> x = {1, 0, 0};
  expect_wrong_parameter(SMP::Combination_initial_guess({}, 0.), "no rotation");
  expect_wrong_parameter(SMP::Combination_initial_guess({{x, 0.3, 0.}, {x, 0.7, 0.}}, 0.), "all weights are zero");
  expect_wrong_parameter(SMP::Combination_initial_guess({{{0, 0, 0}, 0.3, 1.}}), "zero axis");
  expect_wrong_parameter(SMP::Combination_initial_guess({{x, nan, 1.}}), "non-finite");
  expect_wrong_parameter(SMP::Combination_initial_guess({{{inf, 0, 0}, 0.3, 1.}}), "non-finite");
  expect_wrong_parameter(SMP::Combination_initial_guess({{x, 0.3, inf}}), "non-finite");
  expect_wrong_parameter(SMP::Combination_initial_guess({{x, 0.3, -1.}}), "negative weight");
  expect_wrong_parameter(SMP::Combination_initial_guess({{x, 0.3, 1.}}, nan), "sphere weight");
  expect_wrong_parameter(SMP::Combination_initial_guess({{x, 0.3, 1.}}, -1.), "sphere weight");
}

TEST(CombinationGuess, OneUnrotatedCopyIsXYMinMax)
{
  const auto& geometry = geometry_of("cow");
  std::vector<UV> xy, combined;
  std::string message;
  ASSERT_EQ(run_guess(SMP::XY_min_max_initial_guess(), geometry, xy, message), SMP::OK);
  ASSERT_EQ(run_guess(SMP::Combination_initial_guess({{{0, 0, 1}, 0., 1.}}, 0.), geometry, combined, message), SMP::OK);
  ASSERT_EQ(combined.size(), xy.size());
  for(std::size_t i = 0; i < xy.size(); ++i)
    ASSERT_TRUE(combined[i] == xy[i]) << "vertex " << i;
}

// S(u, v) about the centroid, scaled to [0,1]^2: u / (2 pi) and v / pi + 1/2.
TEST(CombinationGuess, SphereMapTakesTheAnglesAboutTheCentroid)
{
  const std::array<double, 3> c = {1, 2, 3};
  std::vector<std::array<double, 3> > points = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for(auto& p : points)
    for(int k = 0; k < 3; ++k) p[k] += c[k];
  const auto geometry = make_geometry(points, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 0}, {5, 0}});
  std::vector<UV> uv;
  std::string message;
  ASSERT_EQ(run_guess(SMP::Combination_initial_guess({}, 1.), geometry, uv, message), SMP::OK) << message;
  const std::vector<UV> expected = {{0., 0.5}, {0.25, 0.5}, {0.5, 0.5}, {0.75, 0.5}, {0., 1.}, {0., 0.}};
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    EXPECT_NEAR(uv[i][0], expected[i][0], 1e-15) << "vertex " << i;
    EXPECT_NEAR(uv[i][1], expected[i][1], 1e-15) << "vertex " << i;
  }
}

// Points on the z axis: rotated about x or y they keep zero extent in x or y, so those copies
// are left out; rotated about (1, 1, 0) they do not.
TEST(CombinationGuess, LeavesOutRotatedCopiesWithZeroExtent)
{
  const auto geometry = make_geometry({{0, 0, 0}, {0, 0, 1}, {0, 0, 3}}, {{0, 1}, {1, 2}});
  const Rotation about_x{{1, 0, 0}, 0.3, 1.}, about_y{{0, 1, 0}, 0.7, 1.}, diagonal{{1, 1, 0}, 0.5, 2.};
  std::vector<UV> all, alone;
  std::string message;
  ASSERT_EQ(run_guess(SMP::Combination_initial_guess({about_x, diagonal, about_y}, 0.), geometry, all, message), SMP::OK)
    << message;
  ASSERT_EQ(run_guess(SMP::Combination_initial_guess({diagonal}, 0.), geometry, alone, message), SMP::OK);
  for(std::size_t i = 0; i < all.size(); ++i)
    EXPECT_TRUE(all[i] == alone[i]) << "vertex " << i;

  EXPECT_EQ(run_guess(SMP::Combination_initial_guess({about_x, about_y}, 0.), geometry, all, message),
            SMP::ERROR_WRONG_PARAMETER);
  EXPECT_NE(message.find("zero extent"), std::string::npos) << message;
  EXPECT_EQ(run_guess(SMP::Combination_initial_guess({about_x, about_y}, 1.), geometry, all, message), SMP::OK)
    << message;
}

// --- The parameterizer with each guess --------------------------------------------------------

template <typename Guess>
void expect_parameterizes_and_improves_on_the_guess(const std::string& name)
{
  using Parameterizer = SMP::Norm_preserving_parameterizer_3<Mesh, Guess>;
  using Vertex = Mesh::Vertex_index;
  std::vector<std::vector<np_test::Point_2> > runs;
  for(int run = 0; run < 2; ++run)
  {
    Mesh mesh = np_test::load_mesh(name);
    auto uv = mesh.add_property_map<Vertex, np_test::Point_2>("v:uv").first;
    auto marked = mesh.add_property_map<Vertex, bool>("v:marked", false).first;
    Parameterizer parameterizer;
    parameterizer.set_texture_fit(SMP::NORM_PRESERVING_NO_FIT);
    const SMP::Error_code status =
      parameterizer.parameterize(mesh, *halfedges(mesh).begin(), uv, get(CGAL::vertex_index, mesh), marked);
    ASSERT_EQ(status, SMP::OK) << name << ": " << parameterizer.report().message;
    EXPECT_LE(parameterizer.report().objective, parameterizer.report().initial_objective) << name;
    runs.emplace_back();
    for(Vertex v : vertices(mesh))
    {
      ASSERT_TRUE(get(marked, v));
      runs.back().push_back(get(uv, v));
    }
  }
  EXPECT_TRUE(runs[0] == runs[1]) << name << ": two runs differ";
}

// The solution, not the guess: the default solver within 1e-4 of the exact (interior-point)
// optimum, with the same guess and signs (eight: genus 2, small enough for the exact solver).
template <typename Guess>
void expect_the_exact_optimum(const std::string& name)
{
  auto objective = [&name](auto parameterizer) {
    Mesh mesh = np_test::load_mesh(name);
    auto uv = mesh.add_property_map<Mesh::Vertex_index, np_test::Point_2>("v:uv").first;
    auto marked = mesh.add_property_map<Mesh::Vertex_index, bool>("v:marked", false).first;
    const SMP::Error_code status =
      parameterizer.parameterize(mesh, *halfedges(mesh).begin(), uv, get(CGAL::vertex_index, mesh), marked);
    EXPECT_EQ(status, SMP::OK) << name << ": " << parameterizer.report().message;
    return parameterizer.report().objective;
  };
  const double admm = objective(SMP::Norm_preserving_parameterizer_3<Mesh, Guess>());
  const double exact =
    objective(SMP::Norm_preserving_parameterizer_3<Mesh, Guess, SMP::Interior_point_quadratic_program_traits<> >());
  EXPECT_GE(admm, exact * (1 - 1e-9)) << name;
  EXPECT_LE(admm, exact * (1 + 1e-4)) << name;
}

TEST(GraphBasedGuess, DefaultSolverReachesTheExactOptimum) { expect_the_exact_optimum<SMP::Graph_based_initial_guess>("eight"); }

TEST(CombinationGuess, DefaultSolverReachesTheExactOptimum) { expect_the_exact_optimum<SMP::Combination_initial_guess>("eight"); }

TEST(GraphBasedGuess, ParameterizerSolvesCowAndKnot1)
{
  for(const std::string name : {"cow", "knot1"})
    expect_parameterizes_and_improves_on_the_guess<SMP::Graph_based_initial_guess>(name);
}

TEST(CombinationGuess, ParameterizerSolvesCowAndKnot1)
{
  for(const std::string name : {"cow", "knot1"})
    expect_parameterizes_and_improves_on_the_guess<SMP::Combination_initial_guess>(name);
}

} // namespace
