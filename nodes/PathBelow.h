#pragma once

#include "scene/CoinRef.h"

#include <Inventor/SoPath.h>
#include <Inventor/misc/SoChildList.h>
#include <Inventor/nodes/SoNode.h>

#include <vector>

namespace ivshadow {

// The way from a node to one below it, kept without holding a reference to any node on it:
// the child index at each level. An SoPath holds a reference to every node on it, so a node
// that keeps a path starting at itself (or at one of its ancestors) through its own members
// holds itself and is never freed (each scene a group drew leaked whole: about 9 MB for
// coloured_shadows.iv, found by SceneRenderFuzzer). The path is made again when it is needed.
class PathBelow {
 public:
  PathBelow() = default;
  // The indices of `path` (null: none).
  explicit PathBelow(const SoPath* path) : valid_(path != nullptr) {
    if (path == nullptr) return;
    for (int i = 1; i < path->getLength(); ++i) indices_.push_back(path->getIndex(i));
  }

  explicit operator bool() const { return valid_; }

  // The path from `head`, the node the recorded path started at; null when there is none or
  // the graph below `head` no longer has it.
  CoinRef<SoPath> from(SoNode* head) const {
    if (!valid_ || head == nullptr) return {};
    CoinRef<SoPath> path(new SoPath(head));
    for (const int index : indices_) {
      const SoChildList* children = path->getTail()->getChildren();
      if (children == nullptr || index < 0 || index >= children->getLength()) return {};
      path->append(index);
    }
    return path;
  }

 private:
  std::vector<int> indices_;
  bool valid_ = false;
};

}  // namespace ivshadow
