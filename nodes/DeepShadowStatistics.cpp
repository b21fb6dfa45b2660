#include "nodes/DeepShadowStatistics.h"

#include "nodes/SoTransparentShadowGroup.h"

#include <Inventor/actions/SoSearchAction.h>

namespace ivshadow {

DeepShadowStatistics collectDeepShadowStatistics(SoNode* root) {
  DeepShadowStatistics total;
  SoSearchAction search;
  search.setType(SoTransparentShadowGroup::getClassTypeId());
  search.setInterest(SoSearchAction::ALL);
  search.setSearchingAll(TRUE);
  search.apply(root);
  const SoPathList& paths = search.getPaths();
  for (int i = 0; i < paths.getLength(); ++i) {
    const auto* group = static_cast<SoTransparentShadowGroup*>(paths[i]->getTail());
    const DeepShadowStatistics& stats = group->getStatistics();
    total.lights.insert(total.lights.end(), stats.lights.begin(), stats.lights.end());
    total.lastBuildMs += stats.lastBuildMs;
    total.totalBuildMs += stats.totalBuildMs;
    total.rebuilds += stats.rebuilds;
    total.casterTriangles += stats.casterTriangles;
  }
  return total;
}

}  // namespace ivshadow
