#pragma once

#include <string>

namespace ivshadow {

struct ViewerOptions {
  std::string scene;       // may be empty: start with nothing loaded
  std::string screenshot;  // non-empty: save the first rendered frame here and quit
  std::string size = "800x600";
};

// Runs the SoQt viewer until its window closes. Returns the process exit status: 0, 2 for bad
// input (scene, size) in screenshot mode, 3 when there is no display to open a window on.
int runViewer(const ViewerOptions& options, const char* programName);

}  // namespace ivshadow
