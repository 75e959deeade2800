#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_PARAMETERIZER_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_PARAMETERIZER_3_H

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_ADMM_solver.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_report.h>
#include <CGAL/Surface_mesh_parameterization/Texture_fit.h>
#include <CGAL/Surface_mesh_parameterization/XY_min_max_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Fixed_pair.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Mesh_component.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sign_constrained_qp.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sign_refinement.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Similarity_transform.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Solver_statistics.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Stress_majorization.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Texture_space_fit.h>

#include <CGAL/Default.h>
#include <CGAL/boost/graph/helpers.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <chrono>
#include <cmath>
#include <iterator>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterization
/// Norm-preserving texture mapping of Lai & Cheng ("Texture Mapping on Surfaces of Arbitrary
/// Topology using Norm Preserving based Optimization"): every vertex of a connected triangle
/// mesh of any topology (disk, closed of any genus, many border loops) gets one uv, with no
/// cut, minimizing `sum_edges (||P_i - P_j||_1 - |u_i - u_j| - |v_i - v_j|)^2` with the signs
/// of the differences frozen from an initial guess, so that the problem is a convex QP
/// (Eq. 5), solved to optimality.
///
/// Closed meshes fold (front and back overlap in uv, the texture repeats): that is the method.
/// A border halfedge is not required: `parameterize()` accepts any halfedge of the component;
/// only CGAL's free function `parameterize(mesh, parameterizer, bhd, uvmap)` asks for a border
/// one.
///
/// \tparam TriangleMesh_ a model of `FaceGraph` with an internal `vertex_point` map
/// \tparam InitialGuess_ a model of `NormPreservingInitialGuess`;
///         default `XY_min_max_initial_guess`
/// \tparam SolverTraits_ `Norm_preserving_ADMM_solver` (the default: fast, to a tolerance) or
///         a model of `QuadraticProgramTraits`, such as `Interior_point_quadratic_program_traits`
///         (the exact optimum) or `CGAL::OSQP_quadratic_program_traits`
///
/// \cgalModels `Parameterizer_3`
template <typename TriangleMesh_,
          typename InitialGuess_ = Default,
          typename SolverTraits_ = Default>
class Norm_preserving_parameterizer_3
{
public:
  /// the mesh type
  typedef TriangleMesh_ Triangle_mesh;
  /// the mesh type (CGAL's other parameterizers name it so too)
  typedef TriangleMesh_ TriangleMesh;
  /// the initial-guess type
  typedef typename Default::Get<InitialGuess_, XY_min_max_initial_guess>::type Initial_guess;
  /// the QP solver type
  typedef typename Default::Get<SolverTraits_, Norm_preserving_ADMM_solver>::type Solver_traits;
  /// halfedge handle of the mesh
  typedef typename boost::graph_traits<Triangle_mesh>::halfedge_descriptor halfedge_descriptor;
  /// vertex handle of the mesh
  typedef typename boost::graph_traits<Triangle_mesh>::vertex_descriptor vertex_descriptor;

  /// creates a parameterizer with the given initial guess and QP solver.
  explicit Norm_preserving_parameterizer_3(Initial_guess guess = Initial_guess(),
                                           Solver_traits solver = Solver_traits())
    : m_guess(guess), m_solver(solver)
  { }

