#include "nodes/GroupShading.h"

#include "gl/ShadingUniforms.h"
#include "nodes/GroupContents.h"
#include "nodes/TexGenWatchElement.h"
#include "scene/LightLimit.h"

#include <Inventor/SoPath.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/elements/SoEnvironmentElement.h>
#include <Inventor/elements/SoLightElement.h>
#include <Inventor/elements/SoModelMatrixElement.h>
#include <Inventor/elements/SoProjectionMatrixElement.h>
#include <Inventor/elements/SoViewingMatrixElement.h>
#include <Inventor/elements/SoViewportRegionElement.h>
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
  warnLightsPastGlLimit(contents_.owner(), outsideLights_ + contents_.lightsOn());
  uniforms_.lightCount =
      std::min(ShadingUniforms::kMaxLights, outsideLights_ + contents_.lightsOn());
  findView(state);
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

const ShadingLocations* GroupShading::bind(SoGLRenderAction* action, ShadingVariant variant) {
  if (camera_ == nullptr) return nullptr;
  const ShadingLocations* program = programs_.bind(action, variant, features_);
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

void GroupShading::findView(SoState* state) {
  const CoinRef<SoPath> cameraPath = contents_.cameraPath();
  if (!cameraPath) {
    localToEye_ = SoModelMatrixElement::get(state) * SoViewingMatrixElement::get(state);
    projection_ = SoProjectionMatrixElement::get(state);
    return;
  }
  // A camera inside the group is traversed after the group sets its uniforms; the viewing
  // matrix it will set, relative to the group's coordinates, is what maps them to the eye,
  // and its projection (for this viewport's aspect) what the eye's coordinates go through.
  struct View {
    SbMatrix viewing = SbMatrix::identity();
    SbMatrix projection = SbMatrix::identity();
  } view;
  SoCallbackAction action(SoViewportRegionElement::get(state));
  action.addPostCallback(
      SoCamera::getClassTypeId(),
      [](void* data, SoCallbackAction* a, const SoNode*) {
        auto* found = static_cast<View*>(data);
        found->viewing = a->getViewingMatrix();
        found->projection = a->getProjectionMatrix();
        return SoCallbackAction::CONTINUE;
      },
      &view);
  action.apply(cameraPath.get());
  localToEye_ = view.viewing;
  projection_ = view.projection;
}

int GroupShading::fogType(SoState* state) const {
  // Like a camera, an environment inside the group is traversed after the uniforms are set.
  if (const CoinRef<SoPath> path = contents_.environmentPath())
    return static_cast<const SoEnvironment*>(path->getTail())->fogType.getValue();
  return int(SoEnvironmentElement::getFogType(state));
}

}  // namespace ivshadow
