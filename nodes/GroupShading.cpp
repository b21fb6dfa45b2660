#include "nodes/GroupShading.h"

#include "callbacks/ShadingUniforms.h"
#include "nodes/GroupContents.h"
#include "nodes/TexGenWatchElement.h"

#include <Inventor/SoPath.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/elements/SoEnvironmentElement.h>
#include <Inventor/elements/SoLightElement.h>
#include <Inventor/elements/SoModelMatrixElement.h>
#include <Inventor/elements/SoViewingMatrixElement.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoEnvironment.h>

#include <algorithm>

namespace ivshadow {

ShadingUniforms* GroupShading::begin(SoGLRenderAction* action, int textureUnits,
                                     const ShadingFeatures& lights) {
  SoState* state = action->getState();
  const int fog = fogType(state);
  features_ = lights;
  features_.fog = fog != 0;
  camera_ = programs_.bind(action, ShadingVariant::Shade, features_);
  if (camera_ == nullptr) return nullptr;
  syncTexGen(state);
  uniforms_ = ShadingUniforms{};
  uniforms_.textureUnits = textureUnits;
  outsideLights_ = SoLightElement::getLights(state).getLength();
  uniforms_.lightCount =
      std::min(ShadingUniforms::kMaxLights, outsideLights_ + contents_.lightsOn());
  localToEye_ = findLocalToEye(state);
  const SbMatrix eyeToLocal = localToEye_.inverse();
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 4; ++column)
      uniforms_.eyeToLocal[row * 4 + column] = eyeToLocal[row][column];
  uniforms_.fogType = fog;
  return &uniforms_;
}

void GroupShading::apply() {
  uniforms_.apply(*camera_);
  darkenLights(outsideLights_);
}

const UniformLocations* GroupShading::bind(SoGLRenderAction* action, ShadingVariant variant) {
  if (camera_ == nullptr) return nullptr;
  const UniformLocations* program = programs_.bind(action, variant, features_);
  if (program != nullptr) uniforms_.apply(*program);
  syncTexGen(action->getState());
  return program;
}

void GroupShading::syncTexGen(SoState* state) {
  syncTexGen(state, TexGenWatchElement::generatesTexCoords(state));
}

void GroupShading::syncTexGen(SoState* state, bool generated) {
  // The common case, no function and no program told of one, costs no GL call.
  if (!generated && !programs_.anyTexGen(state)) return;
  // Every variant, not only the one bound: a SoShadowStyle switches the program off and on
  // again without a bind, and a variant bound later must not draw with old modes.
  programs_.sendTexGen(state, generated ? currentTexGenModes() : TexGenModes{});
}

SbMatrix GroupShading::findLocalToEye(SoState* state) const {
  if (!contents_.cameraPath())
    return SoModelMatrixElement::get(state) * SoViewingMatrixElement::get(state);
  // A camera inside the group is traversed after the group sets its uniforms; the viewing
  // matrix it will set, relative to the group's coordinates, is what maps them to the eye.
  SbMatrix viewing = SbMatrix::identity();
  SoCallbackAction action;
  action.addPostCallback(
      SoCamera::getClassTypeId(),
      [](void* data, SoCallbackAction* a, const SoNode*) {
        *static_cast<SbMatrix*>(data) = a->getViewingMatrix();
        return SoCallbackAction::CONTINUE;
      },
      &viewing);
  action.apply(contents_.cameraPath());
  return viewing;
}

int GroupShading::fogType(SoState* state) const {
  // Like a camera, an environment inside the group is traversed after the uniforms are set.
  if (contents_.environmentPath())
    return static_cast<const SoEnvironment*>(contents_.environmentPath()->getTail())
        ->fogType.getValue();
  return int(SoEnvironmentElement::getFogType(state));
}

}  // namespace ivshadow