  /// fixes `source(bhd)` at the origin and `target(bhd)` along the guessed direction (default).
  void set_fixed_pair_from_halfedge() { m_pair_choice = Pair_choice::HALFEDGE; }
  /// fixes the vertex of smallest x (lowest index on ties) and its neighbour across the
  /// longest L1 edge (lowest index on ties) among those that the initial guess puts elsewhere.
  void set_automatic_fixed_pair() { m_pair_choice = Pair_choice::AUTOMATIC; }
  /// fixes `a` at the origin and `b` along the guessed direction; they must be adjacent
  /// vertices of the component being parameterized.
  void set_fixed_pair(vertex_descriptor a, vertex_descriptor b)
  {
    m_pair_choice = Pair_choice::EXPLICIT;
    m_a = a;
    m_b = b;
  }
  /// sets how the solution is fitted into texture space; default `UNIFORM_FIT`.
  void set_texture_fit(Texture_fit fit) { m_fit = fit; }
  /// sets the `m x n` tiling: `u` is scaled by `m` and `v` by `n` after the fit; default 1 x 1.
  void set_tiling(int m, int n) { m_tiles = {m, n}; }
  /// sign refinement (beyond the paper): after the QP, up to `max_rounds` times, takes the
  /// signs from the solution, turning the zero differences the way Eq. 3 decreases, and
  /// solves again (warm-started with the default solver); stops when a round lowers Eq. 3 by
  /// at most `tolerance` (relative) or not at all. Eq. 3 never increases. Default: off (0).
  /// \param max_rounds at least 0; 0 turns it off
  /// \param tolerance at least 0
  void set_sign_refinement(int max_rounds, double tolerance = 1e-3)
  {
    m_sign_refinement = {max_rounds, tolerance};
  }
  /// Euclidean refinement (beyond the paper): after the QP (and the sign refinement), minimizes
  /// the Euclidean objective `sum (||P_i - P_j||_2 - ||T_i - T_j||_2)^2` (Eq. 2 with q = 2) from
  /// the solution scaled to fit, the fixed pair held at its Euclidean distance, by stress
  /// majorization: at most `max_iterations` steps, each one solve with the Laplacian factored
  /// once, stopping when a step lowers the objective by at most `tolerance` (relative); it never
  /// increases. The result no longer satisfies the sign constraints. Default: off (0).
  /// The QP is then only its start: a loose solver tolerance (`Norm_preserving_ADMM_solver(1e-2)`)
  /// gives the same result faster (doc/refinement.md).
  /// \param max_iterations at least 0; 0 turns it off
  /// \param tolerance at least 0
  void set_euclidean_refinement(int max_iterations, double tolerance = 1e-3)
  {
    m_euclidean_refinement = {max_iterations, tolerance};
  }

  /// the initial guess.
  const Initial_guess& initial_guess() const { return m_guess; }
  /// the QP solver, as configured (each call solves with a copy of it).
  Solver_traits& solver_traits() { return m_solver; }
  /// what the last call of `parameterize()` did.
  const Norm_preserving_report& report() const { return m_report; }

  /// assigns a uv to every vertex of the connected component of `bhd`, which may be any
  /// halfedge of it, border or not, and marks each in `vpmap`.
  ///
  /// On failure it returns `ERROR_EMPTY_MESH`, `ERROR_NON_TRIANGULAR_MESH` (a face that is
  /// not a triangle of three distinct vertices, or a vertex of the component whose faces form
  /// several fans), `ERROR_WRONG_PARAMETER` (non-finite
  /// coordinates, zero extent, an undefined guess, a fixed pair that is not an edge of the
  /// component) or `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM`, explains it in `report().message`,
  /// and writes nothing to `uvmap` or `vpmap`.
  ///
  /// \tparam VertexUVmap a model of `ReadWritePropertyMap` from vertices to a 2D point type
  /// \tparam VertexIndexMap unused: the component is indexed in the mesh's vertex order
  /// \tparam VertexParameterizedMap a model of `ReadWritePropertyMap` from vertices to `bool`
  template <typename VertexUVmap, typename VertexIndexMap, typename VertexParameterizedMap>
  Error_code parameterize(Triangle_mesh& mesh,
                          halfedge_descriptor bhd,
                          VertexUVmap uvmap,
                          VertexIndexMap /* vimap */,
                          VertexParameterizedMap vpmap)
  {
    typedef typename boost::property_traits<VertexUVmap>::value_type Point_2;
    const auto start = std::chrono::steady_clock::now();
    m_report = Norm_preserving_report();
    internal::Norm_preserving::Mesh_component<Triangle_mesh> component;
    std::vector<std::array<double, 2> > uv;
    m_report.status = compute(mesh, bhd, component, uv);
    if(m_report.status == OK)
      for(std::size_t i = 0; i < uv.size(); ++i)
      {
        put(uvmap, component.vertices[i], Point_2(uv[i][0], uv[i][1]));
        put(vpmap, component.vertices[i], true);
      }
    m_report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const Norm_preserving_timings& t = m_report.timings;
    m_report.timings.write_back = (std::max)(0., m_report.seconds - t.extraction - t.guess - t.assembly - t.factorization
                                                   - t.iterations - t.sign_refinement - t.euclidean_refinement);
    return m_report.status;
  }

private:
  enum class Pair_choice { HALFEDGE, AUTOMATIC, EXPLICIT };

  Error_code fail(Error_code code, const std::string& message)
  {
    m_report.message = message;
    return code;
  }

