// The command-line tool, and the main job: textures a mesh (by default the cow of CGAL's
// collection) with the norm-preserving parameterizer and writes a textured OBJ with its MTL
// and a checkerboard PNG, the UV layout as an SVG and a distortion report. Run with --help.

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_distortion.h>
#include <CGAL/Surface_mesh_parameterization/texture_polygon_mesh.h>
#include <CGAL/property_map.h>

#include "obj_soup_reader.h"
#include "texture_settings.h"
#include "textured_obj_writer.h"
#include "uv_layout_svg.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace fs = std::filesystem;
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
  "Lai & Cheng, with no cut and no seam, and writes\n"
  "  output.obj         the mesh with one vt per vertex, using output.mtl\n"
  "  output.mtl         a material whose texture is output.png\n"
  "  output.png         a checkerboard texture\n"
  "  output_uv.svg      the UV layout (flipped faces in red)\n"
  "  output_report.txt  the objective, the time and the distortion measures\n"
  "\n"
  "  input    OFF, OBJ, PLY, STL or GOCAD TS file (default: the cow of CGAL's collection)\n"
  "  output   basename of the files written (default: cow_textured)\n"
  "\n"
  "options:\n"
  "  --guess xy|combination|graph  initial guess (default xy: the paper's XY-MinMax)\n"
  "  --fit uniform|clamp|none      fit into texture space (default uniform: [0,1]^2,\n"
  "                                aspect kept; clamp: each axis to [0,1]; none: mesh units)\n"
  "  --tiles MxN                   repeat the texture M times along u, N along v (default 1x1)\n"
  "  --fixed-pair A,B              fix the edge between input vertices A and B (0-based);\n"
  "                                default: an automatic pair in every component\n"
  "  --quality draft|default|exact how close to the optimum the solver goes (default: default;\n"
  "                                draft: about 1% above, fastest; exact: certified to 1e-9)\n"
  "  --tolerance T                 the solver's tolerance (default: the quality's)\n"
  "  --time-limit S                stop the solver after S seconds with its best point\n"
  "  --refine-signs                re-solve with the signs of the solution (at most 10 rounds)\n"
  "  --refine-euclidean            then minimize the Euclidean edge-length error from the\n"
  "                                solution (stress majorization, at most 1000 steps)\n"
  "  --keep-coincident             do not weld vertices at the same position (by default they\n"
  "                                are one vertex for the solve, so a file split along old\n"
  "                                seams gets no seam)\n"
  "  --help                        print this and exit\n"
  "\n"
  "Nothing is written unless every file can be. Exit status 0 on success, 1 on bad input or\n"
  "failure, 2 on a bad command line.\n";

