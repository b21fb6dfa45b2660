#pragma once

#include <glm/vec3.hpp>

namespace ivshadow {

class CameraRays;
struct CameraRay;

namespace detail {

struct Extraction;
struct Triangle;

// GL's texture level of detail where camera ray `ray` meets `tri` of `data` at `position`: the
// pixel's footprint on the triangle's plane (CameraRays::footprint) in texels of its texture
// (textureLod), so that the tracer takes texels from the mipmap level GL's rasteriser would.
// 0 where no mipmapped texture is sampled.
float levelOfDetail(const Extraction& data, const CameraRays& rays, const CameraRay& ray,
                    const Triangle& tri, const glm::vec3& position);

}  // namespace detail
}  // namespace ivshadow