  // The pipeline of DESIGN.md: extract, guess, fixed pair + similarity, QP, fit.
  Error_code compute(Triangle_mesh& mesh, halfedge_descriptor bhd,
                     internal::Norm_preserving::Mesh_component<Triangle_mesh>& component,
                     std::vector<std::array<double, 2> >& uv)
  {
    namespace NP = internal::Norm_preserving;
    auto step_start = std::chrono::steady_clock::now();
    auto lap = [&step_start]() {
      const auto now = std::chrono::steady_clock::now();
      const double seconds = std::chrono::duration<double>(now - step_start).count();
      step_start = now;
      return seconds;
    };
    if(m_sign_refinement.max_rounds < 0 || !(m_sign_refinement.tolerance >= 0)
       || m_euclidean_refinement.max_iterations < 0 || !(m_euclidean_refinement.tolerance >= 0))
      return fail(ERROR_WRONG_PARAMETER, "a refinement has a negative iteration limit or tolerance");
    Error_code status = NP::extract_component(mesh, bhd, component, m_report.message);
    if(status != OK)
      return status;
    Norm_preserving_geometry& geometry = component.geometry;
    m_report.vertices = geometry.points.size();
    m_report.edges = geometry.edges.size();

    std::size_t a = 0, b = 0;
    status = choose_fixed_pair(mesh, bhd, component, a, b);
    if(status != OK)
      return status;
    m_report.fixed_a = a;
    m_report.fixed_b = b;

    // Work in units of the mean L1 edge length, relative to the first fixed vertex, so that
    // the QP is equally well conditioned at every model scale.
    std::vector<double> lengths = NP::edge_l1_lengths(geometry);
    double unit = 0;
    for(double l : lengths) unit += l;
    unit /= double(lengths.size());
    if(!std::isfinite(unit))
      return fail(ERROR_WRONG_PARAMETER, "the edge lengths overflow: the coordinates are too large");
    if(!(unit > 0))
      return fail(ERROR_WRONG_PARAMETER, "all edges have zero length");
    const std::array<double, 3> origin = geometry.points[a];
    for(auto& p : geometry.points)
      for(int c = 0; c < 3; ++c)
        p[c] = (p[c] - origin[c]) / unit;
    lengths = NP::edge_l1_lengths(geometry);
    m_report.timings.extraction = lap();

    status = m_guess(geometry, uv, m_report.message);
    if(status != OK)
      return status;
    if(uv.size() != geometry.points.size())
      return fail(ERROR_WRONG_PARAMETER, "the initial guess did not give one value per vertex");
    for(const auto& p : uv)
      if(!std::isfinite(p[0]) || !std::isfinite(p[1]))
        return fail(ERROR_WRONG_PARAMETER, "the initial guess has a non-finite value");
    if(m_pair_choice == Pair_choice::AUTOMATIC && uv[a] == uv[b])
      m_report.fixed_b = b = NP::automatic_partner(geometry, a, &uv); // the guess must tell a from b

    std::array<NP::Fixed_vertex, 2> fixed = {NP::Fixed_vertex{a, {}}, NP::Fixed_vertex{b, {}}};
    const double l1_ab = NP::l1_distance(geometry.points[a], geometry.points[b]);
    if(!(l1_ab > 0))
      return fail(ERROR_WRONG_PARAMETER, "the fixed vertices are at the same position");
    if(!NP::fixed_pair_targets(uv[a], uv[b], l1_ab, fixed[0].target, fixed[1].target))
      return fail(ERROR_WRONG_PARAMETER, "the initial guess puts both fixed vertices at the same point");
    NP::transform(uv, NP::similarity_from_pairs(uv[a], uv[b], fixed[0].target, fixed[1].target));
    uv[a] = fixed[0].target;
    uv[b] = fixed[1].target;

    NP::Edge_signs signs = NP::edge_signs(geometry, uv);
    m_report.initial_objective = NP::sign_constrained_objective(geometry, lengths, signs, uv) * unit * unit;
    m_report.constraints = 2 * geometry.edges.size();
    m_report.timings.guess = lap();

    NP::Admm_state state; // shared by the QP and the refinements (default solver)
    const bool refined = m_sign_refinement.max_rounds > 0 || m_euclidean_refinement.max_iterations > 0;
    status = solve_qp(geometry, lengths, signs, fixed, uv, refined ? &state : nullptr);
    if(status != OK)
      return status;
    if(m_sign_refinement.max_rounds > 0)
    {
      lap();
      refine_signs(geometry, lengths, fixed, signs, uv, state, unit);
      m_report.timings.sign_refinement = lap();
    }

    m_report.objective = NP::l1_norm_objective(geometry, lengths, uv) * unit * unit;
    const auto extent = NP::sign_constraint_extent(geometry, signs, uv, 1e-8);
    m_report.max_constraint_violation = (std::max)(0., -extent.first) * unit;
    m_report.active_constraints = extent.second;
    if(m_euclidean_refinement.max_iterations > 0)
    {
      lap();
      status = refine_euclidean(geometry, fixed, uv, state, unit);
      m_report.timings.euclidean_refinement = lap();
      if(status != OK)
        return status;
    }

    for(auto& p : uv)
      for(int c = 0; c < 2; ++c)
        p[c] *= unit;
    NP::fit_to_texture_space(uv, m_fit, m_tiles[0], m_tiles[1]);
    return OK;
  }

