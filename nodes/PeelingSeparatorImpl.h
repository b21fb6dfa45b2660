#pragma once

#include "ivshadow/PeelStatistics.h"
#include "nodes/GroupContents.h"
#include "nodes/GroupShading.h"
#include "nodes/PerContext.h"
#include "nodes/TracerActivity.h"

class SoGLRenderAction;
class SoNotList;
class SoPeelingSeparator;
class SoState;

namespace ivshadow {

class PeelPass;

// The work behind SoPeelingSeparator: the opaque pass, the peel passes and the compositing.
// Layers are shaded by a surrounding deep shadow group's shading, with its maps, or else by
// the separator's own (the same programs, lit by the lights in force, without shadows).
class PeelingSeparatorImpl {
 public:
  explicit PeelingSeparatorImpl(SoPeelingSeparator* owner);
  ~PeelingSeparatorImpl();
  PeelingSeparatorImpl(const PeelingSeparatorImpl&) = delete;
  PeelingSeparatorImpl& operator=(const PeelingSeparatorImpl&) = delete;

  void render(SoGLRenderAction* action, bool inPath);
  void changed(SoNotList* list) {
    // A traced group asking for its refined frame changes nothing here.
    if (!TracerActivity::active(TracerActivity::RefineTouch)) contents_.changed(list);
  }
  const PeelStatistics& statistics() const { return statistics_; }

 private:
  // The passes of this context; null (with one warning) when it cannot peel.
  PeelPass* passFor(SoState* state);
  // False when GL could not make the peel targets: nothing was drawn, and the caller draws the
  // children plainly.
  bool peel(SoGLRenderAction* action, bool inPath, GroupShading& shading);
  void renderPlainly(SoGLRenderAction* action, bool inPath);

  SoPeelingSeparator* owner_;
  GroupContents contents_;  // the lights and camera below it (it casts no shadows)
  GroupShading shading_;
  PerContext<PeelPass> passes_;
  PeelStatistics statistics_;
};

}  // namespace ivshadow
