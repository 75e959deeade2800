// The command-line tool, and the main job: textures a mesh (by default the cow of CGAL's
// collection) with the norm-preserving parameterizer and writes it textured, as an OBJ with its
// MTL and texture image or as a binary glTF, with the UV layout as an SVG, a distortion report
// and, if asked, a web page that shows it. Run with --help.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_distortion.h>
#include <CGAL/Surface_mesh_parameterization/texture_polygon_mesh.h>
#include <CGAL/Surface_mesh_parameterization/triangulate_polygon_soup.h>
#include <CGAL/property_map.h>

#include "checkerboard.h"
#include "glb_writer.h"
#include "output_files.h"
#include "progress_display.h"
#include "soup_reader.h"
#include "texture_image.h"
#include "texture_settings.h"
#include "textured_obj_writer.h"
#include "uv_layout_svg.h"
#include "vertex_uv.h"
#include "viewer_page.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <limits>
#include <new>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace fs = std::filesystem;
using np_examples::lower_case;
using Kernel = CGAL::Simple_cartesian<double>;
using Point_3 = Kernel::Point_3;
using Polygon = std::vector<std::size_t>;
using UV = std::vector<Kernel::Point_2>;

// The soup as read: vertices and faces in the file's order.
struct Soup
{
  std::vector<Point_3> points;
  std::vector<Polygon> polygons;
};

const char* const usage =
  "usage: texture_mesh [options] [input] [output]\n"
  "\n"
  "Textures any polygon soup (closed, with holes, several components, non-manifold,\n"
  "inconsistently oriented or non-orientable) with the norm-preserving parameterization of\n"
  "Lai & Cheng, with no cut and no seam, and writes, as an OBJ (the default):\n"
  "  output.obj         the mesh with one vt per vertex, using output.mtl\n"
  "  output.mtl         a material whose texture is output.png\n"
  "  output.png         the texture: a checkerboard, or a copy of the --texture image\n"
  "                     (output.jpg for a JPEG image)\n"
  "or, as a glb (--format glb, or an output name ending in .glb):\n"
  "  output.glb         binary glTF 2.0: the mesh with one vertex per input vertex, its\n"
  "                     normals, uvs and triangles, and the texture embedded\n"
  "and in both cases\n"
  "  output_uv.svg      the UV layout (flipped faces in red)\n"
  "  output_report.txt  the objective, the time and the distortion measures\n"
  "  output.html        with --viewer: a page that shows the textured model, turned with the\n"
  "                     mouse, in any browser with WebGL, offline (three.js inlined)\n"
  "\n"
  "  input    OFF, OBJ, PLY (triangle strips too), STL or GOCAD TS file (default: the cow of\n"
  "           CGAL's collection)\n"
  "  output   basename of the files written, or a name ending in .obj or .glb, which chooses\n"
  "           the format (default: the input's name with _textured; cow_textured)\n"
  "\n"
  "options:\n"
  "  --texture IMAGE               texture with this PNG or JPEG image instead of the\n"
  "                                checkerboard (copied beside an OBJ, embedded in a glb)\n"
  "  --format obj|glb              the format of the textured mesh (default: by the output\n"
  "                                name, else obj)\n"
  "  --viewer                      also write output.html\n"
  "  --quiet                       print nothing but errors: no progress, no summary\n"
  "  --guess xy|combination|graph  initial guess (default xy: the paper's XY-MinMax)\n"
  "  --fit uniform|clamp|none      fit into texture space (default uniform: [0,1]^2,\n"
  "                                aspect kept; clamp: each axis to [0,1]; none: mesh units)\n"
  "  --tiles MxN                   repeat the texture M times along u, N along v (default 1x1)\n"
  "  --fixed-pair A,B              fix the edge between input vertices A and B (0-based);\n"
  "                                default: an automatic pair in every component\n"
  "  --quality draft|default|exact how close to the optimum the solver goes (default: default;\n"
  "                                draft: at most 2% above, fastest; exact: certified to 1e-9)\n"
  "  --tolerance T                 the solver's tolerance (default: the quality's)\n"
  "  --time-limit S                stop the solver after S seconds with its best point\n"
  "                                (default inf: no limit)\n"
  "  --refine-signs                re-solve with the signs of the solution (at most 10 rounds)\n"
  "  --refine-euclidean            then minimize the Euclidean edge-length error from the\n"
  "                                solution (stress majorization, at most 1000 steps)\n"
  "  --keep-coincident             do not weld vertices at the same position (by default they\n"
  "                                are one vertex for the solve, so a file split along old\n"
  "                                seams gets no seam)\n"
  "  --help                        print this and exit\n"
  "\n"
  "The summary goes to stdout, the progress to stderr: on a terminal, one line updated in\n"
  "place for every step that runs over a second; into a file or a pipe, whole lines (the\n"
  "time of every step). The environment variable NP_PROGRESS_DELAY=S sets that second to S\n"
  "seconds (0: every step shown; inf: none). Nothing is written unless every file can be.\n"
  "Exit status 0 on success, 1 on bad input or failure, 2 on a bad command line.\n";

