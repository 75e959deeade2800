// The linear algebra under the ADMM: the two-column Cholesky factor of the free-vertex
// Laplacian (its orderings: Eigen's AMD, CHOLMOD's AMD or METIS, a level-set dissection; its
// split into parts solved on several threads; its solve by runs of columns) against Eigen's own
// factorizations, the Laplacian it factors, and the gather over each free vertex's edges.

#include "test_geometry.h"

#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Free_vertex_laplacian.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Level_set_dissection.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Two_column_cholesky.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <numeric>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
using np_test::component_geometry;
using np_test::Mesh;

// The ends of edge `e` fixed at (0, 0) and (1, 0).
std::array<SMP::internal::Norm_preserving::Fixed_vertex, 2> fixed_edge(const SMP::Norm_preserving_geometry& geometry,
                                                                       std::size_t e)
{
  namespace NP = SMP::internal::Norm_preserving;
  return {NP::Fixed_vertex{geometry.edges[e][0], {0., 0.}}, NP::Fixed_vertex{geometry.edges[e][1], {1., 0.}}};
}

// The free-vertex Laplacian of a mesh with its first edge's ends fixed, as the ADMM builds it.
SMP::internal::Norm_preserving::Sparse_matrix free_laplacian(const Mesh& mesh)
{
  namespace NP = SMP::internal::Norm_preserving;
  const SMP::Norm_preserving_geometry geometry = component_geometry(mesh);
  return NP::free_vertex_laplacian(geometry, NP::free_vertex_indices(geometry.points.size(), fixed_edge(geometry, 0)));
}

// Two right-hand sides for n unknowns: column c of row i is sin(0.37 (2 i + c)).
Eigen::MatrixXd two_right_hand_sides(Eigen::Index n)
{
  Eigen::MatrixXd b(n, 2);
  for(Eigen::Index i = 0; i < n; ++i)
    for(Eigen::Index c = 0; c < 2; ++c)
      b(i, c) = std::sin(0.37 * double(2 * i + c));
  return b;
}

// The two columns of `b` solved by the two-column solve (which takes them interleaved).
Eigen::MatrixXd two_column_solve(const SMP::internal::Norm_preserving::Two_column_cholesky& cholesky,
                                 const Eigen::MatrixXd& b)
{
  Eigen::MatrixXd x = b.transpose(); // column-major: x0 y0 x1 y1 ...
  std::vector<double> interleaved(x.data(), x.data() + x.size());
  cholesky.solve(interleaved);
  std::copy(interleaved.begin(), interleaved.end(), x.data());
  return x.transpose();
}

// The two-column solve, split into parts solved on several threads, matches Eigen's own
// LDL' solve of the same Laplacian; a small factor (nefertiti, 299 vertices) is not split,
// the factor of a few thousand vertices is (cow, AMD order).
TEST(TwoColumnCholesky, SolvesLikeEigenAndSplitsLargeFactors)
{
  namespace NP = SMP::internal::Norm_preserving;
  for(const std::string name : {"nefertiti", "cow", "bunny00"})
  {
    const NP::Sparse_matrix lower = free_laplacian(np_test::load_mesh(name));
    const std::size_t n = std::size_t(lower.rows());
    NP::Two_column_cholesky cholesky;
    ASSERT_TRUE(cholesky.compute(lower)) << name;
    if(name == "nefertiti")
    {
      EXPECT_EQ(cholesky.sequential_columns(), n);
    }
    else if(name == "cow")
    {
      EXPECT_LT(cholesky.sequential_columns(), n / 10) << "the factor of cow is split into parts";
    }
#ifdef CGAL_NORM_PRESERVING_USE_CHOLMOD // CHOLMOD's AMD ordering's tree; Eigen's may split worse
    else
    {
      EXPECT_LT(cholesky.sequential_columns(), n / 20) << "the factor of bunny00 is split into parts";
    }
#endif
    Eigen::SimplicialLDLT<NP::Sparse_matrix, Eigen::Lower> ldlt(lower);
    ASSERT_EQ(ldlt.info(), Eigen::Success);
    const Eigen::MatrixXd b = two_right_hand_sides(lower.rows()), x = ldlt.solve(b);
    EXPECT_LT((two_column_solve(cholesky, b) - x).cwiseAbs().maxCoeff(), 1e-9 * x.cwiseAbs().maxCoeff()) << name;
  }
}

