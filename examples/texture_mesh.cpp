// The command-line tool, and the main job: textures a mesh (by default the cow of CGAL's
// collection) with the norm-preserving parameterizer and writes a textured OBJ with its MTL
// and a checkerboard PNG, the UV layout as an SVG and a distortion report. Run with --help.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Combination_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/Graph_based_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_distortion.h>
#include <CGAL/Surface_mesh_parameterization/texture_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include "textured_obj_writer.h"
#include "uv_layout_svg.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace fs = std::filesystem;
using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Vertex = Mesh::Vertex_index;
using UV_map = Mesh::Property_map<Vertex, Kernel::Point_2>;

const char* const usage =
  "usage: texture_mesh [options] [input] [output]\n"
  "\n"
  "Textures a polygon mesh of any topology (closed, with holes, several components) with the\n"
  "norm-preserving parameterization of Lai & Cheng, with no cut and no seam, and writes\n"
  "  output.obj         the mesh with one vt per vertex, using output.mtl\n"
  "  output.mtl         a material whose texture is output.png\n"
  "  output.png         a checkerboard texture\n"
  "  output_uv.svg      the UV layout (flipped faces in red)\n"
  "  output_report.txt  the objective, the time and the distortion measures\n"
  "\n"
  "  input    OFF, OBJ, PLY or STL mesh (default: the cow of CGAL's collection)\n"
  "  output   basename of the files written (default: cow_textured)\n"
  "\n"
  "options:\n"
  "  --guess xy|combination|graph  initial guess (default xy: the paper's XY-MinMax)\n"
  "  --fit uniform|clamp|none      fit into texture space (default uniform: [0,1]^2,\n"
  "                                aspect kept; clamp: each axis to [0,1]; none: mesh units)\n"
  "  --tiles MxN                   repeat the texture M times along u, N along v (default 1x1)\n"
  "  --fixed-pair A,B              fix the edge between input vertices A and B (0-based);\n"
  "                                default: an automatic pair in every component\n"
  "  --refine-signs                re-solve with the signs of the solution (at most 10 rounds)\n"
  "  --refine-euclidean            then minimize the Euclidean edge-length error from the\n"
  "                                solution (stress majorization, at most 1000 steps)\n"
  "  --repair                      split non-manifold vertices first (common in STL files)\n"
  "  --help                        print this and exit\n"
  "\n"
  "Nothing is written unless every file can be. Exit status 0 on success, 1 on bad input or\n"
  "failure, 2 on a bad command line.\n";

struct Settings
{
  std::string input = std::string(NP_MESH_DIR) + "/cow.off";
  std::string output = "cow_textured";
  std::string guess = "xy";
  SMP::Texture_fit fit = SMP::UNIFORM_FIT;
  int tiles_u = 1, tiles_v = 1;
  std::optional<std::pair<std::size_t, std::size_t> > fixed_pair;
  bool repair = false;
  bool refine_signs = false;
  bool refine_euclidean = false;
};

// Parses the command line; returns an error message, or nothing on success.
std::optional<std::string> parse(int argc, char** argv, Settings& s, bool& help)
{
  std::vector<std::string> positional;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&]() -> std::optional<std::string> {
      if(i + 1 < argc) return std::string(argv[++i]);
      return std::nullopt;
    };
    if(arg == "--help" || arg == "-h")
      help = true;
    else if(arg == "--repair")
      s.repair = true;
    else if(arg == "--refine-signs")
      s.refine_signs = true;
    else if(arg == "--refine-euclidean")
      s.refine_euclidean = true;
    else if(arg == "--guess")
    {
      const auto v = value();
      if(!v || (*v != "xy" && *v != "combination" && *v != "graph")) return "--guess takes xy, combination or graph";
      s.guess = *v;
    }
    else if(arg == "--fit")
    {
      const auto v = value();
      if(v && *v == "uniform") s.fit = SMP::UNIFORM_FIT;
      else if(v && *v == "clamp") s.fit = SMP::CLAMP_FIT;
      else if(v && *v == "none") s.fit = SMP::NO_FIT;
      else return "--fit takes uniform, clamp or none";
    }
    else if(arg == "--tiles")
    {
      const auto v = value();
      char x = 0, rest = 0;
      std::istringstream in(v ? *v : std::string());
      if(!(in >> s.tiles_u >> x >> s.tiles_v) || (x != 'x' && x != 'X') || in >> rest || s.tiles_u < 1 || s.tiles_v < 1)
        return "--tiles takes MxN with M, N >= 1, such as 2x3";
    }
    else if(arg == "--fixed-pair")
    {
      const auto v = value();
      long long a = -1, b = -1;
      char comma = 0, rest = 0;
      std::istringstream in(v ? *v : std::string());
      if(!(in >> a >> comma >> b) || comma != ',' || in >> rest || a < 0 || b < 0)
        return "--fixed-pair takes two vertex indices A,B such as 0,1";
      s.fixed_pair = std::make_pair(std::size_t(a), std::size_t(b));
    }
    else if(arg.size() > 1 && arg[0] == '-')
      return "unknown option " + arg;
    else
      positional.push_back(arg);
  }
  if(positional.size() > 2)
    return "too many arguments";
  if(positional.size() > 0) s.input = positional[0];
  if(positional.size() > 1) s.output = positional[1];
  else if(positional.size() == 1) s.output = fs::path(s.input).stem().string() + "_textured";
  return std::nullopt;
}