struct Settings
{
  std::string input = std::string(NP_MESH_DIR) + "/cow.off";
  std::string output = "cow_textured";
  np_examples::Texture_settings texture;
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
    else if(arg == "--keep-coincident")
      s.texture.keep_coincident = true;
    else if(arg == "--refine-signs")
      s.texture.refine_signs = true;
    else if(arg == "--refine-euclidean")
      s.texture.refine_euclidean = true;
    else if(arg == "--guess" || arg == "--fit" || arg == "--quality")
    {
      const auto v = value();
      std::string& setting = arg == "--guess" ? s.texture.guess : arg == "--fit" ? s.texture.fit : s.texture.quality;
      setting = v ? *v : std::string();
      if(const auto problem = np_examples::settings_problem(s.texture))
        return "--" + *problem;
    }
    else if(arg == "--tolerance" || arg == "--time-limit")
    {
      const auto v = value();
      std::istringstream in(v ? *v : std::string());
      double number = 0;
      char rest = 0;
      if(!(in >> number) || in >> rest || !(number > 0) || !std::isfinite(number))
        return arg + " takes a positive number" + (arg == "--time-limit" ? std::string(" of seconds") : std::string());
      if(arg == "--tolerance")
        s.texture.tolerance = number;
      else
        s.texture.time_limit = number;
    }
    else if(arg == "--tiles")
    {
      const auto v = value();
      char x = 0, rest = 0;
      std::istringstream in(v ? *v : std::string());
      if(!(in >> s.texture.tiles_u >> x >> s.texture.tiles_v) || (x != 'x' && x != 'X') || in >> rest ||
         s.texture.tiles_u < 1 || s.texture.tiles_v < 1)
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
      s.texture.fixed_pair = std::make_pair(std::size_t(a), std::size_t(b));
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
  const fs::path name = fs::path(s.output).filename();
  if(name.empty() || name == "." || name == "..")
    return "the output basename must end in a file name, not '" + s.output + "'";
  return std::nullopt;
}

// The standard error's own buffer, taken before any work can redirect std::cerr (the reader's
// messages are captured on the work's thread while the progress is shown).
std::streambuf* const terminal_buffer = std::cerr.rdbuf();

// Runs `work` and, when it takes more than a second, shows the elapsed time on stderr.
template <typename Work>
auto with_progress(const std::string& what, Work work)
{
  std::ostream terminal(terminal_buffer);
  auto result = std::async(std::launch::async, work);
  int seconds = 0;
  while(result.wait_for(std::chrono::seconds(1)) != std::future_status::ready)
    terminal << "\r" << what << "... " << ++seconds << " s" << std::flush;
  if(seconds > 0)
    terminal << "\r" << what << ": done in about " << seconds << " s\n";
  return result.get();
}

// Why CGAL 5.5's PLY soup reader cannot read the vertices of the file at `path`, if it cannot:
// it reads a missing x, y or z as 0, and crashes on coordinates that are not floating point or
// on a property declared before any element.
std::optional<std::string> ply_vertex_problem(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string line, word;
  if(!std::getline(in, line) || !(std::istringstream(line) >> word) || word != "ply")
    return std::nullopt; // not a PLY header: the reader says what is wrong
  bool in_element = false, in_vertex = false;
  std::map<std::string, std::string> types; // of the current vertex element's scalar properties, the first of a name
  auto vertex_problem = [&]() -> std::optional<std::string> {
    for(const std::string axis : {"x", "y", "z"})
    {
      const auto type = types.find(axis);
      if(type == types.end())
        return "its vertices have no " + axis + " coordinate";
      if(type->second != "float" && type->second != "float32" && type->second != "double" && type->second != "float64")
        return "its vertex coordinate " + axis + " is of type " + type->second + " (CGAL 5.5 reads float and double)";
    }
    return std::nullopt;
  };
  while(std::getline(in, line))
  {
    std::istringstream words(line);
    if(!(words >> word) || (word != "element" && word != "property" && word != "end_header"))
      continue;
    if(word == "property" && !in_element)
      return std::string("a property is declared before any element");
    if(word != "property" && in_vertex) // the vertex element ends here
      if(const std::optional<std::string> problem = vertex_problem())
        return problem;
    std::string type, name;
    if(word == "end_header")
      return std::nullopt;
    if(word == "element")
    {
      in_element = true;
      in_vertex = words >> name && (name == "vertex" || name == "vertices");
      types.clear();
    }
    else if(in_vertex && words >> type >> name && type != "list")
      types.emplace(name, type);
  }
  return std::nullopt; // no end of the header: the reader says what is wrong
}

// The first line of `text` (an exception's message may hold several).
std::string first_line(const std::string& text)
{
  return text.substr(0, text.find('\n'));
}

// The standard streams captured while it lives (a reader's messages), restored even when the
// reader throws.
struct Captured_streams
{
  std::ostringstream text;
  std::streambuf* const err = std::cerr.rdbuf(text.rdbuf());
  std::streambuf* const out = std::cout.rdbuf(text.rdbuf());
  ~Captured_streams()
  {
    std::cerr.rdbuf(err);
    std::cout.rdbuf(out);
  }
};

// Reads `path`: OBJ with the tool's own reader (obj_soup_reader.h), the other formats with
// CGAL's polygon soup reader; on failure, says what is wrong.
std::optional<std::string> read_soup(const std::string& path, Soup& soup)
{
  std::error_code ec;
  if(!fs::exists(path, ec))
    return "no such file";
  if(!fs::is_regular_file(path, ec))
    return "not a regular file";
  if(fs::file_size(path, ec) == 0)
    return "the file is empty";
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if(extension != ".off" && extension != ".obj" && extension != ".ply" && extension != ".stl" && extension != ".ts")
    return "not a mesh format: " + (extension.empty() ? std::string("no extension") : extension) +
           " (OFF, OBJ, PLY, STL and GOCAD TS files are read)";
  const std::string format = extension.substr(1);
  if(extension == ".obj")
  {
    const std::optional<std::string> wrong = np_examples::read_obj_soup(path, soup.points, soup.polygons);
    if(wrong)
      return "not a valid obj file: " + *wrong;
    if(soup.polygons.empty())
      return "the " + format + " file has no face";
    return std::nullopt;
  }
  if(extension == ".ply")
    if(const std::optional<std::string> problem = ply_vertex_problem(path))
      return "not a readable ply file: " + *problem;
  // The reader says why it failed on the standard streams: keep its first line that names an
  // error, else its first that is not blank, a progress line ("Parsing ASCII file...") or a
  // binary STL's header. It throws on some malformed counts.
  Captured_streams said;
  bool read = false;
  try
  {
    read = CGAL::IO::read_polygon_soup(path, soup.points, soup.polygons, CGAL::parameters::verbose(true));
  }
  catch(const std::bad_alloc&)
  {
    return "not a valid " + format + " file: its counts ask for more memory than there is";
  }
  catch(const std::length_error&)
  {
    return "not a valid " + format + " file: a count is negative or out of range";
  }
  catch(const std::exception& e)
  {
    return "not a valid " + format + " file: the reader failed (" + first_line(e.what()) + ")";
  }
  if(read && !soup.polygons.empty())
    return std::nullopt;
  std::istringstream lines(said.text.str());
  std::string reason, line;
  while(std::getline(lines, line))
    if(line.find("rror") != std::string::npos)
    {
      reason = line;
      break;
    }
    else if(reason.empty() && line.find_first_not_of(" \t\r") != std::string::npos &&
            line.compare(0, 7, "Parsing") != 0 && line.compare(0, 7, "header:") != 0)
      reason = line;
  if(read || (!soup.points.empty() && soup.polygons.empty() && reason.find("empty") != std::string::npos))
    return "the " + format + " file has no face";
  return "not a valid " + format + " file" + (reason.empty() ? std::string() : ": " + reason);
}

// The five files the tool writes: their directory and names.
struct Output_files
{
  fs::path directory;
  std::string stem;
  std::vector<std::string> names;
};

Output_files output_files(const std::string& basename)
{
  const fs::path target = fs::absolute(basename);
  const std::string stem = target.filename().string();
  return {target.parent_path(), stem, {stem + ".obj", stem + ".mtl", stem + ".png", stem + "_uv.svg", stem + "_report.txt"}};
}

// Why the files cannot be written, if that is known before writing them.
std::optional<std::string> output_problem(const Output_files& files)
{
  std::error_code ec;
  if(!fs::exists(files.directory, ec))
    return "no such directory: " + files.directory.string();
  if(!fs::is_directory(files.directory, ec))
    return "not a directory: " + files.directory.string();
  for(const std::string& name : files.names)
    if(fs::is_directory(files.directory / name, ec))
      return (files.directory / name).string() + " is a directory";
  return std::nullopt;
}

// A directory this run created, removed with what it holds when it goes out of scope.
struct Scratch_directory
{
  fs::path path;
  ~Scratch_directory()
  {
    std::error_code ec;
    if(!path.empty())
      fs::remove_all(path, ec);
  }
};

// Writes every output file into a new scratch directory beside them, then moves them in place
// (replacing files of the same names): on any failure nothing of this run is left behind, and
// the reason is returned.
std::optional<std::string> write_outputs(const Settings& s, const Soup& soup, const UV& uv,
                                         const std::vector<char>& has_uv, const std::string& report)
{
  const Output_files files = output_files(s.output);
  if(const std::optional<std::string> problem = output_problem(files))
    return problem;
  std::error_code ec;
  Scratch_directory scratch; // stem.partial, or stem.partial.1, ...
  for(int k = 0; scratch.path.empty(); ++k)
  {
    const fs::path candidate =
      files.directory / (files.stem + ".partial" + (k > 0 ? "." + std::to_string(k) : std::string()));
    if(fs::create_directory(candidate, ec))
      scratch.path = candidate;
    else if((ec && ec != std::errc::file_exists) || k == 100)
      return "cannot create a directory in " + files.directory.string() + (ec ? ": " + ec.message() : std::string());
  }
  std::ofstream text((scratch.path / files.names[4]).string());
  text << report;
  text.close();
  std::vector<std::vector<std::array<double, 2> > > layout;
  for(const Polygon& polygon : soup.polygons)
    if(polygon.size() > 2 && std::all_of(polygon.begin(), polygon.end(), [&](std::size_t i) { return has_uv[i]; }))
    {
      layout.emplace_back();
      for(std::size_t i : polygon)
        layout.back().push_back({uv[i].x(), uv[i].y()});
    }
  if(!text || !np_examples::write_textured_obj((scratch.path / files.stem).string(), soup.points, soup.polygons, uv) ||
     !np_examples::write_uv_layout_svg((scratch.path / files.names[3]).string(), layout))
    return "cannot write into " + scratch.path.string();
  for(std::size_t k = 0; k < files.names.size(); ++k)
  {
    fs::rename(scratch.path / files.names[k], files.directory / files.names[k], ec);
    if(ec)
    {
      const std::string reason = "cannot move " + files.names[k] + " into place: " + ec.message();
      for(std::size_t moved = 0; moved < k; ++moved)
        fs::remove(files.directory / files.names[moved], ec);
      return reason;
    }
  }
  return std::nullopt;
}

// Says on stderr why the output files cannot be written; the exit status.
int cannot_write(const Settings& s, const std::string& why)
{
  std::cerr << "error: cannot write " << s.output << ".obj/.mtl/.png/_uv.svg/_report.txt: " << why << "; nothing written\n";
  return 1;
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
  if(const std::optional<std::string> problem = output_problem(output_files(s.output)))
    return cannot_write(s, *problem); // known before the work

  Soup soup;
  const std::optional<std::string> unread = with_progress("reading " + s.input, [&] { return read_soup(s.input, soup); });
  if(unread)
  {
    std::cerr << "error: cannot read " << s.input << ": " << *unread << '\n';
    return 1;
  }

  // The library leaves a vertex on no face alone; the OBJ would carry its position as it is.
  std::vector<char> on_face(soup.points.size(), 0);
  for(const Polygon& polygon : soup.polygons)
    for(std::size_t i : polygon)
      if(i < on_face.size()) // an index out of range is the library's to report
        on_face[i] = 1;
  for(std::size_t i = 0; i < soup.points.size(); ++i)
  {
    const Point_3& p = soup.points[i];
    if(!on_face[i] && !(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z())))
    {
      std::cerr << "error: vertex " << i << " of " << s.input << " is on no face and has a non-finite coordinate\n";
      return 1;
    }
  }

