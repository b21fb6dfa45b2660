#include "ivshadow/PeelStatistics.h"

#include "ivshadow/SoPeelingSeparator.h"
#include "nodes/NodesOfType.h"

namespace ivshadow {

PeelStatistics collectPeelStatistics(SoNode* root) {
  PeelStatistics total;
  forEachNodeOfType<SoPeelingSeparator>(root, [&](const SoPeelingSeparator& separator) {
    const PeelStatistics& one = separator.getStatistics();
    total.passes += one.passes;
    total.peelMs += one.peelMs;
    total.gpuPeelMs += one.gpuPeelMs;
    total.frames += one.frames;
  });
  return total;
}

}  // namespace ivshadow
