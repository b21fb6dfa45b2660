#pragma once

#include "reference/ReferenceRenderer.h"

#include <string>
#include <vector>

namespace ivshadow {

struct ReferenceCommandOptions {
  std::string scene;
  std::string output;  // PNG
  std::string pfm;     // optional: unrounded float RGB
  std::string size = "800x600";
  std::vector<std::string> assignments;  // NAME.field=VALUE
  int threads = 0;
  // Rays per point of one diffuse bounce in groups with bounce TRUE
  // (ReferenceOptions::bounceSamples); bounceGiven when the command line set it.
  int bounce = ReferenceOptions::kDefaultBounceSamples;
  bool bounceGiven = false;
};

// `ivshadow reference`: the exact CPU picture (reference/ReferenceRenderer.h). Exit 0, 2 on
// bad input, 128 + the signal when interrupted (130 for Ctrl-C), 1 otherwise; never leaves a
// partial file.
int runReference(const ReferenceCommandOptions& options);

}  // namespace ivshadow
