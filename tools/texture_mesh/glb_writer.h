// Makes a binary glTF 2.0 file (.glb) of a mesh with per-vertex uvs and its texture image, the
// format game engines and web viewers load: one glTF vertex per vertex of the soup (the map has
// no seam, so no vertex needs splitting), with its position, normal and uv, the faces'
// triangles (and the soup's edges, as lines) as indices, and the image embedded, wrapped with
// REPEAT so that tiles beyond [0,1]^2 show. A vertex without uv gets written_uv()'s (0, 0).
// glTF holds 32-bit floats and 32-bit lengths: a coordinate beyond float range, or a file over
// 4 GiB, is refused with a message rather than written as inf or with a wrapped length.

#ifndef NP_EXAMPLES_GLB_WRITER_H
#define NP_EXAMPLES_GLB_WRITER_H

#include "image_file.h"
#include "vertex_uv.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace np_examples {

// Unit normals of the vertices: the area-weighted mean of the normals of their triangles; a
// vertex on no triangle, or where they cancel, gets +z (glTF wants a unit vector everywhere).
template <typename PointRange>
std::vector<std::array<double, 3> > vertex_normals(const PointRange& points,
                                                   const std::vector<std::array<std::size_t, 3> >& triangles)
{
  std::vector<std::array<double, 3> > normals(points.size(), {0., 0., 0.});
  for(const auto& t : triangles)
  {
    double d[2][3];
    for(int c = 0; c < 3; ++c)
    {
      d[0][c] = double(points[t[1]][c]) - double(points[t[0]][c]);
      d[1][c] = double(points[t[2]][c]) - double(points[t[0]][c]);
    }
    const double cross[3] = {d[0][1] * d[1][2] - d[0][2] * d[1][1], d[0][2] * d[1][0] - d[0][0] * d[1][2],
                             d[0][0] * d[1][1] - d[0][1] * d[1][0]}; // twice the area, along the normal
    for(std::size_t i : t)
      for(int c = 0; c < 3; ++c)
        normals[i][c] += cross[c];
  }
  for(auto& n : normals)
  {
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if(length > 0 && std::isfinite(length))
      n = {n[0] / length, n[1] / length, n[2] / length};
    else
      n = {0., 0., 1.};
  }
  return normals;
}

// The binary chunk of a glb, with the views into it that the JSON chunk describes.
class Glb_buffer
{
public:
  // Appends `count` little-endian values, each of `size` bytes, as a new buffer view; returns
  // its index. `target` is 34962 for vertex attributes, 34963 for indices, 0 for none.
  template <typename Integer>
  std::size_t add_integers(const std::vector<Integer>& values, std::size_t size, int target)
  {
    const std::size_t start = begin_view();
    for(Integer value : values)
      for(std::size_t b = 0; b < size; ++b)
        m_bytes.push_back(static_cast<unsigned char>(std::uint64_t(value) >> (8 * b)));
    return end_view(start, target);
  }
  std::size_t add_floats(const std::vector<float>& values)
  {
    std::vector<std::uint32_t> bits(values.size());
    for(std::size_t i = 0; i < values.size(); ++i)
      std::memcpy(&bits[i], &values[i], 4);
    return add_integers(bits, 4, 34962);
  }
  std::size_t add_bytes(const std::vector<unsigned char>& bytes)
  {
    const std::size_t start = begin_view();
    m_bytes.insert(m_bytes.end(), bytes.begin(), bytes.end());
    return end_view(start, 0);
  }
  const std::vector<unsigned char>& bytes() const { return m_bytes; }
  // The "bufferViews" array of the JSON chunk.
  std::string views_json() const { return "[" + m_views.str() + "]"; }

private:
  std::size_t begin_view()
  {
    m_bytes.resize((m_bytes.size() + 3) / 4 * 4, 0); // every view 4-byte aligned, as accessors need
    return m_bytes.size();
  }
  std::size_t end_view(std::size_t start, int target)
  {
    m_views << (m_count > 0 ? "," : "") << "{\"buffer\":0,\"byteOffset\":" << start
            << ",\"byteLength\":" << m_bytes.size() - start;
    if(target != 0)
      m_views << ",\"target\":" << target;
    m_views << "}";
    return m_count++;
  }

