// Copies what a QP solver reports into the parameterizer's report, for solvers that report
// (those with a `statistics()` member, as `Interior_point_quadratic_program_traits`).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_SOLVER_STATISTICS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_NORM_PRESERVING_SOLVER_STATISTICS_H

#include <CGAL/Surface_mesh_parameterization/Norm_preserving_report.h>

#include <algorithm>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace Norm_preserving {

template <typename T, typename = void>
struct Has_statistics : std::false_type { };
template <typename T>
struct Has_statistics<T, std::void_t<decltype(std::declval<const T&>().statistics())> > : std::true_type { };

template <typename QuadraticProgramTraits>
void copy_solver_statistics(const QuadraticProgramTraits& qp, Norm_preserving_report& report)
{
  if constexpr(Has_statistics<QuadraticProgramTraits>::value)
  {
    const auto& statistics = qp.statistics();
    report.has_solver_statistics = true;
    report.solver_iterations = statistics.iterations;
    report.kkt_residual = (std::max)({statistics.primal_residual, statistics.dual_residual,
                                      statistics.complementarity});
    report.message = statistics.message;
  }
}

} // namespace Norm_preserving
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