// Runs `work` and, when it takes more than a second, shows the elapsed time on stderr.
template <typename Work>
auto with_progress(const std::string& what, Work work)
{
  auto result = std::async(std::launch::async, work);
  int seconds = 0;
  while(result.wait_for(std::chrono::seconds(1)) != std::future_status::ready)
    std::cerr << "\r" << what << "... " << ++seconds << " s" << std::flush;
  if(seconds > 0)
    std::cerr << "\r" << what << ": done in about " << seconds << " s\n";
  return result.get();
}

template <typename InitialGuess>
SMP::Error_code texture(const Mesh& mesh, UV_map uv, const Settings& s, SMP::Texture_polygon_mesh_report& report)
{
  SMP::Texture_polygon_mesh_options<Mesh, InitialGuess> options;
  options.texture_fit = s.fit;
  options.tiles_u = s.tiles_u;
  options.tiles_v = s.tiles_v;
  options.sign_refinement_rounds = s.refine_signs ? 10 : 0;
  options.euclidean_refinement_iterations = s.refine_euclidean ? 1000 : 0;
  if(s.fixed_pair)
    options.fixed_pair = std::make_pair(Vertex(Mesh::size_type(s.fixed_pair->first)),
                                        Vertex(Mesh::size_type(s.fixed_pair->second)));
  return SMP::texture_polygon_mesh(mesh, uv, options, &report);
}

// Writes every output file into a scratch directory beside them, then moves them in place:
// on any failure nothing is left behind.
bool write_outputs(const Settings& s, const Mesh& mesh, const Mesh& triangles, UV_map uv, const std::string& report)
{
  const fs::path target = fs::absolute(s.output);
  const fs::path scratch = target.parent_path() / (target.filename().string() + ".partial");
  std::error_code ec;
  fs::remove_all(scratch, ec);
  if(!fs::create_directories(scratch, ec))
    return false;
  const std::string stem = target.filename().string();
  const std::vector<std::string> names = {stem + ".obj", stem + ".mtl", stem + ".png", stem + "_uv.svg",
                                          stem + "_report.txt"};
  std::ofstream text((scratch / names[4]).string());
  text << report;
  text.close();
  bool ok = bool(text) && np_examples::write_textured_obj((scratch / stem).string(), mesh, uv) &&
            np_examples::write_uv_layout_svg((scratch / names[3]).string(), triangles, uv);
  for(std::size_t k = 0; ok && k < names.size(); ++k)
  {
    fs::rename(scratch / names[k], target.parent_path() / names[k], ec);
    ok = !ec;
  }
  fs::remove_all(scratch, ec);
  return ok;
}