// The free-vertex Laplacian, written in compressed form column by column, is the one Eigen
// assembles from a triplet per entry (the diagonal, the degree; -1 per edge between free
// vertices), its rows sorted in each column.
TEST(TwoColumnCholesky, LaplacianIsTheOneOfItsTriplets)
{
  namespace NP = SMP::internal::Norm_preserving;
  for(const std::string name : {"nefertiti", "cow"})
  {
    const SMP::Norm_preserving_geometry geometry = component_geometry(np_test::load_mesh(name));
    const std::array<NP::Fixed_vertex, 2> fixed = fixed_edge(geometry, 3);
    const std::vector<int> free_index = NP::free_vertex_indices(geometry.points.size(), fixed);
    const NP::Sparse_matrix lower = NP::free_vertex_laplacian(geometry, free_index);
    std::vector<Eigen::Triplet<double> > triplets;
    for(const auto& e : geometry.edges)
    {
      const int fi = free_index[e[0]], fj = free_index[e[1]];
      if(fi >= 0) triplets.emplace_back(fi, fi, 1.);
      if(fj >= 0) triplets.emplace_back(fj, fj, 1.);
      if(fi >= 0 && fj >= 0) triplets.emplace_back((std::max)(fi, fj), (std::min)(fi, fj), -1.);
    }
    NP::Sparse_matrix expected(lower.rows(), lower.cols());
    expected.setFromTriplets(triplets.begin(), triplets.end());
    ASSERT_TRUE(lower.isCompressed()) << name;
    ASSERT_EQ(lower.nonZeros(), expected.nonZeros()) << name;
    EXPECT_TRUE(std::equal(lower.outerIndexPtr(), lower.outerIndexPtr() + lower.cols() + 1, expected.outerIndexPtr())) << name;
    EXPECT_TRUE(std::equal(lower.innerIndexPtr(), lower.innerIndexPtr() + lower.nonZeros(), expected.innerIndexPtr())) << name;
    EXPECT_TRUE(std::equal(lower.valuePtr(), lower.valuePtr() + lower.nonZeros(), expected.valuePtr())) << name;
  }
}

// The gather over each free vertex's edges (Free_vertex_edges, the edge and its end packed in 32
// bits) is D' times the edge values: each edge's value added at its first end and subtracted at
// its second, in edge order (the same sums, to the bit), under any numbering of the free
// vertices (here the reverse of their order).
TEST(FreeVertexEdges, GatherIsTheTransposedIncidence)
{
  namespace NP = SMP::internal::Norm_preserving;
  for(const std::string name : {"nefertiti", "cow"})
  {
    const SMP::Norm_preserving_geometry geometry = component_geometry(np_test::load_mesh(name));
    const std::array<NP::Fixed_vertex, 2> fixed = fixed_edge(geometry, 5);
    std::vector<int> number = NP::free_vertex_indices(geometry.points.size(), fixed);
    const int free_count = int(geometry.points.size()) - 2;
    for(int& f : number)
      if(f >= 0) f = free_count - 1 - f;
    const std::size_t m = geometry.edges.size();
    std::vector<std::array<double, 2> > values(m);
    for(std::size_t e = 0; e < m; ++e)
      values[e] = {std::sin(0.37 * double(2 * e)), std::sin(0.37 * double(2 * e + 1))};
    std::vector<double> expected(2 * std::size_t(free_count), 0.);
    for(std::size_t e = 0; e < m; ++e)
      for(int c = 0; c < 2; ++c)
      {
        const int fi = number[geometry.edges[e][0]], fj = number[geometry.edges[e][1]];
        if(fi >= 0) expected[2 * std::size_t(fi) + std::size_t(c)] += values[e][std::size_t(c)];
        if(fj >= 0) expected[2 * std::size_t(fj) + std::size_t(c)] -= values[e][std::size_t(c)];
      }
    std::vector<double> gathered(expected.size());
    NP::gather_edge_values(NP::free_vertex_edges(geometry, number), values, gathered);
    EXPECT_EQ(gathered, expected) << name;
  }
}

