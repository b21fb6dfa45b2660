#include "ivshadow/PeelStatistics.h"

#include "ivshadow/SoPeelingSeparator.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "nodes/NodesOfType.h"

#include <algorithm>

namespace ivshadow {

namespace {

void add(PeelStatistics& total, const PeelStatistics& one) {
  total.passes += one.passes;
  total.peelMs += one.peelMs;
  total.gpuPeelMs += one.gpuPeelMs;
  total.frames += one.frames;
  // The fewest slots of the nodes that listed: a fallback in one is not hidden by another.
  if (one.listPasses > 0)
    total.listSlots =
        total.listPasses > 0 ? std::min(total.listSlots, one.listSlots) : one.listSlots;
  total.listPasses += one.listPasses;
  total.listFragments += one.listFragments;
  total.tracedFrames += one.tracedFrames;
}

}  // namespace

PeelStatistics collectPeelStatistics(SoNode* root) {
  PeelStatistics total;
  forEachNodeOfType<SoPeelingSeparator>(
      root, [&](const SoPeelingSeparator& separator) { add(total, separator.getStatistics()); });
  forEachNodeOfType<SoTransparentShadowGroup>(
      root, [&](const SoTransparentShadowGroup& group) { add(total, group.getPeelStatistics()); });
  return total;
}

}  // namespace ivshadow
