#include "image/PngFile.h"

#include "image/AtomicFile.h"
#include "scene/InputError.h"

#include <png.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <vector>

namespace ivshadow {
namespace {

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

// libpng reports errors through longjmp by default; these handlers turn them into C++
// exceptions instead, so the stack unwinds normally and no file handle leaks.
[[noreturn]] void throwPngError(png_structp png, png_const_charp message) {
  throw std::runtime_error(*static_cast<const std::string*>(png_get_error_ptr(png)) +
                           ": error: " + message);
}
void ignorePngWarning(png_structp, png_const_charp) {}

}  // namespace

void writePng(const std::string& path, const Image& image) {
  AtomicFile output(path);
  writePngTo(output.temporaryPath(), path, image);
  output.commit();
}

void writePngTo(const std::string& fileName, const std::string& path, const Image& image) {
  FilePtr file(std::fopen(fileName.c_str(), "wb"));
  if (!file) throw std::runtime_error(path + ": error: cannot write: " + std::strerror(errno));
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, const_cast<std::string*>(&path),
                                            throwPngError, ignorePngWarning);
  png_infop info = png_create_info_struct(png);
  try {
    png_init_io(png, file.get());
    png_set_IHDR(png, info, static_cast<png_uint_32>(image.width()),
                 static_cast<png_uint_32>(image.height()), 8, PNG_COLOR_TYPE_RGB_ALPHA,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < image.height(); ++y) {
      png_write_row(png, const_cast<png_bytep>(image.pixel(0, y)));
    }
    png_write_end(png, info);
  } catch (...) {
    png_destroy_write_struct(&png, &info);
    throw;
  }
  png_destroy_write_struct(&png, &info);
  // fclose reports what the last flush could not write (a full disk, /dev/full).
  if (std::fclose(file.release()) != 0) {
    throw std::runtime_error(path + ": error: cannot write: " + std::strerror(errno));
  }
}

Image readPng(const std::string& path) {
  FilePtr file(std::fopen(path.c_str(), "rb"));
  if (!file) throw InputError(path + ": error: cannot open: " + std::strerror(errno));
  png_byte signature[8] = {};
  if (std::fread(signature, 1, sizeof signature, file.get()) != sizeof signature ||
      png_sig_cmp(signature, 0, sizeof signature) != 0) {
    throw InputError(path + ": error: not a PNG file");
  }
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, const_cast<std::string*>(&path),
                                           throwPngError, ignorePngWarning);
  png_infop info = png_create_info_struct(png);
  Image image;
  try {
    png_init_io(png, file.get());
    png_set_sig_bytes(png, sizeof signature);
    png_read_info(png, info);
    png_set_expand(png);
    png_set_strip_16(png);
    png_set_gray_to_rgb(png);
    png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
    png_read_update_info(png, info);
    image = Image(static_cast<int>(png_get_image_width(png, info)),
                  static_cast<int>(png_get_image_height(png, info)));
    std::vector<png_bytep> rows(static_cast<std::size_t>(image.height()));
    for (int y = 0; y < image.height(); ++y) rows[static_cast<std::size_t>(y)] = image.pixel(0, y);
    png_read_image(png, rows.data());
  } catch (const std::runtime_error& error) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw InputError(error.what());
  }
  png_destroy_read_struct(&png, &info, nullptr);
  return image;
}

}  // namespace ivshadow