  Error_code choose_fixed_pair(const Triangle_mesh& mesh, halfedge_descriptor bhd,
                               const internal::Norm_preserving::Mesh_component<Triangle_mesh>& component,
                               std::size_t& a, std::size_t& b)
  {
    namespace NP = internal::Norm_preserving;
    if(m_pair_choice == Pair_choice::AUTOMATIC)
    {
      std::tie(a, b) = NP::automatic_fixed_pair(component.geometry);
      return OK;
    }
    const vertex_descriptor va = m_pair_choice == Pair_choice::EXPLICIT ? m_a : source(bhd, mesh);
    const vertex_descriptor vb = m_pair_choice == Pair_choice::EXPLICIT ? m_b : target(bhd, mesh);
    if(!component.has(va) || !component.has(vb))
      return fail(ERROR_WRONG_PARAMETER, "a fixed vertex is not in the component of the halfedge");
    a = std::size_t(get(component.index, va));
    b = std::size_t(get(component.index, vb));
    if(!NP::is_edge(component.geometry, a, b))
      return fail(ERROR_WRONG_PARAMETER, "the fixed vertices are not the two ends of an edge");
    return OK;
  }

  // `state`, if given, keeps the default solver's factorization for the refinements.
  Error_code solve_qp(const Norm_preserving_geometry& geometry, const std::vector<double>& lengths,
                      const internal::Norm_preserving::Edge_signs& signs,
                      const std::array<internal::Norm_preserving::Fixed_vertex, 2>& fixed,
                      std::vector<std::array<double, 2> >& uv, internal::Norm_preserving::Admm_state* state)
  {
    namespace NP = internal::Norm_preserving;
    if constexpr(std::is_same<Solver_traits, Norm_preserving_ADMM_solver>::value)
    {
      Solver_traits solver = m_solver;
      const bool solved = state ? solver.solve(geometry, lengths, signs, fixed, uv, *state)
                                : solver.solve(geometry, lengths, signs, fixed, uv);
      const Norm_preserving_ADMM_statistics& statistics = solver.statistics();
      m_report.has_solver_statistics = true;
      m_report.solver_status = statistics.status;
      m_report.solver_iterations = statistics.iterations;
      m_report.kkt_residual = (std::max)(statistics.primal_residual, statistics.dual_residual);
      m_report.message = statistics.message;
      m_report.timings.assembly = statistics.assembly_seconds;
      m_report.timings.factorization = statistics.factorization_seconds;
      m_report.timings.iterations = statistics.iteration_seconds;
      if(!solved)
        return fail(ERROR_CANNOT_SOLVE_LINEAR_SYSTEM, "the QP solver failed: " + statistics.message);
      return OK;
    }
    else
      return solve_general_qp(geometry, lengths, signs, fixed, uv);
  }

