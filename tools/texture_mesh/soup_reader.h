// Reads a mesh file as a polygon soup, for the command-line tool and the Python module's
// read_mesh(): OBJ and PLY with the readers of this directory (obj_soup_reader.h,
// ply_soup_reader.h), OFF, STL and GOCAD TS with CGAL's polygon soup reader, guarded: what any of
// them cannot read is a message, never a crash or an exception (but std::bad_alloc from the
// readers of this directory, which the caller reports as it reports running out of memory).

#ifndef NP_EXAMPLES_SOUP_READER_H
#define NP_EXAMPLES_SOUP_READER_H

#include "obj_soup_reader.h"
#include "ply_soup_reader.h"

#include <CGAL/IO/polygon_soup_io.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <new>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace np_examples {

// `name` in lower case (file name extensions are compared so).
inline std::string lower_case(std::string name)
{
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return name;
}

// The first line of `text` (an exception's message may hold several).
inline std::string first_line(const std::string& text)
{
  return text.substr(0, text.find('\n'));
}

// The standard streams captured while it lives (a reader's messages), restored even when the
// reader throws. One capture at a time in the process (the module's calls may run on several
// threads): the streams are the process's.
struct Captured_streams
{
  static std::mutex& one_at_a_time()
  {
    static std::mutex mutex;
    return mutex;
  }
  const std::lock_guard<std::mutex> lock{one_at_a_time()};
  std::ostringstream text;
  std::streambuf* const err = std::cerr.rdbuf(text.rdbuf());
  std::streambuf* const out = std::cout.rdbuf(text.rdbuf());
  ~Captured_streams()
  {
    std::cerr.rdbuf(err);
    std::cout.rdbuf(out);
  }
};

// The whole file `path` in `text`; false if it cannot be read.
inline bool read_whole_file(const std::string& path, std::string& text)
{
  std::ifstream in(path, std::ios::binary);
  if(!in.seekg(0, std::ios::end))
    return false;
  const std::streamoff size = in.tellg();
  if(size < 0 || !in.seekg(0, std::ios::beg))
    return false;
  text.resize(std::size_t(size));
  return bool(in.read(&text[0], size));
}

// The PLY file `path`, read with ply_soup_reader.h; returns what is wrong, if anything.
template <typename PointRange, typename PolygonRange>
std::optional<std::string> read_ply_file(const std::string& path, PointRange& points, PolygonRange& polygons)
{
  std::string text;
  if(!read_whole_file(path, text))
    return std::string("cannot read the file");
  Ply_header header;
  std::size_t data = 0;
  if(const std::optional<std::string> wrong = read_ply_header(text, header, data))
    return "not a valid ply file: " + *wrong;
  if(!has_ply_face_element(header))
    return "the ply file has " + ply_element_names(header) + "; no face element";
  if(const std::optional<std::string> wrong = read_ply_data(text, data, header, points, polygons))
    return "not a valid ply file: " + *wrong;
  return std::nullopt;
}

// The file `path` of a format CGAL's polygon soup reader reads (OFF, STL, GOCAD TS), whose
// lower-case name is `format`; returns what is wrong, if anything.
template <typename PointRange, typename PolygonRange>
std::optional<std::string> read_cgal_soup(const std::string& path, const std::string& format, PointRange& points,
                                          PolygonRange& polygons)
{
  // The reader says why it failed on the standard streams: keep its first line that names an
  // error, else its first that is not blank, a progress line ("Parsing ASCII file...") or a
  // binary STL's header. It throws on some malformed counts.
  Captured_streams said;
  bool read = false;
  try
  {
    read = CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(true));
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
  if(read && !polygons.empty())
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
  if(read || (!points.empty() && polygons.empty() && reason.find("empty") != std::string::npos))
    return "the " + format + " file has no face";
  return "not a valid " + format + " file" + (reason.empty() ? std::string() : ": " + reason);
}

// Reads the mesh file `path` (OFF, OBJ, PLY, STL or GOCAD TS, by its extension) into `points`
// (3D points constructed from three doubles) and `polygons` (vectors of indices), in the file's
// order; returns what is wrong, if anything: no such file, not a mesh format, a file its reader
// cannot read, or one with no face.
template <typename PointRange, typename PolygonRange>
std::optional<std::string> read_soup(const std::string& path, PointRange& points, PolygonRange& polygons)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  if(!fs::exists(path, ec))
    return std::string("no such file");
  if(!fs::is_regular_file(path, ec))
    return std::string("not a regular file");
  if(fs::file_size(path, ec) == 0)
    return std::string("the file is empty");
  const std::string extension = lower_case(fs::path(path).extension().string());
  if(extension != ".off" && extension != ".obj" && extension != ".ply" && extension != ".stl" && extension != ".ts")
    return "not a mesh format: " + (extension.empty() ? std::string("no extension") : extension) +
           " (OFF, OBJ, PLY, STL and GOCAD TS files are read)";
  const std::string format = extension.substr(1);
  std::optional<std::string> wrong;
  if(extension == ".obj")
  {
    wrong = read_obj_soup(path, points, polygons);
    if(wrong)
      wrong = "not a valid obj file: " + *wrong;
  }
  else if(extension == ".ply")
    wrong = read_ply_file(path, points, polygons);
  else
    return read_cgal_soup(path, format, points, polygons);
  if(!wrong && polygons.empty())
    wrong = "the " + format + " file has no face";
  return wrong;
}

} // namespace np_examples

#endif
