#pragma once

#include "gl/GlHandles.h"
#include "gl/GlProgram.h"
#include "ivshadow/Export.h"
#include "scene/ShadowTypes.h"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace ivshadow {

// The GL side of a group whose renderer is TRACER, in one context: reads the depth that GL
// drew before the group (the trace ends there), then hands the traced picture to the
// framebuffer: its colour composited over what is there (dst = rgb + a * dst, alpha the
// transmittance the picture leaves) and its nearest opaque depth written, so that what GL
// draws after depth-tests against it.
class IVSHADOW_INTERNAL TracedPicturePass {
 public:
  // Null, with the reason, when the context lacks what the pass needs (GL 4.5, its program).
  static std::unique_ptr<TracedPicturePass> create(std::string& whyNot);
  // Whether the current context can draw a traced picture; `whyNot` says why not.
  static bool supported(std::string& whyNot);

  // The draw framebuffer's window depths over `viewport` (x, y, width, height), rows bottom
  // to top. A multisampled framebuffer (an application's, FreeCAD's saveImage) is resolved
  // first: GL cannot read its samples. Empty when read; else why not, and `out` holds the far
  // plane (the trace then ends where GL's depth test would end nothing).
  std::string readDepth(const std::array<int, 4>& viewport, std::vector<float>& out) const;
  // The depth buffer of the draw framebuffer, as polygon offset sees it.
  static DepthBuffer drawDepthBuffer();
  // Uploads a picture of `width` x `height` pixels (`rgba` premultiplied colour and
  // transmittance, `depth` window depths, rows top to bottom). Empty when uploaded; else what
  // GL said when allocating the textures.
  std::string upload(int width, int height, const float* rgba, const float* depth);
  // Draws the picture uploaded last over `viewport`, whatever state Coin left, and puts the
  // state back. A picture smaller than the viewport (a frame traced at a lower resolution
  // while the scene moves) is stretched over it: its depth the nearest pixel's, its colour
  // interpolated among the pixels at that depth (traced_picture.frag). Only the pixels of
  // `region` ({x0, y0, x1, y1} from the viewport's corner) are drawn: outside it the picture
  // holds no surface, and its depth there (what GL drew when it was traced) may be older than
  // the framebuffer's.
  void draw(const std::array<int, 4>& viewport, const std::array<int, 4>& region) const;
  // The picture's depth alone, written again over `region` of `viewport` (colours untouched):
  // what the framebuffer's depth held after draw(), for GL to test against once more.
  void drawDepth(const std::array<int, 4>& viewport, const std::array<int, 4>& region) const;

 private:
  TracedPicturePass() = default;

  GlProgram program_;           // a picture of the viewport's size
  GlProgram stretchedProgram_;  // a smaller one, stretched over it
  GlVertexArray emptyVertexArray_;
  GlTexture colour_;
  GlTexture depth_;
  int width_ = 0;
  int height_ = 0;
};

}  // namespace ivshadow
