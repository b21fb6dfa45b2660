#include "ivshadow/DeepShadowStatistics.h"

#include "gl/GlPassTimer.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "nodes/NodesOfType.h"

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
