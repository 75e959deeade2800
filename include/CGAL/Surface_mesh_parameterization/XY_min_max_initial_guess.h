#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_XY_MIN_MAX_INITIAL_GUESS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_XY_MIN_MAX_INITIAL_GUESS_H

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/Norm_preserving_initial_guess.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgNormPreservingParameterization
/// The XY-MinMax initial guess of Lai & Cheng (Section 4.1): each vertex is guessed at
/// `((x - Xmin) / (Xmax - Xmin), (y - Ymin) / (Ymax - Ymin))`.
///
/// If all vertices share the same x or the same y the guess is undefined (the paper divides
/// by zero): it then returns `ERROR_WRONG_PARAMETER` and says so, rather than invent an
/// order; choose another initial guess for such a mesh.
///
/// \cgalModels `NormPreservingInitialGuess`
class XY_min_max_initial_guess
{
public:
  /// computes the guess of every vertex of `geometry`.
  Error_code operator()(const Norm_preserving_geometry& geometry,
                        std::vector<std::array<double, 2> >& uv,
                        std::string& message) const
  {
    const auto& points = geometry.points;
    if(points.empty())
    {
      message = "no vertex to guess";
      return ERROR_EMPTY_MESH;
    }
    std::array<double, 2> low = {points[0][0], points[0][1]}, high = low;
    for(const auto& p : points)
      for(int c = 0; c < 2; ++c)
      {
        low[c] = (std::min)(low[c], p[c]);
        high[c] = (std::max)(high[c], p[c]);
      }
    for(int c = 0; c < 2; ++c)
      if(!(high[c] > low[c]))
      {
        message = std::string("all vertices have the same ") + (c == 0 ? "x" : "y") +
                  ": the XY-MinMax guess is undefined; use another initial guess";
        return ERROR_WRONG_PARAMETER;
      }
    uv.resize(points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
      for(int c = 0; c < 2; ++c)
        uv[i][c] = (points[i][c] - low[c]) / (high[c] - low[c]);
    return OK;
  }
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
