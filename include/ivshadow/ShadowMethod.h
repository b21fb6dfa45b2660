#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace ivshadow {

// How a light's shadow is computed: the `method` field of SoDeepShadowLight, its spot and
// directional kin and SoTransparentShadowGroup (whose SoDeepShadowLight::Method values these
// equal), and what a light's statistics say it used, where Auto is already resolved.
enum class ShadowMethod {
  Auto,       // RAYS on a software rasteriser, MAP on a GPU
  Map,        // a deep shadow map
  Rays,       // exact shadow rays on the CPU (Embree), per pixel
  Volumes,    // exact hard shadows by transparent shadow volumes (GL), per pixel
  OpacityMap  // light absorbed per uniform depth slice
};

// The names files, messages and `ivshadow render --stats` give the methods, in the enum's
// order: the one place they are spelled.
inline constexpr const char* kShadowMethodNames[] = {"AUTO", "MAP", "RAYS", "VOLUMES",
                                                     "OPACITY_MAP"};
inline constexpr std::size_t kShadowMethodCount =
    sizeof(kShadowMethodNames) / sizeof(kShadowMethodNames[0]);

inline constexpr const char* shadowMethodName(ShadowMethod method) {
  return kShadowMethodNames[std::size_t(method)];
}

// The method a name spells, or none.
inline constexpr std::optional<ShadowMethod> shadowMethodNamed(std::string_view name) {
  for (std::size_t i = 0; i < kShadowMethodCount; ++i)
    if (name == kShadowMethodNames[i]) return ShadowMethod(i);
  return std::nullopt;
}

// Whether the method shadows per pixel of the view instead of keeping a map: RAYS and
// VOLUMES, which share the capture of the visible surfaces and the shading's lookup.
inline constexpr bool shadowsPerPixel(ShadowMethod method) {
  return method == ShadowMethod::Rays || method == ShadowMethod::Volumes;
}

}  // namespace ivshadow