// Below CHOLMOD's size the factor is in the order of Eigen's AMDOrdering (where AMD's tree does
// not split so unevenly that a dissection is tried), although AMD runs on a pattern written
// without Eigen's A' + A.
TEST(TwoColumnCholesky, OrdersLikeEigensAmd)
{
  namespace NP = SMP::internal::Norm_preserving;
  for(const std::string name : {"handle", "cow", "nefertiti", "elephant-with-holes"})
  {
    const NP::Sparse_matrix lower = free_laplacian(np_test::load_mesh(name));
    NP::Two_column_cholesky cholesky;
    ASSERT_TRUE(cholesky.compute(lower)) << name;
    const Eigen::SimplicialLLT<NP::Sparse_matrix, Eigen::Lower, Eigen::AMDOrdering<int> > llt(lower);
    ASSERT_EQ(llt.info(), Eigen::Success) << name;
    const int* expected = llt.permutationP().indices().data();
    EXPECT_TRUE(std::equal(cholesky.positions().begin(), cholesky.positions().end(), expected)) << name;
  }
}

// A right-hand side given in the factor's order (the ADMM's mesh step) is solved like Eigen's
// LDL' solve of the matrix, on the Eigen factor (cow, split into parts; nefertiti, all top, no
// slots) and, configured with CHOLMOD, on CHOLMOD's (bunny00); again in the same vector, whose
// tail the first solve filled.
TEST(TwoColumnCholesky, SolvesInItsOwnOrder)
{
  namespace NP = SMP::internal::Norm_preserving;
  for(const std::string name : {"cow", "bunny00", "nefertiti"})
  {
    const NP::Sparse_matrix lower = free_laplacian(np_test::load_mesh(name));
    const std::size_t n = std::size_t(lower.rows());
    NP::Two_column_cholesky cholesky;
    ASSERT_TRUE(cholesky.compute(lower)) << name;
    // Slots for the parts only where the factor is split (not nefertiti's, all top).
    const bool split = cholesky.sequential_columns() < n;
    EXPECT_EQ(split, name != "nefertiti") << name;
    EXPECT_EQ(cholesky.solve_size(), 2 * (n + (split ? 4 * cholesky.sequential_columns() : 0))) << name;
    Eigen::SimplicialLDLT<NP::Sparse_matrix, Eigen::Lower> ldlt(lower);
    ASSERT_EQ(ldlt.info(), Eigen::Success);
    std::vector<double> y;
    for(double scale : {1., -3.})
    {
      const Eigen::MatrixXd b = scale * two_right_hand_sides(lower.rows()), x = ldlt.solve(b);
      y.resize((std::max)(y.size(), 2 * n)); // the second time, longer: the tail is left as it was
      for(std::size_t i = 0; i < n; ++i)
        for(int c = 0; c < 2; ++c)
          y[2 * std::size_t(cholesky.positions()[i]) + std::size_t(c)] = b(Eigen::Index(i), c);
      cholesky.solve_in_order(y);
      double error = 0;
      for(std::size_t i = 0; i < n; ++i)
        for(int c = 0; c < 2; ++c)
          error = (std::max)(error, std::abs(y[2 * std::size_t(cholesky.positions()[i]) + std::size_t(c)] - x(Eigen::Index(i), c)));
      EXPECT_LT(error, 1e-9 * x.cwiseAbs().maxCoeff()) << name << " " << scale;
    }
  }
}

