#include "nodes/PeelStatistics.h"

#include "nodes/NodesOfType.h"
#include "nodes/SoPeelingSeparator.h"

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
