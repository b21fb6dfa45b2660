#pragma once

#include "viewer/ViewerOptions.h"

namespace ivshadow {

// Runs the SoQt viewer until its window closes. Returns the process exit status: 0; 2 for bad
// input (scene, size, --set, output paths) in a scripted run; 3 when there is no display to
// open a window on; 1 when a screenshot could not be saved.
int runViewer(const ViewerOptions& options, const char* programName);

}  // namespace ivshadow
