#pragma once

#include "ivshadow/Export.h"
#include "ivshadow/ShadowFieldList.h"

#include <Inventor/fields/SoSFBool.h>
#include <Inventor/fields/SoSFEnum.h>
#include <Inventor/fields/SoSFFloat.h>
#include <Inventor/fields/SoSFInt32.h>
#include <Inventor/nodes/SoSeparator.h>

namespace ivshadow {
class TransparentShadowGroupImpl;
struct DeepShadowStatistics;
struct PeelStatistics;
}  // namespace ivshadow

/*!
  \class SoTransparentShadowGroup
  A separator whose subgraph is rendered with shadows from the lights in it: shadows whose
  strength follows each caster's opacity and whose colour follows its colour.

  Every light turned on in the subgraph casts (`castingLights ALL_LIGHTS`, the default), or
  only the deep shadow lights (`DEEP_SHADOW_LIGHTS`: SoDeepShadowLight, SoDeepShadowSpotLight,
  SoDeepShadowDirectionalLight). A SoDeepShadowLight is a point light
  with its own shadow fields; an ordinary SoPointLight, SoSpotLight or SoDirectionalLight
  (Coin's SoShadowSpotLight and SoShadowDirectionalLight included) casts with the group's
  fields below, which mean what the SoDeepShadowLight fields of the same names mean. Point and
  spot lights get a deep shadow map (MAP: a cube, or one perspective face over a spot light's
  cone up to 60 degrees) or shadow rays (RAYS) from their location; a directional light gets
  an orthographic map over the casters it can shade in view, or rays (docs/LIGHTS.md). A
  light of zero direction, or a spot light whose cutOffAngle is not in (0, pi/2], lights
  without a shadow, with one warning. At most 8 lights cast (the shading program's limit);
  further ones light without a shadow, with one warning.

  The children are rendered with a per-pixel version of Coin's own lighting in which each
  casting light's contribution is multiplied by its visibility. SoShadowStyle is honoured as
  by SoShadowGroup: only shapes whose style includes CASTS_SHADOW cast, and only shapes whose
  style includes SHADOWED receive shadows. Like SoShadowGroup, the group treats every light
  found in its subgraph as lighting all of it.

  The state in force where the group is traversed applies to its casters as it does to what
  Coin draws: a Material, BaseColor, Complexity, Texture2, Units, DrawStyle, ShapeHints,
  LightModel or SoShadowStyle set above the group, outside it (unlike SoShadowGroup, which
  resets the shadow style at the group). Casters and lights are kept in the group's
  coordinates, so transforms above move both. A change above the group is seen in the next
  frame (see docs/DEEP_SHADOWS.md, "State inherited from above the group").

  With `bounce TRUE` the casting lights' light also reaches what they do not light directly,
  after one diffuse reflection off an opaque caster, coloured by the transparent casters it
  crossed on the way there (light through red glass onto a white floor puts red on the wall
  beside it). It is computed as Kyloušek 2013 does: `bounceLights` virtual point lights are placed
  where the lights land (traced with Embree on the CPU, whatever the method), each with an
  imperfect shadow map (a point-sampled view of the opaque casters, holes filled by
  pull-push), and every shaded point adds their diffuse light. Transparent casters filter the
  light on its way to the bounce but not after it, and do not reflect (docs/DEEP_SHADOWS.md,
  "One bounce").

  Transparent surfaces in the subgraph are composited in exact per-pixel depth order by
  default (transparency PEELED): the children are drawn once for the opaque surfaces and
  then peeled two layers per pass (dual depth peeling, as SoPeelingSeparator's DUAL), every
  layer shaded with the group's shadows, whatever Coin's transparency type. A frame whose
  view shows no transparent fragment draws the children once, as Coin would. A
  SoPeelingSeparator inside a peeling group draws its children as part of the group's
  peeling (one peeling per pixel: its own fields do not apply there), and so does a group
  inside a peeling (shaded by the enclosing group's or separator's shading). COIN_BLENDING
  leaves transparency to Coin (the action's transparency type, in traversal order), as
  before.

  With `renderer TRACER` the children's triangles are not drawn by GL: every pixel's ray is
  traced through them on the CPU with Embree (the reference renderer's code: exact shadows of
  every casting light, whatever its method, and every transparent surface composited in
  exact depth order), from the near plane to the depth GL drew before the group, and the
  picture is blended onto the framebuffer with the depth of its nearest opaque surface, so
  what GL draws after the group depth-tests against it. The picture is kept while the
  subgraph, the state above the group (transforms, lights, material, light model,
  environment), the camera, the viewport and the depth drawn before it stay the same: a still
  frame only draws it again. Shapes drawn with lines, points or screen-aligned pixels have no
  triangles to trace: GL draws them after the picture, depth-tested against it, lit as Coin
  lights them and without shadows (one warning names them). With `bounce TRUE`, `bounceLights` is
  the number of bounce rays per shaded point (rounded up to a square). The fields of the maps
  (resolution, layers, filters) do not apply.

  `renderer AUTO` chooses per GL context: TRACER where GL is a software rasteriser (Mesa's
  llvmpipe, softpipe), whose shading costs more than the trace, RASTER on a GPU; it says which
  once. AUTO is the default.

  `movingResolution` trades a traced group's picture for speed while the scene moves, as the
  viewports of path tracers do: a frame that must trace again right after a frame that traced
  for a change (a light, the camera or a caster moving from frame to frame) is traced at that
  fraction of the viewport's width and height and stretched over it; the first frame of a
  motion is traced in full, so a single edit is never blurred. The first frame that finds nothing
  changed traces the full picture; the group asks for that frame itself, through Coin's
  sensors, a quarter of a second after the last reduced one, so a viewer refines once the
  motion stops. The default is 0.5; at 1 every frame is traced in full: what batch rendering of
  successive frames needs.

  FILE FORMAT/DEFAULTS:
  \code
    TransparentShadowGroup {
        renderCaching AUTO
        boundingBoxCaching AUTO
        renderCulling AUTO
        pickCulling AUTO
        isActive TRUE            # FALSE renders the children like a plain SoSeparator
        castingLights ALL_LIGHTS # ALL_LIGHTS or DEEP_SHADOW_LIGHTS
        # The shadows of the ordinary lights (SoDeepShadowLight nodes use their own fields):
        method AUTO          # AUTO, MAP (deep shadow map), RAYS (exact, Embree on the CPU),
                             #   VOLUMES (exact hard shadows, shadow volumes in GL) or
                             #   OPACITY_MAP (fixed cost: light absorbed per depth slice)
        resolution 512       # map face size in texels, 1 .. GL_MAX_TEXTURE_SIZE
        maxLayers 4          # peeled layers per face, 1 .. 64
        layerOverflow MERGE  # the ordinary lights' maps: as SoDeepShadowLight's
        slices 4             # OPACITY_MAP: depth slices per face, 1 .. 32
        bias 0.1             # towards the light beyond the receiver's plane, texels at the receiver
        shadowColor AUTO     # AUTO, MONOCHROME or COLORED
        colorModel SATURATE  # SATURATE (Rejent 2014, eq. 5.3) or POWER (eq. 5.2)
        precision FLOAT      # FLOAT or HALF (16-bit visibility; depth stays 32-bit)
        filter PCF           # NONE (the nearest texel) or PCF
        filterSize 1         # PCF: the mean over filterSize x filterSize texels, 1 .. 9
                             #   (1: bilinear)
        transparency PEELED      # PEELED: transparent surfaces in exact depth order per
                                 #   pixel; COIN_BLENDING: Coin's transparency type
        bounce FALSE         # TRUE: one diffuse bounce of the casting lights' light, tinted by
                             #   the glass it passed (virtual point lights, Kyloušek 2013)
        bounceLights 256     # bounce: virtual point lights placed, about, 1 .. 1024
        bounceMapSize 128    # bounce: each one's imperfect shadow map, 16 .. 256 texels, a
                             #   power of two
        renderer AUTO        # RASTER: GL draws the children; TRACER: their triangles are
                             #   traced on the CPU (exact shadows and glass in one pass);
                             #   AUTO: TRACER on a software rasteriser, else RASTER
        movingResolution 0.5 # TRACER: the fraction of the viewport's width and height
                             #   traced while the scene moves, 0.125 .. 1 (1: always full)
    }
  \endcode
*/
class IVSHADOW_API SoTransparentShadowGroup : public SoSeparator {
  typedef SoSeparator inherited;
  SO_NODE_HEADER(SoTransparentShadowGroup);

