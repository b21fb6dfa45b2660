#include "viewer/LiveFigures.h"

#include "ivshadow/ShadowMethod.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "nodes/NodesOfType.h"

#include <nlohmann/json.hpp>

#include <QStringList>

#include <algorithm>

namespace ivshadow {
namespace {

QString mebibytes(std::uint64_t bytes) {
  return QString("%1 MiB").arg(static_cast<double>(bytes) / (1024.0 * 1024.0), 0, 'f', 1);
}

QString ms(double value) {
  return QString("%1 ms").arg(value, 0, 'f', 1);
}

// Rays in thousands or millions, so that a line stays short.
QString count(std::uint64_t n) {
  if (n >= 10'000'000) return QString("%1M").arg(double(n) / 1e6, 0, 'f', 1);
  if (n >= 10'000) return QString("%1k").arg(double(n) / 1e3, 0, 'f', 0);
  return QString::number(n);
}

// A pass of this frame cannot have taken longer than the frame (a figure above it is one of an
// earlier frame, or a timer read wrongly). One millisecond allows for the clocks' rounding.
bool withinFrame(double passMs, double frameMs) {
  return passMs >= 0.0 && passMs <= frameMs + 1.0;
}

// GPU time beside the wall time of the same work: the wall clock waited for the GPU, so the GPU
// time is at most that (5 % and half a millisecond for the two clocks). Others are not shown.
QString gpuBeside(double gpuMs, double wallMs) {
  if (gpuMs <= 0.0 || gpuMs > wallMs * 1.05 + 0.5) return {};
  return "  GPU " + ms(gpuMs);
}

}  // namespace

LiveFigures LiveFigures::collect(SoNode* root, double frameMs, double gpuFrameMs,
                                 double framesPerSecond, bool softwareRenderer,
                                 const LiveFigures& previous) {
  LiveFigures figures;
  figures.frameMs = frameMs;
  figures.gpuFrameMs = gpuFrameMs;
  figures.framesPerSecond = framesPerSecond;
  if (root != nullptr) {
    figures.shadows = collectDeepShadowStatistics(root);
    figures.peeling = collectPeelStatistics(root);
    int unnamed = 0;
    forEachNodeOfType<SoTransparentShadowGroup>(root, [&](SoTransparentShadowGroup& node) {
      Group group;
      group.name = node.getName().getString();
      ++unnamed;
      if (group.name.empty()) group.name = "group " + std::to_string(unnamed);
      const int renderer = node.renderer.getValue();
      group.autoRenderer = renderer == SoTransparentShadowGroup::AUTO_RENDERER;
      // As the group decides (AutoTracerChoice): AUTO traces where GL is a software rasteriser.
      group.traced =
          renderer == SoTransparentShadowGroup::TRACER || (group.autoRenderer && softwareRenderer);
      group.stats = node.getStatistics();
      figures.groups.push_back(std::move(group));
    });
  }
  // Counters that moved since the frame before tell which passes ran during this one; the
  // times beside them are those of the last run, whenever it was.
  figures.rebuiltThisFrame = figures.shadows.rebuilds != previous.shadows.rebuilds;
  figures.tracedThisFrame = figures.shadows.rayFrames != previous.shadows.rayFrames;
  figures.pictureTracedThisFrame = figures.shadows.tracerFrames != previous.shadows.tracerFrames;
  figures.peeledThisFrame = figures.peeling.frames != previous.peeling.frames ||
                            figures.peeling.tracedFrames != previous.peeling.tracedFrames;
  return figures;
}

bool LiveFigures::gpuFramePlausible() const {
  return gpuFrameMs > 0.0 && gpuFrameMs <= frameMs * 1.05 + 0.5;
}

QString LiveFigures::pathSummary() const {
  bool traced = false, raster = false, automatic = false;
  for (const Group& group : groups) {
    (group.traced ? traced : raster) = true;
    automatic = automatic || group.autoRenderer;
  }
  QString path = traced && raster ? "TRACER + RASTER"
                 : traced         ? "TRACER (CPU)"
                 : raster         ? "RASTER (GL)"
                                  : "no shadow group";
  if (automatic) path += ", by AUTO";
  return path;
}

QString LiveFigures::text() const {
  QStringList lines;
  // Short lines: the first ones, which every page shows, fit the panel at its narrowest.
  lines << QString("frame %1  %2 fps")
               .arg(ms(frameMs))
               .arg(framesPerSecond, 0, 'f', framesPerSecond < 10.0 ? 1 : 0);
  if (gpuFramePlausible()) lines << "GL    " + ms(gpuFrameMs) + " (timer)";
  lines << "path  " + pathSummary();
  double passes = 0.0;
  if (rebuiltThisFrame && withinFrame(shadows.lastBuildMs, frameMs)) {
    lines << QString("map   %1%2  build %3")
                 .arg(ms(shadows.lastBuildMs), gpuBeside(shadows.gpuBuildMs, shadows.lastBuildMs))
                 .arg(shadows.rebuilds);
    passes += shadows.lastBuildMs;
  }
  if (peeledThisFrame && withinFrame(peeling.peelMs, frameMs)) {
    lines << (peeling.passes > 0
                  ? QString("peel  %1%2  passes %3")
                        .arg(ms(peeling.peelMs), gpuBeside(peeling.gpuPeelMs, peeling.peelMs))
                        .arg(peeling.passes)
                  : QString("peel  %1  traced").arg(ms(peeling.peelMs)));
    passes += peeling.peelMs;
  }
  if (tracedThisFrame && withinFrame(shadows.raysMs, frameMs)) {
    QString rays = QString("rays  %1  %2 rays").arg(ms(shadows.raysMs), count(shadows.raysTraced));
    if (shadows.volumeFaces > 0) rays += QString("  %1 faces").arg(count(shadows.volumeFaces));
    lines << rays;
    passes += shadows.raysMs;
  }
  if (pictureTracedThisFrame && withinFrame(shadows.tracerMs, frameMs)) {
    lines << QString("trace %1  %2x%3 %4")
                 .arg(ms(shadows.tracerMs))
                 .arg(shadows.tracerWidth)
                 .arg(shadows.tracerHeight)
                 .arg(shadows.tracerReduced > 0 ? "moving" : "full");
    passes += shadows.tracerMs;
  } else if (shadows.tracerScenes > 0 &&
             std::any_of(groups.begin(), groups.end(), [](const Group& g) { return g.traced; })) {
    // A still frame of a traced group draws the picture it kept: nothing is traced.
    lines << QString("trace kept (%1 refined)").arg(shadows.tracerRefines);
  }
  const bool raster =
      std::any_of(groups.begin(), groups.end(), [](const Group& g) { return !g.traced; });
  if (raster || groups.empty()) {
    // The nodes time their own passes; what is left of the frame is the shaded scene.
    lines << QString("shade %1%2")
                 .arg(ms(std::max(0.0, frameMs - passes)),
                      gpuBeside(shadows.gpuShadingMs, frameMs - passes));
  }
  std::uint64_t total = 0;
  int maps = 0;
  for (const Group& group : groups) {
    if (group.traced) {
      // Its lights' shadows are traced with the picture: the group keeps no maps.
      lines << QString::fromStdString(group.name) + ": traced, no maps";
      continue;
    }
    for (const DeepShadowLightStatistics& light : group.stats.lights) {
      const QString name =
          light.name.empty() ? QString("light") : QString::fromStdString(light.name);
      if (shadowsPerPixel(light.method)) {
        lines << name + ": " + shadowMethodName(light.method) + ", no map";
        continue;
      }
      const bool opacity = light.method == ShadowMethod::OpacityMap;
      total += light.bytes;
      ++maps;
      const QString build = light.mapBuild == "FRAGMENT_LISTS" ? ", lists"
                            : light.mapBuild == "PEELING"      ? ", peeled"
                                                               : "";
      lines << QString("%1: %2 %3 %4")
                   .arg(name, opacity ? "OPACITY" : "MAP")
                   .arg(light.resolution)
                   .arg(light.coloured ? "colour" : "mono");
      QStringList faces;
      for (int layers : light.layersUsed) faces << QString::number(layers);
      lines << QString("  %1 %2").arg(opacity ? "slices" : "layers", faces.join(' '));
      lines << "  " + mebibytes(light.bytes) + build;
    }
  }
  if (maps > 1) lines << "maps  " + mebibytes(total);
  return lines.join('\n');
}

std::string LiveFigures::json() const {
  nlohmann::json out;
  out["frame_ms"] = frameMs;
  out["gpu_ms"] = gpuFrameMs;
  out["frames_per_second"] = framesPerSecond;
  out["passes"] = {{"dsm_build_ms", shadows.lastBuildMs},
                   {"dsm_build_gpu_ms", shadows.gpuBuildMs},
                   {"peel_ms", peeling.peelMs},
                   {"peel_gpu_ms", peeling.gpuPeelMs},
                   {"rays_ms", shadows.raysMs},
                   {"tracer_ms", shadows.tracerMs},
                   {"rays_capture_gpu_ms", shadows.gpuCaptureMs},
                   {"shading_gpu_ms", shadows.gpuShadingMs}};
  out["this_frame"] = {{"map_build", rebuiltThisFrame},
                       {"peel", peeledThisFrame},
                       {"rays", tracedThisFrame},
                       {"tracer", pictureTracedThisFrame}};
  nlohmann::json paths = nlohmann::json::object();
  for (const Group& group : groups) paths[group.name] = group.traced ? "TRACER" : "RASTER";
  out["group_paths"] = paths;
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
                      {"method", shadowMethodName(light.method)},
                      {"map_build", light.mapBuild}});
  }
  out["dsm_layers_used"] = lights;
  out["dsm_bytes"] = bytes;
  out["peel_passes"] = peeling.passes;
  out["tracer_frames"] = shadows.tracerFrames;
  out["tracer_size"] = {shadows.tracerWidth, shadows.tracerHeight};
  out["tracer_reduced"] = shadows.tracerReduced > 0;
  out["tracer_refines"] = shadows.tracerRefines;
  out["panel_text"] = text().toStdString();
  return out.dump();
}

}  // namespace ivshadow
