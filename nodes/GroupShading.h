#pragma once

#include "gl/ShadingUniforms.h"
#include "nodes/ShadingProgram.h"

#include <Inventor/SbMatrix.h>

class SoGLRenderAction;
class SoState;

namespace ivshadow {

class GroupContents;

// The shading of a group's shapes: the variants of the shading program and the uniforms they
// share in one frame (lights, the eye-to-group transform, fog, and whatever the caller adds
// about its lights' maps). SoTransparentShadowGroup shades with it, and so does a
// SoPeelingSeparator that is not inside one. A frame is
//   begin(); <fill in the maps>; apply(); [bind(variant); <Coin draws>]...; end();
// in a traversal state the caller pushes before begin() and pops after end().
class GroupShading {
 public:
  explicit GroupShading(const GroupContents& contents) : contents_(contents) {}
  GroupShading(const GroupShading&) = delete;
  GroupShading& operator=(const GroupShading&) = delete;

  // Binds the camera pass, compiled with what the frame's lights need (`lights`; fog is added
  // from the state), and starts the frame's uniforms from the state, the samplers' units taken
  // from a context of `textureUnits` units. Null when the program did not build (Coin has said
  // why): the caller then renders plainly.
  ShadingUniforms* begin(SoGLRenderAction* action, int textureUnits, const ShadingFeatures& lights);
  // The group's coordinates to the eye's, and the eye's to clip coordinates, as a camera
  // inside the group will set them (begin() finds them).
  const SbMatrix& localToEye() const { return localToEye_; }
  const SbMatrix& projection() const { return projection_; }
  // Sets the frame's uniforms on the camera pass and leaves the GL lights the scene does not
  // use dark.
  void apply();
  // Between begin() and end(): binds `variant`, with the frame's features and uniforms, and
  // returns it; null when it did not build or outside a frame.
  const ShadingLocations* bind(SoGLRenderAction* action, ShadingVariant variant);
  void end() { camera_ = nullptr; }
  // Tells the bound program how Coin's texture coordinate function in force generates
  // texture coordinates (bind() calls it; TexGenWatchElement whenever the function changes,
  // with `generated` read from the element that is or becomes the top: during a pop the
  // state still holds the one going away).
  void syncTexGen(SoState* state);
  void syncTexGen(SoState* state, bool generated);

  // GL lights on before the group, as begin() found them this frame.
  int outsideLights() const { return outsideLights_; }

 private:
  // Sets localToEye_ and projection_.
  void findView(SoState* state);
  int fogType(SoState* state) const;

  const GroupContents& contents_;
  ShadingProgram programs_;
  ShadingUniforms uniforms_;
  const ShadingLocations* camera_ = nullptr;  // the camera pass, bound by begin()
  ShadingFeatures features_;                  // the frame's, set by begin()
  int outsideLights_ = 0;                     // GL lights on before the group
  SbMatrix localToEye_;
  SbMatrix projection_;
};

}  // namespace ivshadow