// Where AMD's elimination tree holds most of the factor in one subtree (blade: a solve's
// longest path holds about 90% of the factor), the factor is in a level-set dissection's
// order, whose parts are balanced; where AMD's tree splits well (lion), in AMD's order. Both
// solve to round-off.
TEST(TwoColumnCholesky, DissectsWhereAmdSplitsUnevenly)
{
  namespace NP = SMP::internal::Norm_preserving;
  for(const auto& [name, dissected] : {std::pair<std::string, bool>{"blade", true}, {"lion", false}})
  {
    const NP::Sparse_matrix lower = free_laplacian(np_test::load_mesh(name));
    const std::size_t n = std::size_t(lower.rows());
    ASSERT_LT(n, NP::Cholesky_settings::cholmod_minimum_rows) << name;
    const Eigen::SimplicialLLT<NP::Sparse_matrix, Eigen::Lower, Eigen::AMDOrdering<int> > amd(lower);
    const std::vector<int> amd_positions(amd.permutationP().indices().data(), amd.permutationP().indices().data() + n);
    NP::Two_column_cholesky cholesky;
    ASSERT_TRUE(cholesky.compute(lower)) << name;
    EXPECT_EQ(cholesky.positions() != amd_positions, dissected) << name;
    EXPECT_LT(cholesky.longest_path_share(), 0.6) << name;
    const Eigen::MatrixXd b = two_right_hand_sides(lower.rows());
    const Eigen::MatrixXd residual = lower.selfadjointView<Eigen::Lower>() * two_column_solve(cholesky, b) - b;
    EXPECT_LT(residual.cwiseAbs().maxCoeff(), 1e-10 * b.cwiseAbs().maxCoeff()) << name;
  }
}

// A dense matrix is one run of columns with the same rows: solved as one supernode (its
// triangle; no rows below it) as Eigen's LDL' solves it; a mesh Laplacian has runs too, with
// rows below them (their solve: SolvesLikeEigenAndSplitsLargeFactors).
TEST(TwoColumnCholesky, SolvesByRunsOfColumns)
{
  namespace NP = SMP::internal::Norm_preserving;
  const int n = 100;
  Eigen::MatrixXd dense(n, n);
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
      dense(i, j) = (i == j ? n : 0.) + std::cos(double(i + 1) * double(j + 1));
  dense = (dense * dense.transpose()).eval();
  NP::Sparse_matrix lower(n, n);
  std::vector<Eigen::Triplet<double> > entries;
  for(int j = 0; j < n; ++j)
    for(int i = j; i < n; ++i)
      entries.emplace_back(i, j, dense(i, j));
  lower.setFromTriplets(entries.begin(), entries.end());
  NP::Two_column_cholesky cholesky;
  ASSERT_TRUE(cholesky.compute(lower));
  EXPECT_EQ(cholesky.supernode_count(), 1u);
  const Eigen::MatrixXd b = two_right_hand_sides(n), x = dense.ldlt().solve(b);
  EXPECT_LT((two_column_solve(cholesky, b) - x).cwiseAbs().maxCoeff(), 1e-12 * x.cwiseAbs().maxCoeff());

  const NP::Sparse_matrix laplacian = free_laplacian(np_test::load_mesh("cow"));
  ASSERT_TRUE(cholesky.compute(laplacian));
  EXPECT_LT(cholesky.supernode_count(), std::size_t(laplacian.rows()) * 3 / 4);
}

// The lower triangle of the matrix of a grid of `side`^`dimensions` nodes with `diagonal` on
// the diagonal and -1 between neighbours. In 3D with 6.1 (the Laplacian plus 0.1 times the
// identity), a matrix that AMD fills with hundreds of entries a row (a mesh's Laplacian: 20-70).
SMP::internal::Norm_preserving::Sparse_matrix grid_matrix(int side, int dimensions, double diagonal)
{
  namespace NP = SMP::internal::Norm_preserving;
  int n = 1;
  for(int d = 0; d < dimensions; ++d)
    n *= side;
  std::vector<Eigen::Triplet<double> > triplets;
  for(int k = 0; k < n; ++k)
  {
    triplets.emplace_back(k, k, diagonal);
    for(int d = 0, stride = 1; d < dimensions; ++d, stride *= side)
      if(k / stride % side > 0)
        triplets.emplace_back(k, k - stride, -1.);
  }
  NP::Sparse_matrix lower(n, n);
  lower.setFromTriplets(triplets.begin(), triplets.end());
  return lower;
}

