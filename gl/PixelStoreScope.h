#pragma once

namespace ivshadow {

// Tightly packed pixel transfers between client memory and GL for the scope's lifetime,
// whatever pixel-store state and pixel buffer bindings Coin or the application left: saves
// them (glPushClientAttrib, the pack and unpack buffer bindings), sets alignment 4 with no row
// length or skips, and puts everything back on destruction.
class PixelStoreScope {
 public:
  PixelStoreScope();
  ~PixelStoreScope();
  PixelStoreScope(const PixelStoreScope&) = delete;
  PixelStoreScope& operator=(const PixelStoreScope&) = delete;

 private:
  int packBuffer_ = 0;
  int unpackBuffer_ = 0;
};

}  // namespace ivshadow
