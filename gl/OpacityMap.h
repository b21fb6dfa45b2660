#pragma once

#include "gl/DeepShadowMap.h"
#include "gl/GlHandles.h"

#include <cstdint>

namespace ivshadow {

class CasterBuffers;
class GlProgram;

// One light's opacity map (method OPACITY_MAP, after seeds/002), a cube or one face
// (MapFrame). Each face holds `slices` uniform slices of the distances from sliceNear to
// sliceFar and one opaque depth per texel:
// - a slice (RGBA, 16 or 32 bits per channel): the absorption -log(transmittance) per channel
//   of the transparent surfaces inside it and before it, summed (so a lookup reads three
//   slices whatever their count), and in alpha the slice coordinate (0 .. 1 over all slices)
//   of the first surface inside it (kOpacityEmptySlice: none);
// - the opaque depth (32 bits): the distance of the nearest opaque surface (kOpacityNoOpaque:
//   none), so opaque bodies shadow as sharply as in a shadow map, not spread over a slice.
// Array layer f of the depths is face f; layer f * slices + k of the slices its slice k.
// The casters are drawn once per kOpacitySlicesPerDraw slices of a face, whatever the depth
// complexity: the draws are fixed by the slices, and the fill grows with the casters'
// fragments, not with how many lie behind one another.
class OpacityMap {
 public:
  // Draws every face. The program (opacity_map.frag), vertex array, framebuffer and blend
  // state are left changed: the caller saves and restores GL state around the build.
  MapBuildResult build(const MapRequest& request, const GlProgram& program,
                       const CasterBuffers& casters);
  // What the map of `request` takes: it needs no scratch memory, and a build of a new shape
  // frees the old textures first, so this is its peak too.
  static std::uint64_t bytesFor(const MapRequest& request);
  void bind(int depthUnit, int visibilityUnit) const;
  std::uint64_t bytes() const { return bytes_; }

 private:
  // Makes the textures (or keeps the last build's, of the same shape) and the framebuffer, and
  // clears the textures; false, everything released, when GL ran out of memory.
  bool makeTargets(const MapRequest& request);
  // The GL state and uniforms every draw of the build shares.
  void beginDraws(const MapRequest& request, const GlProgram& program);
  // Attaches face `face`'s slices from `first` on, as many as one draw fills.
  void attachSlices(const MapRequest& request, int face, int first);
  // Draws face `face`'s slices, a draw per kOpacitySlicesPerDraw; false, with
  // result.failure, when the framebuffer is incomplete.
  bool drawFace(const MapRequest& request, const GlProgram& program, const CasterBuffers& casters,
                int face, MapBuildResult& result);
  void release();

  // What the textures were made for; a build of the same shape reuses them.
  struct Shape {
    int faces = 0, size = 0, slices = 0;
    unsigned format = 0;
    bool operator==(const Shape& o) const {
      return faces == o.faces && size == o.size && slices == o.slices && format == o.format;
    }
  };
  Shape shape_;
  GlTexture opaque_;
  GlTexture slices_;
  GlFramebuffer framebuffer_;
  std::uint64_t bytes_ = 0;
};

}  // namespace ivshadow