// A level-set dissection of a grid, and of two grids apart (a piece whose breadth-first
// search does not reach it all: there the separator is empty), is an order of every vertex
// whose separator (one level: the last vertices, as many as its clique's entries say) leaves
// two sides of at least 40% of the vertices that no edge joins: a search from the first
// vertex, around the separator, reaches one side only.
TEST(LevelSetDissection, SeparatesAndOrdersEveryVertex)
{
  namespace NP = SMP::internal::Norm_preserving;
  const NP::Sparse_matrix grid = grid_matrix(60, 2, 4.);
  NP::Sparse_matrix apart(2 * grid.rows(), 2 * grid.rows());
  std::vector<Eigen::Triplet<double> > blocks;
  for(int k = 0; k < grid.outerSize(); ++k)
    for(NP::Sparse_matrix::InnerIterator it(grid, k); it; ++it)
      for(int b = 0; b < 2; ++b)
        blocks.emplace_back(int(it.row()) + b * int(grid.rows()), int(it.col()) + b * int(grid.rows()), it.value());
  apart.setFromTriplets(blocks.begin(), blocks.end());
  for(const NP::Sparse_matrix& lower : {grid, apart})
  {
    const NP::Sparse_matrix pattern = lower.selfadjointView<Eigen::Lower>();
    const std::size_t n = std::size_t(pattern.rows());
    std::vector<int> identity(n);
    std::iota(identity.begin(), identity.end(), 0);
    const NP::Level_set_dissection::Result dissection = NP::Level_set_dissection::order(pattern, 1, identity);
    std::vector<int> sorted(dissection.order);
    std::sort(sorted.begin(), sorted.end());
    ASSERT_TRUE(sorted == identity) << n << " rows: not an order of every vertex";
    const std::size_t width = std::size_t(std::lround((std::sqrt(8 * dissection.separator_entries + 1) - 1) / 2));
    std::vector<char> reached(n, 0);
    for(std::size_t k = n - width; k < n; ++k)
      reached[std::size_t(dissection.order[k])] = 1; // the separator: never entered
    std::vector<int> queue(1, dissection.order[0]);
    reached[std::size_t(queue[0])] = 1;
    for(std::size_t h = 0; h < queue.size(); ++h)
      for(NP::Sparse_matrix::InnerIterator it(pattern, queue[h]); it; ++it)
        if(!reached[std::size_t(it.index())])
        {
          reached[std::size_t(it.index())] = 1;
          queue.push_back(int(it.index()));
        }
    EXPECT_GE(double(queue.size()), 0.4 * double(n)) << n << " rows";
    EXPECT_GE(double(n - width - queue.size()), 0.4 * double(n)) << n << " rows: the separator does not separate";
  }
}

// A matrix that is not positive definite is refused in Eigen's factorization too (below
// CHOLMOD's size, or in a build without CHOLMOD): a 100 x 100 grid with 3 on the diagonal.
TEST(TwoColumnCholesky, RefusesAnIndefiniteMatrixOfEigensSize)
{
  namespace NP = SMP::internal::Norm_preserving;
  const NP::Sparse_matrix indefinite = grid_matrix(100, 2, 3.);
  ASSERT_LT(std::size_t(indefinite.rows()), NP::Cholesky_settings::cholmod_minimum_rows);
  NP::Two_column_cholesky cholesky;
  EXPECT_FALSE(cholesky.compute(indefinite));
}

#ifdef CGAL_NORM_PRESERVING_USE_CHOLMOD
// CHOLMOD's analysis of `lower` by one ordering: the position of each unknown in its order,
// and the entries of its factor.
std::pair<std::vector<int>, double> cholmod_order(const SMP::internal::Norm_preserving::Sparse_matrix& lower,
                                                  int ordering)
{
  cholmod_common common;
  cholmod_start(&common);
  common.supernodal = ordering == CHOLMOD_METIS ? CHOLMOD_SUPERNODAL : CHOLMOD_SIMPLICIAL;
  common.nmethods = 1;
  common.method[0].ordering = ordering;
  cholmod_sparse view = Eigen::viewAsCholmod(lower.selfadjointView<Eigen::Lower>());
  cholmod_factor* factor = cholmod_analyze(&view, &common);
  EXPECT_NE(factor, nullptr);
  std::vector<int> position(std::size_t(lower.rows()));
  if(factor == nullptr)
    return {position, 0.};
  const int* permutation = static_cast<const int*>(factor->Perm);
  for(std::size_t k = 0; k < position.size(); ++k)
    position[std::size_t(permutation[k])] = int(k);
  const double entries = common.lnz;
  cholmod_free_factor(&factor, &common);
  cholmod_finish(&common);
  return {position, entries};
}

