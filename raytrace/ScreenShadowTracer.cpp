#include "raytrace/ScreenShadowTracer.h"

#include "raytrace/CasterScene.h"
#include "raytrace/ParallelRows.h"

namespace ivshadow {

std::vector<float> traceScreenShadows(const CasterScene& casters,
                                      const std::vector<SurfaceLayer>& layers,
                                      const std::vector<RayLight>& lights, std::size_t& rays) {
  rays = 0;
  if (layers.empty() || lights.empty()) return {};
  const int width = layers.front().width, height = layers.front().height;
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  std::vector<float> visibility(lights.size() * layers.size() * pixels * 4, 1.0f);
  std::vector<std::size_t> counts(static_cast<std::size_t>(workerCount(0)), 0);
  parallelRows(height, 0, [&](int y, int worker) {
    std::size_t& count = counts[std::size_t(worker)];
    for (std::size_t l = 0; l < layers.size(); ++l) {
      const SurfaceLayer& layer = layers[l];
      for (int x = 0; x < width; ++x) {
        const std::size_t pixel = std::size_t(y) * std::size_t(width) + std::size_t(x);
        if (!layer.traced(pixel)) continue;
        const float* p = &layer.position[pixel * 4];
        const float* n = &layer.normal[pixel * 4];
        const glm::vec3 from(p[0], p[1], p[2]), normal(n[0], n[1], n[2]);
        for (std::size_t r = 0; r < lights.size(); ++r) {
          const RayLight& light = lights[r];
          const glm::vec3 to(light.position[0], light.position[1], light.position[2]);
          const glm::vec3 v = casters.transmittance(from, normal, to, light.model);
          float* out = &visibility[((r * layers.size() + l) * pixels + pixel) * 4];
          out[0] = v.r;
          out[1] = v.g;
          out[2] = v.b;
          ++count;
        }
      }
    }
  });
  std::size_t traced = 0;
  for (std::size_t count : counts) traced += count;
  rays = traced;
  return visibility;
}

}  // namespace ivshadow
