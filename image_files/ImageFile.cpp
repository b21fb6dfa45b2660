#include "image_files/ImageFile.h"

#include "image_files/AtomicFile.h"
#include "image_files/JpegFile.h"
#include "image_files/OutputFiles.h"
#include "image_files/PngFile.h"
#include "scene/InputError.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace ivshadow {

ImageFormat imageFormatFor(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".png") return ImageFormat::Png;
  if (extension == ".jpg" || extension == ".jpeg") return ImageFormat::Jpeg;
  // A device or pipe (`-o /dev/null`, a FIFO) is written in place whatever its name.
  if (AtomicFile::writesInPlace(path)) return ImageFormat::Png;
  throw InputError(path + ": error: cannot write images of type '" +
                   (extension.empty() ? std::string("(no extension)") : extension) +
                   "'; supported: " + kImageExtensions);
}

void writeImage(const std::string& path, const Image& image) {
  OutputFiles files;
  files.addImage(path, image);
  files.commit();
}

void writeImageTo(const std::string& file, const std::string& name, const Image& image) {
  if (imageFormatFor(name) == ImageFormat::Jpeg)
    writeJpegTo(file, name, image);
  else
    writePngTo(file, name, image);
}

Image readImage(const std::string& path) {
  return imageFormatFor(path) == ImageFormat::Jpeg ? readJpeg(path) : readPng(path);
}

}  // namespace ivshadow
