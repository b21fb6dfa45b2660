#include "image/ImageFile.h"

#include "image/JpegFile.h"
#include "image/PngFile.h"
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
  throw InputError(path + ": error: cannot write images of type '" +
                   (extension.empty() ? std::string("(no extension)") : extension) +
                   "'; supported: .png, .jpg, .jpeg");
}

void writeImage(const std::string& path, const Image& image) {
  if (imageFormatFor(path) == ImageFormat::Jpeg)
    writeJpeg(path, image);
  else
    writePng(path, image);
}

Image readImage(const std::string& path) {
  return imageFormatFor(path) == ImageFormat::Jpeg ? readJpeg(path) : readPng(path);
}

}  // namespace ivshadow
