#include "viewer/LiveFigures.h"

#include <nlohmann/json.hpp>

#include <QStringList>

#include <algorithm>

namespace ivshadow {
namespace {

QString mebibytes(std::uint64_t bytes) {
  return QString("%1 MiB").arg(static_cast<double>(bytes) / (1024.0 * 1024.0), 0, 'f', 1);
}

}  // namespace

LiveFigures LiveFigures::collect(SoNode* root, double frameMs, double gpuFrameMs,
                                 const LiveFigures& previous) {
  LiveFigures figures;
  figures.frameMs = frameMs;
  figures.gpuFrameMs = gpuFrameMs;
  if (root != nullptr) {
    figures.shadows = collectDeepShadowStatistics(root);
    figures.peeling = collectPeelStatistics(root);
  }
  figures.rebuiltThisFrame = figures.shadows.rebuilds != previous.shadows.rebuilds;
  figures.tracedThisFrame = figures.shadows.rayFrames != previous.shadows.rayFrames;
  figures.pictureTracedThisFrame = figures.shadows.tracerFrames != previous.shadows.tracerFrames;
  return figures;
}

QString LiveFigures::text() const {
  QStringList lines;
  lines << QString("frame      %1 ms (GL timer %2 ms)")
               .arg(frameMs, 0, 'f', 1)
               .arg(gpuFrameMs, 0, 'f', 1);
  const double build = rebuiltThisFrame ? shadows.lastBuildMs : 0.0;
  lines << QString("map build  %1 ms, GPU %2 ms (%3 so far)%4")
               .arg(shadows.lastBuildMs, 0, 'f', 1)
               .arg(shadows.gpuBuildMs, 0, 'f', 1)
               .arg(shadows.rebuilds)
               .arg(rebuiltThisFrame ? " (this frame)" : "");
  lines << QString("peel       %1 ms, GPU %2 ms, %3 passes")
               .arg(peeling.peelMs, 0, 'f', 1)
               .arg(peeling.gpuPeelMs, 0, 'f', 1)
               .arg(peeling.passes);
  const bool tracing =
      std::any_of(shadows.lights.begin(), shadows.lights.end(),
                  [](const DeepShadowLightStatistics& light) { return light.method != "MAP"; });
  if (tracing) {
    lines << QString(
                 "rays       %1 ms, capture GPU %2 ms, %3 rays, %4 volume faces%5 (BVH %6 ms, "
                 "%7)")
                 .arg(shadows.raysMs, 0, 'f', 1)
                 .arg(shadows.gpuCaptureMs, 0, 'f', 1)
                 .arg(shadows.raysTraced)
                 .arg(shadows.volumeFaces)
                 .arg(tracedThisFrame ? " (this frame)" : "")
                 .arg(shadows.bvhBuildMs, 0, 'f', 1)
                 .arg(mebibytes(shadows.bvhBytes));
  }
  if (shadows.tracerScenes > 0) {
    // Which picture the frame shows: one traced now, at the viewport's size or reduced while
    // the scene moves (movingResolution), or the one kept.
    const QString which =
        !pictureTracedThisFrame
            ? QString("kept")
            : QString("%1 x %2, %3")
                  .arg(shadows.tracerWidth)
                  .arg(shadows.tracerHeight)
                  .arg(shadows.tracerReduced > 0 ? "reduced while moving, refined when still"
                                                 : "full");
    lines << QString("tracer     %1 ms (%2), %3 rays, %4 refined")
                 .arg(shadows.tracerMs, 0, 'f', 1)
                 .arg(which)
                 .arg(shadows.raysTraced)
                 .arg(shadows.tracerRefines);
  }
  // The nodes time their own passes; what is left of the frame is the shaded scene.
  const double rays =
      (tracedThisFrame ? shadows.raysMs : 0.0) + (pictureTracedThisFrame ? shadows.tracerMs : 0.0);
  lines << QString("shading    %1 ms, GPU %2 ms (the groups' children)")
               .arg(std::max(0.0, frameMs - build - peeling.peelMs - rays), 0, 'f', 1)
               .arg(shadows.gpuShadingMs, 0, 'f', 1);
  std::uint64_t total = 0;
  const char* const faceNames[] = {"+x", "-x", "+y", "-y", "+z", "-z"};
  for (const DeepShadowLightStatistics& light : shadows.lights) {
    const QString name = light.name.empty() ? QString("light") : QString::fromStdString(light.name);
    const bool opacity = light.method == "OPACITY_MAP";
    if (light.method != "MAP" && !opacity) {
      // Traced shadows and shadow volumes keep no map: no layers, no memory of their own.
      lines << name + (light.method == "VOLUMES" ? ": shadow volumes, no map"
                                                 : ": shadow rays, no map");
      continue;
    }
    total += light.bytes;
    // How the map was built: from fragment lists, or peeled where they did not fit.
    const QString build = light.mapBuild == "FRAGMENT_LISTS" ? ", fragment lists"
                          : light.mapBuild == "PEELING"      ? ", peeled"
                                                             : "";
    lines << QString("%1: %2 x %2 per face, %3%4%5")
                 .arg(name)
                 .arg(light.resolution)
                 .arg(light.coloured ? "colour" : "monochrome")
                 .arg(opacity ? ", opacity map" : "")
                 .arg(build);
    QStringList faces;
    for (int face = 0; face < 6; ++face) {
      faces << QString("%1 %2").arg(faceNames[face]).arg(light.layersUsed[std::size_t(face)]);
    }
    lines << (opacity ? "  slices " : "  layers ") + faces.join("  ");
    lines
        << QString("  memory %1 (peak %2)").arg(mebibytes(light.bytes), mebibytes(light.peakBytes));
  }
  if (total > 0) lines << "maps total " + mebibytes(total);
  return lines.join('\n');
}

std::string LiveFigures::json() const {
  nlohmann::json out;
  out["frame_ms"] = frameMs;
  out["gpu_ms"] = gpuFrameMs;
  out["passes"] = {{"dsm_build_ms", shadows.lastBuildMs},
                   {"dsm_build_gpu_ms", shadows.gpuBuildMs},
                   {"peel_ms", peeling.peelMs},
                   {"peel_gpu_ms", peeling.gpuPeelMs},
                   {"rays_ms", shadows.raysMs},
                   {"tracer_ms", shadows.tracerMs},
                   {"rays_capture_gpu_ms", shadows.gpuCaptureMs},
                   {"shading_gpu_ms", shadows.gpuShadingMs}};
  out["rays_traced"] = shadows.raysTraced;
  out["volume_faces"] = shadows.volumeFaces;
  out["dsm_rebuilds"] = shadows.rebuilds;
  std::uint64_t bytes = 0;
  nlohmann::json lights = nlohmann::json::array();
  for (const DeepShadowLightStatistics& light : shadows.lights) {
    bytes += light.bytes;
    lights.push_back({{"light", light.name},
                      {"faces", light.layersUsed},
                      {"bytes", light.bytes},
                      {"colored", light.coloured},
                      {"resolution", light.resolution},
                      {"method", light.method},
                      {"map_build", light.mapBuild}});
  }
  out["dsm_layers_used"] = lights;
  out["dsm_bytes"] = bytes;
  out["peel_passes"] = peeling.passes;
  out["tracer_frames"] = shadows.tracerFrames;
  out["tracer_size"] = {shadows.tracerWidth, shadows.tracerHeight};
  out["tracer_reduced"] = shadows.tracerReduced > 0;
  out["tracer_refines"] = shadows.tracerRefines;
  return out.dump();
}

}  // namespace ivshadow
