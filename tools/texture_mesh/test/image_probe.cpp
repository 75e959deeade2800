// Checks and makes the images of the command-line tool's tests, through the tool's own decoder
// and checkerboard (libpng, libjpeg):
//   image_probe checkerboard FILE           exit 0 if FILE is, pixel for pixel, the tool's
//                                           checkerboard: 512 x 512 pixels, 8 x 8 cells of
//                                           cream (235,225,200) and blue (40,60,140), cream in
//                                           the top left corner
//   image_probe covers FILE SHARE R,G,B...  exit 0 if each colour covers at least SHARE of the
//                                           pixels, under any light from 40% to 130% as bright
//   image_probe write-jpeg FILE R,G,B R,G,B [W H]
//                                           writes a JPEG of W x H pixels (512 x 512) of square
//                                           cells of 64 pixels of the two colours (a texture the
//                                           tests can recognize)
//   image_probe write-png FILE W H          writes a PNG of W x H pixels of the same cells in
//                                           the checkerboard's colours

#include "checkerboard.h"
#include "texture_image.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

using np_examples::Rgb_pixels;

// Decodes the image file `path` whole into `image`.
bool read_image(const std::string& path, Rgb_pixels& image)
{
  std::ifstream in(path, std::ios::binary);
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  bool interlaced = false;
  const auto wrong = np_examples::decode_image(
    bytes, image.width, image.height,
    [&](int y, const unsigned char* rgb) {
      image.rgb.resize(std::size_t(3) * std::size_t(image.width) * std::size_t(image.height));
      std::copy(rgb, rgb + 3 * std::size_t(image.width), image.rgb.begin() + std::ptrdiff_t(3 * std::size_t(image.width) * std::size_t(y)));
    },
    interlaced);
  if(wrong || interlaced)
  {
    std::cerr << path << ": " << (wrong ? *wrong : std::string("an interlaced PNG, which image_probe does not read")) << '\n';
    return false;
  }
  return true;
}

bool parse_colour(const std::string& text, double colour[3])
{
  char comma[2];
  std::istringstream in(text);
  return bool(in >> colour[0] >> comma[0] >> colour[1] >> comma[1] >> colour[2]) && comma[0] == ',' && comma[1] == ',';
}

// Cell (x / 64 + y / 64) of the 512-pixel checkerboard: cream when even, blue when odd.
int checkerboard(const std::string& path)
{
  Rgb_pixels image;
  if(!read_image(path, image))
    return 1;
  if(image.width != 512 || image.height != 512)
  {
    std::cerr << path << ": " << image.width << " x " << image.height << ", not 512 x 512\n";
    return 1;
  }
  const unsigned char cream[3] = {235, 225, 200}, blue[3] = {40, 60, 140};
  for(int y = 0; y < 512; ++y)
    for(int x = 0; x < 512; ++x)
    {
      const unsigned char* expected = (x / 64 + y / 64) % 2 == 1 ? blue : cream;
      const unsigned char* pixel = &image.rgb[3 * (std::size_t(y) * 512 + std::size_t(x))];
      if(pixel[0] != expected[0] || pixel[1] != expected[1] || pixel[2] != expected[2])
      {
        std::cerr << path << ": pixel (" << x << ", " << y << ") is " << int(pixel[0]) << "," << int(pixel[1]) << ","
                  << int(pixel[2]) << ", not the checkerboard's\n";
        return 1;
      }
    }
  std::cout << path << ": the checkerboard, pixel for pixel\n";
  return 0;
}

// A pixel shows `colour` when it is that colour scaled by a brightness in [0.4, 1.3] (how a lit
// surface shows its texture), within 12% of its length.
bool shows(const unsigned char* pixel, const double colour[3])
{
  double dot = 0, norm = 0;
  for(int c = 0; c < 3; ++c)
  {
    dot += pixel[c] * colour[c];
    norm += colour[c] * colour[c];
  }
  const double brightness = dot / norm;
  if(brightness < 0.4 || brightness > 1.3)
    return false;
  double off = 0;
  for(int c = 0; c < 3; ++c)
    off += std::pow(pixel[c] - brightness * colour[c], 2);
  return std::sqrt(off) <= 0.12 * brightness * std::sqrt(norm);
}