 public:
  static void initClass();
  SoTransparentShadowGroup();

  enum Transparency {
    PEELED,        //!< exact per-pixel depth order, by dual depth peeling
    COIN_BLENDING  //!< Coin's transparency type (order-dependent)
  };

  enum Renderer {
    RASTER,  //!< GL draws the children, shaded with the group's shadows
    TRACER,  //!< Embree traces the children's triangles on the CPU; GL draws the picture
    // TRACER on a software rasteriser (Mesa's llvmpipe), RASTER on a GPU (file name: AUTO;
    // SoSeparator's CacheEnabled has AUTO).
    AUTO_RENDERER
  };
  enum CastingLights {
    ALL_LIGHTS,         //!< every light turned on in the subgraph casts
    DEEP_SHADOW_LIGHTS  //!< only the deep shadow lights cast (SoDeepShadowLight and its spot
                        //!< and directional kin); other lights only light
  };

  SoSFBool isActive;
  SoSFEnum transparency;
  SoSFEnum renderer;
  SoSFEnum castingLights;
  // The ordinary lights' shadow fields of the FILE FORMAT block above, declared from their one
  // list (ivshadow/ShadowFieldList.h; the enums are SoDeepShadowLight's).
  IVSHADOW_SHADOW_FIELDS(IVSHADOW_DECLARE_FIELD)
  SoSFBool bounce;
  SoSFInt32 bounceLights;
  SoSFInt32 bounceMapSize;
  SoSFFloat movingResolution;

  //! What the last render in any context did: per light, layers used per face, map bytes,
  //! build time, and how many times the maps were rebuilt since the group was created.
  const ivshadow::DeepShadowStatistics& getStatistics() const;
  //! Passes and time of the last frame's peeling in any context (transparency PEELED).
  const ivshadow::PeelStatistics& getPeelStatistics() const;

  void GLRenderBelowPath(SoGLRenderAction* action) override;
  void GLRenderInPath(SoGLRenderAction* action) override;
  void notify(SoNotList* list) override;

 protected:
  ~SoTransparentShadowGroup() override;

 private:
  ivshadow::TransparentShadowGroupImpl* impl_;
};
