#pragma once

#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>

namespace ivshadow {

// Calls `visit(path)` with the path to every node of `type` under `root`, in traversal order;
// with `searchingAll` false, not below switches that turn their children off.
template <typename Visit>
void forEachPathTo(SoNode* root, SoType type, bool searchingAll, Visit visit) {
  SoSearchAction search;
  search.setType(type);
  search.setInterest(SoSearchAction::ALL);
  search.setSearchingAll(searchingAll ? TRUE : FALSE);
  search.apply(root);
  const SoPathList& paths = search.getPaths();
  for (int i = 0; i < paths.getLength(); ++i) visit(*paths[i]);
}

// Calls `visit(node)` for every node of type T under `root`, switched off or not, in
// traversal order.
template <typename T, typename Visit>
void forEachNodeOfType(SoNode* root, Visit visit) {
  forEachPathTo(root, T::getClassTypeId(), true,
                [&visit](SoPath& path) { visit(*static_cast<T*>(path.getTail())); });
}

}  // namespace ivshadow
