// libFuzzer target: the bytes are an OFF file, read by CGAL's reader as a polygon soup and as
// a Surface_mesh, then textured by the whole-mesh calls with each initial guess. Whatever the
// input, a call returns OK with a finite uv in the unit square for every vertex on a face and
// none for the others, or an error with a message and the uv map untouched; anything else
// (a crash, a sanitizer report, NaN) aborts, and libFuzzer keeps the input.

#include <CGAL/Surface_mesh_parameterization/Combination_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/Graph_based_initial_guess.h>
#include <CGAL/Surface_mesh_parameterization/texture_polygon_mesh.h>

#include <CGAL/IO/OFF.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_2 Point_2;
typedef Kernel::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;

const Point_2 sentinel(-123.5, 456.25);
const std::size_t max_elements = 2000; // vertices and faces: keeps one input well under a second

void check(bool condition, const char* what)
{
  if(condition) return;
  std::fprintf(stderr, "fuzz_texture_off: %s\n", what);
  std::abort();
}

// `written[i]`: whether vertex i is on a face, hence must get a uv on success.
void check_result(SMP::Error_code status, const SMP::Texture_polygon_mesh_report& report,
                  const std::vector<Point_2>& uv, const std::vector<bool>& on_face)
{
  check(report.status == status, "the report disagrees with the returned code");
  if(status != SMP::OK)
  {
    check(!report.message.empty(), "a failure without a message");
    for(const Point_2& p : uv)
      check(p == sentinel, "a failure wrote to the uv map");
    return;
  }
  for(std::size_t i = 0; i < uv.size(); ++i)
  {
    if(!on_face[i])
    {
      check(uv[i] == sentinel, "a vertex on no face got a uv");
      continue;
    }
    check(std::isfinite(uv[i].x()) && std::isfinite(uv[i].y()), "a non-finite uv");
    check(uv[i].x() >= 0 && uv[i].x() <= 1 && uv[i].y() >= 0 && uv[i].y() <= 1, "a uv outside the unit square");
  }
}

template <typename Guess>
void texture_soup(const std::vector<Point_3>& points, const std::vector<std::vector<std::size_t> >& polygons,
                  const std::vector<bool>& on_face)
{
  std::vector<Point_2> uv(points.size(), sentinel);
  SMP::Texture_polygon_mesh_report report;
  const SMP::Error_code status = SMP::texture_polygon_soup(points, polygons, CGAL::make_property_map(uv),
                                                           SMP::parameters::initial_guess(Guess()).combine(SMP::parameters::report(report)));
  check_result(status, report, uv, on_face);
}

template <typename Guess>
void texture_mesh(const Mesh& mesh)
{
  Mesh copy = mesh;
  auto uvmap = copy.add_property_map<Mesh::Vertex_index, Point_2>("v:uv", sentinel).first;
  SMP::Texture_polygon_mesh_report report;
  const SMP::Error_code status =
    SMP::texture_polygon_mesh(copy, uvmap, SMP::parameters::initial_guess(Guess()).combine(SMP::parameters::report(report)));
  std::vector<Point_2> uv;
  std::vector<bool> on_face;
  for(auto v : vertices(copy))
  {
    uv.push_back(get(uvmap, v));
    on_face.push_back(!copy.is_isolated(v));
  }
  check_result(status, report, uv, on_face);
}

std::vector<std::vector<std::string> > tokens_of_lines(const std::string& text)
{
  std::vector<std::vector<std::string> > lines;
  std::istringstream in(text);
  std::string line, token;
  while(std::getline(in, line))
  {
    std::istringstream words(line.substr(0, line.find('#')));
    std::vector<std::string> tokens;
    while(words >> token) tokens.push_back(token);
    if(!tokens.empty()) lines.push_back(tokens);
  }
  return lines;
}

bool is_count(const std::string& token, std::size_t& value)
{
  if(token.empty() || token.size() > 9 || token.find_first_not_of("0123456789") != std::string::npos)
    return false;
  value = std::stoul(token);
  return true;
}

bool is_number(const std::string& token)
{
  char* end = nullptr;
  std::strtod(token.c_str(), &end);
  return end == token.c_str() + token.size();
}

// The inputs handed to CGAL's reader: plain OFF ("OFF", the counts, vertex lines of three
// numbers, face lines of a size n and n indices, no colour, at most `max_elements` of each),
// because CGAL 5.5's OFF scanner has undefined behaviour of its own elsewhere, which the
// fuzzer found at once: it casts a negative face size, read as a double, to std::size_t, and
// reads past the end of a line's entries when colours are missing or short
// (File_scanner_OFF::scan_facet and scan_color). Within plain OFF everything else is left
// to the mutations: any number, any index (out of range, repeated), any face size.
bool is_plain_off(const std::string& text)
{
  const auto lines = tokens_of_lines(text);
  std::size_t vertices = 0, faces = 0, edges = 0;
  if(lines.size() < 2 || lines[0] != std::vector<std::string>{"OFF"} || lines[1].size() != 3 ||
     !is_count(lines[1][0], vertices) || !is_count(lines[1][1], faces) || !is_count(lines[1][2], edges) ||
     vertices > max_elements || faces > max_elements || lines.size() != 2 + vertices + faces)
    return false;
  for(std::size_t k = 2; k < 2 + vertices; ++k)
    if(lines[k].size() != 3 || !is_number(lines[k][0]) || !is_number(lines[k][1]) || !is_number(lines[k][2]))
      return false;
  for(std::size_t k = 2 + vertices; k < lines.size(); ++k)
  {
    std::size_t size = 0, index = 0;
    if(!is_count(lines[k][0], size) || lines[k].size() != size + 1)
      return false;
    for(std::size_t i = 1; i <= size; ++i)
      if(!is_count(lines[k][i], index)) return false;
  }
  return true;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  if(!is_plain_off(text))
    return 0;

  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  std::istringstream soup_in(text);
  if(CGAL::IO::read_OFF(soup_in, points, polygons))
  {
    std::vector<bool> on_face(points.size(), false);
    for(const auto& polygon : polygons)
      for(std::size_t i : polygon)
        if(i < points.size()) on_face[i] = true;
    texture_soup<SMP::XY_min_max_initial_guess>(points, polygons, on_face);
    texture_soup<SMP::Combination_initial_guess>(points, polygons, on_face);
    texture_soup<SMP::Graph_based_initial_guess>(points, polygons, on_face);
  }

  Mesh mesh;
  std::istringstream mesh_in(text);
  if(CGAL::IO::read_OFF(mesh_in, mesh))
  {
    texture_mesh<SMP::XY_min_max_initial_guess>(mesh);
    texture_mesh<SMP::Combination_initial_guess>(mesh);
    texture_mesh<SMP::Graph_based_initial_guess>(mesh);
  }
  return 0;
}