// Where CHOLMOD factors (from 25,000 rows), the factor is in AMD's order while AMD's factor
// has fewer than metis_fill_per_row entries a row (bunny00's Laplacian: 29), in METIS's order
// from there (a 30 x 30 x 30 grid: over 200); either solves its system (residual within 1e-10
// of the right-hand side; 4e-13 measured).
TEST(TwoColumnCholesky, OrdersByMetisOnlyWhereAmdFillsMuch)
{
  namespace NP = SMP::internal::Norm_preserving;
  const std::pair<NP::Sparse_matrix, bool> cases[] = {{free_laplacian(np_test::load_mesh("bunny00")), false},
                                                       {grid_matrix(30, 3, 6.1), true}};
  for(const auto& [lower, metis] : cases)
  {
    const std::size_t n = std::size_t(lower.rows());
    ASSERT_GE(n, NP::Cholesky_settings::cholmod_minimum_rows);
    const std::pair<std::vector<int>, double> amd = cholmod_order(lower, CHOLMOD_AMD);
    EXPECT_EQ(amd.second >= NP::Cholesky_settings::metis_fill_per_row * double(n), metis) << n << " rows";
    NP::Two_column_cholesky cholesky;
    ASSERT_TRUE(cholesky.compute(lower)) << n << " rows";
    EXPECT_TRUE(cholesky.positions() == (metis ? cholmod_order(lower, CHOLMOD_METIS).first : amd.first)) << n << " rows";
    const Eigen::MatrixXd b = two_right_hand_sides(lower.rows());
    const Eigen::MatrixXd residual = lower.selfadjointView<Eigen::Lower>() * two_column_solve(cholesky, b) - b;
    EXPECT_LT(residual.cwiseAbs().maxCoeff(), 1e-10 * b.cwiseAbs().maxCoeff()) << n << " rows";
  }
}

// A symmetric matrix that is not positive definite is refused in either order: a 200 x 200
// grid with 3 on the diagonal (eigenvalues from -1 to 7; AMD's order, 27 entries a row) and
// the 30 x 30 x 30 grid with 5 (from -1 to 11; METIS's order).
TEST(TwoColumnCholesky, RefusesAMatrixThatIsNotPositiveDefinite)
{
  namespace NP = SMP::internal::Norm_preserving;
  for(const NP::Sparse_matrix& indefinite : {grid_matrix(200, 2, 3.), grid_matrix(30, 3, 5.)})
  {
    ASSERT_GE(std::size_t(indefinite.rows()), NP::Cholesky_settings::cholmod_minimum_rows);
    NP::Two_column_cholesky cholesky;
    EXPECT_FALSE(cholesky.compute(indefinite)) << indefinite.rows() << " rows";
  }
}

// The METIS ordering runs under the package's lock (the race it prevents shows only now and
// then): a factorization started while the lock is held cannot finish until it is released.
// The matrix (a 30 x 30 x 30 grid) is one METIS orders; it factors in a fraction of a second.
TEST(Threads, TheMetisOrderingWaitsForTheLock)
{
  namespace NP = SMP::internal::Norm_preserving;
  const NP::Sparse_matrix lower = grid_matrix(30, 3, 6.1);
  std::atomic<bool> done(false), factored(false);
  std::unique_lock<std::mutex> held(NP::metis_mutex());
  std::thread worker([&] {
    NP::Two_column_cholesky cholesky;
    factored = cholesky.compute(lower);
    done = true;
  });
  for(int k = 0; k < 200 && !done; ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_FALSE(done) << "the analysis did not wait for the METIS lock";
  held.unlock();
  worker.join();
  EXPECT_TRUE(done);
  EXPECT_TRUE(factored);
}
#endif

} // namespace
