#pragma once

class SoSeparator;

namespace ivshadow::bench {

enum class Shadows {
  None,             // plain SoSeparator and SoPointLight
  DeepShadowGroup,  // SoTransparentShadowGroup and SoDeepShadowLight
  CoinShadowGroup   // Coin's SoShadowGroup and SoShadowSpotLight (opaque casters only)
};

// A floor under a grid of lat-long spheres of about `triangles` triangles in all, lit from
// above; half the spheres are coloured glass when `transparent`. Returns a referenced root.
SoSeparator* sphereField(int triangles, bool transparent, Shadows shadows, int width, int height);

}  // namespace ivshadow::bench
