#pragma once

#include "ivshadow/Export.h"

#include <cstdint>
#include <vector>

namespace ivshadow {

// An 8-bit RGBA picture, rows top to bottom, as written to PNG.
class IVSHADOW_INTERNAL Image {
 public:
  Image() = default;
  Image(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  bool empty() const { return width_ == 0 || height_ == 0; }

  std::uint8_t* pixel(int x, int y) { return &rgba_[index(x, y)]; }
  const std::uint8_t* pixel(int x, int y) const { return &rgba_[index(x, y)]; }
  std::uint8_t* data() { return rgba_.data(); }
  const std::uint8_t* data() const { return rgba_.data(); }

  // Reverses the row order (GL reads bottom-up).
  void flipVertically();

 private:
  std::size_t index(int x, int y) const {
    return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
            static_cast<std::size_t>(x)) *
           4u;
  }

  int width_ = 0;
  int height_ = 0;
  std::vector<std::uint8_t> rgba_;
};

}  // namespace ivshadow
