#include "image/Image.h"

#include <algorithm>

namespace ivshadow {

Image::Image(int width, int height)
    : width_(width),
      height_(height),
      rgba_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4u, 0u) {}

void Image::flipVertically() {
  const std::size_t rowBytes = static_cast<std::size_t>(width_) * 4u;
  for (int top = 0, bottom = height_ - 1; top < bottom; ++top, --bottom) {
    std::swap_ranges(rgba_.begin() + static_cast<std::ptrdiff_t>(top * rowBytes),
                     rgba_.begin() + static_cast<std::ptrdiff_t>((top + 1) * rowBytes),
                     rgba_.begin() + static_cast<std::ptrdiff_t>(bottom * rowBytes));
  }
}

}  // namespace ivshadow