  // Any model of QuadraticProgramTraits: Eq. 5 written out as a general QP.
  Error_code solve_general_qp(const Norm_preserving_geometry& geometry, const std::vector<double>& lengths,
                              const internal::Norm_preserving::Edge_signs& signs,
                              const std::array<internal::Norm_preserving::Fixed_vertex, 2>& fixed,
                              std::vector<std::array<double, 2> >& uv)
  {
    namespace NP = internal::Norm_preserving;
    auto start = std::chrono::steady_clock::now();
    Solver_traits qp = m_solver;
    NP::assemble_sign_constrained_qp(geometry, lengths, signs, fixed, qp);
    m_report.timings.assembly = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    start = std::chrono::steady_clock::now();
    std::vector<double> x;
    x.reserve(2 * uv.size());
    const bool solved = qp.solve(std::back_inserter(x));
    m_report.timings.iterations = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    NP::copy_solver_statistics(qp, m_report);
    if(!solved || x.size() != 2 * uv.size())
      return fail(ERROR_CANNOT_SOLVE_LINEAR_SYSTEM, "the QP solver failed" +
                  (m_report.message.empty() ? std::string() : ": " + m_report.message));
    for(double value : x)
      if(!std::isfinite(value))
        return fail(ERROR_CANNOT_SOLVE_LINEAR_SYSTEM, "the QP solver returned a non-finite value");
    for(std::size_t i = 0; i < uv.size(); ++i)
      uv[i] = {x[2 * i], x[2 * i + 1]};
    for(const NP::Fixed_vertex& f : fixed)
      uv[f.index] = f.target;
    m_report.solver_status = SOLVER_CONVERGED;
    return OK;
  }

  // Beyond the paper: re-solve with the signs of the solution while Eq. 3 decreases.
  void refine_signs(const Norm_preserving_geometry& geometry, const std::vector<double>& lengths,
                    const std::array<internal::Norm_preserving::Fixed_vertex, 2>& fixed,
                    internal::Norm_preserving::Edge_signs& signs, std::vector<std::array<double, 2> >& uv,
                    internal::Norm_preserving::Admm_state& state, double unit)
  {
    namespace NP = internal::Norm_preserving;
    auto solve = [&](const NP::Edge_signs& next, const NP::UV_vector& order, NP::UV_vector& candidate) {
      if constexpr(std::is_same<Solver_traits, Norm_preserving_ADMM_solver>::value)
      {
        Solver_traits solver = m_solver;
        return solver.solve(geometry, lengths, next, fixed, candidate, state, &order);
      }
      else
      {
        (void)order;
        const Norm_preserving_report kept = m_report; // a round's solver report is not the call's
        const bool solved = solve_general_qp(geometry, lengths, next, fixed, candidate) == OK;
        m_report = kept;
        return solved;
      }
    };
    const std::vector<double> objectives =
      NP::refine_signs(geometry, lengths, fixed, m_sign_refinement, signs, uv, solve);
    m_report.sign_refinement_rounds = int(objectives.size()) - 1;
    for(double objective : objectives)
      m_report.sign_refinement_objectives.push_back(objective * unit * unit);
  }

  // Beyond the paper: the Euclidean objective by stress majorization, from the QP solution.
  Error_code refine_euclidean(const Norm_preserving_geometry& geometry,
                              std::array<internal::Norm_preserving::Fixed_vertex, 2> fixed,
                              std::vector<std::array<double, 2> >& uv,
                              const internal::Norm_preserving::Admm_state& state, double unit)
  {
    namespace NP = internal::Norm_preserving;
    const std::vector<double> lengths = NP::edge_euclidean_lengths(geometry);
    if(!NP::euclidean_start(geometry, lengths, fixed, uv))
      return fail(ERROR_CANNOT_SOLVE_LINEAR_SYSTEM, "the Euclidean refinement failed: the solution has no extent");
    const NP::Stress_majorization_result result =
      NP::majorize_stress(geometry, lengths, fixed, m_euclidean_refinement, uv, state.factored ? &state.cholesky : nullptr);
    m_report.euclidean_iterations = result.iterations;
    for(double stress : result.stress)
      m_report.euclidean_stress.push_back(stress * unit * unit);
    if(!result.solved)
      return fail(ERROR_CANNOT_SOLVE_LINEAR_SYSTEM,
                  "the Euclidean refinement failed: the graph Laplacian could not be factored or a value overflowed");
    return OK;
  }

  Initial_guess m_guess;
  Solver_traits m_solver;
  Pair_choice m_pair_choice = Pair_choice::HALFEDGE;
  vertex_descriptor m_a, m_b;
  Texture_fit m_fit = UNIFORM_FIT;
  std::array<int, 2> m_tiles = {1, 1};
  internal::Norm_preserving::Sign_refinement_settings m_sign_refinement = {0, 1e-3};
  internal::Norm_preserving::Stress_majorization_settings m_euclidean_refinement = {0, 1e-3};
  Norm_preserving_report m_report;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
