// The options of the command-line tool and of the Python module, by the names both use, and
// the whole-soup call they make: one definition of each option's name, default and range.

#ifndef NP_EXAMPLES_TEXTURE_SETTINGS_H
#define NP_EXAMPLES_TEXTURE_SETTINGS_H

#include <CGAL/Surface_mesh_parameterization/Combination_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/Graph_based_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/XY_min_max_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/texture_polygon_mesh.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <utility>

namespace np_examples {

namespace SMP = CGAL::Surface_mesh_parameterization;

struct Texture_settings
{
  std::string guess = "xy";          // xy | combination | graph
  std::string fit = "uniform";       // uniform | clamp | none
  int tiles_u = 1, tiles_v = 1;
  std::optional<std::pair<std::size_t, std::size_t> > fixed_pair; // input vertex indices
  bool keep_coincident = false;      // do not weld vertices at the same position
  bool refine_signs = false;         // at most `sign_refinement_rounds` rounds
  bool refine_euclidean = false;     // at most `euclidean_refinement_steps` steps
  std::string quality = "default";   // draft | default | exact
  std::optional<double> tolerance;   // of the quality's solver; its preset by default
  double time_limit = std::numeric_limits<double>::infinity(); // seconds
};

constexpr int sign_refinement_rounds = 10;
constexpr int euclidean_refinement_steps = 1000;

inline std::optional<SMP::Texture_fit> fit_named(const std::string& name)
{
  if(name == "uniform") return SMP::NORM_PRESERVING_UNIFORM_FIT;
  if(name == "clamp") return SMP::NORM_PRESERVING_CLAMP_FIT;
  if(name == "none") return SMP::NORM_PRESERVING_NO_FIT;
  return std::nullopt;
}

inline std::optional<SMP::Norm_preserving_quality> quality_named(const std::string& name)
{
  if(name == "draft") return SMP::NORM_PRESERVING_DRAFT_QUALITY;
  if(name == "default") return SMP::NORM_PRESERVING_DEFAULT_QUALITY;
  if(name == "exact") return SMP::NORM_PRESERVING_EXACT_QUALITY;
  return std::nullopt;
}

// Why `s` cannot be used, named as the option that is wrong, or nothing.
inline std::optional<std::string> settings_problem(const Texture_settings& s)
{
  if(s.guess != "xy" && s.guess != "combination" && s.guess != "graph")
    return std::string("guess takes xy, combination or graph");
  if(!fit_named(s.fit))
    return std::string("fit takes uniform, clamp or none");
  if(s.tiles_u < 1 || s.tiles_v < 1)
    return std::string("tiles takes M and N of at least 1");
  if(!quality_named(s.quality))
    return std::string("quality takes draft, default or exact");
  if(s.tolerance && !(*s.tolerance > 0 && std::isfinite(*s.tolerance)))
    return std::string("tolerance takes a positive number");
  if(!(s.time_limit > 0))
    return std::string("time limit takes a positive number of seconds");
  return std::nullopt;
}

// The solver of the settings' quality, with their tolerance and time limit.
inline SMP::Norm_preserving_ADMM_solver settings_solver(const Texture_settings& s)
{
  const SMP::Norm_preserving_quality quality = *quality_named(s.quality);
  if(!s.tolerance)
    return SMP::Norm_preserving_ADMM_solver(quality, s.time_limit);
  if(quality == SMP::NORM_PRESERVING_EXACT_QUALITY)
    return SMP::Norm_preserving_ADMM_solver::certified(*s.tolerance, 200000, s.time_limit);
  return SMP::Norm_preserving_ADMM_solver(*s.tolerance, 20000, s.time_limit);
}

// texture_polygon_soup() with the settings (checked by settings_problem()) and a progress
// callback (a callable `bool(const SMP::Norm_preserving_progress&)`).
template <typename PointRange, typename PolygonRange, typename VertexUVMap, typename Progress>
SMP::Error_code texture_with_settings(const PointRange& points, const PolygonRange& polygons, VertexUVMap uvmap,
                                      const Texture_settings& s, SMP::Texture_polygon_mesh_report& report,
                                      const Progress& progress)
{
  auto call = [&](auto guess) {
    namespace P = SMP::parameters;
    const auto np = P::initial_guess(guess).combine(
      P::solver(settings_solver(s)), P::texture_fit(*fit_named(s.fit)), P::tiling(s.tiles_u, s.tiles_v),
      P::sign_refinement(s.refine_signs ? sign_refinement_rounds : 0),
      P::euclidean_refinement(s.refine_euclidean ? euclidean_refinement_steps : 0),
      P::weld_coincident_vertices(!s.keep_coincident), P::report(report), P::progress(progress));
    if(s.fixed_pair)
      return SMP::texture_polygon_soup(points, polygons, uvmap,
                                       np.combine(P::fixed_pair(s.fixed_pair->first, s.fixed_pair->second)));
    return SMP::texture_polygon_soup(points, polygons, uvmap, np);
  };
  if(s.guess == "combination") return call(SMP::Combination_initial_guess());
  if(s.guess == "graph") return call(SMP::Graph_based_initial_guess());
  return call(SMP::XY_min_max_initial_guess());
}

} // namespace np_examples

#endif
