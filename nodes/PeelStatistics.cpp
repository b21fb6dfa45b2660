#include "nodes/PeelStatistics.h"

#include "nodes/SoPeelingSeparator.h"

#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>

namespace ivshadow {

PeelStatistics collectPeelStatistics(SoNode* root) {
  PeelStatistics total;
  SoSearchAction search;
  search.setType(SoPeelingSeparator::getClassTypeId());
  search.setInterest(SoSearchAction::ALL);
  search.setSearchingAll(TRUE);
  search.apply(root);
  const SoPathList& paths = search.getPaths();
  for (int i = 0; i < paths.getLength(); ++i) {
    const PeelStatistics& one =
        static_cast<SoPeelingSeparator*>(paths[i]->getTail())->getStatistics();
    total.passes += one.passes;
    total.peelMs += one.peelMs;
    total.frames += one.frames;
  }
  return total;
}

}  // namespace ivshadow
