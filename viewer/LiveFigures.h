#pragma once

#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/PeelStatistics.h"

#include <QString>

#include <string>
#include <vector>

class SoNode;

namespace ivshadow {

// What the last frame cost and what the deep shadow maps hold, for the panel. Each figure names
// what the path each group took did during this frame: a pass that did not run this frame (a
// map kept from an earlier frame, a picture a traced group kept) shows no time, so no figure of
// an earlier frame or of the other path is left standing. Frame time is the wall clock to
// glFinish; beside it the frames per second over the last second and the GL_TIME_ELAPSED of
// the traversal, the latter only where it is possible (not above the wall clock: a first
// frame's timer read 1155101.5 ms).
struct LiveFigures {
  // How one SoTransparentShadowGroup drew this frame.
  struct Group {
    std::string name;     // DEF name, or "group N"
    bool traced = false;  // renderer TRACER, or AUTO on a software rasteriser: traced on the CPU
    bool autoRenderer = false;  // the path was AUTO's choice
    DeepShadowStatistics stats;
  };

  double frameMs = 0.0;
  double gpuFrameMs = 0.0;
  double framesPerSecond = 0.0;
  bool rebuiltThisFrame = false;        // a RASTER group built its maps
  bool tracedThisFrame = false;         // a RASTER group traced shadow rays (RAYS, VOLUMES)
  bool pictureTracedThisFrame = false;  // a traced group traced its picture (else kept it)
  bool peeledThisFrame = false;         // a peeling separator or group peeled (or traced)
  std::vector<Group> groups;
  DeepShadowStatistics shadows;
  PeelStatistics peeling;

  // `previous` are the figures of the frame before, to tell which passes ran this frame;
  // `softwareRenderer`: the GL is a software rasteriser, where AUTO picks the tracer.
  static LiveFigures collect(SoNode* root, double frameMs, double gpuFrameMs,
                             double framesPerSecond, bool softwareRenderer,
                             const LiveFigures& previous);

  // Whether gpuFrameMs is a time this frame can have taken.
  bool gpuFramePlausible() const;
  // "traced (TRACER)", "GL (RASTER)", or both, for the status bar.
  QString pathSummary() const;
  // Short lines for the panel: this frame's passes and their times, then one line per light.
  QString text() const;
  // One JSON object with the keys `ivshadow render --stats` uses for the same figures
  // (dsm_layers_used, dsm_bytes, dsm_rebuilds, peel_passes, passes.*), plus what ran this
  // frame (`this_frame`), the groups' paths and the panel's lines, for scripts and tests.
  std::string json() const;
};

}  // namespace ivshadow
