#pragma once

#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/PeelStatistics.h"
#include "nodes/AutoTracerChoice.h"
#include "nodes/GroupContents.h"
#include "nodes/GroupShading.h"
#include "nodes/GroupTracer.h"
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
// the separator's own (the same programs, lit by the lights in force, without shadows). With
// method TRACER (or AUTO on a software rasteriser) outside a group, the children are traced
// on the CPU instead (GroupTracer).
class PeelingSeparatorImpl {
 public:
  explicit PeelingSeparatorImpl(SoPeelingSeparator* owner);
  ~PeelingSeparatorImpl();
  PeelingSeparatorImpl(const PeelingSeparatorImpl&) = delete;
  PeelingSeparatorImpl& operator=(const PeelingSeparatorImpl&) = delete;

  void render(SoGLRenderAction* action, bool inPath);
  // Says once per field the user set that maxPasses and earlyTermination (and the method, unless
  // `methodActs`) do nothing on the path this frame took: `why`.
  void sayFieldsIdle(const char* why, bool methodActs);
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
  // Whether the children are traced on the CPU in this context (method TRACER, or AUTO on a
  // software rasteriser).
  bool traced(SoState* state);

  SoPeelingSeparator* owner_;
  GroupContents contents_;  // the lights and camera below it (it casts no shadows)
  GroupShading shading_;
  PerContext<PeelPass> passes_;
  PeelStatistics statistics_;
  AutoTracerChoice autoTracer_;
  GroupTracer tracer_;
  DeepShadowStatistics tracerStatistics_;  // the tracer's figures; statistics_ has its time
  // The bounce rays per pixel of the groups below with bounce TRUE (the largest), found for
  // the shapes of castersVersion bounceVersion_.
  int bounceSamples_ = 0;
  std::uint64_t bounceVersion_ = ~std::uint64_t(0);
};

}  // namespace ivshadow