int covers(const std::string& path, double share, const std::vector<std::string>& colours)
{
  Rgb_pixels image;
  if(!read_image(path, image))
    return 1;
  int status = 0;
  const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
  for(const std::string& text : colours)
  {
    double colour[3];
    if(!parse_colour(text, colour))
    {
      std::cerr << "not a colour R,G,B: " << text << '\n';
      return 2;
    }
    std::size_t count = 0;
    for(std::size_t i = 0; i < pixels; ++i)
      count += shows(&image.rgb[3 * i], colour);
    std::cout << path << ": colour " << text << " covers " << 100. * double(count) / double(pixels) << "% of the pixels\n";
    if(double(count) < share * double(pixels))
      status = 1;
  }
  return status;
}

// The file closed when it goes out of scope.
struct File_closer
{
  void operator()(FILE* file) const { std::fclose(file); }
};

int write_jpeg(const std::string& path, const std::string& first, const std::string& second, int width, int height)
{
  double colour[2][3];
  if(!parse_colour(first, colour[0]) || !parse_colour(second, colour[1]))
    return 2;
  unsigned char rgb[2][3];
  for(int k = 0; k < 2; ++k)
    for(int c = 0; c < 3; ++c)
      rgb[k][c] = static_cast<unsigned char>(colour[k][c]);
  const Rgb_pixels pixels = np_examples::checker_pixels(width, height, 64, rgb[0], rgb[1]);
  std::unique_ptr<FILE, File_closer> file(std::fopen(path.c_str(), "wb"));
  if(!file)
    return 1;
  jpeg_compress_struct jpeg;
  jpeg_error_mgr errors;
  jpeg.err = jpeg_std_error(&errors); // exits on an error: a test helper may
  jpeg_create_compress(&jpeg);
  jpeg_stdio_dest(&jpeg, file.get());
  jpeg.image_width = JDIMENSION(width);
  jpeg.image_height = JDIMENSION(height);
  jpeg.input_components = 3;
  jpeg.in_color_space = JCS_RGB;
  jpeg_set_defaults(&jpeg);
  jpeg_set_quality(&jpeg, 92, TRUE);
  jpeg_start_compress(&jpeg, TRUE);
  while(jpeg.next_scanline < jpeg.image_height)
  {
    JSAMPROW row = const_cast<unsigned char*>(&pixels.rgb[3 * std::size_t(width) * std::size_t(jpeg.next_scanline)]);
    jpeg_write_scanlines(&jpeg, &row, 1);
  }
  jpeg_finish_compress(&jpeg);
  jpeg_destroy_compress(&jpeg);
  return std::fclose(file.release()) == 0 ? 0 : 1;
}

int write_png(const std::string& path, int width, int height)
{
  const std::vector<unsigned char> bytes = np_examples::encode_png(np_examples::checker_pixels(
    width, height, 64, np_examples::checkerboard_colours[0], np_examples::checkerboard_colours[1]));
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  return !bytes.empty() && out ? 0 : 1;
}

int size_in(const std::string& text)
{
  const int size = std::atoi(text.c_str());
  return size > 0 && size <= 1 << 20 ? size : 0;
}

} // namespace

int main(int argc, char** argv)
{
  const std::vector<std::string> args(argv + 1, argv + argc);
  if(args.size() == 2 && args[0] == "checkerboard")
    return checkerboard(args[1]);
  if(args.size() >= 4 && args[0] == "covers")
    return covers(args[1], std::stod(args[2]), std::vector<std::string>(args.begin() + 3, args.end()));
  if(args.size() == 4 && args[0] == "write-jpeg")
    return write_jpeg(args[1], args[2], args[3], 512, 512);
  if(args.size() == 6 && args[0] == "write-jpeg" && size_in(args[4]) && size_in(args[5]))
    return write_jpeg(args[1], args[2], args[3], size_in(args[4]), size_in(args[5]));
  if(args.size() == 4 && args[0] == "write-png" && size_in(args[2]) && size_in(args[3]))
    return write_png(args[1], size_in(args[2]), size_in(args[3]));
  std::cerr << "usage: image_probe checkerboard FILE | covers FILE SHARE R,G,B... | write-jpeg FILE R,G,B R,G,B [W H] | "
               "write-png FILE W H\n";
  return 2;
}
