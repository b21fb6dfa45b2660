#pragma once

#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/PeelStatistics.h"

#include <QString>

#include <string>

class SoNode;

namespace ivshadow {

// What the last frame cost and what the deep shadow maps hold, for the panel: frame time
// (wall clock to glFinish, and the GL_TIME_ELAPSED of the traversal), the last map build and
// the last frame's peeling (wall times that wait for each of their GL passes, from the nodes'
// statistics), the rest of the frame as shading, layers used per cube face and map memory.
struct LiveFigures {
  double frameMs = 0.0;
  double gpuFrameMs = 0.0;
  bool rebuiltThisFrame = false;
  bool tracedThisFrame = false;
  bool pictureTracedThisFrame = false;  // a group with renderer TRACER traced its picture
  DeepShadowStatistics shadows;
  PeelStatistics peeling;

  // `previous` are the figures of the frame before, to tell whether this frame built the
  // maps, traced the shadow rays or a group's picture (and so whether their times are part
  // of frameMs).
  static LiveFigures collect(SoNode* root, double frameMs, double gpuFrameMs,
                             const LiveFigures& previous);

  // Lines for the panel.
  QString text() const;
  // One JSON object with the keys `ivshadow render --stats` uses for the same figures
  // (dsm_layers_used, dsm_bytes, dsm_rebuilds, peel_passes, passes.*), for scripts and tests.
  std::string json() const;
};

}  // namespace ivshadow
