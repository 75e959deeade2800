// Writes a mesh with per-vertex uvs as an OBJ with `vt` lines and its MTL, whose material's
// texture is an image file beside them, so that any viewer (MeshLab, Blender) shows the texture
// on the model: the one writer of the command-line tool and of the Python module's write_obj().

#ifndef NP_EXAMPLES_TEXTURED_OBJ_WRITER_H
#define NP_EXAMPLES_TEXTURED_OBJ_WRITER_H

#include "image_file.h"
#include "output_files.h"
#include "vertex_uv.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace np_examples {

// Writes the material library `path`: one material, "texture", whose diffuse map is the image
// file `image_name` (relative to the MTL file).
inline bool write_texture_mtl(const std::string& path, const std::string& image_name)
{
  std::ofstream mtl(path);
  mtl << "newmtl texture\nKa 1 1 1\nKd 1 1 1\nKs 0 0 0\nmap_Kd " << image_name << '\n';
  return bool(mtl);
}

// Writes the OBJ file `path`, using the material of the library `mtl_name` (relative to the
// OBJ file): the soup's vertices in their order (17 digits: the doubles themselves), one `vt`
// per vertex from `uv` (2D points, one per vertex; written_uv() of each), and its faces as they
// are (a face of two vertices as a line, a face of one skipped).
template <typename PointRange, typename PolygonRange, typename UVRange>
bool write_textured_obj(const std::string& path, const std::string& mtl_name, const PointRange& points,
                        const PolygonRange& polygons, const UVRange& uv)
{
  std::ofstream obj(path);
  obj.precision(17);
  obj << "mtllib " << mtl_name << "\nusemtl texture\n";
  for(const auto& p : points)
    obj << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for(const auto& t : uv)
  {
    const std::array<double, 2> written = written_uv(t);
    obj << "vt " << written[0] << ' ' << written[1] << '\n';
  }
  for(const auto& polygon : polygons)
  {
    if(polygon.size() < 2)
      continue;
    obj << (polygon.size() == 2 ? 'l' : 'f');
    for(std::size_t i : polygon)
      obj << ' ' << i + 1 << '/' << i + 1;
    obj << '\n';
  }
  return bool(obj);
}

// A vertex with a non-finite coordinate, and whether it is on a face.
struct Non_finite_vertex
{
  std::size_t index;
  bool on_face;
};

// The first vertex of the soup with a non-finite coordinate, if any: an OBJ would carry it as it
// is ("nan"), which other readers refuse. (A vertex on a face is refused by the package's calls
// too; one on no face only by the writers.) Indices out of range are skipped.
template <typename PointRange, typename PolygonRange>
std::optional<Non_finite_vertex> first_non_finite_vertex(const PointRange& points, const PolygonRange& polygons)
{
  std::vector<char> on_face(points.size(), 0);
  for(const auto& polygon : polygons)
    for(std::size_t i : polygon)
      if(i < on_face.size())
        on_face[i] = 1;
  std::size_t i = 0;
  for(const auto& p : points)
  {
    if(!(std::isfinite(double(p.x())) && std::isfinite(double(p.y())) && std::isfinite(double(p.z()))))
      return Non_finite_vertex{i, on_face[i] != 0};
    ++i;
  }
  return std::nullopt;
}

// "vertex 3 is on no face and has a non-finite coordinate"
inline std::string non_finite_vertex_message(const Non_finite_vertex& v)
{
  return "vertex " + std::to_string(v.index) + (v.on_face ? "" : " is on no face and") + " has a non-finite coordinate";
}

// The files of a textured OBJ named `stem`, for write_outputs(): stem.obj, stem.mtl and the
// texture image stem.png or stem.jpg. They read the soup, the uvs and the image when written:
// these must outlive the writing.
template <typename PointRange, typename PolygonRange, typename UVRange>
std::vector<Output_file> textured_obj_files(const std::string& stem, const PointRange& points,
                                            const PolygonRange& polygons, const UVRange& uv,
                                            const Texture_image& texture)
{
  return {{stem + ".obj",
           [&points, &polygons, &uv, stem](const std::string& path) {
             return write_textured_obj(path, stem + ".mtl", points, polygons, uv);
           }},
          {stem + ".mtl",
           [image = stem + texture.extension](const std::string& path) { return write_texture_mtl(path, image); }},
          {stem + texture.extension, [&texture](const std::string& path) { return write_bytes(path, texture.bytes); }}};
}

} // namespace np_examples

#endif
