#include "raytrace/TextureFootprint.h"

#include "raytrace/CameraRays.h"
#include "raytrace/SceneExtraction.h"
#include "raytrace/SurfaceOptics.h"

namespace ivshadow::detail {

float levelOfDetail(const Extraction& data, const CameraRays& rays, const CameraRay& ray,
                    const Triangle& tri, const glm::vec3& position) {
  const TextureImage* image = imageOf(data, tri);
  if (image == nullptr || !image->mipmapped) return 0.0f;
  const auto [across, up] = rays.footprint(ray, position, tri.geometricNormal);
  const glm::vec3* corners = &data.positions[std::size_t(&tri - data.triangles.data()) * 3];
  return textureLod(*image, corners, tri.texCoord, across, up);
}

}  // namespace ivshadow::detail
