#include "raytrace/CastingLight.h"

#include "ivshadow/SoDeepShadowDirectionalLight.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoDeepShadowSpotLight.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "scene/WarnOnce.h"

#include <Inventor/SbMatrix.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/nodes/SoDirectionalLight.h>
#include <Inventor/nodes/SoPointLight.h>
#include <Inventor/nodes/SoSpotLight.h>

#include <cmath>
#include <limits>
#include <string>

namespace ivshadow {
namespace {

void warnCannotCast(const SoLight& light, const std::string& why) {
  if (!firstWarning(&light, "cannot cast")) return;
  const std::string name = light.getName().getString();
  const std::string type = std::string("So") + light.getTypeId().getName().getString();
  const std::string label = name.empty() ? type : type + " \"" + name + "\"";
  SoDebugError::postWarning(type.c_str(), "%s lights without a shadow: %s", label.c_str(),
                            why.c_str());
}

// A direction Coin can light along: finite and not zero.
bool usableDirection(const SbVec3f& direction) {
  const float length = direction.length();
  return std::isfinite(length) && length > 0.0f;
}

}  // namespace

bool isDeepShadowLight(const SoLight& light) {
  return light.isOfType(SoDeepShadowLight::getClassTypeId()) ||
         light.isOfType(SoDeepShadowSpotLight::getClassTypeId()) ||
         light.isOfType(SoDeepShadowDirectionalLight::getClassTypeId());
}

bool castingLight(const SoLight& light, const SoTransparentShadowGroup& group,
                  const SbMatrix& toGroup, CastingLight& out) {
  if (!light.on.getValue()) return false;
  if (!isDeepShadowLight(light) &&
      group.castingLights.getValue() == SoTransparentShadowGroup::DEEP_SHADOW_LIGHTS)
    return false;
  if (light.isOfType(SoSpotLight::getClassTypeId())) {
    const auto& spot = static_cast<const SoSpotLight&>(light);
    const float cutOff = spot.cutOffAngle.getValue();
    if (!usableDirection(spot.direction.getValue())) {
      warnCannotCast(light, "its direction is zero");
      return false;
    }
    if (!(cutOff > 0.0f && cutOff <= float(M_PI / 2.0) + 1e-6f)) {
      warnCannotCast(light, "cutOffAngle " + std::to_string(cutOff) + " is not in (0, pi/2]");
      return false;
    }
    SbVec3f axis;
    toGroup.multDirMatrix(spot.direction.getValue(), axis);
    if (!usableDirection(axis)) {
      warnCannotCast(light, "its direction is zero");
      return false;
    }
    axis.normalize();
    out.kind = LightKind::Spot;
    out.axis = axis;
    out.cutOffAngle = cutOff;
    toGroup.multVecMatrix(spot.location.getValue(), out.position);
    return true;
  }
  if (light.isOfType(SoPointLight::getClassTypeId())) {
    out.kind = LightKind::Point;
    toGroup.multVecMatrix(static_cast<const SoPointLight&>(light).location.getValue(),
                          out.position);
    return true;
  }
  if (light.isOfType(SoDirectionalLight::getClassTypeId())) {
    const SbVec3f direction = static_cast<const SoDirectionalLight&>(light).direction.getValue();
    SbVec3f towards;
    toGroup.multDirMatrix(-direction, towards);
    if (!usableDirection(direction) || !usableDirection(towards)) {
      warnCannotCast(light, "its direction is zero");
      return false;
    }
    towards.normalize();
    out.kind = LightKind::Directional;
    out.position = towards;
    return true;
  }
  warnCannotCast(light, "only point, spot and directional lights cast");
  return false;
}

ShadowColourModel shadowColourModel(int shadowColor, int colorModel, bool colouredCasters) {
  const bool coloured = shadowColor == SoDeepShadowLight::COLORED ||
                        (shadowColor == SoDeepShadowLight::AUTO && colouredCasters);
  if (!coloured) return ShadowColourModel::Monochrome;
  return colorModel == SoDeepShadowLight::POWER ? ShadowColourModel::Power
                                                : ShadowColourModel::Saturate;
}

ShadowColourModel castingColourModel(const SoLight& light, const SoTransparentShadowGroup& group,
                                     bool colouredCasters) {
  // The colour fields of the node whose fields the light casts with (castingSettings' choice,
  // nodes/DeepShadowSettings.cpp); they are read as set, never clamped.
  const auto model = [&](const auto& node) {
    return shadowColourModel(node.shadowColor.getValue(), node.colorModel.getValue(),
                             colouredCasters);
  };
  if (light.isOfType(SoDeepShadowLight::getClassTypeId()))
    return model(static_cast<const SoDeepShadowLight&>(light));
  if (light.isOfType(SoDeepShadowSpotLight::getClassTypeId()))
    return model(static_cast<const SoDeepShadowSpotLight&>(light));
  if (light.isOfType(SoDeepShadowDirectionalLight::getClassTypeId()))
    return model(static_cast<const SoDeepShadowDirectionalLight&>(light));
  return model(group);
}

}  // namespace ivshadow
