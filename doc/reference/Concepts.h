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
*/
class NormPreservingInitialGuess
{
public:
  /// copy constructor: the parameterizer keeps its own copy.
  NormPreservingInitialGuess(const NormPreservingInitialGuess&);

  /// resizes `uv` to `geometry.points.size()` and fills it with finite values, or returns an
  /// error code (such as `ERROR_WRONG_PARAMETER`) and a readable `message`.
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

} // namespace Surface_mesh_parameterization
} // namespace CGAL
