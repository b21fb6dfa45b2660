#include "viewer/QtImage.h"

#include <QImage>

#include <cstring>

namespace ivshadow {

Image imageFromQt(const QImage& picture) {
  const QImage rgba = picture.convertToFormat(QImage::Format_RGBA8888);
  Image image(rgba.width(), rgba.height());
  for (int y = 0; y < rgba.height(); ++y)
    std::memcpy(image.pixel(0, y), rgba.constScanLine(y), std::size_t(rgba.width()) * 4);
  return image;
}

}  // namespace ivshadow
