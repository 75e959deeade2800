// The uv each vertex carries into the output files (OBJ, glb), in one place for the command-line
// tool and the Python module: its own, or (0, 0) for a vertex without one (not finite: a vertex
// on no face, which texture_polygon_soup() leaves alone and the module gives NaN).

#ifndef NP_EXAMPLES_VERTEX_UV_H
#define NP_EXAMPLES_VERTEX_UV_H

#include <array>
#include <cmath>

namespace np_examples {

template <typename Point_2>
bool has_uv(const Point_2& uv)
{
  return std::isfinite(double(uv.x())) && std::isfinite(double(uv.y()));
}

// The uv written for a vertex whose uv is `uv`.
template <typename Point_2>
std::array<double, 2> written_uv(const Point_2& uv)
{
  if(!has_uv(uv))
    return {0., 0.};
  return {double(uv.x()), double(uv.y())};
}

} // namespace np_examples

#endif
