// Concepts of the package, for Doxygen only: never compiled.

namespace CGAL {
namespace Surface_mesh_parameterization {

/*!
\ingroup PkgNormPreservingParameterizationConcepts
\cgalConcept

An initial guess of `Norm_preserving_parameterizer_3`: gives every vertex of a component a uv,
whose order along `u` and along `v` on each edge fixes the signs of the QP (Eq. 5). Only that
order matters: the guess is then moved by a similarity transform onto the fixed pair.

\cgalHasModel `XY_min_max_initial_guess`, `Combination_initial_guess`, `Graph_based_initial_guess`

Checked at compile time by `concepts::NormPreservingInitialGuess`.
*/
class NormPreservingInitialGuess
{
public:
  /// copy constructor: the parameterizer keeps its own copy.
  NormPreservingInitialGuess(const NormPreservingInitialGuess&);

  /// resizes `uv` to `geometry.points.size()` and fills it with finite values, or returns an
  /// error code (such as `ERROR_WRONG_PARAMETER`) and a readable `message`. The whole-soup
  /// calls built with TBB call it for several components at once: it changes no shared state.
  Error_code operator()(const Norm_preserving_geometry& geometry,
                        std::vector<std::array<double, 2> >& uv,
                        std::string& message) const;
};

/*!
\ingroup PkgNormPreservingParameterizationConcepts
\cgalConcept

Reads a user's indexed mesh, of any type, for `texture_indexed_mesh()`: vertices are
`0..number_of_vertices(m)-1`, faces `0..number_of_faces(m)-1`. Every function may be static.

\cgalHasModel any specialization of `Indexed_mesh_traits`
*/
class IndexedMeshTraits
{
public:
  /// the number of vertices of `m`.
  std::size_t number_of_vertices(const IndexedMesh& m) const;
  /// the position of vertex `i`: any type with `x()`, `y()` and `z()` convertible to `double`.
  Point_3 point(const IndexedMesh& m, std::size_t i) const;
  /// the number of faces of `m`.
  std::size_t number_of_faces(const IndexedMesh& m) const;
  /// the vertex indices of face `f`, in order around it: any range of integers, of any
  /// length of at least three.
  Range face(const IndexedMesh& m, std::size_t f) const;
};

/*!
\ingroup PkgNormPreservingParameterizationConcepts
\cgalConcept

Solves the sign-constrained QP of one component (the paper's Eq. 5), given as a
`Norm_preserving_problem`, for `Norm_preserving_parameterizer_3` and the whole-soup calls.
The parameterizer solves once, then, with the sign refinement, again with other signs on the
same geometry and fixed pair, handing every solve the same `State`.

\cgalHasModel `Norm_preserving_ADMM_solver`, `Norm_preserving_QP_solver`

Checked at compile time by `concepts::NormPreservingSolver`.
*/
class NormPreservingSolver
{
public:
  /// what a solve leaves to the next on the same geometry and fixed pair (a factorization, a
  /// warm start); default-constructible, empty at the first solve.
  typedef unspecified_type State;

  /// copy constructor: the parameterizer keeps its own copy.
  NormPreservingSolver(const NormPreservingSolver&);

  /// solves `problem` from `uv`, a point that satisfies its constraints (the transformed
  /// guess, or the previous solution), and writes the solution to `uv`, the fixed vertices at
  /// their targets; fills `report`. Returns `false`, with `report.message` saying why, if
  /// there is no solution; a solve stopped by a limit returns `true` with the best feasible
  /// point and says so in `report.status`. The whole-soup calls built with TBB solve several
  /// components at once, each with its own `State`: it changes no shared state.
  bool solve(const Norm_preserving_problem& problem, std::vector<std::array<double, 2> >& uv, State& state,
             Norm_preserving_solve_report& report) const;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL
