// A texture image of the user's (the command-line tool's --texture): a PNG or JPEG file, checked
// before any work by decoding it row by row through Debian's libpng and libjpeg, one row buffer
// for the whole image; its bytes are kept as they are, to be copied beside an OBJ or embedded in
// a glb. The decoders' state is owned by guard objects, so that every way out (a decoder's error,
// which jumps back with longjmp, an exception such as std::bad_alloc) releases it.

#ifndef NP_EXAMPLES_TEXTURE_IMAGE_H
#define NP_EXAMPLES_TEXTURE_IMAGE_H

#include "image_file.h"

#include <png.h>

#include <csetjmp>
#include <cstddef>
#include <cstdio> // before jpeglib.h, which needs FILE and size_t
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include <jerror.h>
#include <jpeglib.h>

namespace np_examples {

// The largest width and height of a texture taken: what GPUs and WebGL commonly take.
constexpr int max_texture_side = 16384;

// Receives each row of a decoded image: its index from the top, and its width's RGB bytes.
using Image_rows = std::function<void(int row, const unsigned char* rgb)>;

inline bool starts_with_png_signature(const std::vector<unsigned char>& bytes)
{
  return bytes.size() >= 8 && png_sig_cmp(bytes.data(), 0, 8) == 0;
}

inline bool starts_with_jpeg_signature(const std::vector<unsigned char>& bytes)
{
  return bytes.size() >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF;
}

// Why an image of `width` x `height` pixels is not taken, if it is not.
inline std::optional<std::string> image_size_problem(const char* format, unsigned long width, unsigned long height)
{
  if(width <= (unsigned long)max_texture_side && height <= (unsigned long)max_texture_side)
    return std::nullopt;
  return std::string("the ") + format + " image is " + std::to_string(width) + " x " + std::to_string(height) +
         " pixels: larger than " + std::to_string(max_texture_side) + " pixels a side, which GPUs do not take";
}

// ------------------------------------------------------------------------------------ PNG

// libpng's state for reading a PNG file in memory, destroyed with the guard. libpng reports
// errors through a callback that must not return: it keeps the message and jumps back to the
// setjmp() of the step under way (png_header(), png_rows()), which then returns false.
struct Png_reader
{
  const std::vector<unsigned char>& bytes;
  std::size_t at = 8; // the signature, checked
  char message[256] = "";
  png_structp png = nullptr;
  png_infop info = nullptr;

  explicit Png_reader(const std::vector<unsigned char>& file) : bytes(file)
  {
    png = png_create_read_struct(PNG_LIBPNG_VER_STRING, this, &error, &warning);
    if(png)
      info = png_create_info_struct(png);
    if(png && info)
      png_set_read_fn(png, this, &read);
  }
  ~Png_reader() { png_destroy_read_struct(png ? &png : nullptr, info ? &info : nullptr, nullptr); }
  Png_reader(const Png_reader&) = delete;
  Png_reader& operator=(const Png_reader&) = delete;

  static void error(png_structp png, png_const_charp text)
  {
    Png_reader* self = static_cast<Png_reader*>(png_get_error_ptr(png));
    std::snprintf(self->message, sizeof self->message, "%s", text);
    png_longjmp(png, 1);
  }
  static void warning(png_structp, png_const_charp) {}
  static void read(png_structp png, png_bytep out, png_size_t length)
  {
    Png_reader* self = static_cast<Png_reader*>(png_get_io_ptr(png));
    if(self->bytes.size() - self->at < length)
      png_error(png, "the file ends before the image does");
    std::memcpy(out, self->bytes.data() + self->at, length);
    self->at += length;
  }
};

// Reads the header; false on an error (its message in the reader). No C++ object lives in a
// function that calls setjmp(), so that a longjmp() skips no destructor.
inline bool png_header(Png_reader& r, png_uint_32& width, png_uint_32& height)
{
  if(setjmp(png_jmpbuf(r.png)))
    return false;
  png_set_sig_bytes(r.png, 8);
  png_read_info(r.png, r.info);
  width = png_get_image_width(r.png, r.info);
  height = png_get_image_height(r.png, r.info);
  return true;
}

// Decodes every row as 8-bit RGB into `row` (3 * width bytes), passing each to `rows` (in a
// non-interlaced image; an interlaced one is decoded, but its rows are complete only at the end,
// and are not passed), then reads the file to its end; false on an error.
inline bool png_rows(Png_reader& r, png_uint_32 height, unsigned char* row, std::size_t row_bytes, const Image_rows& rows,
                     bool& interlaced)
{
  if(setjmp(png_jmpbuf(r.png)))
    return false;
  png_set_expand(r.png);
  png_set_strip_16(r.png);
  png_set_strip_alpha(r.png);
  png_set_gray_to_rgb(r.png);
  const int passes = png_set_interlace_handling(r.png);
  png_read_update_info(r.png, r.info);
  if(png_get_rowbytes(r.png, r.info) != row_bytes)
    png_error(r.png, "an unexpected row size");
  interlaced = passes > 1;
  for(int pass = 0; pass < passes; ++pass)
    for(png_uint_32 y = 0; y < height; ++y)
    {
      png_read_row(r.png, row, nullptr);
      if(!interlaced && rows)
        rows(int(y), row);
    }
  png_read_end(r.png, nullptr);
  return true;
}

// Decodes the PNG `bytes`, passing each row to `rows`; returns why it cannot (libpng's reason),
// or why the image is not taken.
inline std::optional<std::string> decode_png(const std::vector<unsigned char>& bytes, int& width, int& height,
                                             const Image_rows& rows, bool& interlaced)
{
  Png_reader reader(bytes);
  if(!reader.png || !reader.info)
    return std::string("libpng cannot start (out of memory)");
  png_uint_32 w = 0, h = 0;
  if(!png_header(reader, w, h))
    return "not a valid PNG image: " + std::string(reader.message);
  if(const std::optional<std::string> problem = image_size_problem("PNG", w, h))
    return problem;
  width = int(w);
  height = int(h);
  std::vector<unsigned char> row(std::size_t(3) * w);
  if(!png_rows(reader, h, row.data(), row.size(), rows, interlaced))
    return "not a valid PNG image: " + std::string(reader.message);
  return std::nullopt;
}

// ------------------------------------------------------------------------------------ JPEG

// libjpeg's state for reading a JPEG file, destroyed with the guard. libjpeg reports errors
// through a callback that must not return: it keeps the message and jumps back to the setjmp()
// of the step under way. A truncated file is only a warning to libjpeg (it pads the image with
// gray), and is kept as an error here: the texture would not be the user's.
struct Jpeg_reader
{
  jpeg_error_mgr manager{};      // first: libjpeg's pointer to it is one to the reader
  jpeg_decompress_struct info{}; // zeroed: jpeg_destroy_decompress() is a no-op until created
  std::jmp_buf back;
  char message[JMSG_LENGTH_MAX] = "";
  bool truncated = false;

  Jpeg_reader()
  {
    info.err = jpeg_std_error(&manager);
    manager.error_exit = &error_exit;
    manager.emit_message = &emit_message;
  }
  ~Jpeg_reader() { jpeg_destroy_decompress(&info); }
  Jpeg_reader(const Jpeg_reader&) = delete;
  Jpeg_reader& operator=(const Jpeg_reader&) = delete;

