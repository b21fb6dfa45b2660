#include "image_files/JpegFile.h"

#include "image_files/AtomicFile.h"
#include "scene/InputError.h"

// jpeglib.h needs FILE and size_t declared before it.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <vector>

#include <jpeglib.h>

namespace ivshadow {
namespace {

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};

// libjpeg's default error handler calls exit(); this one throws instead, so the stack
// unwinds, the temporary file is removed and the command reports the error.
[[noreturn]] void throwJpegError(j_common_ptr info) {
  char message[JMSG_LENGTH_MAX] = {};
  (*info->err->format_message)(info, message);
  throw std::runtime_error(message);
}

}  // namespace

void writeJpeg(const std::string& path, const Image& image, int quality) {
  AtomicFile output(path);
  writeJpegTo(output.temporaryPath(), path, image, quality);
  output.commit();
}

void writeJpegTo(const std::string& fileName, const std::string& path, const Image& image,
                 int quality) {
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(fileName.c_str(), "wb"));
  if (!file) throw std::runtime_error(path + ": error: cannot write: " + std::strerror(errno));
  jpeg_compress_struct info{};
  jpeg_error_mgr errors{};
  info.err = jpeg_std_error(&errors);
  errors.error_exit = throwJpegError;
  try {
    jpeg_create_compress(&info);
    jpeg_stdio_dest(&info, file.get());
    info.image_width = static_cast<JDIMENSION>(image.width());
    info.image_height = static_cast<JDIMENSION>(image.height());
    info.input_components = 3;
    info.in_color_space = JCS_RGB;
    jpeg_set_defaults(&info);
    jpeg_set_quality(&info, quality, TRUE);
    jpeg_start_compress(&info, TRUE);
    std::vector<JSAMPLE> row(static_cast<std::size_t>(image.width()) * 3u);
    for (int y = 0; y < image.height(); ++y) {
      const std::uint8_t* rgba = image.pixel(0, y);
      for (int x = 0; x < image.width(); ++x)
        for (int c = 0; c < 3; ++c)
          row[static_cast<std::size_t>(x) * 3u + std::size_t(c)] = rgba[x * 4 + c];
      JSAMPROW rows[] = {row.data()};
      jpeg_write_scanlines(&info, rows, 1);
    }
    jpeg_finish_compress(&info);
  } catch (const std::runtime_error& error) {
    jpeg_destroy_compress(&info);
    throw std::runtime_error(path + ": error: " + error.what());
  }
  jpeg_destroy_compress(&info);
  // fclose reports what the last flush could not write (a full disk, /dev/full).
  if (std::fclose(file.release()) != 0)
    throw std::runtime_error(path + ": error: cannot write: " + std::strerror(errno));
}

Image readJpeg(const std::string& path) {
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
  if (!file) throw InputError(path + ": error: cannot open: " + std::strerror(errno));
  jpeg_decompress_struct info{};
  jpeg_error_mgr errors{};
  info.err = jpeg_std_error(&errors);
  errors.error_exit = throwJpegError;
  Image image;
  try {
    jpeg_create_decompress(&info);
    jpeg_stdio_src(&info, file.get());
    jpeg_read_header(&info, TRUE);
    info.out_color_space = JCS_RGB;
    jpeg_start_decompress(&info);
    image = Image(static_cast<int>(info.output_width), static_cast<int>(info.output_height));
    std::vector<JSAMPLE> row(static_cast<std::size_t>(image.width()) * 3u);
    while (info.output_scanline < info.output_height) {
      const int y = static_cast<int>(info.output_scanline);
      JSAMPROW rows[] = {row.data()};
      jpeg_read_scanlines(&info, rows, 1);
      std::uint8_t* rgba = image.pixel(0, y);
      for (int x = 0; x < image.width(); ++x) {
        for (int c = 0; c < 3; ++c)
          rgba[x * 4 + c] = row[static_cast<std::size_t>(x) * 3u + std::size_t(c)];
        rgba[x * 4 + 3] = 255;
      }
    }
    jpeg_finish_decompress(&info);
  } catch (const std::runtime_error& error) {
    jpeg_destroy_decompress(&info);
    throw InputError(path + ": error: not a readable JPEG file: " + error.what());
  }
  jpeg_destroy_decompress(&info);
  return image;
}

}  // namespace ivshadow
