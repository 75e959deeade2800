// Writes a mesh with per-vertex uvs as an OBJ with `vt` lines, its MTL, and a checkerboard
// PNG texture, so that any viewer (MeshLab, Blender) shows the texture on the model.

#ifndef NP_EXAMPLES_TEXTURED_OBJ_WRITER_H
#define NP_EXAMPLES_TEXTURED_OBJ_WRITER_H

#include <array>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace np_examples {

inline std::uint32_t crc32(const std::uint8_t* data, std::size_t size, std::uint32_t crc = 0)
{
  crc = ~crc;
  for(std::size_t i = 0; i < size; ++i)
  {
    crc ^= data[i];
    for(int k = 0; k < 8; ++k)
      crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

inline void append_u32(std::vector<std::uint8_t>& out, std::uint32_t value)
{
  for(int shift = 24; shift >= 0; shift -= 8)
    out.push_back(std::uint8_t(value >> shift));
}

inline void append_chunk(std::vector<std::uint8_t>& png, const char* type, const std::vector<std::uint8_t>& data)
{
  append_u32(png, std::uint32_t(data.size()));
  const std::size_t start = png.size();
  png.insert(png.end(), type, type + 4);
  png.insert(png.end(), data.begin(), data.end());
  append_u32(png, crc32(png.data() + start, png.size() - start));
}

// An RGB PNG with uncompressed (stored) deflate blocks: no zlib needed.
inline bool write_png(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb)
{
  std::vector<std::uint8_t> raw;
  for(int y = 0; y < height; ++y)
  {
    raw.push_back(0); // filter: none
    raw.insert(raw.end(), rgb.begin() + std::ptrdiff_t(3) * width * y, rgb.begin() + std::ptrdiff_t(3) * width * (y + 1));
  }
  std::vector<std::uint8_t> zlib = {0x78, 0x01};
  for(std::size_t pos = 0; pos < raw.size() || pos == 0; pos += 65535)
  {
    const std::size_t size = std::min<std::size_t>(65535, raw.size() - pos);
    zlib.push_back(pos + size == raw.size() ? 1 : 0);
    zlib.push_back(std::uint8_t(size & 0xFF)); zlib.push_back(std::uint8_t(size >> 8));
    zlib.push_back(std::uint8_t(~size & 0xFF)); zlib.push_back(std::uint8_t((~size >> 8) & 0xFF));
    zlib.insert(zlib.end(), raw.begin() + std::ptrdiff_t(pos), raw.begin() + std::ptrdiff_t(pos + size));
    if(size == 0) break;
  }
  std::uint32_t a = 1, b = 0;
  for(std::uint8_t byte : raw) { a = (a + byte) % 65521; b = (b + a) % 65521; }
  append_u32(zlib, (b << 16) | a);

  std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::vector<std::uint8_t> header;
  append_u32(header, std::uint32_t(width));
  append_u32(header, std::uint32_t(height));
  header.insert(header.end(), {8, 2, 0, 0, 0}); // 8-bit RGB, no interlace
  append_chunk(png, "IHDR", header);
  append_chunk(png, "IDAT", zlib);
  append_chunk(png, "IEND", {});
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
  return bool(out);
}

inline bool write_checkerboard_png(const std::string& path, int size = 512, int squares = 8)
{
  std::vector<std::uint8_t> rgb(std::size_t(3) * size * size);
  for(int y = 0; y < size; ++y)
    for(int x = 0; x < size; ++x)
    {
      const bool dark = ((x * squares / size) + (y * squares / size)) % 2 == 1;
      const std::array<std::uint8_t, 3> color = dark ? std::array<std::uint8_t, 3>{40, 60, 140}
                                                     : std::array<std::uint8_t, 3>{235, 225, 200};
      std::copy(color.begin(), color.end(), rgb.begin() + 3 * (std::ptrdiff_t(y) * size + x));
    }
  return write_png(path, size, size, rgb);
}

// Writes `basename`.obj, `basename`.mtl and `basename`.png: the soup's vertices in their
// order, one `vt` per vertex from `uv` (2D points, one per vertex), and its faces as
// they are (a face of two vertices as a line).
template <typename PointRange, typename PolygonRange, typename UVRange>
bool write_textured_obj(const std::string& basename, const PointRange& points, const PolygonRange& polygons,
                        const UVRange& uv)
{
  const std::string stem = basename.substr(basename.find_last_of('/') + 1);
  std::ofstream mtl(basename + ".mtl");
  mtl << "newmtl checkerboard\nKa 1 1 1\nKd 1 1 1\nKs 0 0 0\nmap_Kd " << stem << ".png\n";
  std::ofstream obj(basename + ".obj");
  obj.precision(17);
  obj << "mtllib " << stem << ".mtl\nusemtl checkerboard\n";
  for(const auto& p : points)
    obj << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for(const auto& t : uv)
    obj << "vt " << t.x() << ' ' << t.y() << '\n';
  for(const auto& polygon : polygons)
  {
    if(polygon.size() < 2)
      continue;
    obj << (polygon.size() == 2 ? 'l' : 'f');
    for(std::size_t i : polygon)
      obj << ' ' << i + 1 << '/' << i + 1;
    obj << '\n';
  }
  return bool(obj) && bool(mtl) && write_checkerboard_png(basename + ".png");
}

} // namespace np_examples

#endif
