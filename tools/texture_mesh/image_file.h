// An image as the tool's outputs carry it (a file's bytes, copied beside an OBJ or embedded in a
// glb), and decoded pixels.

#ifndef NP_EXAMPLES_IMAGE_FILE_H
#define NP_EXAMPLES_IMAGE_FILE_H

#include <string>
#include <vector>

namespace np_examples {

// An image file as it is, and what it holds.
struct Texture_image
{
  std::vector<unsigned char> bytes;
  std::string mime_type; // image/png or image/jpeg
  std::string extension; // .png or .jpg: the name a copy of it takes
  int width = 0, height = 0;
};

// Pixels: 8-bit RGB, rows from the top.
struct Rgb_pixels
{
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
};

} // namespace np_examples

#endif
