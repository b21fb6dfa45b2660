#pragma once

#include "image/Image.h"

#include <array>

namespace ivshadow {

// How far one picture is from another (the reference), per colour channel and over all three.
// Errors are in 8-bit steps (0..255).
struct ImageComparison {
  struct Channel {
    double rmse = 0.0;
    int maxError = 0;
    double psnr = 0.0;         // dB; +infinity when the channel is identical
    double shareAbove2 = 0.0;  // share of pixels off by more than 2/255
  };
  std::array<Channel, 3> channels;  // red, green, blue
  Channel all;                      // the three channels together (share: any channel above)
  int maxErrorX = 0;
  int maxErrorY = 0;

  // Throws InputError naming `nameA`/`nameB` when the sizes differ.
  static ImageComparison compare(const Image& a, const Image& b, const char* nameA,
                                 const char* nameB);
};

// A heat map of the per-pixel error (largest channel): black where equal, through blue, red
// and yellow to white at `scale` steps and above.
Image errorHeatMap(const Image& a, const Image& b, int scale);

}  // namespace ivshadow
