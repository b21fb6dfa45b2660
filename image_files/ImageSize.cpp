#include "image_files/ImageSize.h"

#include "scene/InputError.h"

#include <regex>

namespace ivshadow {

ImageSize ImageSize::parse(const std::string& text, const std::string& option) {
  // 16384 is the largest render target any current GL driver offers; the GL limit of the
  // actual context is checked again when the target is made.
  constexpr long kMaxSide = 16384;
  static const std::regex pattern(R"(^\s*(\d{1,6})\s*[xX]\s*(\d{1,6})\s*$)");
  std::smatch match;
  if (std::regex_match(text, match, pattern)) {
    const long width = std::stol(match[1].str());
    const long height = std::stol(match[2].str());
    if (width >= 1 && height >= 1 && width <= kMaxSide && height <= kMaxSide) {
      return {static_cast<int>(width), static_cast<int>(height)};
    }
  }
  throw InputError(option + " '" + text +
                   "': error: expected WIDTHxHEIGHT with each side from 1 to " +
                   std::to_string(kMaxSide) + ", e.g. 800x600");
}

}  // namespace ivshadow
