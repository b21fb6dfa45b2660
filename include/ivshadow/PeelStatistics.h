#pragma once

#include "ivshadow/Export.h"

class SoNode;

namespace ivshadow {

// What the last frame of one SoPeelingSeparator, or of a peeling SoTransparentShadowGroup,
// cost.
struct PeelStatistics {
  int passes = 0;          // peel passes, the depth-range pass included (not the opaque pass)
  double peelMs = 0.0;     // wall time of the peel passes and compositing (waits for each pass)
  double gpuPeelMs = 0.0;  // GPU time of the same (GL_TIMESTAMP queries)
  int frames = 0;          // frames peeled since the node was created
  // Of `passes`, those that filled fragment lists (FRAGMENT_LISTS: 1, or 2 when the buffer
  // grew), and the transparent fragments they stored.
  int listPasses = 0;
  long long listFragments = 0;
  // The fragments each pixel keeps in slots of its own before the shared overflow (4, fewer,
  // down to 0, where GL could not give the storage for more); summed, the fewest of the nodes
  // that listed.
  int listSlots = 0;
  // A SoPeelingSeparator traced on the CPU (method TRACER, or AUTO on a software rasteriser):
  // its frames that traced the picture since it was created (the others drew the one kept;
  // peelMs is then the trace's and the picture's wall time, passes 0).
  int tracedFrames = 0;
};

// The last frame of every SoPeelingSeparator and SoTransparentShadowGroup under `root`,
// summed.
IVSHADOW_API PeelStatistics collectPeelStatistics(SoNode* root);

}  // namespace ivshadow
