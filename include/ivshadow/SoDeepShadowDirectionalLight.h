#pragma once

#include "ivshadow/Export.h"

#include <Inventor/fields/SoSFEnum.h>
#include <Inventor/nodes/SoDirectionalLight.h>

/*!
  \class SoDeepShadowDirectionalLight
  A directional light with its own shadow colour fields: inside a SoTransparentShadowGroup it
  casts with these instead of the group's (docs/LIGHTS.md). Its shadows are traced (RAYS) with
  either method, so it has no map fields. Outside a group it is a SoDirectionalLight.

  FILE FORMAT/DEFAULTS:
  \code
    DeepShadowDirectionalLight {
        on TRUE
        intensity 1
        color 1 1 1
        direction 0 0 -1
        shadowColor AUTO     # AUTO, MONOCHROME or COLORED (SoDeepShadowLight::ShadowColor)
        colorModel SATURATE  # SATURATE or POWER (SoDeepShadowLight::ColorModel)
    }
  \endcode
*/
class IVSHADOW_API SoDeepShadowDirectionalLight : public SoDirectionalLight {
  typedef SoDirectionalLight inherited;
  SO_NODE_HEADER(SoDeepShadowDirectionalLight);

 public:
  static void initClass();
  SoDeepShadowDirectionalLight();

  SoSFEnum shadowColor;
  SoSFEnum colorModel;

 protected:
  ~SoDeepShadowDirectionalLight() override;
};
