#pragma once

#include "ivshadow/Export.h"

#include <string>
#include <vector>

namespace ivshadow {

// One array layer of a deep shadow map, read back from the GL for inspection.
struct MapLayerReadback {
  int size = 0;                   // texels per side
  int channels = 0;               // visibility channels: 1 (monochrome) or 3 (coloured)
  std::vector<float> depth;       // size * size distances, rows bottom to top
  std::vector<float> visibility;  // size * size * channels
};

// Reads array layer `layer` of the map that the SoTransparentShadowGroup now rendering its
// children has bound for light slot `slot`. Only valid during that render (an SoCallback
// among the group's children calls it): the textures on the units its shading program reads
// for the slot (mapDepthUnit and mapVisibilityUnit, ShaderConstants.h, as ShadingUniforms
// sets them). Stalls the GL until the map is read; restores the active texture unit, the pack
// buffer and the pixel-store state. Returns false with the reason in `whyNot`.
IVSHADOW_INTERNAL bool readBoundMapLayer(int slot, int layer, MapLayerReadback& out,
                                         std::string& whyNot);
// The same from the map's two array textures (GL names): its distances and visibilities.
bool readMapLayer(unsigned int depth, unsigned int visibility, int layer, MapLayerReadback& out,
                  std::string& whyNot);

}  // namespace ivshadow
