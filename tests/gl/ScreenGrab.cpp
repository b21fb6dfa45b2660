#include "tests/gl/ScreenGrab.h"

#include "tests/gl/ViewerTestSupport.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <regex>
#include <sstream>

namespace ivshadow::test {
namespace {

std::uint32_t bigEndian(const std::string& data, std::size_t at) {
  return (std::uint32_t(std::uint8_t(data[at])) << 24) |
         (std::uint32_t(std::uint8_t(data[at + 1])) << 16) |
         (std::uint32_t(std::uint8_t(data[at + 2])) << 8) |
         std::uint32_t(std::uint8_t(data[at + 3]));
}

// The lowest set bit of a channel mask, for the shift that brings the channel to bits 0-7.
int shiftOf(std::uint32_t mask) {
  int shift = 0;
  while (mask != 0 && (mask & 1u) == 0) {
    mask >>= 1;
    ++shift;
  }
  return shift;
}

}  // namespace

Image grabScreen(const std::string& display) {
  const std::string path = outputDir() + "/screen.xwd";
  const ProcessResult result = run({"xwd", "-root", "-silent", "-display", display, "-out", path});
  if (result.exitCode != 0) {
    ADD_FAILURE() << "xwd -root on " << display << " failed: " << result.err;
    return Image();
  }
  const std::string data = readText(path);
  // The XWD header (X11/XWDFile.h): 25 big-endian 32-bit fields, then the window name, then
  // ncolors colour entries of 12 bytes, then the pixels in rows of bytes_per_line.
  if (data.size() < 100) {
    ADD_FAILURE() << path << " is too short for an XWD file";
    return Image();
  }
  const auto field = [&data](int index) { return bigEndian(data, 4u * std::size_t(index)); };
  const std::uint32_t headerSize = field(0), width = field(4), height = field(5);
  const std::uint32_t lsbFirst = field(7) == 0, bitsPerPixel = field(11), bytesPerLine = field(12);
  const std::uint32_t masks[3] = {field(14), field(15), field(16)};
  const std::uint32_t colours = field(19);
  const std::size_t pixels = headerSize + 12u * colours;
  const std::uint32_t bytesPerPixel = bitsPerPixel / 8;
  if ((bytesPerPixel != 3 && bytesPerPixel != 4) ||
      data.size() < pixels + std::size_t(bytesPerLine) * height) {
    ADD_FAILURE() << path << ": " << bitsPerPixel << " bits per pixel or truncated; expected a "
                  << "TrueColor screen of 24 or 32 bits";
    return Image();
  }
  Image image(static_cast<int>(width), static_cast<int>(height));
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      const std::size_t at =
          pixels + std::size_t(y) * bytesPerLine + std::size_t(x) * bytesPerPixel;
      std::uint32_t value = 0;
      for (std::uint32_t b = 0; b < bytesPerPixel; ++b) {
        const std::uint32_t byte = std::uint8_t(data[at + b]);
        value |= lsbFirst ? byte << (8 * b) : byte << (8 * (bytesPerPixel - 1 - b));
      }
      std::uint8_t* out = image.pixel(int(x), int(y));
      for (int c = 0; c < 3; ++c) out[c] = std::uint8_t((value & masks[c]) >> shiftOf(masks[c]));
      out[3] = 255;
    }
  }
  return image;
}

Image crop(const Image& screen, const ScreenRect& rect) {
  Image part(rect.width, rect.height);
  for (int y = 0; y < rect.height; ++y)
    for (int x = 0; x < rect.width; ++x) {
      const int sx = rect.x + x, sy = rect.y + y;
      if (sx < 0 || sy < 0 || sx >= screen.width() || sy >= screen.height()) continue;
      for (int c = 0; c < 4; ++c) part.pixel(x, y)[c] = screen.pixel(sx, sy)[c];
    }
  return part;
}

WindowTree windowTree(const std::string& display, const std::string& id) {
  WindowTree tree;
  const ProcessResult info = run({"xwininfo", "-display", display, "-id", id});
  std::smatch match;
  const std::regex x("Absolute upper-left X: +(-?\\d+)"), y("Absolute upper-left Y: +(-?\\d+)"),
      w("Width: +(\\d+)"), h("Height: +(\\d+)");
  const auto number = [&info, &match](const std::regex& pattern) {
    return std::regex_search(info.out, match, pattern) ? std::stoi(match[1]) : -1;
  };
  tree.window = {number(x), number(y), number(w), number(h)};

  const ProcessResult children = run({"xwininfo", "-display", display, "-tree", "-id", id});
  // A child's line ends "WxH+X+Y  +ABSX+ABSY"; a window with children is followed by a line
  // "N child:" or "N children:".
  const std::regex line("(\\d+)x(\\d+)[+-]-?\\d+[+-]-?\\d+ +\\+(-?\\d+)\\+(-?\\d+)\\s*$");
  const std::regex parent("^\\s*\\d+ child(ren)?:");
  std::istringstream lines(children.out);
  std::string text;
  bool previousIsWindow = false;
  while (std::getline(lines, text)) {
    if (std::regex_search(text, match, line)) {
      if (previousIsWindow) tree.leaves.push_back(tree.all.back());
      tree.all.push_back(
          {std::stoi(match[3]), std::stoi(match[4]), std::stoi(match[1]), std::stoi(match[2])});
      previousIsWindow = true;
    } else if (std::regex_search(text, parent)) {
      previousIsWindow = false;
    }
  }
  if (previousIsWindow) tree.leaves.push_back(tree.all.back());
  return tree;
}

std::vector<int> frameExtents(const std::string& display, const std::string& id) {
  const ProcessResult result = run({"xprop", "-display", display, "-id", id, "_NET_FRAME_EXTENTS"});
  std::smatch match;
  const std::regex extents("= (\\d+), (\\d+), (\\d+), (\\d+)");
  if (!std::regex_search(result.out, match, extents)) return {0, 0, 0, 0};
  return {std::stoi(match[1]), std::stoi(match[2]), std::stoi(match[3]), std::stoi(match[4])};
}

}  // namespace ivshadow::test