  // Vertices on no face keep {0, 0}: one vt per v in the OBJ.
  const Kernel::Point_2 no_uv(std::nan(""), std::nan(""));
  UV uv(soup.points.size(), no_uv);
  SMP::Texture_polygon_mesh_report report;
  if(s.texture.fixed_pair &&
     (s.texture.fixed_pair->first >= soup.points.size() || s.texture.fixed_pair->second >= soup.points.size()))
  {
    std::cerr << "error: --fixed-pair: the file has " << soup.points.size() << " vertices\n";
    return 1;
  }
  const SMP::Error_code status = with_progress("texturing " + std::to_string(soup.points.size()) + " vertices", [&] {
    return np_examples::texture_with_settings(soup.points, soup.polygons, CGAL::make_property_map(uv), s.texture, report,
                                              [](const SMP::Norm_preserving_progress&) { return true; });
  });
  if(status != SMP::OK)
  {
    std::cerr << "error: " << SMP::norm_preserving_error_message(status) << ": " << report.message << '\n';
    return 1;
  }
  std::vector<char> has_uv(uv.size());
  for(std::size_t i = 0; i < uv.size(); ++i)
  {
    has_uv[i] = !std::isnan(uv[i].x());
    if(!has_uv[i]) uv[i] = Kernel::Point_2(0, 0);
  }

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
  if(const auto unwritten = with_progress("writing " + s.output, [&] { return write_outputs(s, soup, uv, has_uv, details.str()); }))
    return cannot_write(s, *unwritten);
  std::cout << summary.str() << "wrote " << s.output << ".obj, .mtl, .png, _uv.svg, _report.txt\n";
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
    std::cerr << "error: " << first_line(e.what()) << "; nothing written\n";
  }
  catch(...)
  {
    std::cerr << "error: an unknown failure; nothing written\n";
  }
  return 1;
}
