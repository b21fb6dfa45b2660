#pragma once

#include <string>

namespace ivshadow {

// How far each way of drawing a shadow group may stray from the exact reference, and why
// (docs/AGREEMENT.md says the same for users). The differential test and its fuzzer hold
// every path to these: a picture below its floor fails, unless the render said why it could
// not do better (a warning naming the cause).
struct MethodAgreement {
  const char* path;       // as the test names it
  const char* renderer;   // the groups' renderer field
  const char* method;     // every light's method field ("" : as the scene says)
  double minPsnrDb;       // over the whole picture, all channels
  double maxShareAbove2;  // of pixels off by more than 2/255 in some channel
  const char* why;
};

// Measured on the bundled scenes and 40 generated ones at 96 x 72 (docs/AGREEMENT.md gives
// the figures); each floor leaves a little room under the worst.
inline constexpr MethodAgreement kMethodAgreements[] = {
    {"TracerRays", "TRACER", "", 60.0, 0.001,
     "the reference's own trace; only GL's 8-bit store of the picture differs"},
    {"RasterRays", "RASTER", "RAYS", 26.0, 0.045,
     "exact shadows; GL rasterises edges with 1/256-pixel snapping where the trace samples "
     "pixel centres, and rounds each transparent layer to 8 bits as it composites"},
    {"RasterVolumes", "RASTER", "VOLUMES", 26.0, 0.045,
     "exact hard shadows, as RAYS; a caster whose colour changes across its face casts its "
     "mean (said once)"},
    {"RasterMap", "RASTER", "MAP", 26.0, 0.06,
     "as RAYS, and the map's texels and filter soften shadow edges by a texel or two"},
    {"RasterOpacityMap", "RASTER", "OPACITY_MAP", 26.0, 0.085,
     "as MAP, and light absorbed per depth slice, not per surface: stacked glass shadows "
     "within a slice blend"},
};

// The agreement of the path named `path` (one of the table's; the table ends the search).
inline const MethodAgreement& methodAgreement(const std::string& path) {
  for (const MethodAgreement& agreement : kMethodAgreements)
    if (path == agreement.path) return agreement;
  return kMethodAgreements[0];
}

}  // namespace ivshadow
