// The default texture of the command-line tool and of the Python module's write_obj(): a
// checkerboard, encoded as a PNG by libpng.

#ifndef NP_EXAMPLES_CHECKERBOARD_H
#define NP_EXAMPLES_CHECKERBOARD_H

#include "image_file.h"

#include <png.h>

#include <cstddef>
#include <cstring>
#include <vector>

namespace np_examples {

// The checkerboard's colours: cream, and blue.
inline constexpr unsigned char checkerboard_colours[2][3] = {{235, 225, 200}, {40, 60, 140}};
constexpr int checkerboard_size = 512, checkerboard_cell = 64; // 8 x 8 cells

// `width` x `height` pixels of square cells of `cell` pixels, of the colour `first` where the
// cell's column plus its row is even, else `second`.
inline Rgb_pixels checker_pixels(int width, int height, int cell, const unsigned char first[3],
                                 const unsigned char second[3])
{
  Rgb_pixels pixels{width, height, std::vector<unsigned char>(std::size_t(3) * std::size_t(width) * std::size_t(height))};
  for(int y = 0; y < height; ++y)
    for(int x = 0; x < width; ++x)
      std::memcpy(&pixels.rgb[3 * (std::size_t(y) * std::size_t(width) + std::size_t(x))],
                  (x / cell + y / cell) % 2 == 0 ? first : second, 3);
  return pixels;
}

// The PNG file of `pixels`, encoded by libpng (empty if libpng fails).
inline std::vector<unsigned char> encode_png(const Rgb_pixels& pixels)
{
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = png_uint_32(pixels.width);
  png.height = png_uint_32(pixels.height);
  png.format = PNG_FORMAT_RGB;
  png_alloc_size_t size = 0;
  std::vector<unsigned char> bytes;
  if(png_image_write_get_memory_size(png, size, 0, pixels.rgb.data(), 0, nullptr))
  {
    bytes.resize(size);
    if(png_image_write_to_memory(&png, bytes.data(), &size, 0, pixels.rgb.data(), 0, nullptr))
      bytes.resize(size);
    else
      bytes.clear();
  }
  png_image_free(&png);
  return bytes;
}

// The default texture: 512 x 512 pixels, 8 x 8 cells of cream and blue, as a PNG file (no bytes
// if libpng fails, which the writers report).
inline Texture_image checkerboard_texture()
{
  const Rgb_pixels pixels = checker_pixels(checkerboard_size, checkerboard_size, checkerboard_cell,
                                           checkerboard_colours[0], checkerboard_colours[1]);
  return {encode_png(pixels), "image/png", ".png", pixels.width, pixels.height};
}

} // namespace np_examples

#endif