struct Settings
{
  std::string input = std::string(NP_MESH_DIR) + "/cow.off";
  std::string output = "cow_textured"; // the basename: without .obj or .glb
  std::string format;                  // obj or glb; empty: by the output name, else obj
  std::string texture_image;           // the image's path; empty: the checkerboard
  bool viewer = false;
  bool quiet = false;
  np_examples::Texture_settings texture;
};

// Takes the format from the output name's extension (.obj or .glb), which leaves the basename;
// returns an error message, or nothing.
std::optional<std::string> take_format_from_output(Settings& s)
{
  const std::string extension = lower_case(fs::path(s.output).extension().string());
  if(extension != ".obj" && extension != ".glb")
  {
    if(s.format.empty())
      s.format = "obj";
    return std::nullopt;
  }
  if(!s.format.empty() && "." + s.format != extension)
    return "--format " + s.format + " and the output name " + s.output + " disagree";
  s.format = extension.substr(1);
  s.output.erase(s.output.size() - extension.size());
  return std::nullopt;
}

// `text` as a whole number, if it is one (strtod's syntax: 1e-3, inf).
std::optional<double> number_in(const std::string& text)
{
  char* end = nullptr;
  errno = 0;
  const double number = std::strtod(text.c_str(), &end);
  if(text.empty() || end != text.c_str() + text.size() || (errno == ERANGE && std::isinf(number)))
    return std::nullopt;
  return number;
}

// `text` as a non-negative integer that fits an int, if it is one.
std::optional<int> count_in(const std::string& text)
{
  if(text.empty() || text.find_first_not_of("0123456789") != std::string::npos || text.size() > 9)
    return std::nullopt;
  return std::stoi(text);
}

// `text` as a vertex index, if it is one.
std::optional<std::size_t> index_in(const std::string& text)
{
  if(text.empty() || text.find_first_not_of("0123456789") != std::string::npos || text.size() > 18)
    return std::nullopt;
  return std::size_t(std::stoull(text));
}

// A problem of np_examples::settings_problem(), which names the option as the Python module
// does ("time limit takes ..."), in the command line's words ("--time-limit takes ...").
std::string as_option(const std::string& problem)
{
  const std::size_t takes = problem.find(" takes ");
  std::string name = problem.substr(0, takes);
  std::replace(name.begin(), name.end(), ' ', '-');
  std::replace(name.begin(), name.end(), '_', '-');
  return "--" + name + (takes == std::string::npos ? std::string() : problem.substr(takes));
}

