#pragma once

#include "ivshadow/Export.h"
#include "ivshadow/ShadowFieldList.h"

#include <Inventor/fields/SoSFEnum.h>
#include <Inventor/fields/SoSFFloat.h>
#include <Inventor/fields/SoSFInt32.h>
#include <Inventor/nodes/SoPointLight.h>

/*!
  \class SoDeepShadowLight
  A point light whose shadows let light through transparent casters, tinted by their colour.

  Inside a SoTransparentShadowGroup the light owns a cube deep shadow map: for each of the six
  faces, the nearest `maxLayers` surfaces from the light, each layer storing its distance and
  the visibility (1 or 3 channels) after it. The map is built from per-texel fragment lists
  (one draw of the casters per face, then a sort); where GL cannot give the lists' storage,
  by depth peeling (one draw per layer), which stores the same map, with one warning.
  Outside such a group it behaves exactly like a SoPointLight.

  FILE FORMAT/DEFAULTS:
  \code
    DeepShadowLight {
        on TRUE
        intensity 1
        color 1 1 1
        location 0 0 1
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

  With `method RAYS` the light keeps no map: after the camera's depth is known, one shadow ray
  per pixel (per visible surface layer) is traced on the CPU through the group's casters,
  multiplying the transmittance of every surface crossed; resolution, maxLayers, bias,
  precision and filter then do not apply. AUTO picks RAYS on software rasterisers (llvmpipe,
  softpipe, swrast), where it is both faster and exact, and MAP on GPUs.

  With `method VOLUMES` the same visible surfaces are shadowed by transparent shadow volumes
  drawn in GL (after Kim et al. 2007): each caster triangle's volume carries its log
  transmittance per channel, and the sum over the volumes behind which a surface lies is its
  log visibility, so the shadow is exact and hard like RAYS without tracing on the CPU. A
  caster whose colour varies across a triangle (per-vertex colours, textures) casts its mean
  colour, with one warning per light.

  With `method OPACITY_MAP` the map is an opacity map (after Vinkelis 2008): `slices` uniform
  slices per face over the transparent casters' distances from the light, each holding the
  light its transparent surfaces absorb (per channel) and the distance of its first surface,
  and one depth per texel of the nearest opaque surface. Each face draws the casters once for
  every 7 slices (one draw at the default 4), however many surfaces lie behind one another. A
  receiver takes the absorption of the slices before it, and of a slice it lies in or just
  behind in proportion to its distance past that slice's first surface (up to one slice's
  depth): exact for a receiver at least one slice behind each transparent caster, softer
  nearer than that. Opaque casters shadow exactly, as in a shadow map. maxLayers does not
  apply.

  Out-of-range values are clamped when the map is built, with one warning naming the node and
  the field.
*/
class IVSHADOW_API SoDeepShadowLight : public SoPointLight {
  typedef SoPointLight inherited;
  SO_NODE_HEADER(SoDeepShadowLight);

 public:
  static void initClass();
  SoDeepShadowLight();

  enum ShadowColor {
    AUTO,        //!< colour channels only when some transparent caster is not grey
    MONOCHROME,  //!< one visibility channel (Rejent 2014, eq. 5.1)
    COLORED      //!< three visibility channels
  };
  enum ColorModel {
    SATURATE,  //!< V' (1 - a) clamp(1 - a + c, 0, 1), Rejent 2014, eq. 5.3
    POWER      //!< V' (1 - a)^(2 - c), Rejent 2014, eq. 5.2
  };
  enum Precision {
    FLOAT,  //!< 32-bit visibility
    HALF    //!< 16-bit visibility, half the memory
  };
  enum Method {
    AUTO_METHOD = 0,  //!< RAYS on a software rasteriser, MAP on a GPU (file name: AUTO)
    MAP = 1,          //!< the cube deep shadow map
    RAYS = 2,         //!< exact shadow rays on the CPU (Embree)
    VOLUMES = 3,      //!< exact hard shadows by transparent shadow volumes (GL)
    OPACITY_MAP = 4   //!< light absorbed per uniform depth slice, a fixed-cost approximation
  };
  enum Filter {
    NONE,  //!< nearest texel
    PCF    //!< average of filterSize x filterSize texels
  };
  enum LayerOverflow {
    MERGE,    //!< every surface kept, neighbours merged into maxLayers groups (error bounded)
    TRUNCATE  //!< the nearest maxLayers surfaces only (light behind them too bright)
  };

  // The shadow fields of the FILE FORMAT block above, declared from their one list
  // (ivshadow/ShadowFieldList.h), and the map's nearRadius and farRadius.
  IVSHADOW_SHADOW_FIELDS(IVSHADOW_DECLARE_FIELD)
  IVSHADOW_MAP_RANGE_FIELDS(IVSHADOW_DECLARE_FIELD)

 protected:
  ~SoDeepShadowLight() override;
};
