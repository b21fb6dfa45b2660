#pragma once

#include "ivshadow/Export.h"
#include "ivshadow/ShadowFieldList.h"

#include <Inventor/fields/SoSFEnum.h>
#include <Inventor/fields/SoSFFloat.h>
#include <Inventor/fields/SoSFInt32.h>
#include <Inventor/nodes/SoSpotLight.h>

/*!
  \class SoDeepShadowSpotLight
  A spot light with its own shadow fields: inside a SoTransparentShadowGroup it casts with
  these instead of the group's (docs/LIGHTS.md), as SoDeepShadowLight does for a point light.
  Outside a group it is a SoSpotLight. The fields mean what SoDeepShadowLight's of the same
  names mean; the map is one perspective face over the cone (a cone wider than 60 degrees:
  a cube map at the location, of which only the cone is lit).

  FILE FORMAT/DEFAULTS:
  \code
    DeepShadowSpotLight {
        on TRUE
        intensity 1
        color 1 1 1
        location 0 0 1
        direction 0 0 -1
        dropOffRate 0
        cutOffAngle 0.785398
        method AUTO          # AUTO, MAP (deep shadow map), RAYS (exact, Embree on the CPU),
                             #   VOLUMES (exact hard shadows, shadow volumes in GL) or
                             #   OPACITY_MAP (fixed cost: light absorbed per depth slice)
        resolution 512       # map face size in texels, 1 .. GL_MAX_TEXTURE_SIZE
        maxLayers 4          # layers per face, 1 .. 64
        layerOverflow MERGE  # a texel with more surfaces than maxLayers: MERGE them into
                             #   maxLayers groups, least error first (Lokovic-Veach), or
                             #   TRUNCATE to the nearest maxLayers
        slices 4             # OPACITY_MAP: depth slices per face, 1 .. 32
        bias 0.1             # towards the light beyond the receiver's plane, texels at the receiver
        shadowColor AUTO     # AUTO, MONOCHROME or COLORED
        colorModel SATURATE  # SATURATE (Rejent 2014, eq. 5.3) or POWER (eq. 5.2)
        precision FLOAT      # FLOAT or HALF (16-bit visibility; depth stays 32-bit)
        filter PCF           # NONE (the nearest texel) or PCF
        filterSize 1         # PCF: the mean over filterSize x filterSize texels, 1 .. 9
                             #   (1: bilinear)
        nearRadius -1        # distances from the light covered by the map; -1 fits them
        farRadius -1         #   to the bounding box of the group's shadow casters
    }
  \endcode
*/
class IVSHADOW_API SoDeepShadowSpotLight : public SoSpotLight {
  typedef SoSpotLight inherited;
  SO_NODE_HEADER(SoDeepShadowSpotLight);

 public:
  static void initClass();
  SoDeepShadowSpotLight();

  // The shadow fields of the FILE FORMAT block above, declared from their one list
  // (ivshadow/ShadowFieldList.h; the enums are SoDeepShadowLight's), and the map's nearRadius
  // and farRadius.
  IVSHADOW_SHADOW_FIELDS(IVSHADOW_DECLARE_FIELD)
  IVSHADOW_MAP_RANGE_FIELDS(IVSHADOW_DECLARE_FIELD)

 protected:
  ~SoDeepShadowSpotLight() override;
};