// Parses the command line; returns an error message, or nothing on success. Here only the
// syntax of each option is checked; the values of the texture's settings are checked after, by
// np_examples::settings_problem(), as the Python module checks them.
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
    else if(arg == "--viewer")
      s.viewer = true;
    else if(arg == "--quiet")
      s.quiet = true;
    else if(arg == "--texture")
    {
      const auto v = value();
      if(!v || v->empty())
        return std::string("--texture takes an image file (PNG or JPEG)");
      s.texture_image = *v;
    }
    else if(arg == "--format")
    {
      const auto v = value();
      if(!v || (*v != "obj" && *v != "glb"))
        return std::string("--format takes obj or glb");
      s.format = *v;
    }
    else if(arg == "--keep-coincident")
      s.texture.keep_coincident = true;
    else if(arg == "--refine-signs")
      s.texture.refine_signs = true;
    else if(arg == "--refine-euclidean")
      s.texture.refine_euclidean = true;
    else if(arg == "--guess" || arg == "--fit" || arg == "--quality")
    {
      const auto v = value();
      if(!v)
        return arg + " takes a value";
      (arg == "--guess" ? s.texture.guess : arg == "--fit" ? s.texture.fit : s.texture.quality) = *v;
    }
    else if(arg == "--tolerance" || arg == "--time-limit")
    {
      const auto v = value();
      const std::optional<double> number = v ? number_in(*v) : std::nullopt;
      if(!number)
        return arg + " takes a number" + (arg == "--time-limit" ? std::string(" of seconds") : std::string());
      if(arg == "--tolerance")
        s.texture.tolerance = *number;
      else
        s.texture.time_limit = *number;
    }
    else if(arg == "--tiles")
    {
      const auto v = value();
      const std::size_t x = v ? v->find_first_of("xX") : std::string::npos;
      const std::optional<int> m = x != std::string::npos ? count_in(v->substr(0, x)) : std::nullopt;
      const std::optional<int> n = x != std::string::npos ? count_in(v->substr(x + 1)) : std::nullopt;
      if(!m || !n)
        return std::string("--tiles takes MxN, such as 2x3");
      s.texture.tiles_u = *m;
      s.texture.tiles_v = *n;
    }
    else if(arg == "--fixed-pair")
    {
      const auto v = value();
      const std::size_t comma = v ? v->find(',') : std::string::npos;
      const std::optional<std::size_t> a = comma != std::string::npos ? index_in(v->substr(0, comma)) : std::nullopt;
      const std::optional<std::size_t> b = comma != std::string::npos ? index_in(v->substr(comma + 1)) : std::nullopt;
      if(!a || !b)
        return std::string("--fixed-pair takes two vertex indices A,B such as 0,1");
      s.texture.fixed_pair = std::make_pair(*a, *b);
    }
    else if(arg.size() > 1 && arg[0] == '-')
      return "unknown option " + arg;
    else
      positional.push_back(arg);
  }
  if(const std::optional<std::string> problem = np_examples::settings_problem(s.texture))
    return as_option(*problem);
  if(positional.size() > 2)
    return std::string("too many arguments");
  if(positional.size() > 0) s.input = positional[0];
  if(positional.size() > 1) s.output = positional[1];
  else if(positional.size() == 1) s.output = fs::path(s.input).stem().string() + "_textured";
  if(const std::optional<std::string> disagree = take_format_from_output(s))
    return disagree;
  const fs::path name = fs::path(s.output).filename();
  if(name.empty() || name == "." || name == "..")
    return "the output basename must end in a file name, not '" + s.output + "'";
  return std::nullopt;
}

// What the output files are written from, once the work has made it.
struct Textured_soup
{
  Soup soup;
  UV uv;                          // one per vertex; NaN on a vertex on no face (written as (0, 0))
  std::vector<char> has_uv;       // false on a vertex on no face
  std::string report;             // output_report.txt
  std::vector<unsigned char> glb; // output.glb, also shown by output.html
};

using np_examples::Output_files;

// The uv layout of the faces whose vertices all have a uv.
std::vector<std::vector<std::array<double, 2> > > uv_layout(const Textured_soup& result)
{
  std::vector<std::vector<std::array<double, 2> > > layout;
  for(const Polygon& polygon : result.soup.polygons)
    if(polygon.size() > 2 && std::all_of(polygon.begin(), polygon.end(), [&](std::size_t i) { return result.has_uv[i]; }))
    {
      layout.emplace_back();
      for(std::size_t i : polygon)
        layout.back().push_back({result.uv[i].x(), result.uv[i].y()});
    }
  return layout;
}

// The files the settings ask for, with their writers, which read `result` and `texture` when
// np_examples::write_outputs() calls them, once the work has filled `result`.
Output_files output_files(const Settings& s, const np_examples::Texture_image& texture, const Textured_soup& result)
{
  const fs::path target = fs::absolute(s.output);
  const std::string stem = target.filename().string();
  Output_files out{target.parent_path(), stem, {}};
  auto add = [&](const std::string& suffix, std::function<bool(const std::string&)> write) {
    out.files.push_back({stem + suffix, write});
  };
  if(s.format == "obj")
    out.files = np_examples::textured_obj_files(stem, result.soup.points, result.soup.polygons, result.uv, texture);
  else
    add(".glb", [&result](const std::string& path) { return np_examples::write_bytes(path, result.glb); });
  add("_uv.svg", [&result](const std::string& path) { return np_examples::write_uv_layout_svg(path, uv_layout(result)); });
  add("_report.txt", [&result](const std::string& path) {
    std::ofstream text(path);
    text << result.report;
    return bool(text);
  });
  if(s.viewer)
    add(".html", [&result, stem](const std::string& path) {
      return np_examples::write_viewer_page(path, stem, result.glb, NP_THREE_JS_DIR);
    });
  return out;
}