  static Jpeg_reader* of(j_common_ptr info) { return reinterpret_cast<Jpeg_reader*>(info->err); }
  static void error_exit(j_common_ptr info)
  {
    Jpeg_reader* self = of(info);
    info->err->format_message(info, self->message);
    std::longjmp(self->back, 1);
  }
  static void emit_message(j_common_ptr info, int level)
  {
    Jpeg_reader* self = of(info);
    if(level < 0 && info->err->msg_code == JWRN_JPEG_EOF && !self->truncated)
    {
      self->truncated = true;
      info->err->format_message(info, self->message);
    }
  }
};

// Reads the header of the JPEG `bytes`; false on an error (its message in the reader). No C++
// object lives in a function that calls setjmp().
inline bool jpeg_header(Jpeg_reader& r, const std::vector<unsigned char>& bytes)
{
  if(setjmp(r.back))
    return false;
  jpeg_create_decompress(&r.info);
  jpeg_mem_src(&r.info, bytes.data(), static_cast<unsigned long>(bytes.size()));
  jpeg_read_header(&r.info, TRUE);
  return true;
}

// Decodes every row as 8-bit RGB into `row` (3 * width bytes), passing each to `rows`; false on
// an error.
inline bool jpeg_rows(Jpeg_reader& r, unsigned char* row, std::size_t row_bytes, const Image_rows& rows)
{
  if(setjmp(r.back))
    return false;
  r.info.out_color_space = JCS_RGB;
  jpeg_start_decompress(&r.info);
  if(std::size_t(r.info.output_width) * std::size_t(r.info.output_components) != row_bytes)
  {
    std::snprintf(r.message, sizeof r.message, "an unexpected row size");
    return false;
  }
  while(r.info.output_scanline < r.info.output_height)
  {
    const int y = int(r.info.output_scanline);
    JSAMPROW rows_read[1] = {row};
    if(jpeg_read_scanlines(&r.info, rows_read, 1) != 1 || r.truncated)
      break; // the data ends: a warning to libjpeg, an error here
    if(rows)
      rows(y, row);
  }
  if(!r.truncated)
    jpeg_finish_decompress(&r.info);
  return !r.truncated;
}

// Decodes the JPEG `bytes`, passing each row to `rows`; returns why it cannot (libjpeg's
// reason), or why the image is not taken.
inline std::optional<std::string> decode_jpeg(const std::vector<unsigned char>& bytes, int& width, int& height,
                                              const Image_rows& rows)
{
  Jpeg_reader reader;
  if(!jpeg_header(reader, bytes))
    return "not a valid JPEG image: " + std::string(reader.message);
  if(const std::optional<std::string> problem =
       image_size_problem("JPEG", reader.info.image_width, reader.info.image_height))
    return problem;
  width = int(reader.info.image_width);
  height = int(reader.info.image_height);
  std::vector<unsigned char> row(std::size_t(3) * reader.info.image_width);
  if(!jpeg_rows(reader, row.data(), row.size(), rows) || reader.truncated)
    return "not a valid JPEG image: " + std::string(reader.message);
  return std::nullopt;
}

// ------------------------------------------------------------------------------------ both

// Decodes a PNG or JPEG image, told apart by its signature, passing each row to `rows` (none
// for an interlaced PNG: `interlaced` says so); returns what is wrong, if anything: "not a PNG
// or JPEG image", "not a valid PNG image: <libpng's reason>", ..., or the size refused.
inline std::optional<std::string> decode_image(const std::vector<unsigned char>& bytes, int& width, int& height,
                                               const Image_rows& rows, bool& interlaced)
{
  interlaced = false;
  if(starts_with_png_signature(bytes))
    return decode_png(bytes, width, height, rows, interlaced);
  if(starts_with_jpeg_signature(bytes))
    return decode_jpeg(bytes, width, height, rows);
  return std::string("not a PNG or JPEG image");
}

// Reads the image file `path` into `image`; returns what is wrong with it, if anything: the file
// is missing or unreadable, is no PNG or JPEG, does not decode to its end, or is too large.
inline std::optional<std::string> read_texture_image(const std::string& path, Texture_image& image)
{
  std::error_code ec;
  if(!std::filesystem::exists(path, ec))
    return std::string("no such file");
  if(!std::filesystem::is_regular_file(path, ec))
    return std::string("not a regular file");
  std::ifstream in(path, std::ios::binary);
  image.bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if(!in.good() && !in.eof())
    return std::string("cannot read the file");
  const bool png = starts_with_png_signature(image.bytes);
  bool interlaced = false;
  if(const std::optional<std::string> wrong = decode_image(image.bytes, image.width, image.height, nullptr, interlaced))
    return wrong;
  image.mime_type = png ? "image/png" : "image/jpeg";
  image.extension = png ? ".png" : ".jpg";
  return std::nullopt;
}

} // namespace np_examples

#endif
