#pragma once

#include "ivshadow/PeelStatistics.h"
#include "nodes/PerContext.h"
#include "nodes/TransparentShadowGroupImpl.h"

class SoGLRenderAction;
class SoNotList;
class SoPeelingSeparator;

namespace ivshadow {

class PeelPass;

// The work behind SoPeelingSeparator: the opaque pass, the peel passes and the compositing.
// Layers are shaded by the program current when the separator renders: a surrounding deep
// shadow group's, or else its own (the group's program without shadows).
class PeelingSeparatorImpl {
 public:
  explicit PeelingSeparatorImpl(SoPeelingSeparator* owner);
  ~PeelingSeparatorImpl();
  PeelingSeparatorImpl(const PeelingSeparatorImpl&) = delete;
  PeelingSeparatorImpl& operator=(const PeelingSeparatorImpl&) = delete;

  void render(SoGLRenderAction* action, bool inPath);
  void changed(SoNotList* list) { shading_.changed(list); }
  const PeelStatistics& statistics() const { return statistics_; }

 private:
  void peel(SoGLRenderAction* action, bool inPath);
  void renderPlainly(SoGLRenderAction* action, bool inPath);

  SoPeelingSeparator* owner_;
  TransparentShadowGroupImpl shading_;
  PerContext<PeelPass> passes_;
  PeelStatistics statistics_;
};

}  // namespace ivshadow
