#pragma once

#include "gl/GlHandles.h"
#include "gl/ShaderConstants.h"
#include "scene/ShadowTypes.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace ivshadow {

class GlStateScope;
struct ShadingLocations;

// The GL side of SoDeepShadowLight's RAYS method in one context. Before the group's children
// are shaded, Coin draws them into capture targets: first the nearest opaque surface of each
// pixel, then up to kMaxTransparentLayers transparent surfaces in front of it, nearest first.
// Each capture is read back (positions, normals) for the CPU tracer; the traced visibility is
// uploaded as a texture array that the shading program reads instead of a map. A frame is
//   beginCapture(); [startLayer(k); <Coin draws>; finishLayer(k)]...; endCapture();
//   upload(); bind() while the children are shaded.
class RayShadowPass {
 public:
  static constexpr int kMaxTransparentLayers = kMaxScreenLayers - 1;

  // `firstUnit`: the first of the kRayUnits units of the ray samplers
  // (DeepShadowPass::rayUnit(0)).
  explicit RayShadowPass(int firstUnit) : firstUnit_(firstUnit) {}

  // Saves GL state and sizes the capture targets to the viewport's far corner (window
  // coordinates index them). Empty when the targets are ready; else what GL said when
  // allocating them (nothing can be captured: the caller ends the capture at once).
  std::string beginCapture(int x, int y, int width, int height);
  // Binds layer k's target (0: opaque), clears it and sets the capture uniforms of
  // `program`, the capture variant of the shading program bound for this layer.
  void startLayer(int layer, const ShadingLocations& program);
  // Reads layer k back; returns false when it caught no traced surface (deeper layers would
  // catch nothing either).
  bool finishLayer(int layer, SurfaceLayer& out);
  // Restores the GL state.
  void endCapture();

  // Uploads the captured depths of the first `count` layers for the shading pass, sized for
  // `lights` screen-space lights (RAYS and VOLUMES), and the visibility that the CPU traced
  // for some of them: light i of `visibility` is screen light traced[i]. `surfacesChanged`
  // false: the layers are the ones uploaded last (only the lights moved), whose depths the
  // textures still hold. `positions`: the layers' positions too (positionTexture()), for the
  // shadow volumes. Empty when uploaded; else what GL said when allocating the textures,
  // which then hold nothing (layers() is 0: the lights are shaded without shadows).
  std::string upload(const std::vector<SurfaceLayer>& layers, int count, bool surfacesChanged,
                     const std::vector<std::uint16_t>& visibility, const std::vector<int>& traced,
                     int lights, bool positions);
  int layers() const { return uploadedLayers_; }
  // The textures upload() filled, for a pass that writes a screen light's visibility on the
  // GPU (ShadowVolumePass): visibility per light and layer (layer light * layers() + captured
  // layer), and their size.
  unsigned int visibilityTexture() const { return shadingVisibility_.get(); }
  // Per layer the captured position in the group's coordinates and the window depth (1
  // where nothing is traced); 0 unless upload() was asked for it.
  unsigned int positionTexture() const { return shadingPosition_.get(); }
  int width() const { return shadingWidth_; }
  int height() const { return shadingHeight_; }
  // Binds the shading textures until the returned scope ends.
  std::unique_ptr<GlStateScope> bind() const;

 private:
  std::string allocate(int width, int height);
  int unit(int i) const { return firstUnit_ + i; }

  int firstUnit_ = 0;
  int width_ = 0;
  int height_ = 0;
  // Capture targets: [0] the opaque layer, [1] and [2] alternate for transparent layers.
  std::vector<GlTexture> positions_;
  std::vector<GlTexture> normals_;
  GlTexture depth_;
  std::vector<GlFramebuffer> framebuffers_;
  std::unique_ptr<GlStateScope> saved_;
  // The debugger's groups of the capture (beginCapture() to endCapture()) and of its current
  // layer (startLayer() to finishLayer()).
  std::unique_ptr<GlDebugGroup> captureGroup_;
  std::unique_ptr<GlDebugGroup> layerGroup_;
  std::vector<int> viewport_;
  GlTexture shadingDepth_;
  GlTexture shadingVisibility_;
  GlTexture shadingPosition_;
  int uploadedLayers_ = 0;
  int uploadedRays_ = 0;
  int shadingWidth_ = 0;
  int shadingHeight_ = 0;
  std::vector<float> depthScratch_;
  std::vector<float> positionScratch_;
};

}  // namespace ivshadow
