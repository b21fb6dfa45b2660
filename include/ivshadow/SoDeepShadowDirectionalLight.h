#pragma once

#include "ivshadow/Export.h"

#include <Inventor/fields/SoSFEnum.h>
#include <Inventor/fields/SoSFFloat.h>
#include <Inventor/fields/SoSFInt32.h>
#include <Inventor/nodes/SoDirectionalLight.h>

/*!
  \class SoDeepShadowDirectionalLight
  A directional light with its own shadow fields: inside a SoTransparentShadowGroup it casts
  with these instead of the group's (docs/LIGHTS.md), as SoDeepShadowLight does for a point
  light. Outside a group it is a SoDirectionalLight. The fields mean what SoDeepShadowLight's
  of the same names mean; the map (method MAP) is one orthographic face across the light,
  fitted to the casters that the view can show, so it has no nearRadius or farRadius.

  FILE FORMAT/DEFAULTS:
  \code
    DeepShadowDirectionalLight {
        on TRUE
        intensity 1
        color 1 1 1
        direction 0 0 -1
        method AUTO
        resolution 512
        maxLayers 4
        bias 1
        shadowColor AUTO     # AUTO, MONOCHROME or COLORED (SoDeepShadowLight::ShadowColor)
        colorModel SATURATE  # SATURATE or POWER (SoDeepShadowLight::ColorModel)
        precision FLOAT
        filter NONE
        filterSize 3
    }
  \endcode
*/
class IVSHADOW_API SoDeepShadowDirectionalLight : public SoDirectionalLight {
  typedef SoDirectionalLight inherited;
  SO_NODE_HEADER(SoDeepShadowDirectionalLight);

 public:
  static void initClass();
  SoDeepShadowDirectionalLight();

  SoSFEnum method;  //!< SoDeepShadowLight::Method
  SoSFInt32 resolution;
  SoSFInt32 maxLayers;
  SoSFFloat bias;
  SoSFEnum shadowColor;  //!< SoDeepShadowLight::ShadowColor
  SoSFEnum colorModel;   //!< SoDeepShadowLight::ColorModel
  SoSFEnum precision;    //!< SoDeepShadowLight::Precision
  SoSFEnum filter;       //!< SoDeepShadowLight::Filter
  SoSFInt32 filterSize;

 protected:
  ~SoDeepShadowDirectionalLight() override;
};