  std::vector<unsigned char> m_bytes;
  std::ostringstream m_views;
  std::size_t m_count = 0;
};

// `text` as a JSON string; bytes outside printable ASCII become '_' (a name need not be UTF-8).
inline std::string json_string(const std::string& text)
{
  std::string quoted = "\"";
  for(char c : text)
  {
    if(c == '"' || c == '\\')
      quoted += '\\';
    quoted += (c >= 0x20 && c < 0x7F) ? c : '_';
  }
  return quoted + "\"";
}

inline void append_u32(std::vector<unsigned char>& out, std::size_t value)
{
  for(int b = 0; b < 4; ++b)
    out.push_back(static_cast<unsigned char>(value >> (8 * b)));
}

// Whether `x` is a float: finite and within float range (a double beyond it has no float).
inline bool fits_in_float(double x)
{
  return std::abs(x) <= double(std::numeric_limits<float>::max());
}

// Makes `glb`, the glb of the soup `points` (3D points) with `uv` (2D points, one per point),
// drawn as the triangles `triangles` and the lines `edges` (indices into `points`; where there
// are neither, as points), textured with `texture`, named `name`; returns why it cannot, if it
// cannot: a coordinate or a uv beyond float range, or a file over 4 GiB.
template <typename PointRange, typename UVRange>
std::optional<std::string> glb_file(const PointRange& points, const UVRange& uv,
                                    const std::vector<std::array<std::size_t, 3> >& triangles,
                                    const std::vector<std::array<std::size_t, 2> >& edges,
                                    const Texture_image& texture, const std::string& name,
                                    std::vector<unsigned char>& glb)
{
  const std::size_t n = points.size();
  // The binary chunk's length, each view padded to 4 bytes, checked before anything is made.
  const int index_size = n < 0xFF ? 1 : n < 0xFFFF ? 2 : 4; // the largest value of each is reserved
  auto padded = [](std::uint64_t bytes) { return (bytes + 3) / 4 * 4; };
  const std::uint64_t binary_length = std::uint64_t(n) * (12 + 12 + 8) +
                                      padded(std::uint64_t(triangles.size()) * 3 * std::uint64_t(index_size)) +
                                      padded(std::uint64_t(edges.size()) * 2 * std::uint64_t(index_size)) +
                                      padded(texture.bytes.size());
  const std::uint64_t most = 0xFFFFFFFFu; // glb lengths are 32-bit
  auto too_large = [](std::uint64_t bytes) {
    return "the glb would be " + std::to_string(bytes) + " bytes; glTF's binary format holds at most 4 GiB";
  };
  if(binary_length > most - 28 || n > most)
    return too_large(binary_length + 28);

  std::vector<float> positions, normals, texcoords;
  positions.reserve(3 * n);
  texcoords.reserve(2 * n);
  float low[3], high[3];
  std::fill(low, low + 3, std::numeric_limits<float>::infinity());
  std::fill(high, high + 3, -std::numeric_limits<float>::infinity());
  std::size_t i = 0;
  for(const auto& p : points)
  {
    for(int c = 0; c < 3; ++c)
    {
      if(!fits_in_float(double(p[c])))
        return "vertex " + std::to_string(i) + " has a coordinate beyond the range of glTF's 32-bit floats";
      positions.push_back(float(p[c]));
      low[c] = std::min(low[c], positions.back());
      high[c] = std::max(high[c], positions.back());
    }
    ++i;
  }
  i = 0;
  for(const auto& t : uv)
  {
    const std::array<double, 2> written = written_uv(t);
    if(!fits_in_float(written[0]) || !fits_in_float(1 - written[1]))
      return "the uv of vertex " + std::to_string(i) + " is beyond the range of glTF's 32-bit floats";
    texcoords.push_back(float(written[0]));
    texcoords.push_back(float(1 - written[1])); // glTF's v runs down the image
    ++i;
  }
  for(const auto& normal : vertex_normals(points, triangles))
    normals.insert(normals.end(), normal.begin(), normal.end());

  Glb_buffer buffer;
  std::ostringstream accessors, primitives;
  // min and max must be the data's: each float written as the double it is, which a JSON reader
  // (in doubles) reads back exactly.
  accessors.precision(std::numeric_limits<double>::max_digits10);
  std::size_t accessor_count = 0;
  auto add_accessor = [&](std::size_t view, int component_type, std::size_t count, const char* type) {
    accessors << (accessor_count > 0 ? "," : "") << "{\"bufferView\":" << view << ",\"componentType\":"
              << component_type << ",\"count\":" << count << ",\"type\":\"" << type << "\"";
    return accessor_count++;
  };
  add_accessor(buffer.add_floats(positions), 5126, n, "VEC3");
  accessors << ",\"min\":[" << double(low[0]) << "," << double(low[1]) << "," << double(low[2]) << "],\"max\":["
            << double(high[0]) << "," << double(high[1]) << "," << double(high[2]) << "]}";
  add_accessor(buffer.add_floats(normals), 5126, n, "VEC3");
  accessors << "}";
  add_accessor(buffer.add_floats(texcoords), 5126, n, "VEC2");
  accessors << "}";

  // The smallest index type that holds every index.
  const int index_type = index_size == 1 ? 5121 : index_size == 2 ? 5123 : 5125;
  auto add_primitive = [&](int mode, const std::vector<std::size_t>& indices) {
    primitives << (primitives.tellp() > 0 ? "," : "")
               << "{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,\"TEXCOORD_0\":2},\"material\":0,\"mode\":" << mode;
    if(!indices.empty())
    {
      primitives << ",\"indices\":"
                 << add_accessor(buffer.add_integers(indices, std::size_t(index_size), 34963), index_type,
                                 indices.size(), "SCALAR");
      accessors << "}";
    }
    primitives << "}";
  };
  if(!triangles.empty())
  {
    std::vector<std::size_t> indices;
    for(const auto& t : triangles)
      indices.insert(indices.end(), t.begin(), t.end());
    add_primitive(4, indices);
  }
  if(!edges.empty())
  {
    std::vector<std::size_t> indices;
    for(const auto& e : edges)
      indices.insert(indices.end(), e.begin(), e.end());
    add_primitive(1, indices);
  }
  if(triangles.empty() && edges.empty())
    add_primitive(0, {});
  const std::size_t image_view = buffer.add_bytes(texture.bytes);

  std::ostringstream json;
  json << "{\"asset\":{\"version\":\"2.0\",\"generator\":\"texture_mesh (CGAL norm-preserving parameterization)\"},"
       << "\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0,\"name\":" << json_string(name) << "}],"
       << "\"meshes\":[{\"name\":" << json_string(name) << ",\"primitives\":[" << primitives.str() << "]}],"
       << "\"materials\":[{\"name\":\"texture\",\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0},"
       << "\"metallicFactor\":0,\"roughnessFactor\":1},\"doubleSided\":true}],"
       << "\"textures\":[{\"sampler\":0,\"source\":0}],"
       << "\"samplers\":[{\"magFilter\":9729,\"minFilter\":9987,\"wrapS\":10497,\"wrapT\":10497}],"
       << "\"images\":[{\"bufferView\":" << image_view << ",\"mimeType\":\"" << texture.mime_type << "\"}],"
       << "\"accessors\":[" << accessors.str() << "],\"bufferViews\":" << buffer.views_json() << ","
       << "\"buffers\":[{\"byteLength\":" << buffer.bytes().size() << "}]}";

  // Header, then the JSON chunk padded with spaces and the binary chunk with zeros to 4 bytes.
  std::string text = json.str();
  text.resize((text.size() + 3) / 4 * 4, ' ');
  std::vector<unsigned char> binary = buffer.bytes();
  binary.resize((binary.size() + 3) / 4 * 4, 0);
  const std::uint64_t total = 12 + 8 + std::uint64_t(text.size()) + 8 + binary.size();
  if(total > most)
    return too_large(total);
  glb = {'g', 'l', 'T', 'F'};
  append_u32(glb, 2);
  append_u32(glb, 12 + 8 + text.size() + 8 + binary.size());
  append_u32(glb, text.size());
  glb.insert(glb.end(), {'J', 'S', 'O', 'N'});
  glb.insert(glb.end(), text.begin(), text.end());
  append_u32(glb, binary.size());
  glb.insert(glb.end(), {'B', 'I', 'N', 0});
  glb.insert(glb.end(), binary.begin(), binary.end());
  return std::nullopt;
}

} // namespace np_examples

#endif
