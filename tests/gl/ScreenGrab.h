#pragma once

#include "image/Image.h"

#include <string>
#include <vector>

namespace ivshadow::test {

// A window's place on its screen: its inside, without the window manager's frame.
struct ScreenRect {
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;

  bool operator==(const ScreenRect& other) const {
    return x == other.x && y == other.y && width == other.width && height == other.height;
  }
  bool contains(const ScreenRect& other) const {
    return other.x >= x && other.y >= y && other.x + other.width <= x + width &&
           other.y + other.height <= y + height;
  }
};

// What X shows on `display` (":N.S"), read by `xwd -root`: every window as drawn on the
// screen, the 3D area as the GL last swapped it.
Image grabScreen(const std::string& display);

// The pixels of `rect` in `screen`.
Image crop(const Image& screen, const ScreenRect& rect);

// The window `id` (hex, as xdotool prints it in decimal or xwininfo in hex) and every X window
// below it, from `xwininfo -tree` (absolute positions). Qt makes native X windows of the GL
// widget and its parents only, so the 3D area is one of these.
struct WindowTree {
  ScreenRect window;
  std::vector<ScreenRect> all;     // every window below, at any depth
  std::vector<ScreenRect> leaves;  // those without windows of their own below
};
WindowTree windowTree(const std::string& display, const std::string& id);

// The window manager's frame around window `id`: left, right, top, bottom
// (_NET_FRAME_EXTENTS); zeros when it has none.
std::vector<int> frameExtents(const std::string& display, const std::string& id);

}  // namespace ivshadow::test
