// Reads an OBJ file as a polygon soup for the command-line tool: the vertices (`v`), the faces
// (`f`) and the lines (`l`, each segment a face of two corners: an edge of the graph), with
// corners `i`, `i/t`, `i//n` or `i/t/n` and negative (relative) indices; every other statement
// (`vt`, `vn`, `o`, `g`, `s`, `usemtl`, `mtllib`, `p`, curves) is skipped. CGAL 5.5's reader
// refuses a file with an `l` statement, which Blender writes for loose edges and the tool
// itself writes for faces of two corners (doc/decisions.md, "The command-line tool reads OBJ itself").

#ifndef NP_EXAMPLES_OBJ_SOUP_READER_H
#define NP_EXAMPLES_OBJ_SOUP_READER_H

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace np_examples {

// Appends the soup of the OBJ file `path` to `points` (constructed from three doubles) and
// `polygons` (vectors of indices into `points`); returns what is wrong, with the line, if
// anything. A `#` ends a line; an `l` of one vertex is a face of one corner, as an `f` is.
template <typename PointRange, typename PolygonRange>
std::optional<std::string> read_obj_soup(const std::string& path, PointRange& points, PolygonRange& polygons)
{
  typedef typename PointRange::value_type Point;
  typedef typename PolygonRange::value_type Polygon;
  std::ifstream in(path);
  if(!in)
    return std::string("cannot open the file");
  const std::size_t base = points.size(); // the file's vertex 1 is points[base]
  std::vector<std::pair<std::size_t, long long> > ahead; // (line, 1-based index) of a vertex not read yet
  std::string line, statement;
  std::size_t number = 0;
  while(std::getline(in, line))
  {
    ++number;
    const std::size_t first_line = number;
    if(number == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) // UTF-8 byte order mark
      line.erase(0, 3);
    for(;;) // a comment cut, CRLF and trailing blanks dropped, continued lines joined
    {
      line = line.substr(0, line.find('#'));
      while(!line.empty() && std::isspace(static_cast<unsigned char>(line.back())))
        line.pop_back();
      std::string next;
      if(line.empty() || line.back() != '\\' || !std::getline(in, next))
        break;
      line.back() = ' ';
      line += next;
      ++number;
    }
    if(!line.empty() && line.back() == '\\')
      line.pop_back();
    std::istringstream words(line);
    if(!(words >> statement))
      continue;
    auto where = [&]() { return "line " + std::to_string(first_line) + ": "; };
    if(statement == "v")
    {
      double xyz[3];
      std::string word;
      for(double& c : xyz)
      {
        char* end = nullptr;
        if(words >> word)
          c = std::strtod(word.c_str(), &end);
        if(end == nullptr || end == word.c_str() || *end != '\0')
          return where() + "a vertex needs three coordinates";
      }
      points.push_back(Point(xyz[0], xyz[1], xyz[2]));
    }
    else if(statement == "f" || statement == "l")
    {
      Polygon corners;
      std::string corner;
      while(words >> corner)
      {
        char* end = nullptr;
        const long long index = std::strtoll(corner.c_str(), &end, 10);
        if(end == corner.c_str() || (*end != '\0' && *end != '/') || index == 0)
          return where() + "'" + corner + "' is not a vertex index";
        const long long absolute = index < 0 ? (long long)(points.size() - base) + index + 1 : index;
        if(absolute < 1)
          return where() + "'" + corner + "' refers to no vertex before it";
        if(std::size_t(absolute) > points.size() - base)
          ahead.emplace_back(first_line, absolute);
        corners.push_back(base + std::size_t(absolute - 1));
      }
      if(corners.empty())
        return where() + "'" + statement + "' without vertices";
      if(statement == "f" || corners.size() == 1)
        polygons.push_back(corners);
      else
        for(std::size_t k = 0; k + 1 < corners.size(); ++k)
          polygons.push_back(Polygon{corners[k], corners[k + 1]});
    }
  }
  for(const auto& reference : ahead)
    if(std::size_t(reference.second) > points.size() - base)
      return "line " + std::to_string(reference.first) + ": vertex " + std::to_string(reference.second) + " of " +
             std::to_string(points.size() - base);
  return std::nullopt;
}

} // namespace np_examples

#endif
