#include "image_files/PngFile.h"

#include "image_files/AtomicFile.h"
#include "image_files/MemoryBudget.h"
#include "scene/InputError.h"

#include <png.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
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

// Deflate expands its input at most 1032 times (a 258-byte match per 2 bits, RFC 1951); zlib's
// own figure for its compression bound.
constexpr std::uint64_t kDeflateLargestExpansion = 1032;

// The size a header declares against what the file can hold and the machine can give, before
// a row is allocated (a 74-byte PNG declaring 60000 x 60000 died in std::bad_alloc; one of
// 30000 x 30000 was read after 3.5 GB and 7.8 s).
void checkDeclaredSize(const std::string& path, png_structp png, png_infop info) {
  const std::uint64_t width = png_get_image_width(png, info);
  const std::uint64_t height = png_get_image_height(png, info);
  const std::uint64_t data = height * (1 + std::uint64_t(png_get_rowbytes(png, info)));
  std::error_code ec;
  const std::uint64_t fileBytes = std::filesystem::file_size(path, ec);
  if (!ec && data > fileBytes * kDeflateLargestExpansion)
    throw InputError(
        path + ": error: the header declares " + std::to_string(width) + " x " +
        std::to_string(height) + " pixels, " + std::to_string(data) +
        " bytes of image data; a PNG file of " + std::to_string(fileBytes) +
        " bytes holds at most " + std::to_string(fileBytes * kDeflateLargestExpansion) +
        " (deflate expands at most " + std::to_string(kDeflateLargestExpansion) + " times)");
  const std::uint64_t pixels = width * height * 4;
  const std::uint64_t available = MemoryBudget::available();
  if (pixels > available || width * height > std::uint64_t(std::numeric_limits<int>::max()))
    throw InputError(path + ": error: the header declares " + std::to_string(width) + " x " +
                     std::to_string(height) + " pixels, " + std::to_string(pixels) +
                     " bytes as RGBA; " + std::to_string(available) + " bytes are available");
}

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
    // Rendered pictures are flat or smooth regions mostly: unfiltered rows deflate about as
    // well as libpng's choice of a filter per row (of the 16 bundled scenes at 640 x 480, 10
    // came out smaller, 5 up to a third larger) in 0.4 of its time, which a sweep of small
    // pictures pays once per variant (docs/PERFORMANCE.md, "Variants sweeps").
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
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
    checkDeclaredSize(path, png, info);
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
