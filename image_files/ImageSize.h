#pragma once

#include <string>

namespace ivshadow {

struct ImageSize {
  int width = 0;
  int height = 0;

  // Parses "WIDTHxHEIGHT" (e.g. "800x600"), each side 1..16384. Throws InputError naming
  // `option` and what was expected.
  static ImageSize parse(const std::string& text, const std::string& option);
  std::string toString() const { return std::to_string(width) + "x" + std::to_string(height); }
};

}  // namespace ivshadow
