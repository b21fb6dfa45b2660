#pragma once

#include "gl/GlHandles.h"
#include "gl/GlProgram.h"
#include "scene/ShadowTypes.h"

#include <memory>
#include <string>
#include <vector>

namespace ivshadow {

// The GL side of SoDeepShadowLight's VOLUMES method in one context: draws a light's shadow
// volumes (raytrace/ShadowVolumes) against the surfaces the RAYS capture found, all layers in
// one draw (shadow_volume.frag), and turns the sums into the visibility the shading program
// reads for a screen-space shadow (shadow_volume_resolve.frag), in place of the CPU's rays.
class ShadowVolumePass {
 public:
  // Null, with the reason, when the program does not build or the context draws to fewer
  // than kMaxScreenLayers colour attachments at once.
  static std::unique_ptr<ShadowVolumePass> create(std::string& whyNot);
  ~ShadowVolumePass();

  // How the group's coordinates reach the window (SbMatrix memory: GL's column-major order).
  struct View {
    float localToClip[16];
    float localToEye[16];
    int viewport[4];
    float winding = 1.0f;    // -1 when localToEye mirrors
    bool depthClamp = true;  // false: localToClip has its far plane at infinity
  };
  // Draws `faces` against the first `layers` layers of `positionArray` (captured positions
  // in the group's coordinates, w the window depth, 1 where nothing is traced; `width` x
  // `height`, window coordinates; RayShadowPass::positionTexture()) and writes their visibility
  // into layers first .. first + layers - 1 of `visibilityArray`, sampling on texture unit `unit`.
  // Empty, or what GL said when the sums' target could not be allocated (nothing written).
  std::string draw(const std::vector<VolumeVertex>& faces, const View& view, unsigned positionArray,
                   int layers, unsigned visibilityArray, int first, int width, int height,
                   int unit);

 private:
  ShadowVolumePass() = default;
  std::string allocate(int width, int height);

  GlProgram volumes_;
  GlProgram resolve_;
  GlVertexArray faceArray_;
  GlVertexArray emptyArray_;
  GlBuffer faceBuffer_;
  GlTexture sums_;  // RGBA32F array, one layer per captured layer: log visibility
  GlFramebuffer sumsFramebuffer_;
  GlFramebuffer visibilityFramebuffer_;
  int width_ = 0;
  int height_ = 0;
};

}  // namespace ivshadow
