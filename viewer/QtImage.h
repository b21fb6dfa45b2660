#pragma once

#include "image/Image.h"

class QImage;

namespace ivshadow {

// `picture` as 8-bit RGBA rows top to bottom, so that Qt's pictures (the window, the map
// inspector) are written by the same writer as the rest, in the format their names ask for.
Image imageFromQt(const QImage& picture);

}  // namespace ivshadow