// Says on stderr why the output files cannot be written; the exit status.
int cannot_write(const Output_files& files, const std::string& why)
{
  std::cerr << "error: cannot write " << np_examples::file_list(files) << ": " << why << "; nothing written\n";
  return 1;
}

// The texture of the settings: their image, checked, or the checkerboard; returns what is wrong
// with the image, if anything.
std::optional<std::string> load_texture(const Settings& s, np_examples::Texture_image& texture)
{
  if(s.texture_image.empty())
  {
    texture = np_examples::checkerboard_texture();
    return std::nullopt;
  }
  return np_examples::read_texture_image(s.texture_image, texture);
}

// Makes the glb of the textured soup: its faces cut into the triangles the library mapped (its
// triangulate_polygon_soup()), its faces of two corners as lines; returns why it cannot, if it
// cannot.
std::optional<std::string> make_glb(Textured_soup& result, const np_examples::Texture_image& texture,
                                    const std::string& name)
{
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<std::array<std::size_t, 2> > edges;
  SMP::triangulate_polygon_soup(result.soup.points, result.soup.polygons, std::back_inserter(triangles),
                                std::back_inserter(edges));
  return np_examples::glb_file(result.soup.points, result.uv, triangles, edges, texture, name, result.glb);
}

// The tool; main() turns what escapes it (a reader's or the allocator's exception) into exit 1.
int run(int argc, char** argv)
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
  // Everything that can be checked before the work is.
  np_examples::Texture_image texture;
  if(const std::optional<std::string> wrong = load_texture(s, texture))
  {
    std::cerr << "error: cannot read the texture " << s.texture_image << ": " << *wrong << "; nothing written\n";
    return 1;
  }
  if(s.viewer)
    if(const std::optional<std::string> wrong = np_examples::viewer_scripts_problem(NP_THREE_JS_DIR))
    {
      std::cerr << "error: --viewer: " << *wrong << "; nothing written\n";
      return 1;
    }
  Textured_soup result;
  const Output_files files = output_files(s, texture, result);
  if(const std::optional<std::string> problem = np_examples::output_problem(files))
    return cannot_write(files, *problem);
  np_examples::Progress_display progress(np_examples::Progress_display::mode_for_stderr(s.quiet), std::cerr.rdbuf(),
                                         np_examples::Progress_display::delay_from_environment());

  Soup& soup = result.soup;
  const std::optional<std::string> unread =
    progress.run("reading " + s.input, [&] { return np_examples::read_soup(s.input, soup.points, soup.polygons); });
  if(unread)
  {
    std::cerr << "error: cannot read " << s.input << ": " << *unread << '\n';
    return 1;
  }

  // The library leaves a vertex on no face alone, and the output files would carry its position
  // as it is; it refuses a non-finite coordinate on a face itself.
  if(const auto v = np_examples::first_non_finite_vertex(soup.points, soup.polygons))
    if(!v->on_face)
    {
      std::cerr << "error: vertex " << v->index << " of " << s.input << " is on no face and has a non-finite coordinate\n";
      return 1;
    }

  // The library writes the uv of every vertex on a face; the others keep NaN, no uv, which the
  // writers write as (0, 0) (vertex_uv.h): one vt per v in the OBJ, one uv per vertex in the glb.
  UV& uv = result.uv;
  uv.assign(soup.points.size(), Kernel::Point_2(std::nan(""), std::nan("")));
  SMP::Texture_polygon_mesh_report report;
  if(s.texture.fixed_pair &&
     (s.texture.fixed_pair->first >= soup.points.size() || s.texture.fixed_pair->second >= soup.points.size()))
  {
    std::cerr << "error: --fixed-pair: " << s.input << " has " << soup.points.size() << " vertices\n";
    return 1;
  }
  const SMP::Error_code status = progress.run("texturing " + std::to_string(soup.points.size()) + " vertices", [&] {
    return np_examples::texture_with_settings(soup.points, soup.polygons, CGAL::make_property_map(uv), s.texture, report,
                                              [&](const SMP::Norm_preserving_progress& p) {
                                                progress.set_fraction(p.fraction);
                                                return true;
                                              });
  });
  if(status != SMP::OK)
  {
    std::cerr << "error: " << SMP::norm_preserving_error_message(status) << ": " << report.message << '\n';
    return 1;
  }
  std::vector<char>& has_uv = result.has_uv;
  has_uv.resize(uv.size());
  for(std::size_t i = 0; i < uv.size(); ++i)
    has_uv[i] = np_examples::has_uv(uv[i]);

  std::size_t active = 0, constraints = 0, iterations = 0;
  double initial = 0, kkt = 0;
  std::string solver, stopped; // the solver and its setting; why a solve stopped short of its tolerance
  for(const SMP::Norm_preserving_report& r : report.reports)
  {
    if(!r.solver.method.empty())
      solver = r.solver.method;
    if(stopped.empty())
      stopped = r.solver.message;
    active += r.active_constraints;
    constraints += r.constraints;
    iterations = std::max<std::size_t>(iterations, std::size_t(r.solver.iterations));
    initial += r.initial_objective;
    kkt = std::max(kkt, r.solver.kkt_residual);
  }
  const SMP::Parameterization_distortion d =
    SMP::measure_soup_distortion(soup.points, soup.polygons, CGAL::make_property_map(uv), CGAL::make_property_map(has_uv));

  std::ostringstream summary;
  summary << s.input << ": " << soup.points.size() << " vertices, " << soup.polygons.size() << " faces, "
          << report.components << " component(s)";
  if(report.welded_vertices > 0)
    summary << ", " << report.welded_vertices << " coincident vertices welded";
  summary << '\n'
          << "objective (Eq. 3): " << initial << " at the guess -> " << report.objective << ", "
          << active << "/" << constraints << " sign constraints active, " << iterations
          << " solver iterations, KKT residual " << kkt << ", within " << report.optimality_gap
          << " of the optimum (certified)\n"
          << "solver: " << solver << (stopped.empty() ? std::string() : "; " + stopped) << '\n'
          << "time: " << report.seconds << " s\n"
          << "distortion: edge-length error " << d.edge_length_error << " (L1 " << d.l1_edge_length_error
          << "), flipped faces " << d.flipped_faces << "/" << d.faces << " ("
          << 100 * d.flipped_area_fraction << "% of the area)\n";
  std::ostringstream details;
  details << summary.str()
          << "initial guess: " << s.texture.guess << (s.texture.refine_signs ? ", sign refinement" : "")
          << (s.texture.refine_euclidean ? ", Euclidean refinement" : "") << ", tiles: " << s.texture.tiles_u << "x"
          << s.texture.tiles_v << '\n'
          << "scale of the best fit to 3D lengths: " << d.scale << '\n'
          << "mean / max angle distortion (degrees): " << d.mean_angle_distortion << " / " << d.max_angle_distortion << '\n'
          << "area distortion (RMS log ratio): " << d.area_distortion << '\n'
          << "L2 / Linf stretch: " << d.l2_stretch << " / " << d.linf_stretch << '\n'
          << "faces of zero uv area: " << d.degenerate_uv_faces << '\n'
          << "vertices on no face (no uv, written as vt 0 0): " << report.isolated_vertices << '\n'
          << "coincident vertices welded: " << report.welded_vertices << '\n'
          << "face corners dropped as repeats: " << report.repeated_corners << '\n'
          << "components of zero extent (mapped to a point): " << report.point_components << '\n';
  result.report = details.str();
  const std::optional<std::string> unwritten = progress.run("writing " + s.output, [&]() -> std::optional<std::string> {
    if(s.format == "glb" || s.viewer)
      if(std::optional<std::string> wrong = make_glb(result, texture, files.stem))
        return wrong;
    return np_examples::write_outputs(files);
  });
  if(unwritten)
    return cannot_write(files, *unwritten);
  if(!s.quiet)
    std::cout << summary.str() << "wrote " << np_examples::file_list(files) << '\n';
  return 0;
}

int main(int argc, char** argv)
{
  try
  {
    return run(argc, argv);
  }
  catch(const std::bad_alloc&)
  {
    std::cerr << "error: out of memory; nothing written\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << np_examples::first_line(e.what()) << "; nothing written\n";
  }
  catch(...)
  {
    std::cerr << "error: an unknown failure; nothing written\n";
  }
  return 1;
}