int main(int argc, char** argv)
{
  Settings s;
  bool help = false;
  if(const auto error = parse(argc, argv, s, help))
  {
    std::cerr << "error: " << *error << "\n\n" << usage;
    return 2;
  }
  if(help)
  {
    std::cout << usage;
    return 0;
  }

  Mesh mesh;
  const bool read = with_progress("reading " + s.input, [&] {
    return fs::is_regular_file(s.input) && CGAL::IO::read_polygon_mesh(s.input, mesh) && !is_empty(mesh);
  });
  if(!read)
  {
    std::cerr << "error: cannot read a polygon mesh from " << s.input
              << " (it must exist and be a valid OFF, OBJ, PLY or STL polygon mesh)\n";
    return 1;
  }

  if(s.repair)
  {
    const std::size_t split = CGAL::Polygon_mesh_processing::duplicate_non_manifold_vertices(mesh);
    if(split > 0)
      std::cerr << "--repair: split " << split << " non-manifold vertices\n";
  }

  UV_map uv = mesh.add_property_map<Vertex, Kernel::Point_2>("v:uv").first;
  SMP::Texture_polygon_mesh_report report;
  const SMP::Error_code status = with_progress("texturing " + std::to_string(num_vertices(mesh)) + " vertices", [&] {
    if(s.guess == "combination") return texture<SMP::Combination_initial_guess>(mesh, uv, s, report);
    if(s.guess == "graph") return texture<SMP::Graph_based_initial_guess>(mesh, uv, s, report);
    return texture<SMP::XY_min_max_initial_guess>(mesh, uv, s, report);
  });
  if(status != SMP::OK)
  {
    std::cerr << "error: " << SMP::error_message(status) << ": " << report.message << '\n';
    if(!s.repair && report.message.find("non-manifold") != std::string::npos)
      std::cerr << "(--repair splits non-manifold vertices)\n";
    return 1;
  }

  std::size_t active = 0, constraints = 0, iterations = 0;
  double initial = 0, kkt = 0;
  for(const SMP::Norm_preserving_report& r : report.reports)
  {
    active += r.active_constraints;
    constraints += r.constraints;
    iterations = std::max<std::size_t>(iterations, std::size_t(r.solver_iterations));
    initial += r.initial_objective;
    kkt = std::max(kkt, r.kkt_residual);
  }
  // Distortion is measured on triangles; triangulating adds no vertex, so uvs stay valid.
  Mesh triangles = mesh;
  CGAL::Polygon_mesh_processing::triangulate_faces(triangles);
  UV_map triangle_uv = triangles.property_map<Vertex, Kernel::Point_2>("v:uv").first;
  auto on_face = triangles.add_property_map<Vertex, bool>("v:on_face", true).first;
  for(Vertex v : vertices(triangles))
    put(on_face, v, !triangles.is_isolated(v));
  const SMP::Parameterization_distortion d = SMP::measure_distortion(triangles, triangle_uv, on_face);

  std::ostringstream summary;
  summary << s.input << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces, "
          << report.components << " component(s)\n"
          << "objective (Eq. 3): " << initial << " at the guess -> " << report.objective << ", "
          << active << "/" << constraints << " sign constraints active, " << iterations
          << " solver iterations, KKT residual " << kkt << '\n'
          << "time: " << report.seconds << " s\n"
          << "distortion: edge-length error " << d.edge_length_error << " (L1 " << d.l1_edge_length_error
          << "), flipped faces " << d.flipped_faces << "/" << d.faces << " ("
          << 100 * d.flipped_area_fraction << "% of the area)\n";
  std::ostringstream details;
  details << summary.str()
          << "initial guess: " << s.guess << (s.refine_signs ? ", sign refinement" : "")
          << (s.refine_euclidean ? ", Euclidean refinement" : "") << ", tiles: " << s.tiles_u << "x" << s.tiles_v << '\n'
          << "scale of the best fit to 3D lengths: " << d.scale << '\n'
          << "mean / max angle distortion (degrees): " << d.mean_angle_distortion << " / " << d.max_angle_distortion << '\n'
          << "area distortion (RMS log ratio): " << d.area_distortion << '\n'
          << "L2 / Linf stretch: " << d.l2_stretch << " / " << d.linf_stretch << '\n'
          << "faces of zero uv area: " << d.degenerate_uv_faces << '\n'
          << "vertices on no face (no uv): " << report.isolated_vertices << '\n';
  if(!with_progress("writing " + s.output, [&] { return write_outputs(s, mesh, triangles, uv, details.str()); }))
  {
    std::cerr << "error: cannot write " << s.output << ".obj/.mtl/.png/_uv.svg/_report.txt; nothing written\n";
    return 1;
  }
  std::cout << summary.str() << "wrote " << s.output << ".obj, .mtl, .png, _uv.svg, _report.txt\n";
  return 0;
}
