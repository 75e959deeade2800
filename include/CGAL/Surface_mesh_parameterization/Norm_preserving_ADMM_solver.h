#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_ADMM_SOLVER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_NORM_PRESERVING_ADMM_SOLVER_H

#include <CGAL/Surface_mesh_parameterization/Norm_preserving_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sign_constrained_admm.h>

#include <limits>
#include <string>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterization
/// Statistics of the last solve of `Norm_preserving_ADMM_solver`.
struct Norm_preserving_ADMM_statistics
{
  Norm_preserving_solver_status status = SOLVER_FAILED; ///< how the solve ended
  int iterations = 0;         ///< ADMM iterations
  double primal_residual = 0; ///< `|Ax - z| / |l1|`: how far the mesh is from the edge values
  double dual_residual = 0;   ///< `|A'(z - z_prev)| / |l1|`: how much the edge values still move
  double assembly_seconds = 0;      ///< building the Laplacian and the feasible sweep
  double factorization_seconds = 0; ///< the Laplacian's Cholesky factorization
  double iteration_seconds = 0;     ///< the iterations and the final sweep
  std::string message;        ///< why the solve did not converge, empty if it did
};

/// \ingroup PkgNormPreservingParameterization
/// The default solver of `Norm_preserving_parameterizer_3`: solves the sign-constrained QP
/// (the paper's Eq. 5) by the alternating direction method of multipliers, split so that the
/// only linear system is the mesh's graph Laplacian, factored once (CHOLMOD when the package
/// is configured with it). Each iteration costs one two-column triangular solve and a
/// closed-form step per edge. The result satisfies every sign constraint exactly (the last
/// iterate is swept onto the feasible set), so its objective is never below the optimum.
///
/// For the exact optimum use `Interior_point_quadratic_program_traits` (or any model of
/// `QuadraticProgramTraits`) as the solver instead: it solves the same QP to 1e-10.
///
/// With the default time limit (none) the result depends on the input only, bit for bit.
class Norm_preserving_ADMM_solver
{
public:
  /// creates a solver that stops when the objective of the feasible point has decreased by at
  /// most `tolerance` (relative) over the last 50 iterations, or both relative residuals are at
  /// most `tolerance`; or after `max_iterations` iterations or `time_limit` seconds. The
  /// default puts the objective within 1e-4 of the optimum on the test suite (measured 2e-6
  /// to 7e-5 at 1e-4); `1e-9` reaches it to 1e-8.
  explicit Norm_preserving_ADMM_solver(double tolerance = 5e-5, int max_iterations = 20000,
                                       double time_limit = std::numeric_limits<double>::infinity())
    : m_settings{tolerance, max_iterations, time_limit}
  { }

  /// the statistics of the last solve.
  const Norm_preserving_ADMM_statistics& statistics() const { return m_statistics; }

  /// solves Eq. 5 for `geometry` from the transformed guess `uv`, which satisfies the sign
  /// constraints, and writes the solution to `uv`; returns `false` if there is none. Called by
  /// `Norm_preserving_parameterizer_3`.
  bool solve(const Norm_preserving_geometry& geometry, const std::vector<double>& l1_lengths,
             const internal::Norm_preserving::Edge_signs& signs,
             const std::array<internal::Norm_preserving::Fixed_vertex, 2>& fixed,
             std::vector<std::array<double, 2> >& uv)
  {
    return record(internal::Norm_preserving::solve_sign_constrained_admm(geometry, l1_lengths, signs, fixed,
                                                                         m_settings, uv));
  }

  /// solves Eq. 5 as above, reusing the Laplacian factorization and starting from the edge
  /// values and multipliers that the previous solve on the same geometry and fixed pair left
  /// in `state` (a cold start if there is none), and leaves its own there. `signs` may differ
  /// from the previous ones; they must be those of the values `order` (null: `uv`) with the
  /// tie rule of the parameterizer. Called by its refinements.
  bool solve(const Norm_preserving_geometry& geometry, const std::vector<double>& l1_lengths,
             const internal::Norm_preserving::Edge_signs& signs,
             const std::array<internal::Norm_preserving::Fixed_vertex, 2>& fixed,
             std::vector<std::array<double, 2> >& uv, internal::Norm_preserving::Admm_state& state,
             const std::vector<std::array<double, 2> >* order = nullptr)
  {
    return record(internal::Norm_preserving::solve_sign_constrained_admm(geometry, l1_lengths, signs, fixed,
                                                                         m_settings, uv, &state, order));
  }

private:
  bool record(const internal::Norm_preserving::Admm_result& result)
  {
    namespace NP = internal::Norm_preserving;
    m_statistics = Norm_preserving_ADMM_statistics();
    m_statistics.iterations = result.iterations;
    m_statistics.primal_residual = result.primal_residual;
    m_statistics.dual_residual = result.dual_residual;
    m_statistics.assembly_seconds = result.assembly_seconds;
    m_statistics.factorization_seconds = result.factorization_seconds;
    m_statistics.iteration_seconds = result.iteration_seconds;
    switch(result.outcome)
    {
      case NP::Admm_outcome::CONVERGED: m_statistics.status = SOLVER_CONVERGED; break;
      case NP::Admm_outcome::ITERATION_LIMIT:
        m_statistics.status = SOLVER_ITERATION_LIMIT;
        m_statistics.message = "iteration limit reached before the tolerance";
        break;
      case NP::Admm_outcome::TIME_LIMIT:
        m_statistics.status = SOLVER_TIME_LIMIT;
        m_statistics.message = "time limit reached before the tolerance";
        break;
      case NP::Admm_outcome::FACTORIZATION_FAILED:
        m_statistics.message = "the graph Laplacian could not be factored";
        return false;
    }
    return true;
  }

  internal::Norm_preserving::Admm_settings m_settings;
  Norm_preserving_ADMM_statistics m_statistics;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
