#include "ivshadow/DeepShadowStatistics.h"

#include "gl/GlPassTimer.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "nodes/NodesOfType.h"

#include <Inventor/nodes/SoNode.h>

#include <algorithm>

namespace ivshadow {

// The pass timers keep the switch: while it is off they read no result GL has not finished,
// so the map builds, which are always timed, never wait for the GPU for a figure nobody reads.
void setPassTiming(bool on) {
  GlPassTimer::setWaitForResults(on);
}

bool passTiming() {
  return GlPassTimer::waitsForResults();
}

DeepShadowStatistics collectDeepShadowStatistics(SoNode* root) {
  DeepShadowStatistics total;
  forEachNodeOfType<SoTransparentShadowGroup>(root, [&](const SoTransparentShadowGroup& group) {
    const DeepShadowStatistics& stats = group.getStatistics();
    if (total.renderer.empty())
      total.renderer = stats.renderer;
    else if (!stats.renderer.empty() && stats.renderer != total.renderer)
      total.renderer = "MIXED";
    total.lights.insert(total.lights.end(), stats.lights.begin(), stats.lights.end());
    total.lastBuildMs += stats.lastBuildMs;
    total.totalBuildMs += stats.totalBuildMs;
    total.rebuilds += stats.rebuilds;
    total.casterTriangles += stats.casterTriangles;
    total.raysMs += stats.raysMs;
    total.gpuBuildMs += stats.gpuBuildMs;
    total.gpuShadingMs += stats.gpuShadingMs;
    total.gpuCaptureMs += stats.gpuCaptureMs;
    total.rayCaptureMs += stats.rayCaptureMs;
    total.rayTraceMs += stats.rayTraceMs;
    total.rayLayers = std::max(total.rayLayers, stats.rayLayers);
    total.bvhBuildMs += stats.bvhBuildMs;
    total.raysTraced += stats.raysTraced;
    total.volumeFaces += stats.volumeFaces;
    total.bvhBytes += stats.bvhBytes;
    total.rayFrames += stats.rayFrames;
    total.rayCaptures += stats.rayCaptures;
    total.bvhBuilds += stats.bvhBuilds;
    total.bvhRefits += stats.bvhRefits;
    total.bounceLights += stats.bounceLights;
    total.bounceSamples += stats.bounceSamples;
    total.bouncePlaceMs += stats.bouncePlaceMs;
    total.bounceMapMs += stats.bounceMapMs;
    total.bounceBytes += stats.bounceBytes;
    total.tracerSceneMs += stats.tracerSceneMs;
    total.tracerLightsMs += stats.tracerLightsMs;
    total.tracerMs += stats.tracerMs;
    total.tracerScenes += stats.tracerScenes;
    total.tracerFrames += stats.tracerFrames;
    total.tracerWidth = std::max(total.tracerWidth, stats.tracerWidth);
    total.tracerHeight = std::max(total.tracerHeight, stats.tracerHeight);
    total.tracerReduced += stats.tracerReduced;
    total.tracerCameraRays += stats.tracerCameraRays;
    total.tracerRefines += stats.tracerRefines;
  });
  return total;
}

}  // namespace ivshadow

const char* ivshadow_renderer_in_use(SoNode* root) {
  if (root == nullptr) return "";
  // A search action refs and unrefs the node it is applied to: a node nothing holds yet (as
  // pivy's createInstance() gives) would be deleted under the caller.
  root->ref();
  const std::string renderer = ivshadow::collectDeepShadowStatistics(root).renderer;
  root->unrefNoDelete();
  // Literals: the caller keeps no storage of the plugin's.
  for (const char* name : {"TRACER", "RASTER", "MIXED"})
    if (renderer == name) return name;
  return "";
}
