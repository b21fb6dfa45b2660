#pragma once

#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>

namespace ivshadow {

// Calls `visit(node)` for every node of type T under `root`, switched off or not, in
// traversal order.
template <typename T, typename Visit>
void forEachNodeOfType(SoNode* root, Visit visit) {
  SoSearchAction search;
  search.setType(T::getClassTypeId());
  search.setInterest(SoSearchAction::ALL);
  search.setSearchingAll(TRUE);
  search.apply(root);
  const SoPathList& paths = search.getPaths();
  for (int i = 0; i < paths.getLength(); ++i) visit(*static_cast<T*>(paths[i]->getTail()));
}

}  // namespace ivshadow
