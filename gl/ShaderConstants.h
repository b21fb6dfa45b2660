#pragma once

#include "scene/ShadowTypes.h"

#include <array>
#include <string>

namespace ivshadow {

// The values that the C++ passes and the GLSL programs must agree on, each written once here.
// composeShader() prepends them to every shader as #defines (shaderConstantDefines()), so a
// shader says IVSHADOW_MAX_LIGHTS where it needs the light limit and cannot drift from C++.

// Peeled layers per cube face a deep shadow map may hold (SoDeepShadowLight::maxLayers).
inline constexpr int kMaxMapLayers = 64;

// An opacity map's depth slices per face (SoDeepShadowLight::slices). Its build draws the
// casters once per kOpacitySlicesPerDraw slices, one colour attachment each beside the
// opaque surfaces' depth (GL guarantees 8 attachments): 32 slices are five draws per face
// and 516 bytes per texel and face (RGBA 32-bit slices).
inline constexpr int kMaxOpacitySlices = 32;
inline constexpr int kOpacitySlicesPerDraw = 7;
// What an opacity map holds where no surface is: the opaque depth the largest float (beyond
// any receiver), a slice's first-surface coordinate (0 .. 1 over the slices) a value beyond
// any, which half precision still holds.
inline constexpr float kOpacityNoOpaque = 3.40282347e+38f;
inline constexpr float kOpacityEmptySlice = 1.0e4f;

// Cube face f looks along kFaceAxis[f]; kFaceRight[f] and kFaceUp[f] span its image plane.
// The map build makes each face's view matrix from them, the lookup picks texels with them.
using FaceVectors = std::array<std::array<float, 3>, 6>;
inline constexpr FaceVectors kFaceAxis = {
    {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
inline constexpr FaceVectors kFaceRight = {
    {{0, 0, -1}, {0, 0, 1}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {-1, 0, 0}}};
inline constexpr FaceVectors kFaceUp = {
    {{0, 1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}, {0, 1, 0}, {0, 1, 0}}};

// How a deep shadow map sees its casters: a point light's cube (six faces of kFaceAxis), one
// perspective face along a spot light's axis that covers its cone, or one orthographic face
// along a directional light. The map build and the lookup (lighting.glsl) both branch on it.
enum class MapProjection : int { Cube = 0, Perspective = 1, Orthographic = 2 };

// A spot light whose cone is at most this wide (half angle, radians) gets one perspective
// face; a wider one the cube of a point light, since one face of more than 120 degrees
// spends its texels at the rim (a texel at the axis covers 4 times less angle than at 60
// degrees, 15 times less at 75).
inline constexpr float kMaxSpotFaceHalfAngle = 1.04719755f;  // pi / 3

// Shader storage binding points: the map build's "any / transparent fragment" flags, the
// peel passes' "deeper layers left" flag, the fragment lists (FragmentListPass,
// MapFragmentLists) and the texels a map's lists merge; the storage bindings the passes use,
// 0 .. kStorageBindings - 1 (GlStateScope restores them).
inline constexpr int kMapFlagsBinding = 0;
inline constexpr int kPeelProgressBinding = 1;
inline constexpr int kFragmentListBinding = 2;
inline constexpr int kMapMergeQueueBinding = 3;
inline constexpr int kStorageBindings = 4;
// Image units of the fragment lists: each pixel's first fragment and its count, and the
// layers a deep shadow map's lists are resolved into (MapFragmentLists), its distances and
// visibilities (GlStateScope restores units 0 .. kImageUnits - 1).
inline constexpr int kFragmentHeadsUnit = 0;
inline constexpr int kFragmentCountsUnit = 1;
inline constexpr int kMapLayerDepthUnit = 2;
inline constexpr int kMapLayerVisibilityUnit = 3;
inline constexpr int kImageUnits = 4;
// Fragments a pixel's list may hold: the resolve sorts them in registers. A view with more
// transparent surfaces in one pixel is peeled instead (docs/PEELING.md).
inline constexpr int kMaxFragmentsPerPixel = 32;
// Bytes a fragment takes in the lists (std430: colour as four 16-bit unorms, depth, next).
inline constexpr int kFragmentBytes = 16;
// Fragments a pixel keeps in slots of its own (fragment k of pixel p at k * pixels + p, no
// shared counter), before the rest go into a linked overflow list: on a software rasteriser
// the one counter that every fragment of a linked list increments is half the list pass's
// time (docs/PERFORMANCE.md). Four cost 64 bytes a pixel (31 MB at 800 x 600).
inline constexpr int kFixedFragmentsPerPixel = 4;
// Bytes a fragment of a deep shadow map's lists takes (dsm_list_common.glsl, std430:
// transmittance and opacity vec4, distance, triangle, next, padding to 16).
inline constexpr int kMapFragmentBytes = 32;
// Pixels along each side of a compute workgroup that resolves a map's lists.
inline constexpr int kMapResolveGroupSize = 8;
// Words per face the resolve of a map's lists reports in (dsm_list_resolve.comp).
inline constexpr int kMapFaceFlags = 7;
// Texels a workgroup of the merge of a map's lists takes (dsm_list_merge.comp), one each; the
// largest map that merges (the queue names a texel in 14 bits a side; the map is peeled,
// truncated, above).
inline constexpr int kMapMergeGroupSize = 64;
inline constexpr int kMaxMergeResolution = 16384;

// Layers of visible surfaces a screen-space shadow (RAYS, VOLUMES) is computed for: the
// nearest opaque one and up to four transparent ones in front of it. The shadow volumes
// write them all from one draw, one colour attachment each (GL guarantees 8).
inline constexpr int kMaxScreenLayers = 5;
// Relative distance within which a shadow volume's face and a captured surface are one place
// (a caster's own near cap, which the capture drew through Coin's matrices and the volume
// through ours). The surface then counts as lying on the light's side of its own cap, as a
// shadow ray steps over its own surface: a face entering a volume (seen from the eye) there
// counts as beyond it, a face leaving one as in front, so a surface never shadows itself
// whichever side the camera sees. Measured on the bundled scenes against RAYS: below 3e-7
// surfaces shadow themselves in specks (float rounding of the two paths); above 1e-5 the
// faces of other casters passing within it near contact edges are misjudged (atrium 56 dB,
// 57 at 2e-6, 74 dB for all_directions at 1e-6).
inline constexpr float kVolumeDepthTolerance = 2e-6f;
// Texture units of the plugin's passes, counted down from the context's highest unit so that
// Coin's own textures keep the low ones: the maps (depth and visibility per light slot) at the
// top, the peel targets below them, the traced shadows of RAYS lights below those, the one
// bounce's atlas and lights below those.
inline constexpr int kMapUnits = 2 * kMaxGlLights;
inline constexpr int kPeelUnits = 3;
inline constexpr int kRayUnits = 4;
// The one-bounce gather's: the imperfect shadow maps' atlas and the virtual point lights.
inline constexpr int kBounceUnits = 2;
inline constexpr int kCoinUnitsAtLeast = 4;
inline constexpr int kTextureUnitsNeeded =
    kMapUnits + kPeelUnits + kRayUnits + kBounceUnits + kCoinUnitsAtLeast;
// First unit of each block in a context with `available` fragment texture units.
constexpr int firstMapUnit(int available) {
  return available - kMapUnits;
}
constexpr int firstPeelUnit(int available) {
  return firstMapUnit(available) - kPeelUnits;
}
constexpr int firstRayUnit(int available) {
  return firstPeelUnit(available) - kRayUnits;
}
constexpr int bounceAtlasUnit(int available) {
  return firstRayUnit(available) - kBounceUnits;
}
constexpr int bounceLightsUnit(int available) {
  return bounceAtlasUnit(available) + 1;
}
// The units of light slot `slot`'s map: its depths and its visibility.
constexpr int mapDepthUnit(int available, int slot) {
  return firstMapUnit(available) + slot;
}
constexpr int mapVisibilityUnit(int available, int slot) {
  return firstMapUnit(available) + kMaxGlLights + slot;
}

// One bounce (SoTransparentShadowGroup::bounce, gl/ImperfectShadowMaps.h). Each virtual
// point light is three texels of its buffer (position, normal, flux). Its imperfect shadow map
// is drawn from kIsmPointsPerLight of a pool of kIsmPointPool points on the opaque casters,
// spread evenly by area; light i takes every (pool / per light)-th point from i modulo that,
// so neighbouring lights see different points and their errors do not line up (Ritschel et
// al.). Points are splats of kIsmPointSize texels (seeds/001: 1 leaves holes, 4 overgrows).
inline constexpr int kBounceTexelsPerLight = 3;
inline constexpr int kIsmPointPool = 32768;
inline constexpr int kIsmPointsPerLight = 8192;
inline constexpr float kIsmPointSize = 3.0f;
// Pull-push levels over the atlas (seeds/001: the last two push steps come nearest the
// perfect map); tiles of at least 16 texels stay apart through them.
inline constexpr int kIsmPullLevels = 2;
// The pull and push compute programs' work group side, and their image units: the level each
// reads (finer for the pull, coarser for the push) and the level it writes (within
// kImageUnits, which GlStateScope restores).
inline constexpr int kIsmGroupSize = 8;
inline constexpr int kIsmReadUnit = 0;
inline constexpr int kIsmWriteUnit = 1;
static_assert(kIsmReadUnit < kImageUnits && kIsmWriteUnit < kImageUnits);
// What a texel holds where no point fell (after pull-push: no surface that way).
inline constexpr float kIsmEmpty = 1.0e30f;
// A receiver counts as seen by a light while its distance is within this fraction beyond the
// distance stored in its direction: a splat's texels hold its point's distance, which along
// a surface seen at a slant differs from that of the surface in the texel's own direction.
// Tuned on bounce_wall.iv and a box in front of its wall (tests/gl/BounceTest.cpp).
inline constexpr float kIsmBias = 0.1f;
// How far a receiver is moved along its normal towards each light before its map is read, in
// texels of that map at the receiver's distance (a tile's texel spans 4 / size radians at its
// centre, 2 / size at its rim): half a splat and more, so the splats of the receiver's own
// surface do not hide it. The shaders get it in radians per texel-of-a-one-texel-tile:
// kIsmNormalOffset * 4, divided by the tile size there.
inline constexpr float kIsmNormalOffset = 1.5f;
// How far each light's map sits off its surface, as a fraction of the casters' diagonal
// (seeds/001 moves it 0.01 along the normal): the surface's own points fall behind it.
inline constexpr float kBounceLiftFraction = 0.002f;

// The constants above (and the colour models of ShadowColourModel) as GLSL #define lines.
std::string shaderConstantDefines();

}  // namespace ivshadow
