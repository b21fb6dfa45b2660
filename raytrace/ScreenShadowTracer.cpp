#include "raytrace/ScreenShadowTracer.h"

#include "raytrace/CasterScene.h"
#include "raytrace/ParallelRows.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>

namespace ivshadow {
namespace {
const std::uint16_t kHalfOne = glm::packHalf1x16(1.0f);
}  // namespace

std::size_t traceScreenShadows(const CasterScene& casters, const std::vector<SurfaceLayer>& layers,
                               std::size_t layerCount, const std::vector<RayLight>& lights,
                               std::vector<std::uint16_t>& visibility) {
  if (layerCount == 0 || lights.empty()) {
    visibility.clear();
    return 0;
  }
  const int width = layers.front().width, height = layers.front().height;
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  // Same size as last frame: no allocation, no clearing; every element is written below.
  visibility.resize(lights.size() * layerCount * pixels * 4);
  std::vector<std::size_t> counts(static_cast<std::size_t>(workerCount(0)), 0);
  parallelRows(height, 0, [&](int y, int worker) {
    std::size_t& count = counts[std::size_t(worker)];
    for (std::size_t l = 0; l < layerCount; ++l) {
      const SurfaceLayer& layer = layers[l];
      for (int x = 0; x < width; ++x) {
        const std::size_t pixel = std::size_t(y) * std::size_t(width) + std::size_t(x);
        const bool traced = layer.traced(pixel);
        if (!traced) {
          // Most pixels of the transparent layers: no conversion to half floats (glm's is
          // done in software); this halved the loop's own time (perf, docs/PERFORMANCE.md).
          for (std::size_t r = 0; r < lights.size(); ++r)
            std::fill_n(&visibility[((r * layerCount + l) * pixels + pixel) * 4], 4, kHalfOne);
          continue;
        }
        const float* p = &layer.position[pixel * 4];
        const float* n = &layer.normal[pixel * 4];
        const glm::vec3 from(p[0], p[1], p[2]), normal(n[0], n[1], n[2]);
        for (std::size_t r = 0; r < lights.size(); ++r) {
          const RayLight& light = lights[r];
          const glm::vec3 at(light.position[0], light.position[1], light.position[2]);
          const glm::vec3 v = light.directional
                                  ? casters.transmittanceTowards(from, normal, at, light.model)
                                  : casters.transmittance(from, normal, at, light.model);
          ++count;
          std::uint16_t* out = &visibility[((r * layerCount + l) * pixels + pixel) * 4];
          out[0] = glm::packHalf1x16(v.r);
          out[1] = glm::packHalf1x16(v.g);
          out[2] = glm::packHalf1x16(v.b);
          out[3] = kHalfOne;
        }
      }
    }
  });
  std::size_t rays = 0;
  for (std::size_t count : counts) rays += count;
  return rays;
}

}  // namespace ivshadow
