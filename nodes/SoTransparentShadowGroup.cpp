#include "ivshadow/SoTransparentShadowGroup.h"

#include "ivshadow/SoDeepShadowLight.h"
#include "nodes/DeepShadowSettings.h"
#include "nodes/LightScopeElement.h"
#include "nodes/ScreenAlignedShapes.h"
#include "nodes/ShadowFields.h"
#include "nodes/ShadowGroupElement.h"
#include "nodes/TransparentShadowGroupImpl.h"

#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/annex/FXViz/elements/SoShadowStyleElement.h>

SO_NODE_SOURCE(SoTransparentShadowGroup);

void SoTransparentShadowGroup::initClass() {
  if (getClassTypeId() != SoType::badType()) return;
  SoDeepShadowLight::initClass();
  ivshadow::ShadowGroupElement::initClass();
  // Its shading adds up GL lights by number: a light turned off must add nothing.
  ivshadow::registerLightScopeElement();
  ivshadow::registerScreenAlignedShapes();
  // Registered without the "So" prefix, as Coin registers its own nodes: Coin writes that
  // name to files, and SoType::fromName finds "TransparentShadowGroup" from either spelling.
  PRIVATE_COMMON_INIT_CODE(SoTransparentShadowGroup, "TransparentShadowGroup",
                           &SoTransparentShadowGroup::createInstance, SoSeparator);
  // The casters are collected with a SoCallbackAction, which must track SoShadowStyle; the
  // group reads the style it inherits when it renders (Coin enables that one too).
  SO_ENABLE(SoCallbackAction, SoShadowStyleElement);
  SO_ENABLE(SoGLRenderAction, SoShadowStyleElement);
}

SoTransparentShadowGroup::SoTransparentShadowGroup()
    : impl_(new ivshadow::TransparentShadowGroupImpl(this,
                                                     [this](SoGLRenderAction* action, bool inPath) {
                                                       if (inPath)
                                                         inherited::GLRenderInPath(action);
                                                       else
                                                         inherited::GLRenderBelowPath(action);
                                                     })) {
  SO_NODE_CONSTRUCTOR(SoTransparentShadowGroup);
  SO_NODE_ADD_FIELD(isActive, (TRUE));
  SO_NODE_ADD_FIELD(castingLights, (ALL_LIGHTS));
  IVSHADOW_ADD_SHADOW_FIELDS();
  SO_NODE_DEFINE_ENUM_VALUE(CastingLights, ALL_LIGHTS);
  SO_NODE_DEFINE_ENUM_VALUE(CastingLights, DEEP_SHADOW_LIGHTS);
  SO_NODE_SET_SF_ENUM_TYPE(castingLights, CastingLights);
  SO_NODE_ADD_FIELD(transparency, (PEELED));
  SO_NODE_DEFINE_ENUM_VALUE(Transparency, PEELED);
  SO_NODE_DEFINE_ENUM_VALUE(Transparency, COIN_BLENDING);
  SO_NODE_SET_SF_ENUM_TYPE(transparency, Transparency);
  SO_NODE_ADD_FIELD(renderer, (AUTO_RENDERER));
  SO_NODE_DEFINE_ENUM_VALUE(Renderer, RASTER);
  SO_NODE_DEFINE_ENUM_VALUE(Renderer, TRACER);
  // Files say AUTO; the C++ name is AUTO_RENDERER, since SoSeparator's CacheEnabled has AUTO.
  fieldData->addEnumValue("Renderer", "AUTO", AUTO_RENDERER);
  SO_NODE_SET_SF_ENUM_TYPE(renderer, Renderer);
  SO_NODE_ADD_FIELD(bounce, (FALSE));
  SO_NODE_ADD_FIELD(bounceLights, (ivshadow::kDefaultBounceLights));
  SO_NODE_ADD_FIELD(bounceMapSize, (ivshadow::kDefaultBounceMapSize));
  SO_NODE_ADD_FIELD(movingResolution, (0.5f));
}

SoTransparentShadowGroup::~SoTransparentShadowGroup() {
  delete impl_;
}

const ivshadow::DeepShadowStatistics& SoTransparentShadowGroup::getStatistics() const {
  return impl_->statistics();
}

const ivshadow::PeelStatistics& SoTransparentShadowGroup::getPeelStatistics() const {
  return impl_->peelStatistics();
}

void SoTransparentShadowGroup::GLRenderBelowPath(SoGLRenderAction* action) {
  const bool peel = transparency.getValue() == PEELED;
  if (!isActive.getValue() || !impl_->render(action, false, peel))
    inherited::GLRenderBelowPath(action);
}

void SoTransparentShadowGroup::GLRenderInPath(SoGLRenderAction* action) {
  const bool peel = transparency.getValue() == PEELED;
  if (!isActive.getValue() || !impl_->render(action, true, peel)) inherited::GLRenderInPath(action);
}

void SoTransparentShadowGroup::notify(SoNotList* list) {
  impl_->changed(list);
  inherited::notify(list);
}
